// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Measures chosen by name at run time (command lines, configuration files).

#ifndef CGAL_DISTORTION_OPTIMIZATION_MEASURE_BY_NAME_H
#define CGAL_DISTORTION_OPTIMIZATION_MEASURE_BY_NAME_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <CGAL/assertions.h>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationMeasures
/// The registry of built-in measures, in the order of the paper's equations 8-16: every run-time
/// choice of a measure (`measure_names()`, `with_measure()`, `Product_of_measures`, the tool) is
/// generated from this list and from each type's `name()`.
using Built_in_measures = std::tuple<Conformal_dilatation, Condition_number, MIPS, Isometric_dilatation, ARAP,
                                     Symmetric_dirichlet, Volume_distortion, Dirichlet>;

namespace measures_internal {

constexpr std::size_t number_of_built_in_measures = std::tuple_size<Built_in_measures>::value;

// f(the built-in measure number k), k < number_of_built_in_measures.
template <std::size_t I = 0, class F>
decltype(auto) visit_built_in(std::size_t k, F&& f)
{
  using M = std::tuple_element_t<I, Built_in_measures>;
  if constexpr(I + 1 == number_of_built_in_measures) {
    CGAL_precondition(k == I);
    return f(M());
  } else {
    if(k == I) return f(M());
    return visit_built_in<I + 1>(k, std::forward<F>(f));
  }
}

// The number of the built-in measure with that name, number_of_built_in_measures if none.
inline std::size_t built_in_measure_number(const std::string& name);

} // namespace measures_internal

/// \ingroup PkgDistortionOptimizationMeasures
/// The names of the built-in measures, which `with_measure()` understands, in registry order.
inline const std::vector<std::string>& measure_names()
{
  static const std::vector<std::string> names =
    std::apply([](const auto&... m) { return std::vector<std::string>{m.name()...}; }, Built_in_measures());
  return names;
}

inline std::size_t measures_internal::built_in_measure_number(const std::string& name)
{
  const auto& names = measure_names();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

/// \ingroup PkgDistortionOptimizationMeasures
/// The product of built-in measures chosen at run time by their names, e.g. K * C (the paper's Fig. 9).
class Product_of_measures
{
public:
  static constexpr std::size_t max_factors = 8;

  /// \throws Invalid_input if a name is not one of `measure_names()`.
  explicit Product_of_measures(const std::vector<std::string>& names)
  {
    for(const std::string& name : names) {
      if(name.empty()) throw Invalid_input("a product of measures has an empty factor");
      const std::size_t k = measures_internal::built_in_measure_number(name);
      if(k == measures_internal::number_of_built_in_measures) throw Invalid_input("unknown measure '" + name + "'");
      factors_.push_back(k);
    }
    if(factors_.empty() || factors_.size() > max_factors)
      throw Invalid_input("a product of measures has 1 to " + std::to_string(max_factors) + " factors");
  }

  std::string name() const
  {
    std::string s;
    for(std::size_t k : factors_) s += (s.empty() ? "" : "*") + measure_names()[k];
    return s;
  }
  bool is_normalized() const { return all([](const auto& m) { return m.is_normalized(); }); }
  template <int n> bool is_symmetric() const { return all([](const auto& m) { return m.template is_symmetric<n>(); }); }

  template <int n>
  double laplacian_weight(const Singular_values<n>& s) const
  {
    // The largest factor's weight, as Product does.
    double w = 0;
    for(std::size_t k : factors_) visit(k, [&](const auto& m) { w = std::max(w, measures_internal::laplacian_weight<n>(m, s)); });
    return w;
  }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    double v = 1;
    for(std::size_t k : factors_) visit(k, [&](const auto& m) { v *= m.template value<n>(s); });
    return v;
  }
  // Product rule: sum_k (prod_{j != k} D_j) grad D_k.
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    std::array<double, max_factors> values;
    std::array<Singular_values<n>, max_factors> gradients;
    std::size_t count = 0;
    for(std::size_t k : factors_)
      visit(k, [&](const auto& m) {
        values[count] = m.template value<n>(s);
        gradients[count++] = m.template gradient<n>(s);
      });
    Singular_values<n> g = Singular_values<n>::Zero();
    for(std::size_t k = 0; k < count; ++k) {
      double others = 1;
      for(std::size_t j = 0; j < count; ++j)
        if(j != k) others *= values[j];
      g += others * gradients[k];
    }
    return g;
  }

private:
  template <class F>
  static void visit(std::size_t k, F&& f)
  {
    measures_internal::visit_built_in(k, std::forward<F>(f));
  }
  template <class Predicate>
  bool all(Predicate p) const
  {
    bool result = true;
    for(std::size_t k : factors_) visit(k, [&](const auto& m) { result = result && p(m); });
    return result;
  }

  std::vector<std::size_t> factors_;
};

/// \ingroup PkgDistortionOptimizationMeasures
/// Calls `f(measure)` with the measure named `name`: one of `measure_names()` (passed as its own
/// type, so the SVD-free forms are used), or a product of them written `a*b*...` (passed as a
/// `Product_of_measures`). Returns what `f` returns.
/// \throws Invalid_input for an unknown name.
template <class F>
decltype(auto) with_measure(const std::string& name, F&& f)
{
  if(name.find('*') != std::string::npos) {
    std::vector<std::string> factors;
    std::size_t begin = 0;
    for(std::size_t star; (star = name.find('*', begin)) != std::string::npos; begin = star + 1)
      factors.push_back(name.substr(begin, star - begin));
    factors.push_back(name.substr(begin));
    return f(Product_of_measures(factors));
  }
  const std::size_t k = measures_internal::built_in_measure_number(name);
  if(k == measures_internal::number_of_built_in_measures) {
    std::string known;
    for(const auto& n : measure_names()) known += " " + n;
    throw Invalid_input("unknown measure '" + name + "'; known:" + known + ", or products such as " + measure_names()[0] +
                        "*" + measure_names()[3]);
  }
  return measures_internal::visit_built_in(k, std::forward<F>(f));
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_MEASURE_BY_NAME_H
