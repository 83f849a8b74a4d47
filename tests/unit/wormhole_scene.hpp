#pragma once
// A frame in a wormhole for the tests (ends_test.cpp, morris_thorne_test.cpp):
// a static observer at the scene point (t, l, 90°, 0), legs e_l (towards
// larger l), e_θ, e_φ; this side's sky uniformly 0.25, the other side's
// (end 1) 0.75; rays escape at `escape_radius` in |l|.  traced() follows
// directions in the eye's frame through the renderer's trace and shade
// stages.

#include <memory>
#include <span>
#include <vector>

#include "camera/pinhole_params.hpp"
#include "core/constants.hpp"
#include "eye/tetrad.hpp"
#include "objects/objects.hpp"
#include "render/trace_templates.hpp"

namespace lc::test {

template <class S>
SceneIn<S> wormhole_scene(const S& st, double l, ShotResources& res, double escape_radius) {
  const auto uniform = [&](float c) {
    CheckerSky::Params p;
    p.colors = Palette{{c, c, c}, {c, c, c}};
    return Sky(SkySpec{p}, res);
  };
  RayOptions rays;
  rays.escape = EscapeRule::fixed;
  rays.escape_radius = escape_radius;
  SceneIn<S> sc{st, {}, Camera(PinholeParams{}, 8, 8), uniform(0.25f), {{1, uniform(0.75f)}}, std::make_shared<ObjectSet>(), rays};
  sc.eye.scene_event = {0.0, l, 0.5 * pi, 0.0};
  sc.eye.event = st.trace_from_scene(sc.eye.scene_event);
  sc.eye.metric = st.metric(sc.eye.event);
  sc.eye.frame = static_frame(st, sc.eye.scene_event);
  return sc;
}

template <class S>
std::vector<RaySample> traced(const SceneIn<S>& sc, const std::vector<Vec3>& dirs) {
  std::vector<RaySample> out(dirs.size());
  trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(out));
  return out;
}

}  // namespace lc::test
