#include "video/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "durable_file.hpp"
#include "image/image_io.hpp"
#include "image/srgb.hpp"
#include "video/pixel_font.hpp"

namespace lc {

namespace {

// Layout constants in sheet pixels: the gap around thumbnails, and the
// label's font scale follows the thumbnail width (readable, not dominant).
constexpr int gap = 8;
constexpr float background = 0.01f;  // linear; about sRGB 25
constexpr float label = 0.7f;        // linear; about sRGB 218

// Resizes linear RGB by area averaging: each output pixel is the mean of the
// source area it covers (weighted by overlap), right both for shrinking a
// 1280-wide frame to a thumbnail and for blowing up a 32-pixel preview
// (then it is nearest-neighbour, keeping pixels crisp).
FrameImage resample(const FrameImage& src, int w, int h) {
  FrameImage out;
  out.width = w;
  out.height = h;
  out.rgb.assign(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
  // Per output column/row: the source pixels it overlaps and their weights.
  struct Span {
    int first;
    std::vector<double> weights;
  };
  auto spans = [](int n_src, int n_dst) {
    std::vector<Span> s(static_cast<std::size_t>(n_dst));
    const double ratio = static_cast<double>(n_src) / n_dst;
    for (int d = 0; d < n_dst; ++d) {
      const double a = d * ratio, b = (d + 1) * ratio;
      const int first = static_cast<int>(std::floor(a));
      const int last = std::min(n_src - 1, static_cast<int>(std::ceil(b)) - 1);
      Span& sp = s[static_cast<std::size_t>(d)];
      sp.first = first;
      for (int k = first; k <= last; ++k)
        sp.weights.push_back((std::min<double>(b, k + 1) - std::max<double>(a, k)) / ratio);
    }
    return s;
  };
  const std::vector<Span> xs = spans(src.width, w), ys = spans(src.height, h);
  for (int y = 0; y < h; ++y) {
    const Span& sy = ys[static_cast<std::size_t>(y)];
    for (int x = 0; x < w; ++x) {
      const Span& sx = xs[static_cast<std::size_t>(x)];
      double acc[3] = {0, 0, 0};
      for (std::size_t j = 0; j < sy.weights.size(); ++j)
        for (std::size_t i = 0; i < sx.weights.size(); ++i) {
          const double wgt = sy.weights[j] * sx.weights[i];
          const std::size_t p = 3 * ((static_cast<std::size_t>(sy.first) + j) * static_cast<std::size_t>(src.width) +
                                     static_cast<std::size_t>(sx.first) + i);
          for (int c = 0; c < 3; ++c) acc[c] += wgt * src.rgb[p + static_cast<std::size_t>(c)];
        }
      const std::size_t q = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x));
      for (int c = 0; c < 3; ++c) out.rgb[q + static_cast<std::size_t>(c)] = static_cast<float>(acc[c]);
    }
  }
  return out;
}

// Copies `tile` into `sheet` with its top-left corner at (x0, y0).
void paste(FrameImage& sheet, const FrameImage& tile, int x0, int y0) {
  for (int y = 0; y < tile.height; ++y)
    std::copy_n(&tile.rgb[3 * static_cast<std::size_t>(y) * static_cast<std::size_t>(tile.width)], 3 * tile.width,
                &sheet.rgb[3 * ((static_cast<std::size_t>(y0 + y)) * static_cast<std::size_t>(sheet.width) +
                                static_cast<std::size_t>(x0))]);
}

}  // namespace

std::vector<std::size_t> pick_evenly(std::size_t available, std::size_t count) {
  // Inputs: how many frames exist and how many to show; output: indices
  // round(k (available-1) / (count-1)), which are distinct when count < available.
  std::vector<std::size_t> picks;
  if (available == 0 || count == 0) return picks;
  if (available <= count || count == 1) {
    const std::size_t n = std::min(available, count);
    for (std::size_t i = 0; i < n; ++i) picks.push_back(i);
    return picks;
  }
  for (std::size_t k = 0; k < count; ++k)
    picks.push_back(static_cast<std::size_t>(std::llround(static_cast<double>(k) * static_cast<double>(available - 1) /
                                                           static_cast<double>(count - 1))));
  return picks;
}

