// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A cell's energy Hessian in its vertices, projected to be positive semi-definite: what the
// global step's Newton direction is built from. For a measure D(s) of the singular values of
// J = U diag(s) V^T, the Hessian of D in J has a closed-form eigensystem (Smith, De Goes, Kim,
// "Analytic eigensystems for isotropic distortion energies", ACM TOG 2019): n "scaling" modes
// U diag(a) V^T with a and the eigenvalue from the n x n Hessian of D in s, and for each pair
// i < j a "twist" (u_i v_j^T - u_j v_i^T) / sqrt 2 with eigenvalue (D_i + D_j) / (s_i + s_j)
// and a "flip" (u_i v_j^T + u_j v_i^T) / sqrt 2 with eigenvalue (D_i - D_j) / (s_i - s_j).
// Dropping the negative eigenvalues gives the nearest positive semi-definite Hessian, at the cost
// of one small eigensolve per cell instead of a dense n^2 x n^2 one.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_HESSIAN_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_HESSIAN_H

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>
#include <CGAL/Distortion_optimization/internal/svd.h>

#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n> using Cell_hessian = Eigen::Matrix<double, n * (n + 1), n * (n + 1)>;

// For a cell with Jacobian J = Ds Dm^-1 (`inverse_rest` = Dm^-1) and det J > 0: its Hessian in
// its n + 1 vertices (vertex-major: rows n i .. n i + n - 1 for vertex i), with the negative
// eigenvalues of the Hessian in J dropped when `project`, and its vertex gradients. Returns
// false, with H and gradient unspecified, where the measure's derivatives are not finite (a flat
// or inverted cell).
template <int n, class Measure>
bool cell_hessian(const Measure& measure, const Matrix<n>& J, const Matrix<n>& inverse_rest, Cell_hessian<n>& H,
                  std::array<Vector<n>, n + 1>& gradient, bool project = true)
{
  Signed_svd<n> svd;
  if(!signed_svd(J, svd) || !(svd.sigma[n - 1] > 0)) return false;
  const Vector<n>& s = svd.sigma;
  const Vector<n> d = measure.template gradient<n>(s);
  const Singular_values_hessian<n> h = measure.template hessian<n>(s);
  if(!d.allFinite() || !h.allFinite()) return false;
  // dJ / dx_i = e_a G_i^T for coordinate a of vertex i, with G_i the hat function's gradient.
  const Matrix<n> Mt = inverse_rest.transpose();
  const Matrix<n> dDs = svd.U * d.asDiagonal() * svd.V.transpose() * Mt;
  Eigen::Matrix<double, n, n + 1> G;
  for(int i = 0; i <= n; ++i) {
    G.col(i) = vertex_derivative(Mt, i);
    gradient[i] = vertex_derivative(dDs, i);
  }
  H.setZero();
  // A mode Q of the Hessian in J, with eigenvalue lambda: lambda w w^T with w = dJ/dx : Q.
  const auto add = [&](double lambda, const Matrix<n>& Q) {
    if(project && !(lambda > 0)) return;
    Eigen::Matrix<double, n * (n + 1), 1> w;
    for(int i = 0; i <= n; ++i) w.template segment<n>(n * i) = Q * G.col(i);
    H.template selfadjointView<Eigen::Lower>().rankUpdate(w, lambda);
  };
  // The closed form (its vectors are orthonormal to about sqrt(eps) where eigenvalues nearly
  // repeat: the sum below stays positive semi-definite) takes about half the time of the
  // iterative solver, which was a tenth of a 54K-cell MIPS run. The iterative one stays for an h
  // whose trace overflows, where the closed form gives NaN.
  Eigen::SelfAdjointEigenSolver<Singular_values_hessian<n>> scaling;
  scaling.computeDirect(h);
  if(!scaling.eigenvalues().allFinite()) scaling.compute(h);
  for(int k = 0; k < n; ++k)
    add(scaling.eigenvalues()[k], svd.U * scaling.eigenvectors().col(k).asDiagonal() * svd.V.transpose());
  const double root_half = std::sqrt(0.5);
  for(int i = 0; i < n; ++i)
    for(int j = i + 1; j < n; ++j) {
      const Matrix<n> a = svd.U.col(i) * svd.V.col(j).transpose(), b = svd.U.col(j) * svd.V.col(i).transpose();
      add((d[i] + d[j]) / (s[i] + s[j]), root_half * (a - b));
      // Where s_i and s_j nearly coincide, the difference quotient loses its digits: its limit
      // D_ii - D_ij (for a measure symmetric in s_i, s_j) takes over.
      const double gap = s[i] - s[j];
      add(gap > 1e-6 * (s[i] + s[j]) ? (d[i] - d[j]) / gap : h(i, i) - h(i, j), root_half * (a + b));
    }
  // Exactly symmetric: the modes were added to the lower triangle only.
  H.template triangularView<Eigen::StrictlyUpper>() = H.transpose();
  return true;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_HESSIAN_H
