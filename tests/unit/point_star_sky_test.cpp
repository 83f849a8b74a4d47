// lc.starfield{}'s stars (engine/sky/point_star_sky.hpp, engine/stars/
// star_field.hpp): a blackbody star seen through a frequency ratio g is the
// blackbody at g T (its colour and its luminance Y(gT) / Y(T)), beaming
// alone scales it by g^4, a star without a temperature is shifted as a
// texture; KStars' catalogue (a file typed here, named by
// LIGHTCONE_STAR_CATALOGUE) gives each star its place (right ascension and
// declination on the equatorial sphere, the pole on +z) and its light
// (10^(-0.4 V) times the V = 0 star's, at its B - V's temperature); the
// generated field keeps the light its texture rendering gives each star;
// `faintest` leaves the fainter stars out and `rotate` turns them as it
// turns textures.

#include "sky/point_star_sky.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "assets/shot_resources.hpp"
#include "core/constants.hpp"
#include "image/generated_stars.hpp"
#include "light/light.hpp"
#include "scratch_dir.hpp"
#include "sky/texture_sky.hpp"
#include "stars/star_catalogue.hpp"

namespace lc {
namespace {

double luminance(const Color& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

TEST(PointStarSky, AShiftedBlackbodyStarIsTheBlackbodyAtGT) {
  ShotResources res;
  auto colors = res.blackbody_colors(5800.0);
  const Color sun = (*colors)(5800.0);
  const double k = 2.0 / luminance(sun);  // luminance 2
  const StarField field({{{0, 0, 1}, {float(k * sun[0]), float(k * sun[1]), float(k * sun[2])}, 5800.0},
                         {{0, 1, 0}, {0.2f, 0.5f, 0.9f}, 0.0}},
                        colors, res.spectral_shift());
  // Geometric light: as it is.
  EXPECT_EQ(field.seen(0, 1.0f, 1.0f), field.stars()[0].flux);
  // Shifted by g = 1.3: the blackbody at 7540 K, luminance 2 Y(7540) / Y(5800).
  const Color seen = field.seen(0, 1.3f, 1.3f), hot = (*colors)(1.3 * 5800.0);
  EXPECT_NEAR(luminance(seen), 2 * luminance(hot) / luminance(sun), 1e-4 * luminance(seen));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c] / luminance(seen), hot[c] / luminance(hot), 1e-4);
  // Beaming alone: g^4 times the light, its colour kept.
  const Color beamed = field.seen(0, 1.0f, 1.3f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(beamed[c], std::pow(1.3, 4) * field.stars()[0].flux[c], 1e-4 * beamed[c]);
  // The colour shift alone: the blackbody at g T with g^-4 of its light.
  const Color shifted = field.seen(0, 1.3f, 1.0f);
  EXPECT_NEAR(luminance(shifted), luminance(seen) / std::pow(1.3, 4), 1e-4 * luminance(shifted));
  // No temperature: shifted as a texture's colour.
  const Color texture = SeenShift{double(1.3f), double(1.3f), res.spectral_shift().get()}.texture(field.stars()[1].flux);
  const Color star = field.seen(1, 1.3f, 1.3f);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(star[c], texture[c]);
}

TEST(PointStarSky, KStarsStarsSitWhereTheCatalogueSaysWithTheirMagnitudesLight) {
  test::ScratchDir dir;
  const auto file = dir / "stars.dat";
  // Sirius (V -1.44, B-V 0.01), Vega (V 0.03, B-V -0.00), and a V 8.50 star.
  std::ofstream(file) << "# typed for the test\n"
                      << "064508.92 -164258.0 -000546.0-001223.100379.2 -1.4400.01A0 1, alp CMa, Sirius\n"
                      << "183656.34 +384701.3 000201.7 000286.9 00128.9 00.03-0.00A0 1, alp Lyr, Vega\n"
                      << "120000.00 +000000.0 000000.0 000000.0 00000.0 08.5000.50G0 1\n";
  ::setenv("LIGHTCONE_STAR_CATALOGUE", file.c_str(), 1);
  ShotResources res;
  PointStarSky::Params p;
  p.catalogue = StarCatalogue::kstars;
  const auto stars = PointStarSky::stars(p, res);  // faintest 8: two stars
  p.faintest = 9;
  const auto more = PointStarSky::stars(p, res);
  p.faintest = 8;
  p.rotate = 30;
  const auto turned = PointStarSky::stars(p, res);
  ::unsetenv("LIGHTCONE_STAR_CATALOGUE");
  ASSERT_EQ(stars.field->stars().size(), 2u);
  EXPECT_EQ(more.field->stars().size(), 3u);
  const PointStar& sirius = stars.field->stars()[0];
  const double ra = 15 * (6 + 45 / 60.0 + 8.92 / 3600) * degree, dec = -(16 + 42 / 60.0 + 58.0 / 3600) * degree;
  EXPECT_NEAR(sirius.direction[0], std::cos(dec) * std::cos(ra), 1e-12);
  EXPECT_NEAR(sirius.direction[1], std::cos(dec) * std::sin(ra), 1e-12);
  EXPECT_NEAR(sirius.direction[2], std::sin(dec), 1e-12);
  EXPECT_NEAR(sirius.temperature, star_temperature(0.01), 1e-9);
  EXPECT_NEAR(luminance(sirius.flux), star_flux_v0 * std::pow(10, 0.4 * 1.44), 1e-4 * luminance(sirius.flux));
  const PointStar& vega = stars.field->stars()[1];
  EXPECT_NEAR(luminance(sirius.flux) / luminance(vega.flux), std::pow(10, 0.4 * 1.47), 1e-3);
  // Turned as a texture is: what was at longitude L is at L - rotate.
  const double phi = std::atan2(sirius.direction[1], sirius.direction[0]);
  const Vec3& t = turned.field->stars()[0].direction;
  EXPECT_NEAR(std::remainder(std::atan2(t[1], t[0]) - (phi - 30 * degree), two_pi), 0.0, 1e-12);
  EXPECT_NEAR(rotated_longitude(std::atan2(t[1], t[0]), 30), phi < 0 ? phi + two_pi : phi, 1e-12);
}

TEST(PointStarSky, TheGeneratedStarsKeepTheirTextureLight) {
  ShotResources res;
  PointStarSky::Params p;
  p.faintest = 12;  // all of them
  const auto stars = PointStarSky::stars(p, res);
  const auto catalogue = starfield_catalogue(p.seed);
  ASSERT_EQ(stars.field->stars().size(), catalogue.size());
  for (std::size_t k = 0; k < catalogue.size(); k += 97) {
    const Star& s = catalogue[k];
    const double flux = two_pi * s.sigma * s.sigma * s.peak;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(stars.field->stars()[k].flux[c], flux * s.tint[static_cast<std::size_t>(c)], 1e-6 * flux);
  }
  p.faintest = 4;
  EXPECT_LT(PointStarSky::stars(p, res).field->stars().size(), catalogue.size() / 10);
}

}  // namespace
}  // namespace lc
