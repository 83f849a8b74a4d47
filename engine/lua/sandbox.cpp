#include "lua/sandbox.hpp"

#include <fcntl.h>
#include <luajit.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <system_error>
#include <utility>

#include "core/file_checks.hpp"
#include "lua/determinism.hpp"
#include "lua/library_guards.hpp"
#include "lua/string_patterns.hpp"

namespace lc::lua {

namespace {

// print(...) writing to standard error, tab-separated, via tostring (which
// may run a __tostring metamethod: a call back into Lua).
int print_to_stderr(lua_State* L) {
  const int n = lua_gettop(L);
  lua_getglobal(L, "tostring");
  for (int i = 1; i <= n; ++i) {
    lua_pushvalue(L, -1);
    lua_pushvalue(L, i);
    {
      const detail::NestedCall nested(L);
      lua_call(L, 1, 1);
    }
    std::size_t len = 0;
    const char* text = lua_tolstring(L, -1, &len);
    if (text == nullptr) return luaL_error(L, "'tostring' must return a string to 'print'");
    if (i > 1) std::fputc('\t', stderr);
    std::fwrite(text, 1, len, stderr);
    lua_pop(L, 1);
  }
  std::fputc('\n', stderr);
  return 0;
}

using Clock = std::chrono::steady_clock;

// How often (in VM instructions) the deadline is checked. Reading the clock
// costs ~20 ns, so this keeps the check far below 1 % of interpretation.
constexpr int kHookInstructions = 1000;

// Returned by Impl::require_module when the Lua value on top of the stack is
// an error to re-raise as is (it already carries its location).
constexpr int kRethrow = -1;

// Frames of a traceback kept before and after an elision.
constexpr std::size_t kFramesHead = 8;
constexpr std::size_t kFramesTail = 3;

// C stack kept free below the deepest nested call back into Lua, and needed
// to start an evaluation: for what runs there without another check. The
// most is LuaJIT's parser on a module of 200 nested function definitions
// (~224 KiB measured); also up to 1000 VM instructions until the hook looks
// again (a __tostring calling string.format on itself: ~40 KiB), pattern
// matching, the message handler and its traceback.
constexpr std::size_t kStackReserve = 384u << 10;

// Lua stack slots kept free below LuaJIT's limit (65,500 slots, about
// 22,000 levels of a small function): a recursion fails once fewer are
// left, where the message handler still has room (time_hook). Below 8,000:
// lua_checkstack refuses more at once.
constexpr int kLuaStackReserve = 6000;

// Levels of calls below which the Lua stack cannot be within
// kLuaStackReserve of LuaJIT's limit: 200 frames of LuaJIT's largest (250
// slots and 2 of the frame's own) are 50,400 slots.
constexpr int kDeepLevels = 200;

// The time an error object's __tostring gets from the message handler: it
// only has to produce a line of text.
constexpr double kTostringSeconds = 0.1;

// The longest error message kept (a script may raise a string of hundreds
// of MiB, which would be copied into the traceback, the exception, stderr).
constexpr std::size_t kMaxMessageBytes = 4096;

// `text`, cut to kMaxMessageBytes.
std::string clipped(std::string_view text) {
  if (text.size() <= kMaxMessageBytes) return std::string(text);
  return fmt::format("{}... ({} more bytes)", text.substr(0, kMaxMessageBytes), text.size() - kMaxMessageBytes);
}

// The most of a module name or path a require message quotes: names may
// be of any length, and a message is cut at kMaxMessageBytes, which must
// not take its reason.
constexpr std::size_t kShownNameBytes = 200;

// `text` as a require message quotes it: whole up to kShownNameBytes, else
// its start and its length.
std::string shortened(std::string_view text) {
  if (text.size() <= kShownNameBytes) return std::string(text);
  return fmt::format("{}... ({} bytes)", text.substr(0, kShownNameBytes), text.size());
}

// A folder modules are read from, as the real paths of modules must lie
// in it: canonical, or as near as can be for one that does not exist.
std::filesystem::path module_root(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::path root = std::filesystem::canonical(dir, ec);
  if (ec) root = std::filesystem::weakly_canonical(std::filesystem::absolute(dir, ec), ec);
  return root;
}

// Reads a whole Lua source file into `out`. Returns "" or why it cannot:
// the OS error ("No such file or directory", ...), or that it is no regular
// file (a FIFO or /dev/zero would block or never end; the type is checked
// on the opened file, which a non-blocking open makes safe for FIFOs), or
// that it is larger than `max_bytes` (its text must fit in the capped heap
// anyway; reading it first would not be capped).
std::string read_source_file(const std::filesystem::path& path, std::size_t max_bytes, std::string& out) {
  out.clear();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::generic_category().message(errno);
  std::string problem;
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    problem = std::generic_category().message(errno);
  } else if (S_ISDIR(st.st_mode)) {
    problem = std::generic_category().message(EISDIR);
  } else if (!S_ISREG(st.st_mode)) {
    problem = fmt::format("{}, not a regular file", file_kind(st.st_mode));
  } else if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    problem = fmt::format("{} bytes, more than the memory limit of {} bytes", st.st_size, max_bytes);
  } else {
    out.resize(static_cast<std::size_t>(st.st_size));
    std::size_t done = 0;
    while (problem.empty()) {
      if (done == out.size()) out.resize(done + (1 << 14));  // it grew since fstat
      const ssize_t n = ::read(fd, out.data() + done, out.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) problem = std::generic_category().message(errno);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
      if (done > max_bytes) problem = fmt::format("more than the memory limit of {} bytes", max_bytes);
    }
    out.resize(done);
  }
  ::close(fd);
  return problem;
}

// Deep enough for a stack of C functions nested to the limit.
constexpr int kMaxLevels = 8 * detail::kMaxNestedCalls;

// The stack level of the nearest line of a script at `level` or below (up
// to `max_level`), or -1 if there is none. Lines of the sandbox's own Lua
// (library_guards.cpp) are skipped: an author knows nothing of them.
int nearest_script_level(lua_State* L, int level, int max_level = kMaxLevels) {
  for (; level < max_level; ++level) {
    lua_Debug ar;
    if (lua_getstack(L, level, &ar) == 0) break;
    const std::string loc = Sandbox::where(L, level);
    if (loc != "?" && !loc.starts_with("[sandbox]:")) return level;
  }
  return -1;
}

