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
#include <new>
#include <span>
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
  int channels = 0;  // 3 (B, G, R) or 4 (A, B, G, R), in the file's order
  bool alpha = false;
  bool decreasing_y = false;  // the blocks stored bottom first
  std::size_t data_start = 0;  // the offset table's first byte
};

struct Box {
  std::int32_t x0, y0, x1, y1;
};

Box box_at(const unsigned char* p) {
  return {little_endian<std::int32_t>(p), little_endian<std::int32_t>(p + 4), little_endian<std::int32_t>(p + 8),
          little_endian<std::int32_t>(p + 12)};
}

// The size OpenEXR reads a value of `type` by, whatever size the file
// declares (0: it reads the declared size: strings and types it does not
// know; -1: a type whose size is in its value, which this reader does not
// take).  A file declaring another size is read differently by the two, so
// it is left to OpenImageIO.
int value_size_of(std::string_view type) {
  struct Fixed {
    std::string_view type;
    int size;
  };
  static constexpr std::array<Fixed, 21> fixed = {{{"int", 4},          {"float", 4},        {"double", 8},
                                                   {"v2i", 8},          {"v2f", 8},          {"v2d", 16},
                                                   {"v3i", 12},         {"v3f", 12},         {"v3d", 24},
                                                   {"box2i", 16},       {"box2f", 16},       {"m33f", 36},
                                                   {"m33d", 72},        {"m44f", 64},        {"m44d", 128},
                                                   {"rational", 8},     {"timecode", 8},     {"keycode", 28},
                                                   {"chromaticities", 32}, {"tiledesc", 9}, {"envmap", 1}}};
  for (const Fixed& f : fixed)
    if (f.type == type) return f.size;
  if (type == "compression" || type == "lineOrder" || type == "deepImageState") return 1;
  if (type == "preview") return -1;
  return 0;
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
  layout.alpha = std::equal(names.begin(), names.end(), abgr.begin(), abgr.end());
  if (!layout.alpha && !std::equal(names.begin(), names.end(), bgr.begin(), bgr.end())) return false;
  layout.channels = layout.alpha ? 4 : 3;
  return true;
}

// What parsing a header found.
enum class HeaderEnd { layout, other, needs_more };

