#include "trace_command.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <stdexcept>

#include <fmt/format.h>

#include "command_output.hpp"
#include "core/json.hpp"
#include "geodesic_csv.hpp"
#include "job/frame_range.hpp"
#include "job/image_size.hpp"
#include "render/hit_kind_names.hpp"
#include "render/layers.hpp"
#include "render/scene_builder.hpp"
#include "render/scene_visit.hpp"
#include "render/trace_templates.hpp"
#include "script/shot.hpp"

namespace lc {

namespace {


// A float as JSON: its shortest exact spelling (the EXR's value to the
// bit), null where JSON has no number.
std::string json_float(float v) { return std::isfinite(v) ? fmt::format("{}", v) : "null"; }

// What the ray through pixel (i, j) of frame f found, for people: one line
// (the layers to 9 digits, the colour to 4).
// `end`: the spacetime's end a sky ray escaped to (empty for other rays).
std::string text_report(int f, int i, int j, const RaySample& s, std::string_view end) {
  std::string values;
  for (const LayerSpec& l : layers)
    values += fmt::format("{}{} {:.9g}", values.empty() ? "" : ", ", l.name, l.value(s.hit));
  return fmt::format("trace: frame {} pixel {},{}: hit {}{}, stop reason {}, {} steps; {}; colour {:.4g} {:.4g} {:.4g}\n",
                     f, i, j, hit_kind_name(s.hit.kind), end.empty() ? "" : fmt::format(" at {}", end),
                     to_string(s.hit.reason), s.hit.steps, values, s.color[0], s.color[1], s.color[2]);
}

// The same as one JSON object, for scripts: every number exact (layers and
// colour as the floats the EXR holds).
std::string json_report(int f, int i, int j, const RaySample& s, std::string_view end) {
  std::string values;
  for (const LayerSpec& l : layers)
    values += fmt::format("{}{}: {}", values.empty() ? "" : ", ", json_string(std::string(l.name)),
                          json_float(l.value(s.hit)));
  return fmt::format(
      "{{\"frame\": {}, \"pixel\": [{}, {}], \"hit\": {}, \"end\": {}, \"stop_reason\": {}, \"steps\": {}, "
      "\"layers\": {{{}}}, \"colour\": [{}, {}, {}]}}\n",
      f, i, j, json_string(std::string(hit_kind_name(s.hit.kind))), end.empty() ? "null" : json_string(std::string(end)),
      json_string(std::string(to_string(s.hit.reason))), s.hit.steps, values, json_float(s.color[0]),
      json_float(s.color[1]), json_float(s.color[2]));
}

}  // namespace

int run_trace(const TraceCommand& cmd) {
  const Delivery delivery = delivery_from_flags(cmd.delivery);  // (before the shot: a bad flag is said first)
  Shot shot(cmd.shot);
  shot.set_delivery(delivery);
  const ShotInfo& info = shot.info();
  const int f = parse_frame_range(std::to_string(cmd.frame), info.frames, "--frame").first;
  const auto [shot_width, shot_height] = delivery_size(delivery.camera, info.width, info.height);
  const auto [width, height] = output_size(shot_width, shot_height, cmd.size, cmd.scale);
  const auto [i, j] = parse_pixel(cmd.pixel, "--pixel");
  if (i < 0 || i >= width || j < 0 || j >= height)
    throw std::invalid_argument(fmt::format("--pixel {},{}: outside the {}x{} image", i, j, width, height));

  const SceneSpec fs = shot.frame(f);
  ShotResources resources(shot.asset_dirs());
  const Scene scene = build_scene(fs, cmd.shot, f, width, height, resources);

  // The path, as the geodesic tool reports a curve integrated into the past:
  // lambda = -(affine parameter of the backward ray), tangent future-directed.
  GeodesicPath path;
  Spacetime st_out = Minkowski{};
  std::string_view end;  // the end a sky ray escaped to
  const RaySample s = visit_scene(
      [&](const auto& sc) {
        st_out = sc.spacetime;
        auto record = [&](const RayState& y, double mu) {
          GeodesicSample g{};
          g.lambda = -mu;
          g.x = {y[0], y[1], y[2], y[3]};
          Vec4 dx, dp;
          sc.spacetime.hamiltonian_rhs(g.x, {y[4], y[5], y[6], y[7]}, dx, dp);
          g.u = -1.0 * dx;
          path.samples.push_back(g);
        };
        // A pixel the camera has no ray through (outside a fisheye's disc)
        // is reported as such, with an empty path.
        const std::optional<CameraRay> ray = sc.camera.ray({i + 0.5, j + 0.5, 0.0});
        if (!ray) return no_ray_sample();
        // From the camera's eye for the pixel (a stereo camera's is beside
        // the observer).
        EyePool eyes;
        RaySample r = trace_sample(sc, eyes.start(sc, *ray), [&](const RayState& y, double sigma) { record(y, sigma); });
        record(r.hit.end, r.hit.lambda_end);
        if (r.hit.kind == HitKind::sky) end = std::decay_t<decltype(sc.spacetime)>::ends[r.hit.spacetime_end].name;
        return r;
      },
      scene);
  path.reason = s.hit.reason;
  path.end = end;
  path.steps = s.hit.steps;
  // With --json standard output is the report's, so the path goes only
  // to a file named with -o.
  if (!cmd.json || cmd.output) {
    std::string csv = geodesic_csv_header({st_out}, false, false);
    append_geodesic_csv(csv, st_out, path, false, std::nullopt);
    write_output(cmd.output, csv);
  }
  // Every data layer's value (render/layers.hpp), as the pixel's EXR holds it.
  if (cmd.json)
    write_output(std::nullopt, json_report(f, i, j, s, end));
  else
    fmt::print(stderr, "{}", text_report(f, i, j, s, end));
  return 0;
}

}  // namespace lc
