#pragma once
// Title cards for the showcase: plain cards with large block-letter text in
// the built-in pixel font, as pictures (title_card) or as clips ready to be
// joined with a sequence's video (encode_title_card).

#include <filesystem>
#include <string>
#include <vector>

#include "video/encode_options.hpp"
#include "video/encode_sequence.hpp"
#include "video/rgb8_image.hpp"

namespace lc {

// A width x height card: near-black, `lines` centred in light grey, the
// first line large (a title), the others at half its size (subtitles).
// The scale is the largest whole one that keeps every line within 80% of
// the width and the text block within 70% of the height.  Throws
// std::invalid_argument when there are no lines or the text cannot fit even
// at one image pixel per font pixel.
Rgb8Image title_card(int width, int height, const std::vector<std::string>& lines);

// The card shown for `frames` frames, encoded into `out` with `options` (use
// the sequences' options so concat_videos can join them without re-encoding).
EncodeResult encode_title_card(const std::vector<std::string>& lines, int width, int height, int frames,
                               const EncodeOptions& options, const std::filesystem::path& out,
                               const ProgressFn& progress = {});

}  // namespace lc
