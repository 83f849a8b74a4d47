#pragma once
// A frame's look: how its scene-linear light (the EXR, as traced) becomes
// what a screen shows (the PNG, and so the video and the contact sheet, made
// from the PNGs).  In order: the light times 2^exposure; bloom (the light
// above 1 spread, energy kept); white balance; saturation; the view
// transform (image/view_transform.hpp); then the sRGB encoder.  Plain data:
// the shot's fields (ShotInfo) and a frame's own `exposure` meet here
// (docs/light.md, "Exposure, look and view").

#include <array>
#include <string>
#include <string_view>

#include "image/frame_image.hpp"
#include "image/grade.hpp"
#include "image/view_transform.hpp"

namespace lc {

struct Look {
  double exposure = 0.0;  // stops
  View view = View::standard;
  double white_balance = 0.0;  // the colour temperature shown as white, K; 0: none
  double saturation = 1.0;
  double bloom = 0.0;          // Bloom::strength; 0: none
  double bloom_radius = 0.01;  // Bloom::radius, a fraction of the frame's diagonal

  // Whether the PNG is the EXR's light as it is (the paper's look).
  bool identity() const { return exposure == 0.0 && view == View::standard && !graded(); }
  // Whether anything besides the exposure and the view acts.
  bool graded() const { return white_balance != 0.0 || saturation != 1.0 || bloom != 0.0; }

  // The image through the look: its colours, size and alpha (its layers
  // dropped: the PNG has none).  For an ungraded look in the standard or
  // filmic view each channel is x 2^exposure (in double) through the
  // curve, as it always was, so those frames' PNGs do not change.
  FrameImage applied(const FrameImage& image) const;

  bool operator==(const Look&) const = default;
};

// The names of a look's members, as the shot's fields that set them are
// named (scene/shot_info.hpp), in the order above.
inline constexpr std::array<std::string_view, 6> look_field_names = {"exposure",   "view",  "white_balance",
                                                                     "saturation", "bloom", "bloom_radius"};

// A look as one word, for the journal (which `lightcone develop` reads to
// make a frame's PNG again): the members that differ from Look{}, as
// "name:value" joined by ',' in the order above, named as the shot's fields
// are, each number the shortest text that reads back as the same double
// ("exposure:-1.5,view:gamut_safe"); "" for Look{}.
std::string look_text(const Look& look);

// Reads look_text's spelling.  Throws std::invalid_argument naming the part
// at fault (an unknown name, a number that is not one, an unknown view).
Look parse_look_text(std::string_view text);

}  // namespace lc
