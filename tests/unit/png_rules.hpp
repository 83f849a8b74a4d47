// What the PNG specification (ISO/IEC 15948, W3C PNG 2nd edition) asks of a
// file, checked on its bytes with zlib alone: so a PNG writer's test holds
// it to the format, not to the bytes another library's writer makes.  The
// pixels are the caller's to compare after a decoder (libpng) has read them.
#pragma once

#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace lc::test {

struct PngChunk {
  std::string type;
  std::string data;
};

// What the file's IHDR must say.  Rows are expected not interlaced: no
// writer of lightcone interlaces.
struct PngHeader {
  std::uint32_t width = 0, height = 0;
  int bit_depth = 8;
  int colour_type = 2;  // 2: truecolour (RGB), 6: truecolour with alpha
};

inline std::uint32_t png_be32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return (std::uint32_t{u[0]} << 24) | (std::uint32_t{u[1]} << 16) | (std::uint32_t{u[2]} << 8) | std::uint32_t{u[3]};
}

// A chunk's CRC as the specification defines it: CRC-32 over type and data.
inline std::uint32_t png_crc(const std::string& type, const std::string& data) {
  uLong crc = ::crc32(0L, Z_NULL, 0);
  crc = ::crc32(crc, reinterpret_cast<const Bytef*>(type.data()), static_cast<uInt>(type.size()));
  crc = ::crc32(crc, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size()));
  return static_cast<std::uint32_t>(crc);
}

// A tEXt keyword's rule (section 11.3.4.3): 1-79 printable Latin-1 bytes,
// no leading, trailing or doubled space.
inline bool png_keyword_ok(const std::string& k) {
  if (k.empty() || k.size() > 79 || k.front() == ' ' || k.back() == ' ' || k.find("  ") != std::string::npos)
    return false;
  for (const char ch : k) {
    const auto c = static_cast<unsigned char>(ch);
    if (!((c >= 32 && c <= 126) || c >= 161)) return false;
  }
  return true;
}

