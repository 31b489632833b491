// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Signed singular value decomposition of 2x2 and 3x3 Jacobians.
//
// J = U diag(sigma) V^T with U, V proper rotations (det +1), sigma_1 >= ... >= sigma_{n-1} >= |sigma_n|
// and sign(sigma_n) = sign(det J).  Keeping the sign in sigma_n (instead of a reflection in U or V)
// is what lets a measure see an inverted cell (Appendix C of the paper: a regular measure is +inf there).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SVD_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SVD_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n> using Matrix = Eigen::Matrix<double, n, n>;
template <int n> using Vector = Eigen::Matrix<double, n, 1>;

template <int n>
struct Signed_svd
{
  Matrix<n> U, V;
  Vector<n> sigma;
};

template <int n>
Vector<n> not_a_number_vector()
{
  return Vector<n>::Constant(std::numeric_limits<double>::quiet_NaN());
}

// ---------------------------------------------------------------- 2x2, closed form
// With E=(a+d)/2, F=(a-d)/2, G=(c+b)/2, H=(c-b)/2, J is the sum of a similarity (E,H) and an
// anti-similarity (F,G); their magnitudes Q, R give sigma = (Q+R, Q-R) and their angles the two
// rotations.  sigma_2 is taken as det/sigma_1 to avoid the cancellation in Q-R.

inline Vector<2> signed_singular_values(const Matrix<2>& J)
{
  const double E = 0.5 * (J(0, 0) + J(1, 1)), F = 0.5 * (J(0, 0) - J(1, 1));
  const double G = 0.5 * (J(1, 0) + J(0, 1)), H = 0.5 * (J(1, 0) - J(0, 1));
  const double s1 = std::hypot(E, H) + std::hypot(F, G);
  const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
  return Vector<2>(s1, s1 > 0 ? det / s1 : 0.);
}

inline bool signed_svd(const Matrix<2>& J, Signed_svd<2>& out)
{
  if(!J.allFinite()) {
    out.sigma = not_a_number_vector<2>();
    return false;
  }
  const double E = 0.5 * (J(0, 0) + J(1, 1)), F = 0.5 * (J(0, 0) - J(1, 1));
  const double G = 0.5 * (J(1, 0) + J(0, 1)), H = 0.5 * (J(1, 0) - J(0, 1));
  const double s1 = std::hypot(E, H) + std::hypot(F, G);
  const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
  const double a1 = std::atan2(G, F), a2 = std::atan2(H, E);
  const double phi = 0.5 * (a2 + a1), theta = 0.5 * (a2 - a1);
  const double cp = std::cos(phi), sp = std::sin(phi), ct = std::cos(theta), st = std::sin(theta);
  out.U << cp, -sp, sp, cp;
  out.V << ct, st, -st, ct;   // V^T is the rotation by theta
  out.sigma = Vector<2>(s1, s1 > 0 ? det / s1 : 0.);
  return true;
}

// ---------------------------------------------------------------- 3x3
// The closed-form eigen-decomposition of J^T J (Eigen's computeDirect) gives V up to ~sqrt(eps)
// where singular values repeat; one or two sweeps of one-sided Jacobi on B = J V (Hestenes'
// method) make the columns of B orthogonal to machine precision at a few dozen flops per
// rotation; then a Gram-Schmidt QR of the sorted columns gives U and the signed values, as in
// McAdams, Selle, Tamstorf, Teran and Sifakis, "Computing the Singular Value Decomposition of
// 3x3 matrices with minimal branching and elementary floating point operations" (2011).

inline Vector<3> any_unit_orthogonal(const Vector<3>& u)
{
  const Vector<3> a = std::abs(u[0]) < 0.9 ? Vector<3>::UnitX() : Vector<3>::UnitY();
  return u.cross(a).normalized();
}

// Rotates columns i and j of B (and V) to make them orthogonal; returns their squared cosine before.
inline double jacobi_rotation(Matrix<3>& B, Matrix<3>& V, int i, int j)
{
  const double alpha = B.col(i).squaredNorm(), beta = B.col(j).squaredNorm(), gamma = B.col(i).dot(B.col(j));
  const double cosine2 = gamma * gamma / (alpha * beta);
  if(!(cosine2 > 1e-32)) return 0;
  const double zeta = (beta - alpha) / (2 * gamma);
  const double t = (zeta >= 0 ? 1. : -1.) / (std::abs(zeta) + std::sqrt(1 + zeta * zeta));
  const double c = 1 / std::sqrt(1 + t * t), s = c * t;
  for(Matrix<3>* M : {&B, &V}) {
    const Vector<3> a = M->col(i), b = M->col(j);
    M->col(i) = c * a - s * b;
    M->col(j) = s * a + c * b;
  }
  return cosine2;
}

