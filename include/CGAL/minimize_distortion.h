// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_MINIMIZE_DISTORTION_H
#define CGAL_MINIMIZE_DISTORTION_H

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/c3t3_adapter.h>
#include <CGAL/Distortion_optimization/internal/minimize.h>
#include <CGAL/Distortion_optimization/internal/triangle_mesh_adapter.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The options every minimize_distortion() overload shares, read from a named-parameter pack.
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
  o.schedule = choose_parameter(get_parameter(np, internal_np::schedule), o.schedule);
  o.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), o.threads);
  o.global_injectivity = choose_parameter(get_parameter(np, internal_np::preserve_global_injectivity), o.global_injectivity);
  o.parallel_sweep = choose_parameter(get_parameter(np, internal_np::parallel_sweep), o.parallel_sweep);
  o.harmonic_start = choose_parameter(get_parameter(np, internal_np::use_harmonic_start),
                                      o.schedule != Schedule::LOCAL);
  auto visitor = get_parameter(np, CGAL::internal_np::visitor);
  if constexpr(!std::is_same<decltype(visitor), CGAL::internal_np::Param_not_found>::value)
    o.visitor = [visitor](std::size_t iteration, double energy) { return static_cast<bool>(visitor(iteration, energy)); };
  if(o.threads < 0)
    throw Invalid_input("the number of threads must be 0 (all) or positive");
  if(!(o.threshold >= 0))
    throw Invalid_input("the convergence threshold must be a non-negative number");
  return o;
}

// Builds the problem from an adapter (Triangle_mesh_adapter or C3t3_adapter), reads vertex weights
// and constraints from the named parameters (default_fixed(i) when no constraint map is given),
// minimizes, and returns the problem so that the caller writes its targets back.
template <int n, class Adapter, class Measure, class NamedParameters, class DefaultFixed>
std::pair<Result, Optimization_problem<n>>
minimize_adapted(Adapter& adapter, const Measure& measure, const NamedParameters& np, DefaultFixed default_fixed)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Optimization_problem<n> problem;
  problem.map = std::move(adapter.map);   // the adapter keeps only its vertex and cell handles
  auto weights = get_parameter(np, internal_np::vertex_weight_map);
  if constexpr(!std::is_same<decltype(weights), CGAL::internal_np::Param_not_found>::value)
    problem.omega = vertex_weights(adapter.vertex_of, weights);
  auto constrained = get_parameter(np, CGAL::internal_np::vertex_is_constrained);
  problem.is_free.resize(adapter.vertex_of.size());
  for(std::size_t i = 0; i < adapter.vertex_of.size(); ++i) {
    if constexpr(std::is_same<decltype(constrained), CGAL::internal_np::Param_not_found>::value)
      problem.is_free[i] = !default_fixed(i);
    else
      problem.is_free[i] = !get(constrained, adapter.vertex_of[i]);
  }
  problem.finalize(choose_parameter(get_parameter(np, internal_np::cell_weighting), Cell_weighting::AVERAGE_VOLUME));
  Result result = minimize(problem, measure, read_options(np));
  return {std::move(result), std::move(problem)};
}

} // namespace internal
} // namespace Distortion_optimization

/*!
\ingroup PkgDistortionOptimizationRef

Minimizes the distortion of the simplicial map that sends each vertex `v` of the triangle mesh
`tm` from its source position to `get(target, v)`, moving the free vertices' targets:
a planar deformation (`Point_2` source) or a surface parametrization (`Point_3` source).

The method is Algorithm 1 of Naitsat, Saucan and Zeevi, "Geometry-based distortion measures for
space deformation": sweeps over the free vertices, the most distorted first (Algorithm 2), each
one moved along the exact gradient of its ring's energy by a line search that never leaves the
kernel of the ring. No triangle that is positively oriented in the start map is ever flipped or
flattened (checked with exact predicates); the energy never increases.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam TargetMap a model of `ReadWritePropertyMap` from vertex descriptors to a `Point_2`
\tparam Measure a model of `DistortionMeasure`, e.g. `Distortion_optimization::Symmetric_dirichlet`
\tparam NamedParameters a sequence of named parameters

\param tm the source mesh (not modified)
\param target the start map on input, the optimized map on output; written only on success, and
       only for free vertices
\param measure the distortion measure D
\param np optional named parameters among:
  - `CGAL::parameters::vertex_point_map`: source positions, `Point_2` or `Point_3`; default
    `get(CGAL::vertex_point, tm)`
  - `CGAL::parameters::vertex_is_constrained_map`: a readable vertex property map to `bool`;
    constrained vertices keep their target. Default: the border vertices.
  - `Distortion_optimization::parameters::vertex_weight_map`: omega(v) > 0; default 1
  - `Distortion_optimization::parameters::cell_weighting`: a `Distortion_optimization::Cell_weighting`;
    default `AVERAGE_VOLUME`
  - `CGAL::parameters::number_of_iterations`: the largest number of iterations; default 100
  - `Distortion_optimization::parameters::convergence_threshold`: stop when an iteration decreases
    the energy by less than this fraction of the energy above the measure's minimum (normalized
    measures) or of the energy; default 1e-4
  - `Distortion_optimization::parameters::local_solver`: `GRADIENT_DESCENT` (default) or `BFGS`
  - `Distortion_optimization::parameters::vertex_order`: `SORTED_PER_SWEEP` (default) or `GREEDY`
    (the paper's live priority queue)
  - `Distortion_optimization::parameters::schedule`: what an iteration does: `LOCAL` (the paper's
    sweep), `GLOBAL` (one preconditioned step of all free vertices) or `ALTERNATING` (default: both)
  - `Distortion_optimization::parameters::use_harmonic_start`: start from the harmonic map of the
    fixed vertices, or from the best safe point towards it; default `true` except with `LOCAL`
  - `Distortion_optimization::parameters::preserve_global_injectivity`: `true` to keep the map
    globally injective when boundary vertices are free (a move that would make the target
    boundary cross itself is shortened; exact predicates); the start map's boundary must not
    cross itself. Default `false`.
  - `Distortion_optimization::parameters::number_of_threads`: threads for the sweeps and global
    steps when the program links `CGAL::TBB_support`; 0 for all; default 1. The output is
    deterministic for a given number of threads.
  - `Distortion_optimization::parameters::parallel_sweep`: `INDEPENDENT_SETS` (default) or
    `PARTITION` (the paper's Algorithm 3), for more than one thread
  - `CGAL::parameters::visitor`: a callable `bool(std::size_t iteration, double energy)` called
    after each iteration; returning `false` stops the run with the map of that iteration

\returns a `Distortion_optimization::Result`

\throws Distortion_optimization::Invalid_input for the input `compute_distortion()` rejects,
non-positive vertex weights, and, when the measure is infinite on inverted cells (normalized), a
start map with an inverted or flat triangle (the message names it).
*/
template <class TriangleMesh, class TargetMap, class Measure,
          class NamedParameters = parameters::Default_named_parameters>
