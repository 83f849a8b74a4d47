// Stars binned on the sky (engine/stars/star_bins.hpp) against brute
// force: every star within a cap's radius is visited, once, for caps
// anywhere (at the poles, across phi = 0, large and tiny), and the visit
// stays local (a small cap does not visit most of the sky).

#include "stars/star_bins.hpp"
#include "stars/star_field.hpp"

#include <algorithm>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "core/constants.hpp"

namespace lc {
namespace {

Vec3 random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), p(0.0, two_pi);
  const double z = u(rng), phi = p(rng), s = std::sqrt(1 - z * z);
  return {s * std::cos(phi), s * std::sin(phi), z};
}

double angle(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], -1.0, 1.0));
}

// A star field refuses a star of NaN direction or light before binning it
// (the bins index cells by its angles: a NaN one crashed the render).
TEST(StarBins, TheStarFieldRefusesANanStarBeforeBinningIt) {
  const double nan = std::nan("");
  for (const PointStar& bad : {PointStar{{nan, 0.0, 1.0}, {1.0f, 1.0f, 1.0f}, 0.0},
                               PointStar{{0.0, 0.0, 1.0}, {1.0f, static_cast<float>(nan), 1.0f}, 0.0},
                               PointStar{{0.0, 0.0, 2.0}, {1.0f, 1.0f, 1.0f}, 0.0}}) {
    try {
      StarField({PointStar{{1.0, 0.0, 0.0}, {1.0f, 1.0f, 1.0f}, 0.0}, bad}, nullptr, nullptr);
      ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("star field: star 2 of 2 has the"), std::string::npos) << e.what();
    }
  }
}

TEST(StarBins, EveryStarInACapIsVisitedOnce) {
  std::mt19937_64 rng(11);
  std::vector<Vec3> stars;
  for (int k = 0; k < 20000; ++k) stars.push_back(random_direction(rng));
  const StarBins bins(stars, 2 * degree);
  std::vector<std::pair<Vec3, double>> caps = {{{0, 0, 1}, 3 * degree},  {{0, 0, -1}, 0.5 * degree},
                                               {{1, 0, 0}, 1 * degree},  {{0.9999, -0.0141, 0}, 0.2 * degree},
                                               {{0, 0.6, 0.8}, 40 * degree}, {{0.2, 0.1, 0.97}, 179 * degree}};
  for (int k = 0; k < 200; ++k) {
    std::uniform_real_distribution<double> r(1e-4, 0.2);
    caps.push_back({random_direction(rng), r(rng)});
  }
  for (const auto& [centre0, radius] : caps) {
    const double n = std::sqrt(centre0[0] * centre0[0] + centre0[1] * centre0[1] + centre0[2] * centre0[2]);
    const Vec3 centre = {centre0[0] / n, centre0[1] / n, centre0[2] / n};
    std::multiset<std::size_t> seen;
    bins.near(centre, radius, [&](std::size_t k) { seen.insert(k); });
    for (std::size_t k = 0; k < stars.size(); ++k) {
      EXPECT_LE(seen.count(k), 1u) << "star " << k << " visited twice";
      if (angle(stars[k], centre) <= radius) {
        EXPECT_EQ(seen.count(k), 1u) << "star " << k << " at " << angle(stars[k], centre) << " of a cap of " << radius;
      }
    }
    // Local: a cap of 0.2 rad holds ~1% of the sky; the cells visited
    // hold well under a quarter of it.
    if (radius <= 0.2) EXPECT_LT(seen.size(), stars.size() / 4) << "radius " << radius;
  }
}

}  // namespace
}  // namespace lc
