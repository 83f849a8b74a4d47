#include "farm/content_hash.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace lc::farm {

namespace {
constexpr std::uint64_t fnv_prime = 0x100000001b3ull;
}

// Folds each byte into the state (FNV-1a: xor, then multiply).
ContentHash& ContentHash::add(std::string_view bytes) {
  for (unsigned char c : bytes) {
    h_ ^= c;
    h_ *= fnv_prime;
  }
  return *this;
}

// Folds the 8 bytes of `value`, least significant first (platform-independent).
ContentHash& ContentHash::add(std::uint64_t value) {
  for (int i = 0; i < 8; ++i) {
    h_ ^= (value >> (8 * i)) & 0xffu;
    h_ *= fnv_prime;
  }
  return *this;
}

std::string ContentHash::hex() const { return to_hex(h_); }

std::uint64_t hash_bytes(std::string_view bytes) { return ContentHash().add(bytes).value(); }

// Streams the file in 1 MiB blocks so large textures need no big buffer.
std::uint64_t hash_file(const std::filesystem::path& file) {
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (!f) throw std::runtime_error(fmt::format("cannot read {}: {}", file.string(), std::strerror(errno)));
  ContentHash h;
  std::vector<char> buf(1 << 20);
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) h.add(std::string_view(buf.data(), n));
  const bool failed = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  if (failed) throw std::runtime_error(fmt::format("cannot read {}: {}", file.string(), std::strerror(err)));
  return h.value();
}

std::string to_hex(std::uint64_t value) { return fmt::format("{:016x}", value); }

}  // namespace lc::farm
