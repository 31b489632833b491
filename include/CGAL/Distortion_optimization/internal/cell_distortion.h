// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The per-cell kernel: D(J) and its exact derivative dD/dJ = U diag(dD/dsigma) V^T.
// Measures that can be written with invariants of J (norms of J and of its cofactor matrix,
// determinant) skip the SVD and evaluate several cells at once, one per SIMD lane (number_types.h).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DISTORTION_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DISTORTION_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/number_types.h>
#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>
#include <CGAL/Distortion_optimization/internal/measure_kernel.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>
#include <CGAL/Distortion_optimization/internal/svd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <class Measure, int n, class = void>
struct Has_invariant_form : std::false_type {};

template <class Measure, int n>
struct Has_invariant_form<Measure, n,
  std::void_t<decltype(std::declval<const Measure&>().template value_of_invariants<n, double>(
    std::declval<const Jacobian_invariants<double>&>(), static_cast<Jacobian_invariants<double>*>(nullptr)))>> : std::true_type {};

// D(J) and, if dJ is given, dD/dJ through the measure's invariant form, for one cell (T = double)
// or one cell per lane: NaN where J has a non-finite entry, +inf where a normalized measure sees
// det J <= 0 (dJ is then meaningless; callers replace it by NaN). The chain rule needs
// d|J|^2/dJ = 2J, d(det J)/dJ = cof J and d|cof J|^2/dJ, which is 2J in 2D (cof J is J turned a
// quarter) and 2(|J|^2 J - J J^T J) in 3D (there |cof J|^2 = (|J|^4 - |J^T J|^2) / 2).
template <int n, class T, class Measure>
T distortion_from_invariants(const Measure& measure, bool normalized, const T (&J)[n][n], T (*dJ)[n])
{
  T C[n][n];
  cofactor_matrix<n>([&](int r, int c) { return J[r][c]; }, C);
  Jacobian_invariants<T> I{T{}, T{}, T{}}, dI;
  for(int r = 0; r < n; ++r)
    for(int c = 0; c < n; ++c) {
      I.norm2 += J[r][c] * J[r][c];
      I.cofactor_norm2 += C[r][c] * C[r][c];
    }
  for(int c = 0; c < n; ++c) I.det += J[0][c] * C[0][c];
  T value = measure.template value_of_invariants<n>(I, dJ ? &dI : nullptr);
  if(normalized) value = I.det > 0. ? value : lanes::broadcast<T>(infinity);
  value = I.norm2 * 0. == 0. ? value : lanes::broadcast<T>(not_a_number);   // |J|^2 is finite iff J is (or beyond 1e154)
  if(dJ) {
    const T a = 2. * (n == 2 ? dI.norm2 + dI.cofactor_norm2 : dI.norm2);
    for(int r = 0; r < n; ++r)
      for(int c = 0; c < n; ++c) dJ[r][c] = a * J[r][c] + dI.det * C[r][c];
    if constexpr(n == 3) {
      if(lanes::any_nonzero(dI.cofactor_norm2)) {
        T A[3][3];   // J^T J
        for(int r = 0; r < 3; ++r)
          for(int c = r; c < 3; ++c) A[r][c] = A[c][r] = J[0][r] * J[0][c] + J[1][r] * J[1][c] + J[2][r] * J[2][c];
        const T b = 2. * dI.cofactor_norm2;
        for(int r = 0; r < 3; ++r)
          for(int c = 0; c < 3; ++c)
            dJ[r][c] += b * (I.norm2 * J[r][c] - (J[r][0] * A[0][c] + J[r][1] * A[1][c] + J[r][2] * A[2][c]));
      }
    }
  }
  return value;
}

// The same on an Eigen matrix (one cell).
template <int n, class Measure>
double distortion_from_invariants(const Measure& measure, const Matrix<n>& J, Matrix<n>* dJ)
{
  double j[n][n], dj[n][n];
  for(int r = 0; r < n; ++r)
    for(int c = 0; c < n; ++c) j[r][c] = J(r, c);
  const double value = distortion_from_invariants<n>(measure, measure.is_normalized(), j, dJ ? dj : nullptr);
  if(dJ)
    for(int r = 0; r < n; ++r)
      for(int c = 0; c < n; ++c) (*dJ)(r, c) = dj[r][c];
  return value;
}

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
    if(value < infinity) *dJ = gram_spectral_product(J, A, l, s, measure.template gradient<3>(s));
    else dJ->setConstant(not_a_number);
  }
  return value;
}

