// Tests of what the shot-author API says about names and fields it does not
// know: lc.<name> for a name the library lacks (engine/script/engine_api.cpp,
// scripts/lightcone.lua), and unknown fields before bad values, for every
// constructor (engine/script/field_reader.hpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lua/sandbox.hpp"
#include "camera/camera_params.hpp"
#include "lua/table_reader.hpp"
#include "objects/object_params.hpp"
#include "observers/observers.hpp"
#include "sky/sky.hpp"
#include "spacetime/spacetime.hpp"
#include "script/geodesic_spec.hpp"
#include "scene/scene_spec.hpp"
#include "script/shot.hpp"
#include "scratch_dir.hpp"
#include "test_errors.hpp"

namespace {

namespace fs = std::filesystem;
using lc::lua::FieldError;
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

// lc.orthographic{...} was "attempt to call field 'orthographic' (a nil value)": an
// unknown name is an error at the line that names it, saying what lc has.
TEST(ScriptErrors, UnknownNameInLcIsAnErrorAtItsLine) {
  ScratchDir dir;
  const fs::path file = shot_running(dir, "local fov = 180\nlocal cam = lc.orthographic{fov = fov}");
  const std::string msg = first_line(error_of<ScriptError>([&] { lc::Shot shot(file); }));
  EXPECT_EQ(msg.rfind(file.string() + ":3: lc.orthographic is not a lightcone constructor or function; lc has ", 0), 0u)
      << msg;
  // Each group of constructors as its registry lists it (sorted, as the
  // message sorts them), so a new kind needs no line here.
  const auto group = []<class R>(std::string_view title, std::vector<std::string> names, R*) {
    R::for_each([&](auto* kind) { names.emplace_back(std::remove_pointer_t<decltype(kind)>::name); });
    std::sort(names.begin(), names.end());
    std::string out = std::string(title) + ": ";
    for (std::size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "lc." : ", lc.") + names[i];
    return out + ";";
  };
  const std::vector<std::string> expected = {
      group("spacetimes", {}, static_cast<lc::SpacetimeRegistry*>(nullptr)),
      group("observers and worldlines", {"worldline"}, static_cast<lc::ObserverRegistry*>(nullptr)),
      group("cameras", {}, static_cast<lc::CameraSpecs*>(nullptr)),
      group("skies", {}, static_cast<lc::SkyRegistry*>(nullptr)),
      group("objects", {}, static_cast<lc::ObjectSpecs*>(nullptr)),
      "light: lc.light;", "helpers: lc.apocentres, ", "lc.look_at", "lc.timeline", "(docs/shots.md)"};
  for (const std::string& listed : expected)
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
  EXPECT_NE(error("local st = lc.kerr_nemwan{mass = 1, charge = 0.5}")
                .find(":2: lc.kerr_nemwan is not a lightcone constructor or function (did you mean lc.kerr?); lc has "),
            std::string::npos);
  // A special case of a spacetime, by its own name: how it is written.
  EXPECT_NE(error("local st = lc.kerr_newman{mass = 1, charge = 0.5}")
                .find(":2: lc.kerr_newman is no constructor of its own: it is written lc.kerr{mass = M, spin = a, "
                      "charge = Q} (docs/physics.md)"),
            std::string::npos);
  EXPECT_NE(error("local st = lc.schwarzschild{mass = 1}").find("it is written lc.kerr{mass = M}"), std::string::npos);
  const std::string wormhole = error("local st = lc.wormhole{throat = 1}");
  EXPECT_NE(wormhole.find(":2: lc.wormhole is no constructor of its own: it is written lc.ellis_wormhole{throat = b} "
                          "or lc.interstellar_wormhole{"),
            std::string::npos)
      << wormhole;
  const std::string unknown = error("local st = lc.warp_drive{speed = 2}");
  EXPECT_NE(unknown.find(":2: lc.warp_drive is not a lightcone constructor or function; lc has "), std::string::npos)
      << unknown;
  EXPECT_NE(error("local s = lc.sky_chekcer{}").find("(did you mean lc.sky_checker?)"), std::string::npos);
  EXPECT_NE(error("local c = lc.camrea{}").find("(did you mean lc.camera?)"), std::string::npos);
  EXPECT_NE(error("local x = lc[1]").find(":2: lc[1] is not a lightcone constructor or function"), std::string::npos);
  const std::string long_name = error("local x = lc[string.rep('a', 100000)]");
  EXPECT_NE(long_name.find(":2: lc." + std::string(64, 'a') + "... is not a lightcone"), std::string::npos);
  EXPECT_LT(long_name.size(), 2000u);
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
                                       "  if i == 1 then s.camera = lc.orthographic{fov = 180} end\n"
                                       "  return s\n"
                                       "end}\n");
  lc::Shot shot(file);
  EXPECT_NO_THROW(shot.frame(0));
  const std::string msg = first_line(error_of<ScriptError>([&] { shot.frame(1); }));
  EXPECT_EQ(msg.rfind(file.string() + ": frame 1: " + file.string() + ":4: lc.orthographic is not a lightcone", 0), 0u)
      << msg;
}

