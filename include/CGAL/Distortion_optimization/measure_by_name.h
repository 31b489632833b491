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
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationMeasures
/// The names `with_measure()` understands, in the order of the paper's equations 8-16.
inline const std::vector<std::string>& measure_names()
{
  static const std::vector<std::string> names = {"conformal", "condition", "mips", "isometric", "arap",
                                                 "symmetric_dirichlet", "volume", "dirichlet"};
  return names;
}

/// \ingroup PkgDistortionOptimizationMeasures
/// The product of built-in measures chosen at run time, e.g. K * C from "conformal*isometric".
class Product_of_measures
{
public:
  static constexpr std::size_t max_factors = 8;

  /// \throws Invalid_input if a name is not one of `measure_names()`.
  explicit Product_of_measures(const std::vector<std::string>& names)
  {
    for(const std::string& name : names) {
      std::size_t k = 0;
      while(k < measure_names().size() && measure_names()[k] != name) ++k;
      if(k == measure_names().size()) throw Invalid_input("unknown measure '" + name + "'");
      factors_.push_back(static_cast<int>(k));
    }
    if(factors_.empty() || factors_.size() > max_factors)
      throw Invalid_input("a product of measures has 1 to " + std::to_string(max_factors) + " factors");
  }

  std::string name() const
  {
    std::string s;
    for(int k : factors_) s += (s.empty() ? "" : "*") + measure_names()[k];
    return s;
  }
  bool is_normalized() const { return all([](const auto& m) { return m.is_normalized(); }); }
  template <int n> bool is_symmetric() const { return all([](const auto& m) { return m.template is_symmetric<n>(); }); }

  template <int n>
  double laplacian_weight(const Singular_values<n>& s) const
  {
    // The largest factor's weight, as Product does.
    double w = 0;
    for(int k : factors_) visit(k, [&](const auto& m) { w = std::max(w, measures_internal::laplacian_weight<n>(m, s)); });
    return w;
  }

  template <int n>
  double value(const Singular_values<n>& s) const
  {
    double v = 1;
    for(int k : factors_) visit(k, [&](const auto& m) { v *= m.template value<n>(s); });
    return v;
  }
  // Product rule: sum_k (prod_{j != k} D_j) grad D_k.
  template <int n>
  Singular_values<n> gradient(const Singular_values<n>& s) const
  {
    std::array<double, max_factors> values;
    std::array<Singular_values<n>, max_factors> gradients;
    std::size_t count = 0;
    for(int k : factors_)
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
  static void visit(int k, F&& f)
  {
    switch(k) {
      case 0: f(Conformal_dilatation()); break;
      case 1: f(Condition_number()); break;
      case 2: f(MIPS()); break;
      case 3: f(Isometric_dilatation()); break;
      case 4: f(ARAP()); break;
      case 5: f(Symmetric_dirichlet()); break;
      case 6: f(Volume_distortion()); break;
      default: f(Dirichlet()); break;
    }
  }
  template <class Predicate>
  bool all(Predicate p) const
  {
    bool result = true;
    for(int k : factors_) visit(k, [&](const auto& m) { result = result && p(m); });
    return result;
  }

  std::vector<int> factors_;
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
  if(name == "conformal") return f(Conformal_dilatation());
  if(name == "condition") return f(Condition_number());
  if(name == "mips") return f(MIPS());
  if(name == "isometric") return f(Isometric_dilatation());
  if(name == "arap") return f(ARAP());
  if(name == "symmetric_dirichlet") return f(Symmetric_dirichlet());
  if(name == "volume") return f(Volume_distortion());
  if(name == "dirichlet") return f(Dirichlet());
  std::string known;
  for(const auto& n : measure_names()) known += " " + n;
  throw Invalid_input("unknown measure '" + name + "'; known:" + known + ", or products such as conformal*isometric");
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_MEASURE_BY_NAME_H
