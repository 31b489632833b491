// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Everything the public functions read from a named-parameter pack, in one place: the options of
// the optimization, and, through an adapter (triangle_mesh_adapter.h, c3t3_adapter.h), the vertex
// weights and the constraints of the problem.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// What minimize() does, beyond the problem itself.
struct Options
{
  std::size_t iterations = 100;
  double threshold = 1e-4;
  Local_solver solver = Local_solver::GRADIENT_DESCENT;
  Vertex_order order = Vertex_order::SORTED_PER_SWEEP;
  // Unset: global steps only where they are Newton's, else alternating (Steps).
  std::optional<Schedule> schedule;
  bool harmonic_start = true;   // false by default with Schedule::LOCAL (read_options)
  bool global_injectivity = false;   // guard the boundary of free boundary vertices
  int threads = 1;
  Parallel_sweep parallel_sweep = Parallel_sweep::INDEPENDENT_SETS;
  // Unset: projected Newton where the measure's own steps lead, or its model's (newton_model.h).
  std::optional<Global_solver> global_solver;
  // (iteration, energy, inverted cells) -> continue? While untangling, the energy is the barrier's.
  std::function<bool(std::size_t, double, std::size_t)> visitor;
  bool untangle_first = false;
};

template <class T> struct Is_optional : std::false_type {};
template <class T> struct Is_optional<std::optional<T>> : std::true_type {};

// Sets `option` to a named parameter's value if it was given: a value, or a std::optional of one
// (empty: the default, which an optional `option` keeps empty).
template <class Option, class Parameter>
void assign_if_given(Option& option, const Parameter& value)
{
  if constexpr(std::is_same<Parameter, CGAL::internal_np::Param_not_found>::value) {
    return;
  } else if constexpr(Is_optional<Parameter>::value && !Is_optional<Option>::value) {
    if(value) option = *value;
  } else {
    option = value;
  }
}

template <class NamedParameters>
Options read_options(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Options o;
  o.iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), o.iterations);
  o.threshold = choose_parameter(get_parameter(np, internal_np::convergence_threshold), o.threshold);
  o.solver = choose_parameter(get_parameter(np, internal_np::local_solver), o.solver);
  o.order = choose_parameter(get_parameter(np, internal_np::vertex_order), o.order);
  assign_if_given(o.schedule, get_parameter(np, internal_np::schedule));
  o.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), o.threads);
  o.global_injectivity = choose_parameter(get_parameter(np, internal_np::preserve_global_injectivity), o.global_injectivity);
  o.parallel_sweep = choose_parameter(get_parameter(np, internal_np::parallel_sweep), o.parallel_sweep);
  assign_if_given(o.global_solver, get_parameter(np, internal_np::global_solver));
  o.harmonic_start = choose_parameter(get_parameter(np, internal_np::use_harmonic_start),
                                      o.schedule != Schedule::LOCAL);
  o.untangle_first = choose_parameter(get_parameter(np, internal_np::untangle_first), o.untangle_first);
  auto visitor = get_parameter(np, CGAL::internal_np::visitor);
  if constexpr(!std::is_same<decltype(visitor), CGAL::internal_np::Param_not_found>::value)
    o.visitor = [visitor](std::size_t iteration, double energy, std::size_t inverted) {
      // The user's visitor takes the inverted cells' count only if it wants it.
      if constexpr(std::is_invocable<const std::decay_t<decltype(visitor)>&, std::size_t, double, std::size_t>::value)
        return static_cast<bool>(visitor(iteration, energy, inverted));
      else
        return static_cast<bool>(visitor(iteration, energy));
    };
  if(o.threads < 0)
    throw Invalid_input("the number of threads must be 0 (all) or positive");
  if(!(o.threshold >= 0))
    throw Invalid_input("the convergence threshold must be a non-negative number");
  return o;
}

// omega(v) for the adapter's vertices from `vertex_weight_map` (empty: omega = 1); throws unless
// every weight is finite and positive.
template <class Adapter, class NamedParameters>
std::vector<double> read_vertex_weights(const Adapter& adapter, const NamedParameters& np)
{
  std::vector<double> w;
  auto weights = CGAL::parameters::get_parameter(np, internal_np::vertex_weight_map);
  if constexpr(!std::is_same<decltype(weights), CGAL::internal_np::Param_not_found>::value) {
    w.reserve(adapter.vertex_of.size());
    for(const auto& v : adapter.vertex_of) {
      w.push_back(static_cast<double>(get(weights, v)));
      if(!(w.back() > 0) || !std::isfinite(w.back()))
        throw Invalid_input("vertex " + std::to_string(w.size() - 1) + " has a weight that is not finite and positive");
    }
  }
  return w;
}

