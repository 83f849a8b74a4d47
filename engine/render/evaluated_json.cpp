#include "render/evaluated_json.hpp"

#include <fmt/format.h>

#include "render/scene_visit.hpp"
#include "scene/scene_json.hpp"

namespace lc {

namespace {

template <class S>
std::string evaluated(const SceneIn<S>& sc) {
  const bool polar = S::chart == SceneChart::polar;
  const S& st = sc.spacetime;
  auto leg = [&](const Vec4& v) { return json_components(st.scene_vector(sc.eye.event, v)); };
  // A camera axis (components on the spatial legs) as a vector.
  auto axis = [&](const Vec3& d) {
    Vec4 v{};
    for (int i = 0; i < 3; ++i) v = v + d[i] * sc.eye.frame.e[i + 1];
    return leg(v);
  };
  return fmt::format(
      "{{\"observer\": {{\"event\": {}, \"tetrad\": {{\"e0\": {}, \"e1\": {}, \"e2\": {}, \"e3\": {}}}}}, "
      "\"camera\": {{\"forward\": {}, \"up\": {}, \"right\": {}}}, "
      "\"rays\": {{\"escape_radius\": {}, \"free_radius\": {}}}}}",
      json_position(sc.eye.scene_event, polar), leg(sc.eye.frame.e[0]), leg(sc.eye.frame.e[1]), leg(sc.eye.frame.e[2]),
      leg(sc.eye.frame.e[3]), axis(sc.camera.axes().forward), axis(sc.camera.axes().up), axis(sc.camera.axes().right),
      json_number(sc.rays.escape_radius), json_number(sc.rays.free_radius));
}

}  // namespace

std::string evaluated_json(const Scene& scene) {
  return visit_scene([](const auto& sc) { return evaluated(sc); }, scene);
}

}  // namespace lc
