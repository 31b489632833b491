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

#include <algorithm>
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

// D(J) and, if dJ is given, dD/dJ (NaN where D is infinite) in 3D from the separated eigenvalues
// l of A = J^T J (svd.h): the singular vectors only through Sylvester's formula.
template <class Measure>
double distortion_from_gram(const Measure& measure, const Matrix<3>& J, const Matrix<3>& A, const Vector<3>& l,
                            Matrix<3>* dJ, Vector<3>* sigma)
{
  const Vector<3> s = signed_singular_values_from_gram(J, l);
  const double value = measure.template value<3>(s);
  if(sigma) *sigma = s;
  if(dJ) {
    if(value < std::numeric_limits<double>::infinity()) *dJ = gram_spectral_product(J, A, l, s, measure.template gradient<3>(s));
    else dJ->setConstant(std::numeric_limits<double>::quiet_NaN());
  }
  return value;
}

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
      Matrix<3> A;
      Vector<3> l;
      if(separated_gram_eigenvalues(J, A, l)) {
        value = distortion_from_gram(measure, J, A, l, &dJ, sigma);
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

// dD/dx_i of cell c from dD/dJ: with G = dD/dJ Dm^-T, column i-1 of G for vertex i and minus
// their sum for vertex 0.
template <int n>
void vertex_gradients_from_jacobian_gradient(const Simplicial_map<n>& map, std::size_t c, const Matrix<n>& dJ,
                                             std::array<Vector<n>, n + 1>& vertex_gradients)
{
  const Matrix<n> G = dJ * map.inverse_rest[c].transpose();
  vertex_gradients[0] = -G.rowwise().sum();
  for(int i = 0; i < n; ++i)
    vertex_gradients[i + 1] = G.col(i);
}

/// D(J_c) of cell c of a map and its derivative in the cell's n+1 target positions.
template <int n, class Measure>
double cell_distortion(const Measure& measure, const Simplicial_map<n>& map, std::size_t c,
                       std::array<Vector<n>, n + 1>& vertex_gradients, Vector<n>* sigma = nullptr)
{
  Matrix<n> dJ;
  const double value = cell_distortion<n>(measure, map.jacobian(c), dJ, sigma);
  vertex_gradients_from_jacobian_gradient(map, c, dJ, vertex_gradients);
  return value;
}

/// The kernel on `count` cells of a map at once: values[k] = D(J_c) for c = cell_at(k) and, if
/// given, the vertex gradients and signed singular values as above. In 3D, for measures that need
/// singular values, the Gram eigenvalues of eight cells are solved together (svd.h): one cell's
/// solve is a chain of dependent square roots and divisions, eight independent ones fill the
/// pipeline and the SIMD lanes, for about half the time per cell.
template <int n, class Measure, class CellAt>
void cell_distortions(const Measure& measure, const Simplicial_map<n>& map, std::size_t count, const CellAt& cell_at,
                      double* values, std::array<Vector<n>, n + 1>* vertex_gradients = nullptr, Vector<n>* sigma = nullptr)
{
  constexpr bool batched = n == 3 && !Has_value_without_svd<Measure, n>::value;
  constexpr std::size_t lanes = batched ? 8 : 1;
  using Lanes = Eigen::Array<double, lanes, 1>;
  std::array<Matrix<n>, lanes> J, A;
  Matrix<n> dJ;
  for(std::size_t first = 0; first < count; first += lanes) {
    const std::size_t m = std::min(lanes, count - first);
    for(std::size_t i = 0; i < m; ++i) J[i] = map.jacobian(cell_at(first + i));
    std::array<Lanes, 3> l;
    if constexpr(batched) {
      Lanes a00, a11, a22, a01, a02, a12;
      for(std::size_t i = 0; i < lanes; ++i) {
        A[i].noalias() = J[i < m ? i : 0].transpose() * J[i < m ? i : 0];
        a00[i] = A[i](0, 0), a11[i] = A[i](1, 1), a22[i] = A[i](2, 2), a01[i] = A[i](0, 1), a02[i] = A[i](0, 2), a12[i] = A[i](1, 2);
      }
      l = symmetric_eigenvalues(a00, a11, a22, a01, a02, a12);
    }
    for(std::size_t i = 0; i < m; ++i) {
      const std::size_t k = first + i;
      Vector<n>* s = sigma ? sigma + k : nullptr;
      bool done = false;   // by the batched eigenvalues; otherwise cell by cell
      if constexpr(batched) {
        const Vector<3> li(l[0][i], l[1][i], l[2][i]);
        if((done = are_separated(A[i].trace(), li)))
          values[k] = distortion_from_gram(measure, J[i], A[i], li, vertex_gradients ? &dJ : nullptr, s);
      }
      if(!done) values[k] = vertex_gradients || s ? cell_distortion<n>(measure, J[i], dJ, s) : cell_distortion<n>(measure, J[i]);
      if(vertex_gradients) vertex_gradients_from_jacobian_gradient(map, cell_at(k), dJ, vertex_gradients[k]);
    }
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DISTORTION_H