// The location ("file:LINE") of that line, or "".
std::string nearest_script_line(lua_State* L, int level) {
  const int at = nearest_script_level(L, level);
  return at < 0 ? std::string() : Sandbox::where(L, at);
}

// Whether `text` starts with "loc: ".
bool starts_with_location(std::string_view text, std::string_view loc) {
  return text.starts_with(loc) && text.substr(loc.size()).starts_with(": ");
}

// LuaJIT bytecode dumps start with ESC; text sources never legitimately do.
bool looks_like_bytecode(std::string_view source) {
  return !source.empty() && source.front() == '\033';
}

// Module names are dot-separated words of [A-Za-z0-9_]: this makes paths,
// '..' and absolute names unrepresentable rather than filtered.
bool valid_module_name(std::string_view name) {
  if (name.empty() || name.front() == '.' || name.back() == '.') return false;
  char prev = '.';
  for (const char c : name) {
    const bool word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                      (c >= '0' && c <= '9') || c == '_';
    if (!word && !(c == '.' && prev != '.')) return false;
    prev = c;
  }
  return true;
}

std::string join(const std::vector<std::string>& parts, std::string_view sep) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i != 0) out += sep;
    out += parts[i];
  }
  return out;
}

// Keeps the message and a short traceback: elides the middle of deep stacks
// and drops anonymous C frames ("[C]: at 0x55..."), which LuaJIT prints for C
// functions it cannot name: the C++ harness, and C functions reached by a
// tail call (`return kerr{...}`), except `require`, which gets its name back.
// Frames of the sandbox's own Lua ("[sandbox]:9: in function 'tostring'")
// are dropped too: the script's line that called it follows; so are fast
// functions LuaJIT shows by address ("[builtin#89]: at 0x7feb...").
std::string tidy_traceback(std::string_view message, std::uintptr_t require_address) {
  constexpr std::string_view kMarker = "\nstack traceback:";
  const std::size_t at = message.find(kMarker);
  if (at == std::string_view::npos) return std::string(message);
  std::string out(message.substr(0, at + kMarker.size()));
  std::vector<std::string> frames;
  std::size_t pos = at + kMarker.size();
  while (pos < message.size()) {
    if (message[pos] == '\n') ++pos;
    const std::size_t end = std::min(message.find('\n', pos), message.size());
    const std::string_view line = message.substr(pos, end - pos);
    pos = end;
    constexpr std::string_view kAnonymousC = "\t[C]: at 0x";
    if (line.starts_with(kAnonymousC)) {
      const std::string hex(line.substr(kAnonymousC.size()));
      if (std::strtoull(hex.c_str(), nullptr, 16) == require_address) {
        frames.emplace_back("\t[C]: in function 'require'");
      }
      continue;
    }
    // LuaJIT shows a fast function it cannot name as "[builtin#89]: at
    // 0x7feb...": an address, which means nothing to an author.
    if (line.empty() || line == "\t[C]: in ?" || line.starts_with("\t[sandbox]:") || line.starts_with("\t[builtin#"))
      continue;
    frames.emplace_back(line);
  }
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (frames.size() > kFramesHead + kFramesTail + 1 && i == kFramesHead) {
      out += "\n\t...";
      i = frames.size() - kFramesTail;
    }
    out += '\n';
    out += frames[i];
  }
  return out;
}

std::string format_mib(std::size_t bytes) {
  return fmt::format("{:g} MiB", static_cast<double>(bytes) / double(1u << 20));
}

// The lowest address the calling thread's C stack may reach before a
// sandbox stops going deeper: its bottom plus kStackReserve (0: unknown, no
// check).  Looked up once per thread and kept (a thread's stack does not
// move): pthread_getattr_np reads /proc/self/maps for the main thread,
// which cost more than the rest of making a sandbox, and a shot makes one
// for every frame.
std::uintptr_t this_threads_stack_floor() {
  thread_local const std::uintptr_t floor = [] {
    std::uintptr_t out = 0;
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) == 0) {
      void* low = nullptr;
      std::size_t size = 0;
      if (pthread_attr_getstack(&attr, &low, &size) == 0) out = reinterpret_cast<std::uintptr_t>(low) + kStackReserve;
      pthread_attr_destroy(&attr);
    }
    return out;
  }();
  return floor;
}

// Whether `message` is LuaJIT's error for a full Lua stack: "stack
// overflow", with or without a location in front (LuaJIT adds none when the
// overflow comes as a function is entered, which is most of the time).
bool is_stack_overflow(std::string_view message) {
  constexpr std::string_view kOverflow = "stack overflow";
  return message == kOverflow || (message.ends_with(kOverflow) && message.size() > kOverflow.size() + 2 &&
                                  message.substr(message.size() - kOverflow.size() - 2, 2) == ": ");
}

// How many levels the stack of L has (lua_getstack walks the frames from
// the top, so the depth is found by doubling, then halving).
int stack_depth(lua_State* L) {
  lua_Debug ar;
  int known = 0;  // a level that exists
  int step = 1;
  while (lua_getstack(L, known + step, &ar) != 0) {
    known += step;
    step *= 2;
  }
  for (step /= 2; step >= 1; step /= 2)
    if (lua_getstack(L, known + step, &ar) != 0) known += step;
  return known + 1;
}

// One traceback line for the function at `level`, as luaL_traceback writes
// it, or "" for a C function without a name (which tidy_traceback drops
// anyway). Pushes nothing: it runs where the Lua stack is full.
std::string traceback_line(lua_State* L, int level) {
  lua_Debug ar;
  if (lua_getstack(L, level, &ar) == 0 || lua_getinfo(L, "Sln", &ar) == 0) return {};
  const bool named = ar.namewhat != nullptr && *ar.namewhat != '\0' && ar.name != nullptr;
  if (ar.what != nullptr && std::string_view(ar.what) == "C")
    return named ? fmt::format("\n\t[C]: in function '{}'", ar.name) : std::string();
  const std::string at = ar.currentline > 0 ? fmt::format("{}:{}:", ar.short_src, ar.currentline)
                                            : fmt::format("{}:", ar.short_src);
  if (named) return fmt::format("\n\t{} in function '{}'", at, ar.name);
  if (ar.what != nullptr && std::string_view(ar.what) == "main") return fmt::format("\n\t{} in main chunk", at);
  return fmt::format("\n\t{} in function <{}:{}>", at, ar.short_src, ar.linedefined);
}

