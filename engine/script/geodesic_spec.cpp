#include "script/geodesic_spec.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "eye/tetrad.hpp"
#include "lua/sandbox.hpp"
#include "lua/table_reader.hpp"
#include "script/engine_api.hpp"
#include "script/script_paths.hpp"
#include "script/spacetime_reader.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace {

// One of `choices`, or an error listing them (and the nearest one).
std::string read_choice(lua::TableReader& t, std::string_view key, std::optional<std::string_view> fallback,
                        std::initializer_list<std::string> choices) {
  const std::string v = fallback ? t.string_or(key, *fallback) : t.string(key);
  for (const auto& c : choices)
    if (v == c) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  const std::vector<std::string> cands(choices);
  const std::string near = lua::nearest(v, cands);
  throw lua::FieldError(fmt::format("{}: field '{}' must be one of {}, got \"{}\"{}", t.context(), key, list, v,
                                    near.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", near)));
}

// Components along the static frame's spatial legs: (r, theta, phi) for a
// Boyer–Lindquist scene, (x, y, z) for a Cartesian one.  Missing ones are 0.
Vec3 read_frame_vector(lua::TableReader& t, bool polar) {
  const char* k[3] = {"x", "y", "z"};
  if (polar) k[0] = "r", k[1] = "theta", k[2] = "phi";
  Vec3 v = {t.number_or(k[0], 0.0), t.number_or(k[1], 0.0), t.number_or(k[2], 0.0)};
  t.finish();
  return v;
}

struct Start {
  Vec4 scene;  // scene coordinates, angles in radians
  Vec4 trace;
  Tetrad frame;  // static observer
};

template <class S>
Start read_start(const S& st, lua::TableReader& t, bool polar) {
  Start s{};
  if (polar) {
    s.scene = {t.number_or("t", 0.0), t.number("r"), t.number("theta") * degree, t.number("phi") * degree};
    if (!(s.scene[1] > 0.0) && !scene_radius_is_signed<S>())
      throw lua::FieldError(fmt::format("{}: r must be > 0, got {}", t.context(), s.scene[1]));
  } else {
    s.scene = {t.number_or("t", 0.0), t.number("x"), t.number("y"), t.number("z")};
  }
  t.finish();
  s.trace = st.trace_from_scene(s.scene);
  // Its directions and velocities are given in a static (or ZAMO) frame:
  // the start must be where an observer may stand.
  if (const std::string_view why = st.why_no_observer(s.trace); !why.empty()) {
    if (polar) throw lua::FieldError(fmt::format("{}: the start r = {} lies {}", t.context(), s.scene[1], why));
    throw lua::FieldError(fmt::format("{}: the start lies {}", t.context(), why));
  }
  try {
    s.frame = velocity_reference_frame(st, s.scene);
  } catch (const ObserverError& e) {
    throw lua::FieldError(fmt::format("{}: {} (directions and velocities are given in the static observer's frame, or inside an ergoregion the ZAMO's)",
                                      t.context(), e.what()));
  }
  return s;
}

}  // namespace

namespace {

GeodesicSpec read_geodesic_spec(lua::TableReader& spec) {
  const std::string& ctx = spec.context();
  GeodesicSpec out;
  GeodesicProblem& pb = out.problem;
  pb.kind = read_choice(spec, "curve", std::nullopt, {"null", "timelike"}) == "null" ? CurveKind::null
                                                                                      : CurveKind::timelike;
  pb.direction = read_choice(spec, "time", "future", {"future", "past"}) == "future" ? TimeDirection::future
                                                                                      : TimeDirection::past;
  // Future-directed curves go through the future horizon, past-directed ones
  // through the past horizon: pick the Kerr–Schild chart regular there.
  auto st_table = spec.table("spacetime");
  pb.spacetime = for_tracing(read_spacetime(st_table), pb.direction);
  out.polar_scene = has_polar_scene(pb.spacetime);

  std::visit(
      [&](const auto& st) {
        auto start_table = spec.table("start");
        const Start start = read_start(st, start_table, out.polar_scene);
        pb.x0 = start.trace;
        Tetrad frame = start.frame;
        if (pb.kind == CurveKind::null) {
          auto dir = spec.table("direction");
          const Vec3 n = read_frame_vector(dir, out.polar_scene);
          const double len = norm3(n);
          if (!(len > 0.0)) throw lua::FieldError(fmt::format("{}: the direction must not be zero", dir.context()));
          // `direction` is where the curve heads spatially as it is integrated
          // (for time = "past": where a camera looks to see this light).
          const double sgn = pb.direction == TimeDirection::future ? 1.0 : -1.0;
          pb.u0 = frame.e[0];
          for (int i = 0; i < 3; ++i) pb.u0 = pb.u0 + (sgn * n[i] / len) * frame.e[i + 1];
          if (spec.has("velocity"))
            throw lua::FieldError(fmt::format("{}: a null curve takes 'direction', not 'velocity'", ctx));
        } else {
          Vec3 v{};
          if (auto vt = spec.optional_table("velocity")) v = read_frame_vector(*vt, out.polar_scene);
          if (!(norm3(v) < 1.0))
            throw lua::FieldError(fmt::format("{}.velocity: |v| = {} must be below the speed of light (1)", ctx,
                                              norm3(v)));
          frame = boost(frame, v);
          pb.u0 = frame.e[0];
          if (spec.has("direction"))
            throw lua::FieldError(fmt::format("{}: a timelike curve takes 'velocity', not 'direction'", ctx));
        }
        if (spec.boolean_or("transport", false)) pb.tetrad = frame;
      },
      pb.spacetime.kinds());

  auto stop = spec.table("stop");
  int given = 0;
  for (auto [key, param] : {std::pair{"affine", StopParameter::affine},
                            std::pair{"proper_time", StopParameter::proper_time},
                            std::pair{"coordinate_time", StopParameter::coordinate_time}}) {
    if (auto v = stop.optional_number(key)) {
      ++given;
      pb.stop_parameter = param;
      pb.stop_value = *v;
      if (!(*v > 0.0)) throw lua::FieldError(fmt::format("{}: {} must be > 0, got {}", stop.context(), key, *v));
    }
  }
  stop.finish();
  if (given != 1)
    throw lua::FieldError(fmt::format(
        "{}: give exactly one of affine, proper_time, coordinate_time (the amount to integrate)", stop.context()));
  if (pb.kind == CurveKind::null && pb.stop_parameter == StopParameter::proper_time)
    throw lua::FieldError(fmt::format("{}: a null curve has no proper time; use affine or coordinate_time",
                                      stop.context()));

  const auto samples = spec.integer_or("samples", 1001);
  if (samples < 2 || samples > 10'000'000)
    throw lua::FieldError(fmt::format("{}: samples must be between 2 and 10000000, got {}", ctx, samples));
  pb.samples = static_cast<int>(samples);
  pb.escape_radius = spec.number_or("escape_radius", default_escape_radius);
  if (!(pb.escape_radius > 0.0))
    throw lua::FieldError(fmt::format("{}: escape_radius must be > 0, got {}", ctx, pb.escape_radius));
  pb.tolerance = spec.number_or("tolerance", 1e-12);
  if (!(pb.tolerance >= 1e-15 && pb.tolerance <= 1e-3))
    throw lua::FieldError(fmt::format("{}: tolerance must be between 1e-15 and 1e-3, got {}", ctx, pb.tolerance));
  const auto stepper = read_choice(spec, "integrator", "rk8pd", {"rk8pd", "rkf45"});
  pb.stepper = stepper == "rk8pd" ? GslStepper::rk8pd : GslStepper::rkf45;
  spec.finish();
  return out;
}

}  // namespace

GeodesicSpecs load_geodesic_specs(const std::filesystem::path& file) {
  lua::Sandbox sandbox(require_dirs_for(file));
  install_engine_api(sandbox);
  sandbox.run_file(file, 1);
  lua_State* L = sandbox.state();
  const std::string ctx = file.string();
  if (!lua_istable(L, -1))
    throw lua::FieldError(fmt::format("{}: the script must return a table (a geodesic spec or an array of them), got {}",
                                      ctx, luaL_typename(L, -1)));
  lua::TableReader top(L, -1, ctx);
  GeodesicSpecs out;
  if (top.length() > 0 && !top.has("curve")) {
    out.bundle = true;
    for (std::size_t i = 1; i <= top.length(); ++i) {
      auto one = top.table_at(i);
      out.specs.push_back(read_geodesic_spec(one));
    }
    top.finish();
  } else {
    out.specs.push_back(read_geodesic_spec(top));
  }
  return out;
}

}  // namespace lc
