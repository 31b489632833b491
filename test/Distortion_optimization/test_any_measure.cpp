// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Any_measure: a measure chosen at run time gives the same runs, to the last bit, as its own type
// (the command-line tool relies on it): its functions, and runs on triangle maps
// (test_any_measure_3.cpp: on tetrahedral maps).

#include "test_meshes.h"

#include <CGAL/Distortion_optimization/Any_measure.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/minimize_distortion.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

namespace DO = CGAL::Distortion_optimization;

// The names a program may give: each built-in measure, a product and a weighted sum.
std::vector<std::string> names()
{
  std::vector<std::string> all = DO::measure_names();
  all.push_back("conformal*isometric");
  all.push_back("0.5*mips+arap");
  return all;
}

template <int n, class Measure>
void expect_same_functions(const Measure& measure, const DO::Any_measure& any)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.3, 3.);
  for(int k = 0; k < 50; ++k) {
    DO::Singular_values<n> s;
    for(int i = 0; i < n; ++i) s[i] = uniform(random);
    std::sort(s.data(), s.data() + n, [](double a, double b) { return a > b; });
    if(k % 5 == 0) s[n - 1] = -s[n - 1];   // an inverted cell
    EXPECT_EQ(measure.template value<n>(s), any.value<n>(s)) << measure.name();
    const DO::Singular_values<n> g = measure.template gradient<n>(s), h = any.gradient<n>(s);
    for(int i = 0; i < n; ++i) EXPECT_TRUE(g[i] == h[i] || (std::isnan(g[i]) && std::isnan(h[i]))) << measure.name();
    EXPECT_EQ(DO::measures_internal::laplacian_weight<n>(measure, s), DO::measures_internal::laplacian_weight<n>(any, s));
    if constexpr(DO::measures_internal::Has_hessian<Measure, n>::value) {
      if(s[n - 1] > 0) {
        EXPECT_TRUE(measure.template hessian<n>(s) == any.hessian<n>(s)) << measure.name();
      }
    }
  }
  constexpr bool has_hessian = DO::measures_internal::Has_hessian<Measure, n>::value;
  constexpr bool has_weight = DO::measures_internal::Has_laplacian_weight<Measure, n>::value;
  EXPECT_EQ(has_hessian, any.has_hessian<n>()) << measure.name();
  EXPECT_EQ(has_weight, any.has_laplacian_weight<n>()) << measure.name();
  EXPECT_EQ(measure.template is_symmetric<n>(), any.is_symmetric<n>()) << measure.name();
}

TEST(AnyMeasure, HoldsEachMeasureWithItsOwnFunctionsAndNewtonModel)
{
  for(const std::string& name : names()) {
    const DO::Any_measure any = DO::measure_from_name(name);
    DO::with_measure(name, [&](const auto& measure) {
      EXPECT_EQ(any.name(), measure.name());
      EXPECT_EQ(any.is_normalized(), measure.is_normalized()) << name;
      expect_same_functions<2>(measure, any);
      expect_same_functions<3>(measure, any);
      using Model = DO::internal::Newton_model<std::decay_t<decltype(measure)>>;
      const auto model = any.newton_model();
      EXPECT_EQ(model.has_value(), Model::of(measure).has_value()) << name;
      if(model && Model::of(measure)) {
        EXPECT_EQ(model->name(), Model::of(measure)->name());
      }
      return 0;
    });
  }
  // The dilatations take MIPS's and symmetric Dirichlet's Newton steps (internal/newton_model.h).
  EXPECT_EQ(DO::measure_from_name("conformal").newton_model()->name(), "mips");
  EXPECT_EQ(DO::measure_from_name("isometric").newton_model()->name(), "symmetric_dirichlet");
  EXPECT_FALSE(DO::measure_from_name("mips").newton_model());
  EXPECT_THROW(DO::measure_from_name("nonsense"), DO::Invalid_input);
  EXPECT_THROW(DO::measure_from_name("0*mips"), DO::Invalid_input);
}

TEST(AnyMeasure, TriangleMapsAreTheSameBitsAsWithTheMeasuresOwnType)
{
  using namespace test_meshes;
  const auto bend = [](const Point_2& p) {
    return Point_2(p.x() + 0.3 * p.y() * p.y(), p.y() + 0.2 * std::sin(3 * p.x()));
  };
  for(const std::string& name : names())
    for(const bool free_border : {false, true}) {
      if(name == "dirichlet" && free_border) continue;   // its minimum collapses a free map
      Mesh2 a = planar_grid(12), b = planar_grid(12);
      auto uv_a = make_target(a, bend), uv_b = make_target(b, bend);
      // Free: two corners pinned; fixed: the border, by default.
      auto pinned = a.add_property_map<Mesh2::Vertex_index, bool>("v:pinned", false).first;
      pinned[Mesh2::Vertex_index(0)] = pinned[Mesh2::Vertex_index(12)] = true;
      const auto run = [&](Mesh2& mesh, auto& uv, const auto& measure) {
        const auto np = CGAL::parameters::number_of_iterations(8);
        return free_border ? CGAL::minimize_distortion(mesh, uv, measure, np.vertex_is_constrained_map(pinned))
                           : CGAL::minimize_distortion(mesh, uv, measure, np);
      };
      const DO::Result own = DO::with_measure(name, [&](const auto& measure) { return run(a, uv_a, measure); });
      const DO::Result held = run(b, uv_b, DO::measure_from_name(name));
      EXPECT_EQ(own.final_energy, held.final_energy) << name << (free_border ? ", border free" : "");
      EXPECT_EQ(own.iterations, held.iterations) << name;
      EXPECT_LE(held.final_energy, held.initial_energy) << name;
      EXPECT_EQ(targets_of(a, uv_a), targets_of(b, uv_b)) << name << (free_border ? ", border free" : "");
    }
}

} // namespace
