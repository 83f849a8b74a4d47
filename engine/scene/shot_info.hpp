#pragma once
// ShotInfo: a shot's frame-independent settings, the fields of the table a
// shot script returns besides `frame`.  Declared once (core/fields.hpp): the
// reader, `lightcone inspect`'s JSON and the reference in docs/shots.md come
// from the declarations.

#include <cctype>
#include <stdexcept>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/fields.hpp"
#include "image/look.hpp"
#include "scene/shutter.hpp"

namespace lc {

struct ShotInfo {
  std::string name;
  int frames = 1;
  double fps = 30.0;
  int width = 640, height = 360;
  int supersample = 1;
  double exposure = 0.0;
  int filmic = 0;
  // The rest of the look (image/look.hpp); a frame may give its own `exposure`.
  View view = View::standard;
  double white_balance = 0.0;
  double saturation = 1.0;
  double bloom = 0.0;
  double bloom_radius = 0.01;
  // Automatic exposure (image/auto_exposure.hpp): each frame's own light
  // metered, the exposure above added to it.
  int auto_exposure = 0;
  double auto_exposure_level = 1.0;
  double auto_exposure_smoothing = 12.0;
  // The shutter (scene/shutter.hpp; docs/motion_blur.md); a frame may give
  // its own `shutter`.
  double shutter = 0.0;
  ShutterPosition shutter_position = ShutterPosition::centre;
  int time_samples = 8;

  static constexpr auto fields = std::tuple{
      field("name", &ShotInfo::name, std::optional<std::string>{}, std::nullopt, std::nullopt,
            "names the output files (`name.0000.exr`, ...): letters, digits, '_' and '-'"),
      field("frames", &ShotInfo::frames, std::optional<int>{}, at_least(1), at_most(10'000'000),
            "frames, numbered 0 .. frames-1"),
      field("fps", &ShotInfo::fps, std::optional<double>{30.0}, above(0.0), std::nullopt,
            "frames per second of the film (the video's rate)"),
      field("width", &ShotInfo::width, std::optional<int>{}, at_least(1), at_most(16384), "image width", "pixels"),
      field("height", &ShotInfo::height, std::optional<int>{}, at_least(1), at_most(16384), "image height", "pixels"),
      field("supersample", &ShotInfo::supersample, std::optional<int>{1}, at_least(1), at_most(16),
            "N x N samples per pixel (the paper: 2)"),
      field("exposure", &ShotInfo::exposure, std::optional<double>{0.0}, at_least(-64.0), at_most(64.0),
            "the PNG and the video show the light times 2^exposure (the EXR keeps it as traced; docs/light.md)",
            "stops"),
      field("filmic", &ShotInfo::filmic, std::optional<int>{0}, at_least(0), at_most(1),
            "the PNG's and the video's tone curve: 0, light above 1 shows as 1 (the paper's look); 1, highlights roll "
            "off along a film-like curve (for a glowing disk; docs/light.md); the same as view = \"filmic\""),
      field("view", &ShotInfo::view, std::optional<View>{View::standard}, std::nullopt, std::nullopt,
            "the PNG's and the video's view transform: standard (light above 1 clips, the paper's look), filmic "
            "(the filmic curve per channel) or gamut_safe (a tone curve on luminance; colours too bright or too "
            "saturated to show fade towards white, keeping their hue; docs/light.md)"),
      field("white_balance", &ShotInfo::white_balance, std::optional<double>{0.0}, at_least(0.0), at_most(40000.0),
            "the colour temperature the PNG shows as white (a 10000 K disk reads as hot gas at about 6500); 0: none, "
            "else 1000 to 40000",
            "K"),
      field("saturation", &ShotInfo::saturation, std::optional<double>{1.0}, at_least(0.0), at_most(4.0),
            "the PNG's colourfulness about each pixel's luminance: 1 as traced, 0 grey"),
      field("bloom", &ShotInfo::bloom, std::optional<double>{0.0}, at_least(0.0), at_most(1.0),
            "share of the light above the display's white (after exposure) spread into a glow around it, the light "
            "kept; 0: none"),
      field("bloom_radius", &ShotInfo::bloom_radius, std::optional<double>{0.01}, above(0.0), at_most(0.5),
            "the glow's Gaussian width, a fraction of the frame's diagonal"),
      field("auto_exposure", &ShotInfo::auto_exposure, std::optional<int>{0}, at_least(0), at_most(1),
            "1: each frame's exposure follows its own light: a pass over every frame of the shot at 64 pixels wide "
            "reads its 99th percentile of luminance, which is shown at auto_exposure_level, smoothed over "
            "neighbouring frames; `exposure` (the shot's or a frame's) then adds to it; the same whichever frames are "
            "rendered (docs/light.md)"),
      field("auto_exposure_level", &ShotInfo::auto_exposure_level, std::optional<double>{1.0}, above(0.0),
            at_most(1e6), "the light (before the view) the metered 99th percentile is shown at: 1 is the display's white"),
      field("auto_exposure_smoothing", &ShotInfo::auto_exposure_smoothing, std::optional<double>{12.0}, at_least(0.0),
            at_most(10000.0), "how many frames the metered exposure is smoothed over (a Gaussian's standard deviation; 0: "
            "none)",
            "frames"),
      field("shutter", &ShotInfo::shutter, std::optional<double>{0.0}, at_least(0.0), at_most(1.0),
            "how long the shutter is open, in frame intervals: 0 (closed: every frame an instant), 0.5 (the film "
            "camera's 180 degrees), up to 1; a frame's `shutter` overrides it (docs/motion_blur.md)",
            "frames"),
      field("shutter_position", &ShotInfo::shutter_position, std::optional<ShutterPosition>{ShutterPosition::centre},
            std::nullopt, std::nullopt,
            "where the open shutter lies against the frame's moment: centre, start (opens at it) or end (closes at "
            "it)"),
      field("time_samples", &ShotInfo::time_samples, std::optional<int>{8}, at_least(1), at_most(max_time_samples),
            "instants the open shutter is cut into: the shot is evaluated at each, and a pixel sampled in full takes "
            "at least this many samples, one instant each"),
  };

  // What the fields' ranges cannot say: the name must make file names.
  // Throws std::invalid_argument.
  void validate() const {
    if (filmic && view != View::standard && view != View::filmic)
      throw std::invalid_argument(fmt::format(
          "filmic = 1 and view = '{}' disagree: give view alone (filmic = 1 is view = 'filmic')", choice_name(view)));
    if (white_balance != 0.0 && white_balance < 1000.0)
      throw std::invalid_argument(
          fmt::format("white_balance {:g} K: must be 0 (none) or from 1000 to 40000 K", white_balance));
    if (name.size() > max_shot_name_length)
      throw std::invalid_argument(fmt::format(
          "name has {} characters, at most {} are allowed (it names the output files)", name.size(), max_shot_name_length));
    for (char c : name)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
        throw std::invalid_argument(
            fmt::format("name '{}' may only use letters, digits, '_' and '-' (it names the output files)", name));
  }

  // The shutter the shot gives its frames.
  Shutter shot_shutter() const { return {shutter, shutter_position, time_samples}; }

  // What the PNG and the video show of a frame's linear light, at the
  // shot's exposure (a frame's own `exposure` replaces it).
  Look look() const {
    return {exposure, filmic ? View::filmic : view, white_balance, saturation, bloom, bloom_radius};
  }
};

}  // namespace lc