/// D(J) of one Jacobian. NaN when J has a non-finite entry, so that callers can report it (never
/// silently +inf).
template <int n, class Measure>
double jacobian_distortion(const Measure& measure, const Matrix<n>& J)
{
  if constexpr(measures_internal::is_erased<Measure>)
    return measure.template kernel<n>().jacobian_distortion(J, nullptr, nullptr);
  else if constexpr(Has_invariant_form<Measure, n>::value)
    return distortion_from_invariants<n>(measure, J, nullptr);
  else if(!J.allFinite())
    return not_a_number;
  else
    return measure.template value<n>(signed_singular_values(J));
}

/// D(J) and dD/dJ. Where D is +inf (an inverted cell under a normalized measure) or J is not
/// finite, dJ is NaN. If `sigma` is given it receives the signed singular values of J.
template <int n, class Measure>
double jacobian_distortion(const Measure& measure, const Matrix<n>& J, Matrix<n>& dJ, Vector<n>* sigma = nullptr)
{
  if constexpr(measures_internal::is_erased<Measure>)
    return measure.template kernel<n>().jacobian_distortion(J, &dJ, sigma);
  double value = not_a_number;
  if(J.allFinite()) {
    if constexpr(Has_invariant_form<Measure, n>::value) {
      value = distortion_from_invariants<n>(measure, J, &dJ);
      if(sigma) *sigma = signed_singular_values(J);
    } else if constexpr(n == 2) {
      // With J = S + A, S = [E -H; H E] and A = [F G; G -F] (svd.h): dQ/dJ = S / 2Q and
      // dR/dJ = A / 2R, so dD/dJ = (g1 + g2) S / 2Q + (g1 - g2) A / 2R needs no angle.
      const Conformal_parts p(J);
      const Vector<2> s = p.signed_singular_values(J);
      value = measure.template value<2>(s);
      if(sigma) *sigma = s;
      if(value < infinity) {
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
        if(value < infinity)
          dJ.noalias() = svd.U * measure.template gradient<3>(svd.sigma).asDiagonal() * svd.V.transpose();
      }
    }
  }
  if(!(value < infinity))
    dJ.setConstant(not_a_number);
  return value;
}

// dD/dx_i of cell c from dD/dJ (cell_derivatives.h).
template <int n>
void vertex_gradients_from_jacobian_gradient(const Simplicial_map<n>& map, std::size_t c, const Matrix<n>& dJ,
                                             std::array<Vector<n>, n + 1>& vertex_gradients)
{
  const Matrix<n> G = dJ * map.inverse_rest[c].transpose();
  for(int i = 0; i <= n; ++i) vertex_gradients[i] = vertex_derivative(G, i);
}

// cell_distortions for measures with an invariant form: each lane gathers one cell's target edges
// Ds and Dm^-1, then J = Ds Dm^-1, D, dD/dJ and G = dD/dJ Dm^-T are computed on all lanes at once.
template <int n, class Measure, class CellAt>
void distortions_from_invariants(const Measure& measure, const Simplicial_map<n>& map, std::size_t count, const CellAt& cell_at,
                                 double* values, std::array<Vector<n>, n + 1>* vertex_gradients, Vector<n>* sigma)
{
  using T = lanes::Cell_lanes;
  constexpr int width = lanes::count<T>;
  const bool normalized = measure.is_normalized();
  for(std::size_t first = 0; first < count; first += width) {
    const int m = static_cast<int>(std::min<std::size_t>(width, count - first));
    T X[n + 1][n], B[n][n], Ds[n][n], J[n][n], dJ[n][n];
    for(int l = 0; l < width; ++l) {   // lanes past the count repeat the first cell
      const std::size_t c = cell_at(first + (l < m ? l : 0));
      for(int j = 0; j <= n; ++j) {
        const Vector<n>& x = map.target[map.cells[c][j]];
        for(int i = 0; i < n; ++i) lanes::set(X[j][i], l, x[i]);
      }
      for(int j = 0; j < n; ++j)
        for(int i = 0; i < n; ++i) lanes::set(B[i][j], l, map.inverse_rest[c](i, j));
    }
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) Ds[i][j] = X[j + 1][i] - X[0][i];
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j) {
        J[i][j] = Ds[i][0] * B[0][j];
        for(int k = 1; k < n; ++k) J[i][j] += Ds[i][k] * B[k][j];
      }
    const T value = distortion_from_invariants<n>(measure, normalized, J, vertex_gradients ? dJ : nullptr);
    for(int l = 0; l < m; ++l) values[first + l] = lanes::get(value, l);
    if(vertex_gradients) {
      T G[n][n + 1];   // vertex_derivative's lane form: dD/dJ Dm^-T in columns 1..n, minus their sum in column 0
      const auto finite = value < infinity;
      for(int i = 0; i < n; ++i) {
        G[i][0] = T{};
        for(int j = 0; j < n; ++j) {
          G[i][j + 1] = dJ[i][0] * B[j][0];
          for(int k = 1; k < n; ++k) G[i][j + 1] += dJ[i][k] * B[j][k];
          G[i][j + 1] = finite ? G[i][j + 1] : lanes::broadcast<T>(not_a_number);
          G[i][0] -= G[i][j + 1];
        }
      }
      for(int l = 0; l < m; ++l)
        for(int j = 0; j <= n; ++j)
          for(int i = 0; i < n; ++i) vertex_gradients[first + l][j][i] = lanes::get(G[i][j], l);
    }
    if(sigma)
      for(int l = 0; l < m; ++l) {
        Matrix<n> Jl;
        for(int i = 0; i < n; ++i)
          for(int j = 0; j < n; ++j) Jl(i, j) = lanes::get(J[i][j], l);
        if(Jl.allFinite()) sigma[first + l] = signed_singular_values(Jl);
      }
  }
}

