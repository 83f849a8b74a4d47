#include "script/scene_reader.hpp"

#include <cmath>

#include <fmt/format.h>

#include "camera/camera_params.hpp"
#include "objects/object_params.hpp"
#include "core/constants.hpp"
#include "script/field_reader.hpp"
#include "script/spacetime_reader.hpp"

namespace lc {

namespace {

using lua::FieldError;
using lua::TableReader;

[[noreturn]] void fail(const TableReader& t, const std::string& what) {
  throw FieldError(fmt::format("{}: {}", t.context(), what));
}

// The __kind of a constructor-made table (or "" for a plain table).
std::string kind_of(TableReader& t) {
  t.mark_known({"__where"});
  return t.optional_string("__kind").value_or("");
}

// What p.validate() says is wrong with p, reported at the table t.
template <class P>
void validate_at(TableReader& t, const P& p) {
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    fail(t, e.what());
  }
}

void expect_kind(TableReader& t, std::initializer_list<const char*> kinds, const char* made_by) {
  const std::string k = kind_of(t);
  for (const char* want : kinds)
    if (k == want) return;
  fail(t, fmt::format("expected a value made by {}{}", made_by, k.empty() ? "" : fmt::format(", got a {}", k)));
}

// The parameters of whichever kind of registry R (core/registry.hpp) made
// the table: its declared fields read and checked (positions against st,
// the scene's spacetime, when given), the script line that made it where
// the kind keeps one (`where`), then extra(params) for what a kind holds
// besides them, then the kind's own validate() where it has one.  `what`
// and `more` name the constructors in the error for a table none of them
// made.
template <class R, class Extra = void (*)(const void*)>
typename R::Spec read_kind(TableReader& t, const char* what, const char* more = "", const Spacetime* st = nullptr,
                           Extra extra = [](const void*) {}) {
  const std::string k = kind_of(t);
  std::optional<typename R::Spec> out;
  std::string kinds;
  R::for_each([&](auto* kind) {
    using K = std::remove_pointer_t<decltype(kind)>;
    kinds += fmt::format("{}lc.{}{{...}}", kinds.empty() ? "" : ", ", K::name);
    if (out || k != K::name) return;
    typename K::Params p;
    read_fields(t, p, st);
    if constexpr (requires { p.where; }) p.where = t.string_or("__where", t.context());
    extra(&p);
    if constexpr (requires { p.validate(); }) validate_at(t, p);
    t.finish();
    out = p;
  });
  if (!out) fail(t, fmt::format("expected a value made by {}: {}{}", what, kinds, more));
  return *out;
}

// The script line that made a value in the plain table t (a constructor's
// __where: "shot.lua:12"), for errors about the table itself, which has no
// line of its own; empty where no value has one.
std::string line_of_a_value(const TableReader& t) {
  lua_State* L = t.state();
  const int top = lua_gettop(L);
  t.push();
  std::string where;
  lua_pushnil(L);
  while (where.empty() && lua_next(L, -2) != 0) {
    if (lua_istable(L, -1)) {
      lua_getfield(L, -1, "__where");
      if (lua_type(L, -1) == LUA_TSTRING) where = lua_tostring(L, -1);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  lua_settop(L, top);
  return where;
}

// `text` led by `where` (a script line, "shot.lua:12") where there is one.
std::string led_by(const std::string& where, const std::string& text) {
  return where.empty() ? text : where + ": " + text;
}

// fail(t, what), led by `where` where there is one.
[[noreturn]] void fail_at(const std::string& where, const TableReader& t, const std::string& what) {
  throw FieldError(led_by(where, fmt::format("{}: {}", t.context(), what)));
}

double positive(TableReader& t, const char* key, std::optional<double> fallback = std::nullopt) {
  const double v = fallback ? t.number_or(key, *fallback) : t.number(key);
  if (!(v > 0.0)) fail(t, fmt::format("field '{}' must be > 0, got {}", key, v));
  return v;
}

// Components on the static frame's legs: {r, theta, phi} or {x, y, z}.
Vec3 read_leg_vector(TableReader& t, bool polar) {
  const char* k[3] = {"x", "y", "z"};
  if (polar) k[0] = "r", k[1] = "theta", k[2] = "phi";
  t.mark_known({k[0], k[1], k[2]});
  t.finish();  // unknown keys before bad values, as for declared fields (field_reader.hpp)
  Vec3 v = {t.number_or(k[0], 0.0), t.number_or(k[1], 0.0), t.number_or(k[2], 0.0)};
  t.finish();
  return v;
}

}  // namespace

ScriptPosition read_position(TableReader& t) {
  const bool has_polar = t.has("r") || t.has("theta") || t.has("phi");
  const bool has_cart = t.has("x") || t.has("y") || t.has("z");
  if (has_polar && has_cart) fail(t, "give either {r, theta, phi} (Boyer–Lindquist, degrees) or {x, y, z}, not both");
  if (!has_polar && !has_cart) fail(t, "a position needs {r, theta, phi} (Boyer–Lindquist, degrees) or {x, y, z}");
  t.mark_known({"t", "r", "theta", "phi", "x", "y", "z"});
  t.finish();  // unknown keys before bad values, as for declared fields (field_reader.hpp)
  ScriptPosition p;
  p.polar = has_polar;
  if (p.polar) {
    p.coords = {t.number_or("t", 0.0), t.number("r"), t.number("theta") * degree, t.number("phi") * degree};
    // r's sign is the spacetime's to judge (resolve_position); a NaN never.
    if (!std::isfinite(p.coords[1])) fail(t, fmt::format("r must be a finite number, got {}", p.coords[1]));
  } else {
    p.coords = {t.number_or("t", 0.0), t.number("x"), t.number("y"), t.number("z")};
  }
  t.finish();
  return p;
}

Vec4 resolve_position(const ScriptPosition& p, const Spacetime& st, const std::string& context) {
  const bool polar = has_polar_scene(st);
  if (p.polar != polar)
    throw FieldError(fmt::format("{}: positions in {} are {}", context, spacetime_name(st),
                                 polar ? "Boyer–Lindquist {r, theta, phi} (degrees)" : "Cartesian {x, y, z}"));
  if (polar && !(p.coords[1] > 0.0) && !scene_radius_is_signed(st))
    throw FieldError(fmt::format("{}: r must be > 0, got {}", context, p.coords[1]));
  return p.coords;
}

CameraSpec read_camera(TableReader& t) { return CameraSpecKinds(read_kind<CameraSpecs>(t, "a camera constructor")); }


SkySpec read_sky(TableReader& t) {
  return read_kind<SkyRegistry>(t, "a sky constructor");
}

std::vector<EndSky> read_end_skies(TableReader& t, const Spacetime& st, bool scene_has_sky) {
  const std::span<const SpacetimeEnd> ends = spacetime_ends(st);
  const std::string where = line_of_a_value(t);
  std::string far;
  for (const SpacetimeEnd& e : ends)
    if (is_far(e.kind)) far += (far.empty() ? "" : ", ") + std::string(e.name);
  std::vector<EndSky> out;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const std::string name(ends[i].name);
    if (!t.has(name)) continue;
    if (!is_far(ends[i].kind))
      fail_at(where, t, fmt::format("'{}' is a horizon of {}: no ray that reaches it sees a sky (the ends with a sky: {})",
                                    name, spacetime_name(st), far));
    auto sky = t.table(name);
    SkySpec spec = read_sky(sky);
    if (i == 0) {
      // The first end's sky is the scene's `sky`, given once.
      if (scene_has_sky)
        fail_at(where, t,
                fmt::format("the sky at '{}' is the scene's `sky`, given twice: keep one of `sky` and `skies.{}`", name,
                            name));
    } else if (has_point_stars(spec)) {
      // The star stage draws points from the rays that reached the first
      // end (render/shade.hpp): a further end's points would be lost.
      fail_at(where, t,
              fmt::format("the sky at '{}' is lc.{}, whose stars are drawn as points on the scene's first sky only; "
                          "give this end lc.sky_stars{{...}} (the same stars painted into the sky) or lc.sky_image, "
                          "lc.sky_checker",
                          name, SkyRegistry::name(spec)));
    }
    out.push_back({i, name, std::move(spec)});
  }
  try {
    t.finish();
  } catch (const lua::FieldError& e) {
    throw lua::FieldError(
        led_by(where, fmt::format("{} ({} has these ends with a sky: {})", e.what(), spacetime_name(st), far)));
  }
  return out;
}

LightParams read_light(TableReader& t) {
  expect_kind(t, {"light"}, "lc.light{...}");
  LightParams p;
  read_fields(t, p);
  validate_at(t, p);
  t.finish();
  return p;
}

WorldlineSpec read_worldline(TableReader& t) {
  expect_kind(t, {"worldline"}, "lc.worldline{...}");
  t.mark_known({"spacetime", "start", "velocity", "duration"});
  t.finish();  // unknown keys before bad values, as for declared fields (field_reader.hpp)
  WorldlineSpec w;
  w.where = t.string_or("__where", t.context());
  auto st = t.table("spacetime");
  w.spacetime = read_spacetime(st);
  auto start = t.table("start");
  w.start = resolve_position(read_position(start), w.spacetime, start.context());
  if (auto v = t.optional_table("velocity")) w.velocity = read_leg_vector(*v, has_polar_scene(w.spacetime));
  if (!(norm3(w.velocity) < 1.0))
    fail(t, fmt::format("|velocity| = {} must be below the speed of light (1)", norm3(w.velocity)));
  w.duration = positive(t, "duration");
  if (w.duration > max_worldline_duration)
    fail(t, fmt::format("field 'duration' must be at most {:g} M of proper time, got {:g} (a worldline is held in "
                        "memory, ~9.5 KB per M: docs/shots.md, Limits)",
                        max_worldline_duration, w.duration));
  t.finish();
  return w;
}

Placement read_placement(TableReader& t, const Spacetime* st) {
  const bool has_pos = t.has("position"), has_wl = t.has("worldline");
  if (has_pos == has_wl) fail(t, "give either position (held at rest) or worldline (free fall)");
  Placement out;
  if (has_pos) {
    auto p = t.table("position");
    const ScriptPosition sp = read_position(p);
    const std::string where = t.string_or("__where", "");
    out.at = st ? resolve_position(sp, *st, led_by(where, p.context())) : sp.coords;
  } else {
    auto w = t.table("worldline");
    out.at = read_worldline(w);
  }
  return out;
}

namespace {

// What an observer kind holds besides its declared fields, read by hand,
// each in one place: an observer at rest's position (the table's own
// {t, r, theta, phi} or {t, x, y, z}), a free fall's worldline.  Positions
// resolve against `st` when given.
template <class Kind>
void read_observer_extra(TableReader& t, AtRestParams<Kind>& o, const Spacetime* st) {
  const ScriptPosition p = read_position(t);  // reads and finishes t
  // Led by the line that made the observer: the scene's spacetime judges
  // the position only now, past the constructor's call.
  const std::string where = t.string_or("__where", "");
  o.position = st ? resolve_position(p, *st, led_by(where, t.context())) : p.coords;
}
void read_observer_extra(TableReader& t, FreeFall::Params& o, const Spacetime*) {
  auto w = t.table("worldline");
  o.worldline = read_worldline(w);
}
// A kind with only declared fields (a circular orbit) holds nothing more.
void read_observer_extra(TableReader&, CircularOrbit::Params&, const Spacetime*) {}

}  // namespace

ObjectSpec read_object(TableReader& t, const Spacetime* st) {
  return ObjectSpecKinds(read_kind<ObjectSpecs>(t, "an object constructor", "", st));
}

ObserverSpec read_observer(TableReader& t, const Spacetime* st) {
  return read_kind<ObserverRegistry>(t, "an observer constructor", "", st,
                                     [&](auto* p) { read_observer_extra(t, *p, st); });
}

SceneSpec read_scene_spec(TableReader& t) {
  SceneSpec fs;
  auto st = t.table("spacetime");
  fs.spacetime = read_spacetime(st);
  {
    auto o = t.table("observer");
    fs.observer = read_observer(o, &fs.spacetime);
  }
  if (auto time = t.optional_number("time"))
    if (const std::string refused = set_scene_time(fs.observer, *time); !refused.empty()) fail(t, refused);
  if (auto c = t.optional_table("camera")) fs.camera = read_camera(*c);
  if (auto d = t.optional_table("disk")) fs.objects.push_back(read_object(*d, &fs.spacetime));
  if (auto s = t.optional_table("sky")) fs.sky = read_sky(*s);
  if (auto s = t.optional_table("skies")) {
    fs.end_skies = read_end_skies(*s, fs.spacetime, t.has("sky"));
    // `skies.<first end>` is the scene's `sky` by its end's name.
    if (!fs.end_skies.empty() && fs.end_skies.front().end == 0) {
      fs.sky = std::move(fs.end_skies.front().sky);
      fs.end_skies.erase(fs.end_skies.begin());
    }
  }
  if (auto l = t.optional_table("light")) fs.light = read_light(*l);
  if (auto shutter = t.optional_number("shutter")) {
    if (!(*shutter >= 0.0 && *shutter <= 1.0))
      fail(t, fmt::format("field 'shutter' must be between 0 and 1 (frame intervals the shutter is open), got {:g}",
                          *shutter));
    fs.shutter = *shutter;
  }
  if (auto exposure = t.optional_number("exposure")) {
    if (!(*exposure >= -64.0 && *exposure <= 64.0))
      fail(t, fmt::format("field 'exposure' must be between -64 and 64 (stops), got {:g}", *exposure));
    fs.exposure = *exposure;
  }
  if (auto objs = t.optional_table("objects")) {
    if (objs->length() > max_scene_objects)
      fail(*objs, fmt::format("at most {} objects, got {}", max_scene_objects, objs->length()));
    for (std::size_t i = 1; i <= objs->length(); ++i) {
      auto o = objs->table_at(i);
      fs.objects.push_back(read_object(o, &fs.spacetime));
    }
    objs->finish();
  }
  t.finish();
  return fs;
}

ShotInfo read_shot_info(TableReader& t) {
  ShotInfo s;
  read_fields(t, s);
  validate_at(t, s);
  return s;
}

}  // namespace lc
