#include "script/engine_api.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "camera/camera_params.hpp"
#include "lua/table_reader.hpp"
#include "objects/object_params.hpp"
#include "script/scene_reader.hpp"
#include "script/spacetime_reader.hpp"
#include "spacetime/chart.hpp"
#include "spacetime/spacetime.hpp"
#include "worldline/worldline.hpp"

namespace lc {

namespace {

// Builds {__kind = kind, __where = "file:line", <every argument field>} from
// the call's argument table (a missing table reads as {}), leaving it on the
// stack top, and returns a reader of it. The copy gets the argument's
// metatable, so that the reader refuses fields its __index would give (the
// copy holds own fields only); construct() takes it off again.
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
  if (lua_getmetatable(L, 1) != 0) lua_setmetatable(L, out);
  return lua::TableReader(L, out, kind);
}

// A constructor lc.<kind>{...}: copy and tag the arguments, then validate
// them with the same reader the engine uses on the frame's scene, so an
// error names the script line that made the value.  The kind's name and its
// validator are the closure's upvalues.
using Validator = void (*)(lua::TableReader&);
int construct(lua_State* L) {
  return lua::protect(L, [](lua_State* L) {
    const char* kind = lua_tostring(L, lua_upvalueindex(1));
    const auto validate = reinterpret_cast<Validator>(lua_touserdata(L, lua_upvalueindex(2)));
    {
      lua::TableReader r = tagged_copy(L, kind);
      validate(r);
    }
    lua_pushnil(L);
    lua_setmetatable(L, -2);
    return 1;
  });
}

void validate_spacetime(lua::TableReader& t) { read_spacetime(t); }
void validate_camera(lua::TableReader& t) { read_camera(t); }
void validate_object(lua::TableReader& t) { read_object(t, nullptr); }
void validate_sky(lua::TableReader& t) { read_sky(t); }
void validate_worldline(lua::TableReader& t) { read_worldline(t); }
void validate_light(lua::TableReader& t) { read_light(t); }
void validate_observer(lua::TableReader& t) { read_observer(t, nullptr); }

// apocentres(w) -> array of {t = scene time, tau = proper time, r = radius}
// where the worldline's distance from the origin peaks (turning points of an
// oscillation).  Integrates the worldline (once per call).
int l_apocentres(lua_State* L) {
  return lua::protect(L, [](lua_State* L) {
    auto* memo = static_cast<EngineMemo*>(lua_touserdata(L, lua_upvalueindex(1)));
    const WorldlineSpec spec = [&] {
      lua::TableReader t(L, 1, "apocentres");
      return read_worldline(t);
    }();
    auto compute = [&] {
      const Worldline w = Worldline::integrate(spec);
      std::vector<EngineMemo::Apocentre> out;
      for (const WorldlineEvent& e : w.apocentres()) {
        double t_unused, r, phi_unused;
        std::visit([&](const auto& st) { scene_polar(st, e.x, t_unused, r, phi_unused); }, w.spacetime().kinds());
        out.push_back({w.scene_time(e.x), e.tau, r});
      }
      return out;
    };
    std::vector<EngineMemo::Apocentre> uncached;
    const std::vector<EngineMemo::Apocentre>& events =
        memo ? memo->apocentres(spec.key(), compute) : (uncached = compute());
    lua_createtable(L, static_cast<int>(events.size()), 0);
    for (std::size_t i = 0; i < events.size(); ++i) {
      lua_createtable(L, 0, 3);
      lua_pushnumber(L, events[i].t);
      lua_setfield(L, -2, "t");
      lua_pushnumber(L, events[i].tau);
      lua_setfield(L, -2, "tau");
      lua_pushnumber(L, events[i].r);
      lua_setfield(L, -2, "r");
      lua_rawseti(L, -2, static_cast<int>(i + 1));
    }
    return 1;
  });
}

// What the names of `lc` are, in the order the error for an unknown one
// lists them.  Every constructor the engine makes has one of the first six;
// the rest (lc.apocentres, lc.look_at, the animation helpers of
// scripts/lightcone/animation.lua, a shot's own additions) are helpers.
enum class NameGroup { spacetimes, observers, cameras, skies, objects, light, helpers };
constexpr std::array<std::string_view, 7> kGroupTitles = {
    "spacetimes", "observers and worldlines", "cameras", "skies", "objects", "light", "helpers"};

// lc's __index (scripts/lightcone.lua): lc.<name> for a name lc lacks.
// Arguments: lc and the key; upvalue 1 maps each constructor's name to its
// NameGroup, upvalue 2 the other names of special cases (a spacetime's
// other_names: lc.kerr_newman) to how they are written.  Raises, at the script line that reads the name, an error that
// says it is no lightcone constructor or function, suggests the nearest
// name and lists every name lc has by group, so `lc.fisheye{...}` fails
// there instead of as "attempt to call field 'fisheye' (a nil value)".  A
// script tests for a name without the error by rawget(lc, name).
int l_unknown_name(lua_State* L) {
  return lua::protect(L, [](lua_State* L) -> int {
    std::array<std::vector<std::string>, kGroupTitles.size()> groups;
    std::vector<std::string> all;
    lua_settop(L, 2);
    lua_pushnil(L);
    while (lua_next(L, 1) != 0) {
      lua_pop(L, 1);
      if (lua_type(L, -1) != LUA_TSTRING) continue;
      std::size_t n = 0;
      const char* p = lua_tolstring(L, -1, &n);
      std::string name(p, n);
      if (name.starts_with("__")) continue;
      lua_pushvalue(L, -1);
      lua_rawget(L, lua_upvalueindex(1));
      const auto group = lua_isnumber(L, -1) ? static_cast<std::size_t>(lua_tointeger(L, -1))
                                             : static_cast<std::size_t>(NameGroup::helpers);
      lua_pop(L, 1);
      groups[std::min(group, groups.size() - 1)].push_back(name);
      all.push_back(std::move(name));
    }
    std::string shown;
    std::string suggestion;
    if (lua_type(L, 2) == LUA_TSTRING) {
      std::size_t n = 0;
      const char* p = lua_tolstring(L, 2, &n);
      const std::string key(p, n);
      // A script may index lc with a string of any length: a long one is cut.
      constexpr std::size_t kShown = 64;
      shown = n <= kShown ? "lc." + key : fmt::format("lc.{}...", key.substr(0, kShown));
      std::sort(all.begin(), all.end());
      lua_pushvalue(L, 2);
      lua_rawget(L, lua_upvalueindex(2));  // a special case's other name
      if (lua_type(L, -1) == LUA_TSTRING)
        throw lua::FieldError(fmt::format("{} is no constructor of its own: it is written {} (docs/physics.md)", shown,
                                          lua_tostring(L, -1)));
      if (const std::string near = lua::nearest(key, all); !near.empty())
        suggestion = fmt::format(" (did you mean lc.{}?)", near);
      lua_pop(L, 1);
    } else if (lua_type(L, 2) == LUA_TNUMBER) {
      shown = fmt::format("lc[{}]", lua_tonumber(L, 2));
    } else {
      shown = fmt::format("lc[<a {}>]", luaL_typename(L, 2));
    }
    std::string listed;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (groups[g].empty()) continue;
      std::sort(groups[g].begin(), groups[g].end());
      std::string names;
      for (const auto& name : groups[g]) names += fmt::format("{}lc.{}", names.empty() ? "" : ", ", name);
      listed += fmt::format("{}{}: {}", listed.empty() ? "" : "; ", kGroupTitles[g], names);
    }
    throw lua::FieldError(fmt::format("{} is not a lightcone constructor or function{}; lc has {} (docs/shots.md)",
                                      shown, suggestion, listed));
  });
}

}  // namespace