// cell_distortions for measures that need singular values: in 3D, eight cells' Gram eigenvalues
// at once, then each cell from them (or by its full SVD where they are too close).
template <int n, class Measure, class CellAt>
void distortions_from_singular_values(const Measure& measure, const Simplicial_map<n>& map, std::size_t count, const CellAt& cell_at,
                                      double* values, std::array<Vector<n>, n + 1>* vertex_gradients, Vector<n>* sigma)
{
  constexpr bool batched = n == 3;
  constexpr std::size_t width = batched ? 8 : 1;
  using Lanes = Eigen::Array<double, width, 1>;
  std::array<Matrix<n>, width> J, A;
  Matrix<n> dJ;
  for(std::size_t first = 0; first < count; first += width) {
    const std::size_t m = std::min(width, count - first);
    for(std::size_t i = 0; i < m; ++i) J[i] = map.jacobian(cell_at(first + i));
    std::array<Lanes, 3> l;
    if constexpr(batched) {
      Lanes a00, a11, a22, a01, a02, a12;
      for(std::size_t i = 0; i < width; ++i) {
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
        if((done = are_separated(A[i].trace(), li, !vertex_gradients)))
          values[k] = distortion_from_gram(measure, J[i], A[i], li, vertex_gradients ? &dJ : nullptr, s);
      }
      if(!done) values[k] = vertex_gradients || s ? jacobian_distortion<n>(measure, J[i], dJ, s) : jacobian_distortion<n>(measure, J[i]);
      if(vertex_gradients) vertex_gradients_from_jacobian_gradient(map, cell_at(k), dJ, vertex_gradients[k]);
    }
  }
}

/// The kernel on `count` cells of a map at once: values[k] = D(J_c) for c = cell_at(k) and, if
/// given, the vertex gradients and signed singular values as above. Measures with an invariant form
/// take the lanes above. In 3D, for the others, the Gram eigenvalues of eight cells are solved
/// together (svd.h): one cell's solve is a chain of dependent square roots and divisions, eight
/// independent ones fill the pipeline and the SIMD lanes, for about half the time per cell.
template <int n, class Measure, class CellAt>
void cell_distortions(const Measure& measure, const Simplicial_map<n>& map, std::size_t count, const CellAt& cell_at,
                      double* values, std::array<Vector<n>, n + 1>* vertex_gradients = nullptr, Vector<n>* sigma = nullptr)
{
  if constexpr(measures_internal::is_erased<Measure>) {
    // The measure's own kernel, on the cells listed (one virtual call per batch).
    static thread_local std::vector<std::uint32_t> cells;
    cells.resize(count);
    for(std::size_t k = 0; k < count; ++k) cells[k] = static_cast<std::uint32_t>(cell_at(k));
    measure.template kernel<n>().cell_distortions(map, count, cells.data(), values, vertex_gradients, sigma);
  } else if constexpr(Has_invariant_form<Measure, n>::value) {
    distortions_from_invariants<n>(measure, map, count, cell_at, values, vertex_gradients, sigma);
  } else {
    distortions_from_singular_values<n>(measure, map, count, cell_at, values, vertex_gradients, sigma);
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_CELL_DISTORTION_H
