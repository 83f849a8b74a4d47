#include "render/accuracy.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "objects/disk.hpp"

namespace lc {

namespace {

double quantile(std::vector<double>& v, double q) {
  if (v.empty()) return 0.0;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

AccuracyReport compare_samples(const std::vector<RaySample>& reference, const std::vector<RaySample>& test,
                               const SceneSpec& scene) {
  AccuracyReport rep;
  std::vector<double> dr, dphi;
  rep.pixels = static_cast<long>(std::min(reference.size(), test.size()));
  for (long p = 0; p < rep.pixels; ++p) {
    const RaySample& a = reference[p];
    const RaySample& b = test[p];
    if (a.hit.kind != b.hit.kind) {
      ++rep.kind_mismatches;
      continue;
    }
    // The bench's disk metrics: the first disk of the scene's.
    const DiskParams* d = nullptr;
    for (const ObjectSpec& o : scene.objects)
      if (!d) d = o.get_if<DiskParams>();
    if (a.hit.kind == Disk::hit_kind && d) {
      auto cell = [&](const RaySample& s) {
        return std::pair{static_cast<long>(std::floor((s.hit.r - d->inner) / (d->outer - d->inner) * d->rings)),
                         static_cast<long>(std::floor(s.hit.phi / two_pi * d->sectors))};
      };
      if (cell(a) != cell(b)) ++rep.cell_mismatches;
      dr.push_back(std::abs(a.hit.r - b.hit.r));
      dphi.push_back(std::abs(std::remainder(a.hit.phi - b.hit.phi, two_pi)));
      ++rep.disk_pixels;
    } else if (a.color != b.color) {
      ++rep.cell_mismatches;
    }
  }
  if (!dr.empty()) {
    rep.dr_max = *std::max_element(dr.begin(), dr.end());
    rep.dphi_max = *std::max_element(dphi.begin(), dphi.end());
    rep.dr_median = quantile(dr, 0.5);
    rep.dr_p99 = quantile(dr, 0.99);
    rep.dphi_median = quantile(dphi, 0.5);
    rep.dphi_p99 = quantile(dphi, 0.99);
  }
  return rep;
}

}  // namespace lc
