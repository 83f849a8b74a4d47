#pragma once
// What the frames of a shot are made from, for the frame store's resume
// check: the script, every module it required and the files each frame's
// sky reads (its image; the star catalogue, LIGHTCONE_STAR_CATALOGUE's or
// KStars'), each hashed by content.  A frame's input hash combines the
// hashes of the script and modules (any of them may shape any frame) with
// those of its own sky's files, so rendering a sub-range and later the whole shot
// agree on the frames they share.  Engine changes are not covered: a
// rebuilt lightcone resumes an old render as it stands.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera_spec.hpp"
#include "store/journal.hpp"
#include "render/renderer.hpp"
#include "script/shot.hpp"
#include "sky/sky.hpp"

namespace lc::farm {

struct FrameFacts {
  std::string spacetime;  // describe(spacetime), for the EXR header
  SkySpec sky;            // for the stage after the pixels (point stars)
  CameraSpec camera;
  // Each instant's sky and camera where the frame is blurred (its shutter
  // open and its scene changing within it: scene/frame_specs.hpp), for the
  // star stage, which draws each instant's stars; else empty.
  struct Instant {
    SkySpec sky;
    CameraSpec camera;
  };
  std::vector<Instant> instants;
  std::optional<double> exposure;  // the frame's own `exposure` (stops), over the shot's; unset: the shot's
  std::string shutter;  // where blurred, its shutter (Shutter::describe) for the EXR header
  std::string inputs;     // 16 hex digits
  InputParts parts;       // what `inputs` combines, for the journal
};

struct ShotSurvey {
  std::map<int, FrameFacts> frames;
  std::map<std::string, std::string> files;  // path -> 16 hex digits
};

// Evaluates the scene of every listed frame (script only: no worldlines are
// integrated, no textures decoded), so a script error anywhere stops the
// render before it starts.  `each(done)`, where given, is called after
// each frame (progress; it may throw to stop the survey: a signal).
// Throws the script's error, or std::invalid_argument for a sky image
// that cannot be used (naming the shot, frame and why: see
// resolve_sky_image).
ShotSurvey survey_shot(Shot& shot, const std::vector<int>& frames,
                       const std::function<void(std::size_t done)>& each = {});

// What every MPI rank must agree on before working together: the shot's
// settings, the render settings, the stripe layout and the content of the
// script and modules loaded so far.  Ranks whose digests differ run
// different scripts or flags (a stale copy on one node).
std::uint64_t job_digest(const Shot& shot, const RenderSettings& rs, int stripes, int preview_every);

}  // namespace lc::farm
