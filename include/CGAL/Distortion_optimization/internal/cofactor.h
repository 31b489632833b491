// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_COFACTOR_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_COFACTOR_H

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// det A and its cofactor matrix C = det A * A^-T, computed without a division:
// d(det A)/dA = C, |A^-1|^2 = |C|^2 / det^2. For A = Ds (a cell's target edges), column i-1 of C
// is the derivative of the cell's signed volume (times n!) in vertex i, and minus their sum the
// derivative in vertex 0.
template <int n>
struct Cofactor_and_determinant
{
  double det;
  Eigen::Matrix<double, n, n> cofactor;
  explicit Cofactor_and_determinant(const Eigen::Matrix<double, n, n>& A)
  {
    if constexpr(n == 2) {
      cofactor << A(1, 1), -A(1, 0), -A(0, 1), A(0, 0);
      det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
    } else {
      cofactor.col(0) = A.col(1).cross(A.col(2));
      cofactor.col(1) = A.col(2).cross(A.col(0));
      cofactor.col(2) = A.col(0).cross(A.col(1));
      det = A.col(0).dot(cofactor.col(0));
    }
  }
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_COFACTOR_H
