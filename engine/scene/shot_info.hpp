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
#include "image/display.hpp"
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
            "off along a film-like curve (for a glowing disk; docs/light.md)"),
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

  // What the PNG and the video show of the frame's linear light.
  DisplayTransform display() const {
    return {exposure, filmic ? ToneCurve::filmic : ToneCurve::clip};
  }
};

}  // namespace lc
