#include "script/engine_api.hpp"

#include <string>

#include "lua/table_reader.hpp"
#include "script/scene_reader.hpp"
#include "scene/worldline.hpp"
#include "spacetime/chart.hpp"
#include "script/spacetime_reader.hpp"

namespace lc {

namespace {

// Builds {__kind = kind, __where = "file:line", <every argument field>} from
// the call's argument table (a missing table reads as {}), leaving it on the
// stack top, and returns a reader of it.
lua::TableReader tagged_copy(lua_State* L, const char* kind) {
  if (lua_isnoneornil(L, 1)) {
    lua_settop(L, 0);
    lua_newtable(L);
  }
  if (!lua_istable(L, 1))
    throw lua::FieldError(std::string(kind) + ": expected a table of fields, like " + kind + "{...}, got " +
                          luaL_typename(L, 1));
  lua_newtable(L);
  const int out = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, 1) != 0) {
    lua_pushvalue(L, -2);
    lua_insert(L, -2);
    lua_rawset(L, out);
  }
  lua_pushstring(L, kind);
  lua_setfield(L, out, "__kind");
  const std::string where = lua::Sandbox::where(L, 1);
  lua_pushstring(L, where.c_str());
  lua_setfield(L, out, "__where");
  return lua::TableReader(L, out, kind);
}

// One constructor: copy and tag the arguments, then validate them with the
// same reader the engine uses on the frame's scene, so an error names the
// script line that made the value.
template <void (*Validate)(lua::TableReader&)>
int construct(lua_State* L, const char* kind) {
  return lua::protect(L, [kind](lua_State* L) {
    {
      lua::TableReader r = tagged_copy(L, kind);
      Validate(r);
    }
    return 1;
  });
}

void validate_spacetime(lua::TableReader& t) { read_spacetime(t, KerrSchildSense::outgoing); }
void validate_camera(lua::TableReader& t) { read_camera(t); }
void validate_disk(lua::TableReader& t) { read_disk(t); }
void validate_sky(lua::TableReader& t) { read_sky(t); }
void validate_worldline(lua::TableReader& t) { read_worldline(t); }
void validate_sphere(lua::TableReader& t) { read_sphere(t, nullptr); }
void validate_observer(lua::TableReader& t) { read_observer(t, nullptr); }

// apocentres(w) -> array of {t = scene time, tau = proper time, r = radius}
// where the worldline's distance from the origin peaks (turning points of an
// oscillation).  Integrates the worldline (once per call).
int l_apocentres(lua_State* L) {
  return lua::protect(L, [](lua_State* L) {
    const Worldline w = [&] {
      lua::TableReader t(L, 1, "apocentres");
      return Worldline::integrate(read_worldline(t));
    }();
    const std::vector<WorldlineEvent> events = w.apocentres();
    lua_createtable(L, static_cast<int>(events.size()), 0);
    for (std::size_t i = 0; i < events.size(); ++i) {
      lua_createtable(L, 0, 3);
      lua_pushnumber(L, w.scene_time(events[i].x));
      lua_setfield(L, -2, "t");
      lua_pushnumber(L, events[i].tau);
      lua_setfield(L, -2, "tau");
      double t_unused, r, phi_unused;
      std::visit([&](const auto& st) { scene_polar(st, events[i].x, t_unused, r, phi_unused); }, w.spacetime());
      lua_pushnumber(L, r);
      lua_setfield(L, -2, "r");
      lua_rawseti(L, -2, static_cast<int>(i + 1));
    }
    return 1;
  });
}

#define LC_CONSTRUCTOR(name, validate) \
  int l_##name(lua_State* L) { return construct<validate>(L, #name); }
LC_CONSTRUCTOR(kerr, validate_spacetime)
LC_CONSTRUCTOR(dihole, validate_spacetime)
LC_CONSTRUCTOR(minkowski, validate_spacetime)
LC_CONSTRUCTOR(camera, validate_camera)
LC_CONSTRUCTOR(disk, validate_disk)
LC_CONSTRUCTOR(sky_checker, validate_sky)
LC_CONSTRUCTOR(sky_image, validate_sky)
LC_CONSTRUCTOR(sky_stars, validate_sky)
LC_CONSTRUCTOR(worldline, validate_worldline)
LC_CONSTRUCTOR(sphere, validate_sphere)
LC_CONSTRUCTOR(static_observer, validate_observer)
LC_CONSTRUCTOR(zamo, validate_observer)
LC_CONSTRUCTOR(free_fall, validate_observer)
#undef LC_CONSTRUCTOR

}  // namespace

void install_engine_api(lua::Sandbox& sandbox) {
  lua_State* L = sandbox.state();
  lua_newtable(L);
  const luaL_Reg functions[] = {
      {"kerr", l_kerr},           {"dihole", l_dihole},           {"minkowski", l_minkowski},
      {"camera", l_camera},       {"disk", l_disk},               {"sky_checker", l_sky_checker},
      {"sky_image", l_sky_image}, {"sky_stars", l_sky_stars}, {"worldline", l_worldline},     {"sphere", l_sphere},
      {"static_observer", l_static_observer}, {"zamo", l_zamo},   {"free_fall", l_free_fall},
      {"apocentres", l_apocentres},
      {nullptr, nullptr}};
  for (const luaL_Reg* f = functions; f->name; ++f) {
    lua_pushcfunction(L, f->func);
    lua_setfield(L, -2, f->name);
  }
  lua_setglobal(L, "__lightcone");
}

}  // namespace lc
