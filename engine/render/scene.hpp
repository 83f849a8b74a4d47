#pragma once
// SceneIn<S>: a frame ready to render in spacetime S — the spacetime in the
// chart rays are traced in, the observer's event and tetrad, the camera, the
// sky and the built objects — and Scene, one of those for any registered
// spacetime.  render/scene_builder.hpp makes it from the script's SceneSpec
// (scene/scene_spec.hpp); render/trace.hpp follows camera rays through it.
// Templated on the concrete spacetime so the metric inlines into the
// integrator.

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "geodesic/null_ray.hpp"
#include "camera/camera.hpp"
#include "eye/eye.hpp"
#include "light/light.hpp"
#include "observers/observers.hpp"
#include "sky/sky.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

struct ObjectSet;  // objects/objects.hpp

template <class S>
struct SceneIn {
  S spacetime;
  // The observer at the frame's moment: where its camera's rays start
  // unless a sample has an eye or a time of its own (render/ray_start.hpp).
  Eye eye{};
  Camera camera;
  // What a ray that escaped sees: `sky` at the spacetime's first end
  // (S::ends[0]) and at every far end without a sky of its own in
  // end_skies (end index, sky).  sky_of picks it.
  Sky sky;
  std::vector<std::pair<std::size_t, Sky>> end_skies{};
  // The built objects, one list per kind; shared by copies of the scene,
  // never changed once built.  Set by render/scene_builder (never null in a
  // scene it built).
  std::shared_ptr<const ObjectSet> objects;
  RayOptions rays;
  // still_key() of the frame's scene where the spacetime is stationary, else
  // empty: frames with equal non-empty keys may share the samples of rays
  // that stay clear of moving objects (render/sample_memo.hpp).
  std::string still_key{};
  Light light{};  // how hits' light is shown
  // The observer as a path: the eye at a time offset within the frame
  // (observers/observers.hpp); observer_path.at(0) is `eye`, bit for bit.
  ObserverPath<S> observer_path{};
  // Where this scene lies in its frame's shutter: its offset from the
  // frame's moment, in frame intervals (0: the frame's own scene).
  double moment = 0.0;
  // The frame's scene at each instant of its open shutter, in order
  // (scene/frame_specs.hpp); each sample takes one (render/sample_times.hpp).
  // Empty: the shutter is closed or nothing changes within it, and every
  // sample is at the frame's moment.
  std::vector<SceneIn> instants{};

  const Sky& sky_of(std::size_t end) const {
    for (const auto& [e, s] : end_skies)
      if (e == end) return s;
    return sky;
  }
};

// A scene in any registered spacetime (spacetime/spacetime.hpp).
template <class V>
struct SceneVariantOf;
template <class... S>
struct SceneVariantOf<std::variant<S...>> {
  using type = std::variant<SceneIn<S>...>;
};
// A class, not an alias of the variant, so that a header that only passes
// scenes on (render/renderer.hpp) declares `struct Scene;` and does not
// bring every registry into the files that include it (docs/architecture.md,
// "What a new kind rebuilds").  std::visit and std::get take it as the
// variant it is.
struct Scene : SceneVariantOf<SpacetimeList>::type {
  using Base = SceneVariantOf<SpacetimeList>::type;
  using Base::Base;
};


}  // namespace lc