// Frames scanned from the top for the head of an overflow's traceback: a
// recursion through fast functions has thousands without a line.
constexpr int kOverflowHeadScan = 64;

// More levels than this above the deepest script line mean the recursion
// ran where Lua keeps no line (tail calls, fast functions).
constexpr int kLinelessRecursion = 100;

// The report of a stack overflow seen from the message handler (level 0):
// "file:LINE: stack overflow: ..." at the deepest script line on the stack,
// what it means, and a short traceback (kFramesHead frames from the top,
// kFramesTail from the bottom: where the recursion started). Built without
// pushing anything onto the full Lua stack (luaL_traceback would need
// slots it no longer has, and fail as "error in error handling").
// `message` is the error as raised. On a shallow stack the overflow happened
// elsewhere (in a coroutine, whose error the script raised again): its own
// location, if it has one, is kept.
std::string overflow_report(lua_State* L, std::string_view message) {
  constexpr std::string_view kWhat =
      "a function that calls itself without end, or a metamethod (__index, __newindex, __call, __tostring, "
      "__concat, ...) that uses itself";
  const int depth = stack_depth(L);
  // The whole stack: a recursion through fast functions may leave its only
  // lines at the bottom (each lua_getstack walks from the top: quadratic,
  // but only on this error, and ~0.1 s at LuaJIT's deepest stack).
  const int at = nearest_script_level(L, 1, depth);
  const bool here = depth >= kDeepLevels;
  std::string out;
  if (!here && message != "stack overflow")
    out = std::string(message);
  else
    out = at < 0 ? std::string("stack overflow") : fmt::format("{}: stack overflow", Sandbox::where(L, at));
  out += here ? fmt::format(": calls nested too deeply ({} levels fill the Lua stack): {}", depth, kWhat)
              : fmt::format(": calls nested too deeply: {}", kWhat);
  if (at > kLinelessRecursion)
    out += "; the recursion runs through tail calls or library functions, which keep no line: the line named is the "
           "one that started it";
  out += "\nstack traceback:";
  std::size_t shown = 0;
  int level = 1;
  for (; level < std::min(depth - static_cast<int>(kFramesTail), kOverflowHeadScan) && shown < kFramesHead; ++level) {
    const std::string line = traceback_line(L, level);
    if (!line.empty()) ++shown, out += line;
  }
  if (level < depth - static_cast<int>(kFramesTail)) out += "\n\t...";
  for (level = std::max(level, depth - static_cast<int>(kFramesTail)); level < depth; ++level)
    out += traceback_line(L, level);
  return out;
}

// Lua names a chunk whose file name is longer than LUA_IDSIZE by its tail
// ("...ots/shot.lua:3:"), in its own messages and in tracebacks; in a
// checkout with a long path that hides which file failed.  `msg` with each
// such tail that ends exactly one of `files` (the names its chunks were
// loaded under) replaced by that file's whole name.
std::string with_whole_file_names(std::string msg, const std::vector<std::string>& files) {
  std::size_t at = 0;
  while ((at = msg.find("...", at)) != std::string::npos) {
    const std::size_t tail_begin = at + 3, tail_end = msg.find(':', tail_begin);
    if (tail_end == std::string::npos) break;
    const std::string_view tail(msg.data() + tail_begin, tail_end - tail_begin);
    const std::string* whole = nullptr;
    int matches = 0;
    if (!tail.empty() && tail.find('\n') == std::string_view::npos)
      for (const std::string& f : files)
        if (f.size() > tail.size() && std::string_view(f).ends_with(tail) && (!whole || *whole != f)) {
          whole = &f;
          ++matches;
        }
    if (matches == 1) {
      msg.replace(at, tail_end - at, *whole);
      at += whole->size();
    } else {
      at = tail_end;
    }
  }
  return msg;
}

}  // namespace

// Everything one sandboxed state needs. It is the allocator's user data, so
// the C callbacks (allocator, hook, message handler, require) reach it from
// any lua_State of the sandbox with lua_getallocf and no global state.
struct Sandbox::Impl {
  lua_State* L = nullptr;
  std::vector<std::filesystem::path> require_dirs;
  SandboxLimits limits;
  std::vector<std::filesystem::path> loaded;
  // The file names chunks were loaded under (after the '@'), to name them
  // whole in messages (with_whole_file_names).
  std::vector<std::string> chunk_files;

  std::size_t heap_bytes = 0;  // live bytes handed out to Lua
  std::size_t refused = 0;     // allocations the cap refused, ever
  bool cap_lifted = false;     // while the handler formats a traceback
  int depth = 0;               // nesting of run_file/call; >0 means evaluating
  Clock::time_point deadline;
  bool timed_out = false;  // the evaluation hit its deadline; the hook fires on every instruction
  int nested_calls = 0;    // detail::NestedCall levels held

  std::vector<std::filesystem::path> require_roots;  // require_dirs and mounted folders, canonical
  // Sandbox::mount_modules: names "<prefix>.<rest>" are read from the folder.
  std::vector<std::pair<std::string, std::filesystem::path>> mounts;
  std::vector<std::string> loading;  // the chain of modules being required
  std::vector<std::string> loading_files;  // their paths, for locating errors
  std::vector<int> loading_mounts;         // the mount each was read through, or -1
  std::string main_file;                   // the outermost run_file's script

