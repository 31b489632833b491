// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The per-cell kernel: D(J) and its exact derivative dD/dJ = U diag(dD/dsigma) V^T.
// Measures that can be written with invariants of J (norm, determinant, inverse) skip the SVD.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DISTORTION_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DISTORTION_H

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>
#include <CGAL/Distortion_optimization/internal/svd.h>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <class Measure, int n, class = void>
struct Has_value_without_svd : std::false_type {};

template <class Measure, int n>
struct Has_value_without_svd<Measure, n,
  std::void_t<decltype(std::declval<const Measure&>().template value_without_svd<n>(
    std::declval<const Matrix<n>&>(), static_cast<Matrix<n>*>(nullptr)))>> : std::true_type {};

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

/// D(J). NaN when J has a non-finite entry, so that callers can report it (never silently +inf).
template <int n, class Measure>
double cell_distortion(const Measure& measure, const Matrix<n>& J)
{
  if(!J.allFinite())
    return not_a_number;
  if constexpr(Has_value_without_svd<Measure, n>::value)
    return measure.template value_without_svd<n>(J, nullptr);
  else
    return measure.template value<n>(signed_singular_values(J));
}

/// D(J) and dD/dJ. Where D is +inf (an inverted cell under a normalized measure) or J is not
/// finite, dJ is NaN. If `sigma` is given it receives the signed singular values of J.
template <int n, class Measure>
double cell_distortion(const Measure& measure, const Matrix<n>& J, Matrix<n>& dJ, Vector<n>* sigma = nullptr)
{
  double value = not_a_number;
  if(J.allFinite()) {
    if constexpr(Has_value_without_svd<Measure, n>::value) {
      value = measure.template value_without_svd<n>(J, &dJ);
      if(sigma) *sigma = signed_singular_values(J);
    } else if constexpr(n == 2) {
      // With J = S + A, S = [E -H; H E] and A = [F G; G -F] (svd.h): dQ/dJ = S / 2Q and
      // dR/dJ = A / 2R, so dD/dJ = (g1 + g2) S / 2Q + (g1 - g2) A / 2R needs no angle.
      const Conformal_parts p(J);
      const Vector<2> s = p.signed_singular_values(J);
      value = measure.template value<2>(s);
      if(sigma) *sigma = s;
      if(value < std::numeric_limits<double>::infinity()) {
        const Vector<2> g = measure.template gradient<2>(s);
        const double a = p.Q > 0 ? (g[0] + g[1]) / (2 * p.Q) : 0., b = p.R > 0 ? (g[0] - g[1]) / (2 * p.R) : 0.;
        dJ << a * p.E + b * p.F, -a * p.H + b * p.G,
              a * p.H + b * p.G,  a * p.E - b * p.F;
      }
    } else {
      // 3D: the singular vectors only through Sylvester's formula where the values are apart.
      Matrix<3> A;
      Vector<3> l;
      if(separated_gram_eigenvalues(J, A, l)) {
        const double s1 = std::sqrt(l[0]), s2 = std::sqrt(l[1]);
        const Vector<3> s(s1, s2, J.determinant() / (s1 * s2));
        value = measure.template value<3>(s);
        if(sigma) *sigma = s;
        if(value < std::numeric_limits<double>::infinity())
          dJ = gram_spectral_product(J, A, l, s, measure.template gradient<3>(s));
      } else {
        Signed_svd<3> svd;
        signed_svd(J, svd);
        value = measure.template value<3>(svd.sigma);
        if(sigma) *sigma = svd.sigma;
        if(value < std::numeric_limits<double>::infinity())
          dJ.noalias() = svd.U * measure.template gradient<3>(svd.sigma).asDiagonal() * svd.V.transpose();
      }
    }
  }
  if(!(value < std::numeric_limits<double>::infinity()))
    dJ.setConstant(not_a_number);
  return value;
}

/// D(J_c) of cell c of a map and its derivative in the cell's n+1 target positions:
/// with G = dD/dJ Dm^-T, dD/dx_i is column i-1 of G and dD/dx_0 = -(sum of the columns).
template <int n, class Measure>
double cell_distortion(const Measure& measure, const Simplicial_map<n>& map, std::size_t c,
                       std::array<Vector<n>, n + 1>& vertex_gradients, Vector<n>* sigma = nullptr)
{
  Matrix<n> dJ;
  const double value = cell_distortion<n>(measure, map.jacobian(c), dJ, sigma);
  const Matrix<n> G = dJ * map.inverse_rest[c].transpose();
  vertex_gradients[0] = -G.rowwise().sum();
  for(int i = 0; i < n; ++i)
    vertex_gradients[i + 1] = G.col(i);
  return value;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DISTORTION_H
