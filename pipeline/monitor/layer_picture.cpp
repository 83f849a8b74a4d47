#include "monitor/layer_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "image/srgb.hpp"

namespace lc::monitor {

namespace {

// Viridis at 0, 1/4, 1/2, 3/4 and 1 (8-bit sRGB), interpolated linearly
// between: close enough to the full table for a glance at a layer.
constexpr std::array<std::array<double, 3>, 5> viridis = {
    {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}};

std::array<double, 3> colour_at(double t) {
  const double x = std::clamp(t, 0.0, 1.0) * 4.0;
  const auto k = std::min<std::size_t>(3, static_cast<std::size_t>(x));
  const double f = x - static_cast<double>(k);
  std::array<double, 3> c{};
  for (std::size_t i = 0; i < 3; ++i) c[i] = viridis[k][i] + f * (viridis[k + 1][i] - viridis[k][i]);
  return c;
}

}  // namespace

bool layer_picture(const FrameImage& frame, const std::string& name, FrameImage& picture) {
  const auto layer = std::find_if(frame.layers.begin(), frame.layers.end(), [&](const auto& l) { return l.name == name; });
  if (layer == frame.layers.end()) return false;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const float v : layer->values)
    if (std::isfinite(v)) lo = std::min(lo, double{v}), hi = std::max(hi, double{v});
  picture = FrameImage{frame.width, frame.height, std::vector<float>(3 * layer->values.size(), 0.0f), {}, {}, {}};
  for (std::size_t p = 0; p < layer->values.size(); ++p) {
    const float v = layer->values[p];
    if (!std::isfinite(v)) continue;  // black
    const auto c = colour_at(hi > lo ? (v - lo) / (hi - lo) : 0.5);
    for (std::size_t i = 0; i < 3; ++i) picture.rgb[3 * p + i] = static_cast<float>(srgb_to_linear(c[i] / 255.0));
  }
  return true;
}

}  // namespace lc::monitor
