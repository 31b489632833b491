// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
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

#include <CGAL/license/Distortion_optimization.h>

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

// The nearest positive semi-definite matrix to p (its negative eigenvalues dropped), in place.
// Where p already is one, as the Hessian in s of a separable convex measure (symmetric Dirichlet)
// always is, Sylvester's test on its leading minors spares the eigensolve, a notable share of a
// Newton run. Eigen's closed form otherwise (its vectors are orthonormal to about
// sqrt(eps) where eigenvalues nearly repeat: the result stays positive semi-definite); the
// iterative solver for a p whose trace overflows, where the closed form gives NaN.
template <int n>
void drop_negative_eigenvalues(Singular_values_hessian<n>& p)
{
  if(p(0, 0) > 0) {
    if constexpr(n == 2) {
      if(p.determinant() >= 0) return;
    } else {
      if(p(0, 0) * p(1, 1) - p(1, 0) * p(1, 0) > 0 && p.determinant() >= 0) return;
    }
  }
  Eigen::SelfAdjointEigenSolver<Singular_values_hessian<n>> eigen;
  eigen.computeDirect(p);
  if(!eigen.eigenvalues().allFinite()) eigen.compute(p);
  p = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.).asDiagonal() * eigen.eigenvectors().transpose();
}

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
  const auto w_of = [&](const Matrix<n>& Q) {
    Eigen::Matrix<double, n * (n + 1), 1> w;
    for(int i = 0; i <= n; ++i) w.template segment<n>(n * i) = Q * G.col(i);
    return w;
  };
  const auto add = [&](double lambda, const Matrix<n>& Q) {
    if(!project || lambda > 0) H.template selfadjointView<Eigen::Lower>().rankUpdate(w_of(Q), lambda);
  };
  // The scaling modes U diag(a) V^T, whose w is linear in a: together, W p W^T with W's columns
  // the w of u_k v_k^T and p = h with its negative eigenvalues dropped.
  Singular_values_hessian<n> p = h.template selfadjointView<Eigen::Lower>();   // as an eigensolver reads h
  if(project) drop_negative_eigenvalues<n>(p);
  Eigen::Matrix<double, n * (n + 1), n> W;
  for(int k = 0; k < n; ++k) W.col(k) = w_of(svd.U.col(k) * svd.V.col(k).transpose());
  const Eigen::Matrix<double, n * (n + 1), n> Wp = W * p;
  H += Wp.lazyProduct(W.transpose());   // fixed-size and unrolled: a triangular product takes Eigen's GEMM path
  const double root_half = std::sqrt(0.5);
  for(int i = 0; i < n; ++i)
    for(int j = i + 1; j < n; ++j) {
      const Matrix<n> a = svd.U.col(i) * svd.V.col(j).transpose(), b = svd.U.col(j) * svd.V.col(i).transpose();
      add((d[i] + d[j]) / (s[i] + s[j]), root_half * (a - b));
      // Where s_i and s_j nearly coincide, the difference quotient loses its digits: its limit
      // D_ii - D_ij takes over for a measure smooth and symmetric in s_i, s_j. A maximum such as
      // K or the condition number has a kink there instead, D_i - D_j stays apart from 0 and the
      // quotient grows without bound: it is taken at the smallest gap resolved.
      const double gap = s[i] - s[j], resolved = 1e-6 * (s[i] + s[j]);
      add(gap > resolved ? (d[i] - d[j]) / gap : std::max(h(i, i) - h(i, j), (d[i] - d[j]) / resolved), root_half * (a + b));
    }
  // Exactly symmetric: the lower triangle, where every mode was added, replaces the upper.
  H.template triangularView<Eigen::StrictlyUpper>() = H.transpose();
  return true;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_HESSIAN_H