// Reads the header at the start of `bytes` (the file, or its first part).
// layout: the layout this reader takes, whole in `bytes`; other: any
// other file, or one OpenEXR would refuse or read otherwise; needs_more:
// `bytes` ends inside the header.
HeaderEnd read_layout(std::span<const unsigned char> bytes, Layout& layout) {
  if (bytes.size() < 8) return HeaderEnd::needs_more;
  const auto version = little_endian<std::uint32_t>(bytes.data() + 4);
  if (little_endian<std::uint32_t>(bytes.data()) != exr_magic || (version & ~long_names_flag) != version_number)
    return HeaderEnd::other;
  const std::size_t longest_name = (version & long_names_flag) != 0 ? 255 : 31;
  std::vector<std::string_view> seen;
  std::optional<Box> data_window, display_window;
  bool have_channels = false, have_compression = false, have_line_order = false, have_aspect = false,
       have_window_center = false, have_window_width = false;
  const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::size_t at = 8;
  for (;;) {
    if (at >= all.size()) return HeaderEnd::needs_more;
    const std::string_view rest = all.substr(at);
    if (rest.front() == '\0') {
      at += 1;
      break;
    }
    const std::size_t name_end = rest.find('\0');
    if (name_end == std::string_view::npos) return HeaderEnd::needs_more;
    const std::size_t type_end = rest.find('\0', name_end + 1);
    if (type_end == std::string_view::npos || rest.size() - type_end - 1 < 4) return HeaderEnd::needs_more;
    const std::string_view name = rest.substr(0, name_end), type = rest.substr(name_end + 1, type_end - name_end - 1);
    if (name.size() > longest_name || type.size() > longest_name) return HeaderEnd::other;
    // OpenEXR merges an attribute given twice; this reader takes none so.
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) return HeaderEnd::other;
    seen.push_back(name);
    const auto size = little_endian<std::int32_t>(reinterpret_cast<const unsigned char*>(rest.data() + type_end + 1));
    const int expected = value_size_of(type);
    if (size < 0 || expected < 0 || (expected > 0 && size != expected)) return HeaderEnd::other;
    if (rest.size() - type_end - 5 < static_cast<std::size_t>(size)) return HeaderEnd::needs_more;
    const std::string_view value = rest.substr(type_end + 5, static_cast<std::size_t>(size));
    const auto* v = reinterpret_cast<const unsigned char*>(value.data());
    if (name == "channels") {
      if (type != "chlist" || !read_channels(value, layout)) return HeaderEnd::other;
      have_channels = true;
    } else if (name == "compression") {
      if (type != "compression") return HeaderEnd::other;
      const auto c = static_cast<Compression>(v[0]);
      if (c != Compression::none && c != Compression::zips && c != Compression::zip) return HeaderEnd::other;
      layout.compression = c;
      layout.rows_per_block = c == Compression::zip ? 16 : 1;
      have_compression = true;
    } else if (name == "dataWindow" || name == "displayWindow") {
      if (type != "box2i") return HeaderEnd::other;
      (name == "dataWindow" ? data_window : display_window) = box_at(v);
    } else if (name == "lineOrder") {
      if (type != "lineOrder" || v[0] > 1) return HeaderEnd::other;  // increasing or decreasing y, not random
      layout.decreasing_y = v[0] == 1;
      have_line_order = true;
    } else if (name == "pixelAspectRatio") {
      // Within the range OpenEXR takes; anything else is its to judge.
      const auto ratio = little_endian<float>(v);
      if (type != "float" || !(ratio >= 1e-3f && ratio <= 1e3f)) return HeaderEnd::other;
      have_aspect = true;
    } else if (name == "screenWindowWidth") {
      const auto width = little_endian<float>(v);
      if (type != "float" || !(width >= 0.0f && width <= 1e30f)) return HeaderEnd::other;
      have_window_width = true;
    } else if (name == "screenWindowCenter") {
      if (type != "v2f") return HeaderEnd::other;
      have_window_center = true;
    } else if (name == "tiles" || name == "type" || name == "chunkCount") {
      return HeaderEnd::other;  // a tiled, deep or multi-part file
    }
    at += type_end + 5 + static_cast<std::size_t>(size);
  }
  // The attributes OpenEXR requires of every file.
  if (!have_channels || !have_compression || !have_line_order || !data_window || !display_window || !have_aspect ||
      !have_window_center || !have_window_width)
    return HeaderEnd::other;
  const Box d = *data_window;
  if (d.x0 != 0 || d.y0 != 0 || d.x0 != display_window->x0 || d.y0 != display_window->y0 ||
      d.x1 != display_window->x1 || d.y1 != display_window->y1)
    return HeaderEnd::other;
  if (d.x1 < 0 || d.y1 < 0 || d.x1 >= max_image_side || d.y1 >= max_image_side) return HeaderEnd::other;
  layout.width = d.x1 + 1;
  layout.height = d.y1 + 1;
  layout.data_start = at;
  return HeaderEnd::layout;
}

// Where a block is in the file, and its rows.
struct Block {
  std::size_t data = 0;    // its data's first byte
  std::size_t stored = 0;  // its data's size in the file
  std::size_t y0 = 0, rows = 0;
};

