// Tests of what the shot-author API says about names it does not know:
// lc.<name> for a name the library lacks (engine/script/engine_api.cpp,
// scripts/lightcone.lua).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lua/sandbox.hpp"
#include "script/geodesic_spec.hpp"
#include "script/shot.hpp"
#include "scratch_dir.hpp"
#include "test_errors.hpp"

namespace {

namespace fs = std::filesystem;
using lc::lua::ScriptError;
using lc::test::error_of;
using lc::test::ScratchDir;

constexpr const char* kScene =
    "{spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = 0}}";

fs::path write_file(const ScratchDir& dir, const std::string& name, const std::string& text) {
  const fs::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

// A shot whose main chunk runs `lines` (from line 2 on) before returning a
// one-frame shot of kScene.
fs::path shot_running(const ScratchDir& dir, const std::string& lines) {
  return write_file(dir, "shot.lua",
                    "local lc = require 'lightcone'\n" + lines +
                        "\nreturn {name = 'shot', frames = 1, width = 8, height = 8, frame = function(i) return " +
                        kScene + " end}\n");
}

// The first line of an error (without its traceback).
std::string first_line(const std::string& msg) { return msg.substr(0, msg.find('\n')); }

// lc.fisheye{...} was "attempt to call field 'fisheye' (a nil value)": an
// unknown name is an error at the line that names it, saying what lc has.
TEST(ScriptErrors, UnknownNameInLcIsAnErrorAtItsLine) {
  ScratchDir dir;
  const fs::path file = shot_running(dir, "local fov = 180\nlocal cam = lc.fisheye{fov = fov}");
  const std::string msg = first_line(error_of<ScriptError>([&] { lc::Shot shot(file); }));
  EXPECT_EQ(msg.rfind(file.string() + ":3: lc.fisheye is not a lightcone constructor or function; lc has ", 0), 0u)
      << msg;
  for (const char* listed :
       {"spacetimes: lc.dihole, lc.kerr, lc.minkowski;", "observers and worldlines: lc.free_fall, lc.static_observer, "
                                                         "lc.worldline, lc.zamo;",
        "cameras: lc.camera;", "skies: lc.sky_checker, lc.sky_image, lc.sky_stars, lc.starfield;",
        "objects: lc.disk, lc.sphere;", "light: lc.light;", "helpers: lc.apocentres, ", "lc.look_at", "lc.timeline",
        "(docs/shots.md)"})
    EXPECT_NE(msg.find(listed), std::string::npos) << listed << "\n" << msg;
  EXPECT_EQ(msg.find("__"), std::string::npos) << msg;  // the engine's own names are not shown
  EXPECT_EQ(msg.find("did you mean"), std::string::npos) << msg;
}

// The other two names, and misspellings: the nearest name is
// suggested where one is close.
TEST(ScriptErrors, UnknownNameSuggestsTheNearestOne) {
  ScratchDir dir;
  const auto error = [&](const std::string& line) {
    const fs::path file = shot_running(dir, line);
    return first_line(error_of<ScriptError>([&] { lc::Shot shot(file); }));
  };
  EXPECT_NE(error("local st = lc.kerr_newman{mass = 1, charge = 0.5}")
                .find(":2: lc.kerr_newman is not a lightcone constructor or function (did you mean lc.kerr?); lc has "),
            std::string::npos);
  const std::string wormhole = error("local st = lc.wormhole{throat = 1}");
  EXPECT_NE(wormhole.find(":2: lc.wormhole is not a lightcone constructor or function; lc has "), std::string::npos)
      << wormhole;
  EXPECT_NE(error("local s = lc.sky_chekcer{}").find("(did you mean lc.sky_checker?)"), std::string::npos);
  EXPECT_NE(error("local c = lc.camrea{}").find("(did you mean lc.camera?)"), std::string::npos);
  EXPECT_NE(error("local x = lc[1]").find(":2: lc[1] is not a lightcone constructor or function"), std::string::npos);
}

// Inside frame(i) the error names the frame and the line.
TEST(ScriptErrors, UnknownNameInsideFrameNamesTheFrameAndLine) {
  ScratchDir dir;
  const fs::path file = write_file(dir, "shot.lua",
                                   "local lc = require 'lightcone'\n"
                                   "return {name = 'shot', frames = 2, width = 8, height = 8, frame = function(i)\n"
                                   "  local s = " +
                                       std::string(kScene) +
                                       "\n"
                                       "  if i == 1 then s.camera = lc.fisheye{fov = 180} end\n"
                                       "  return s\n"
                                       "end}\n");
  lc::Shot shot(file);
  EXPECT_NO_THROW(shot.frame(0));
  const std::string msg = first_line(error_of<ScriptError>([&] { shot.frame(1); }));
  EXPECT_EQ(msg.rfind(file.string() + ": frame 1: " + file.string() + ":4: lc.fisheye is not a lightcone", 0), 0u)
      << msg;
}

// Reading a name without the error (rawget), and names a shot adds itself,
// still work: the error is only for names lc lacks.
TEST(ScriptErrors, RawgetAndAddedNamesStillWork) {
  ScratchDir dir;
  const fs::path file = shot_running(dir,
                                     "assert(rawget(lc, 'fisheye') == nil)\n"
                                     "assert(type(rawget(lc, 'kerr')) == 'function')\n"
                                     "lc.my_helper = function() return 2 end\n"
                                     "assert(lc.my_helper() == 2)\n"
                                     "assert(lc.ease.smoothstep(0) == 0)");
  EXPECT_NO_THROW(lc::Shot shot(file));
}

// Geodesic specs require the same library: the same error.
TEST(ScriptErrors, UnknownNameInAGeodesicSpecIsAnErrorAtItsLine) {
  ScratchDir dir;
  const fs::path file = write_file(dir, "spec.lua",
                                   "local lc = require 'lightcone'\n"
                                   "return {spacetime = lc.kerr_newman{mass = 1},\n"
                                   "  curve = 'null', start = {r = 10, theta = 90, phi = 0}}\n");
  const std::string msg = first_line(error_of<ScriptError>([&] { lc::load_geodesic_specs(file); }));
  EXPECT_EQ(msg.rfind(file.string() + ":2: lc.kerr_newman is not a lightcone constructor or function (did you mean "
                                       "lc.kerr?)",
                      0),
            0u)
      << msg;
}

}  // namespace
