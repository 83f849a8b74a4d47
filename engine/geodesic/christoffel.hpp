#pragma once
// Christoffel symbols from a spacetime's analytic metric derivatives, for the
// equations that need them (timelike worldlines, parallel transport).  Null
// rays use the Hamiltonian form instead, which needs no Christoffel symbols.

#include "core/tensor.hpp"

namespace lc {

// G[mu][a][b] = Gamma^mu_{ab} = 1/2 g^{mu nu} (∂_a g_{nu b} + ∂_b g_{nu a} - ∂_nu g_{ab}).
using Christoffel = std::array<Mat4, 4>;

template <class S>
Christoffel christoffel(const S& st, const Vec4& x) {
  const Mat4 gi = st.inverse_metric(x);
  const Mat4Derivs d = st.metric_derivatives(x);
  Christoffel lower{};  // Gamma_{nu a b}
  for (int n = 0; n < 4; ++n)
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b)
        lower[n][a][b] = lower[n][b][a] = 0.5 * (d[a][n][b] + d[b][n][a] - d[n][a][b]);
  Christoffel G{};
  for (int m = 0; m < 4; ++m)
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b) {
        double s = 0.0;
        for (int n = 0; n < 4; ++n) s += gi[m][n] * lower[n][a][b];
        G[m][a][b] = G[m][b][a] = s;
      }
  return G;
}

// dV^mu/dlambda = -Gamma^mu_{ab} u^a V^b: parallel transport of V along a
// curve with tangent u.
inline Vec4 transport_rate(const Christoffel& G, const Vec4& u, const Vec4& V) {
  Vec4 r{};
  for (int m = 0; m < 4; ++m) {
    double s = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) s += G[m][a][b] * u[a] * V[b];
    r[m] = -s;
  }
  return r;
}

}  // namespace lc
