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

// Where a card's text goes: a flat screen's (or a 360-degree video's:
// its centre is the viewer's front) middle, or a dome master's sweet spot.
enum class CardShape {
  flat,
  // A 180-degree dome master: the disc touching the frame's sides, black
  // outside it; the text in the box around 35 degrees above the dome's
  // front horizon (0.61 of the disc's radius below its centre, where
  // camera/delivery.hpp puts the shot's subject), not at the zenith.
  dome,
};

// A width x height card: near-black, `lines` centred in light grey in the
// text box of `shape`, the first line large (a title), the others at half
// its size (subtitles).  The scale is the largest whole one that keeps
// every line within 80% of the box's width and the text block within 70%
// of its height (the box: the whole frame, or for a dome 1.0 x 0.5 of the
// disc's radius about the sweet spot, inside the disc).  A card too small
// for a line as written at one image pixel per font pixel breaks its lines
// between words instead.  Throws std::invalid_argument when there are no
// lines or the text cannot fit even so.
Rgb8Image title_card(int width, int height, const std::vector<std::string>& lines, CardShape shape = CardShape::flat);

// The card shown for `frames` frames, encoded into `out` with `options` (use
// the sequences' options so concat_videos can join them without re-encoding).
EncodeResult encode_title_card(const std::vector<std::string>& lines, int width, int height, int frames,
                               const EncodeOptions& options, const std::filesystem::path& out,
                               const ProgressFn& progress = {}, CardShape shape = CardShape::flat);

}  // namespace lc
