// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Signed singular value decomposition of 2x2 and 3x3 Jacobians.
//
// J = U diag(sigma) V^T with U, V proper rotations (det +1), sigma_1 >= ... >= sigma_{n-1} >= |sigma_n|
// and sign(sigma_n) = sign(det J).  Keeping the sign in sigma_n (instead of a reflection in U or V)
// is what lets a measure see an inverted cell (Appendix C of the paper: a regular measure is +inf there).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SVD_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SVD_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/number_types.h>
#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n>
struct Signed_svd
{
  Matrix<n> U, V;
  Vector<n> sigma;
};

template <int n>
Vector<n> not_a_number_vector()
{
  return Vector<n>::Constant(not_a_number);
}

// ---------------------------------------------------------------- 2x2, closed form
// J = [E -H; H E] + [F G; G -F], the sum of a similarity and an anti-similarity with
// E=(a+d)/2, F=(a-d)/2, G=(c+b)/2, H=(c-b)/2; their magnitudes Q, R give sigma = (Q+R, Q-R) and
// their angles the two rotations. sigma_2 is taken as det/sigma_1 to avoid the cancellation in Q-R.

// |(a, b)|: std::hypot is several times slower than a square root; it is kept only where the
// sum of squares would overflow or underflow.
inline double magnitude(double a, double b)
{
  const double m2 = a * a + b * b;
  return m2 < 1e300 && m2 > 1e-300 ? std::sqrt(m2) : std::hypot(a, b);
}

struct Conformal_parts
{
  double E, F, G, H, Q, R;
  explicit Conformal_parts(const Matrix<2>& J)
    : E(0.5 * (J(0, 0) + J(1, 1))), F(0.5 * (J(0, 0) - J(1, 1))),
      G(0.5 * (J(1, 0) + J(0, 1))), H(0.5 * (J(1, 0) - J(0, 1))), Q(magnitude(E, H)), R(magnitude(F, G)) {}
  Vector<2> signed_singular_values(const Matrix<2>& J) const
  {
    const double s1 = Q + R;
    return Vector<2>(s1, s1 > 0 ? (J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0)) / s1 : 0.);
  }
};

inline Vector<2> signed_singular_values(const Matrix<2>& J) { return Conformal_parts(J).signed_singular_values(J); }

