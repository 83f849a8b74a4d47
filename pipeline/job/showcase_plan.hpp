#pragma once
// What `lightcone showcase` makes, decided before anything runs: the paper's
// three sequences in order, with the frames, size and sampling each is
// rendered at and the frame rate its video plays at, for one of two
// qualities (docs/showcase.md).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/delivery_camera.hpp"

namespace lc {

enum class ShowcaseQuality { preview, production };

// "preview" / "production"; throws std::invalid_argument naming --quality.
ShowcaseQuality parse_showcase_quality(const std::string& name);

// Preview settings, chosen so the README's first command (install, build,
// render, encode) ends within about 15 minutes on a fresh 2-core machine:
// the film keeps its length and timing, at a fifth of the linear size, one
// sample per pixel and a few frames per second of story.
inline constexpr int preview_width = 256;
inline constexpr int preview_height = 144;
inline constexpr double preview_fps = 3;
// Through a dome master or a 360-degree camera (--camera; docs/showcase.md):
// square and 2:1 frames, at preview of about the pinhole preview's pixel
// count, at production at the delivery standards (a touring dome's 4096
// square, a 4K 360-degree video).
inline constexpr int dome_preview_side = 256, dome_production_side = 4096;
inline constexpr int sphere_preview_height = 192, sphere_production_height = 2048;
// Title cards: long enough to read two lines.
inline constexpr double title_seconds = 3;

struct SequencePlan {
  std::string name;                      // the shot's name (its frames are <name>.NNNN.png)
  std::filesystem::path shot;            // the script
  std::vector<std::string> title;        // its title card, first line large
  std::vector<int> frames;               // ascending; the first and last frames of the shot always
  int shot_frames = 0;                   // frames in the whole shot
  std::optional<std::string> size;       // WxH, or the shot's own
  std::optional<int> supersample;        // or the shot's own
  bool layers = false;                   // data layers in the EXRs: a preview's frames can be checked (docs/layers.md)
  double fps = 30;                       // the video's frame rate
};

struct ShowcasePlan {
  std::vector<std::string> opening;      // the film's first title card
  std::vector<SequencePlan> sequences;   // in showing order
  double fps = 30;                       // every clip's (title cards too, so they join without re-encoding)
  int width = 1280, height = 720;        // every clip's
  DeliveryCamera camera = DeliveryCamera::shot;  // what the sequences are rendered through
};

// What the user chose: a quality, and optionally a smaller or larger image
// (--size), for a preview more or fewer frames per second of story
// (--rate), and the fourth sequence after the paper's three (--thermal).
struct ShowcaseSettings {
  ShowcaseQuality quality = ShowcaseQuality::preview;
  std::optional<std::string> size;  // WxH
  std::optional<double> rate;       // preview only
  bool thermal = false;             // kerr_accrDisk_thermal.lua too
  DeliveryCamera camera = DeliveryCamera::shot;  // --camera: the shots' own, dome or 360
};

// Loads the three shots from `shots_dir` (kerr_accrDisk.lua, kerr_passing.lua,
// dihole.lua, and kerr_accrDisk_thermal.lua with settings.thermal) for their
// frame counts, rates and sizes.  Production renders
// every frame at the shot's size and sampling; preview picks
// max(4, round(seconds x preview_fps)) frames evenly (first and last included) at
// preview_width x preview_height, one sample per pixel; --size and --rate
// change those.  Through a dome or a 360-degree camera the sizes are
// dome_*_side square and 2:1 of sphere_*_height, unless --size says.  Throws std::invalid_argument naming --size or --rate,
// std::runtime_error naming a missing or failing script, or when the shots
// disagree on fps or size (their clips could not be joined).
ShowcasePlan plan_showcase(const ShowcaseSettings& settings, const std::filesystem::path& shots_dir);

}  // namespace lc
