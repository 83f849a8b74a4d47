#pragma once
// Image accuracy against a reference: how far the per-pixel hits of a render
// are from those of a tight-tolerance render of the same scene.  What
// `lightcone bench` reports next to speed, so that speed is never bought
// with wrong pictures.

#include <vector>

#include "render/hit_record.hpp"
#include "scene/scene_spec.hpp"

namespace lc {

struct AccuracyReport {
  long pixels = 0;
  long kind_mismatches = 0;  // hit.kind differs
  long cell_mismatches = 0;  // same kind, but another checker cell (disk) or colour (sphere, sky)
  long disk_pixels = 0;      // both hit the disk
  double dr_median = 0, dr_p99 = 0, dr_max = 0;        // |delta r| of disk hits (M)
  double dphi_median = 0, dphi_p99 = 0, dphi_max = 0;  // |delta phi| of disk hits (rad)
};

// Compares samples pixel by pixel (same order, same scene).
AccuracyReport compare_samples(const std::vector<RaySample>& reference, const std::vector<RaySample>& test,
                               const SceneSpec& scene);

}  // namespace lc
