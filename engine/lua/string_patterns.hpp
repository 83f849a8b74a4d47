#pragma once
// string.find, string.match, string.gmatch and string.gsub for the sandbox.
//
// They give the results LuaJIT's own give (Lua 5.1 patterns, LuaJIT's
// argument conversions, limits and error messages; tested side by side in
// lua_patterns_test), but LuaJIT's match in C until it is done, and a
// pattern like ("a*"):rep(60) .. "b" backtracks for longer than any time
// limit. These check the sandbox's clock as they go (detail::check_time)
// and fail with its time-limit message at the script line. gsub builds its
// result in the Lua heap, under the memory cap, and holds a
// detail::NestedCall while it calls a replacement function or a table's
// __index.

#include <lua.hpp>

namespace lc::lua {

// Replaces find, match, gmatch and gsub in the string table of a state made
// by a Sandbox (the functions reach its limits through the state's
// allocator data). Strings' methods are the string table, so s:find(...)
// uses them too.
void install_string_patterns(lua_State* L);

}  // namespace lc::lua
