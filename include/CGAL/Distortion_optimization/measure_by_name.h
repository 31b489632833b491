// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Measures chosen by name at run time (command lines, configuration files).

#ifndef CGAL_DISTORTION_OPTIMIZATION_MEASURE_BY_NAME_H
#define CGAL_DISTORTION_OPTIMIZATION_MEASURE_BY_NAME_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Any_measure.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>
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
/// \cgalModels `DistortionMeasure`
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
    const Factors<n, false> f(*this, s);
    Singular_values<n> g = Singular_values<n>::Zero();
    for(std::size_t k = 0; k < f.count; ++k) g += f.product_except(k, k) * f.gradients[k];
    return g;
  }
  // sum_k (prod_{j != k} D_j) hess D_k + sum_{k != l} (prod_{j != k, l} D_j) grad D_k grad D_l^T.
  template <int n>
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const
  {
    const Factors<n, true> f(*this, s);
    Singular_values_hessian<n> h = Singular_values_hessian<n>::Zero();
    for(std::size_t k = 0; k < f.count; ++k) {
      h += f.product_except(k, k) * f.hessians[k];
      for(std::size_t l = 0; l < f.count; ++l)
        if(l != k) h += f.product_except(k, l) * (f.gradients[k] * f.gradients[l].transpose());
    }
    return h;
  }

private:
  // The factors' values and gradients at s, and their Hessians if asked.
  template <int n, bool with_hessians>
  struct Factors
  {
    Factors(const Product_of_measures& product, const Singular_values<n>& s)
    {
      for(std::size_t k : product.factors_)
        visit(k, [&](const auto& m) {
          values[count] = m.template value<n>(s);
          gradients[count] = m.template gradient<n>(s);
          if constexpr(with_hessians) hessians[count] = m.template hessian<n>(s);
          ++count;
        });
    }
    // The product of the values but for the factors k and l.
    double product_except(std::size_t k, std::size_t l) const
    {
      double p = 1;
      for(std::size_t j = 0; j < count; ++j)
        if(j != k && j != l) p *= values[j];
      return p;
    }

    std::size_t count = 0;
    std::array<double, max_factors> values;
    std::array<Singular_values<n>, max_factors> gradients;
    std::array<Singular_values_hessian<n>, with_hessians ? max_factors : 0> hessians;
  };

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
/// A weighted sum of products of built-in measures chosen at run time, e.g.
/// 0.5 K + C (`"0.5*conformal+isometric"`), the run-time counterpart of `Weighted_sum`.
/// \cgalModels `DistortionMeasure`
class Sum_of_measures
{
public:
  /// One term: a positive weight times a product of measures.
  struct Term
  {
    double weight;
    Product_of_measures product;
  };

  /// \throws Invalid_input if there is no term or a weight is not positive and finite.
  explicit Sum_of_measures(std::vector<Term> terms) : terms_(std::move(terms))
  {
    if(terms_.empty()) throw Invalid_input("a sum of measures has no term");
    for(const Term& t : terms_)
      if(!(t.weight > 0) || !std::isfinite(t.weight))
        throw Invalid_input("the weight of '" + t.product.name() + "' is not a positive finite number" +
                            (std::isinf(t.weight) ? " (the product of its factors' weights overflows)" : ""));
  }

