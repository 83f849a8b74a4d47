// The PNG format: ISO/IEC 15948 (W3C PNG, 2nd edition): chunks of length,
// type, data and CRC-32; the image rows each led by a filter type byte and
// filtered (None, Sub, Up, Average, Paeth), all rows deflated as one zlib
// stream split over IDAT chunks.
//
// What libpng 1.6 (pngwutil.c) does with the settings OpenImageIO 2.4
// gives it, reproduced here byte for byte:
// - each row's filter: the one of the five whose filtered bytes, each read
//   as a signed byte, have the least sum of magnitudes; the earlier one on
//   a tie, in the order None, Sub, Up, Average, Paeth (the "minimum sum of
//   absolute differences" heuristic the PNG specification suggests); for a
//   one-row image only None and Sub, for a one-column image None and Up;
// - zlib at level 6, the default strategy, memory level 8, a 32 KiB window
//   made smaller for an image of at most 16 KiB (windowBits down while the
//   data plus 262 fits in half the window), and then the stream's first
//   two bytes rewritten to claim the smallest window the data fits in;
// - IDAT chunks of 8,192 bytes, the last one what is left.
#include "image/png_encoder.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace lc {

namespace {

constexpr std::size_t idat_size = 8192;  // libpng's PNG_ZBUF_SIZE
constexpr int zlib_level = 6, zlib_memory_level = 8, largest_window_bits = 15;
// PNG's own limit is 2^31 - 1; this one keeps a row's bytes far inside
// zlib's 32-bit counts and is twice the largest frame lightcone makes.
constexpr int max_png_side = 65536;

enum Filter : std::uint8_t { none = 0, sub = 1, up = 2, average = 3, paeth = 4 };

void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

void put_chunk(std::vector<unsigned char>& out, std::string_view type, std::span<const unsigned char> data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type.begin(), type.end());
  out.insert(out.end(), data.begin(), data.end());
  const auto crc = ::crc32(0L, out.data() + start, static_cast<uInt>(out.size() - start));
  put32(out, static_cast<std::uint32_t>(crc));
}

std::vector<unsigned char> be32s(std::initializer_list<std::uint32_t> values) {
  std::vector<unsigned char> bytes;
  for (std::uint32_t v : values) put32(bytes, v);
  return bytes;
}

// A filtered byte's weight in the heuristic: its magnitude as a signed byte.
inline unsigned weight(std::uint8_t v) { return v < 128 ? v : 256u - v; }

inline std::uint8_t paeth_predictor(int a, int b, int c) {
  const int p = b - c, q = a - c;
  const int pa = std::abs(p), pb = std::abs(q), pc = std::abs(p + q);
  return static_cast<std::uint8_t>((pa <= pb && pa <= pc) ? a : (pb <= pc) ? b : c);
}

// Filters `row` (n bytes, 3 a pixel) against `above` (zeros for the first
// row) with every filter into `candidates` (4 rows of n: Sub, Up, Average,
// Paeth), and returns each filter's heuristic sum (None's too).  Plain
// loops over bytes the compiler vectorises.
std::array<unsigned long, 5> filter_row(const std::uint8_t* row, const std::uint8_t* above, std::size_t n,
                                        std::uint8_t* candidates) {
  constexpr std::size_t bpp = 3;
  std::uint8_t* s = candidates;
  std::uint8_t* u = candidates + n;
  std::uint8_t* a = candidates + 2 * n;
  std::uint8_t* p = candidates + 3 * n;
  for (std::size_t i = 0; i < std::min(bpp, n); ++i) {
    s[i] = row[i];
    a[i] = static_cast<std::uint8_t>(row[i] - (above[i] >> 1));
    p[i] = static_cast<std::uint8_t>(row[i] - above[i]);
  }
  for (std::size_t i = bpp; i < n; ++i) {
    s[i] = static_cast<std::uint8_t>(row[i] - row[i - bpp]);
    a[i] = static_cast<std::uint8_t>(row[i] - ((row[i - bpp] + above[i]) >> 1));
    p[i] = static_cast<std::uint8_t>(row[i] - paeth_predictor(row[i - bpp], above[i], above[i - bpp]));
  }
  for (std::size_t i = 0; i < n; ++i) u[i] = static_cast<std::uint8_t>(row[i] - above[i]);
  std::array<unsigned long, 5> sums{};
  for (std::size_t i = 0; i < n; ++i) {
    sums[none] += weight(row[i]);
    sums[sub] += weight(s[i]);
    sums[up] += weight(u[i]);
    sums[average] += weight(a[i]);
    sums[paeth] += weight(p[i]);
  }
  return sums;
}

// libpng's window for `size` bytes of filtered data (png_deflate_claim).
int window_bits_for(std::size_t size) {
  int bits = largest_window_bits;
  if (size <= 16384) {
    std::size_t half = std::size_t{1} << (bits - 1);
    while (size + 262 <= half) {
      half >>= 1;
      --bits;
    }
  }
  return bits;
}

// libpng's rewrite of the stream's header for small images (optimize_cmf):
// the window it claims shrunk to the smallest that holds `size` bytes, the
// check bits made right again.
void claim_smallest_window(unsigned char* header, std::size_t size) {
  if (size > 16384) return;
  unsigned cmf = header[0];
  if ((cmf & 0x0f) != 8 || (cmf & 0xf0) > 0x70) return;
  unsigned cinfo = cmf >> 4;
  std::size_t half = std::size_t{1} << (cinfo + 7);
  if (size > half) return;
  do {
    half >>= 1;
    --cinfo;
  } while (cinfo > 0 && size <= half);
  cmf = (cmf & 0x0f) | (cinfo << 4);
  header[0] = static_cast<unsigned char>(cmf);
  unsigned flg = header[1] & 0xe0u;
  flg += 0x1f - ((cmf << 8) + flg) % 0x1f;
  header[1] = static_cast<unsigned char>(flg);
}