  int handler_ref = LUA_NOREF;     // the traceback message handler
  int modules_ref = LUA_NOREF;     // module name -> value of loaded modules
  int last_trace_ref = LUA_NOREF;  // the last message the handler produced
  // The report of the last stack overflow the handler saw (overflow_report),
  // kept in C++: pushing it may fail on the full stack, and then the call
  // ends as "error in error handling" (LUA_ERRERR), which fail() replaces
  // by it.
  std::string overflow_text;
  // Its address, as a light userdata, stands for a memory error re-raised by
  // require (lua_error cannot raise LUA_ERRMEM itself).
  char memory_sentinel = 0;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    if (L != nullptr) lua_close(L);
  }

  static Impl& of(lua_State* L) {
    void* ud = nullptr;
    lua_getallocf(L, &ud);
    return *static_cast<Impl*>(ud);
  }

  // The cap only binds while a script is evaluated, so the engine's own
  // stack work between evaluations (reading results) cannot fail with an
  // unprotected memory error, which would abort the process.
  static void* allocate(void* ud, void* ptr, std::size_t osize, std::size_t nsize) {
    auto& s = *static_cast<Impl*>(ud);
    if (ptr == nullptr) osize = 0;
    if (nsize == 0) {
      std::free(ptr);
      s.heap_bytes -= osize;
      return nullptr;
    }
    if (s.depth > 0 && !s.cap_lifted && nsize > osize &&
        s.heap_bytes - osize + nsize > s.limits.memory_bytes) {
      ++s.refused;
      return nullptr;  // LuaJIT raises LUA_ERRMEM
    }
    void* p = std::realloc(ptr, nsize);
    if (p != nullptr) s.heap_bytes = s.heap_bytes - osize + nsize;
    return p;
  }

  // Count hook: fails the evaluation once its deadline has passed. After the
  // first failure it fires on every instruction, so a script cannot swallow
  // the error with pcall and keep looping: the first instruction it runs
  // outside a pcall fails again. It also stops C stack growth that no
  // NestedCall sees (a __tostring that calls string.format on itself).
  static void time_hook(lua_State* L, lua_Debug*) {
    Impl& s = of(L);
    if (s.depth == 0) return;
    std::size_t left = 0;
    if (s.timed_out || Clock::now() >= s.deadline) {
      s.fail_every_instruction();
      push_at_running_line(L, s.time_limit_message());
    } else if (!s.stack_has_room(left)) {
      push_at_running_line(L, s.nesting_message(left));
    } else if (!s.lua_stack_has_room(L)) {
      // LuaJIT's own words at the running line: the message handler
      // explains them (overflow_report), with the room this check kept
      // for it; in a coroutine (no handler) the line stays with them.
      push_at_running_line(L, "stack overflow");
    } else {
      return;
    }
    lua_error(L);
  }

  // Whether the running coroutine's Lua stack can still grow by
  // kLuaStackReserve slots. Checked by the hook, so that a recursion fails
  // here, where the message handler has room to run: at LuaJIT's own limit
  // a recursing metamethod (__index, __newindex, __call) fails without it
  // ("stack overflow", no line). lua_checkstack grows the stack as the
  // script's next calls would, and fails near the limit; a refusal by the
  // memory cap is no overflow (the script's own allocations fail as usual).
  // Only a stack of kDeepLevels levels is looked at: fewer, even of the
  // largest frames, cannot come near the limit, and the stack of a shallow
  // coroutine is not grown for nothing.
  bool lua_stack_has_room(lua_State* L) {
    lua_Debug ar;
    if (lua_getstack(L, kDeepLevels, &ar) == 0) return true;
    const std::size_t before = refused;
    return lua_checkstack(L, kLuaStackReserve) != 0 || refused != before;
  }

  // Pushes "file:LINE: text" for the script line running (level 0 in a hook).
  static void push_at_running_line(lua_State* L, const std::string& text) {
    const std::string loc = nearest_script_line(L, 0);
    const std::string msg = loc.empty() ? text : fmt::format("{}: {}", loc, text);
    lua_pushlstring(L, msg.data(), msg.size());
  }

  // Pushes "file:LINE: text" for the script line calling the running C
  // function, or with the script's name if no script line is on the stack
  // (`return s:match(p)` in a main chunk: a tail call leaves none).
  void push_at_calling_line(lua_State* L, const std::string& text) const {
    if (nearest_script_line(L, 1).empty() && !main_file.empty()) {
      const std::string msg = fmt::format("{}: {}", main_file, text);
      lua_pushlstring(L, msg.data(), msg.size());
    } else {
      detail::push_located_message(L, text.c_str());
    }
  }

  void fail_every_instruction() {
    if (timed_out) return;
    timed_out = true;
    lua_sethook(L, &time_hook, LUA_MASKCOUNT, 1);
  }

  std::string time_limit_message() const {
    return fmt::format("time limit of {:g} s exceeded (set by {})", limits.seconds, limits.set_by);
  }

  std::string nesting_message(std::size_t stack_left) const {
    if (nested_calls >= detail::kMaxNestedCalls) {
      return fmt::format(
          "too deeply nested: more than {} calls back into Lua from C functions at once (coroutine.resume or "
          "wrap, gsub or sort callbacks, __tostring, require, error handlers)",
          detail::kMaxNestedCalls);
    }
    return fmt::format(
        "too deeply nested: this thread's C stack is nearly used up ({} KiB left, {} calls back into Lua from C "
        "functions held)",
        stack_left >> 10, nested_calls);
  }

  // Whether the calling thread's C stack has more than kStackReserve left
  // (`left`: how much it has); NestedCall refuses to go deeper.
  bool stack_has_room(std::size_t& left) {
    const std::uintptr_t stack_floor = this_threads_stack_floor();
    const auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    const std::uintptr_t low = stack_floor - kStackReserve;
    left = stack_floor == 0 || here < low ? 0 : here - low;
    return stack_floor == 0 || here > stack_floor;
  }

  // Throws ScriptError before an outermost evaluation of `what` on a thread
  // with less than kStackReserve of C stack left, where the script could
  // not even be parsed safely.
  void check_stack_to_start(const std::string& what) {
    std::size_t left = 0;
    if (depth != 0 || stack_has_room(left)) return;
    throw ScriptError(fmt::format("cannot evaluate {}: this thread has {} KiB of C stack left, the sandbox needs {} KiB",
                                  what, left >> 10, kStackReserve >> 10));
  }

  // Runs lua_pcall(L, nargs, 1, 0) with at most `seconds` of the
  // evaluation's time. `over` tells whether that ran out; if the
  // evaluation's own deadline has not passed, it goes on normally.
  int call_with_budget(lua_State* L, int nargs, double seconds, bool& over) {
    const Clock::time_point outer = deadline;
    deadline = std::min(outer, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(seconds)));
    const int status = lua_pcall(L, nargs, 1, 0);
    over = timed_out;
    deadline = outer;
    if (timed_out && Clock::now() < outer) {
      timed_out = false;
      lua_sethook(L, &time_hook, LUA_MASKCOUNT, kHookInstructions);
    }
    return status;
  }

  // The message for an error value that is no string, at index 1: its
  // __tostring's text if that returns a string within kTostringSeconds;
  // else what the value is, where it was raised, and what went wrong.
  // A handler must not run script code without a budget: LuaJIT calls it
  // for an error already raised, where a second error (the time limit)
  // only leaves "error in error handling".
  std::string describe_error_object(lua_State* L) {
    const std::string where = nearest_script_line(L, 1);
    const std::string object = fmt::format("error object (a {} value)", luaL_typename(L, 1));
    std::string what;
    if (luaL_getmetafield(L, 1, "__tostring") == 0) {
      what = fmt::format("error object is a {} value", luaL_typename(L, 1));
    } else if (timed_out) {
      what = object + ": its __tostring was not run, the time limit had passed";
    } else if (!detail::NestedCall::allowed(L)) {
      what = object + ": its __tostring was not run, calls were nested too deeply";
    } else {
      lua_pushvalue(L, 1);
      bool over = false;
      int status = 0;
      {
        const detail::NestedCall nested(L);
        status = call_with_budget(L, 1, kTostringSeconds, over);
      }
      std::size_t len = 0;
      const char* text = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &len) : nullptr;
      if (status == 0 && text != nullptr) return clipped(std::string_view(text, len));
      if (over) {
        what = fmt::format("{}: its __tostring did not return within {:g} s", object, kTostringSeconds);
      } else if (status == LUA_ERRMEM) {
        what = object + ": its __tostring ran out of memory";
      } else if (status != 0) {
        what = fmt::format("{}: its __tostring failed: {}", object,
                           text != nullptr ? clipped(std::string_view(text, len)) : luaL_typename(L, -1));
      } else {
        what = fmt::format("{}: its __tostring returned a {} value, not a string", object, luaL_typename(L, -1));
      }
    }
    lua_settop(L, 1);
    return where.empty() ? what : fmt::format("{}: {}", where, what);
  }

  // Message handler of every protected call: error value -> string with a
  // traceback. Passes through the memory sentinel and a message it already
  // traced (an error re-raised by require carries the module's frames).
  // error() adds no position to non-strings: their messages name the first
  // Lua frame (the line that raised them).
  static int message_handler(lua_State* L) {
    Impl& s = of(L);
    if (lua_type(L, 1) == LUA_TLIGHTUSERDATA && lua_touserdata(L, 1) == &s.memory_sentinel) {
      return 1;
    }
    lua_settop(L, 1);
    lua_rawgeti(L, LUA_REGISTRYINDEX, s.last_trace_ref);
    if (lua_rawequal(L, 1, 2)) return 1;
    lua_settop(L, 1);
    if (lua_type(L, 1) == LUA_TSTRING && is_stack_overflow(lua_tostring(L, 1))) {
      s.overflow_text = overflow_report(L, lua_tostring(L, 1));
      const CapLift lift(s);
      lua_pushlstring(L, s.overflow_text.data(), s.overflow_text.size());
      lua_pushvalue(L, -1);
      lua_rawseti(L, LUA_REGISTRYINDEX, s.last_trace_ref);
      return 1;
    }
    std::string text;
    if (lua_type(L, 1) == LUA_TSTRING || lua_type(L, 1) == LUA_TNUMBER) {
      std::size_t len = 0;
      const char* p = lua_tolstring(L, 1, &len);
      if (len > kMaxMessageBytes) text = clipped(std::string_view(p, len));
    } else {
      text = s.describe_error_object(L);
    }
    {
      // A script that fails close to the cap still gets its message: the
      // few (at most kMaxMessageBytes) bytes of it and of a traceback may
      // exceed the cap.
      const CapLift lift(s);
      if (!text.empty()) {
        lua_pushlstring(L, text.data(), text.size());
        lua_replace(L, 1);
      }
      luaL_traceback(L, L, lua_tostring(L, 1), 1);
    }
    lua_pushvalue(L, -1);
    lua_rawseti(L, LUA_REGISTRYINDEX, s.last_trace_ref);
    return 1;
  }

  // Suspends the memory cap for a bounded allocation by the harness itself.
  class CapLift {
   public:
    explicit CapLift(Impl& s) : s_(s), was_(s.cap_lifted) { s_.cap_lifted = true; }
    ~CapLift() { s_.cap_lifted = was_; }
    CapLift(const CapLift&) = delete;
    CapLift& operator=(const CapLift&) = delete;

   private:
    Impl& s_;
    bool was_;
  };

  void note_loaded(const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::path canon = std::filesystem::canonical(file, ec);
    if (ec) canon = std::filesystem::absolute(file, ec);
    // A hash input, not a log: each file once, in order of first load.
    if (std::find(loaded.begin(), loaded.end(), canon) == loaded.end()) {
      loaded.push_back(std::move(canon));
    }
  }

  // Our `require(name)`: loads name.lua (dots are folders) from the first
  // require directory holding it, once per sandbox, as Lua source. Only
  // regular files whose real path (links resolved) lies inside one of the
  // require directories are read. Runs inside protect(), so failures are C++
  // exceptions located at the calling line.
  int require_module(lua_State* L) {
    // Level 1 is unknown when require is called by pcall, or by a tail call
    // (`return require(...)`: LuaJIT drops the caller's frame). Then name the
    // module being loaded, else the nearest script line, else the script.
    std::string loc = Sandbox::where(L, 1);
    if (loc == "?" && !loading_files.empty()) loc = loading_files.back();
    if (loc == "?") loc = nearest_script_line(L, 2);
    if (loc.empty()) loc = main_file;
    const auto failure = [&loc](const std::string& msg) {
      return std::runtime_error(loc.empty() ? msg : fmt::format("{}: {}", loc, msg));
    };
    if (lua_type(L, 1) != LUA_TSTRING) {
      throw failure(fmt::format("require expects a module name string, got {}", luaL_typename(L, 1)));
    }
    std::size_t len = 0;
    const char* p = lua_tolstring(L, 1, &len);
    const std::string name(p, len);
    const std::string shown = shortened(name);
    if (!valid_module_name(name)) {
      throw failure(fmt::format(
          "invalid module name {:?}{}: use dot-separated names of letters, digits and '_' "
          "(like 'lib.orbits'), not paths",
          name.substr(0, kShownNameBytes),
          name.size() > kShownNameBytes ? fmt::format("... ({} bytes)", name.size()) : std::string()));
    }
    // A mounted prefix is looked for in its folder alone. A name required
    // while a mounted module loads is looked for in that folder first (a
    // shipped shot's siblings: read through the mount, and loaded once per
    // mount, '\n' being in no module name), then as any other.
    std::string relative = name;
    int mount = -1;
    for (std::size_t m = 0; m < mounts.size() && mount < 0; ++m) {
      const std::string& prefix = mounts[m].first;
      if (name.size() > prefix.size() + 1 && name.starts_with(prefix) && name[prefix.size()] == '.') {
        relative = name.substr(prefix.size() + 1);
        mount = static_cast<int>(m);
      }
    }
    std::string key = name;
    if (mount < 0 && !loading_mounts.empty() && loading_mounts.back() >= 0) {
      const int from = loading_mounts.back();
      std::string sibling = name;
      std::replace(sibling.begin(), sibling.end(), '.', '/');
      std::error_code ec;
      if (std::filesystem::exists(mounts[static_cast<std::size_t>(from)].second / (sibling + ".lua"), ec)) {
        mount = from;
        key = fmt::format("{}\n{}", from, name);
      }
    }
    lua_settop(L, 1);
    lua_rawgeti(L, LUA_REGISTRYINDEX, modules_ref);
    lua_pushlstring(L, key.data(), key.size());
    lua_rawget(L, 2);
    if (!lua_isnil(L, 3)) return 1;
    lua_settop(L, 1);

    if (auto it = std::find(loading.begin(), loading.end(), name); it != loading.end()) {
      std::vector<std::string> chain;
      for (; it != loading.end(); ++it) chain.push_back(shortened(*it));
      chain.push_back(shown);
      throw failure(fmt::format("require cycle: {}", join(chain, " -> ")));
    }

    std::vector<std::filesystem::path> dirs_searched;
    if (mount >= 0) {
      dirs_searched.push_back(mounts[static_cast<std::size_t>(mount)].second);
    } else {
      dirs_searched = require_dirs;
    }
    std::replace(relative.begin(), relative.end(), '.', '/');
    relative += ".lua";
    std::vector<std::string> searched;
    std::filesystem::path found;
    std::string source;
    for (const auto& dir : dirs_searched) {
      std::filesystem::path candidate = dir / relative;
      std::error_code ec;
      const std::filesystem::path real = std::filesystem::canonical(candidate, ec);
      if (ec == std::errc::no_such_file_or_directory || ec == std::errc::not_a_directory) {
        searched.push_back(shortened(candidate.string()));
        continue;
      }
      if (ec) {
        throw failure(
            fmt::format("cannot read module '{}' from {}: {}", shown, shortened(candidate.string()), ec.message()));
      }
      // Checked before anything is read: a link in the shot's folder to
      // /etc/shadow would otherwise be parsed, and a line of it quoted in
      // the syntax error.
      if (std::none_of(require_roots.begin(), require_roots.end(),
                       [&](const auto& root) { return is_within(real, root); })) {
        std::vector<std::string> dirs;
        for (const auto& d : require_dirs) dirs.push_back(shortened(d.string()));
        for (const auto& m : mounts) dirs.push_back(shortened(m.second.string()));
        throw failure(fmt::format(
            "module '{}' ({}) leads through a link to {}, outside the folders modules are read from ({})", shown,
            shortened(candidate.string()), shortened(real.string()), join(dirs, ", ")));
      }
      if (const std::string problem = read_source_file(real, limits.memory_bytes, source); !problem.empty()) {
        throw failure(
            fmt::format("cannot read module '{}' from {}: {}", shown, shortened(candidate.string()), problem));
      }
      found = std::move(candidate);
      break;
    }
    if (found.empty()) {
      throw failure(fmt::format("module '{}' not found (searched: {})", shown,
                                           searched.empty() ? "no directories" : join(searched, ", ")));
    }
    if (looks_like_bytecode(source)) {
      throw failure(fmt::format(
          "module '{}' ({}) is precompiled bytecode, which is refused: require Lua source", shown,
          shortened(found.string())));
    }
    note_loaded(found);
    std::string chunkname = "@";  // built in two steps: GCC 12 misreports "@" + s (-Wrestrict, PR 105329)
    chunkname += found.string();
    chunk_files.push_back(found.string());
    // The parser and the module run on this C stack, below the caller's.
    const detail::NestedCall nested(L);
    int status = luaL_loadbufferx(L, source.data(), source.size(), chunkname.c_str(), "t");
    if (status == 0) {
      // stack: name, chunk
      lua_rawgeti(L, LUA_REGISTRYINDEX, handler_ref);
      lua_insert(L, 2);
      lua_pushvalue(L, 1);  // like Lua 5.1, the module receives its name
      loading.push_back(name);
      loading_files.push_back(found.string());
      loading_mounts.push_back(mount);
      status = lua_pcall(L, 1, 1, 2);
      loading.pop_back();
      loading_files.pop_back();
      loading_mounts.pop_back();
    }
    if (status == LUA_ERRMEM) {
      lua_pushlightuserdata(L, &memory_sentinel);
      return kRethrow;
    }
    if (status != 0) return kRethrow;  // value already carries file:line
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      lua_pushboolean(L, 1);
    }
    lua_rawgeti(L, LUA_REGISTRYINDEX, modules_ref);
    lua_pushlstring(L, key.data(), key.size());
    lua_pushvalue(L, -3);
    lua_rawset(L, -3);
    lua_pop(L, 1);
    return 1;
  }

  static int require_entry(lua_State* L) {
    const int n = protect(L, [](lua_State* L) { return of(L).require_module(L); });
    if (n == kRethrow) return lua_error(L);
    return n;
  }

  // Failure of a load or protected call whose error value is on top; the
  // stack is reset to `base`. `name` names the script for memory errors.
  [[noreturn]] void fail(int status, int base, const std::string& name) {
    std::string msg;
    const std::string overflow = std::exchange(overflow_text, std::string());
    if (status == LUA_ERRMEM ||
        (lua_type(L, -1) == LUA_TLIGHTUSERDATA && lua_touserdata(L, -1) == &memory_sentinel)) {
      msg = fmt::format("{}: memory limit of {} exceeded (set by {})", name,
                        format_mib(limits.memory_bytes), limits.set_by);
    } else if (!overflow.empty() && (status == LUA_ERRERR || (lua_type(L, -1) == LUA_TSTRING &&
                                                              overflow == lua_tostring(L, -1)))) {
      msg = tidy_traceback(overflow, reinterpret_cast<std::uintptr_t>(&Impl::require_entry));
    } else if (status == LUA_ERRERR && lua_type(L, -1) == LUA_TSTRING && is_stack_overflow(lua_tostring(L, -1))) {
      // LuaJIT's limit was reached between two looks of the hook (frames
      // of hundreds of slots), where no handler runs: no line is left.
      msg = fmt::format("{}: stack overflow: calls nested too deeply, too fast for the sandbox to see the line: a "
                        "function that calls itself without end, or a metamethod that uses itself",
                        name);
    } else if (lua_type(L, -1) == LUA_TSTRING) {
      std::size_t len = 0;
      const char* p = lua_tolstring(L, -1, &len);
      msg = tidy_traceback(std::string_view(p, len),
                           reinterpret_cast<std::uintptr_t>(&Impl::require_entry));
    } else {
      msg = fmt::format("{}: error object is a {} value", name, luaL_typename(L, -1));
    }
    lua_settop(L, base);
    throw ScriptError(with_whole_file_names(std::move(msg), chunk_files));
  }

  // Brackets one evaluation. Only the outermost one (a C function may call
  // back into Lua) starts the clock, so nesting cannot extend the budget.
  class Evaluation {
   public:
    explicit Evaluation(Impl& s) : s_(s) {
      if (s_.depth++ != 0) return;
      s_.overflow_text.clear();
      const std::chrono::duration<double> budget(s_.limits.seconds);
      s_.deadline = budget < std::chrono::hours(24 * 365)
                        ? Clock::now() + std::chrono::duration_cast<Clock::duration>(budget)
                        : Clock::time_point::max();
      if (s_.timed_out) {
        s_.timed_out = false;
        lua_sethook(s_.L, &time_hook, LUA_MASKCOUNT, kHookInstructions);
      }
    }
    ~Evaluation() { --s_.depth; }
    Evaluation(const Evaluation&) = delete;
    Evaluation& operator=(const Evaluation&) = delete;

   private:
    Impl& s_;
  };
};

