// A frame's scenes with its shutter (scene/frame_specs.hpp), as a shot gives
// them (Shot::frame_specs): the shot evaluated at each instant, a frame that
// does not change within its shutter not blurred, and errors that name the
// fractional frame and the shutter (docs/motion_blur.md).

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "lua/table_reader.hpp"
#include "observers/observers.hpp"
#include "scene/frame_specs.hpp"
#include "script/shot.hpp"
#include "scratch_dir.hpp"
#include "shot_file.hpp"
#include "test_errors.hpp"

namespace lc {
namespace {

using test::ScratchDir;
using test::write_shot;

TEST(FrameSpecs, TheShotIsEvaluatedAtEachInstantClampedToItsFrames) {
  ScratchDir dir;
  const auto file = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
return {name = 's', frames = 3, width = 8, height = 8, shutter = 0.5, time_samples = 2,
  frame = function(i)
    return {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 20, z = 0}, time = 10 * i}
  end})");
  Shot shot(file);
  const FrameSpecs mid = shot.frame_specs(1);
  ASSERT_TRUE(mid.blurred());
  EXPECT_EQ(mid.times, (std::vector<double>{-0.125, 0.125}));
  EXPECT_EQ(observer_clock(mid.frame.observer), 10.0);
  EXPECT_EQ(observer_clock(mid.instants[0].observer), 8.75);
  EXPECT_EQ(observer_clock(mid.instants[1].observer), 11.25);
  // Before the first frame the shot holds still.
  const FrameSpecs first = shot.frame_specs(0);
  EXPECT_EQ(observer_clock(first.instants[0].observer), 0.0);
  EXPECT_EQ(observer_clock(first.instants[1].observer), 1.25);
  // The command line closes it.
  shot.set_shutter({.open = 0.0});
  EXPECT_FALSE(shot.frame_specs(1).blurred());
}

TEST(FrameSpecs, AFrameThatDoesNotChangeWithinItsShutterIsNotBlurred) {
  ScratchDir dir;
  const auto file = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
return {name = 's', frames = 3, width = 8, height = 8, shutter = 1,
  frame = function(i)
    return {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 20, z = 0},
            shutter = i == 2 and 0 or nil}
  end})");
  Shot shot(file);
  const FrameSpecs specs = shot.frame_specs(1);
  EXPECT_EQ(specs.shutter.open, 1.0);
  EXPECT_FALSE(specs.blurred());
  EXPECT_EQ(shot.frame_specs(2).shutter.open, 0.0);  // a frame's own shutter
}

TEST(FrameSpecs, ErrorsNameTheFractionalFrameAndTheShutter) {
  ScratchDir dir;
  // A script that only knows whole frames: a table indexed by i.
  const auto file = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
local heights = {20, 21, 22}
return {name = 's', frames = 3, width = 8, height = 8, shutter = 0.5, time_samples = 2,
  frame = function(i)
    return {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = heights[i + 1], z = 0}}
  end})");
  Shot shot(file);
  const std::string e = test::error_of([&] { shot.frame_specs(1); });
  EXPECT_EQ(e.find("shot.lua: frame 1 at 0.875: "), e.find("shot.lua")) << e;
  EXPECT_NE(e.find("(frame 1's shutter is open: frame(i) is also called at fractional i"), std::string::npos) << e;
  EXPECT_NE(e.find("docs/motion_blur.md"), std::string::npos) << e;

  const auto change = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
return {name = 's', frames = 3, width = 8, height = 8, shutter = 1,
  frame = function(i)
    local st = i < 1.2 and lc.minkowski{} or lc.dihole{m1 = 0.4, m2 = 0.4, d = 1}
    return {spacetime = st, observer = lc.static_observer{x = 0, y = 20, z = 0}}
  end})");
  Shot changing(change);
  const std::string c = test::error_of<std::invalid_argument>([&] { changing.frame_specs(1); });
  EXPECT_NE(c.find("frame 1: the spacetime is minkowski at the frame but dihole at 1.3125"), std::string::npos) << c;

  const auto sky_cut = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
return {name = 's', frames = 3, width = 8, height = 8, shutter = 1, time_samples = 2,
  frame = function(i)
    return {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 20, z = 0},
            sky = i < 1.1 and lc.starfield{} or lc.sky_checker{}}
  end})");
  Shot cutting(sky_cut);
  const std::string k = test::error_of<std::invalid_argument>([&] { cutting.frame_specs(1); });
  EXPECT_NE(k.find("frame 1: the sky is lc.starfield at the frame but lc.sky_checker at 1.25"), std::string::npos) << k;

  const auto bad = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
return {name = 's', frames = 3, width = 8, height = 8,
  frame = function(i)
    return {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 20, z = 0}, shutter = 2}
  end})");
  Shot too_long(bad);
  const std::string b = test::error_of([&] { too_long.frame_specs(0); });
  EXPECT_NE(b.find("field 'shutter' must be between 0 and 1"), std::string::npos) << b;
  EXPECT_NE(b.find("frame 0"), std::string::npos) << b;
}

// A table indexed by a fractional i gives nil: where that was an optional
// field, the instant took its default without a word (issue 43). A field
// set at the frame and absent at an instant is an error naming both; the
// frame's own exposure and shutter (an instant's are not used) may be.
TEST(FrameSpecs, AFieldSetAtTheFrameButNotAtAnInstantIsAnError) {
  ScratchDir dir;
  const auto file = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
local yaws = {0, 10, 20}
return {name = 's', frames = 3, width = 8, height = 8, shutter = 0.5, time_samples = 2,
  frame = function(i)
    return {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 20, z = 0},
            camera = lc.camera{fov = 40, yaw = yaws[i + 1]}}
  end})");
  Shot shot(file);
  const std::string e = test::error_of<lua::FieldError>([&] { shot.frame_specs(1); });
  EXPECT_EQ(e.find("shot.lua: frame 1 at 0.875: field 'camera.yaw' is set at frame 1 but not at 0.875: a table "
                   "indexed by a fractional i gives nil"),
            e.find("shot.lua"))
      << e;
  EXPECT_NE(e.find("(frame 1's shutter is open"), std::string::npos) << e;

  const auto own = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
local exposures = {1, 2, 3}
return {name = 's', frames = 3, width = 8, height = 8, time_samples = 2,
  frame = function(i)
    return {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 20 + i, z = 0},
            exposure = exposures[i + 1], shutter = i == 1 and 0.5 or nil}
  end})");
  Shot frame_only(own);
  EXPECT_TRUE(frame_only.frame_specs(1).blurred());
}

}  // namespace
}  // namespace lc
