#include "image/generated_stars.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"
#include "image/image_io.hpp"

namespace lc {
namespace {

using Dir = std::array<double, 3>;

// The look of the sky, tuned by eye on the 2048 x 1024 rendering.
constexpr double reference_pitch = pi / 1024.0;  // texel size of that rendering, radians
constexpr int field_stars = 4500;                // uniform over the sphere
constexpr int band_stars = 2500;                 // concentrated towards the band
constexpr double faintest_peak = 0.03;           // linear, at the star's intrinsic size
constexpr double brightest_peak = 6.0;
// N(brighter than P) ∝ P^-1.5: stars spread uniformly through space.
constexpr double brightness_slope = 1.5;
constexpr double band_tilt = 60.0 * degree;          // band pole from +z, so the band is not the equator
constexpr double band_star_latitude = 7.0 * degree;  // Gaussian sigma of band stars' latitude
constexpr double band_glow_width = 8.0 * degree;
constexpr double band_glow = 0.008;  // linear, at the centre line before mottling; sRGB code ~ 23
constexpr double bulge_glow = 0.008;
constexpr double bulge_width = 15.0 * degree;
constexpr std::array<float, 3> background = {0.0006f, 0.0008f, 0.0013f};  // sRGB codes ~ 2, 3, 4
constexpr std::array<double, 3> glow_colour = {1.0, 0.92, 0.8};
// Where a star's Gaussian is cut off: far below one 8-bit sRGB step near
// black (~3e-4 linear), so no star shows the edge of its footprint.
constexpr double star_cutoff = 1e-5;

// Independent random streams of one seed, so the band's orientation does not
// depend on how many stars are drawn and vice versa.
enum Stream : std::uint32_t { band_stream = 1, star_stream = 2, noise_stream = 3 };

// Deterministic random draws: std::mt19937_64's sequence is fixed by the
// standard, the std distributions are not, so the conversions are here.
class Draw {
 public:
  // One stream of `seed`.
  Draw(std::uint32_t seed, Stream stream) {
    std::seed_seq seq{seed, static_cast<std::uint32_t>(stream)};
    engine_.seed(seq);
  }
  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Standard normal (Box–Muller; 1 - u keeps the logarithm finite).
  double normal() { return std::sqrt(-2.0 * std::log(1.0 - uniform())) * std::cos(two_pi * uniform()); }
  // Uniform direction on the unit sphere.
  Dir direction() {
    const double z = 2.0 * uniform() - 1.0, phi = two_pi * uniform();
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

 private:
  std::mt19937_64 engine_;
};

double dot(const Dir& a, const Dir& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The band: a great circle with pole `pole`, in-plane axes e1, e2, and a
// brighter bulge around `centre` (in the plane).
struct Band {
  Dir pole, e1, e2, centre;
};

// The band of `seed`: pole tilted by band_tilt at a random longitude, bulge
// at a random point of the circle.
Band band_of(std::uint32_t seed) {
  Draw draw(seed, band_stream);
  const double node = two_pi * draw.uniform(), l0 = two_pi * draw.uniform();
  Band b;
  b.pole = {std::sin(band_tilt) * std::cos(node), std::sin(band_tilt) * std::sin(node), std::cos(band_tilt)};
  b.e1 = {-std::sin(node), std::cos(node), 0.0};  // z × pole, normalised
  b.e2 = {b.pole[1] * b.e1[2] - b.pole[2] * b.e1[1], b.pole[2] * b.e1[0] - b.pole[0] * b.e1[2],
          b.pole[0] * b.e1[1] - b.pole[1] * b.e1[0]};
  for (int k = 0; k < 3; ++k) b.centre[k] = std::cos(l0) * b.e1[k] + std::sin(l0) * b.e2[k];
  return b;
}

// Relative Planck radiance at three wavelengths standing in for R, G, B
// (610, 550, 465 nm): a cheap colour temperature, fine for a slight tint.
std::array<double, 3> planck_rgb(double kelvin) {
  constexpr double hc_over_k = 1.438777e-2;  // metre kelvin
  constexpr std::array<double, 3> wavelength = {610e-9, 550e-9, 465e-9};
  std::array<double, 3> v{};
  for (int c = 0; c < 3; ++c)
    v[c] = 1.0 / (std::pow(wavelength[c], 5) * std::expm1(hc_over_k / (wavelength[c] * kelvin)));
  return v;
}

// Colour factor of a star at `kelvin`: white at 6500 K, luminance 1, and
// only 60% of the black body's saturation (stars look nearly white to the
// eye and on film).
std::array<float, 3> star_tint(double kelvin) {
  const std::array<double, 3> v = planck_rgb(kelvin), w = planck_rgb(6500.0);
  std::array<double, 3> c{};
  for (int k = 0; k < 3; ++k) c[k] = v[k] / w[k];
  const double luminance = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  std::array<float, 3> t{};
  for (int k = 0; k < 3; ++k) t[k] = static_cast<float>(1.0 + 0.6 * (c[k] / luminance - 1.0));
  return t;
}

// One star in direction `dir`: Pareto brightness, size growing with
// brightness (bright stars bloom on film), temperature log-uniform in
// 3000..12000 K.
Star make_star(Draw& draw, const Dir& dir) {
  const double peak = std::min(brightest_peak, faintest_peak * std::pow(1.0 - draw.uniform(), -1.0 / brightness_slope));
  const double sigma = reference_pitch * (0.45 + 0.22 * std::log10(peak / faintest_peak));
  const double kelvin = 3000.0 * std::pow(4.0, draw.uniform());
  return {dir, sigma, peak, star_tint(kelvin)};
}

// Smooth value noise on R^3 in [0, 1): random values on the integer
// lattice, trilinear with smoothstep weights, hashed through a permutation.
class ValueNoise {
 public:
  // Tables drawn from `seed`'s noise stream.
  explicit ValueNoise(std::uint32_t seed) {
    Draw draw(seed, noise_stream);
    for (double& v : values_) v = draw.uniform();
    for (int i = 0; i < 256; ++i) perm_[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
    for (std::size_t i = 255; i > 0; --i)  // Fisher–Yates
      std::swap(perm_[i], perm_[static_cast<std::size_t>(draw.uniform() * static_cast<double>(i + 1))]);
  }

  // Noise at point p.
  double at(double x, double y, double z) const {
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
    const double sx = smooth(x - fx), sy = smooth(y - fy), sz = smooth(z - fz);
    double r = 0.0;
    for (int c = 0; c < 8; ++c) {
      const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
      const double w = (dx ? sx : 1.0 - sx) * (dy ? sy : 1.0 - sy) * (dz ? sz : 1.0 - sz);
      r += w * lattice(ix + dx, iy + dy, iz + dz);
    }
    return r;
  }

  // Four octaves on the unit sphere (3D, so no seam at φ = 0 and no pinch
  // at the poles), in [0, 1).
  double fbm(const Dir& d, double frequency) const {
    double sum = 0.0, amplitude = 1.0, norm = 0.0;
    for (int o = 0; o < 4; ++o) {
      const double shift = 17.3 * o;  // decorrelates the octaves' lattices
      sum += amplitude * at(d[0] * frequency + shift, d[1] * frequency - shift, d[2] * frequency + 0.5 * shift);
      norm += amplitude;
      amplitude *= 0.5;
      frequency *= 2.0;
    }
    return sum / norm;
  }

 private:
  static double smooth(double t) { return t * t * (3.0 - 2.0 * t); }
  double lattice(int i, int j, int k) const {
    const std::size_t h = perm_[(perm_[(perm_[static_cast<std::size_t>(i & 255)] + j) & 255] + k) & 255];
    return values_[h];
  }
  std::array<double, 256> values_{};
  std::array<std::uint8_t, 256> perm_{};
};

// sin/cos of every row's θ and column's φ: directions of pixel centres.
struct PixelDirections {
  std::vector<double> sin_theta, cos_theta, cos_phi, sin_phi;
  PixelDirections(int width, int height)
      : sin_theta(static_cast<std::size_t>(height)),
        cos_theta(static_cast<std::size_t>(height)),
        cos_phi(static_cast<std::size_t>(width)),
        sin_phi(static_cast<std::size_t>(width)) {
    for (int j = 0; j < height; ++j) {
      const double theta = pi * (j + 0.5) / height;
      sin_theta[static_cast<std::size_t>(j)] = std::sin(theta);
      cos_theta[static_cast<std::size_t>(j)] = std::cos(theta);
    }
    for (int i = 0; i < width; ++i) {
      const double phi = two_pi * (i + 0.5) / width;
      cos_phi[static_cast<std::size_t>(i)] = std::cos(phi);
      sin_phi[static_cast<std::size_t>(i)] = std::sin(phi);
    }
  }
  Dir at(int i, int j) const {
    const double s = sin_theta[static_cast<std::size_t>(j)];
    return {s * cos_phi[static_cast<std::size_t>(i)], s * sin_phi[static_cast<std::size_t>(i)],
            cos_theta[static_cast<std::size_t>(j)]};
  }
};

// Background plus the band's glow: a Gaussian in latitude and a bulge,
// mottled by noise and crossed by a dark rift a little off the centre line.
void paint_background(FrameImage& image, std::uint32_t seed) {
  const Band band = band_of(seed);
  const ValueNoise noise(seed);
  const PixelDirections dirs(image.width, image.height);
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const Dir d = dirs.at(i, j);
      const double s = dot(d, band.pole);                                // sine of the band latitude
      const double c2 = std::max(0.0, 2.0 - 2.0 * dot(d, band.centre));  // chord² to the bulge
      double glow = band_glow * std::exp(-s * s / (2.0 * band_glow_width * band_glow_width)) +
                    bulge_glow * std::exp(-c2 / (2.0 * bulge_width * bulge_width));
      if (glow > 1e-6) {
        const double mottle = noise.fbm(d, 4.0);
        const double rift_noise = noise.fbm({d[1], d[2], d[0]}, 6.0);
        const double off = s - 0.25 * band_glow_width;
        const double rift = std::exp(-off * off / (2.0 * 0.2 * band_glow_width * 0.2 * band_glow_width)) *
                            std::clamp((rift_noise - 0.4) * 4.0, 0.0, 1.0);
        glow *= (0.25 + 1.5 * mottle * mottle) * (1.0 - 0.7 * rift);
      }
      float* px = &image.rgb[3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(image.width) +
                                  static_cast<std::size_t>(i))];
      for (int k = 0; k < 3; ++k)
        px[k] = background[static_cast<std::size_t>(k)] +
                static_cast<float>(glow * glow_colour[static_cast<std::size_t>(k)]);
    }
}

// Why width x height is not a star field size, or "" when it is one.
std::string size_problem(int width, int height) {
  if (width > 0 && height > 0 && width <= max_image_side && height <= max_image_side) return {};
  return "bad size " + std::to_string(width) + " x " + std::to_string(height) + " (1 to " +
         std::to_string(max_image_side) + " a side)";
}

}  // namespace

// Field stars first, then band stars; the order of draws is part of the
// seed's meaning, so changing it changes every shipped sky.
std::vector<Star> starfield_catalogue(std::uint32_t seed) {
  const Band band = band_of(seed);
  Draw draw(seed, star_stream);
  std::vector<Star> stars;
  stars.reserve(field_stars + band_stars);
  for (int n = 0; n < field_stars; ++n) {
    const Dir dir = draw.direction();
    stars.push_back(make_star(draw, dir));
  }
  for (int n = 0; n < band_stars; ++n) {
    const double l = two_pi * draw.uniform(), b = band_star_latitude * draw.normal();
    Dir dir{};
    for (int k = 0; k < 3; ++k)
      dir[k] = std::cos(b) * (std::cos(l) * band.e1[k] + std::sin(l) * band.e2[k]) + std::sin(b) * band.pole[k];
    stars.push_back(make_star(draw, dir));
  }
  return stars;
}

// Splats each star over the texels of its cap only (bounded in θ, and in φ
// by the cap's longitude half-width), with the exact angular distance.
void add_stars(FrameImage& image, std::span<const Star> stars) {
  const int W = image.width, H = image.height;
  if (W <= 0 || H <= 0 || image.rgb.size() != 3 * static_cast<std::size_t>(W) * static_cast<std::size_t>(H))
    throw std::invalid_argument("add_stars: image buffer does not match its size");
  const double pitch = pi / H, phi_pitch = two_pi / W;
  // A texel integrates light over its area: blurring by about half a texel
  // keeps a star that is smaller than a texel from vanishing between the
  // pixel centres (or flickering as it moves in the lensed image).
  const double pixel_sigma = 0.5 * pitch;
  const PixelDirections dirs(W, H);
  for (const Star& star : stars) {
    const double sigma2 = star.sigma * star.sigma + pixel_sigma * pixel_sigma;
    const double peak = star.peak * star.sigma * star.sigma / sigma2;  // flux kept
    if (peak <= star_cutoff) continue;
    const double radius = std::sqrt(2.0 * sigma2 * std::log(peak / star_cutoff));
    const Dir& s = star.direction;
    const double theta = std::acos(std::clamp(s[2], -1.0, 1.0));
    double phi = std::atan2(s[1], s[0]);
    if (phi < 0.0) phi += two_pi;

    const int j0 = std::max(0, static_cast<int>(std::floor((theta - radius) / pitch - 0.5)));
    const int j1 = std::min(H - 1, static_cast<int>(std::ceil((theta + radius) / pitch - 0.5)));
    // Longitude half-width of the cap of angular radius `radius`: exactly
    // asin(sin r / sin θ), the 1/sin θ widening; the whole ring when the
    // cap reaches a pole.
    int i0 = 0, count = W;
    const double sin_theta = std::sin(theta);
    if (radius < theta && radius < pi - theta && std::sin(radius) < sin_theta) {
      const double half = std::asin(std::sin(radius) / sin_theta);
      i0 = static_cast<int>(std::floor((phi - half) / phi_pitch - 0.5));
      count = std::min(W, static_cast<int>(std::ceil((phi + half) / phi_pitch - 0.5)) - i0 + 1);
    }
    for (int j = j0; j <= j1; ++j)
      for (int k = 0; k < count; ++k) {
        const int i = ((i0 + k) % W + W) % W;
        // Chord² between directions ≈ angle² for the small angles that matter.
        const double chord2 = std::max(0.0, 2.0 - 2.0 * dot(dirs.at(i, j), s));
        const double v = peak * std::exp(-chord2 / (2.0 * sigma2));
        float* px =
            &image.rgb[3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(W) + static_cast<std::size_t>(i))];
        for (int c = 0; c < 3; ++c) px[c] += static_cast<float>(v * star.tint[static_cast<std::size_t>(c)]);
      }
  }
}

FrameImage render_sky_glow(int width, int height, std::uint32_t seed) {
  if (const std::string problem = size_problem(width, height); !problem.empty())
    throw std::runtime_error("star field: " + problem);
  FrameImage image;
  image.width = width;
  image.height = height;
  image.rgb.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  paint_background(image, seed);
  return image;
}

// Background and band, then the catalogue on top.
FrameImage render_starfield(int width, int height, std::uint32_t seed) {
  FrameImage image = render_sky_glow(width, height, seed);
  const std::vector<Star> stars = starfield_catalogue(seed);
  add_stars(image, stars);
  return image;
}

// Checks the size first so the message names the file.
void make_starfield(const std::filesystem::path& path, int width, int height, std::uint32_t seed) {
  if (const std::string problem = size_problem(width, height); !problem.empty())
    throw std::runtime_error("cannot make star field '" + path.string() + "': " + problem);
  write_png(path, render_starfield(width, height, seed));
}

}  // namespace lc