inline bool signed_svd(const Matrix<3>& J, Signed_svd<3>& out)
{
  if(!J.allFinite()) {
    out.sigma = not_a_number_vector<3>();
    return false;
  }
  Eigen::SelfAdjointEigenSolver<Matrix<3>> es;
  es.computeDirect(J.transpose() * J, Eigen::ComputeEigenvectors);
  Matrix<3>& V = out.V;
  // Descending eigenvalues; where they repeat the closed-form vectors are not quite orthogonal.
  V.col(0) = es.eigenvectors().col(2).normalized();
  V.col(1) = (es.eigenvectors().col(1) - V.col(0).dot(es.eigenvectors().col(1)) * V.col(0)).normalized();
  V.col(2) = V.col(0).cross(V.col(1));
  Matrix<3> B = J * V;
  // Well-separated eigenvalues have accurate closed-form eigenvectors (error ~ eps / relative gap):
  // no polish needed. Otherwise Jacobi, which converges quadratically: after a sweep whose largest
  // cosine was below 1e-8, the next one would only change the columns at the 1e-16 level.
  const Vector<3>& l = es.eigenvalues();
  const bool separated = l[0] > 1e-4 * l[2] && l[1] - l[0] > 1e-2 * l[2] && l[2] - l[1] > 1e-2 * l[2];
  for(int sweep = 0; sweep < 3 && !separated; ++sweep) {
    double largest = jacobi_rotation(B, V, 0, 1);
    largest = std::max(largest, jacobi_rotation(B, V, 0, 2));
    largest = std::max(largest, jacobi_rotation(B, V, 1, 2));
    if(!(largest > 1e-16)) break;
  }
  // Sort the columns by decreasing norm, then make V a rotation (the sign goes to sigma_3 below).
  Vector<3> norms = B.colwise().squaredNorm().transpose();
  for(int i = 0; i < 2; ++i)
    for(int j = 2; j > i; --j)
      if(norms[j] > norms[j - 1]) {
        std::swap(norms[j], norms[j - 1]);
        B.col(j).swap(B.col(j - 1));
        V.col(j).swap(V.col(j - 1));
      }
  if(V.determinant() < 0) { V.col(2) *= -1; B.col(2) *= -1; }

  Matrix<3>& U = out.U;
  const double s1 = B.col(0).norm();
  if(!(s1 > 0)) { U.setIdentity(); out.sigma.setZero(); return true; }
  U.col(0) = B.col(0) / s1;
  const Vector<3> b2 = B.col(1) - U.col(0).dot(B.col(1)) * U.col(0);
  const double s2 = b2.norm();
  U.col(1) = s2 > 0 ? Vector<3>(b2 / s2) : any_unit_orthogonal(U.col(0));
  U.col(2) = U.col(0).cross(U.col(1));
  out.sigma = Vector<3>(s1, s2, U.col(2).dot(B.col(2)));
  return true;
}

// Values only: the closed-form eigenvalues of J^T J (a third of the full decomposition's cost) are
// accurate to a few ulps of sigma_1 when the eigenvalues are well apart and none is tiny; otherwise
// (nearly conformal or nearly flat cells) the full decomposition above is used.
inline Vector<3> signed_singular_values(const Matrix<3>& J)
{
  Eigen::SelfAdjointEigenSolver<Matrix<3>> es;
  es.computeDirect(J.transpose() * J, Eigen::EigenvaluesOnly);
  const Vector<3>& l = es.eigenvalues();   // ascending
  if(l[0] > 1e-4 * l[2] && l[1] - l[0] > 1e-2 * l[2] && l[2] - l[1] > 1e-2 * l[2]) {
    const double s1 = std::sqrt(l[2]), s2 = std::sqrt(l[1]);
    return Vector<3>(s1, s2, J.determinant() / (s1 * s2));
  }
  Signed_svd<3> svd;
  signed_svd(J, svd);
  return svd.sigma;
}

// ---------------------------------------------------------------- reference: Eigen's JacobiSVD
// Kept for the accuracy tests and the benchmark that chose the closed forms above.

template <int n>
bool signed_svd_jacobi(const Matrix<n>& J, Signed_svd<n>& out)
{
  if(!J.allFinite()) {
    out.sigma = not_a_number_vector<n>();
    return false;
  }
  Eigen::JacobiSVD<Matrix<n>> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  out.U = svd.matrixU();
  out.V = svd.matrixV();
  out.sigma = svd.singularValues();
  // Move reflections into the last singular value so that U and V are rotations.
  if(out.U.determinant() < 0) { out.U.col(n - 1) *= -1; out.sigma[n - 1] *= -1; }
  if(out.V.determinant() < 0) { out.V.col(n - 1) *= -1; out.sigma[n - 1] *= -1; }
  return true;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SVD_H
