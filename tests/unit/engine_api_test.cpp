// Tests of the shot-author Lua library (scripts/lightcone.lua and
// scripts/lightcone/*.lua): every tests/lua/*_test.lua runs in the engine's
// sandbox, with the engine API installed, and must return true. The C++
// tests below add what a script cannot check about itself: errors that leave
// the sandbox (file:line of the author's script plus a traceback), and frames
// evaluated through Sandbox::call, in different orders in separate states,
// agreeing bit for bit.

#include "lua/sandbox.hpp"
#include "script/engine_api.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "test_errors.hpp"

namespace {

namespace fs = std::filesystem;
using lc::lua::Sandbox;
using lc::lua::ScriptError;
using lc::test::error_of;

const fs::path kSource = LIGHTCONE_SOURCE_DIR;
const fs::path kLuaTests = kSource / "tests" / "lua";
const fs::path kFixtures = kLuaTests / "fixtures";

// A sandbox as shots get it, plus tests/lua for the test helpers.
Sandbox make_sandbox() {
  Sandbox sandbox({LIGHTCONE_SOURCE_DIR "/scripts", LIGHTCONE_SOURCE_DIR "/tests/lua"});
  lc::install_engine_api(sandbox);
  return sandbox;
}

// The names of tests/lua/*_test.lua, sorted. (Names, not paths, keep the
// parameter ctest prints next to each test short.) Runs during static
// initialization, so it must not throw: a missing directory gives no files,
// which FindsTheLuaTests reports.
std::vector<std::string> lua_test_files() {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(kLuaTests, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.size() > 9 && name.ends_with("_test.lua")) {
      files.push_back(name);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// "keyframes_test.lua" -> "keyframes".
std::string test_name(const std::string& file) {
  std::string name = file.substr(0, file.size() - std::strlen("_test.lua"));
  for (char& c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!ok) c = '_';
  }
  return name;
}

class EngineApiScript : public ::testing::TestWithParam<std::string> {};

TEST_P(EngineApiScript, ReturnsTrue) {
  const fs::path file = kLuaTests / GetParam();
  Sandbox sandbox = make_sandbox();
  try {
    sandbox.run_file(file, 1);
  } catch (const ScriptError& e) {
    FAIL() << file.filename().string() << " failed:\n" << e.what();
  }
  lua_State* L = sandbox.state();
  ASSERT_EQ(lua_gettop(L), 1);
  EXPECT_TRUE(lua_type(L, -1) == LUA_TBOOLEAN && lua_toboolean(L, -1) != 0)
      << file.filename().string() << " returned " << luaL_typename(L, -1) << " instead of true";
  lua_pop(L, 1);
}

INSTANTIATE_TEST_SUITE_P(EngineApi, EngineApiScript, ::testing::ValuesIn(lua_test_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return test_name(info.param);
                         });

// An empty directory listing would instantiate nothing and pass silently.
TEST(EngineApi, FindsTheLuaTests) {
  const std::vector<std::string> names = lua_test_files();
  for (const char* expected : {"ease_test.lua", "lerp_test.lua", "keyframes_test.lua",
                               "timeline_test.lua", "circle_pan_test.lua", "errors_test.lua",
                               "shot_test.lua"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
}

// Whether msg starts with "FILE:LINE: text", FILE being `file` as Lua spells
// it in error positions: the whole path, or "..." and its tail when long.
bool located_at(const std::string& msg, const fs::path& file, int line, const std::string& text) {
  const std::string rest = fmt::format(":{}: {}", line, text);
  const std::size_t at = msg.find(rest);
  if (at == std::string::npos) return false;
  const std::string where = msg.substr(0, at);
  const std::string path = file.string();
  if (where == path) return true;
  return where.starts_with("...") && path.ends_with(where.substr(3));
}

// A library error in a script's main chunk leaves the sandbox as a
// ScriptError located at the script's line, with a traceback.
TEST(EngineApi, ErrorInMainChunkNamesTheScriptLine) {
  Sandbox sandbox = make_sandbox();
  const fs::path file = kFixtures / "error_at_top.lua";
  const std::string msg = error_of<ScriptError>([&] { sandbox.run_file(file, 1); });
  EXPECT_TRUE(located_at(msg, file, 6, "keyframes: frames must increase (key 2 has frame 5 after 10)\n"))
      << msg;
  EXPECT_NE(msg.find("stack traceback:"), std::string::npos) << msg;
  EXPECT_EQ(lua_gettop(sandbox.state()), 0);
}

// Calls shot.frame(i) through Sandbox::call, leaving the scene on the stack.
void call_frame(Sandbox& sandbox, int shot_index, int i) {
  lua_State* L = sandbox.state();
  lua_getfield(L, shot_index, "frame");
  lua_pushinteger(L, i);
  sandbox.call(1, 1);
}

// A library error inside frame(i), as the renderer evaluates it, names the
// line of the shot's frame function.
TEST(EngineApi, ErrorInFrameFunctionNamesTheShotLine) {
  Sandbox sandbox = make_sandbox();
  const fs::path file = kFixtures / "error_in_frame.lua";
  sandbox.run_file(file, 1);
  lua_State* L = sandbox.state();
  ASSERT_TRUE(lua_istable(L, 1));
  call_frame(sandbox, 1, 0);  // frames before the pan are fine
  lua_pop(L, 1);
  const std::string msg = error_of<ScriptError>([&] { call_frame(sandbox, 1, 40); });
  EXPECT_TRUE(
      located_at(msg, file, 17, "timeline:progress: no segment 'pann' (did you mean 'pan'?)\n"))
      << msg;
  EXPECT_EQ(lua_gettop(L), 1);
}

// `frame = function(i) return lc.circle_pan(...) end` is a tail call: LuaJIT
// keeps no frame for the shot's function, so no line of the shot is on the
// stack. The message still says what is wrong, and why it names no line.
TEST(EngineApi, ErrorInTailCallSaysTheLineIsUnknown) {
  Sandbox sandbox = make_sandbox();
  sandbox.run_file(kFixtures / "tail_call_frame.lua", 1);
  const std::string msg = error_of<ScriptError>([&] { call_frame(sandbox, 1, 3); });
  EXPECT_NE(msg.find("animation.lua:"), std::string::npos) << msg;
  EXPECT_NE(msg.find(": circle_pan: from and to are parallel, so the circle through them is not "
                     "unique; pass an axis as the 4th argument (the calling line is unknown: Lua "
                     "keeps none for a tail call like `return lc.f(...)`)"),
            std::string::npos)
      << msg;
}

// Reads a number field of the table at the top of the stack (raw access).
double number_field(lua_State* L, const char* key) {
  lua_pushstring(L, key);
  lua_rawget(L, -2);
  const double v = lua_tonumber(L, -1);
  EXPECT_EQ(lua_type(L, -1), LUA_TNUMBER) << key;
  lua_pop(L, 1);
  return v;
}

struct FrameValues {
  double mass, spin, theta;
  bool operator==(const FrameValues&) const = default;
};

// scene.spacetime.mass, .spin and scene.observer.theta of the scene on top.
FrameValues read_frame(lua_State* L) {
  FrameValues v{};
  lua_pushstring(L, "spacetime");
  lua_rawget(L, -2);
  v.mass = number_field(L, "mass");
  v.spin = number_field(L, "spin");
  lua_pop(L, 1);
  lua_pushstring(L, "observer");
  lua_rawget(L, -2);
  v.theta = number_field(L, "theta");
  lua_pop(L, 1);
  return v;
}

// Two processes evaluating the same shot in different orders (each frame
// once, as the farm does) get identical values, bit for bit.
TEST(EngineApi, FramesDoNotDependOnEvaluationOrder) {
  const fs::path file = kFixtures / "accr_disk_shot.lua";
  Sandbox a = make_sandbox();
  Sandbox b = make_sandbox();
  a.run_file(file, 1);
  b.run_file(file, 1);
  lua_getfield(a.state(), 1, "frames");
  const int frames = static_cast<int>(lua_tointeger(a.state(), -1));
  lua_pop(a.state(), 1);
  ASSERT_EQ(frames, 900);

  std::vector<FrameValues> forward(frames), shuffled(frames);
  for (int i = 0; i < frames; ++i) {
    call_frame(a, 1, i);
    forward[i] = read_frame(a.state());
    lua_pop(a.state(), 1);
  }
  for (int step = 0; step < frames; ++step) {
    const int i = (step * 389 + 17) % frames;  // a permutation: gcd(389, 900) = 1
    call_frame(b, 1, i);
    shuffled[i] = read_frame(b.state());
    lua_pop(b.state(), 1);
  }
  for (int i = 0; i < frames; ++i) EXPECT_EQ(forward[i], shuffled[i]) << "frame " << i;
  EXPECT_EQ(forward[0], (FrameValues{1.0, 0.9, 0.0}));
  EXPECT_EQ(forward[300], (FrameValues{1.0, 0.9, 80.0}));
  EXPECT_EQ(forward[570], (FrameValues{1.0, 0.0, 80.0}));
  EXPECT_EQ(forward[899], (FrameValues{0.0, 0.0, 80.0}));
}

}  // namespace
