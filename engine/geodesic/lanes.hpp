#pragma once
// A vector of doubles (GCC vector extensions), one independent ray per lane,
// for the integrators that advance several rays per instruction stream
// (dormand_prince_lanes.hpp, kerr_mino_lanes.hpp, spacetime/dihole_lanes.hpp):
// eight in an AVX-512 register where the build targets it, else four (AVX2;
// eight lanes in two AVX2 registers measured slower than four).  Arithmetic
// and comparisons work lane by lane.

#include <cmath>

#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace lc {

#if defined(__AVX512F__)
inline constexpr int lane_count = 8;
#else
inline constexpr int lane_count = 4;
#endif
using LaneVec = double __attribute__((vector_size(8 * lane_count)));

// The square root of every lane.
inline LaneVec sqrt_of(LaneVec x) {
#if defined(__AVX512F__)
  // The masked form with every lane on: GCC 12's plain _mm512_sqrt_pd warns
  // about its own undefined pass-through operand.
  const __m512d v = reinterpret_cast<__m512d>(x);
  return reinterpret_cast<LaneVec>(_mm512_mask_sqrt_pd(v, 0xff, v));
#elif defined(__AVX__)
  return reinterpret_cast<LaneVec>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(x)));
#else
  for (int i = 0; i < lane_count; ++i) x[i] = std::sqrt(x[i]);
  return x;
#endif
}

// The absolute value of every lane (its sign bit cleared).
inline LaneVec abs_of(LaneVec x) { return x < 0.0 ? -x : x; }

}  // namespace lc
