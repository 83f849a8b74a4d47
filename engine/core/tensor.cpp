#include "core/tensor.hpp"

#include <stdexcept>
#include <utility>

namespace lc {

// Gauss–Jordan elimination with partial pivoting.  Used off the hot path only
// (Jacobians, tetrad set-up); throws on a singular matrix.
Mat4 inverse(const Mat4& m) {
  Mat4 a = m;
  Mat4 inv{};
  for (int i = 0; i < 4; ++i) inv[i][i] = 1.0;
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 4; ++row)
      if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
    if (a[pivot][col] == 0.0) throw std::domain_error("inverse: singular 4x4 matrix");
    std::swap(a[pivot], a[col]);
    std::swap(inv[pivot], inv[col]);
    const double s = 1.0 / a[col][col];
    for (int k = 0; k < 4; ++k) {
      a[col][k] *= s;
      inv[col][k] *= s;
    }
    for (int row = 0; row < 4; ++row) {
      if (row == col) continue;
      const double f = a[row][col];
      if (f == 0.0) continue;
      for (int k = 0; k < 4; ++k) {
        a[row][k] -= f * a[col][k];
        inv[row][k] -= f * inv[col][k];
      }
    }
  }
  return inv;
}

}  // namespace lc
