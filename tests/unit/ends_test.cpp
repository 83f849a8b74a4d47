// The ends of a ray as a seam (spacetime/ends.hpp): the one infinity of a
// Cartesian-like chart, the registered spacetimes' lists, and a spacetime
// with two far ends — the Ellis wormhole — traced through the renderer's
// own trace and shade stages: rays through the throat reach the other
// infinity and see its sky, the rest see this side's, and an observer
// beyond the throat sees the two skies the other way round.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/constants.hpp"
#include "eye/tetrad.hpp"
#include "spacetime/spacetime.hpp"
#include "wormhole_scene.hpp"

namespace lc {
namespace {

TEST(Ends, CartesianInfinityIsReachedBeyondTheEscapeRadiusMovingOut) {
  const FlightRadii radii{10.0 * 10.0, 20.0 * 20.0};
  const std::array<double, 8> near = {0, 5, 0, 0}, free = {0, 15, 0, 0}, far = {0, 0, 0, 25};
  const std::array<double, 8> out_x = {0, 1, 0, 0}, in_x = {0, -1, 0, 0}, out_z = {0, 0, 0, 1};
  const auto at = [&](const std::array<double, 8>& y, const std::array<double, 8>& dy) {
    return CartesianInfinity::flight(StateComponents{&y}, StateComponents{&dy}, radii);
  };
  EXPECT_FALSE(at(near, out_x).free);
  EXPECT_FALSE(at(near, out_x).escaped);
  EXPECT_TRUE(at(free, out_x).free);
  EXPECT_FALSE(at(free, out_x).escaped);
  EXPECT_FALSE(at(free, in_x).free);
  EXPECT_TRUE(at(far, out_z).escaped);
  EXPECT_EQ(at(far, out_z).end, 0);
  EXPECT_FALSE(at(far, in_x).escaped);  // moving in (x . dx = 0 here: not out)
}

// Every registered spacetime names its ends: the far end where the
// scene's sky is first (infinity, or a cosmological horizon where there is
// no infinity to reach), each end's name its kind's, then its horizons,
// whose index the hit records of captured rays carry.
TEST(Ends, RegisteredSpacetimesListTheirSkysEndFirst) {
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    EXPECT_TRUE(is_far(S::ends[0].kind)) << S::name;
    for (const SpacetimeEnd& e : S::ends)
      if (e.kind != EndKind::infinity) EXPECT_EQ(e.name, to_string(e.kind)) << S::name;
  });
  EXPECT_EQ(end_index<Kerr>(EndKind::horizon), 1u);
  EXPECT_EQ(end_index<Dihole>(EndKind::horizon), 1u);
  EXPECT_EQ(end_index<Kottler>(EndKind::horizon), 1u);
  EXPECT_EQ(end_index<Kottler>(EndKind::cosmological_horizon), 0u);
  EXPECT_EQ(end_index<Minkowski>(EndKind::horizon), Minkowski::ends.size());
  EXPECT_EQ(end_index<EllisWormhole>(EndKind::horizon), EllisWormhole::ends.size());  // none: no ray is captured
  EXPECT_EQ(EllisWormhole::ends[1].name, "other_side");
  EXPECT_EQ(to_string(EndKind::cosmological_horizon), "cosmological horizon");
}

// A frame in the Ellis wormhole (b = 1) seen by a static observer at
// proper distance l; escape at |l| = 60, where the rest of the bending,
// ~b^2/l^2, is below 3e-4.
SceneIn<EllisWormhole> wormhole_scene(double l, ShotResources& res) {
  return test::wormhole_scene(EllisWormhole({1.0}), l, res, 60.0);
}
using test::traced;

// A two-ended spacetime through the renderer's own trace and shade stages:
// rays into the throat from l = 10 reach end 1 and see its sky, with no sky
// point (point stars are drawn on the scene's own sky), the rest see this
// side's.  (Where the edge lies is morris_thorne_test.cpp's.)
TEST(Ends, RaysThroughTheThroatSeeTheOtherSky) {
  ShotResources res;
  const SceneIn<EllisWormhole> sc = wormhole_scene(10.0, res);
  const std::vector<RaySample> s = traced(sc, {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
  EXPECT_EQ(s[0].hit.kind, HitKind::sky);
  EXPECT_EQ(s[0].hit.reason, StopReason::escaped);
  EXPECT_EQ(s[0].hit.spacetime_end, 1);
  EXPECT_NEAR(s[0].color[0], 0.75f, 1e-6f);
  EXPECT_LT(s[0].sky.theta, 0.0) << "no point stars across the throat";
  EXPECT_EQ(s[1].hit.spacetime_end, 0);
  EXPECT_NEAR(s[1].color[0], 0.25f, 1e-6f);
  EXPECT_GE(s[1].sky.theta, 0.0);
}

// Beyond the throat (l = -2.4) an observer may stand: it sees the first
// end's sky through the throat (+e_l, towards larger l) and the other end's
// sky behind it.
TEST(Ends, AnObserverBeyondTheThroatSeesTheSkiesTheOtherWayRound) {
  ShotResources res;
  const SceneIn<EllisWormhole> sc = wormhole_scene(-2.4, res);
  EXPECT_TRUE(sc.spacetime.why_no_observer(sc.eye.event).empty());
  const std::vector<RaySample> s = traced(sc, {{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}});
  EXPECT_EQ(s[0].hit.spacetime_end, 0);
  EXPECT_NEAR(s[0].color[0], 0.25f, 1e-6f);
  EXPECT_EQ(s[1].hit.spacetime_end, 1);
  EXPECT_NEAR(s[1].color[0], 0.75f, 1e-6f);
}

// A scene's one sky serves every far end that has none of its own.
TEST(Ends, AnEndWithoutASkyOfItsOwnSeesTheScenesSky) {
  ShotResources res;
  SceneIn<EllisWormhole> sc = wormhole_scene(10.0, res);
  sc.end_skies.clear();
  const RaySample s = traced(sc, {{-1.0, 0.0, 0.0}})[0];
  EXPECT_EQ(s.hit.spacetime_end, 1);
  EXPECT_NEAR(s.color[0], 0.25f, 1e-6f);
}

}  // namespace
}  // namespace lc