Sandbox::Sandbox(std::vector<std::filesystem::path> require_dirs, SandboxLimits limits)
    : impl_(std::make_unique<Impl>()) {
  if (!(limits.seconds > 0) || limits.memory_bytes == 0) {
    throw std::invalid_argument("SandboxLimits: seconds and memory_bytes must be positive");
  }
  Impl& s = *impl_;
  s.require_dirs = std::move(require_dirs);
  for (const auto& dir : s.require_dirs) s.require_roots.push_back(module_root(dir));
  s.limits = std::move(limits);
  lua_State* L = lua_newstate(&Impl::allocate, &s);
  if (L == nullptr) {
    throw ScriptError("cannot create a Lua state (custom allocators need a GC64 LuaJIT on x64)");
  }
  s.L = L;
  // Count hooks do not fire in compiled traces; the interpreter is also
  // plenty fast for shot logic.
  luaJIT_setmode(L, 0, LUAJIT_MODE_ENGINE | LUAJIT_MODE_OFF);

  const struct {
    lua_CFunction open;
    const char* name;
  } libs[] = {{luaopen_base, ""},
              {luaopen_table, LUA_TABLIBNAME},
              {luaopen_string, LUA_STRLIBNAME},
              {luaopen_math, LUA_MATHLIBNAME},
              {luaopen_bit, LUA_BITLIBNAME}};
  for (const auto& lib : libs) {
    lua_pushcfunction(L, lib.open);
    lua_pushstring(L, lib.name);
    lua_call(L, 1, 0);
  }
  for (const char* name : {"dofile", "loadfile", "load", "loadstring", "require", "module",
                           "getfenv", "setfenv", "collectgarbage", "newproxy", "gcinfo"}) {
    lua_pushnil(L);
    lua_setglobal(L, name);
  }
  lua_getglobal(L, LUA_STRLIBNAME);
  lua_pushnil(L);
  lua_setfield(L, -2, "dump");
  lua_pop(L, 1);
  // Scripts must be deterministic: every thread and MPI rank evaluates the
  // shot itself, in its own order, and all must agree.  A per-state random
  // sequence would make frame(i) depend on which frames ran before it.
  lua_getglobal(L, LUA_MATHLIBNAME);
  for (const char* name : {"random", "randomseed"}) {
    lua_pushnil(L);
    lua_setfield(L, -2, name);
  }
  lua_pop(L, 1);
  // print goes to standard error: standard output may carry data (CSV).
  lua_pushcfunction(L, &print_to_stderr);
  lua_setglobal(L, "print");
  install_library_guards(L);
  install_determinism(L);
  install_string_patterns(L);

  lua_pushcfunction(L, &Impl::message_handler);
  s.handler_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_newtable(L);
  s.modules_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pushboolean(L, 0);
  s.last_trace_ref = luaL_ref(L, LUA_REGISTRYINDEX);

  lua_pushcfunction(L, &Impl::require_entry);
  lua_setglobal(L, "require");
  lua_sethook(L, &Impl::time_hook, LUA_MASKCOUNT, kHookInstructions);
  lua_settop(L, 0);
}

