#pragma once
// Hamilton's equations of the dihole (Dihole::hamiltonian_rhs) for
// lane_count rays at once, one per lane of a vector (geodesic/lanes.hpp's
// LaneVec): the same formulas, for render/trace_batch.hpp.

#include <array>
#include <cmath>

#include "geodesic/lanes.hpp"
#include "spacetime/dihole.hpp"

namespace lc {

// State per lane: x^0..x^3, p_0..p_3, as RayState.
using RayLanes = std::array<LaneVec, 8>;

struct DiholeRhs4 {
  double m1, m2, d;
  explicit DiholeRhs4(const Dihole& st) : m1(st.mass1()), m2(st.mass2()), d(st.separation()) {}

  void operator()(LaneVec, const RayLanes& y, RayLanes& dy) const {
    const LaneVec one = LaneVec{} + 1.0;
    const LaneVec X = y[1], Y = y[2], z1 = y[3] - d, z2 = y[3] + d;
    const LaneVec rho2 = X * X + Y * Y;
    const LaneVec i1 = one / sqrt_of(rho2 + z1 * z1), i2 = one / sqrt_of(rho2 + z2 * z2);
    const LaneVec U = one + m1 * i1 + m2 * i2;
    const LaneVec c1 = m1 * i1 * i1 * i1, c2 = m2 * i2 * i2 * i2;
    const LaneVec gx = -(c1 + c2) * X, gy = -(c1 + c2) * Y, gz = -(c1 * z1 + c2 * z2);
    const LaneVec iU2 = one / (U * U);
    const LaneVec p2 = y[5] * y[5] + y[6] * y[6] + y[7] * y[7];
    dy[0] = -U * U * y[4];
    dy[1] = iU2 * y[5];
    dy[2] = iU2 * y[6];
    dy[3] = iU2 * y[7];
    const LaneVec k = U * y[4] * y[4] + iU2 / U * p2;  // -dH/dU
    dy[4] = LaneVec{};
    dy[5] = k * gx;
    dy[6] = k * gy;
    dy[7] = k * gz;
  }
};

}  // namespace lc
