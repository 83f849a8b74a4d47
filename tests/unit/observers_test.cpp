// Observer kinds as a registry and the observer as a path: each kind's
// eye at offset 0 is, bit for bit, what the scene builder made of the
// observer before the registry (worked out here the old way), an observer
// at rest's eye dt later is the same place at the later time, and a free
// fall's is the worldline dtau further on.

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"
#include "render/scene_builder.hpp"
#include "scene/scene_json.hpp"
#include "scene/still_key.hpp"
#include "script/constructor_docs.hpp"
#include "spacetime/kerr.hpp"

namespace lc {
namespace {

// Whether two values have the same bits (EXPECT_EQ on doubles would take
// -0 for +0).
template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Beaming by g's gravitational part alone: a light model that splits g, so
// each eye carries the ZAMO's 4-velocity.
LightParams splitting_light() {
  LightParams p;
  p.model = LightModel::shifted;
  p.color_shift = 0;
  p.kinematic = 0;
  return p;
}

// The built scene of spec in Kerr (M = 1, a = 0.9), 8 x 8 pixels.
SceneIn<Kerr> kerr_scene(const ObserverSpec& observer, ShotResources& res, bool split) {
  SceneSpec fs;
  fs.spacetime = Kerr(1.0, 0.9);
  fs.observer = observer;
  if (split) fs.light = splitting_light();
  return scene_get<Kerr>(build_scene(fs, 8, 8, res));
}

// The trace chart the builder puts Kerr in.
Kerr kerr_trace_chart() { return trace_chart(Kerr(1.0, 0.9)).get<Kerr>(); }

// The eye at offset 0 equals the SceneIn fields, bit for bit, and those
// equal `expected` (worked out the old way).
void expect_frame_eye(const SceneIn<Kerr>& sc, const Eye& expected) {
  const Eye eye = sc.observer_path.at(0.0);
  EXPECT_TRUE(same_bits(eye.event, expected.event));
  EXPECT_TRUE(same_bits(eye.scene_event, expected.scene_event));
  EXPECT_TRUE(same_bits(eye.time, expected.time));
  EXPECT_TRUE(same_bits(eye.metric, expected.metric));
  EXPECT_TRUE(same_bits(eye.frame, expected.frame));
  EXPECT_TRUE(same_bits(eye.reference, expected.reference));
  EXPECT_TRUE(same_bits(sc.eye.event, eye.event));
  EXPECT_TRUE(same_bits(sc.eye.scene_event, eye.scene_event));
  EXPECT_TRUE(same_bits(sc.eye.time, eye.time));
  EXPECT_TRUE(same_bits(sc.eye.metric, eye.metric));
  EXPECT_TRUE(same_bits(sc.eye.frame, eye.frame));
  EXPECT_TRUE(same_bits(sc.eye.reference, eye.reference));
}

// The eye of an observer at the trace event x with frame f, as the builder
// made it before the path: metric, scene time by scene_polar, and the ZAMO's
// 4-velocity where the light splits g.
Eye old_eye(const Kerr& st, const Vec4& x, const Vec4& scene, const Tetrad& f, bool split) {
  Eye e;
  e.event = x;
  e.scene_event = scene;
  e.frame = f;
  e.metric = st.metric(x);
  double r, phi;
  scene_polar(st, x, e.time, r, phi);
  if (split) e.reference = zamo_velocity(st, x);
  return e;
}

TEST(Observers, AtRestTheFramesEyeIsTodaysObserverToTheBit) {
  const Kerr st = kerr_trace_chart();
  const Vec4 pos = {10.0, 30.0, 80 * degree, 20 * degree};
  for (const bool split : {false, true}) {
    ShotResources res;
    const SceneIn<Kerr> sc = kerr_scene(StaticObserver::Params{pos}, res, split);
    expect_frame_eye(sc, old_eye(st, st.trace_from_scene(pos), pos, static_polar_tetrad(st, pos), split));
  }
  // A ZAMO inside the ergoregion, where no static observer can stand.
  const Vec4 ergo = {0.0, 1.8, 90 * degree, 0.0};
  ShotResources res;
  expect_frame_eye(kerr_scene(Zamo::Params{ergo}, res, true),
                   old_eye(st, st.trace_from_scene(ergo), ergo, zamo_polar_tetrad(st, ergo), true));
}

// A fall from r = 12 with some sideways speed, 20 M of proper time.
WorldlineSpec kerr_fall() {
  WorldlineSpec w;
  w.spacetime = Kerr(1.0, 0.9);
  w.start = {0.0, 12.0, 70 * degree, 0.0};
  w.velocity = {-0.1, 0.05, 0.25};
  w.duration = 20.0;
  w.where = "test";
  return w;
}

TEST(Observers, AFallsFramesEyeIsTodaysObserverToTheBit) {
  const Kerr st = kerr_trace_chart();
  FreeFall::Params ride;
  ride.worldline = kerr_fall();
  ride.proper_time = 3.0;
  for (const bool split : {false, true}) {
    ShotResources res;
    const SceneIn<Kerr> sc = kerr_scene(ride, res, split);
    const WorldlineEvent ev = res.worldline(ride.worldline)->at_proper_time(3.0);
    expect_frame_eye(sc, old_eye(st, ev.x, st.scene_from_trace(ev.x), ev.frame, split));
  }
}

TEST(Observers, AStaticObserversEyeLaterIsTheSamePlaceThen) {
  // In Kerr: at(dt) is the frame's place at scene time t + dt, exactly the
  // eye a frame at that time has; the place and (stationary) the frame
  // and the metric are unchanged.
  const Vec4 pos = {10.0, 30.0, 80 * degree, 20 * degree};
  ShotResources res;
  const SceneIn<Kerr> sc = kerr_scene(StaticObserver::Params{pos}, res, true);
  const Eye now = sc.observer_path.at(0.0);
  for (const double dt : {2.5, -7.0}) {
    const Eye later = sc.observer_path.at(dt);
    Vec4 then = pos;
    then[0] += dt;
    expect_frame_eye(kerr_scene(StaticObserver::Params{then}, res, true), later);
    EXPECT_TRUE(same_bits(later.scene_event, then));
    EXPECT_NEAR(later.time, now.time + dt, 1e-12);
    EXPECT_NEAR(later.event[0], now.event[0] + dt, 1e-12);
    for (int k = 1; k < 4; ++k) EXPECT_EQ(later.event[k], now.event[k]);
    for (int a = 0; a < 4; ++a)
      for (int m = 0; m < 4; ++m) {
        EXPECT_NEAR(later.frame.e[a][m], now.frame.e[a][m], 1e-14) << a << m;
        EXPECT_NEAR(later.metric[a][m], now.metric[a][m], 1e-14) << a << m;
      }
  }
}

TEST(Observers, AFallsEyeLaterIsFurtherAlongItsWorldline) {
  const Kerr st = kerr_trace_chart();
  FreeFall::Params ride;
  ride.worldline = kerr_fall();
  ride.proper_time = 3.0;
  ShotResources res;
  const SceneIn<Kerr> sc = kerr_scene(ride, res, true);
  const auto w = res.worldline(ride.worldline);
  for (const double dtau : {0.25, 1.5, -2.0}) {
    const Eye e = sc.observer_path.at(dtau);
    const WorldlineEvent ev = w->at_proper_time(3.0 + dtau);
    EXPECT_TRUE(same_bits(e.event, ev.x)) << dtau;
    EXPECT_TRUE(same_bits(e.frame, ev.frame)) << dtau;
    EXPECT_TRUE(same_bits(e.scene_event, st.scene_from_trace(ev.x))) << dtau;
    EXPECT_TRUE(same_bits(e.metric, st.metric(ev.x))) << dtau;
    EXPECT_TRUE(same_bits(e.reference, zamo_velocity(st, ev.x))) << dtau;
    EXPECT_NEAR(e.time, w->scene_time(ev.x), 1e-9) << dtau;
  }
  // It moves: later it is elsewhere.
  EXPECT_NE(sc.observer_path.at(1.0).event[1], sc.observer_path.at(0.0).event[1]);
}

TEST(Observers, APathNotBuiltHasNoEye) {
  EXPECT_THROW(ObserverPath<Kerr>().at(0.0), std::logic_error);
}

TEST(Observers, TheRegistryGivesNamesJsonKeysAndTheReference) {
  // Every kind has a name of its own (the list itself is the registry's:
  // nothing here counts it).
  for (std::size_t i = 0; i < ObserverRegistry::names.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(ObserverRegistry::names[i], ObserverRegistry::names[j]);
  EXPECT_EQ(ObserverRegistry::name(ObserverSpec{Zamo::Params{}}), "zamo");
  SceneSpec fs;
  fs.spacetime = Kerr(1.0, 0.9);
  fs.observer = StaticObserver::Params{{5.0, 30.0, 90 * degree, 0.0}};
  const std::string json = to_json(fs, 0);
  EXPECT_NE(json.find("\"observer\": {\"kind\": \"static_observer\", \"position\": {\"t\": 5, \"r\": 30, \"theta\": 90, "
                      "\"phi\": 0}}"),
            std::string::npos)
      << json;
  // The time is what an observer at rest's key leaves out; the kind is in it.
  SceneSpec later = fs;
  EXPECT_EQ(set_scene_time(later.observer, 99.0), "");
  EXPECT_EQ(std::get<StaticObserver::Params>(later.observer).position[0], 99.0);
  EXPECT_EQ(still_key(later), still_key(fs));
  later.observer = Zamo::Params{{5.0, 30.0, 90 * degree, 0.0}};
  EXPECT_NE(still_key(later), still_key(fs));
  // A fall keeps its own clock.
  later.observer = FreeFall::Params{};
  EXPECT_EQ(set_scene_time(later.observer, 99.0),
            "a free-falling observer's time comes from its worldline; remove 'time'");
  EXPECT_EQ(still_key(later), "");
  // Every kind is in the reference, with what it reads by hand.
  const std::string ref = constructor_tables();
  for (const auto name : ObserverRegistry::names)
    EXPECT_NE(ref.find(fmt::format("#### `lc.{}{{...}}`", name)), std::string::npos) << name;
  EXPECT_NE(ref.find("| `proper_time` | required |"), std::string::npos);
  EXPECT_NE(ref.find(FreeFall::Params::extra_doc), std::string::npos);
}

}  // namespace
}  // namespace lc
