#pragma once
// The BL–Mino right-hand side of kerr_mino.hpp for several rays at once, one
// ray per lane of a vector (geodesic/lanes.hpp: four with AVX2, eight with
// AVX-512): each lane has its own constants of motion, the spacetime is
// shared.  With the
// Dormand–Prince pieces of dormand_prince.hpp, which are generic in the
// number type, it lets render/trace_batch.hpp advance lane_count rays per
// instruction stream, each with its own step size and controller.

#include <array>

#include "geodesic/dormand_prince.hpp"
#include "geodesic/kerr_mino.hpp"
#include "geodesic/lanes.hpp"

namespace lc {


using MinoLanes = std::array<LaneVec, 8>;  // component j, lane i: y[j][i]

struct KerrMinoRhs4 {
  LaneVec M{}, a{}, E{}, L{}, K{}, a2{}, aE{}, a2E2{}, alpha{}, u_floor2{}, sign_P{};

  // Lane i takes the constants of one ray.
  void set(int i, const KerrMinoRhs& r) {
    M[i] = r.M;
    a[i] = r.a;
    E[i] = r.E;
    L[i] = r.L;
    K[i] = r.K;
    a2[i] = r.a2;
    aE[i] = r.aE;
    a2E2[i] = r.a2E2;
    alpha[i] = r.alpha;
    u_floor2[i] = r.u_floor2;
    sign_P[i] = r.sign_P;
  }

  // KerrMinoRhs::operator() lane by lane (the same formulas; see there).
  void operator()(LaneVec, const MinoLanes& y, MinoLanes& dy) const {
    const LaneVec zero = LaneVec{} + 0.0, one = LaneVec{} + 1.0;
    const LaneVec u = y[1], c = y[2], s = y[3], U = y[5], w = y[6];
    const LaneVec u2 = u * u;
    const LaneVec Pu = E + alpha * u2;
    const LaneVec inv_D = one / (one - 2.0 * M * u + a2 * u2);
    const LaneVec inv_u2 = one / (u2 > u_floor2 ? u2 : u_floor2);
    const LaneVec s2 = s * s;
    const LaneVec L_s2 = L == zero ? zero : L / s2;
    const LaneVec W2 = Pu * Pu - u2 * (one - 2.0 * M * u + a2 * u2) * K;
    const LaneVec W = sqrt_of(W2 > zero ? W2 : zero);
    dy[0] = a * (L - aE * s2) + sign_P * (one + a2 * u2) * K / (abs_of(Pu) + W);
    dy[1] = U;
    dy[2] = -s * w;
    dy[3] = c * w;
    dy[4] = L_s2 - aE + a * Pu * inv_D;
    dy[5] = 2.0 * alpha * u * Pu - K * u * (one - 3.0 * M * u + 2.0 * a2 * u2);
    dy[6] = c * s * (L_s2 * L_s2 - a2E2);
    dy[7] = inv_u2 + a2 * c * c;
  }
};

}  // namespace lc
