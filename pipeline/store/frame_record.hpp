#pragma once
// What the journal records of a frame (store/journal.hpp writes and reads
// the lines): the settings it was rendered with, what its input hash is made
// of, what it cost, who made it and the look its PNG shows.  The monitor,
// `cost`, `develop` and resume read these.

#include <cstdint>
#include <optional>
#include <string>

#include "camera/delivery_camera.hpp"
#include "camera/image_window.hpp"
#include "image/image_io.hpp"
#include "image/look.hpp"
#include "render/render_settings.hpp"
#include "scene/shutter.hpp"
#include "store/frame_makers.hpp"

namespace lc::farm {

// The settings a frame was rendered with, as the journal spells them.
struct FrameSettings {
  int width = 0, height = 0, supersample = 1;
  bool layers = false;
  bool adaptive = false;  // adaptive supersampling (journal lines without the field: full N x N)
  PngDepth png_depth = PngDepth::eight;  // the PNG's bits per channel (render --png-depth)
  ImageWindow window{};  // the window of the frame the image is (render --region), if any
  Delivery delivery{};  // the camera and sky the shot was delivered through (render --camera ... --sky)
  ShutterOverride shutter{};  // what the command line set of the shutter (render --shutter ...), over the shot's
  bool operator==(const FrameSettings&) const = default;
  // "48x32, 1x1 samples per pixel, no data layers": for messages.  The
  // defaults of the PNG's depth, the window and the camera are said only
  // where `against` (the settings it is shown beside) differs in them:
  // "..., 8-bit PNG" beside "..., 16-bit PNG".
  std::string describe() const;
  std::string describe(const FrameSettings& against) const;
};

// What a frame's input hash is made of, recorded beside it: a reader
// without the shot (encode) can then tell a frame of an earlier version of
// the script from one that merely has another sky image (stale_frames).
struct InputParts {
  std::string script;  // 16 hex: the script and every module it required; "" in older journals
  std::string sky;     // 16 hex for each file the frame's sky reads (its image, a star catalogue), joined
                       // by '+'; "" when it reads none
  bool operator==(const InputParts&) const = default;
};

// What a frame cost, as its journal line records it (docs/cli.md,
// `lightcone cost`).
struct FrameCost {
  long rays = 0;              // samples traced
  long reused = -1;           // samples kept from earlier frames instead (-1: not recorded)
  double core_seconds = -1;   // CPU time of the threads that rendered its working sets, summed, scene
                              // evaluation included (-1: not recorded)
  double star_seconds = 0.0;  // the writer's point-star stage
  std::int64_t finished = 0;  // when it was stored, Unix seconds (0: not recorded)
  double wall_seconds = -1;   // from its first working set handed out to its files stored (-1: not recorded)
  bool recorded() const { return reused >= 0 && core_seconds >= 0.0; }
};

struct JournalFrame {
  int frame = 0;
  FrameSettings settings;
  std::string inputs;  // 16 hex digits: the frame's input hash
  InputParts parts;
  std::uintmax_t exr_bytes = 0, png_bytes = 0;
  FrameCost cost;
  FrameMakers makers;  // who rendered it (none recorded in older journals)
  Look look;  // what the PNG shows of the EXR
  // The look the render made the PNG with, where a develop has since made
  // it with another (`look`); none: `look` is the render's own.
  std::optional<Look> render_look;
  const Look& rendered_look() const { return render_look ? *render_look : look; }
};

// The journal's spelling of the render settings (an 8-bit PNG).
FrameSettings frame_settings(const RenderSettings& rs);

}  // namespace lc::farm
