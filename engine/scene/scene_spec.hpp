#pragma once
// SceneSpec: what the shot script says the scene of one frame is — plain
// data, from the script and nothing else (the first of the three scene
// types: SceneSpec -> render/scene_builder -> SceneIn<S> / Scene, which
// render/scene.hpp defines).  Positions are scene coordinates
// (Boyer–Lindquist for Kerr, Cartesian otherwise) with angles in radians;
// colours are linear RGB.

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera_spec.hpp"
#include "core/color.hpp"
#include "light/light.hpp"
#include "objects/object_spec.hpp"
#include "observers/observers.hpp"
#include "sky/sky.hpp"
#include "core/tensor.hpp"
#include "scene/shot_info.hpp"
#include "worldline/worldline_spec.hpp"
#include "spacetime/spacetime_spec.hpp"

namespace lc {

// A far end's own sky: the scene's `skies`, by the end's name (its index
// in the spacetime's ends, spacetime/ends.hpp, found when it was read).
// Rays that leave by that end see it in place of the scene's `sky`.
struct EndSky {
  std::size_t end = 0;
  std::string name;
  SkySpec sky;
};

struct SceneSpec {
  Spacetime spacetime;  // Minkowski unless set
  ObserverSpec observer;            // a registry's variant (observers/observers.hpp)
  CameraSpec camera;
  SkySpec sky;
  std::vector<ObjectSpec> objects;  // the scene's `disk`, then its `objects`
  LightParams light;                // how its light is shown (lc.light{...})
  // The frame's own `shutter` (scene/shutter.hpp), over the shot's; unset:
  // the shot's.
  std::optional<double> shutter{};
  // The frame's own `exposure` (stops, image/look.hpp), over the shot's;
  // unset: the shot's.  What the PNG shows, not what is traced.
  std::optional<double> exposure{};
  // The far ends' own skies beyond the first (a wormhole's other side), in
  // the order of the spacetime's ends; what handles a scene's skies goes
  // through for_each_sky (scene/scene_skies.hpp).
  std::vector<EndSky> end_skies{};
};

}  // namespace lc
