#include "image/grade.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include <fmt/format.h>

#include "light/blackbody.hpp"

namespace lc {

namespace {

// The Bradford cone-response matrix (K. M. Lam, "Metamerism and colour
// constancy", PhD thesis, University of Bradford, 1985; linearised, as in
// ICC.1:2010 Annex E): XYZ -> the "sharpened" cone space in which von Kries
// scaling (each cone's response divided by its response to the white,
// von Kries 1902) predicts adaptation to a change of illuminant best.
constexpr Mat3 bradford = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};

// XYZ -> linear sRGB as a matrix, read off linear_srgb_exact (its columns
// are the images of the unit vectors) so the constants live in cie.cpp only.
Mat3 rgb_from_xyz() {
  Mat3 m;
  const std::array<XYZ, 3> unit = {XYZ{1.0, 0.0, 0.0}, XYZ{0.0, 1.0, 0.0}, XYZ{0.0, 0.0, 1.0}};
  for (int j = 0; j < 3; ++j) {
    const auto column = linear_srgb_exact(unit[j]);
    for (int i = 0; i < 3; ++i) m[i][j] = column[i];
  }
  return m;
}

double luminance(double r, double g, double b) {
  return rec709_luminance[0] * r + rec709_luminance[1] * g + rec709_luminance[2] * b;
}

void require_pixels(const std::vector<float>& rgb, const char* what) {
  if (rgb.size() % 3 != 0)
    throw std::invalid_argument(fmt::format("{}: {} floats are not whole rgb pixels", what, rgb.size()));
}

// The light of one pixel that blooms: `strength` of its share above the
// threshold.  A function (not a stored buffer) so apply_bloom can compute it
// twice, once to spread and once to take it out, with identical results.
std::array<double, 3> blooming(const float* c, const Bloom& bloom) {
  const double y = luminance(c[0], c[1], c[2]);
  if (!(y > bloom.threshold) || !(y > 0.0)) return {0.0, 0.0, 0.0};
  const double share = bloom.strength * (y - bloom.threshold) / y;
  return {share * c[0], share * c[1], share * c[2]};
}

// One direction of the blur over lines of n pixels: the kernel G(k),
// k = -reach..reach (at g[k + reach]), and each source position's normaliser
// w(x) = 1 / sum of G(x' - x) over the targets x' inside the line.  Scattering
// src(x) w(x) G(x' - x) to every x' in the line then moves all of src(x) and
// none out of the frame: the glow near an edge is brighter, not lost.
struct BlurPass {
  int reach;
  std::vector<double> g;
  std::vector<double> w;
};

BlurPass blur_pass(int n, double sigma) {
  BlurPass p;
  // 3.5 sigma leaves ~5e-4 of a Gaussian's weight outside; the
  // normalisation gives that back to the taps kept, so nothing is lost.
  // Taps farther than the line is long land nowhere: capping there keeps a
  // huge radius cheap and the reach an int.
  p.reach = static_cast<int>(std::clamp(std::ceil(3.5 * sigma), 1.0, std::max(1.0, static_cast<double>(n))));
  p.g.resize(2 * p.reach + 1);
  for (int k = -p.reach; k <= p.reach; ++k)
    // sigma = 0: exp(-inf) = 0 off the centre, a blur that moves nothing.
    p.g[k + p.reach] = k == 0 ? 1.0 : std::exp(-0.5 * k * k / (sigma * sigma));
  p.w.resize(n);
  for (int x = 0; x < n; ++x) {
    double sum = 0.0;
    for (int k = std::max(-p.reach, -x); k <= std::min(p.reach, n - 1 - x); ++k) sum += p.g[k + p.reach];
    p.w[x] = 1.0 / sum;
  }
  return p;
}

}  // namespace

XYZ srgb_white_xyz() {
  const auto w = apply(inverse(rgb_from_xyz()), {1.0, 1.0, 1.0});
  return {w[0] / w[1], 1.0, w[2] / w[1]};
}

