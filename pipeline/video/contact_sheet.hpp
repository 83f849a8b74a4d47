#pragma once
// A contact sheet: one PNG with a grid of frames picked evenly across a
// sequence, each labelled with its frame number — to look a sequence over
// before watching (or waiting for) the film.

#include <cstddef>
#include <filesystem>
#include <vector>

#include "image/frame_image.hpp"
#include "video/frame_sequence.hpp"

namespace lc {

struct ContactSheetOptions {
  int columns = 4;    // frames per row
  int width = 1280;   // the sheet's width in pixels; the height follows
  int count = 16;     // frames shown at most (all of them when there are fewer)
};

// `count` indices spread evenly over 0 .. available-1, the first and the
// last included, ascending and distinct; all indices when available <= count.
std::vector<std::size_t> pick_evenly(std::size_t available, std::size_t count);

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
