// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Distortion measures of "Geometry-based distortion measures for space deformation"
// (Naitsat, Saucan, Zeevi), section 2.1: each is a function D(sigma_1, ..., sigma_n) of the
// singular values of the Jacobian of a simplicial map, together with its exact derivative dD/dsigma.

#ifndef CGAL_DISTORTION_OPTIMIZATION_MEASURES_H
#define CGAL_DISTORTION_OPTIMIZATION_MEASURES_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/number_types.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationMeasures
/// Singular values sigma_1 >= ... >= sigma_{n-1} >= |sigma_n| of a Jacobian; sigma_n carries the
/// sign of det J, so sigma_n <= 0 means a degenerate or inverted cell.
template <int n> using Singular_values = Eigen::Matrix<double, n, 1>;

/// \ingroup PkgDistortionOptimizationMeasures
/// The n x n matrix of second derivatives of a measure in the singular values (the optional
/// member `hessian()` of `DistortionMeasure`).
template <int n> using Singular_values_hessian = Eigen::Matrix<double, n, n>;

/// \ingroup PkgDistortionOptimizationMeasures
/// The n x n Jacobian of a simplicial map on one cell.
template <int n> using Jacobian = Eigen::Matrix<double, n, n>;

/// \ingroup PkgDistortionOptimizationMeasures
/// The invariants of a Jacobian through which some measures are written without its SVD:
/// `norm2` = |J|_F^2 = sum of s_i^2, `cofactor_norm2` = |cof J|_F^2 = sum of the products of n-1
/// distinct s_i^2 (so |J^-1|_F^2 = cofactor_norm2 / det^2), `det` = det J = product of the s_i.
template <class T>
struct Jacobian_invariants
{
  T norm2, cofactor_norm2, det;
};

namespace measures_internal {

// x^k for a small constant k (std::pow with a double exponent is many times slower).
template <int k>
double power(double x)
{
  if constexpr(k == 0) return 1.;
  else return x * power<k - 1>(x);
}

// (s_1 ... s_n)^(2/n), the scale of MIPS.
template <int n, class T>
T mean_square_scale(const T& product)
{
  if constexpr(n == 2) return product;
  else return lanes::cbrt(product * product);
}

template <int n>
Singular_values<n> nan_gradient()
{
  return Singular_values<n>::Constant(not_a_number);
}

template <int n>
Singular_values<n> unit(int i)
{
  return Singular_values<n>::Unit(i);
}

// The monomial F = prod s_i^c_i, through which the ratios of singular values below are
// differentiated: dF/ds_i = F c_i / s_i, d2F/ds_i ds_j = F (c_i c_j - c_i delta_ij) / (s_i s_j).
template <int n>
Singular_values<n> monomial_gradient(double F, const Singular_values<n>& c, const Singular_values<n>& s)
{
  return F * c.cwiseQuotient(s);
}
template <int n>
Singular_values_hessian<n> monomial_hessian(double F, const Singular_values<n>& c, const Singular_values<n>& s)
{
  const Singular_values<n> q = c.cwiseQuotient(s);
  Singular_values_hessian<n> h = F * (q * q.transpose());
  h.diagonal() -= F * c.cwiseQuotient(s.cwiseAbs2());
  return h;
}

template <int n>
Singular_values_hessian<n> nan_hessian()
{
  return Singular_values_hessian<n>::Constant(not_a_number);
}

// A measure that is the larger of two monomials of the singular values (K = max(K_I, K_O),
// C = max(s_1, 1/s_n), V = max(det, 1/det)), or one (the condition number): its derivatives are
// those of the monomial that is larger, NaN where s_n <= 0. `Ratio::branch(s)` gives that
// monomial's value and exponents.
template <class Ratio>
struct Monomial_derivatives
{
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    if(!(s[n - 1] > 0)) return nan_gradient<n>();
    const auto [F, c] = Ratio::template branch<n>(s);
    return monomial_gradient<n>(F, c, s);
  }
  template <int n>
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const
  {
    if(!(s[n - 1] > 0)) return nan_hessian<n>();
    const auto [F, c] = Ratio::template branch<n>(s);
    return monomial_hessian<n>(F, c, s);
  }
};