template <class NamedParameters>
constexpr bool has_sliding_boundary()
{
  return !std::is_same<decltype(CGAL::parameters::get_parameter(std::declval<const NamedParameters&>(),
                                                                internal_np::sliding_boundary)),
                       CGAL::internal_np::Param_not_found>::value;
}

// Which of the adapter's vertices are free: not in `vertex_is_constrained_map`, or, without it,
// not on the boundary (the mesh's border, the complex's boundary), unless the boundary slides.
template <class Adapter, class NamedParameters>
std::vector<unsigned char> read_free_vertices(const Adapter& adapter, const NamedParameters& np)
{
  auto constrained = CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_is_constrained);
  std::vector<unsigned char> is_free(adapter.vertex_of.size());
  for(std::size_t i = 0; i < is_free.size(); ++i) {
    if constexpr(std::is_same<decltype(constrained), CGAL::internal_np::Param_not_found>::value)
      is_free[i] = has_sliding_boundary<NamedParameters>() || !adapter.on_boundary[i];
    else
      is_free[i] = !get(constrained, adapter.vertex_of[i]);
  }
  return is_free;
}

// Whether a sliding surface offers project(x, normal, hint) besides project(x, normal).
template <class Surface, int n, class = void>
struct takes_hints : std::false_type {};
template <class Surface, int n>
struct takes_hints<Surface, n, std::void_t<decltype(std::declval<const Surface&>().project(
  std::declval<const std::array<double, n>&>(), std::declval<std::array<double, n>&>(), std::declval<std::ptrdiff_t&>()))>>
  : std::true_type {};

// With `sliding_boundary`: the free boundary vertices slide on that surface, which sees the user's
// coordinates (the adapter's map is scaled by a power of two, undone exactly around the call).
template <class Adapter, class NamedParameters>
void read_sliding_boundary(const Adapter& adapter, const NamedParameters& np, Optimization_problem<Adapter::dimension>& problem)
{
  constexpr int n = Adapter::dimension;
  if constexpr(has_sliding_boundary<NamedParameters>()) {
    const auto surface = CGAL::parameters::get_parameter(np, internal_np::sliding_boundary);
    problem.is_sliding.assign(adapter.vertex_of.size(), 0);
    for(std::size_t i = 0; i < problem.is_sliding.size(); ++i)
      problem.is_sliding[i] = problem.is_free[i] && adapter.on_boundary[i];
    const double scale = adapter.scale;
    // Where the surface takes hints, each vertex's is the one its last query left (a call is for
    // one vertex, and no two threads move the same vertex at once).
    constexpr bool hinted = takes_hints<decltype(surface), n>::value;
    auto hints = std::make_shared<std::vector<std::ptrdiff_t>>(hinted ? problem.is_sliding.size() : 0, -1);
    problem.slide = [surface, scale, hints](std::size_t v, const Vector<n>& x, Vector<n>& normal) {
      std::array<double, n> p, u, y;
      for(int k = 0; k < n; ++k) p[k] = x[k] / scale;
      if constexpr(hinted) y = surface.project(p, u, (*hints)[v]);
      else y = surface.project(p, u);
      Vector<n> z;
      for(int k = 0; k < n; ++k) {
        z[k] = y[k] * scale;
        normal[k] = u[k];
      }
      return z;
    };
  }
}

// The problem of an adapter's map (moved out of the adapter, which keeps its handles) with the
// named parameters' vertex weights, constraints and cell weighting.
template <class Adapter, class NamedParameters>
Optimization_problem<Adapter::dimension> make_problem(Adapter& adapter, const NamedParameters& np)
{
  Optimization_problem<Adapter::dimension> problem;
  problem.omega = read_vertex_weights(adapter, np);
  // The energy is a mean, unchanged when every weight is scaled: the weights are scaled by a power
  // of two (exactly) so that the largest is in [1, 2), and their sums cannot overflow however large
  // they are. (A weight below 2^-1022 of the largest counts as that: it would underflow to 0.)
  if(!problem.omega.empty()) {
    const int exponent = std::ilogb(*std::max_element(problem.omega.begin(), problem.omega.end()));
    for(double& x : problem.omega) x = (std::max)(std::scalbn(x, -exponent), std::numeric_limits<double>::min());
  }
  problem.is_free = read_free_vertices(adapter, np);
  read_sliding_boundary(adapter, np, problem);
  problem.map = std::move(adapter.map);
  problem.finalize(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::cell_weighting),
                                                      Cell_weighting::AVERAGE_VOLUME));
  return problem;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_NAMED_PARAMETERS_H
