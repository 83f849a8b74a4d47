// still_key: frames that differ only by a static observer's time share a
// key; any other difference, however small, gives another.

#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole_params.hpp"
#include "objects/disk_params.hpp"
#include "objects/sphere_params.hpp"
#include "scene/still_key.hpp"
#include "spacetime/ellis_wormhole.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"

#include <string>

#include "core/registry.hpp"
#include "lua/sandbox.hpp"
#include "script/field_reader.hpp"
#include "test_errors.hpp"

namespace lc {
namespace {

SceneSpec scene() {
  SceneSpec fs;
  fs.spacetime = Kerr(1.0, 0.9);
  fs.observer = StaticObserver::Params{{10.0, 30.0, 1.2, 0.3}};
  fs.objects.emplace_back(DiskParams{});
  SphereParams sp;
  sp.placement.at = Vec4{0.0, 12.0, 1.5, 0.0};
  fs.objects.push_back(sp);
  return fs;
}

TEST(StillKey, OnlyTheStaticObserversTimeIsLeftOut) {
  const std::string key = still_key(scene());
  SceneSpec later = scene();
  std::get<StaticObserver::Params>(later.observer).position[0] = 250.0;
  EXPECT_EQ(still_key(later), key);
  later.observer = Zamo::Params{std::get<StaticObserver::Params>(later.observer).position};
  EXPECT_NE(still_key(later), key);

  auto differs = [&](auto change) {
    SceneSpec fs = scene();
    change(fs);
    return still_key(fs) != key;
  };
  EXPECT_TRUE(differs([](SceneSpec& fs) {
    std::get<StaticObserver::Params>(fs.observer).position[1] = std::nextafter(30.0, 31.0);
  }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.spacetime = Kerr(1.0, std::nextafter(0.9, 1.0)); }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.camera.get<PinholeParams>().roll = 1e-12; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.objects[0].get<DiskParams>().sectors = 25; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.objects.erase(fs.objects.begin()); }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { std::get<CheckerSky::Params>(fs.sky).rotate = 1e-12; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.sky = StarImageSky::Params{2}; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { std::get<Vec4>(fs.objects[1].get<SphereParams>().placement.at)[1] = 12.5; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.objects[1].get<SphereParams>().colors.a[0] = 0.5f; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.objects.push_back(fs.objects[1]); }));
  // A sphere at rest ignores the time in its position.
  EXPECT_FALSE(differs([](SceneSpec& fs) { std::get<Vec4>(fs.objects[1].get<SphereParams>().placement.at)[0] = 99.0; }));
}

// A further end's sky (a wormhole's other side) is keyed with the scene's
// own (for_each_sky): another there, or a change in it, is another scene.
TEST(StillKey, EverySkyIsKeyedByItsEnd) {
  SceneSpec fs;
  fs.spacetime = EllisWormhole({1.0});
  fs.observer = StaticObserver::Params{{0.0, 5.0, 1.2, 0.3}};
  const std::string one_sky = still_key(fs);
  fs.end_skies.push_back({1, "other_side", CheckerSky::Params{}});
  const std::string two_skies = still_key(fs);
  EXPECT_NE(two_skies, one_sky);
  EXPECT_NE(two_skies.find("|sky other_side "), std::string::npos) << two_skies;
  std::get<CheckerSky::Params>(fs.end_skies[0].sky).rotate = 1e-12;
  EXPECT_NE(still_key(fs), two_skies);
}

TEST(StillKey, AFreeFallingObserverHasNone) {
  SceneSpec fs = scene();
  WorldlineSpec w;
  w.spacetime = fs.spacetime;
  w.start = {0.0, 30.0, 1.2, 0.0};
  w.duration = 100.0;
  FreeFall::Params ride;
  ride.worldline = w;
  ride.proper_time = 5.0;
  fs.observer = ride;
  EXPECT_EQ(still_key(fs), "");  // its frames never share rays
}

// A sphere's placement is a declared field: moving it, or making it fall
// along another worldline, changes the key.
TEST(StillKey, TheSpheresPlacementIsKeyed) {
  const std::string key = still_key(scene());
  WorldlineSpec w;
  w.spacetime = Kerr(1.0, 0.9);
  w.start = {0.0, 12.0, 1.5, 0.0};
  w.duration = 100.0;
  auto along = [&](const WorldlineSpec& spec) {
    SceneSpec fs = scene();
    fs.objects[1].get<SphereParams>().placement.at = spec;
    return still_key(fs);
  };
  const std::string falling = along(w);
  EXPECT_NE(falling, key);
  WorldlineSpec longer = w;
  longer.duration = std::nextafter(100.0, 200.0);
  EXPECT_NE(along(longer), falling);
  WorldlineSpec elsewhere = w;
  elsewhere.start[1] = std::nextafter(12.0, 13.0);
  EXPECT_NE(along(elsewhere), falling);
  WorldlineSpec same = w;
  same.where = "another.lua:3";  // where the script made it is no part of the picture
  EXPECT_EQ(along(same), falling);
}

// A toy object kind: a declared placement and nothing written by hand for
// it (no extra_key, extra_json, extra_fields or extra_doc).
struct Toy {
  static constexpr std::string_view name = "toy";
  struct Params {
    double size = 1.0;
    Placement placement;
    static constexpr auto fields = std::tuple{
        field("size", &Params::size, std::optional<double>{1.0}, above(0.0), std::nullopt, "how big", "M"),
        field("placement", &Params::placement, std::optional<NoDefault>{}, std::nullopt, std::nullopt,
              "where it is"),
    };
  };
};
using ToyRegistry = Registry<Toy>;
template <class P>
concept HandWrittenPlacement = requires(const P& p) { p.extra_key(); } || requires(const P& p) { p.extra_json(false); } ||
                               requires { P::extra_fields; } || requires { P::extra_doc; };
static_assert(!HandWrittenPlacement<Toy::Params> && !HandWrittenPlacement<SphereParams>);

Toy::Params toy_at(const Vec4& x) {
  Toy::Params p;
  p.placement.at = x;
  return p;
}

TEST(StillKey, AToyKindsDeclaredPlacementKeysItWithoutHandWrittenMembers) {
  const std::string key = ToyRegistry::key(toy_at({0.0, 3.0, 4.0, 5.0}));
  EXPECT_EQ(ToyRegistry::key(toy_at({7.0, 3.0, 4.0, 5.0})), key);  // at rest: its time is not where it is
  EXPECT_EQ(ToyRegistry::key(toy_at({0.0, 3.0, 4.0, 5.0})), key);
  for (int k = 1; k < 4; ++k) {
    Vec4 x = {0.0, 3.0, 4.0, 5.0};
    x[k] = std::nextafter(x[k], 10.0);
    EXPECT_NE(ToyRegistry::key(toy_at(x)), key) << "coordinate " << k;
  }
  Toy::Params bigger = toy_at({0.0, 3.0, 4.0, 5.0});
  bigger.size = 2.0;
  EXPECT_NE(ToyRegistry::key(bigger), key);
  WorldlineSpec w;
  w.start = {0.0, 3.0, 4.0, 5.0};
  w.duration = 10.0;
  Toy::Params falling;
  falling.placement.at = w;
  EXPECT_NE(ToyRegistry::key(falling), key);
  // And the JSON names the key the shot wrote, in the scene's chart.
  EXPECT_EQ(ToyRegistry::json(toy_at({0.0, 3.0, 4.0, 5.0})),
            R"({"kind": "toy", "size": 1, "position": {"t": 0, "x": 3, "y": 4, "z": 5}})");
  EXPECT_EQ(ToyRegistry::json(toy_at({0.0, 3.0, pi / 2, 0.0}), true),
            R"({"kind": "toy", "size": 1, "position": {"t": 0, "r": 3, "theta": 90, "phi": 0}})");
  EXPECT_EQ(ToyRegistry::json(falling), R"({"kind": "toy", "size": 1, "worldline": )" + w.json() + "}");
}

// The reader knows the toy's placement from its declaration alone: either
// key, one of the two, a misspelt one reported with the nearest name.
class ToyReader : public ::testing::Test {
 protected:
  ToyReader() : sandbox_({}) {}
  Toy::Params read(const std::string& table) {
    lua_State* L = sandbox_.state();
    const std::string chunk = "return " + table;
    EXPECT_EQ(luaL_loadstring(L, chunk.c_str()), 0) << lua_tostring(L, -1);
    sandbox_.call(0, 1);
    lua::TableReader t(L, -1, "toy.lua:1: toy");
    Toy::Params p;
    const Spacetime st = Minkowski{};
    read_fields(t, p, &st);
    t.finish();
    lua_pop(L, 1);
    return p;
  }
  lua::Sandbox sandbox_;
};

TEST_F(ToyReader, ReadsEitherKeyOfTheDeclaredPlacement) {
  const Toy::Params at = read("{size = 2, position = {x = 3, y = 4, z = 5}}");
  ASSERT_NE(at.placement.rest(), nullptr);
  EXPECT_EQ(*at.placement.rest(), (Vec4{0.0, 3.0, 4.0, 5.0}));
  const Toy::Params falling = read(
      "{worldline = {__kind = 'worldline', spacetime = {__kind = 'minkowski'}, start = {x = 3, y = 4, z = 5}, "
      "duration = 10}}");
  ASSERT_NE(falling.placement.worldline(), nullptr);
  EXPECT_EQ(falling.placement.worldline()->duration, 10.0);
  using test::error_of;
  EXPECT_EQ(error_of<lua::FieldError>([&] { read("{size = 2}"); }),
            "toy.lua:1: toy: give either position (held at rest) or worldline (free fall)");
  EXPECT_NE(error_of<lua::FieldError>([&] { read("{positon = {x = 3, y = 4, z = 5}}"); }).find("'position'"),
            std::string::npos);
  EXPECT_EQ(error_of<lua::FieldError>([&] { read("{position = {r = 3, theta = 90, phi = 0}}"); }),
            "toy.lua:1: toy.position: positions in minkowski are Cartesian {x, y, z}");
}

}  // namespace
}  // namespace lc