Mat3 white_balance_matrix_from_xy(double x, double y) {
  // Inputs: the source white's chromaticity.  Output: rgb_from_xyz *
  // B^-1 diag(lms_D65 / lms_source) B * xyz_from_rgb, B the Bradford matrix.
  // Both whites at Y = 1, so the source white keeps its luminance.
  if (!std::isfinite(x) || !std::isfinite(y) || !(y > 0.0))
    throw std::invalid_argument(
        fmt::format("white balance: chromaticity ({}, {}) is not a colour (y must be > 0)", x, y));
  const XYZ d65 = srgb_white_xyz();
  const auto lms_source = apply(bradford, {x / y, 1.0, (1.0 - x - y) / y});
  const auto lms_d65 = apply(bradford, {d65.X, d65.Y, d65.Z});
  Mat3 scale{};
  for (int i = 0; i < 3; ++i) scale[i][i] = lms_d65[i] / lms_source[i];
  const Mat3 to_rgb = rgb_from_xyz();
  const Mat3 adapt = multiply(inverse(bradford), multiply(scale, bradford));
  return multiply(to_rgb, multiply(adapt, inverse(to_rgb)));
}

Mat3 white_balance_matrix(double kelvin) {
  // The range of colour temperatures grading tools offer: at 1000 K the
  // white has so little blue that its balance already scales blue by ~110,
  // and above 40000 K the white hardly changes with T.
  if (!(kelvin >= 1000.0 && kelvin <= 40000.0))
    throw std::invalid_argument(
        fmt::format("white balance: {} K is outside the blackbody temperatures it takes, 1000 to 40000 K", kelvin));
  const XYZ c = blackbody_xyz(kelvin);
  const double s = c.X + c.Y + c.Z;
  return white_balance_matrix_from_xy(c.X / s, c.Y / s);
}

void apply_matrix(std::vector<float>& rgb, const Mat3& m) {
  // Inputs: interleaved linear rgb, any sign.  Each pixel becomes m times
  // it, computed in double and rounded once to float.
  require_pixels(rgb, "apply_matrix");
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    const auto out = apply(m, {rgb[i], rgb[i + 1], rgb[i + 2]});
    for (int c = 0; c < 3; ++c) rgb[i + c] = static_cast<float>(out[c]);
  }
}

void apply_saturation(std::vector<float>& rgb, double s) {
  // Inputs: interleaved linear rgb, any sign; s >= 0.  Linear in each pixel,
  // so luminance (a linear function with weights summing to 1) is kept.
  require_pixels(rgb, "apply_saturation");
  if (!(s >= 0.0) || !std::isfinite(s))
    throw std::invalid_argument(fmt::format("saturation must be >= 0 and finite, got {}", s));
  // Exactly nothing: Y + (c - Y) need not round back to c.
  if (s == 1.0) return;
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    const double y = luminance(rgb[i], rgb[i + 1], rgb[i + 2]);
    for (int c = 0; c < 3; ++c) rgb[i + c] = static_cast<float>(y + s * (rgb[i + c] - y));
  }
}

