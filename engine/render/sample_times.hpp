#pragma once
// Which instant of its frame's open shutter each sample of a pixel takes
// (SceneIn::instants; docs/motion_blur.md).  A pixel's N x N grid samples
// are spread over the K instants as evenly as N N allows (each instant
// takes floor(NN/K) or ceil(NN/K) of them), in an order shuffled per pixel,
// so that a sample's time does not follow its place in the pixel: both are
// stratified, and the pairing is random (pbrt's "padded" sampling of time
// with space).  The shuffle is a hash of the pixel's place in the whole
// frame, so every split over threads, stripes, ranks and resumes gives the
// same times.  The sample adaptive sampling takes first is at the first
// instant in pixels whose first sample is the top-left one and the last in
// the others (RowGrid::first_sample alternates them along a row): where
// anything moves within the shutter, row neighbours' first samples then
// see it at the shutter's two ends, differ, and both pixels are refined.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

namespace lc {

// Samples per side of a pixel's grid for N x N asked for and a shutter of
// K instants: enough that a pixel sampled in full takes every instant.
inline int samples_per_side(int N, int K) {
  int n = N;
  while (n * n < K) ++n;
  return n;
}

// The instants of pixel (x, y)'s NN grid samples (x, y: its place in the
// whole frame) into out[0 .. NN): sample `first` (the one adaptive
// sampling takes first) at instant 0, or K-1 where `first_late`.  Needs
// NN >= K >= 1.
inline void sample_instants(std::int64_t x, std::int64_t y, int K, int first, bool first_late, std::span<int> out) {
  const int NN = static_cast<int>(out.size());
  // A permutation of 0 .. NN-1 with `first` at one end, the rest shuffled
  // (Fisher–Yates) by a splitmix64 stream seeded with the pixel.
  std::uint64_t state = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                        static_cast<std::uint64_t>(y) * 0xD1B54A32D192ED03ull;
  auto next = [&state]() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  const int end = first_late ? NN - 1 : 0;
  // The other ranks in out[1 ..], shuffled (Fisher–Yates), then moved
  // down to make room for `first`.
  for (int v = 0, k = 1; v < NN; ++v)
    if (v != end) out[k++] = v;
  for (int k = NN - 1; k > 1; --k)
    std::swap(out[k], out[1 + static_cast<int>(next() % static_cast<std::uint64_t>(k))]);
  for (int k = 0; k < first; ++k) out[k] = out[k + 1];
  out[first] = end;
  for (int& r : out) r = static_cast<int>(static_cast<std::int64_t>(r) * K / NN);
}

}  // namespace lc
