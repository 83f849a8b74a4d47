// Which stars may lie in each patch of sky (engine/stars/star_search.hpp),
// against a search of every star in every patch: on a flat sky (tiles
// searched in their tangent planes), on a point lens's (tiles across the
// shadow's edge searched in blocks, its ring's patches spread wide), and on
// a wide field, each star that SkyPatch::may_hold and place_in_patch put in
// a patch is offered for that patch, once, and no patch is reported twice.

#include "stars/star_search.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "star_test_sky.hpp"
#include "stars/pass_constants.hpp"
#include "stars/star_image.hpp"

namespace lc {
namespace {

using test::Pinhole;

void expect_every_star_offered(const Pinhole& cam, const std::vector<SkyPoint>& rays, const char* what) {
  std::vector<PointStar> stars;
  unsigned long seed = 777;
  auto uniform = [&seed] {
    seed = seed * 6364136223846793005UL + 1442695040888963407UL;
    return static_cast<double>(seed >> 11) / 9007199254740992.0;
  };
  for (int k = 0; k < 3000; ++k) stars.push_back({unit3({uniform() - 0.5, (uniform() - 0.5) * 0.7, 1}), {1, 1, 1}});
  for (int k = 0; k < 1000; ++k) {  // and the whole sky
    const double z = 2 * uniform() - 1, ph = two_pi * uniform(), s = std::sqrt(1 - z * z);
    stars.push_back({{s * std::cos(ph), s * std::sin(ph), z}, {1, 1, 1}});
  }
  const StarField field(stars, nullptr, nullptr);
  const RayGrid grid(rays, cam.width, cam.height);
  const double cos_max = std::cos(0.3);
  StarSearch search(grid, field, cos_max);
  std::map<std::pair<int, int>, std::multiset<std::size_t>> offered;
  const PatchStars note = [&](int i, int j, const SkyPatch&, std::span<const std::size_t> s) {
    EXPECT_FALSE(offered.count({i, j})) << what << ": quad " << i << "," << j << " reported twice";
    offered[{i, j}].insert(s.begin(), s.end());
  };
  for (int tj = -1; tj < cam.height; tj += star_tile)
    for (int ti = -1; ti < cam.width; ti += star_tile) search.tile(ti, tj, note);
  long inside = 0;
  for (int j = -1; j < cam.height; ++j)
    for (int i = -1; i < cam.width; ++i) {
      const auto patch = patch_of(grid, i, j, cos_max);
      if (!patch) continue;
      for (std::size_t s = 0; s < stars.size(); ++s) {
        const Vec3& d = stars[s].direction;
        if (!patch->may_hold(d) || !place_in_patch(*patch, d)) continue;
        ++inside;
        const auto it = offered.find({i, j});
        EXPECT_TRUE(it != offered.end() && it->second.count(s) == 1)
            << what << ": star " << s << " is in quad " << i << "," << j << " and was not offered there once";
      }
    }
  EXPECT_GT(inside, 100) << what << ": too few stars in patches to test anything";
}

TEST(StarSearch, EveryStarInAPatchIsOfferedForIt) {
  const Pinhole cam{67, 41, 60};
  expect_every_star_offered(cam, cam.sky(true), "flat");
  expect_every_star_offered(cam, test::point_lens_sky(cam, 0.15), "point lens");
  const Pinhole wide{50, 30, 150};
  expect_every_star_offered(wide, wide.sky(), "150-degree field");
}

}  // namespace
}  // namespace lc
