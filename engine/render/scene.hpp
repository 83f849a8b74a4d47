#pragma once
// SceneIn<S>: a frame ready to render in spacetime S — the spacetime in the
// chart rays are traced in, the observer's event and tetrad, the camera, the
// sky and the built objects — and Scene, one of those for any registered
// spacetime.  render/scene_builder.hpp makes it from the script's SceneSpec
// (scene/scene_spec.hpp); render/trace.hpp follows camera rays through it.
// Templated on the concrete spacetime so the metric inlines into the
// integrator.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geodesic/null_ray.hpp"
#include "camera/camera.hpp"
#include "light/light.hpp"
#include "objects/objects.hpp"
#include "observers/observers.hpp"
#include "sky/sky.hpp"

namespace lc {

template <class S>
struct SceneIn {
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
  Light light{};  // how hits' light is shown
  // The ZAMO's 4-velocity at the observer (trace coordinates), where the
  // light model splits g into its parts (light/light.hpp).
  Vec4 reference_observer{};
  // The observer as a path: the eye at a time offset within the frame
  // (observers/observers.hpp).  observer_path.at(0) is the frame's own eye:
  // the fields above (observer, observer_scene, observer_time, metric,
  // frame, reference_observer) hold it too, bit for bit.
  ObserverPath<S> observer_path{};
};

// A scene in any registered spacetime (spacetime/spacetime.hpp).
template <class V>
struct SceneVariantOf;
template <class... S>
struct SceneVariantOf<std::variant<S...>> {
  using type = std::variant<SceneIn<S>...>;
};
using Scene = SceneVariantOf<Spacetime>::type;


}  // namespace lc