Sandbox::~Sandbox() = default;
Sandbox::Sandbox(Sandbox&&) noexcept = default;
Sandbox& Sandbox::operator=(Sandbox&&) noexcept = default;

void Sandbox::run_file(const std::filesystem::path& file, int nresults) {
  Impl& s = *impl_;
  lua_State* L = s.L;
  std::string source;
  if (const std::string problem = read_source_file(file, s.limits.memory_bytes, source); !problem.empty()) {
    throw ScriptError(fmt::format("cannot read script {}: {}", file.string(), problem));
  }
  if (looks_like_bytecode(source)) {
    throw ScriptError(fmt::format(
        "{}: precompiled bytecode is refused; run the Lua source instead", file.string()));
  }
  s.note_loaded(file);
  if (lua_checkstack(L, 2) == 0) throw ScriptError("Lua stack overflow in the engine");
  s.check_stack_to_start(file.string());
  const int base = lua_gettop(L);
  const Impl::Evaluation evaluation(s);
  if (s.depth == 1) s.main_file = file.string();
  lua_rawgeti(L, LUA_REGISTRYINDEX, s.handler_ref);
  std::string chunkname = "@";  // see above
  chunkname += file.string();
  s.chunk_files.push_back(file.string());
  int status = luaL_loadbufferx(L, source.data(), source.size(), chunkname.c_str(), "t");
  if (status == 0) status = lua_pcall(L, 0, nresults, base + 1);
  if (status != 0) s.fail(status, base, file.string());
  lua_remove(L, base + 1);
}

