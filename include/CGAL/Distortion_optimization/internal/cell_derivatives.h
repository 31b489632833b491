// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Derivatives of a cell's functions: the cofactor matrix (the derivative of the determinant),
// and the chain rule from a cell's edge matrix Ds = (x_1 - x_0, ..., x_n - x_0) to its vertices.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DERIVATIVES_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DERIVATIVES_H

#include <CGAL/license/Distortion_optimization.h>

#include <Eigen/Core>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n> using Matrix = Eigen::Matrix<double, n, n>;
template <int n> using Vector = Eigen::Matrix<double, n, 1>;

// The cofactor matrix C = det A * A^-T of the n x n matrix with entries a(r, c), for one matrix
// (T = double) or one per lane: d(det A)/dA = C, |A^-1|^2 = |C|^2 / det^2. In 3D column c is the
// cross product of the other two columns, in cyclic order.
template <int n, class T, class Entry>
void cofactor_matrix(const Entry& a, T (&C)[n][n])
{
  if constexpr(n == 2) {
    C[0][0] = a(1, 1), C[0][1] = -a(1, 0), C[1][0] = -a(0, 1), C[1][1] = a(0, 0);
  } else {
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c) {
        const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        C[r][c] = a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1);
      }
  }
}

// det A and its cofactor matrix, without a division. For A = Ds, column i-1 of the cofactor is
// the derivative of n! times the cell's signed volume in vertex i (see vertex_derivative).
template <int n>
struct Cofactor_and_determinant
{
  double det;
  Matrix<n> cofactor;
  explicit Cofactor_and_determinant(const Matrix<n>& A)
  {
    double C[n][n];
    cofactor_matrix<n>([&](int r, int c) { return A(r, c); }, C);
    for(int r = 0; r < n; ++r)
      for(int c = 0; c < n; ++c) cofactor(r, c) = C[r][c];
    if constexpr(n == 2) det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
    else det = A.col(0).dot(cofactor.col(0));
  }
};

// The derivative in vertex i of a function of Ds whose derivative in Ds is M: column i-1 of M for
// i >= 1, minus the sum of the columns for vertex 0 (which moves every edge). With M = Dm^-T these
// are the gradients of the cell's hat functions; with M = dD/dJ Dm^-T those of D(J).
template <int n>
Vector<n> vertex_derivative(const Matrix<n>& M, int i)
{
  return i == 0 ? Vector<n>(-M.rowwise().sum()) : Vector<n>(M.col(i - 1));
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DERIVATIVES_H
