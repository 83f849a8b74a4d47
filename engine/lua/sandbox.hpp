#pragma once
// The sandboxed LuaJIT runtime that evaluates shot scripts.
//
// A shot script may only compute: it gets base (without the loaders), table,
// string (without dump), math and bit, plus our own `require` that reads
// modules from a fixed list of directories. Every evaluation (run_file, call)
// runs under a wall-clock limit and the whole state under a memory cap; calls
// nested through C functions are bounded (detail::NestedCall), and the
// library functions that could escape these limits are replaced
// (library_guards.hpp, string_patterns.hpp). What LuaJIT takes from the
// state's hash seed or from addresses (the order of pairs, tostring({})) is
// made deterministic (determinism.hpp). Every failure surfaces in C++ as
// ScriptError with the script's file:line.

#include <lua.hpp>

#include <cstddef>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::lua {

namespace detail {
class NestedCall;
void check_time(lua_State* L);
bool timed_out(lua_State* L);
}  // namespace detail

// A script failed to load or run. what() starts with the `file:line: message`
// Lua produced, followed by a short traceback (one frame a line).
class ScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Resource limits of one Sandbox. memory_bytes caps the whole Lua heap while a
// script is being evaluated; seconds is the wall-clock budget of each single
// evaluation (one run_file or one call). set_by is quoted in the limit
// messages so an author learns where the limit comes from (e.g. a CLI flag).
// The clock is checked between VM instructions and inside the string
// library's pattern matching, the one place where a script can make C code
// run for long.
struct SandboxLimits {
  std::size_t memory_bytes = 512u << 20;
  double seconds = 30.0;
  std::string set_by = "the default sandbox limits";
};

// One sandboxed lua_State. Not copyable; movable (a moved-from Sandbox only
// supports destruction and state() == nullptr). Not thread-safe: one thread
// at a time, like any lua_State. Engine code using state() directly outside
// run_file/call must stick to raw access (lua_rawget, TableReader): a script
// table's metamethods would otherwise run unprotected, and an error there
// ends the process (LuaJIT's panic) or is caught by any catch (...).
class Sandbox {
 public:
  // require_dirs: where `require` looks for modules, in order. Throws
  // std::invalid_argument for non-positive limits, ScriptError if the Lua
  // state cannot be created.
  explicit Sandbox(std::vector<std::filesystem::path> require_dirs, SandboxLimits limits = {});
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;
  Sandbox(Sandbox&&) noexcept;
  Sandbox& operator=(Sandbox&&) noexcept;

  // Loads `file` as Lua source (bytecode refused; chunkname "@" + file as
  // given) and runs it under the limits. On success leaves nresults values
  // (LUA_MULTRET: all of them) on the stack; on failure the stack is as
  // before and ScriptError is thrown. An unreadable file names the path and
  // the OS reason.
  void run_file(const std::filesystem::path& file, int nresults = 1);

  // Protected call of the function lying below its nargs arguments on top of
  // the stack, under the limits (a fresh time budget per call). Like
  // lua_pcall it consumes function and arguments and leaves nresults values;
  // on failure it leaves nothing and throws ScriptError. Cheap enough to call
  // per frame: no allocation besides what the Lua code itself does.
  void call(int nargs, int nresults);

  // Modules named "<prefix>.<rest>" are read from `dir` alone, as <rest>
  // (dots are folders): "lightcone.shots" for the project's shots/ folder.
  // `dir` becomes one of the folders a module's real path may lie in.
  // Throws std::invalid_argument if `prefix` is no module name. Call before
  // the scripts run.
  void mount_modules(std::string prefix, std::filesystem::path dir);

  // Every file loaded so far (main scripts and required modules), canonical
  // paths, each once, in order of first load; what a shot's content hash
  // must cover.
  const std::vector<std::filesystem::path>& loaded_files() const;

  const SandboxLimits& limits() const;
  lua_State* state() const;

  // "file.lua:12" for the Lua function at stack `level` (0 = running
  // function; inside a lua_CFunction 1 = the script line that called it).
  // The path is the chunkname without '@', untruncated. "?" if unknown.
  static std::string where(lua_State* L, int level);

 private:
  struct Impl;
  friend class detail::NestedCall;
  friend void detail::check_time(lua_State* L);
  friend bool detail::timed_out(lua_State* L);
  std::unique_ptr<Impl> impl_;
};

// Raises a Lua error "file.lua:LINE: msg" at the script line that called the
// current C function. Only call it from inside a lua_CFunction that runs
// under a protected call (Sandbox::run_file/call). On x64 LuaJIT unwinds Lua
// errors with the system unwinder, so C++ destructors of the frames it skips
// do run (tested in sandbox_test); still prefer to raise from a frame
// that owns no resources, since a frame built without unwind tables would
// break that. Prefer protect() + a C++ exception in new code.
[[noreturn]] void raise(lua_State* L, const std::string& msg);

namespace detail {
// Pushes "file:LINE: what" for the script line calling the current C
// function (or, if that is not a Lua line, the nearest Lua line below it),
// without doubling the location if `what` already starts with it.
void push_located_message(lua_State* L, const char* what);

// The rest of this namespace is for the C functions of the sandbox's own
// library (sandbox.cpp, library_guards.cpp, string_patterns.cpp): they find
// their Sandbox through the state's allocator, so they only work in states
// that a Sandbox made.

// How many C functions may be calling back into Lua at once (a gsub or sort
// callback, a coroutine resumed, print's __tostring, require, an error
// handler). Each such call holds C stack that LuaJIT's own stack checks do
// not see: nested without bound they crash the process.
constexpr int kMaxNestedCalls = 200;

// Holds one level of that nesting while it lives. The constructor raises a
// Lua error at the calling script line ("too deeply nested") instead, when
// kMaxNestedCalls levels are held or the running thread's C stack is nearly
// used up; construct it in a C function just before it calls back into Lua.
// The count makes the limit the same on every thread; the stack check keeps
// a thread with a small stack from crashing first.
class NestedCall {
 public:
  explicit NestedCall(lua_State* L);
  ~NestedCall();
  NestedCall(const NestedCall&) = delete;
  NestedCall& operator=(const NestedCall&) = delete;

  // Whether constructing one now would succeed (for code that must not
  // raise, like a message handler).
  static bool allowed(lua_State* L);

 private:
  lua_State* L_;
};

// Raises the time-limit error at the calling script line once the running
// evaluation is past its deadline: for C code that may run long without
// returning to the VM, where the clock is checked between instructions.
void check_time(lua_State* L);

// True once the running evaluation has hit its time limit. From then on it
// fails at every instruction, and no script error handler may run: LuaJIT
// runs handlers of an error raised by the limit with its instruction hook
// disabled, so a handler would run on without limit.
bool timed_out(lua_State* L);
}  // namespace detail

// Runs f(L) (returning the number of Lua results) inside a lua_CFunction and
// turns any std::exception into a Lua error carrying its message at the
// calling script line; without this LuaJIT reports a bare "C++ exception".
// Only std::exception is caught: Lua errors raised inside f are foreign
// exceptions on x64 and must pass through untouched (a catch (...) would
// swallow them), and other C++ exception types still become "C++ exception".
//
//   int l_kerr(lua_State* L) { return lc::lua::protect(L, [](lua_State* L) {
//     ...; return 1; }); }
template <class F>
int protect(lua_State* L, F&& f) {
  try {
    return static_cast<F&&>(f)(L);
  } catch (const std::exception& e) {
    detail::push_located_message(L, e.what());
  }
  // Raised only once the C++ exception object has been destroyed.
  return lua_error(L);
}

}  // namespace lc::lua
