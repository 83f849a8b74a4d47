#pragma once
// Small fixed-size tensors for 4D spacetime: components are plain doubles in
// std::array so that they live on the stack and the optimiser sees through
// them.  Index conventions: Vec4 v[mu]; Mat4 m[mu][nu]; Mat4Derivs d[alpha][mu][nu]
// holds ∂_alpha m_{mu nu}.

#include <array>
#include <cmath>

namespace lc {

using Vec4 = std::array<double, 4>;
using Vec3 = std::array<double, 3>;
using Mat4 = std::array<std::array<double, 4>, 4>;

// η, the flat metric in Cartesian coordinates (the background of the
// Kerr–Schild forms).
inline constexpr Mat4 minkowski_metric = {{{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
using Mat4Derivs = std::array<Mat4, 4>;

// Contraction g_{mu nu} a^mu b^nu.
inline double contract(const Mat4& g, const Vec4& a, const Vec4& b) {
  double s = 0.0;
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) s += g[m][n] * a[m] * b[n];
  return s;
}

// Index lowering / raising: (g v)_mu = g_{mu nu} v^nu.
inline Vec4 mat_vec(const Mat4& g, const Vec4& v) {
  Vec4 r{};
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) r[m] += g[m][n] * v[n];
  return r;
}

inline double dot(const Vec4& a, const Vec4& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

inline Vec4 operator+(const Vec4& a, const Vec4& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]};
}
inline Vec4 operator-(const Vec4& a, const Vec4& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]};
}
inline Vec4 operator*(double s, const Vec4& a) { return {s * a[0], s * a[1], s * a[2], s * a[3]}; }

inline Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

inline double norm3(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
inline double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 unit3(const Vec3& v) {
  const double n = norm3(v);
  return {v[0] / n, v[1] / n, v[2] / n};
}

}  // namespace lc

namespace lc {
// Inverse of a general 4x4 matrix (off the hot path); throws std::domain_error
// when singular.
Mat4 inverse(const Mat4& m);
}  // namespace lc