// Input: a whole file's bytes and what its header must say.  Output: "" when
// the file keeps every rule below, else the first rule it breaks; `chunks`
// (when given) receives the chunks in file order.
// - the signature; every chunk whole, its type four letters with the
//   reserved bit clear, its CRC right;
// - IHDR first and once, 13 bytes, the expected size, depth and colour
//   type, compression 0, filter method 0, not interlaced;
// - IDAT chunks consecutive, IEND last, empty, nothing after it; no critical
//   chunk this file's colour type does not allow;
// - the ancillary chunks lightcone's writers may make, where they may be
//   and with what they may hold: gAMA, sRGB, cHRM, pHYs, oFFs once each
//   and before IDAT; with sRGB, gAMA and cHRM the values the specification
//   gives for sRGB (section 11.3.3.5); tEXt a keyword, a zero byte, text;
// - the IDAT data one whole zlib stream (its checksum right, nothing after
//   it) inflating to exactly one filter byte (0-4) and the row's bytes for
//   each row.
inline std::string png_rule_broken(const std::string& bytes, const PngHeader& expected,
                                   std::vector<PngChunk>* chunks = nullptr) {
  static const std::string signature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.compare(0, signature.size(), signature) != 0) return "no PNG signature";
  std::vector<PngChunk> read;
  std::size_t pos = signature.size();
  while (pos < bytes.size()) {
    if (bytes.size() - pos < 12) return "a chunk cut short at byte " + std::to_string(pos);
    const std::uint32_t length = png_be32(&bytes[pos]);
    if (length > 0x7fffffffu || length > bytes.size() - pos - 12)
      return "a chunk's length runs past the file at byte " + std::to_string(pos);
    PngChunk c{bytes.substr(pos + 4, 4), bytes.substr(pos + 8, length)};
    for (const char ch : c.type)
      if (!((ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z'))) return "a chunk type not four letters at byte " + std::to_string(pos);
    if (c.type[2] < 'A' || c.type[2] > 'Z') return c.type + ": reserved bit set";
    if (png_crc(c.type, c.data) != png_be32(&bytes[pos + 8 + length])) return c.type + " at byte " + std::to_string(pos) + ": CRC wrong";
    pos += 12 + length;
    read.push_back(std::move(c));
    if (read.back().type == "IEND") break;
  }
  if (read.empty() || read.front().type != "IHDR") return "IHDR not first";
  if (read.back().type != "IEND") return "no IEND";
  if (!read.back().data.empty()) return "IEND not empty";
  if (pos != bytes.size()) return std::to_string(bytes.size() - pos) + " bytes after IEND";

  const std::string& ihdr = read.front().data;
  if (ihdr.size() != 13) return "IHDR not 13 bytes";
  const auto depth = static_cast<unsigned char>(ihdr[8]), colour = static_cast<unsigned char>(ihdr[9]);
  if (png_be32(&ihdr[0]) != expected.width || png_be32(&ihdr[4]) != expected.height) return "IHDR: another size";
  if (depth != expected.bit_depth) return "IHDR: bit depth " + std::to_string(depth);
  if (colour != expected.colour_type) return "IHDR: colour type " + std::to_string(colour);
  if (ihdr[10] != 0 || ihdr[11] != 0) return "IHDR: compression or filter method not 0";
  if (ihdr[12] != 0) return "IHDR: interlaced";

  // Where each chunk stands relative to the image data.
  std::string idat;
  bool idat_seen = false, idat_ended = false, srgb = false;
  std::set<std::string> once;
  for (std::size_t i = 1; i + 1 < read.size(); ++i) {
    const PngChunk& c = read[i];
    if (c.type == "IHDR" || c.type == "IEND") return c.type + " twice";
    if (c.type == "IDAT") {
      if (idat_ended) return "IDAT chunks not consecutive";
      idat_seen = true;
      idat += c.data;
      continue;
    }
    idat_ended = idat_seen;
    if (c.type == "PLTE") {
      if (colour == 0 || colour == 4) return "PLTE in a grey image";
      if (idat_seen) return "PLTE after IDAT";
      continue;
    }
    if (c.type[0] >= 'A' && c.type[0] <= 'Z') return "unknown critical chunk " + c.type;
    const bool before_idat = c.type == "gAMA" || c.type == "sRGB" || c.type == "cHRM" || c.type == "iCCP" ||
                             c.type == "pHYs" || c.type == "oFFs";
    if (before_idat && idat_seen) return c.type + " after IDAT";
    if (before_idat && !once.insert(c.type).second) return c.type + " twice";
    if (c.type == "gAMA" && (c.data.size() != 4 || png_be32(c.data.data()) == 0)) return "gAMA: not 4 bytes of a gamma";
    if (c.type == "sRGB") {
      if (c.data.size() != 1 || static_cast<unsigned char>(c.data[0]) > 3) return "sRGB: not one rendering intent 0-3";
      srgb = true;
    }
    if (c.type == "cHRM" && c.data.size() != 32) return "cHRM: not 32 bytes";
    if ((c.type == "pHYs" || c.type == "oFFs") && (c.data.size() != 9 || static_cast<unsigned char>(c.data[8]) > 1))
      return c.type + ": not 9 bytes with a unit 0 or 1";
    if (c.type == "tEXt") {
      const std::size_t zero = c.data.find('\0');
      if (zero == std::string::npos || !png_keyword_ok(c.data.substr(0, zero))) return "tEXt: no valid keyword";
      if (c.data.find('\0', zero + 1) != std::string::npos) return "tEXt: a zero byte in its text";
    }
  }
  if (!idat_seen) return "no IDAT";
  if (srgb && once.count("iCCP") != 0) return "both sRGB and iCCP";
  for (const PngChunk& c : read) {
    if (srgb && c.type == "gAMA" && png_be32(c.data.data()) != 45455) return "gAMA: not sRGB's 45455 beside sRGB";
    if (srgb && c.type == "cHRM") {
      static constexpr std::array<std::uint32_t, 8> srgb_chrm = {31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000};
      for (std::size_t k = 0; k < srgb_chrm.size(); ++k)
        if (png_be32(&c.data[4 * k]) != srgb_chrm[k]) return "cHRM: not sRGB's white and primaries beside sRGB";
    }
  }

  // The image data: one zlib stream, inflating to exactly the filtered rows.
  const int channels = colour == 6 ? 4 : colour == 2 ? 3 : colour == 4 ? 2 : 1;
  const std::size_t row_bytes = (static_cast<std::size_t>(expected.width) * static_cast<std::size_t>(channels) *
                                     static_cast<std::size_t>(depth) + 7) / 8;
  const std::size_t want = static_cast<std::size_t>(expected.height) * (1 + row_bytes);
  std::string rows(want + 1, '\0');  // one byte more: a stream that makes too much shows
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return "zlib would not start";
  z.next_in = reinterpret_cast<Bytef*>(idat.data());
  z.avail_in = static_cast<uInt>(idat.size());
  z.next_out = reinterpret_cast<Bytef*>(rows.data());
  z.avail_out = static_cast<uInt>(rows.size());
  const int status = inflate(&z, Z_FINISH);
  const std::size_t made = rows.size() - z.avail_out, left = z.avail_in;
  inflateEnd(&z);
  if (status != Z_STREAM_END) return "IDAT: not one whole zlib stream (zlib status " + std::to_string(status) + ")";
  if (left != 0) return "IDAT: bytes after the zlib stream";
  if (made != want) return "IDAT: " + std::to_string(made) + " bytes of rows, not " + std::to_string(want);
  for (std::size_t y = 0; y < expected.height; ++y)
    if (static_cast<unsigned char>(rows[y * (1 + row_bytes)]) > 4) return "row " + std::to_string(y) + ": filter type not 0-4";
  if (chunks != nullptr) *chunks = std::move(read);
  return "";
}

}  // namespace lc::test
