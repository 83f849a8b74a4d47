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

#include "camera/camera.hpp"
#include "core/color.hpp"
#include "light/light.hpp"
#include "objects/objects.hpp"
#include "sky/sky.hpp"
#include "core/tensor.hpp"
#include "scene/shot_info.hpp"
#include "worldline/worldline_spec.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

enum class ObserverKind { static_observer, zamo, free_fall };

struct ObserverSpec {
  ObserverKind kind = ObserverKind::static_observer;
  Vec4 position{};  // static / zamo: the event (t is the scene time)
  std::optional<WorldlineSpec> worldline;  // free_fall
  double proper_time = 0.0;                // free_fall: where on the worldline
  std::string where;  // "shot.lua:12", where the script made it (for errors; not part of the picture)
};

struct SceneSpec {
  Spacetime spacetime = Minkowski{};
  ObserverSpec observer;
  CameraSpec camera;
  SkySpec sky;
  std::vector<ObjectSpec> objects;  // the scene's `disk`, then its `objects`
  LightParams light;                // how its light is shown (lc.light{...})
};

}  // namespace lc
