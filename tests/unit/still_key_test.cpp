// still_key: frames that differ only by a static observer's time share a
// key; any other difference, however small, gives another.

#include <gtest/gtest.h>

#include <cmath>

#include "scene/still_key.hpp"

namespace lc {
namespace {

SceneSpec scene() {
  SceneSpec fs;
  fs.spacetime = Kerr(1.0, 0.9);
  fs.observer = StaticObserver::Params{{10.0, 30.0, 1.2, 0.3}};
  fs.objects.emplace_back(std::in_place_type<Disk::Params>);
  Sphere::Params sp;
  sp.position = Vec4{0.0, 12.0, 1.5, 0.0};
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
  EXPECT_TRUE(differs([](SceneSpec& fs) { std::get<PinholeCamera::Params>(fs.camera).roll = 1e-12; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { std::get<Disk::Params>(fs.objects[0]).sectors = 25; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.objects.erase(fs.objects.begin()); }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { std::get<CheckerSky::Params>(fs.sky).rotate = 1e-12; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.sky = StarSky::Params{2}; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { (*std::get<Sphere::Params>(fs.objects[1]).position)[1] = 12.5; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { std::get<Sphere::Params>(fs.objects[1]).colors.a[0] = 0.5f; }));
  EXPECT_TRUE(differs([](SceneSpec& fs) { fs.objects.push_back(fs.objects[1]); }));
  // A sphere at rest ignores the time in its position.
  EXPECT_FALSE(differs([](SceneSpec& fs) { (*std::get<Sphere::Params>(fs.objects[1]).position)[0] = 99.0; }));
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

}  // namespace
}  // namespace lc
