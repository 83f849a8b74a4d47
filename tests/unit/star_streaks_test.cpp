// stars/star_streaks: which images of consecutive instants are one star's
// streak, and the path each image's light is drawn along.  Positions are
// exact binary fractions, so the paths are compared exactly.

#include "stars/star_streaks.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

lc::FoundStarImage image(std::size_t star, double x, double y) { return {star, x, y, 1.0, {1, 1, 1}}; }

using Path = std::array<double, 2>;

}  // namespace

// A star moving 4 px an instant to the right: each instant's image goes
// from halfway back to halfway on, and the first and last half a step
// beyond, so the streak covers the whole shutter's travel (16 px for 4).
TEST(StarStreaks, AStarMovingSteadilyIsDrawnAlongItsWholeTravel) {
  std::vector<std::vector<lc::FoundStarImage>> k;
  for (int i = 0; i < 4; ++i) k.push_back({image(7, 10.0 + 4 * i, 20.0)});
  const auto paths = lc::star_streaks(k, 64, 64, {});
  ASSERT_EQ(paths.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(paths[i].size(), 1u);
    EXPECT_EQ(paths[i][0].before, (Path{8.0 + 4 * i, 20.0})) << i;
    EXPECT_EQ(paths[i][0].after, (Path{12.0 + 4 * i, 20.0})) << i;
  }
}

// Two images of one star (a lensed pair) each keep to their own streak, and
// another star's image is never joined to them.
TEST(StarStreaks, ALensedStarsImagesKeepToTheirOwnStreaks) {
  const std::vector<std::vector<lc::FoundStarImage>> k = {
      {image(1, 10, 10), image(1, 40, 10), image(2, 12, 10)},
      {image(2, 12, 10), image(1, 42, 10), image(1, 11, 10)},
  };
  const auto paths = lc::star_streaks(k, 64, 64, {});
  EXPECT_EQ(paths[0][0].after, (Path{10.5, 10}));  // star 1's first image, on to (11, 10)
  EXPECT_EQ(paths[0][1].after, (Path{41, 10}));    // its second, on to (42, 10)
  EXPECT_EQ(paths[0][2].after, (Path{12, 10}));    // star 2 stands still
  EXPECT_EQ(paths[1][1].before, (Path{41, 10}));
  EXPECT_EQ(paths[1][2].before, (Path{10.5, 10}));
}

// No streak where the images are not each other's nearest, where they lie a
// quarter of the picture apart or more, or where the star has no image at
// the next instant: those halves stay at the image's place.
TEST(StarStreaks, ImagesThatAreNotOneStarsStepStayPoints) {
  const std::vector<std::vector<lc::FoundStarImage>> far = {{image(3, 0, 0)}, {image(3, 16, 0)}};
  auto paths = lc::star_streaks(far, 64, 64, {});
  EXPECT_EQ(paths[0][0].after, (Path{0, 0}));
  EXPECT_EQ(paths[1][0].before, (Path{16, 0}));
  // Two images at instant 0 both nearest to one at instant 1: only the
  // nearer is its match.
  const std::vector<std::vector<lc::FoundStarImage>> crowd = {{image(3, 10, 10), image(3, 13, 10)},
                                                              {image(3, 14, 10)}};
  paths = lc::star_streaks(crowd, 64, 64, {});
  EXPECT_EQ(paths[0][0].after, (Path{10, 10}));
  EXPECT_EQ(paths[0][1].after, (Path{13.5, 10}));
  const std::vector<std::vector<lc::FoundStarImage>> gone = {{image(3, 10, 10)}, {image(4, 10, 10)}};
  paths = lc::star_streaks(gone, 64, 64, {});
  EXPECT_EQ(paths[0][0].before, (Path{10, 10}));
  EXPECT_EQ(paths[0][0].after, (Path{10, 10}));
  // One instant: points.
  paths = lc::star_streaks(std::vector<std::vector<lc::FoundStarImage>>{{image(3, 5, 5)}}, 64, 64, {});
  EXPECT_EQ(paths[0][0].before, (Path{5, 5}));
  EXPECT_EQ(paths[0][0].after, (Path{5, 5}));
}

// On a picture wrapped in columns (a whole sphere), a star crossing the seam
// steps the short way round.
TEST(StarStreaks, AStarCrossingAWrappedSeamStepsTheShortWay) {
  const std::vector<std::vector<lc::FoundStarImage>> k = {{image(5, 63, 8)}, {image(5, 1, 8)}};
  const auto paths = lc::star_streaks(k, 64, 32, lc::ImageWrap{true, false});
  EXPECT_EQ(paths[0][0].after, (Path{64, 8}));
  EXPECT_EQ(paths[1][0].before, (Path{0, 8}));
  EXPECT_EQ(paths[0][0].before, (Path{62, 8}));  // the shutter's start: half a step back
}