void Sandbox::call(int nargs, int nresults) {
  Impl& s = *impl_;
  lua_State* L = s.L;
  const int func = lua_gettop(L) - nargs;
  if (nargs < 0 || func < 1) throw ScriptError("Sandbox::call: no function below the arguments");
  if (lua_checkstack(L, 2) == 0) throw ScriptError("Lua stack overflow in the engine");
  s.check_stack_to_start(s.main_file.empty() ? "a script function" : s.main_file);
  const Impl::Evaluation evaluation(s);
  // Below the function: a copy of it (to name the script in a memory error,
  // which skips the handler) and the message handler. Neither allocates.
  lua_pushvalue(L, func);
  lua_insert(L, func);
  lua_rawgeti(L, LUA_REGISTRYINDEX, s.handler_ref);
  lua_insert(L, func + 1);
  const int status = lua_pcall(L, nargs, nresults, func + 1);
  if (status != 0) {
    std::string name = "script";
    lua_Debug ar;
    lua_pushvalue(L, func);
    if (lua_getinfo(L, ">S", &ar) != 0 && ar.source != nullptr && ar.source[0] == '@') {
      name = ar.source + 1;
    } else if (!s.loaded.empty()) {
      name = s.loaded.front().string();
    }
    s.fail(status, func - 1, name);
  }
  lua_remove(L, func);
  lua_remove(L, func);
}

