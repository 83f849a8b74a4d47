// Stars as points on a finished frame (engine/stars/star_pass.hpp), in flat
// space where the sky a pixel sees is its own solid angle: a star's light
// lands within the 2 x 2 pixels around it at any field of view, its total
// (radiance times each pixel's solid angle) is conserved to 1% as it pans
// across pixels in tenth-pixel steps (landing exactly on pixel centres'
// lines too: counted once), and a star behind an object (a pixel
// whose ray did not reach the sky) is not drawn.

#include "stars/star_pass.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "stars/sky_quad.hpp"

namespace lc {
namespace {

Vec3 unit(Vec3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

// A pinhole camera looking along +z: the direction through image point
// (x, y) in pixels (centres at i + 0.5), horizontal field fov.
struct Pinhole {
  int width, height;
  double fov;
  Vec3 at(double x, double y) const {
    const double t = std::tan(0.5 * fov * degree);
    return unit({(2 * x / width - 1) * t, (2 * y - height) / width * t, 1});
  }
  SkyDirections sky() const {
    SkyDirections s{width, height, {}, {}};
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        s.direction.push_back(at(i + 0.5, j + 0.5));
        s.reached.push_back(1);
      }
    return s;
  }
  // The solid angle of pixel (i, j): its corners' spherical quad.
  double pixel_solid_angle(int i, int j) const {
    return SkyQuad{{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}}.area();
  }
};

struct Seen {
  double total = 0.0;  // sum of radiance x pixel solid angle (first channel)
  int lit = 0, min_i = 1 << 30, max_i = -1, min_j = 1 << 30, max_j = -1;
};

Seen render(const Pinhole& cam, const SkyDirections& sky, const Vec3& star) {
  std::vector<PointStar> stars = {{star, {1.0f, 1.0f, 1.0f}}};
  const StarBins bins({star}, 1 * degree);
  std::vector<Color> image(static_cast<std::size_t>(cam.width * cam.height), Color{0, 0, 0});
  StarPassOptions o;
  o.pixel_solid_angle = cam.pixel_solid_angle(cam.width / 2, cam.height / 2);
  add_point_stars(sky, stars, bins, o, image);
  Seen s;
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const float r = image[static_cast<std::size_t>(j * cam.width + i)][0];
      if (r <= 0) continue;
      s.total += r * cam.pixel_solid_angle(i, j);
      ++s.lit;
      s.min_i = std::min(s.min_i, i), s.max_i = std::max(s.max_i, i);
      s.min_j = std::min(s.min_j, j), s.max_j = std::max(s.max_j, j);
    }
  return s;
}

TEST(StarPass, AStarIsSharpAndItsLightConservedAsItPans) {
  for (const double fov : {1.0, 20.0, 60.0, 120.0}) {
    const Pinhole cam{64, 36, fov};
    const SkyDirections sky = cam.sky();
    double lo = 1e300, hi = 0;
    for (int step = 0; step <= 20; ++step) {
      const double x = 30.3 + 0.1 * step, y = 17.45 + 0.037 * step;
      const Seen s = render(cam, sky, cam.at(x, y));
      EXPECT_LE(s.max_i - s.min_i, 1) << "fov " << fov << " x " << x;  // within the 2 x 2 pixel filter
      EXPECT_LE(s.max_j - s.min_j, 1) << "fov " << fov << " y " << y;
      lo = std::min(lo, s.total), hi = std::max(hi, s.total);
    }
    EXPECT_NEAR(lo, 1.0, 0.01) << "fov " << fov;
    EXPECT_NEAR(hi, 1.0, 0.01) << "fov " << fov;
  }
}

TEST(StarPass, StarsAtTheImagesEdgeAndBehindObjects) {
  const Pinhole cam{32, 18, 40};
  SkyDirections sky = cam.sky();
  // At the outermost pixel centres, all of a star's light is in the image;
  // between them and the edge it is still drawn (from directions
  // extrapolated beyond it), the pixel filter's share outside it lost: 0.7
  // of it at 0.3 pixels from the edge.  Tolerance 2%: the extrapolated
  // directions make the outer patches ~1% off the true pixels' solid angle.
  EXPECT_NEAR(render(cam, sky, cam.at(0.5, 9.0)).total, 1.0, 0.02);
  EXPECT_NEAR(render(cam, sky, cam.at(0.2, 9.0)).total, 0.7, 0.02);
  // Outside the image: nothing.
  EXPECT_EQ(render(cam, sky, cam.at(-3.0, 9.0)).lit, 0);
  // Pixel (10, 5) met an object: a star beside its centre is hidden.
  sky.reached[5 * 32 + 10] = 0;
  EXPECT_EQ(render(cam, sky, cam.at(10.6, 5.6)).lit, 0);
}

}  // namespace
}  // namespace lc
