// Tests of lc::Shot (engine/script/shot.cpp): what its errors say about the
// shot table and about the frame they happen in.

#include "script/shot.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lua/table_reader.hpp"
#include "scene/scene_json.hpp"
#include "scene/still_key.hpp"
#include "scratch_dir.hpp"
#include "shot_file.hpp"
#include "test_errors.hpp"

namespace {

namespace fs = std::filesystem;
using lc::test::ScratchDir;
using lc::test::error_of;
using lc::test::write_shot;

constexpr const char* kScene =
    "{spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = 0}}";

// A Lua error inside frame(i) named the script's line only; in a shot of
// many frames it must say which one failed, as the scene errors do
// ("shot.lua: frame 0: observer: ...").
TEST(Shot, ErrorsInsideFrameNameTheFrame) {
  ScratchDir dir;
  const fs::path file = write_shot(dir, "shot.lua",
                                   std::string("local lc = require 'lightcone'\n"
                                               "return {name = 'shot', frames = 600, width = 8, height = 8,\n"
                                               "  frame = function(i)\n"
                                               "    if i == 3 then return {disk = lc.disk{inner = -1, outer = 5}} end\n"
                                               "    if i == 517 then local x = nil return x.y end\n"
                                               "    return ") +
                                       kScene + "\n  end}\n");
  lc::Shot shot(file);
  EXPECT_NO_THROW(shot.frame(516));
  const std::string f = file.string();
  // Lua names a long path by its tail ("...Frame_123/shot.lua").
  const std::string tail = "/shot.lua:5: attempt to index local 'x' (a nil value)\nstack traceback:";
  const std::string msg = error_of<lc::lua::ScriptError>([&] { shot.frame(517); });
  EXPECT_EQ(msg.rfind(f + ": frame 517: ", 0), 0u) << msg;
  EXPECT_NE(msg.find(tail), std::string::npos) << msg;
  EXPECT_EQ(error_of<lc::lua::ScriptError>([&] { shot.frame(3); })
                .rfind(f + ": frame 3: " + f + ":4: disk: field 'inner' must be at least 0 M, got -1", 0),
            0u);
  EXPECT_NO_THROW(shot.frame(0));  // the state is fine after errors
}

// The scene of frame i depended on which frames had been evaluated before it
// in the same Lua state: a shot that counted its calls in a global rendered
// differently with --frames 3:5, after a resume and on every MPI rank (issue
// 25, defect 2).  Now every frame runs the script afresh: state kept in a
// global, an upvalue, a table or the library is gone by the next frame.
TEST(Shot, AFramesSceneDependsOnlyOnTheShotAndI) {
  ScratchDir dir;
  const fs::path file = write_shot(dir, "stateful.lua", R"(local lc = require 'lightcone'
local calls = 0          -- an upvalue
local seen = {}          -- a table
return {name = 'stateful', frames = 10, width = 8, height = 8,
  frame = function(i)
    counter = (counter or 0) + 1      -- a global
    calls = calls + 1
    seen[#seen + 1] = i
    first = first or i                -- "the first frame rendered"
    math.kept = (math.kept or 0) + 1  -- a library table
    local yaw = counter * 5 + calls + #seen + (i - first) + math.kept
    return {spacetime = lc.kerr{mass = 1, spin = 0.9},
            observer = lc.static_observer{r = 30, theta = 80, phi = 0},
            camera = lc.camera{fov = 40, yaw = yaw}}
  end}
)");
  auto json_of = [](lc::Shot& shot, int i) { return lc::to_json(shot.frame(i), i); };
  lc::Shot in_order(file);
  std::vector<std::string> ordered;
  for (int i = 0; i < 10; ++i) ordered.push_back(json_of(in_order, i));
  for (int i : {7, 3, 3, 9, 0, 5}) {
    lc::Shot alone(file);  // as --frames i:i, a resume from i, or an MPI rank given i first
    EXPECT_EQ(json_of(alone, i), ordered[i]) << "frame " << i;
    EXPECT_EQ(json_of(in_order, i), ordered[i]) << "frame " << i << " again";
  }
  EXPECT_NE(ordered[0].find("\"yaw\": 8"), std::string::npos) << ordered[0];  // 5 + 1 + 1 + 0 + 1 (frame 0)
}

// A module required inside frame() is one of the shot's inputs, whichever
// frame required it.
TEST(Shot, ModulesRequiredByAnyFrameAreItsInputs) {
  ScratchDir dir;
  std::ofstream(dir / "late.lua") << "return {fov = 33}\n";
  const fs::path file = write_shot(dir, "modules.lua", std::string(R"(local lc = require 'lightcone'
return {name = 'modules', frames = 4, width = 8, height = 8,
  frame = function(i)
    local fov = 40
    if i == 2 then fov = require('late').fov end
    return {spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = 0},
            camera = lc.camera{fov = fov}}
  end}
)"));
  lc::Shot shot(file);
  auto has_late = [&] {
    for (const auto& p : shot.loaded_files())
      if (p.filename() == "late.lua") return true;
    return false;
  };
  shot.frame(0);
  EXPECT_FALSE(has_late());
  shot.frame(2);
  shot.frame(3);  // a later frame in a fresh sandbox does not forget it
  EXPECT_TRUE(has_late());
}

// A misspelt frames suggested 'frame', a field of every shot. (Unknown
// fields are reported before the missing ones they most likely stand for.)
// A shipped shot is a module: a shot in another folder requires it as
// "lightcone.shots.NAME" and renders its scenes (issue 43, item 15), and
// a shipped shot that requires its sibling (the thermal sequence) works
// from there, too.
TEST(Shot, ShippedShotsAreModules) {
  ScratchDir dir;
  const fs::path file = write_shot(dir, "wrap.lua", R"(local paper = require "lightcone.shots.kerr_accrDisk"
local shot = {}
for k, v in pairs(paper) do shot[k] = v end
shot.name = "wrapped"
return shot)");
  lc::Shot wrapped(file);
  lc::Shot paper(fs::path(LIGHTCONE_SOURCE_DIR) / "shots" / "kerr_accrDisk.lua");
  EXPECT_EQ(wrapped.info().name, "wrapped");
  EXPECT_EQ(wrapped.info().frames, paper.info().frames);
  EXPECT_EQ(lc::scene_key(wrapped.frame(450)), lc::scene_key(paper.frame(450)));
  const fs::path thermal = write_shot(dir, "thermal.lua", "return require 'lightcone.shots.kerr_accrDisk_thermal'\n");
  lc::Shot warm(thermal);
  EXPECT_EQ(warm.info().name, "kerr_accrDisk_thermal");
  EXPECT_NO_THROW(warm.frame(0));
}

TEST(Shot, MisspeltFramesSuggestsTheMissingField) {
  ScratchDir dir;
  const fs::path file = write_shot(dir, "shot.lua",
                                   std::string("local lc = require 'lightcone'\n"
                                               "return {name = 'shot', frame_count = 10, width = 8, height = 8,\n"
                                               "  frame = function(i) return ") +
                                       kScene + " end}\n");
  EXPECT_EQ(error_of<lc::lua::FieldError>([&] { lc::Shot shot(file); }),
            file.string() + ": unknown field 'frame_count' (did you mean 'frames'?)");
}

// A script can list one sphere a million times in a few MiB of Lua memory;
// the scene's copy of them took GiBs (and a ray tests every sphere).
TEST(Shot, ObjectsAndNamesAreBounded) {
  ScratchDir dir;
  const std::string spheres =
      "local s = lc.sphere{radius = 1, position = {r = 10, theta = 90, phi = 0}}\n"
      "local many = {} for i = 1, 1e6 do many[i] = s end\n";
  const fs::path file = write_shot(dir, "shot.lua",
                                   "local lc = require 'lightcone'\n" + spheres +
                                       "return {name = 'shot', frames = 2, width = 8, height = 8,\n"
                                       "  frame = function(i)\n"
                                       "    return {spacetime = lc.kerr{mass = 1, spin = 0.9},\n"
                                       "            observer = lc.static_observer{r = 30, theta = 80, phi = 0},\n"
                                       "            objects = i == 0 and {s, s} or many}\n"
                                       "  end}\n");
  lc::Shot shot(file);
  EXPECT_EQ(shot.frame(0).objects.size(), 2u);
  EXPECT_EQ(error_of<lc::lua::FieldError>([&] { shot.frame(1); }),
            file.string() + ": frame 1.objects: at most 1000 objects, got 1000000");

  const fs::path named = write_shot(dir, "named.lua",
                                    "return {name = string.rep('n', 1e6), frames = 1, width = 8, height = 8,\n"
                                    "  frame = function(i) return {} end}\n");
  EXPECT_EQ(error_of<lc::lua::FieldError>([&] { lc::Shot shot(named); }),
            named.string() + ": name has 1000000 characters, at most 128 are allowed (it names the output files)");
}

TEST(Shot, ExposureToneAndGradeReachTheLook) {
  ScratchDir dir;
  const auto shot_with = [&](const std::string& fields) {
    return write_shot(dir, "display.lua",
                      "return {name = 'shot', frames = 1, width = 8, height = 8, " + fields +
                          "\n  frame = function(i) return {} end}\n");
  };
  const lc::Shot plain(shot_with(""));
  EXPECT_TRUE(plain.info().look().identity());
  const lc::Shot filmic(shot_with("exposure = -1.5, filmic = 1,"));
  EXPECT_EQ(filmic.info().look().exposure, -1.5);
  EXPECT_EQ(filmic.info().look().view, lc::View::filmic);
  const lc::Shot graded(
      shot_with("view = 'gamut_safe', white_balance = 9000, saturation = 1.2, bloom = 0.1, bloom_radius = 0.02,"));
  const lc::Look g = graded.info().look();
  EXPECT_EQ(g.view, lc::View::gamut_safe);
  EXPECT_EQ(g.white_balance, 9000.0);
  EXPECT_EQ(g.saturation, 1.2);
  EXPECT_EQ(g.bloom, 0.1);
  EXPECT_EQ(g.bloom_radius, 0.02);
  const fs::path both = shot_with("filmic = 1, view = 'gamut_safe',");
  EXPECT_NE(error_of<lc::lua::FieldError>([&] { lc::Shot shot(both); }).find("give view alone"), std::string::npos);
  const fs::path cold = shot_with("white_balance = 500,");
  EXPECT_NE(error_of<lc::lua::FieldError>([&] { lc::Shot shot(cold); }).find("white_balance 500 K"), std::string::npos);
  const fs::path unknown = shot_with("view = 'agx',");
  EXPECT_NE(error_of<lc::lua::FieldError>([&] { lc::Shot shot(unknown); }).find("view"), std::string::npos);
  const fs::path bad = shot_with("filmic = 2,");
  EXPECT_NE(error_of<lc::lua::FieldError>([&] { lc::Shot shot(bad); }).find("filmic"), std::string::npos);
  const fs::path far = shot_with("exposure = 70,");
  EXPECT_NE(error_of<lc::lua::FieldError>([&] { lc::Shot shot(far); }).find("exposure"), std::string::npos);
}

// lc.light{...} reaches the frame's scene; an unknown model or a switch
// out of range is an error at the line that made it, naming the field.
TEST(Shot, LightIsReadAndCheckedAtTheShotsLine) {
  ScratchDir dir;
  const auto shot_with = [&](const std::string& light) {
    return write_shot(dir, "light.lua",
                      "local lc = require 'lightcone'\n"
                      "return {name = 'shot', frames = 1, width = 8, height = 8,\n"
                      "  frame = function(i) return {spacetime = lc.kerr{mass = 1, spin = 0.9},\n"
                      "    observer = lc.static_observer{r = 30, theta = 80, phi = 0},\n"
                      "    light = " + light + "} end}\n");
  };
  const lc::SceneSpec fs = lc::Shot(shot_with("lc.light{model = 'shifted', kinematic = 0}")).frame(0);
  EXPECT_EQ(fs.light.model, lc::LightModel::shifted);
  EXPECT_EQ(fs.light.kinematic, 0);
  EXPECT_EQ(fs.light.gravitational, 1);
  EXPECT_EQ(lc::Shot(shot_with("lc.light{}")).frame(0).light.model, lc::LightModel::geometric);

  const fs::path unknown = shot_with("lc.light{model = 'physical'}");
  EXPECT_EQ(error_of<lc::lua::ScriptError>([&] { lc::Shot(unknown).frame(0); })
                .rfind(unknown.string() + ": frame 0: " + unknown.string() +
                           ":5: light: field 'model' must be geometric or shifted, got 'physical'\n",
                       0),
            0u);
  const fs::path out_of_range = shot_with("lc.light{model = 'shifted', beaming = 2}");
  EXPECT_NE(error_of<lc::lua::ScriptError>([&] { lc::Shot(out_of_range).frame(0); })
                .find(":5: light: field 'beaming' must be 0 or 1, got 2"),
            std::string::npos);
  // A switch without the shifted model would be ignored: refused.
  const fs::path ignored = shot_with("lc.light{beaming = 0}");
  EXPECT_NE(error_of<lc::lua::ScriptError>([&] { lc::Shot(ignored).frame(0); })
                .find(":5: light: color_shift, beaming, gravitational and kinematic choose what model = \"shifted\" "
                      "shows"),
            std::string::npos);
  const fs::path not_light = shot_with("lc.camera{}");
  EXPECT_NE(error_of<lc::lua::FieldError>([&] { lc::Shot(not_light).frame(0); }).find("expected a value made by lc.light{...}, got a camera"),
            std::string::npos);
}

// A glowing disk is given by its temperature or by physical units, one way;
// a negative rate or half of the physical pair is an error at the line.
TEST(Shot, AGlowingDisksUnitsAreCheckedAtTheShotsLine) {
  ScratchDir dir;
  const auto error_for = [&](const std::string& disk) {
    const fs::path file = write_shot(dir, "disk.lua",
                                     "local lc = require 'lightcone'\n"
                                     "return {name = 'shot', frames = 1, width = 8, height = 8,\n"
                                     "  frame = function(i) return {spacetime = lc.kerr{mass = 1, spin = 0.9},\n"
                                     "    observer = lc.static_observer{r = 30, theta = 80, phi = 0},\n"
                                     "    disk = " + disk + "} end}\n");
    return error_of<lc::lua::ScriptError>([&] { lc::Shot(file).frame(0); });
  };
  EXPECT_NE(error_for("lc.disk{inner = 3, outer = 9, solar_masses = 10, accretion_rate = -1}")
                .find(":5: disk: field 'accretion_rate' must be between 0 and 1000000 M_sun/yr, got -1"),
            std::string::npos);
  EXPECT_NE(error_for("lc.disk{inner = 3, outer = 9, solar_masses = 10}")
                .find(":5: disk: a disk's glow from physical units needs both solar_masses and accretion_rate above 0, "
                      "got 10 and 0"),
            std::string::npos);
  EXPECT_NE(error_for("lc.disk{inner = 3, outer = 9, temperature = 5000, solar_masses = 10, accretion_rate = 1}")
                .find(":5: disk: give a glowing disk either its temperature or its solar_masses and accretion_rate, "
                      "not both"),
            std::string::npos);
  EXPECT_NE(error_for("lc.disk{inner = 3, outer = 9, temperature = -5}")
                .find(":5: disk: field 'temperature' must be between 0 and 1000000000 K, got -5"),
            std::string::npos);
}

}  // namespace
