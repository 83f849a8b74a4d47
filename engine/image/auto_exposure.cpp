#include "image/auto_exposure.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "image/grade.hpp"

namespace lc {

double luminance_percentile(const FrameImage& image, double fraction) {
  std::vector<double> y;
  y.reserve(image.rgb.size() / 3);
  for (std::size_t p = 0; p + 2 < image.rgb.size(); p += 3) {
    const double v = rec709_luminance[0] * image.rgb[p] + rec709_luminance[1] * image.rgb[p + 1] +
                     rec709_luminance[2] * image.rgb[p + 2];
    y.push_back(v > 0.0 ? v : 0.0);  // (NaN compares false)
  }
  const auto n = static_cast<double>(y.size());
  const auto rank = static_cast<std::size_t>(std::clamp(std::ceil(fraction * n), 1.0, n)) - 1;
  std::nth_element(y.begin(), y.begin() + static_cast<long>(rank), y.end());
  return y[rank];
}

std::vector<double> metered_exposures(std::span<const double> readings, double level, double smoothing) {
  const std::size_t n = readings.size();
  std::vector<double> stops(n, 0.0);
  std::vector<bool> lit(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = readings[i];
    lit[i] = lit_reading(r);
    if (lit[i]) stops[i] = std::log2(level / r);
  }
  const long count = static_cast<long>(n);
  const long reach = smoothing_reach(smoothing);
  std::vector<double> out(n, 0.0);
  std::vector<bool> placed(n, false);  // whether a lit frame lies within reach
  for (long i = 0; i < count; ++i) {
    // A straight line fitted by weighted least squares to the lit frames
    // in the window (Cleveland 1979, local linear regression), read at i:
    // s0 a + s1 b = t0, s1 a + s2 b = t1 with d = j - i.
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, t0 = 0.0, t1 = 0.0;
    for (long j = std::max(0L, i - reach); j <= std::min(count - 1, i + reach); ++j) {
      if (!lit[static_cast<std::size_t>(j)]) continue;
      const double d = static_cast<double>(j - i);
      const double w = j == i ? 1.0 : std::exp(-0.5 * d * d / (smoothing * smoothing));
      const double y = stops[static_cast<std::size_t>(j)];
      s0 += w, s1 += w * d, s2 += w * d * d, t0 += w * y, t1 += w * d * y;
    }
    placed[static_cast<std::size_t>(i)] = s0 > 0.0;
    if (s0 <= 0.0) continue;
    const double det = s0 * s2 - s1 * s1;
    // One lit frame, or all on one side at one distance: the mean.
    out[static_cast<std::size_t>(i)] = det > 1e-9 * s0 * s2 ? (s2 * t0 - s1 * t1) / det : t0 / s0;
  }
  // A frame with no lit frame within reach takes the nearest placed one's
  // (the earlier on a tie): the nearest on each side, found in two sweeps.
  std::vector<long> before(n, -1), after(n, -1);
  for (long i = 0, last = -1; i < count; ++i) {
    before[static_cast<std::size_t>(i)] = last;
    if (placed[static_cast<std::size_t>(i)]) last = i;
  }
  for (long i = count - 1, next = -1; i >= 0; --i) {
    after[static_cast<std::size_t>(i)] = next;
    if (placed[static_cast<std::size_t>(i)]) next = i;
  }
  const std::vector<double> smoothed = out;
  for (long i = 0; i < count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (placed[k]) continue;
    const long b = before[k], a = after[k];
    if (b < 0 && a < 0) continue;  // nothing lit in the shot: 0
    out[k] = smoothed[static_cast<std::size_t>(a < 0 || (b >= 0 && i - b <= a - i) ? b : a)];
  }
  for (double& e : out) e = std::clamp(e, -64.0, 64.0);
  return out;
}

std::map<int, double> needed_readings(std::span<const int> frames, int count, double smoothing,
                                      const std::function<std::vector<double>(const std::vector<int>&)>& take) {
  const long reach = smoothing_reach(smoothing);
  std::set<int> wanted;
  for (const int r : frames)
    for (long j = std::max(0L, r - reach); j <= std::min<long>(count - 1L, r + reach); ++j) wanted.insert(static_cast<int>(j));
  std::map<int, double> got;
  auto take_batch = [&](const std::vector<int>& batch) {
    const std::vector<double> readings = take(batch);
    for (std::size_t k = 0; k < batch.size(); ++k) got[batch[k]] = readings.at(k);
  };
  take_batch(std::vector<int>(wanted.begin(), wanted.end()));
  // Out from `from` in direction `step` to the nearest lit frame (or the
  // shot's end).
  auto walk = [&](long from, int step) {
    for (long j = from; j >= 0 && j < count; j += step) {
      if (!got.count(static_cast<int>(j))) take_batch({static_cast<int>(j)});
      if (lit_reading(got.at(static_cast<int>(j)))) return;
    }
  };
  for (const int r : frames) {
    bool lit = false;
    for (long j = std::max(0L, r - reach); j <= std::min<long>(count - 1L, r + reach) && !lit; ++j)
      lit = lit_reading(got.at(static_cast<int>(j)));
    if (lit) continue;
    walk(r - reach - 1, -1);
    walk(r + reach + 1, 1);
  }
  return got;
}

std::map<int, double> exposures_from(const std::map<int, double>& readings, std::span<const int> frames, double level,
                                     double smoothing) {
  std::map<int, double> out;
  if (readings.empty()) return out;
  const int first = readings.begin()->first, last = readings.rbegin()->first;
  std::vector<double> span(static_cast<std::size_t>(last - first + 1), 0.0);
  for (const auto& [frame, reading] : readings) span[static_cast<std::size_t>(frame - first)] = reading;
  const std::vector<double> exposures = metered_exposures(span, level, smoothing);
  for (const int f : frames) out[f] = exposures.at(static_cast<std::size_t>(f - first));
  return out;
}

}  // namespace lc
