#include "image/png_check.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <zlib.h>

namespace lc {

namespace {

constexpr std::array<unsigned char, 8> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t big_endian(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

}  // namespace

void check_png_file(const std::filesystem::path& path, int width, int height) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot be opened");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < signature.size() || std::memcmp(bytes.data(), signature.data(), signature.size()) != 0)
    throw std::runtime_error("not a PNG (no PNG signature)");
  std::size_t pos = signature.size();
  bool ihdr = false, idat = false;
  while (pos < bytes.size()) {
    if (bytes.size() - pos < 12) throw std::runtime_error(fmt::format("cut short at byte {} (a chunk's frame)", pos));
    const std::uint32_t length = big_endian(&bytes[pos]);
    const std::string type(reinterpret_cast<const char*>(&bytes[pos + 4]), 4);
    if (length > bytes.size() - pos - 12)
      throw std::runtime_error(fmt::format("cut short in its {} chunk at byte {}", type, pos));
    const unsigned char* data = &bytes[pos + 8];
    const std::uint32_t stored = big_endian(data + length);
    const auto crc = static_cast<std::uint32_t>(::crc32(::crc32(0L, Z_NULL, 0), &bytes[pos + 4], length + 4));
    if (crc != stored) throw std::runtime_error(fmt::format("its {} chunk at byte {} fails its CRC", type, pos));
    if (!ihdr) {
      if (type != "IHDR" || length != 13) throw std::runtime_error("its first chunk is not an IHDR");
      const auto w = big_endian(data), h = big_endian(data + 4);
      if (w != static_cast<std::uint32_t>(width) || h != static_cast<std::uint32_t>(height))
        throw std::runtime_error(fmt::format("it is {}x{}, not {}x{}", w, h, width, height));
      ihdr = true;
    }
    idat |= type == "IDAT";
    pos += 12 + length;
    if (type == "IEND") {
      if (!idat) throw std::runtime_error("it has no image data (IDAT)");
      if (pos != bytes.size()) throw std::runtime_error(fmt::format("{} bytes follow its IEND", bytes.size() - pos));
      return;
    }
  }
  throw std::runtime_error(fmt::format("cut short: no IEND chunk in its {} bytes", bytes.size()));
}

}  // namespace lc