template <class Measure, int n, class = void>
struct Has_laplacian_weight : std::false_type {};
template <class Measure, int n>
struct Has_laplacian_weight<Measure, n,
  std::void_t<decltype(std::declval<const Measure&>().template laplacian_weight<n>(std::declval<const Singular_values<n>&>()))>>
  : std::true_type {};

template <class Measure, int n, class = void>
struct Has_hessian : std::false_type {};
template <class Measure, int n>
struct Has_hessian<Measure, n,
  std::void_t<decltype(std::declval<const Measure&>().template hessian<n>(std::declval<const Singular_values<n>&>()))>>
  : std::true_type {};

// The base of a measure whose type hides the measure chosen (Any_measure.h): what other measures
// declare by their members, it tells at run time.
struct Erased_measure_tag {};
template <class Measure>
constexpr bool is_erased = std::is_base_of<Erased_measure_tag, Measure>::value;

// Whether the measure has a Hessian in the singular values, and a Laplacian weight of its own.
template <int n, class Measure>
bool has_hessian(const Measure& m)
{
  if constexpr(is_erased<Measure>) return m.template has_hessian<n>();
  else return Has_hessian<Measure, n>::value;
}
template <int n, class Measure>
bool has_laplacian_weight(const Measure& m)
{
  if constexpr(is_erased<Measure>) return m.template has_laplacian_weight<n>();
  else return Has_laplacian_weight<Measure, n>::value;
}

// The factor by which the global step's Laplacian weighs a cell (1 if the measure names none).
template <int n, class Measure>
double laplacian_weight(const Measure& m, const Singular_values<n>& s)
{
  if constexpr(Has_laplacian_weight<Measure, n>::value) {
    const double w = m.template laplacian_weight<n>(s);
    return std::isfinite(w) && w > 0 ? w : 1.;
  } else {
    return 1.;
  }
}

// The global step's per-cell factor, a function of the smallest singular value: conformal
// measures curve like 1 / s_n^2 near a flat cell, the isometric ones like the inverse term of
// symmetric Dirichlet: these weights let the global step move much farther than the plain
// Laplacian on maps with large volume changes.
inline double conformal_weight(double s) { return 1. / (s * s); }
inline double isometric_weight(double s) { return (1. + 3. / power<4>(s)) / 4; }

// What the built-in measures declare about themselves (see the concept DistortionMeasure), by family.
template <double (*weight)(double)>
struct Regular_measure
{
  bool is_normalized() const { return true; }
  template <int n> bool is_symmetric() const { return true; }
  template <int n> double laplacian_weight(const Singular_values<n>& s) const { return s[n - 1] > 0 ? weight(s[n - 1]) : 1.; }
};
struct Unbounded_measure   // finite on inverted cells, not symmetric, no reweighting
{
  bool is_normalized() const { return false; }
  template <int n> bool is_symmetric() const { return false; }
};
template <class A, class B>
struct Pair_of_measures    // what a combination of two measures inherits from both
{
  A a;
  B b;
  Pair_of_measures(const A& a, const B& b) : a(a), b(b) {}
  bool is_normalized() const { return a.is_normalized() && b.is_normalized(); }
  template <int n> bool is_symmetric() const { return a.template is_symmetric<n>() && b.template is_symmetric<n>(); }

  template <int n>
  double laplacian_weight(const Singular_values<n>& s) const
  {
    return std::max(measures_internal::laplacian_weight<n>(a, s), measures_internal::laplacian_weight<n>(b, s));
  }
};

} // namespace measures_internal

