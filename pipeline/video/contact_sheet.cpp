#include "video/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "store/durable_file.hpp"
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

using Span = AreaResampler::Span;

// The spans of n_dst output pixels over n_src source pixels.
std::vector<Span> spans(int n_src, int n_dst) {
  std::vector<Span> s(static_cast<std::size_t>(n_dst));
  const double ratio = static_cast<double>(n_src) / n_dst;
  for (int d = 0; d < n_dst; ++d) {
    const double a = d * ratio, b = (d + 1) * ratio;
    const int first = static_cast<int>(std::floor(a));
    const int last = std::min(n_src - 1, static_cast<int>(std::ceil(b)) - 1);
    Span& sp = s[static_cast<std::size_t>(d)];
    sp.first = first;
    for (int k = first; k <= last; ++k) sp.weights.push_back((std::min<double>(b, k + 1) - std::max<double>(a, k)) / ratio);
  }
  return s;
}

}  // namespace

AreaResampler::AreaResampler(int src_width, int src_height, int width, int height)
    : src_width_(src_width), width_(width), height_(height), columns_(spans(src_width, width)),
      acc_(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0),
      row_(3 * static_cast<std::size_t>(width)) {
  // Each source row's output rows, from the rows' spans.
  rows_of_.resize(static_cast<std::size_t>(src_height));
  const std::vector<Span> rows = spans(src_height, height);
  for (int y = 0; y < height; ++y) {
    const Span& sy = rows[static_cast<std::size_t>(y)];
    for (std::size_t j = 0; j < sy.weights.size(); ++j)
      rows_of_[static_cast<std::size_t>(sy.first) + j].push_back({y, sy.weights[j]});
  }
}

void AreaResampler::add_rows(int y0, int rows, std::span<const float> rgb) {
  // Each row is averaged along x first, then added to the output rows it
  // overlaps with their weights: the separable form of the area average.
  for (int r = 0; r < rows; ++r) {
    const std::size_t j = static_cast<std::size_t>(y0 + r);
    const float* src = rgb.data() + 3 * static_cast<std::size_t>(r) * static_cast<std::size_t>(src_width_);
    for (int x = 0; x < width_; ++x) {
      const Span& sx = columns_[static_cast<std::size_t>(x)];
      double a[3] = {0, 0, 0};
      for (std::size_t i = 0; i < sx.weights.size(); ++i)
        for (int c = 0; c < 3; ++c)
          a[c] += sx.weights[i] * src[3 * (static_cast<std::size_t>(sx.first) + i) + static_cast<std::size_t>(c)];
      for (int c = 0; c < 3; ++c) row_[3 * static_cast<std::size_t>(x) + static_cast<std::size_t>(c)] = a[c];
    }
    for (const auto& [y, weight] : rows_of_[j]) {
      double* out = &acc_[3 * static_cast<std::size_t>(y) * static_cast<std::size_t>(width_)];
      for (std::size_t k = 0; k < row_.size(); ++k) out[k] += weight * row_[k];
    }
  }
}

FrameImage AreaResampler::result() const {
  // The sums are kept in double; the image is float like every frame.
  FrameImage out;
  out.width = width_;
  out.height = height_;
  out.rgb.resize(acc_.size());
  std::transform(acc_.begin(), acc_.end(), out.rgb.begin(), [](double v) { return static_cast<float>(v); });
  return out;
}

FrameImage thumbnail(const std::filesystem::path& file, int width, int height, std::pair<int, int> expected) {
  // The resampler is made at the first band, which says the frame's size.
  std::optional<AreaResampler> resampler;
  read_image_bands(file, thumbnail_band_rows, [&](const ImageBand& band) {
    if (!resampler) {
      if (band.width != expected.first || band.height != expected.second)
        throw std::runtime_error(fmt::format("{}: {}x{}, but the sequence's first frame is {}x{}", file.string(),
                                             band.width, band.height, expected.first, expected.second));
      resampler.emplace(band.width, band.height, width, height);
    }
    resampler->add_rows(band.y0, band.rows, band.rgb);
  });
  return resampler->result();
}

namespace {

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
  // Every pick must be the first's size; each is read a band at a time
  // into its thumbnail, so a huge frame costs a band, not its pixels.
  const auto [first_w, first_h] = image_size(sequence.files[picks.front()]);
  const int thumb_h = std::max(1, static_cast<int>(std::lround(static_cast<double>(thumb_w) * first_h / first_w)));
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
    const int x0 = gap + (k % columns) * (thumb_w + gap);
    const int y0 = gap + (k / columns) * (cell_h + gap);
    paste(sheet, thumbnail(sequence.files[idx], thumb_w, thumb_h, {first_w, first_h}), x0, y0);
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
  DurableFile file(out, StaleTemporaries::remove, options.output_name);
  write_png(file.library_path(), sheet, file.final_path());
  file.commit();
}

}  // namespace lc
