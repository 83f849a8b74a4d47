#include "store/content_hash.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/file_checks.hpp"

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
// Only a regular file is hashed: a FIFO or a device (/dev/zero) would block
// or never end. The type is checked on the opened file; opening does not
// block, even for a FIFO.
std::uint64_t hash_file(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot read {}: {}", file.string(), std::strerror(errno)));
  struct stat st {};
  std::string problem;
  if (::fstat(fd, &st) != 0) {
    problem = std::strerror(errno);
  } else if (!S_ISREG(st.st_mode)) {
    problem = fmt::format("{}, not a regular file", file_kind(st.st_mode));
  }
  if (!problem.empty()) {
    ::close(fd);
    throw std::runtime_error(fmt::format("cannot read {}: {}", file.string(), problem));
  }
  std::FILE* f = ::fdopen(fd, "rb");
  if (!f) {
    const int err = errno;
    ::close(fd);
    throw std::runtime_error(fmt::format("cannot read {}: {}", file.string(), std::strerror(err)));
  }
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