void Sandbox::mount_modules(std::string prefix, std::filesystem::path dir) {
  if (!valid_module_name(prefix)) throw std::invalid_argument("Sandbox::mount_modules: not a module name: " + prefix);
  impl_->require_roots.push_back(module_root(dir));
  impl_->mounts.emplace_back(std::move(prefix), std::move(dir));
}

const std::vector<std::filesystem::path>& Sandbox::loaded_files() const { return impl_->loaded; }

const SandboxLimits& Sandbox::limits() const { return impl_->limits; }

lua_State* Sandbox::state() const { return impl_ ? impl_->L : nullptr; }

std::string Sandbox::where(lua_State* L, int level) {
  lua_Debug ar;
  if (lua_getstack(L, level, &ar) == 0 || lua_getinfo(L, "Sl", &ar) == 0 || ar.currentline <= 0) {
    return "?";
  }
  const char* src = ar.source != nullptr && ar.source[0] == '@' ? ar.source + 1 : ar.short_src;
  return fmt::format("{}:{}", src, ar.currentline);
}

void raise(lua_State* L, const std::string& msg) {
  detail::push_located_message(L, msg.c_str());
  lua_error(L);
  std::abort();  // lua_error does not return; keeps [[noreturn]] honest
}

namespace detail {

void push_located_message(lua_State* L, const char* what) {
  {
    // Level 1 is no Lua line when the C function was called by pcall or by
    // a tail call (LuaJIT drops the calling frame): take the nearest one.
    // Lua's own messages name long files by their tail ("...ots/shot.lua"),
    // which also counts as already located.
    const int at = nearest_script_level(L, 1);
    lua_Debug ar;
    if (at >= 0 && lua_getstack(L, at, &ar) != 0 && lua_getinfo(L, "Sl", &ar) != 0) {
      const std::string loc = Sandbox::where(L, at);
      const std::string short_loc = fmt::format("{}:{}", ar.short_src, ar.currentline);
      const std::string_view text(what);
      if (!starts_with_location(text, loc) && !starts_with_location(text, short_loc)) {
        const std::string msg = fmt::format("{}: {}", loc, text);
        lua_pushlstring(L, msg.data(), msg.size());
        return;
      }
    }
  }
  lua_pushstring(L, what);
}

NestedCall::NestedCall(lua_State* L) : L_(L) {
  Sandbox::Impl& s = Sandbox::Impl::of(L);
  std::size_t left = 0;
  if (s.nested_calls < kMaxNestedCalls && s.stack_has_room(left)) {
    ++s.nested_calls;
    return;
  }
  s.push_at_calling_line(L, s.nesting_message(left));
  lua_error(L);
}

NestedCall::~NestedCall() { --Sandbox::Impl::of(L_).nested_calls; }

bool NestedCall::allowed(lua_State* L) {
  Sandbox::Impl& s = Sandbox::Impl::of(L);
  std::size_t left = 0;
  return s.nested_calls < kMaxNestedCalls && s.stack_has_room(left);
}

void check_time(lua_State* L) {
  Sandbox::Impl& s = Sandbox::Impl::of(L);
  if (s.depth == 0 || (!s.timed_out && Clock::now() < s.deadline)) return;
  s.fail_every_instruction();
  s.push_at_calling_line(L, s.time_limit_message());
  lua_error(L);
}

bool timed_out(lua_State* L) { return Sandbox::Impl::of(L).timed_out; }

}  // namespace detail

}  // namespace lc::lua
