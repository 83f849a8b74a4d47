#pragma once
// Streaks of point stars in a blurred frame (docs/motion_blur.md, "Point
// stars"): the star stage finds each instant's star images apart
// (stars/star_pass.hpp, find_star_images); here the images of one star at
// consecutive instants are matched, and each image is given the path the
// star takes during its instant's share of the shutter, so that its light is
// drawn along the way (draw_star_images) and the streak is continuous at any
// number of instants, instead of K dots.

#include <span>
#include <vector>

#include "core/image_wrap.hpp"
#include "stars/star_pass.hpp"

namespace lc {

// The paths of the images of K instants (`instants[k]`: instant k's images,
// the instants in the shutter's order, evenly spaced in time; every instant
// the same star field, the same width x height picture).  Inputs: the
// images, the picture's size and wrap.  Output: one path per image, in the
// same shape as `instants`.
// An image of star s at instant k and one of s at instant k + 1 belong to
// one streak when each is the other's nearest image of s (so a lensed
// star's several images keep to their own streaks) and they lie less than a
// quarter of the picture's larger side apart.  The star is taken to move
// straight between matched instants: instant k's image gets the path from
// halfway back to its match at k - 1 to halfway on to its match at k + 1;
// the first and last instants, with no instant beyond them, continue their
// one neighbour's step by half of it (the shutter's ends); an image with no
// match on a side keeps that half at its place.
std::vector<std::vector<StreakPath>> star_streaks(std::span<const std::vector<FoundStarImage>> instants, int width,
                                                  int height, const ImageWrap& wrap);

}  // namespace lc
