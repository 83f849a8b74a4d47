// The file layout read here is OpenEXR's (openexr.com, "OpenEXR File
// Layout" and "Technical Introduction"): the magic number and version,
// the header's attributes (name, type, size, value) up to an empty name,
// the offset table (one 64-bit file position per block of scanlines), then
// the blocks, each its first row, its data's size and the data.  A block
// holds its rows one after another, each row its channels in the header's
// (alphabetical) order, each channel `width` values.  ZIP (16 rows a block)
// and ZIPS (1 row) store the block's bytes zlib-compressed after two
// reversible steps that help deflate: the bytes split into even and odd
// halves, then each byte replaced by its difference to the one before plus
// 128.  A block whose compressed form would not be smaller is stored raw.
#include "image/exr_rgb_reader.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <string_view>
#include <vector>

namespace lc {

namespace {

constexpr std::uint32_t exr_magic = 20000630;
// The version: 2, with no flag bit but "long names" (attribute names over
// 31 bytes; the layout is the same): not tiled, deep or multi-part.
constexpr std::uint32_t version_number = 2, long_names_flag = 0x400;

enum class Compression : std::uint8_t { none = 0, zips = 2, zip = 3 };  // OpenEXR's numbers; RLE (1) and the rest are not read here
constexpr std::int32_t pixel_float = 2;

template <class T>
T little_endian(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);  // x86-64 and every machine OpenEXR's layout is read on here are little-endian
  return v;
}
static_assert(std::endian::native == std::endian::little, "the EXR reader takes the file's bytes as they are");

// The header's facts this reader needs, and whether it can read the file.
struct Layout {
  int width = 0, height = 0;
  int rows_per_block = 1;
  Compression compression = Compression::none;
  int channels = 0;          // 3 (B, G, R) or 4 (A, B, G, R), in the file's order
  bool alpha = false;
  std::size_t data_start = 0;  // the offset table's first byte
};

struct Box {
  std::int32_t x0, y0, x1, y1;
};

Box box_at(const unsigned char* p) {
  return {little_endian<std::int32_t>(p), little_endian<std::int32_t>(p + 4), little_endian<std::int32_t>(p + 8),
          little_endian<std::int32_t>(p + 12)};
}

// The channel list's value: names and FLOAT at full sampling, exactly
// "B", "G", "R" or "A", "B", "G", "R" (sorted, as every writer stores them).
bool read_channels(std::string_view value, Layout& layout) {
  std::vector<std::string_view> names;
  std::size_t at = 0;
  while (at < value.size() && value[at] != '\0') {
    const std::size_t end = value.find('\0', at);
    if (end == std::string_view::npos || value.size() - end - 1 < 16) return false;
    const auto* rest = reinterpret_cast<const unsigned char*>(value.data() + end + 1);
    const auto type = little_endian<std::int32_t>(rest);
    const auto x_sampling = little_endian<std::int32_t>(rest + 8), y_sampling = little_endian<std::int32_t>(rest + 12);
    if (type != pixel_float || x_sampling != 1 || y_sampling != 1) return false;
    names.push_back(value.substr(at, end - at));
    at = end + 1 + 16;
  }
  if (at + 1 != value.size()) return false;  // the list ends with one empty name, and the value there
  static constexpr std::array<std::string_view, 3> bgr = {"B", "G", "R"};
  static constexpr std::array<std::string_view, 4> abgr = {"A", "B", "G", "R"};
  if (std::equal(names.begin(), names.end(), bgr.begin(), bgr.end())) {
    layout.channels = 3;
  } else if (std::equal(names.begin(), names.end(), abgr.begin(), abgr.end())) {
    layout.channels = 4;
    layout.alpha = true;
  } else {
    return false;
  }
  return true;
}

// Reads the header of `file`; nullopt unless it is the layout this reader takes.
std::optional<Layout> read_layout(const std::vector<unsigned char>& file) {
  if (file.size() < 8 || little_endian<std::uint32_t>(file.data()) != exr_magic ||
      (little_endian<std::uint32_t>(file.data() + 4) & ~long_names_flag) != version_number)
    return std::nullopt;
  Layout layout;
  bool have_channels = false, have_compression = false, have_line_order = false;
  std::optional<Box> data_window, display_window;
  std::size_t at = 8;
  for (;;) {
    if (at >= file.size()) return std::nullopt;
    const auto* base = reinterpret_cast<const char*>(file.data());
    const std::string_view rest(base + at, file.size() - at);
    if (rest.front() == '\0') {
      at += 1;
      break;
    }
    const std::size_t name_end = rest.find('\0');
    if (name_end == std::string_view::npos) return std::nullopt;
    const std::size_t type_end = rest.find('\0', name_end + 1);
    if (type_end == std::string_view::npos || rest.size() - type_end - 1 < 4) return std::nullopt;
    const std::string_view name = rest.substr(0, name_end), type = rest.substr(name_end + 1, type_end - name_end - 1);
    const auto size = little_endian<std::int32_t>(reinterpret_cast<const unsigned char*>(rest.data() + type_end + 1));
    if (size < 0 || rest.size() - type_end - 5 < static_cast<std::size_t>(size)) return std::nullopt;
    const std::string_view value = rest.substr(type_end + 5, static_cast<std::size_t>(size));
    const auto* v = reinterpret_cast<const unsigned char*>(value.data());
    if (name == "channels") {
      if (type != "chlist" || !read_channels(value, layout)) return std::nullopt;
      have_channels = true;
    } else if (name == "compression") {
      if (type != "compression" || size != 1) return std::nullopt;
      const auto c = static_cast<Compression>(v[0]);
      if (c != Compression::none && c != Compression::zips && c != Compression::zip) return std::nullopt;
      layout.compression = c;
      layout.rows_per_block = c == Compression::zip ? 16 : 1;
      have_compression = true;
    } else if (name == "dataWindow" || name == "displayWindow") {
      if (type != "box2i" || size != 16) return std::nullopt;
      (name == "dataWindow" ? data_window : display_window) = box_at(v);
    } else if (name == "lineOrder") {
      // Any order: the offset table is by row all the same, and each block says its row.
      if (type != "lineOrder" || size != 1) return std::nullopt;
      have_line_order = true;
    } else if (name == "tiles" || name == "type" || name == "chunkCount") {
      return std::nullopt;  // a tiled, deep or multi-part file
    }
    at += type_end + 5 + static_cast<std::size_t>(size);
  }
  if (!have_channels || !have_compression || !have_line_order || !data_window || !display_window) return std::nullopt;
  const Box d = *data_window;
  if (d.x0 != 0 || d.y0 != 0 || d.x0 != display_window->x0 || d.y0 != display_window->y0 ||
      d.x1 != display_window->x1 || d.y1 != display_window->y1)
    return std::nullopt;
  if (d.x1 < 0 || d.y1 < 0 || d.x1 >= max_image_side || d.y1 >= max_image_side) return std::nullopt;
  layout.width = d.x1 + 1;
  layout.height = d.y1 + 1;
  layout.data_start = at;
  return layout;
}

// Undoes zip's two steps on `packed` (the inflated block) into `raw`: the
// running sum of the differences, then the halves merged back.
void unpredict_and_merge(std::vector<unsigned char>& packed, unsigned char* raw) {
  const std::size_t n = packed.size();
  unsigned char* t = packed.data();
  for (std::size_t i = 1; i < n; ++i) t[i] = static_cast<unsigned char>(t[i - 1] + t[i] - 128);
  const unsigned char* even = t;
  const unsigned char* odd = t + (n + 1) / 2;
  for (std::size_t i = 0; i < n / 2; ++i) {
    raw[2 * i] = even[i];
    raw[2 * i + 1] = odd[i];
  }
  if (n % 2 != 0) raw[n - 1] = even[n / 2];
}

struct DecompressorFree {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

}  // namespace

std::optional<FrameImage> read_rgb_exr(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return std::nullopt;
  const std::streamoff length = in.tellg();
  if (length <= 0) return std::nullopt;
  std::vector<unsigned char> file(static_cast<std::size_t>(length));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(file.data()), length)) return std::nullopt;

  const std::optional<Layout> layout = read_layout(file);
  if (!layout) return std::nullopt;
  const std::size_t w = static_cast<std::size_t>(layout->width), h = static_cast<std::size_t>(layout->height);
  const std::size_t nch = static_cast<std::size_t>(layout->channels);
  const std::size_t row_bytes = nch * w * sizeof(float);
  const std::size_t blocks = (h + static_cast<std::size_t>(layout->rows_per_block) - 1) / static_cast<std::size_t>(layout->rows_per_block);
  if (file.size() - layout->data_start < 8 * blocks) return std::nullopt;

  std::unique_ptr<libdeflate_decompressor, DecompressorFree> inflater(libdeflate_alloc_decompressor());
  if (!inflater) return std::nullopt;
  FrameImage image;
  image.width = layout->width;
  image.height = layout->height;
  image.rgb.resize(3 * w * h);
  if (layout->alpha) image.alpha.resize(w * h);
  std::vector<unsigned char> packed, raw;
  for (std::size_t b = 0; b < blocks; ++b) {
    const auto offset = little_endian<std::uint64_t>(&file[layout->data_start + 8 * b]);
    if (offset > file.size() || file.size() - offset < 8) return std::nullopt;
    const std::size_t y0 = b * static_cast<std::size_t>(layout->rows_per_block);
    const std::size_t rows = std::min(static_cast<std::size_t>(layout->rows_per_block), h - y0);
    const auto block_y = little_endian<std::int32_t>(&file[offset]);
    const auto stored = little_endian<std::int32_t>(&file[offset + 4]);
    if (block_y != static_cast<std::int32_t>(y0) || stored < 0 || file.size() - offset - 8 < static_cast<std::size_t>(stored))
      return std::nullopt;
    const unsigned char* data = &file[offset + 8];
    const std::size_t size = rows * row_bytes;
    raw.resize(size);
    if (static_cast<std::size_t>(stored) == size) {
      std::memcpy(raw.data(), data, size);  // stored raw: zip would not have made it smaller
    } else {
      if (layout->compression == Compression::none) return std::nullopt;
      packed.resize(size);
      // With no "actual size" pointer, libdeflate succeeds only when the
      // stream ends exactly at `size` bytes, its Adler-32 checksum right.
      if (libdeflate_zlib_decompress(inflater.get(), data, static_cast<std::size_t>(stored), packed.data(), size,
                                     nullptr) != LIBDEFLATE_SUCCESS)
        return std::nullopt;
      unpredict_and_merge(packed, raw.data());
    }
    // Each row: A (when there), B, G, R planes of w floats each.
    for (std::size_t r = 0; r < rows; ++r) {
      const unsigned char* row = raw.data() + r * row_bytes;
      const std::size_t y = y0 + r;
      const unsigned char* first = row;
      if (layout->alpha) {
        std::memcpy(&image.alpha[y * w], row, w * sizeof(float));
        first += w * sizeof(float);
      }
      float* out = &image.rgb[3 * y * w];
      for (std::size_t c = 0; c < 3; ++c) {
        const unsigned char* plane = first + (2 - c) * w * sizeof(float);  // R is the last plane, B the first
        for (std::size_t x = 0; x < w; ++x) out[3 * x + c] = little_endian<float>(plane + x * sizeof(float));
      }
    }
  }
  return image;
}

}  // namespace lc