/// \ingroup PkgDistortionOptimizationMeasures
/// Quasi-conformal dilatation K = max(K_I, K_O) (eq. 8): K_I = s_1...s_{n-1} / s_n^{n-1},
/// K_O = s_1^{n-1} / (s_2...s_n). Equals the condition number in 2D. Regular, minimum 1.
/// \cgalModels `DistortionMeasure`
struct Conformal_dilatation : measures_internal::Regular_measure<measures_internal::conformal_weight>,
                              measures_internal::Monomial_derivatives<Conformal_dilatation>
{
  std::string name() const { return "conformal"; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    if(!(s[n - 1] > 0)) return infinity;
    return branch<n>(s).first;
  }
  // K_I = s_1...s_{n-1} s_n^{1-n} or K_O = s_1^{n-1} (s_2...s_n)^-1, whichever is larger, and its exponents.
  template <int n>
  static std::pair<double, Singular_values<n>> branch(const Singular_values<n>& s)
  {
    const double p = s.prod();
    const double inner = p / measures_internal::power<n>(s[n - 1]), outer = measures_internal::power<n>(s[0]) / p;
    Singular_values<n> c = Singular_values<n>::Constant(inner >= outer ? 1. : -1.);
    if(inner >= outer) c[n - 1] = 1 - n;
    else c[0] = n - 1;
    return {std::max(inner, outer), c};
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Condition number (linear dilatation) s_1 / s_n (eq. 9). Regular, minimum 1.
/// \cgalModels `DistortionMeasure`
struct Condition_number : measures_internal::Regular_measure<measures_internal::conformal_weight>,
                          measures_internal::Monomial_derivatives<Condition_number>
{
  std::string name() const { return "condition"; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    return s[n - 1] > 0 ? s[0] / s[n - 1] : infinity;
  }
  template <int n>
  static std::pair<double, Singular_values<n>> branch(const Singular_values<n>& s)
  {
    return {s[0] / s[n - 1], measures_internal::unit<n>(0) - measures_internal::unit<n>(n - 1)};
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// MIPS energy (s_1^2 + ... + s_n^2) / (s_1...s_n)^{2/n} = trace(J^T J) / det(J)^{2/n} (eq. 11).
/// In 2D this is exactly eq. 10, s_1/s_2 + s_2/s_1, so one measure serves both equations.
/// Normalized (minimum n); symmetric only in 2D.
/// \cgalModels `DistortionMeasure`
struct MIPS
{
  std::string name() const { return "mips"; }
  bool is_normalized() const { return true; }
  template <int n> bool is_symmetric() const { return n == 2; }

  template <int n> double laplacian_weight(const Singular_values<n>& s) const { return s[n - 1] > 0 ? measures_internal::conformal_weight(s[n - 1]) : 1.; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    if(!(s[n - 1] > 0)) return infinity;
    return s.squaredNorm() / measures_internal::mean_square_scale<n>(s.prod());
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    if(!(s[n - 1] > 0)) return measures_internal::nan_gradient<n>();
    const double scale = measures_internal::mean_square_scale<n>(s.prod()), v = s.squaredNorm() / scale;
    return (2. / scale) * s - (2. / n) * v * s.cwiseInverse();
  }
  // d/ds_j of the gradient's 2 s_i / scale - (2/n) v / s_i.
  template <int n>
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const
  {
    const double scale = measures_internal::mean_square_scale<n>(s.prod()), v = s.squaredNorm() / scale;
    const Singular_values<n> inverse = s.cwiseInverse(), g = (2. / scale) * s - (2. / n) * v * inverse;
    Singular_values_hessian<n> h = (-2. / n) * (inverse * g.transpose()) - (4. / (n * scale)) * (s * inverse.transpose());
    h.diagonal() += (2. / scale) * Singular_values<n>::Ones() + (2. / n) * v * inverse.cwiseAbs2();
    return h;
  }
  template <int n, class T>
  T value_of_invariants(const Jacobian_invariants<T>& I, Jacobian_invariants<T>* dI) const
  {
    const T scale = measures_internal::mean_square_scale<n>(I.det), v = I.norm2 / scale;
    if(dI) *dI = {1. / scale, T{}, (-2. / n) * v / I.det};
    return v;
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Quasi-isometric dilatation C = max(s_1, 1/s_n) (eq. 12). Regular, minimum 1.
/// \cgalModels `DistortionMeasure`
struct Isometric_dilatation : measures_internal::Regular_measure<measures_internal::isometric_weight>,
                              measures_internal::Monomial_derivatives<Isometric_dilatation>
{
  std::string name() const { return "isometric"; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    return s[n - 1] > 0 ? std::max(s[0], 1. / s[n - 1]) : infinity;
  }
  template <int n>
  static std::pair<double, Singular_values<n>> branch(const Singular_values<n>& s)
  {
    if(s[0] >= 1. / s[n - 1]) return {s[0], measures_internal::unit<n>(0)};
    return {1. / s[n - 1], -measures_internal::unit<n>(n - 1)};
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// As-rigid-as-possible energy sum (s_i - 1)^2 (eq. 13), with the signed s_n, so that the
/// nearest rotation (never a reflection) is the reference. Not normalized (finite on inverted
/// cells), not symmetric; minimum 0.
/// \cgalModels `DistortionMeasure`
struct ARAP : measures_internal::Unbounded_measure
{
  std::string name() const { return "arap"; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    return (s.array() - 1.).square().sum();
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    return 2. * (s.array() - 1.).matrix();
  }
  template <int n>
  Singular_values_hessian<n> hessian(const Singular_values<n>&) const
  {
    return 2. * Singular_values_hessian<n>::Identity();
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Symmetric Dirichlet energy (1/2n) sum (s_i^2 + s_i^-2) (eq. 14). Regular, minimum 1.
/// \cgalModels `DistortionMeasure`
struct Symmetric_dirichlet : measures_internal::Regular_measure<measures_internal::isometric_weight>
{
  std::string name() const { return "symmetric_dirichlet"; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    if(!(s[n - 1] > 0)) return infinity;
    return (s.squaredNorm() + s.cwiseInverse().squaredNorm()) / (2 * n);
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    if(!(s[n - 1] > 0)) return measures_internal::nan_gradient<n>();
    return (s.array() - s.array().cube().inverse()).matrix() / n;
  }
  template <int n>
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const
  {
    return ((1. + 3. * s.array().square().square().inverse()) / n).matrix().asDiagonal();
  }
  // |J^-1|^2 = |cof J|^2 / det^2.
  template <int n, class T>
  T value_of_invariants(const Jacobian_invariants<T>& I, Jacobian_invariants<T>* dI) const
  {
    constexpr double half_n = 0.5 / n;
    const T inverse_det = 1. / I.det, inverse_det2 = inverse_det * inverse_det;
    if(dI) *dI = {lanes::broadcast<T>(half_n), half_n * inverse_det2, (-2 * half_n) * I.cofactor_norm2 * inverse_det2 * inverse_det};
    return half_n * (I.norm2 + I.cofactor_norm2 * inverse_det2);
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Volume (area in 2D) distortion V = max(det J, 1/det J) (eq. 15). Regular, minimum 1.
/// \cgalModels `DistortionMeasure`
struct Volume_distortion : measures_internal::Regular_measure<measures_internal::isometric_weight>,
                           measures_internal::Monomial_derivatives<Volume_distortion>
{
  std::string name() const { return "volume"; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    const double d = s.prod();
    return d > 0 ? std::max(d, 1. / d) : infinity;
  }
  template <int n>
  static std::pair<double, Singular_values<n>> branch(const Singular_values<n>& s)
  {
    const double d = s.prod();
    return {std::max(d, 1. / d), Singular_values<n>::Constant(d >= 1 ? 1. : -1.)};
  }
  template <int n, class T>
  T value_of_invariants(const Jacobian_invariants<T>& I, Jacobian_invariants<T>* dI) const
  {
    const T inverse = 1. / I.det;
    if(dI) *dI = {T{}, T{}, I.det >= 1. ? lanes::broadcast<T>(1.) : -inverse * inverse};
    return I.det >= 1. ? I.det : inverse;
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Dirichlet energy (1/n) sum s_i^2 (eq. 16). Not normalized (its minimum is the collapse to a
/// point), not symmetric; 1 on rigid maps.
/// \cgalModels `DistortionMeasure`
struct Dirichlet : measures_internal::Unbounded_measure
{
  std::string name() const { return "dirichlet"; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    return s.squaredNorm() / n;
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    return (2. / n) * s;
  }
  template <int n>
  Singular_values_hessian<n> hessian(const Singular_values<n>&) const
  {
    return (2. / n) * Singular_values_hessian<n>::Identity();
  }
  template <int n, class T>
  T value_of_invariants(const Jacobian_invariants<T>& I, Jacobian_invariants<T>* dI) const
  {
    if(dI) *dI = {lanes::broadcast<T>(1. / n), T{}, T{}};
    return I.norm2 / n;
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// The untangling barrier of Garanzha, Kaporin, Kudryavtseva, Protais, Ray and Sokolov,
/// "Foldover-free maps in 50 lines of code" (SIGGRAPH 2021). With D = det J / `reference_det`, the
/// Jacobian's determinant relative to the map's typical one, and chi(D) = (D + sqrt(eps^2 + D^2)) / 2,
/// a positive and increasing stand-in for D,
///   F = (1 - theta) |J|^2 / (reference_det chi)^{2/n} + theta (D^2 + 1) / chi
/// (a regularized MIPS plus a regularized D + 1/D). It is finite and smooth on every cell, inverted
/// ones included (not normalized), and as eps -> 0 it grows without bound on inverted cells while it
/// stays bounded on positive ones: minimizing it for decreasing eps unfolds a map
/// (`Distortion_optimization::untangle()`). `theta` defaults to the paper's 1/128 in 2D, 1/2 in 3D.
/// \cgalModels `DistortionMeasure`
struct Untangling_barrier : measures_internal::Unbounded_measure
{
  double epsilon = 1;
  double reference_det = 1;
  double theta_2 = 1. / 128, theta_3 = 0.5;

  std::string name() const { return "untangling_barrier"; }

  // chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2, positive for every D, in a form without
  // cancellation on either side of 0; e2 = eps^2 and root = sqrt(eps^2 + D^2).
  template <class T>
  static T regularized_determinant(const T& D, const T& e2, const T& root)
  {
    return D > 0. ? 0.5 * (D + root) : e2 / (2. * (root - D));
  }

  template <int n, class T>
  T value_of_invariants(const Jacobian_invariants<T>& I, Jacobian_invariants<T>* dI) const
  {
    constexpr double k = 2. / n;
    const double theta = n == 2 ? theta_2 : theta_3, r = 1. / reference_det, rk = n == 2 ? r : internal::cbrt_by_octaves(r * r);
    const T D = r * I.det, N = rk * I.norm2, e2 = lanes::broadcast<T>(epsilon * epsilon);
    const T root = lanes::sqrt(e2 + D * D);
    const T chi = regularized_determinant(D, e2, root);
    const T chi_k = n == 2 ? chi : lanes::cbrt(chi) * lanes::cbrt(chi);
    const T f = N / chi_k, g = (D * D + 1.) / chi, dchi = chi / root;
    if(dI)
      *dI = {((1 - theta) * rk) / chi_k, T{},
             r * ((-(1 - theta) * k) * f * dchi / chi + theta * (2. * D - g * dchi) / chi)};
    return (1 - theta) * f + theta * g;
  }
  template <int n>
  double value(const Singular_values<n>& s) const
  {
    return value_of_invariants<n, double>({s.squaredNorm(), 0., s.prod()}, nullptr);
  }
  // The isotropic part of the barrier's Hessian in J, (1 - theta) / chi^(2/n) (relative units):
  // Garanzha et al.'s shape term weighs each cell's Dirichlet energy by it, so the global step's
  // reweighted Laplacian is that term's exact Hessian up to rank-one corrections.
  template <int n>
  double laplacian_weight(const Singular_values<n>& s) const
  {
    const double r = 1. / reference_det, D = r * s.prod(), e2 = epsilon * epsilon, root = std::sqrt(e2 + D * D);
    const double chi = regularized_determinant(D, e2, root);
    return (1 - (n == 2 ? theta_2 : theta_3)) * (n == 2 ? r / chi : internal::cbrt_by_octaves(r * r / (chi * chi)));
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    Jacobian_invariants<double> d;
    value_of_invariants<n, double>({s.squaredNorm(), 0., s.prod()}, &d);
    Singular_values<n> g;
    for(int i = 0; i < n; ++i) {
      double others = 1;   // d det / d s_i
      for(int j = 0; j < n; ++j)
        if(j != i) others *= s[j];
      g[i] = 2 * s[i] * d.norm2 + others * d.det;
    }
    return g;
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Product of two measures, e.g. K * C (the paper's Fig. 9). Normalized / symmetric when both are.
/// \cgalModels `DistortionMeasure` (when `A` and `B` are models)
template <class A, class B>
struct Product : measures_internal::Pair_of_measures<A, B>
{
  using measures_internal::Pair_of_measures<A, B>::a;
  using measures_internal::Pair_of_measures<A, B>::b;
  Product(const A& a = A(), const B& b = B()) : measures_internal::Pair_of_measures<A, B>(a, b) {}

  std::string name() const { return a.name() + "*" + b.name(); }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    return a.template value<n>(s) * b.template value<n>(s);
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    return a.template gradient<n>(s) * b.template value<n>(s) + a.template value<n>(s) * b.template gradient<n>(s);
  }
  template <int n, class AA = A, class = std::enable_if_t<measures_internal::Has_hessian<AA, n>::value &&
                                                          measures_internal::Has_hessian<B, n>::value>>
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const
  {
    const Singular_values<n> ga = a.template gradient<n>(s), gb = b.template gradient<n>(s);
    return a.template hessian<n>(s) * b.template value<n>(s) + a.template value<n>(s) * b.template hessian<n>(s) +
           ga * gb.transpose() + gb * ga.transpose();
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Weighted sum wa * A + wb * B of two measures. Normalized / symmetric when both are. A term of
/// weight 0 is left out, also where its measure is +inf (0, not 0 * inf).
/// \cgalModels `DistortionMeasure` (when `A` and `B` are models)
template <class A, class B>
struct Weighted_sum : measures_internal::Pair_of_measures<A, B>
{
  using measures_internal::Pair_of_measures<A, B>::a;
  using measures_internal::Pair_of_measures<A, B>::b;
  double weight_a, weight_b;
  Weighted_sum(double weight_a, const A& a, double weight_b, const B& b)
    : measures_internal::Pair_of_measures<A, B>(a, b), weight_a(weight_a), weight_b(weight_b) {}

  std::string name() const
  {
    return std::to_string(weight_a) + "*" + a.name() + "+" + std::to_string(weight_b) + "*" + b.name();
  }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    // A zero weight drops its term (0 * inf would be NaN on an inverted cell).
    return (weight_a != 0 ? weight_a * a.template value<n>(s) : 0.) + (weight_b != 0 ? weight_b * b.template value<n>(s) : 0.);
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    Singular_values<n> g = Singular_values<n>::Zero();
    if(weight_a != 0) g += weight_a * a.template gradient<n>(s);
    if(weight_b != 0) g += weight_b * b.template gradient<n>(s);
    return g;
  }
  template <int n, class AA = A, class = std::enable_if_t<measures_internal::Has_hessian<AA, n>::value &&
                                                          measures_internal::Has_hessian<B, n>::value>>
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const
  {
    Singular_values_hessian<n> h = Singular_values_hessian<n>::Zero();
    if(weight_a != 0) h += weight_a * a.template hessian<n>(s);
    if(weight_b != 0) h += weight_b * b.template hessian<n>(s);
    return h;
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// A measure from two callables: `value(s)` and `gradient(s)`, each called with a
/// `Singular_values<n>` (use generic lambdas to serve n = 2 and n = 3). The callables must
/// return +infinity (value) where the map is not admissible, e.g. `s[n-1] <= 0`.
/// \cgalModels `DistortionMeasure`
template <class ValueFunction, class GradientFunction>
struct Custom_measure
{
  ValueFunction value_function;
  GradientFunction gradient_function;
  std::string label;
  bool normalized;
  bool symmetric;

  std::string name() const { return label; }
  bool is_normalized() const { return normalized; }
  template <int n> bool is_symmetric() const { return symmetric; }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    return value_function(s);
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    return gradient_function(s);
  }
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Makes a `Custom_measure`. `normalized` tells the optimizer that the measure is infinite on
/// degenerate cells (so an inverted start is an error); `symmetric` is informative.
template <class ValueFunction, class GradientFunction>
Custom_measure<ValueFunction, GradientFunction>
make_measure(ValueFunction value, GradientFunction gradient, std::string name = "custom",
             bool normalized = true, bool symmetric = false)
{
  return {std::move(value), std::move(gradient), std::move(name), normalized, symmetric};
}

/// \ingroup PkgDistortionOptimizationMeasures
/// The minimum m = D(1, ..., 1) of a measure (C.4): the value on rigid maps.
template <int n, class Measure>
double value_on_rigid_maps(const Measure& measure)
{
  return measure.template value<n>(Singular_values<n>::Ones());
}

/// \ingroup PkgDistortionOptimizationMeasures
/// A regular distortion measure (Appendix C): normalized and symmetric.
template <int n, class Measure>
bool is_regular(const Measure& measure)
{
  return measure.is_normalized() && measure.template is_symmetric<n>();
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_MEASURES_H
