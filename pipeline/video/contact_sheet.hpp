#pragma once
// A contact sheet: one PNG with a grid of frames picked evenly across a
// sequence, each labelled with its frame number — to look a sequence over
// before watching (or waiting for) the film.

#include <cstddef>
#include <filesystem>
#include <span>
#include <utility>
#include <vector>

#include "store/durable_file.hpp"
#include "image/frame_image.hpp"
#include "store/frame_sequence.hpp"

namespace lc {

struct ContactSheetOptions {
  int columns = 4;    // frames per row
  int width = 1280;   // the sheet's width in pixels; the height follows
  int count = 16;     // frames shown at most (all of them when there are fewer)
  FinalName output_name = FinalName::users;  // whose name the sheet's file is (DurableFile's FinalName)
};

// `count` indices spread evenly over 0 .. available-1, the first and the
// last included, ascending and distinct; all indices when available <= count.
std::vector<std::size_t> pick_evenly(std::size_t available, std::size_t count);

// Resizes linear RGB by area averaging, fed a few rows at a time: each
// output pixel is the mean of the source area it covers (weighted by
// overlap), right both for shrinking a frame to a thumbnail and for
// blowing up a 32-pixel preview (then it is nearest-neighbour, keeping
// pixels crisp).  Memory: the output (in double) and one row of it.
class AreaResampler {
 public:
  AreaResampler(int src_width, int src_height, int width, int height);
  // Rows y0 .. y0 + rows - 1 of the source (3 * src_width floats a row);
  // each row once, in any order.
  void add_rows(int y0, int rows, std::span<const float> rgb);
  // The output once every row was added.
  FrameImage result() const;

  // An output column's or row's source pixels: the first, and each one's
  // weight (overlap / the output pixel's width in source pixels).
  struct Span {
    int first = 0;
    std::vector<double> weights;
  };

 private:
  int src_width_, width_, height_;
  std::vector<Span> columns_;
  std::vector<std::vector<std::pair<int, double>>> rows_of_;  // per source row: (output row, weight)
  std::vector<double> acc_, row_;
};

// Rows read at a time for a thumbnail: a 16384-wide frame's band is ~12 MB.
inline constexpr int thumbnail_band_rows = 64;

// The thumbnail (width x height, linear RGB) of the image `file`, read a
// band at a time; throws std::runtime_error naming the file when it is not
// `expected` (width, height) in size or does not read.
FrameImage thumbnail(const std::filesystem::path& file, int width, int height, std::pair<int, int> expected);

// The sheet of `sequence` (linear RGB, for write_png): a dark background,
// thumbnails of equal size (the first frame's aspect, scaled by area
// averaging in linear light), each with its frame number underneath.
// Throws std::invalid_argument naming the flag for bad options
// (--columns, --width, --count), std::runtime_error naming a frame that
// cannot be read or differs in size from the first.
FrameImage make_contact_sheet(const FrameSequence& sequence, const ContactSheetOptions& options);

// make_contact_sheet written as an sRGB PNG at `out` (atomically).
void write_contact_sheet(const FrameSequence& sequence, const ContactSheetOptions& options,
                         const std::filesystem::path& out);

}  // namespace lc
