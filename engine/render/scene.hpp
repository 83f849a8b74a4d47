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

// A frame's scene in whichever registered spacetime: one SceneIn<S>, held
// so that what builds, keeps, passes on or reads a scene in a spacetime it
// names (get<S>) does not include the list of spacetimes, and is not
// rebuilt for a new one (docs/architecture.md, "What a new kind
// rebuilds").  What does something in every spacetime visits it
// (visit_scene, render/scene_visit.hpp), which includes the list.  A value:
// a copy is a copy of the SceneIn.
class Scene {
 public:
  template <class S>
  Scene(SceneIn<S> sc) : held_(new SceneIn<S>(std::move(sc))), kind_(&kind_of<S>) {}
  Scene(const Scene& other) : held_(other.kind_->copy(other.held_)), kind_(other.kind_) {}
  Scene(Scene&& other) noexcept : held_(std::exchange(other.held_, nullptr)), kind_(other.kind_) {}
  Scene& operator=(Scene other) noexcept {
    std::swap(held_, other.held_);
    std::swap(kind_, other.kind_);
    return *this;
  }
  ~Scene() {
    if (held_) kind_->destroy(held_);
  }

  // The scene in spacetime S, if it is in S.
  template <class S>
  const SceneIn<S>* get_if() const {
    return kind_ == &kind_of<S> ? static_cast<const SceneIn<S>*>(held_) : nullptr;
  }
  template <class S>
  SceneIn<S>* get_if() {
    return kind_ == &kind_of<S> ? static_cast<SceneIn<S>*>(held_) : nullptr;
  }
  // The same; throws std::bad_variant_access if it is in another.
  template <class S>
  const SceneIn<S>& get() const {
    if (const SceneIn<S>* p = get_if<S>()) return *p;
    throw std::bad_variant_access();
  }
  template <class S>
  SceneIn<S>& get() {
    if (SceneIn<S>* p = get_if<S>()) return *p;
    throw std::bad_variant_access();
  }
  // Whether both are in the same spacetime (kind, not parameters).
  bool same_spacetime_kind(const Scene& other) const { return kind_ == other.kind_; }

 private:
  // How a held SceneIn<S> is copied and destroyed; its address names S.
  struct Kind {
    void* (*copy)(const void*);
    void (*destroy)(void*);
  };
  template <class S>
  static constexpr Kind kind_of = {
      [](const void* p) -> void* { return new SceneIn<S>(*static_cast<const SceneIn<S>*>(p)); },
      [](void* p) { delete static_cast<SceneIn<S>*>(p); }};
  void* held_;  // a SceneIn<S>, S as kind_ says; null only when moved from
  const Kind* kind_;
};

// scene.get<S>(), also of a temporary scene (by value then).
template <class S>
const SceneIn<S>& scene_get(const Scene& scene) {
  return scene.get<S>();
}
template <class S>
SceneIn<S>& scene_get(Scene& scene) {
  return scene.get<S>();
}
template <class S>
SceneIn<S> scene_get(Scene&& scene) {
  return std::move(scene.get<S>());
}

}  // namespace lc