// Reading a name without the error (rawget), and names a shot adds itself,
// still work: the error is only for names lc lacks.
TEST(ScriptErrors, RawgetAndAddedNamesStillWork) {
  ScratchDir dir;
  const fs::path file = shot_running(dir,
                                     "assert(rawget(lc, 'orthographic') == nil)\n"
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
  EXPECT_EQ(msg.rfind(file.string() + ":2: lc.kerr_newman is no constructor of its own: it is written lc.kerr{mass = M, "
                                       "spin = a, charge = Q}",
                      0),
            0u)
      << msg;
}

// lc.camera{fov = 180, projection = "fisheye"} said fov must be less than
// 180: the unknown field, which the author most likely meant to matter, is
// reported first, for every constructor and the shot table. A kind's own
// extra fields (the sphere's placement) are no unknown ones.
TEST(ScriptErrors, UnknownFieldsAreReportedBeforeBadValues) {
  ScratchDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"lc.camera{fov = 180, projection = 'fisheye'}", "camera: unknown field 'projection'"},
      {"lc.kerr{mass = -1, chrage = 0.5}", "kerr: unknown field 'chrage' (did you mean 'charge'?)"},
      {"lc.dihole{m1 = -1, m2 = 1, distance = 2}", "dihole: unknown field 'distance'"},
      {"lc.minkowski{mass = 1}", "minkowski: unknown field 'mass'"},
      {"lc.sky_checker{rows = 0, colour = {{1, 1, 1}, {0, 0, 0}}}", "sky_checker: unknown field 'colour' (did you "
                                                                    "mean 'colors'?)"},
      {"lc.sky_stars{resolution = 1, sede = 3}", "sky_stars: unknown field 'sede' (did you mean 'seed'?)"},
      {"lc.starfield{glare = 2, backgrnd = 'none'}", "starfield: unknown field 'backgrnd' (did you mean 'background'?)"},
      {"lc.sky_image{file = '', brightnes = 1}", "sky_image: unknown field 'brightnes' (did you mean 'brightness'?)"},
      {"lc.disk{inner = -1, outer = 5, ring = 3}", "disk: unknown field 'ring' (did you mean 'rings'?)"},
      {"lc.sphere{radius = -1, position = {x = 0, y = 0, z = 5}, rows = 0, colums = 3}",
       "sphere: unknown field 'colums' (did you mean 'columns'?)"},
      {"lc.light{model = 'nonsense', doppler = true}", "light: unknown field 'doppler'"},
      // Kinds read by hand check their keys first too.
      {"lc.static_observer{r = -1, theta = 90, phi = 0, tilt = 3}", "static_observer: unknown field 'tilt'"},
      {"lc.zamo{r = 'far', theta = 90, phi = 0, spin = 1}", "zamo: unknown field 'spin'"},
      {"lc.worldline{spacetime = lc.kerr{mass = 1}, start = {r = 10, theta = 90, phi = 0}, duration = -1, "
       "velocty = {phi = 0.3}}",
       "worldline: unknown field 'velocty' (did you mean 'velocity'?)"},
      {"lc.worldline{spacetime = lc.kerr{mass = 1}, start = {r = -10, theta = 90, phi = 0, z = 1}, duration = 5}",
       "worldline.start: give either {r, theta, phi} (Boyer–Lindquist, degrees) or {x, y, z}, not both"},
      {"lc.worldline{spacetime = lc.kerr{mass = 1}, start = {r = -10, theta = 90, phi = 0, q = 1}, duration = 5}",
       "worldline.start: unknown field 'q'"},
      {"lc.worldline{spacetime = lc.kerr{mass = 1}, start = {r = 10, theta = 90, phi = 0}, duration = 5, "
       "velocity = {phi = 2, psi = 1}}",
       "worldline.velocity: unknown field 'psi' (did you mean 'phi'?)"},
      {"lc.free_fall{worldline = lc.worldline{spacetime = lc.kerr{mass = 1}, start = {r = 10, theta = 90, phi = 0}, "
       "duration = 5}, proper_time = 9, tau = 1}",
       "free_fall: unknown field 'tau'"},
  };
  for (const auto& [call, expected] : cases) {
    const fs::path file = shot_running(dir, "local x = " + call);
    const std::string msg = first_line(error_of<ScriptError>([&] { lc::Shot shot(file); }));
    EXPECT_EQ(msg, file.string() + ":2: " + expected) << call;
  }
  // A sphere placed as it must be, with no unknown field, reads.
  EXPECT_NO_THROW(lc::Shot shot(shot_running(dir, "local s = lc.sphere{radius = 1, position = {x = 0, y = 0, z = 5}}")));

  // The shot table.
  const fs::path shot = write_file(dir, "table.lua",
                                   std::string("local lc = require 'lightcone'\n"
                                               "return {name = 'shot', frames = 0, width = 8, height = 8, sampels = 4,\n"
                                               "  frame = function(i) return ") +
                                       kScene + " end}\n");
  EXPECT_EQ(error_of<FieldError>([&] { lc::Shot s(shot); }), shot.string() + ": unknown field 'sampels'");
}

// A constructor's fields inherited through __index were dropped without a
// word (issue 43): refused at the line that called it, naming the field;
// the value made has no metatable.
TEST(ScriptErrors, ConstructorFieldsInheritedThroughIndexAreRefused) {
  ScratchDir dir;
  const fs::path file =
      shot_running(dir, "local base = {fov = 30}\nlocal c = lc.camera(setmetatable({yaw = 5}, {__index = base}))");
  const std::string msg = first_line(error_of<ScriptError>([&] { lc::Shot shot(file); }));
  EXPECT_NE(msg.find("shot.lua:3: camera: field 'fov' is inherited through a metatable's __index"), std::string::npos)
      << msg;
  ScratchDir ok_dir;
  const fs::path ok = shot_running(ok_dir, "local c = lc.camera(setmetatable({yaw = 5}, {__index = {other = 1}}))\n"
                                           "assert(getmetatable(c) == nil and c.yaw == 5)");
  EXPECT_NO_THROW(lc::Shot shot(ok));
}

}  // namespace
