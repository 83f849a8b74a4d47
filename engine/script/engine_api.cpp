#include "script/engine_api.hpp"

#include <string>

#include "lua/table_reader.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace {

// Starts the tagged result table: {__kind = kind, __where = "file:line"}.
void push_tagged(lua_State* L, const char* kind) {
  lua_newtable(L);
  lua_pushstring(L, kind);
  lua_setfield(L, -2, "__kind");
  const std::string where = lua::Sandbox::where(L, 1);
  lua_pushstring(L, where.c_str());
  lua_setfield(L, -2, "__where");
}

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

// Argument table of a constructor call f{...}; a missing table reads as {}.
lua::TableReader arguments(lua_State* L, const char* name) {
  if (lua_isnoneornil(L, 1)) {
    lua_settop(L, 0);
    lua_newtable(L);
  }
  return lua::TableReader(L, 1, name);
}

// kerr{mass = M, spin = a}: |a| <= M, M >= 0.
int l_kerr(lua_State* L) {
  return lua::protect(L, [](lua_State* L) {
    auto args = arguments(L, "kerr");
    const double M = args.number("mass");
    const double a = args.number_or("spin", 0.0);
    args.finish();
    const Kerr check(M, a);  // throws with the reason
    push_tagged(L, "kerr");
    set_number(L, "mass", M);
    set_number(L, "spin", a);
    return 1;
  });
}

// dihole{m1 = , m2 = , d = 1}: holes at z = +d (m1) and z = -d (m2).
int l_dihole(lua_State* L) {
  return lua::protect(L, [](lua_State* L) {
    auto args = arguments(L, "dihole");
    const double m1 = args.number("m1");
    const double m2 = args.number("m2");
    const double d = args.number_or("d", 1.0);
    args.finish();
    const Dihole check(m1, m2, d);
    push_tagged(L, "dihole");
    set_number(L, "m1", m1);
    set_number(L, "m2", m2);
    set_number(L, "d", d);
    return 1;
  });
}

int l_minkowski(lua_State* L) {
  return lua::protect(L, [](lua_State* L) {
    arguments(L, "minkowski").finish();
    push_tagged(L, "minkowski");
    return 1;
  });
}

}  // namespace

void install_engine_api(lua::Sandbox& sandbox) {
  lua_State* L = sandbox.state();
  lua_newtable(L);
  const luaL_Reg functions[] = {{"kerr", l_kerr}, {"dihole", l_dihole}, {"minkowski", l_minkowski}, {nullptr, nullptr}};
  for (const luaL_Reg* f = functions; f->name; ++f) {
    lua_pushcfunction(L, f->func);
    lua_setfield(L, -2, f->name);
  }
  lua_setglobal(L, "__lightcone");
}

}  // namespace lc