// The zlib stream of the filtered rows, fed a row at a time as libpng
// feeds it and cut into IDAT chunks as its buffer fills, so the frame is
// never held filtered whole.
class IdatStream {
 public:
  // `size`: all the filtered rows' bytes, which decide the window.
  IdatStream(std::vector<unsigned char>& png, std::size_t size) : png_(png), size_(size) {
    if (deflateInit2(&z_, zlib_level, Z_DEFLATED, window_bits_for(size), zlib_memory_level, Z_DEFAULT_STRATEGY) != Z_OK)
      throw std::runtime_error("zlib could not start a deflate stream");
    z_.next_out = buffer_.data();
    z_.avail_out = static_cast<uInt>(buffer_.size());
  }
  IdatStream(const IdatStream&) = delete;
  IdatStream& operator=(const IdatStream&) = delete;
  ~IdatStream() { deflateEnd(&z_); }

  // One filtered row (n < 4 GiB: a row of at most 32768 pixels is ~96 KB).
  void add(const unsigned char* row, std::size_t n) {
    z_.next_in = const_cast<unsigned char*>(row);  // zlib's API is not const; it only reads
    z_.avail_in = static_cast<uInt>(n);
    while (z_.avail_in > 0 || z_.avail_out == 0) {
      if (deflate(&z_, Z_NO_FLUSH) == Z_STREAM_ERROR) throw std::runtime_error("zlib failed deflating a frame's rows");
      if (z_.avail_out == 0) emit(buffer_.size());
    }
  }

  // The stream's end, and its last chunk.
  void finish() {
    for (;;) {
      const int status = deflate(&z_, Z_FINISH);
      if (status != Z_OK && status != Z_STREAM_END)
        throw std::runtime_error("zlib failed ending a frame's stream");
      const std::size_t filled = buffer_.size() - z_.avail_out;
      if (z_.avail_out == 0 || status == Z_STREAM_END) emit(filled);
      if (status == Z_STREAM_END) return;
    }
  }

 private:
  // Writes the buffer's first `n` bytes as an IDAT chunk (none when empty).
  void emit(std::size_t n) {
    if (first_) claim_smallest_window(buffer_.data(), size_);
    first_ = false;
    if (n > 0) put_chunk(png_, "IDAT", std::span(buffer_).first(n));
    z_.next_out = buffer_.data();
    z_.avail_out = static_cast<uInt>(buffer_.size());
  }

  std::vector<unsigned char>& png_;
  std::size_t size_;
  z_stream z_{};
  std::array<unsigned char, idat_size> buffer_{};
  bool first_ = true;
};

}  // namespace

std::vector<unsigned char> encode_png8(std::span<const std::uint8_t> rgb, int width, int height) {
  if (width <= 0 || height <= 0 || width > max_png_side || height > max_png_side ||
      rgb.size() != 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument(fmt::format("encode_png8: {} bytes are not a {}x{} frame of 8-bit RGB (at most {} a side)",
                                            rgb.size(), width, height, max_png_side));
  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> ihdr = be32s({static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)});
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, not interlaced
  put_chunk(png, "IHDR", ihdr);
  put_chunk(png, "gAMA", be32s({45455}));  // 1 / 2.2, as libpng writes for sRGB
  put_chunk(png, "sRGB", std::vector<unsigned char>{3});  // rendering intent: absolute colorimetric
  // The sRGB white and primaries (x, y times 100,000), as libpng writes them.
  put_chunk(png, "cHRM", be32s({31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000}));
  put_chunk(png, "oFFs", std::vector<unsigned char>(9, 0));  // offset 0, 0 in pixels
  const std::string_view text("oiio:ColorSpace\0sRGB", 20);
  put_chunk(png, "tEXt", std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));

  // Each row filtered as libpng filters it, led by its filter's type.
  const std::size_t w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height), n = 3 * w;
  IdatStream stream(png, h * (n + 1));
  std::vector<std::uint8_t> zeros(n, 0), candidates(4 * n), filtered(n + 1);
  // libpng leaves out the filters that need a row above (one row) or a
  // pixel to the left (one column).
  std::array<bool, 5> allowed{true, true, true, true, true};
  if (h == 1) allowed[up] = allowed[average] = allowed[paeth] = false;
  if (w == 1) allowed[sub] = allowed[average] = allowed[paeth] = false;
  for (std::size_t y = 0; y < h; ++y) {
    const std::uint8_t* row = rgb.data() + y * n;
    const std::uint8_t* above = y == 0 ? zeros.data() : row - n;
    const auto sums = filter_row(row, above, n, candidates.data());
    int best = none;
    for (int f = sub; f <= paeth; ++f)
      if (allowed[f] && sums[f] < sums[best]) best = f;
    filtered[0] = static_cast<unsigned char>(best);
    const std::uint8_t* src = best == none ? row : candidates.data() + static_cast<std::size_t>(best - 1) * n;
    std::copy_n(src, n, filtered.data() + 1);
    stream.add(filtered.data(), n + 1);
  }
  stream.finish();
  put_chunk(png, "IEND", {});
  return png;
}

}  // namespace lc
