#pragma once
// Shadows for the tests.  shadow_edges: the two edges of a shadow along a
// one-row pinhole image, by bisection (the spacetimes' tests compare them
// with closed forms).  check_shadow: a Schwarzschild shadow seen through
// any camera, for the cameras' tests:
// a static observer at r = 30 M (M = 1) sees the hole's shadow as a disc of
// angular radius 9.6327 degrees about the direction to the hole (sin =
// 3 sqrt(3) M / r sqrt(1 - 2M/r), Synge 1966), forward's default (-e_1).
// The check renders the rows of the frame that come near the shadow, with
// the data layers, and asks every pixel there whether it is horizon; it
// must be exactly where its centre's direction (the camera's projection,
// independent of the renderer) is inside the shadow's angle, but for
// pixels within one pixel's angle of the edge (whose centre may fall
// either side of the traced boundary).  So the edge lands where the
// projection puts it, within a pixel, wherever in the frame it is.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/constants.hpp"
#include "core/hit_kind.hpp"
#include "render/pixel_rows.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "spacetime/kerr.hpp"

namespace lc::test {

// The shadow's angular radius from a static observer at r = 30 M.
inline double schwarzschild_shadow_angle_at_30() { return std::asin(3 * std::sqrt(3.0) / 30 * std::sqrt(1 - 2.0 / 30)); }

struct ShadowCheck {
  long checked = 0;      // pixels whose centre is clearly inside or outside
  long horizon = 0;      // of them, inside
  long wrong = 0;        // of them, on the wrong side
  std::string first_wrong;
};

// Renders `camera` (a camera's Params) at width x height, 1 sample a
// pixel, and checks the shadow as above.  Only rows with a pixel centre
// within 2 degrees of the shadow are traced.
template <class CameraParams>
ShadowCheck check_shadow(const CameraParams& camera, int width, int height) {
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0);
  fs.observer = StaticObserver::Params{{0, 30, 90 * degree, 0}};
  fs.camera = camera;
  ShotResources res;
  const RenderSettings rs{width, height, 1, true, false};
  const auto sc = scene_get<Kerr>(build_scene(fs, width, height, res));
  const double edge = schwarzschild_shadow_angle_at_30();
  const Vec3 hole = {-1, 0, 0};
  auto angle = [&](double px, double py) {
    const Vec3 d = unit3(sc.camera.direction(px, py));
    return std::acos(std::clamp(d[0] * hole[0] + d[1] * hole[1] + d[2] * hole[2], -1.0, 1.0));
  };
  std::vector<int> rows;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      if (sc.camera.ray({i + 0.5, j + 0.5, 0.0}) && angle(i + 0.5, j + 0.5) < edge + 2 * degree) {
        rows.push_back(j);
        break;
      }
  FrameImage img = make_frame(rs);
  render_rows_with(sc, sc.camera, rs, std::span<const int>(rows), img, nullptr, pixel_rows::TraceRays{});
  ShadowCheck out;
  const float horizon = static_cast<float>(HitKind::horizon);
  for (const int j : rows)
    for (int i = 0; i < width; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      if (!sc.camera.ray({x, y, 0.0})) continue;
      const double a = angle(x, y);
      // One pixel's angle here: to the neighbouring centres.
      const double step = std::max({std::abs(angle(x + 1, y) - a), std::abs(angle(x - 1, y) - a),
                                    std::abs(angle(x, y + 1) - a), std::abs(angle(x, y - 1) - a)});
      if (std::abs(a - edge) <= step) continue;
      ++out.checked;
      const bool inside = a < edge;
      out.horizon += inside;
      const bool seen = img.layers[0].values[static_cast<std::size_t>(j) * width + i] == horizon;
      if (seen != inside && out.wrong++ == 0)
        out.first_wrong = "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") at " +
                          std::to_string(a / degree) + " degrees from the hole is " + (seen ? "" : "not ") + "horizon";
    }
  return out;
}

// The angles (radians, signed: left < 0) of the shadow's two edges along the
// centre row of a 1-row pinhole image W wide of horizontal field `fov`
// degrees, found by bisecting between the centre (horizon) and either end
// (sky) to ~1e-9 of the field.
inline std::pair<double, double> shadow_edges(const Scene& scene, int W, double fov) {
  auto edge = [&](double sky_end) {
    double in = W / 2.0, out = sky_end;
    EXPECT_EQ(trace_image_point(scene, in, 0.5).hit.kind, HitKind::horizon);
    EXPECT_EQ(trace_image_point(scene, out, 0.5).hit.kind, HitKind::sky);
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (in + out);
      (trace_image_point(scene, mid, 0.5).hit.kind == HitKind::horizon ? in : out) = mid;
    }
    return std::atan((2 * in / W - 1) * std::tan(0.5 * fov * degree));
  };
  return {edge(0.0), edge(W)};
}

}  // namespace lc::test
