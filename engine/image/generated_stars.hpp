#pragma once
// A procedural night sky for the sky sphere: an equirectangular image of a
// few thousand stars of varying brightness and slight colour over a dark
// background, with a faint mottled band of glow (Milky-Way-like).
//
// The stars are a catalogue on the sphere, drawn from the seed alone, and
// each resolution is a rendering of that same catalogue: a star keeps its
// flux, so at low resolution faint stars blur into the background instead
// of crowding the picture, and a 4096 x 2048 sky shows the stars of the
// 2048 x 1024 one, sharper.
//
// Geometry (the renderer's sky convention, objects.hpp): direction
// (sin θ cos φ, sin θ sin φ, cos θ); pixel (i, j) of a W x H image has its
// centre at φ = 2π (i + ½) / W, θ = π (j + ½) / H, so row 0 is next to +z.
// Stars are Gaussian in the angle on the sphere, which widens their
// footprint by 1 / sin θ in the image near the poles and keeps them round
// on the sphere.  A 2:1 image has square texels; other shapes are allowed.

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "image/frame_image.hpp"

namespace lc {

struct Star {
  std::array<double, 3> direction;  // unit vector
  double sigma;                     // intrinsic angular size (Gaussian sigma), radians
  double peak;                      // linear peak brightness at that size
  std::array<float, 3> tint;        // colour factor, luminance about 1
};

// The seed's star catalogue: same seed, same stars.  The random draws are
// the same on every platform (std::mt19937_64 plus this file's own
// conversions, no std distributions); libm may still differ in a last bit.
std::vector<Star> starfield_catalogue(std::uint32_t seed);

// Adds `stars` to the linear RGB of `image` (any size).  Each star is
// widened by the pixel footprint (sigma_pix = half a texel in θ) with its
// flux kept.  Throws std::invalid_argument for an empty image or one
// whose rgb.size() != 3 * width * height.
void add_stars(FrameImage& image, std::span<const Star> stars);

// The sky for `seed` without its stars: the dark background and the band's
// glow (the diffuse light behind point stars, stars/star_field.hpp), linear
// RGB.  Throws std::runtime_error for a bad size, as render_starfield.
FrameImage render_sky_glow(int width, int height, std::uint32_t seed);

// The whole sky for `seed` at width x height, linear RGB, no layers.
// Throws std::runtime_error for a size that is not positive or above
// max_image_side.
FrameImage render_starfield(int width, int height, std::uint32_t seed);

// Renders the sky for `seed` and writes it as an 8-bit sRGB PNG (same rules
// as write_png: the format does not follow the extension).  Throws
// std::runtime_error naming the file on a bad size or a failed write.
void make_starfield(const std::filesystem::path& path, int width, int height, std::uint32_t seed);

}  // namespace lc
