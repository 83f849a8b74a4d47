#include "render/scene_builder.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "assets/asset_path.hpp"
#include "core/constants.hpp"
#include "scene/still_key.hpp"
#include "spacetime/chart.hpp"

namespace lc {

namespace {

// The distance of a scene point from the origin: r in a polar scene chart,
// |(x, y, z)| in a Cartesian one.
template <class S>
double distance_from_origin(const Vec4& p) {
  if constexpr (S::chart == SceneChart::polar) return std::abs(p[1]);
  else return std::hypot(p[1], p[2], p[3]);  // (no overflow for huge coordinates)
}

// Where the script made the observer ("shot.lua:12"), for its errors.
std::string where_of(const ObserverSpec& ob) { return ob.where.empty() ? std::string("observer") : ob.where; }

// A coordinate radius beyond which a ray moving outwards meets nothing more:
// twice the largest of the objects' reach and the spacetime's photon
// region.  The factor 2 keeps the relaxed integration well clear.
template <class S>
double free_radius(const SceneIn<S>& sc) {
  double reach = sc.spacetime.photon_reach();
  for_each_object(sc.objects, [&](const auto& o, std::size_t) { reach = std::max(reach, o.reach(sc.spacetime.asymptotic_mass())); });
  return 2.0 * std::max(reach, 1.0);
}

template <class S>
Scene build(const S& st, const SceneSpec& fs, int width, int height, ShotResources& res, const RayOptions& rays) {
  const std::string here = describe(fs.spacetime);
  auto check_same = [&](const WorldlineSpec& w, const char* what) {
    if (describe(w.spacetime, true) != describe(fs.spacetime, true))
      throw std::invalid_argument(fmt::format(
          "{}: {}'s worldline ({}) was made in {}, but this frame's spacetime is {}; a worldline only "
          "makes sense in the spacetime it was integrated in",
          w.where, what, w.where, describe(w.spacetime), here));
  };

  SceneIn<S> sc{st, {}, Camera(fs.camera, width, height), Sky(fs.sky, res), {}, rays};
  Eye& eye = sc.eye;
  const ObserverSpec& ob = fs.observer;
  // Where the observer stands is checked before its frame is made: there
  // the reason would show only as "not timelike" or "degenerates".
  auto check_distance = [&](const Vec4& scene_point) {
    const double d = distance_from_origin<S>(scene_point);
    if (!(d <= max_observer_distance))
      throw std::invalid_argument(fmt::format(
          "{}: observer: {}{:g} M from the origin, farther than rays can be traced from ({:g} M at most: double "
          "precision cannot resolve their steps near the hole); for a distant view put the observer at most that "
          "far away and narrow the camera's fov",
          where_of(ob),
          ob.kind == ObserverKind::free_fall ? fmt::format("at proper time {:g} the fall is ", ob.proper_time) : "",
          d, max_observer_distance));
    if (d == 0.0 && ob.kind != ObserverKind::free_fall)
      throw std::invalid_argument(fmt::format(
          "{}: observer: at the origin a {} observer has no view 'at the hole' (forward = -e_r has no "
          "direction there): move it off the origin, and aim with lc.camera's yaw and pitch",
          where_of(ob), ob.kind == ObserverKind::zamo ? "ZAMO" : "static"));
  };
  if (ob.kind != ObserverKind::free_fall) check_distance(ob.position);
  try {
    if (ob.kind == ObserverKind::free_fall) {
      check_same(*ob.worldline, "the observer");
      const auto w = res.worldline(*ob.worldline);
      const WorldlineEvent ev = w->at_proper_time(ob.proper_time);
      eye.event = ev.x;
      eye.frame = ev.frame;
      eye.scene_event = st.scene_from_trace(ev.x);
      check_distance(eye.scene_event);
    } else {
      eye.event = st.trace_from_scene(ob.position);
      eye.scene_event = ob.position;
      eye.frame = ob.kind == ObserverKind::zamo ? zamo_polar_tetrad(st, ob.position)
                                               : static_polar_tetrad(st, ob.position);
    }
  } catch (const ObserverError& e) {
    throw std::invalid_argument(fmt::format("{}: observer: {}", where_of(ob), e.what()));
  }
  if (st.captured(eye.event))
    throw std::invalid_argument(fmt::format(
        "{}: observer: too close to a horizon (inside the capture region where rays are stopped{})", where_of(ob),
        ob.kind == ObserverKind::free_fall ? "; a fall can be shown up to just outside the horizon" : ""));
  eye.metric = st.metric(eye.event);
  double r_unused, phi_unused;
  scene_polar(st, eye.event, eye.time, r_unused, phi_unused);

  for (const ObjectSpec& o : fs.objects) add_object(sc.objects, o, st, res, eye.event);
  if (fs.light.model != LightModel::geometric) sc.light = Light(fs.light, res.spectral_shift());
  if (sc.light.splits()) eye.reference = zamo_velocity(st, eye.event);
  sc.rays.free_radius = free_radius(sc);
  // Where the spacetime's far field is known (far_field_radius), rays
  // escape there, or beyond the objects; the sky lookup adds the rest of
  // the bending (escape_direction).
  if (rays.escape == EscapeRule::far_field)
    sc.rays.escape_radius =
        std::min(sc.rays.escape_radius, std::max(sc.rays.free_radius, st.far_field_radius()));
  if constexpr (S::stationary) {
    // With what the rays are traced by: frames share rays only if these
    // agree too.
    sc.still_key = still_key(fs);
    if (!sc.still_key.empty())
      sc.still_key += fmt::format("|image {}x{}|rays {:a} {:a} {:a} {:a} {} {:a} {} {:a} {}", width, height,
                                  rays.control.rtol, rays.control.atol, rays.control.h_min, rays.control.h_max,
                                  static_cast<int>(rays.kerr_chart), rays.escape_radius, static_cast<int>(rays.escape),
                                  rays.free_radius, rays.max_steps);
  }
  return sc;
}

}  // namespace

Scene build_scene(const SceneSpec& fs, int width, int height, ShotResources& resources, const RayOptions& rays) {
  const Spacetime st = trace_chart(fs.spacetime);
  return std::visit([&](const auto& s) { return build(s, fs, width, height, resources, rays); }, st);
}

Scene build_scene(const SceneSpec& fs, const std::filesystem::path& shot_file, int frame, int width, int height,
                        ShotResources& resources, const RayOptions& rays) {
  try {
    return build_scene(fs, width, height, resources, rays);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: frame {}: {}", shot_file.string(), frame, e.what()));
  }
}

}  // namespace lc
