#pragma once
// The sandbox's versions of the base-library functions through which a
// script could crash the process or slip past the time limit. Each behaves
// as LuaJIT's own for any script that stays within the limits:
//
// - coroutine.resume and the functions coroutine.wrap makes run a coroutine
//   on the C stack of their caller, so recursion through them overflows it
//   (LuaJIT has no check): they hold a detail::NestedCall while it runs.
// - table.sort calls its comparator from C: the comparator is wrapped in a
//   function that holds a NestedCall.
// - xpcall: LuaJIT runs the handler of an error raised by the time limit
//   with the instruction hook disabled, so a looping handler was never
//   stopped; once the time is up, handlers are skipped (the error passes on
//   unchanged). A handler also holds a NestedCall (one may raise and catch
//   inside another).
// - pcall: LuaJIT 2.1 (before 2023) does not check the Lua stack when pcall
//   is a value's own __call metamethod; called through a Lua function it is.
// - tostring tail-calls a __tostring metamethod without running an
//   instruction, so `__tostring = tostring` looped where the hook never
//   fired; through a Lua function it runs instructions. That function is
//   determinism.cpp's, which also gives addresses deterministic names.
//
// print, require and the string library's pattern functions are the
// sandbox's own and hold NestedCalls themselves (sandbox.cpp,
// string_patterns.cpp).

#include <lua.hpp>

namespace lc::lua {

// Replaces those functions in the globals of a state made by a Sandbox
// (they reach its limits through the state's allocator data). Call once,
// after the libraries are opened and before any script runs.
void install_library_guards(lua_State* L);

}  // namespace lc::lua
