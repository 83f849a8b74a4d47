// Tests of the skies' light (engine/sky/): every sky's `brightness` scales
// what its rays see by 2^brightness, so that a sky can be lifted to a scene
// in physical units (docs/light.md), where a shot's exposure near -34 left
// lc.sky_checker{}, which had no brightness, black; and what lc.starfield{}
// puts behind the stars by default: the generated glow for the generated
// field, nothing for the real sky's stars.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "assets/shot_resources.hpp"
#include "camera/pinhole_params.hpp"
#include "core/constants.hpp"
#include "image/look.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "render/trace.hpp"
#include "scratch_dir.hpp"
#include "script/shot.hpp"
#include "spacetime/minkowski.hpp"

namespace lc {
namespace {

namespace fs = std::filesystem;

// The pixel-centre colours of a W x H frame of flat space seen by a static
// observer at z = 10 looking at the origin (every ray escapes to the sky),
// with a camera of 150 degrees: the sky's cells and its band both show.
std::vector<Color> sky_frame(const SkySpec& sky, int W = 24, int H = 12) {
  SceneSpec fs;
  fs.spacetime = Minkowski();
  fs.observer = StaticObserver::Params{{0, 3, 4, 7}};
  fs.camera.get<PinholeParams>().fov = 150;
  fs.sky = sky;
  ShotResources res;
  const Scene scene = build_scene(fs, W, H, res);
  std::vector<Color> out;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i)
      out.push_back(trace_image_point(scene, i + 0.5, j + 0.5).color);
  return out;
}

float largest(const std::vector<Color>& frame) {
  float m = 0.0f;
  for (const Color& c : frame)
    for (float v : c) m = std::max(m, v);
  return m;
}

// In physical units a shot's exposure is near -34 (docs/light.md): the
// checker sky at brightness 34 shows there as the plain sky does at 0,
// exactly (powers of two), and every pixel's light is 2^34 times it.
TEST(Sky, CheckerSkyBrightnessLiftsItIntoPhysicalUnits) {
  CheckerSky::Params plain;
  CheckerSky::Params lifted = plain;
  lifted.brightness = 34;
  const std::vector<Color> a = sky_frame(plain), b = sky_frame(lifted);
  ASSERT_EQ(a.size(), b.size());
  const auto physical = [](float v) {
    return Look{.exposure = -34.0}.applied(FrameImage{1, 1, {v, v, v}, {}, {}, {}}).rgb[0];
  };
  for (std::size_t k = 0; k < a.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(b[k][c], a[k][c] * 0x1p34f) << k;
      EXPECT_EQ(physical(b[k][c]), a[k][c]) << k;
    }
  EXPECT_GT(largest(a), 0.5f);  // the light cells (0.6) show: not black
  // Without it, exposure -34 leaves the checker black (below one 8-bit
  // step of the PNG's 1/255).
  EXPECT_LT(physical(largest(a)), 1.0f / 255);
  // The default brightness is the checker's colours as they were.
  CheckerSky::Params half = plain;
  half.brightness = -1;
  const std::vector<Color> h = sky_frame(half);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(h[k][0], a[k][0] * 0.5f) << k;
}

// The field is declared: lc.sky_checker{brightness = 34} reads, its range
// is checked like the other skies'.
TEST(Sky, CheckerSkyBrightnessIsADeclaredField) {
  test::ScratchDir dir;
  const auto shot_with = [&](const std::string& sky) {
    const fs::path file = dir / "shot.lua";
    std::ofstream(file) << "local lc = require 'lightcone'\n"
                           "return {name = 'shot', frames = 1, width = 8, height = 8, frame = function(i) return\n"
                           "  {spacetime = lc.minkowski{}, observer = lc.static_observer{x = 0, y = 0, z = 10}, sky = "
                        << sky << "} end}\n";
    return file;
  };
  Shot shot(shot_with("lc.sky_checker{brightness = 34}"));
  EXPECT_EQ(std::get<CheckerSky::Params>(shot.frame(0).sky).brightness, 34.0);
  Shot far(shot_with("lc.sky_checker{brightness = 65}"));
  try {
    far.frame(0);
    ADD_FAILURE() << "brightness 65 was read";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("sky_checker: field 'brightness' must be between -64 and 64 stops, got 65"),
              std::string::npos)
        << e.what();
  }
}

// A catalogue of two stars typed for the test, named by
// LIGHTCONE_STAR_CATALOGUE while it lives.
class TypedCatalogue {
 public:
  TypedCatalogue() {
    std::ofstream(dir_ / "stars.dat") << "064508.92 -164258.0 -000546.0-001223.100379.2 -1.4400.01A0 1, alp CMa, Sirius\n"
                                      << "183656.34 +384701.3 000201.7 000286.9 00128.9 00.03-0.00A0 1, alp Lyr, Vega\n";
    ::setenv("LIGHTCONE_STAR_CATALOGUE", (dir_ / "stars.dat").c_str(), 1);
  }
  ~TypedCatalogue() { ::unsetenv("LIGHTCONE_STAR_CATALOGUE"); }
  TypedCatalogue(const TypedCatalogue&) = delete;
  TypedCatalogue& operator=(const TypedCatalogue&) = delete;

 private:
  test::ScratchDir dir_;
};

// lc.starfield{catalogue = "kstars"} painted the generated field's band, in
// a place that has nothing to do with the real Milky Way, behind the real
// stars. By default the real sky's background is black now (its stars are
// drawn after the pixels, not by the rays); the glow is there when asked.
TEST(Sky, TheRealSkysDefaultBackgroundIsNoGeneratedGlow) {
  const TypedCatalogue catalogue;
  PointStarSky::Params real;
  real.catalogue = StarCatalogue::kstars;
  EXPECT_EQ(real.background, "auto");
  EXPECT_EQ(PointStarSky::background(real), "none");
  EXPECT_EQ(largest(sky_frame(real)), 0.0f);

  PointStarSky::Params asked = real;
  asked.background = "generated";
  PointStarSky::Params generated;  // the generated field, its default background
  const std::vector<Color> glow = sky_frame(asked);
  EXPECT_GT(largest(glow), 0.0f);
  EXPECT_EQ(glow, sky_frame(generated));  // the same glow as the generated field's
}

// The generated field keeps its glow by default: the frames of every shot
// that uses it are what they were.
TEST(Sky, TheGeneratedFieldsDefaultBackgroundIsItsGlow) {
  PointStarSky::Params p;
  EXPECT_EQ(PointStarSky::background(p), "generated");
  PointStarSky::Params explicit_glow = p;
  explicit_glow.background = "generated";
  const std::vector<Color> frame = sky_frame(p);
  EXPECT_GT(largest(frame), 0.0f);
  EXPECT_EQ(frame, sky_frame(explicit_glow));
  PointStarSky::Params none = p;
  none.background = "none";
  EXPECT_EQ(largest(sky_frame(none)), 0.0f);
}

}  // namespace
}  // namespace lc
