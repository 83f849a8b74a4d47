#pragma once
// The sandbox's versions of the library functions whose results LuaJIT
// takes from the state's hash seed or from memory addresses. A frame must
// depend only on the shot's files and its number, but every frame runs in
// a fresh state, and Debian's LuaJIT seeds each state's string hash anew:
// `pairs` over string keys walked them in another order in every state,
// and `tostring({})` showed an address. So, in the sandbox:
//
// - pairs(t) walks the keys in a fixed order: integer numbers ascending,
//   then other numbers ascending, then strings by their bytes, then false
//   and true. A table whose keys include a table, function, coroutine or
//   userdata, whose only order is its address, is refused at the calling
//   line (advising an array). pairs takes the keys when it is called: keys
//   assigned during the walk are not visited (Lua leaves that undefined),
//   keys cleared during it are skipped.
// - next(t, k) returns the key after k in that order (the first for nil),
//   looking through the whole table on every call: use pairs to walk one.
// - table.foreach walks as pairs does.
// - tostring of a table, function, coroutine or userdata without
//   __tostring gives "table: #N", N numbering such values in the order the
//   script first asks for one (deterministic because the script is);
//   string.format's %s does the same, and %p gives "#N" (for a string
//   too; NULL for a number, boolean or nil, as LuaJIT's).
//
// - setmetatable refuses a metatable with __mode: what a weak table keeps
//   depends on when the collector runs, which follows the state's seed.
// Left as Lua leaves it: `#` of a table with holes (nil inside its array)
// is any border, and which one can follow the seed; docs/shots.md says so.
//
// tostring stays a Lua function for the reason library_guards.hpp gives
// (`__tostring = tostring` must run instructions, so the time limit sees
// it).

#include <lua.hpp>

namespace lc::lua {

// Replaces those functions in the globals of a state made by a Sandbox
// (errors name the script line through it). Call once, after the
// libraries are opened and install_library_guards has run, before any
// script runs.
void install_determinism(lua_State* L);

}  // namespace lc::lua