void apply_bloom(std::vector<float>& rgb, int width, int height, const Bloom& bloom) {
  // Inputs: a width x height frame of interleaved linear rgb, rows top to
  // bottom.  Output in place: the light that does not bloom, plus the
  // blooming light blurred.  Both blur passes conserve every line's sum, so
  // the frame's sum per channel is kept up to the final rounding to float.
  if (width < 0 || height < 0 ||
      static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3 != rgb.size())
    throw std::invalid_argument(
        fmt::format("bloom: a {}x{} frame needs {} floats, got {}", width, height,
                    3.0 * static_cast<double>(width) * static_cast<double>(height), rgb.size()));
  if (!(bloom.strength >= 0.0 && bloom.strength <= 1.0))
    throw std::invalid_argument(fmt::format("bloom: strength must be in [0, 1], got {}", bloom.strength));
  if (!(bloom.radius >= 0.0) || !std::isfinite(bloom.radius))
    throw std::invalid_argument(fmt::format("bloom: radius must be >= 0 and finite, got {}", bloom.radius));
  if (!(bloom.threshold >= 0.0) || !std::isfinite(bloom.threshold))
    throw std::invalid_argument(fmt::format("bloom: threshold must be >= 0 and finite, got {}", bloom.threshold));
  if (bloom.strength == 0.0 || rgb.empty()) return;

  const std::size_t w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height), row = 3 * w;
  const double sigma = bloom.radius * std::hypot(static_cast<double>(width), static_cast<double>(height));

  // The blooming light, and where in each row it is (first and last pixel;
  // first > last: none): most of a frame is below the threshold, and
  // blurring zeros costs as much as blurring light.  Skipping them changes
  // no value: a sum of zeros is zero, and adding zero changes nothing.
  std::vector<double> bright(rgb.size(), 0.0);
  std::vector<int> first(h, width), last(h, -1);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t i = y * row + 3 * x;
      const auto b = blooming(&rgb[i], bloom);
      for (int c = 0; c < 3; ++c) bright[i + c] = b[c];
      if (b[0] != 0.0 || b[1] != 0.0 || b[2] != 0.0) {
        first[y] = std::min(first[y], static_cast<int>(x));
        last[y] = static_cast<int>(x);
      }
    }

  // Rows, in place: each channel of a row is copied, times its normaliser,
  // into a zero-padded line; the scatter is then a gather from it (G is
  // symmetric), contiguous in x so the compiler vectorises it.  Only the
  // pixels within reach of the row's light get any; the row's extent grows
  // by the reach.
  const BlurPass across = blur_pass(width, sigma);
  {
    const int r = across.reach;
    std::vector<double> padded(w + 2 * r, 0.0), sum(w);
    for (std::size_t y = 0; y < h; ++y) {
      if (first[y] > last[y]) continue;
      const int x0 = std::max(0, first[y] - r), x1 = std::min(width - 1, last[y] + r);
      // The sources the gathers read: [x0 - r, x1 + r], refreshed whole
      // (the padding outside the line stays zero).
      const int s0 = std::max(0, x0 - r), s1 = std::min(width - 1, x1 + r);
      double* line = &bright[y * row];
      for (int c = 0; c < 3; ++c) {
        for (int x = s0; x <= s1; ++x) padded[r + x] = line[3 * x + c] * across.w[x];
        std::fill(sum.begin() + x0, sum.begin() + x1 + 1, 0.0);
        for (int k = 0; k <= 2 * r; ++k) {
          const double gk = across.g[k];
          const double* src = &padded[k];
          for (int x = x0; x <= x1; ++x) sum[x] += gk * src[x];
        }
        for (int x = x0; x <= x1; ++x) line[3 * x + c] = sum[x];
      }
      first[y] = x0;
      last[y] = x1;
    }
  }

  // Columns, as a scatter of whole rows: each lit source row's extent is
  // added, weighted, to the rows within reach; unlit rows cost nothing.
  const BlurPass down = blur_pass(height, sigma);
  std::vector<double> glow(rgb.size(), 0.0);
  for (std::size_t y = 0; y < h; ++y) {
    if (first[y] > last[y]) continue;
    const std::size_t i0 = 3 * static_cast<std::size_t>(first[y]), i1 = 3 * static_cast<std::size_t>(last[y]) + 3;
    const double* src = &bright[y * row];
    const int yi = static_cast<int>(y);
    for (int t = std::max(0, yi - down.reach); t <= std::min(height - 1, yi + down.reach); ++t) {
      const double weight = down.g[t - yi + down.reach] * down.w[y];
      double* dst = &glow[static_cast<std::size_t>(t) * row];
      for (std::size_t i = i0; i < i1; ++i) dst[i] += weight * src[i];
    }
  }

  // What stays plus what arrives, rounded to float once.
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    const auto b = blooming(&rgb[i], bloom);
    for (int c = 0; c < 3; ++c) rgb[i + c] = static_cast<float>((rgb[i + c] - b[c]) + glow[i + c]);
  }
}

}  // namespace lc