// The file's blocks, checked before anything is allocated for them: each
// where the offset table says, saying its first row, its size within the
// file and at most its raw size (OpenEXR inflates a block only when it is
// smaller), a raw-size block of an uncompressed file, and each right after
// the one before it in the file's line order (OpenEXR reads a whole image
// on from one block to the next, whatever the table says).  Empty when
// they are not so.
std::vector<Block> blocks_of(std::span<const unsigned char> file, const Layout& layout, std::size_t row_bytes) {
  const std::size_t h = static_cast<std::size_t>(layout.height), per = static_cast<std::size_t>(layout.rows_per_block);
  const std::size_t count = (h + per - 1) / per;
  if (file.size() < layout.data_start || file.size() - layout.data_start < 8 * count) return {};
  std::vector<Block> blocks(count);
  for (std::size_t b = 0; b < count; ++b) {
    const auto offset = little_endian<std::uint64_t>(&file[layout.data_start + 8 * b]);
    if (offset > file.size() || file.size() - offset < 8) return {};
    Block& k = blocks[b];
    k.y0 = b * per;
    k.rows = std::min(per, h - k.y0);
    const auto y = little_endian<std::int32_t>(&file[offset]);
    const auto stored = little_endian<std::int32_t>(&file[offset + 4]);
    const std::size_t raw = k.rows * row_bytes;
    if (y != static_cast<std::int32_t>(k.y0) || stored <= 0 || static_cast<std::size_t>(stored) > raw ||
        file.size() - offset - 8 < static_cast<std::size_t>(stored))
      return {};
    if (layout.compression == Compression::none && static_cast<std::size_t>(stored) != raw) return {};
    // Deflate makes at most 1,032 bytes of a byte (RFC 1951: a 258-byte
    // match in as few as 2 bits), so a block claiming more is not one.
    if (static_cast<std::size_t>(stored) * 1032 + 64 < raw) return {};
    k.data = static_cast<std::size_t>(offset) + 8;
    k.stored = static_cast<std::size_t>(stored);
  }
  for (std::size_t i = 1; i < count; ++i) {
    const Block& before = layout.decreasing_y ? blocks[count - i] : blocks[i - 1];
    const Block& next = layout.decreasing_y ? blocks[count - 1 - i] : blocks[i];
    if (next.data != before.data + before.stored + 8) return {};
  }
  return blocks;
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


// Reads up to `n` bytes of `in` from where it stands onto the end of `bytes`.
bool read_more(std::ifstream& in, std::vector<unsigned char>& bytes, std::size_t n) {
  const std::size_t had = bytes.size();
  bytes.resize(had + n);
  in.read(reinterpret_cast<char*>(bytes.data() + had), static_cast<std::streamsize>(n));
  bytes.resize(had + static_cast<std::size_t>(in.gcount()));
  return !in.bad();
}

// The frame in `file`, its layout `layout`; nullopt when a block
// does not read whole.
std::optional<FrameImage> read_frame(std::span<const unsigned char> file, const Layout& layout) {
  const std::size_t w = static_cast<std::size_t>(layout.width), h = static_cast<std::size_t>(layout.height);
  const std::size_t row_bytes = static_cast<std::size_t>(layout.channels) * w * sizeof(float);
  const std::vector<Block> blocks = blocks_of(file, layout, row_bytes);
  if (blocks.empty()) return std::nullopt;
  std::unique_ptr<libdeflate_decompressor, DecompressorFree> inflater(libdeflate_alloc_decompressor());
  if (!inflater) return std::nullopt;
  FrameImage image;
  image.width = layout.width;
  image.height = layout.height;
  image.rgb.resize(3 * w * h);
  if (layout.alpha) image.alpha.resize(w * h);
  std::vector<unsigned char> packed, raw;
  for (const Block& block : blocks) {
    const unsigned char* data = &file[block.data];
    const std::size_t size = block.rows * row_bytes;
    raw.resize(size);
    if (block.stored == size) {
      std::memcpy(raw.data(), data, size);  // stored raw: zip would not have made it smaller
    } else {
      packed.resize(size);
      // With no "actual size" pointer, libdeflate succeeds only when the
      // stream ends exactly at `size` bytes, its Adler-32 checksum right.
      if (libdeflate_zlib_decompress(inflater.get(), data, block.stored, packed.data(), size, nullptr) !=
          LIBDEFLATE_SUCCESS)
        return std::nullopt;
      unpredict_and_merge(packed, raw.data());
    }
    // Each row: A (when there), B, G, R planes of w floats each.
    for (std::size_t r = 0; r < block.rows; ++r) {
      const unsigned char* row = raw.data() + r * row_bytes;
      const std::size_t y = block.y0 + r;
      const unsigned char* first = row;
      if (layout.alpha) {
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

}  // namespace

std::optional<FrameImage> read_rgb_exr(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const std::uintmax_t length = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  try {
    // The header first (a frame's is ~500 bytes), so a file in another
    // layout is left to OpenImageIO without reading it all.
    std::vector<unsigned char> file;
    Layout layout;
    HeaderEnd header = HeaderEnd::needs_more;
    for (std::size_t want = 4096; header == HeaderEnd::needs_more; want *= 4) {
      if (!read_more(in, file, want - file.size())) return std::nullopt;
      header = read_layout(file, layout);
      if (header == HeaderEnd::needs_more && file.size() < want) return std::nullopt;  // the file ended in it
    }
    if (header != HeaderEnd::layout) return std::nullopt;
    if (length > file.size() && !read_more(in, file, static_cast<std::size_t>(length - file.size()))) return std::nullopt;
    return read_frame(file, layout);
  } catch (const std::bad_alloc&) {
    return std::nullopt;  // a header claiming more than memory holds: OpenImageIO's to refuse
  }
}

}  // namespace lc