  std::string name() const
  {
    std::string s;
    for(const Term& t : terms_) {
      std::ostringstream weight;
      weight << t.weight;
      s += (s.empty() ? "" : "+") + (t.weight == 1 ? "" : weight.str() + "*") + t.product.name();
    }
    return s;
  }
  bool is_normalized() const
  {
    return std::all_of(terms_.begin(), terms_.end(), [](const Term& t) { return t.product.is_normalized(); });
  }
  template <int n> bool is_symmetric() const
  {
    return std::all_of(terms_.begin(), terms_.end(), [](const Term& t) { return t.product.template is_symmetric<n>(); });
  }
  template <int n>
  double laplacian_weight(const Singular_values<n>& s) const
  {
    double w = 0;   // the largest term's, as Weighted_sum does
    for(const Term& t : terms_) w = std::max(w, t.product.template laplacian_weight<n>(s));
    return w;
  }
  template <int n>
  double value(const Singular_values<n>& s) const
  {
    double v = 0;
    for(const Term& t : terms_) v += t.weight * t.product.template value<n>(s);
    return v;
  }
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    Singular_values<n> g = Singular_values<n>::Zero();
    for(const Term& t : terms_) g += t.weight * t.product.template gradient<n>(s);
    return g;
  }
  template <int n>
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const
  {
    Singular_values_hessian<n> h = Singular_values_hessian<n>::Zero();
    for(const Term& t : terms_) h += t.weight * t.product.template hessian<n>(s);
    return h;
  }

private:
  std::vector<Term> terms_;
};

namespace measures_internal {

// A whole token that is a number (strtod's syntax), into x.
inline bool whole_number(const std::string& token, double& x)
{
  if(token.empty()) return false;
  char* end = nullptr;
  x = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

// "w1*a*b+w2*c+...": the terms of a sum; the weight of a term is the product of its numbers (1 if none).
inline std::vector<Sum_of_measures::Term> parse_sum(const std::string& name)
{
  std::vector<Sum_of_measures::Term> terms;
  std::size_t begin = 0;
  for(bool last = false; !last; ) {
    const std::size_t plus = name.find('+', begin);
    last = plus == std::string::npos;
    const std::string term = name.substr(begin, last ? std::string::npos : plus - begin);
    double weight = 1;
    std::vector<std::string> factors;
    std::size_t b = 0;
    for(bool end = false; !end; ) {
      const std::size_t star = term.find('*', b);
      end = star == std::string::npos;
      const std::string token = term.substr(b, end ? std::string::npos : star - b);
      double x;
      if(whole_number(token, x)) weight *= x;
      else factors.push_back(token);
      b = star + 1;
    }
    if(factors.empty()) throw Invalid_input("the term '" + term + "' of '" + name + "' has no measure");
    terms.push_back({weight, Product_of_measures(factors)});
    begin = plus + 1;
  }
  return terms;
}

} // namespace measures_internal

/// \ingroup PkgDistortionOptimizationMeasures
/// Calls `f(measure)` with the measure named `name`: one of `measure_names()` (passed as its own
/// type, so the SVD-free forms are used), a product of them written `a*b*...` (passed as a
/// `Product_of_measures`), or a weighted sum of such products written `w1*a+w2*b*c+...` (passed as
/// a `Sum_of_measures`; a weight is a positive number among a term's factors, 1 if none). Returns
/// what `f` returns; `f` must return the same type for each kind of measure.
/// \throws Invalid_input for an unknown name or a weight that is not positive and finite.
template <class F>
decltype(auto) with_measure(const std::string& name, F&& f)
{
  bool weighted = name.find('+') != std::string::npos;
  for(std::size_t begin = 0; !weighted && begin <= name.size(); ) {
    const std::size_t star = std::min(name.find('*', begin), name.size());
    double x;
    weighted = measures_internal::whole_number(name.substr(begin, star - begin), x);
    begin = star + 1;
  }
  if(weighted) return f(Sum_of_measures(measures_internal::parse_sum(name)));
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

/// \ingroup PkgDistortionOptimizationMeasures
/// The measure named `name`, as `with_measure()` reads it, held by an `Any_measure`: the functions
/// called with it are compiled once for all the names (where `with_measure()` compiles them once
/// per kind of measure).
/// \throws Invalid_input for an unknown name or a weight that is not positive and finite.
inline Any_measure measure_from_name(const std::string& name)
{
  return with_measure(name, [](const auto& measure) { return Any_measure(measure); });
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_MEASURE_BY_NAME_H
