#pragma once
// The star pass's fifth stage (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them", 3 and 4): a star in a patch of sky (stars/sky_patch.hpp)
// has an image there.  Where in the patch it lies (bilinear coordinates) is
// found in the plane tangent to the sky at the patch's centre, where great
// circles are straight (SkyQuad::locate); the patch's bilinear map then
// carries it back to the quad's four image points, and interpolates the
// corners' magnifications (stars/magnification.hpp) and the light model's
// ratios, with which the star's light is seen (StarField::seen).

#include <array>
#include <cstddef>
#include <optional>

#include "core/color.hpp"
#include "core/tensor.hpp"
#include "stars/sky_patch.hpp"
#include "stars/star_field.hpp"

namespace lc {

// The bilinear coordinates (u, v) in [0, 1)^2 of the unit direction d in
// `patch`, or nullopt where d is not in it.  A direction on an edge two
// patches share is counted in one of them, the one where it is at u = 0
// (v = 0): at u or v of 1 - locate_slack and above it is not in this one.
std::optional<std::array<double, 2>> place_in_patch(const SkyPatch& patch, const Vec3& d);

// A star's image: its place (pixel units from the image's top-left corner),
// its magnification and the light model's ratios there (SeenShift's).
struct StarImage {
  double x, y, magnification, color, beaming;
};

// The image of the star at bilinear coordinates uv of `patch`
// (place_in_patch): the corners' image points, magnifications (mu[k] at
// corner k) and light ratios, weighted by the bilinear weights.
StarImage image_at(const SkyPatch& patch, const std::array<double, 2>& uv, const std::array<double, 4>& mu);

// Star `star`'s light as the frame's light model shows it at its image
// (before the magnification): linear RGB, its flux.
inline Color seen_light(const StarField& field, std::size_t star, const StarImage& image) {
  return field.seen(star, static_cast<float>(image.color), static_cast<float>(image.beaming));
}

}  // namespace lc
