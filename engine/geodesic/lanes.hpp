#pragma once
// Four doubles in one AVX2 vector (GCC vector extensions): one independent
// ray per lane, for the integrators that advance several rays per
// instruction stream (dormand_prince_lanes.hpp, kerr_mino_lanes.hpp,
// spacetime/dihole_lanes.hpp).  Arithmetic and comparisons work lane by lane.

#include <cmath>

#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace lc {

using Lane4 = double __attribute__((vector_size(32)));
inline constexpr int lane_count = 4;

// The square root of every lane.
inline Lane4 sqrt_of(Lane4 x) {
#if defined(__AVX__)
  return reinterpret_cast<Lane4>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(x)));
#else
  for (int i = 0; i < lane_count; ++i) x[i] = std::sqrt(x[i]);
  return x;
#endif
}

}  // namespace lc