inline bool signed_svd(const Matrix<2>& J, Signed_svd<2>& out)
{
  if(!J.allFinite()) {
    out.sigma = not_a_number_vector<2>();
    return false;
  }
  const Conformal_parts c(J);
  const double a1 = std::atan2(c.G, c.F), a2 = std::atan2(c.H, c.E);
  const double phi = 0.5 * (a2 + a1), theta = 0.5 * (a2 - a1);
  const double cp = std::cos(phi), sp = std::sin(phi), ct = std::cos(theta), st = std::sin(theta);
  out.U << cp, -sp, sp, cp;
  out.V << ct, st, -st, ct;   // V^T is the rotation by theta
  out.sigma = c.signed_singular_values(J);
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

// The eigenvalues l_1 >= l_2 >= l_3 of a symmetric 3 x 3 matrix A (the Gram matrix J^T J of a
// Jacobian), for one matrix (T = double) or for several at once (T = an Eigen array: the lanes are
// independent chains of square roots and divisions that fill the pipeline one chain leaves idle).
// They are the roots of A's characteristic cubic: with q = tr A / 3 and p^2 = |A - q I|^2 / 6,
// those of B = (A - q I) / p are the roots t of t^3 - 3t - 2r, r = det B / 2 (Smith, "Eigenvalues
// of a symmetric 3 x 3 matrix", CACM 1961, solves it with acos and cos). Here the largest root
// and the smallest, -t(-r), come from a polynomial seed and one Halley step: no trigonometric call,
// and exact to a few ulps of l_1 where the roots are apart, which `are_separated` checks (l is
// meaningless otherwise, e.g. NaN when A = q I).
inline double clamp_unit(double x) { return std::clamp(x, -1., 1.); }
template <class Lanes> Lanes clamp_unit(const Lanes& x) { return x.max(-1.).min(1.); }

template <class T>
std::array<T, 3> symmetric_eigenvalues(const T& a00, const T& a11, const T& a22, const T& a01, const T& a02, const T& a12)
{
  using std::sqrt;
  // The largest root of t^3 - 3t - 2r is 1 + e with e^2 (3 + e) = w^2, w = sqrt(2 + 2r); e is
  // analytic in w on [0, 2], and this degree-7 least-squares fit in x = w - 1 is within 1.2e-7 of
  // it (Estrin's scheme keeps the dependency chain short).
  const auto seed = [](const T& w) -> T {
    const T x = w - 1., x2 = x * x, x4 = x2 * x2;
    return 1.53208891261343982 + 0.49481809700031087 * x + (-0.031019315777351064 + 0.0049332218603241364 * x) * x2 +
           ((-0.0010031790380941544 + 0.00023087870698921864 * x) + (-6.6317914159677585e-05 + 1.7787376525066081e-05 * x) * x2) * x4;
  };
  const auto halley = [](const T& t, const T& r) -> T {
    const T t2 = t * t, f = t * (t2 - 3.) - 2. * r, df = 3. * (t2 - 1.);
    return t - 2. * f * df / (2. * df * df - 6. * f * t);
  };
  const T q = (a00 + a11 + a22) * (1. / 3), b0 = a00 - q, b1 = a11 - q, b2 = a22 - q;
  const T p2 = (b0 * b0 + b1 * b1 + b2 * b2 + 2. * (a01 * a01 + a02 * a02 + a12 * a12)) * (1. / 6);
  const T p = sqrt(p2);
  const T det_b = b0 * (b1 * b2 - a12 * a12) - a01 * (a01 * b2 - a12 * a02) + a02 * (a01 * a12 - b1 * a02);
  const T r = clamp_unit(T(det_b / (2. * p2 * p)));
  const T t1 = halley(seed(sqrt(2. + 2. * r)), r), t3 = -halley(seed(sqrt(2. - 2. * r)), -r);
  return {q + p * t1, q - p * (t1 + t3), q + p * t3};
}

// Whether the eigenvalues l of a Gram matrix of the given trace are apart enough for the fast
// paths below, and the trace is far from overflow. The values alone (`for_values`) need gaps above
// 1e-2 of the spread l_1 - l_3: the roots of the normalized cubic are then simple, and each l_i is
// within a few ulps of l_1 even where all three cluster (a near-conformal cell). The singular
// vectors' products (gram_spectral_product) divide by the gaps: they need gaps above 1e-2 of l_1.
// Both need l_3 > 1e-4 l_1 (sigma_2 from sqrt(l_2)).
inline bool are_separated(double trace, const Vector<3>& l, bool for_values = false)
{
  const double scale = for_values ? l[0] - l[2] : l[0];
  return trace > 1e-100 && trace < 1e100 && l[0] - l[1] > 1e-2 * scale && l[1] - l[2] > 1e-2 * scale && l[2] > 1e-4 * l[0];
}

inline bool separated_gram_eigenvalues(const Matrix<3>& J, Matrix<3>& A, Vector<3>& l, bool for_values = false)
{
  A.noalias() = J.transpose() * J;
  const std::array<double, 3> roots = symmetric_eigenvalues(A(0, 0), A(1, 1), A(2, 2), A(0, 1), A(0, 2), A(1, 2));
  l = Vector<3>(roots[0], roots[1], roots[2]);
  return are_separated(A.trace(), l, for_values);
}

// The signed singular values of J from the separated eigenvalues l of J^T J: sigma_3 from the
// determinant, so that it carries its sign.
inline Vector<3> signed_singular_values_from_gram(const Matrix<3>& J, const Vector<3>& l)
{
  const double s1 = std::sqrt(l[0]), s2 = std::sqrt(l[1]);
  return Vector<3>(s1, s2, J.determinant() / (s1 * s2));
}

// Values only: from the separated eigenvalues (far cheaper than the full decomposition),
// otherwise the full decomposition.
inline Vector<3> signed_singular_values(const Matrix<3>& J)
{
  Matrix<3> A;
  Vector<3> l;
  if(separated_gram_eigenvalues(J, A, l, true)) return signed_singular_values_from_gram(J, l);
  Signed_svd<3> svd;
  signed_svd(J, svd);
  return svd.sigma;
}

// U diag(g) V^T from the separated eigenvalues l of A = J^T J, without the singular vectors:
// u_i v_i^T = J v_i v_i^T / sigma_i, so U diag(g) V^T = J f(A) for the function f with
// f(l_i) = g_i / sigma_i, which on A's spectrum is the quadratic interpolating these three
// values (Sylvester's formula, here in Newton's divided-difference form). Its rounding error is
// that of the divided differences, below 1e-11 relative under the separation above.
inline Matrix<3> gram_spectral_product(const Matrix<3>& J, const Matrix<3>& A, const Vector<3>& l,
                                       const Vector<3>& sigma, const Vector<3>& g)
{
  const Vector<3> h = g.cwiseQuotient(sigma);
  const double d01 = (h[1] - h[0]) / (l[1] - l[0]), d12 = (h[2] - h[1]) / (l[2] - l[1]);
  const double d012 = (d12 - d01) / (l[2] - l[0]);
  Matrix<3> M0 = A, M1 = A;
  M0.diagonal().array() -= l[0];
  M1.diagonal().array() -= l[1];
  Matrix<3> F = d012 * (M0 * M1) + d01 * M0;
  F.diagonal().array() += h[0];
  return J * F;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SVD_H