FrameImage make_contact_sheet(const FrameSequence& sequence, const ContactSheetOptions& o) {
  // Inputs: a sequence's frames and the layout; output: the sheet.
  if (o.columns < 1 || o.columns > 64) throw std::invalid_argument(fmt::format("--columns {}: must be 1 to 64", o.columns));
  if (o.count < 1 || o.count > 4096) throw std::invalid_argument(fmt::format("--count {}: must be 1 to 4096", o.count));
  if (o.width > 16384) throw std::invalid_argument(fmt::format("--width {}: at most 16384", o.width));
  const int thumb_w = (o.width - gap * (o.columns + 1)) / o.columns;
  if (thumb_w < 16)
    throw std::invalid_argument(fmt::format("--width {}: too narrow for {} columns (each needs 16 pixels and a {}-pixel gap)",
                                            o.width, o.columns, gap));
  if (sequence.files.empty()) throw std::runtime_error(fmt::format("shot {}: no frames", sequence.shot));

  const std::vector<std::size_t> picks = pick_evenly(sequence.files.size(), static_cast<std::size_t>(o.count));
  const int n = static_cast<int>(picks.size());
  const int columns = std::min(o.columns, n);
  const int rows = (n + columns - 1) / columns;
  FrameImage first = read_image_linear(sequence.files[picks.front()]);
  const int first_w = first.width, first_h = first.height;  // every pick must match
  const int thumb_h = std::max(1, static_cast<int>(std::lround(static_cast<double>(thumb_w) * first.height / first.width)));
  const int scale = std::max(1, thumb_w / 160);  // labels ~1/5 of a 160-pixel thumbnail's width
  const int label_h = pixel_font::text_height(scale) + 2 * scale;
  const int cell_h = thumb_h + label_h;

  FrameImage sheet;
  sheet.width = gap + columns * (thumb_w + gap);
  sheet.height = gap + rows * (cell_h + gap);
  if (sheet.height > 32768)
    throw std::invalid_argument(fmt::format("--count {} / --columns {}: the sheet would be {} pixels high; use fewer "
                                            "frames or more columns",
                                            o.count, o.columns, sheet.height));
  sheet.rgb.assign(3 * static_cast<std::size_t>(sheet.width) * static_cast<std::size_t>(sheet.height), background);

  for (int k = 0; k < n; ++k) {
    const std::size_t idx = picks[static_cast<std::size_t>(k)];
    FrameImage frame = k == 0 ? std::move(first) : read_image_linear(sequence.files[idx]);
    if (frame.width != first_w || frame.height != first_h)
      throw std::runtime_error(fmt::format("{}: {}x{}, but {} is {}x{}", sequence.files[idx].string(), frame.width,
                                           frame.height, sequence.files[picks.front()].filename().string(), first_w,
                                           first_h));
    const int x0 = gap + (k % columns) * (thumb_w + gap);
    const int y0 = gap + (k / columns) * (cell_h + gap);
    paste(sheet, resample(frame, thumb_w, thumb_h), x0, y0);
    const std::string text = std::to_string(sequence.frames[idx]);
    const int tx = x0 + (thumb_w - pixel_font::text_width(text, scale)) / 2;
    const int ty = y0 + thumb_h + scale;
    pixel_font::for_each_pixel(text, scale, [&](int px, int py) {
      const int x = tx + px, y = ty + py;
      if (x < 0 || x >= sheet.width) return;  // a label wider than its cell is clipped
      const std::size_t q = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(sheet.width) + static_cast<std::size_t>(x));
      sheet.rgb[q] = sheet.rgb[q + 1] = sheet.rgb[q + 2] = label;
    });
  }
  return sheet;
}

void write_contact_sheet(const FrameSequence& sequence, const ContactSheetOptions& options,
                         const std::filesystem::path& out) {
  // Builds the sheet first (reading every pick), then writes it atomically.
  const FrameImage sheet = make_contact_sheet(sequence, options);
  DurableFile file(out);
  write_png(file.temp_path(), sheet);
  file.commit();
}

}  // namespace lc
