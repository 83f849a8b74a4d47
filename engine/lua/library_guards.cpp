#include "lua/library_guards.hpp"

#include <cstring>
#include <stdexcept>

#include "lua/sandbox.hpp"

namespace lc::lua {

namespace {

// Calls upvalue 1 with this call's arguments and returns all its results,
// holding one level of C-call nesting meanwhile.
int call_nested(lua_State* L) {
  const detail::NestedCall nested(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

// nested(f) -> a function that calls f under call_nested.
int make_nested(lua_State* L) {
  luaL_checktype(L, 1, LUA_TFUNCTION);
  lua_settop(L, 1);
  lua_pushcclosure(L, &call_nested, 1);
  return 1;
}

// coroutine.resume(co, ...): LuaJIT's (upvalue 1) under call_nested. The
// argument is checked here, so that an error names 'resume' and the
// script line (LuaJIT's, called from C, could name neither).
int resume(lua_State* L) {
  if (lua_type(L, 1) != LUA_TTHREAD) luaL_argerror(L, 1, "coroutine expected");
  return call_nested(L);
}

// A function made by coroutine.wrap: resumes its coroutine (upvalue 2) with
// LuaJIT's resume (upvalue 1) and returns what it yields or returns. Errors
// propagate as LuaJIT's wrap has them, a string with the calling line in
// front, but only if it does not start with that line already (an error
// passed up through 200 nested coroutines named it 200 times).
int resume_wrapped(lua_State* L) {
  const detail::NestedCall nested(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_pushvalue(L, lua_upvalueindex(2));
  lua_insert(L, 2);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  if (lua_toboolean(L, 1)) return lua_gettop(L) - 1;
  lua_settop(L, 2);
  if (lua_type(L, 2) == LUA_TSTRING) detail::push_located_message(L, lua_tostring(L, 2));
  return lua_error(L);
}

// coroutine.wrap(f): a coroutine running f, and resume_wrapped for it.
// Upvalue 1 is LuaJIT's resume.
int wrap(lua_State* L) {
  luaL_checktype(L, 1, LUA_TFUNCTION);
  lua_State* co = lua_newthread(L);
  lua_pushvalue(L, 1);
  lua_xmove(L, co, 1);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, -2);
  lua_pushcclosure(L, &resume_wrapped, 2);
  return 1;
}

// xpcall's handler h made safe: skipped once the evaluation has timed out
// or when no more calls may nest (the error then passes on as it is),
// otherwise run holding a NestedCall. Upvalue 1 is h.
int run_handler(lua_State* L) {
  lua_settop(L, 1);
  if (detail::timed_out(L) || !detail::NestedCall::allowed(L)) return 1;
  const detail::NestedCall nested(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, 1, 1);
  return 1;
}

// guard_handler(h) -> run_handler for h.
int guard_handler(lua_State* L) {
  luaL_checktype(L, 1, LUA_TFUNCTION);
  lua_settop(L, 1);
  lua_pushcclosure(L, &run_handler, 1);
  return 1;
}

// The replacements written in Lua: they tail-call LuaJIT's functions, so
// errors those raise still name the function and the script line, and
// coroutines may still yield across pcall and xpcall. `type` is captured:
// a script may reassign the global.
constexpr const char* kPrelude = R"lua(
local pcall_builtin, xpcall_builtin, sort_builtin, nested, guard_handler = ...
local type = type
function pcall(...) return pcall_builtin(...) end
function xpcall(f, handler, ...)
  if type(handler) ~= "function" then return xpcall_builtin(f, handler, ...) end
  return xpcall_builtin(f, guard_handler(handler), ...)
end
function table.sort(t, comp, ...)
  if type(comp) == "function" then comp = nested(comp) end
  return sort_builtin(t, comp, ...)
end
)lua";

}  // namespace

void install_library_guards(lua_State* L) {
  lua_getglobal(L, LUA_COLIBNAME);
  lua_getfield(L, -1, "resume");
  lua_pushvalue(L, -1);
  lua_pushcclosure(L, &resume, 1);
  lua_setfield(L, -3, "resume");
  lua_pushcclosure(L, &wrap, 1);
  lua_setfield(L, -2, "wrap");
  lua_pop(L, 1);

  if (luaL_loadbuffer(L, kPrelude, std::strlen(kPrelude), "=[sandbox]") != 0) {
    throw std::logic_error(lua_tostring(L, -1));
  }
  lua_getglobal(L, "pcall");
  lua_getglobal(L, "xpcall");
  lua_getglobal(L, LUA_TABLIBNAME);
  lua_getfield(L, -1, "sort");
  lua_remove(L, -2);
  lua_pushcfunction(L, &make_nested);
  lua_pushcfunction(L, &guard_handler);
  lua_call(L, 5, 0);
}

}  // namespace lc::lua
