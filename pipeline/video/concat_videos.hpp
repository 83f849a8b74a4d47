#pragma once
// Joins videos end to end without re-encoding (the showcase: title cards and
// the three sequences into one film).  The inputs must share codec, size,
// pixel format, frame rate and codec headers — which clips made by
// lightcone with the same --codec, --preset, --fps and size do.

#include <filesystem>
#include <vector>

#include "video/encode_options.hpp"

namespace lc {

struct ConcatResult {
  int frames = 0;  // packets copied: one per frame
  int width = 0, height = 0;
  double seconds = 0;  // the sum of the inputs' lengths
};

// Copies the video stream of each of `inputs` in order into `out` (its
// extension picks the container, as for encoding; MP4/MOV get faststart),
// shifting each input's timestamps to start where the previous one ended, so
// the result lasts exactly the sum of the inputs.  `progress` gets (inputs
// done, inputs in all).  Throws std::runtime_error naming the input that
// cannot be read, has not exactly one video stream, or differs from the
// first input (saying in what), or naming `out`; on failure nothing is left
// under `out`.  `layout` (a 360-degree film's) is written into `out` for
// players, whatever the inputs carry (title cards carry none).  `name`:
// whose name `out` is (DurableFile's FinalName).
ConcatResult concat_videos(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& out,
                           const ProgressFn& progress = {}, const VideoLayout& layout = {},
                           FinalName name = FinalName::users);

}  // namespace lc
