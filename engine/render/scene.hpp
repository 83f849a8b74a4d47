#pragma once
// A frame ready to render: the spacetime in the chart rays are traced in, the
// observer's event and tetrad, the camera and the objects
// (render/scene_builder.hpp makes it from the script's FrameScene;
// render/trace.hpp follows camera rays through it).  Templated on the
// concrete spacetime so the metric inlines into the integrator.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geodesic/null_ray.hpp"
#include "camera/camera.hpp"
#include "objects/objects.hpp"
#include "sky/sky.hpp"

namespace lc {

template <class S>
struct SceneOf {
  S spacetime;
  Vec4 observer{};       // trace coordinates
  double observer_time;  // scene time of the observer (BL t for Kerr)
  Mat4 metric{};         // at the observer
  Tetrad frame{};
  Camera camera;
  Sky sky;
  ObjectLists objects;
  RayOptions rays;
  Vec4 observer_scene{};  // the observer's event in scene coordinates, exact where the shot gave it (on the axis)
  // still_key() of the frame's scene where the spacetime is stationary, else
  // empty: frames with equal non-empty keys may share the samples of rays
  // that stay clear of moving objects (render/sample_memo.hpp).
  std::string still_key{};
};

// A scene in any registered spacetime (spacetime/spacetime.hpp).
template <class V>
struct ScenesIn;
template <class... S>
struct ScenesIn<std::variant<S...>> {
  using type = std::variant<SceneOf<S>...>;
};
using Scene = ScenesIn<Spacetime>::type;


}  // namespace lc
