#pragma once
// The encode stage as C++ functions (what `lightcone encode` and the showcase
// call): a list of frame images to one video, and a still (a title card)
// held for N frames.

#include <filesystem>
#include <vector>

#include "video/encode_options.hpp"
#include "video/rgb8_image.hpp"

namespace lc {

// What an encoding produced, for the caller's summary line.
struct EncodeResult {
  int frames = 0;
  int width = 0, height = 0;                  // of the input frames
  int encoded_width = 0, encoded_height = 0;  // even: padded when the input was odd
  double seconds = 0;                         // the video's length, frames / fps
};

// Encodes `images` (PNG frames, in order, all the same size) into `out`
// with `options`; the first image fixes the size.  `progress` (may be
// empty) is called after every frame and may throw to abandon.  Throws
// std::runtime_error naming the image that cannot be read or has another
// size, or naming `out`; on any failure nothing is left under `out`.
// The caller checks the sequence is whole (require_complete).
EncodeResult encode_sequence(const std::vector<std::filesystem::path>& images, const EncodeOptions& options,
                             const std::filesystem::path& out, const ProgressFn& progress = {});

// Encodes `image` shown for `frames` frames (a title card, a hold) into `out`.
EncodeResult encode_still(const Rgb8Image& image, int frames, const EncodeOptions& options,
                          const std::filesystem::path& out, const ProgressFn& progress = {});

}  // namespace lc