void install_engine_api(lua::Sandbox& sandbox, EngineMemo* memo) {
  lua_State* L = sandbox.state();
  lua_newtable(L);
  const int api = lua_gettop(L);
  lua_newtable(L);  // constructor name -> NameGroup, for l_unknown_name
  const int groups = lua_gettop(L);
  auto add = [&](std::string_view kind, Validator validate, NameGroup group) {
    const std::string name(kind);
    lua_pushlstring(L, kind.data(), kind.size());
    lua_pushlightuserdata(L, reinterpret_cast<void*>(validate));
    lua_pushcclosure(L, &construct, 2);
    lua_setfield(L, api, name.c_str());
    lua_pushinteger(L, static_cast<lua_Integer>(group));
    lua_setfield(L, groups, name.c_str());
  };
  // Every registered spacetime (spacetime/spacetime.hpp) by its name.
  SpacetimeRegistry::for_each([&](auto* kind) { add(std::remove_pointer_t<decltype(kind)>::name, validate_spacetime, NameGroup::spacetimes); });
  SkyRegistry::for_each(
      [&](auto* kind) { add(std::remove_pointer_t<decltype(kind)>::name, validate_sky, NameGroup::skies); });
  ObserverRegistry::for_each(
      [&](auto* kind) { add(std::remove_pointer_t<decltype(kind)>::name, validate_observer, NameGroup::observers); });
  CameraSpecs::for_each(
      [&](auto* kind) { add(std::remove_pointer_t<decltype(kind)>::name, validate_camera, NameGroup::cameras); });
  ObjectSpecs::for_each(
      [&](auto* kind) { add(std::remove_pointer_t<decltype(kind)>::name, validate_object, NameGroup::objects); });
  add("worldline", validate_worldline, NameGroup::observers);
  add("light", validate_light, NameGroup::light);
  lua_newtable(L);  // other name -> how it is written, for l_unknown_name
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    if constexpr (requires { S::other_names; })
      for (const OtherName& o : S::other_names) {
        lua_pushlstring(L, o.written.data(), o.written.size());
        lua_setfield(L, -2, std::string(o.name).c_str());
      }
  });
  lua_pushcclosure(L, &l_unknown_name, 2);  // takes the group and other-name tables
  lua_setfield(L, api, "__unknown_name");
  // The camera constructors' names in registry order, for lc.look_at
  // (scripts/lightcone.lua), which builds any of them.
  lua_newtable(L);
  int camera = 0;
  CameraSpecs::for_each([&](auto* kind) {
    const std::string_view name = std::remove_pointer_t<decltype(kind)>::name;
    lua_pushlstring(L, name.data(), name.size());
    lua_rawseti(L, -2, ++camera);
  });
  lua_setfield(L, api, "__camera_kinds");
  lua_pushlightuserdata(L, memo);
  lua_pushcclosure(L, l_apocentres, 1);
  lua_setfield(L, api, "apocentres");
  lua_setglobal(L, "__lightcone");
}

}  // namespace lc
