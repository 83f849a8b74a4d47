#pragma once
// The number types the ray integrators are written for, once: double (one
// ray), or a vector of doubles (GCC vector extensions) with one independent
// ray per lane — eight in an AVX-512 register where the build targets it,
// else four (AVX2; eight lanes in two AVX2 registers measured slower than
// four).  Arithmetic, comparisons and `c ? a : b` work lane by lane on the
// vector as they do on a double, so a right-hand side or an integrator step
// templated on T computes the same, lane for lane, for either.

#include <algorithm>
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

// Lanes<W>: double for one ray, LaneVec for lane_count of them.
template <int W>
struct LanesOf;
template <>
struct LanesOf<1> {
  using type = double;
};
template <>
struct LanesOf<lane_count> {
  using type = LaneVec;
};
template <int W>
using Lanes = typename LanesOf<W>::type;

// Lane i of a value, read and written.
inline double get_lane(double x, int) { return x; }
inline double get_lane(const LaneVec& x, int i) { return x[i]; }
inline void set_lane(double& x, int, double v) { x = v; }
inline void set_lane(LaneVec& x, int i, double v) { x[i] = v; }

// The square root, |x| and max of every lane.
inline double sqrt_of(double x) { return std::sqrt(x); }
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
inline double abs_of(double x) { return std::abs(x); }
inline LaneVec abs_of(LaneVec x) { return x < 0.0 ? -x : x; }
inline double max_of(double x, double y) { return std::max(x, y); }
inline LaneVec max_of(LaneVec x, LaneVec y) { return x > y ? x : y; }

}  // namespace lc