std::enable_if_t<!Distortion_optimization::internal::Is_c3t3<TriangleMesh>::value, Distortion_optimization::Result>
minimize_distortion(const TriangleMesh& tm, TargetMap target, const Measure& measure,
                    const NamedParameters& np = parameters::default_values())
{
  namespace DO = Distortion_optimization;
  auto adapter = DO::internal::make_triangle_mesh_adapter(tm, target, np);
  auto solved = DO::internal::minimize_adapted<2>(adapter, measure, np, [&](std::size_t i) {
    return static_cast<bool>(CGAL::is_border(adapter.vertex_of[i], tm));
  });

  using Point_2 = typename boost::property_traits<TargetMap>::value_type;
  const auto& problem = solved.second;
  for(std::size_t i = 0; i < adapter.vertex_of.size(); ++i)
    if(problem.is_free[i])
      put(target, adapter.vertex_of[i], Point_2(problem.map.target[i][0], problem.map.target[i][1]));
  return solved.first;
}

/*!
\ingroup PkgDistortionOptimizationRef

Minimizes the distortion of the simplicial map that sends each vertex `v` of the cells of the
complex `c3t3` from its position to `get(target, v)`, moving the free vertices' targets. Only the
cells in the complex count; the triangulation's other cells are ignored, and only vertices of
complex cells are read or written.

Same method, guarantees and result as the triangle-mesh overload (`n = 3`): no tetrahedron that is
positive in the start map is ever inverted or flattened (exact predicates).

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
\param c3t3 the source complex (not modified)
\param target the start map on input, the optimized map on output (free complex vertices only)
\param measure the distortion measure D
\tparam TargetMap a model of `ReadWritePropertyMap` from `C3T3::Triangulation::Vertex_handle` to a
        `Point_3`, e.g. `boost::associative_property_map<std::unordered_map<Vertex_handle, Point_3>>`
\param np the named parameters of the triangle-mesh overload, with vertex maps keyed by
        `Vertex_handle`; `vertex_point_map` is not used (positions come from the triangulation).
        Default constraint: every vertex on the complex boundary (on a facet between a complex
        cell and a cell outside the complex) is fixed.
*/
template <class C3T3, class TargetMap, class Measure,
          class NamedParameters = parameters::Default_named_parameters>
std::enable_if_t<Distortion_optimization::internal::Is_c3t3<C3T3>::value, Distortion_optimization::Result>
minimize_distortion(const C3T3& c3t3, TargetMap target, const Measure& measure,
                    const NamedParameters& np = parameters::default_values())
{
  namespace DO = Distortion_optimization;
  DO::internal::C3t3_adapter<C3T3> adapter(c3t3, target);
  auto solved = DO::internal::minimize_adapted<3>(adapter, measure, np, [&](std::size_t i) {
    return adapter.on_boundary[i] != 0;
  });

  using Point_3 = typename boost::property_traits<TargetMap>::value_type;
  const auto& problem = solved.second;
  for(std::size_t i = 0; i < adapter.vertex_of.size(); ++i)
    if(problem.is_free[i]) {
      const auto& x = problem.map.target[i];
      put(target, adapter.vertex_of[i], Point_3(x[0], x[1], x[2]));
    }
  return solved.first;
}

} // namespace CGAL

#endif // CGAL_MINIMIZE_DISTORTION_H
