// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_MINIMIZE_DISTORTION_H
#define CGAL_MINIMIZE_DISTORTION_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/c3t3_adapter.h>
#include <CGAL/Distortion_optimization/internal/run_on_adapter.h>
#include <CGAL/Distortion_optimization/internal/triangle_mesh_adapter.h>

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
/*!
\ingroup PkgDistortionOptimizationRef
\anchor minimize_distortion_triangle_mesh

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
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param tm the source mesh (not modified)
\param target the start map on input, the optimized map on output; written only on success, and
       only for free vertices
\param measure the distortion measure D
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating the source positions to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `%Point_2` (planar map) or `%Point_3` (surface parametrization) as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
                    must be available in `TriangleMesh`.}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{a property map containing the constrained-or-not status of each vertex of `tm`:
                          a constrained vertex keeps its target}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `bool` as value type}
    \cgalParamDefault{the border vertices of `tm` are constrained; with `sliding_boundary`, no vertex is}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_weight_map}
    \cgalParamDescription{a property map associating a weight omega(v) to each vertex of `tm`
                          (`Distortion_optimization::parameters::vertex_weight_map()`)}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and a number type convertible to `double` as value type}
    \cgalParamDefault{omega(v) = 1 for every vertex}
    \cgalParamExtra{Every weight must be finite and positive.}
  \cgalParamNEnd

  \cgalParamNBegin{cell_weighting}
    \cgalParamDescription{the cell weights w(c, v) of the energy (eq. 23)
                          (`Distortion_optimization::parameters::cell_weighting()`)}
    \cgalParamType{`Distortion_optimization::Cell_weighting`}
    \cgalParamDefault{`Distortion_optimization::Cell_weighting::AVERAGE_VOLUME`}
  \cgalParamNEnd

  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of iterations}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`100`}
  \cgalParamNEnd

  \cgalParamNBegin{convergence_threshold}
    \cgalParamDescription{the run stops when an iteration decreases the energy by less than this fraction
                          of the energy above the measure's minimum (normalized measures) or of the energy
                          (other measures) (`Distortion_optimization::parameters::convergence_threshold()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`1e-4`}
    \cgalParamExtra{It must be non-negative.}
  \cgalParamNEnd

  \cgalParamNBegin{local_solver}
    \cgalParamDescription{how one vertex's local problem is solved (`Distortion_optimization::parameters::local_solver()`)}
    \cgalParamType{`Distortion_optimization::Local_solver`: `GRADIENT_DESCENT` or `BFGS`}
    \cgalParamDefault{`Distortion_optimization::Local_solver::GRADIENT_DESCENT`}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_order}
    \cgalParamDescription{the order in which a sweep visits the free vertices
                          (`Distortion_optimization::parameters::vertex_order()`)}
    \cgalParamType{`Distortion_optimization::Vertex_order`: `SORTED_PER_SWEEP` or `GREEDY` (the paper's live priority queue)}
    \cgalParamDefault{`Distortion_optimization::Vertex_order::SORTED_PER_SWEEP`}
    \cgalParamExtra{With more than one thread the parallel sweeps always use the sorted order:
                    `GREEDY` applies to the one-thread sweep only.}
  \cgalParamNEnd

  \cgalParamNBegin{schedule}
    \cgalParamDescription{what an iteration does: `LOCAL` (the paper's sweep), `GLOBAL` (one preconditioned
                          step of all free vertices) or `ALTERNATING` (both) (`Distortion_optimization::parameters::schedule()`)}
    \cgalParamType{`Distortion_optimization::Schedule`}
    \cgalParamDefault{`GLOBAL` where the global steps are projected Newton steps (a measure that has a `hessian()`; on tetrahedral complexes with no vertex constrained or sliding, also `Conformal_dilatation`, `Condition_number` and `Isometric_dilatation`, whose steps are a smooth model's), with a local sweep added to an iteration whose step gains too little to go on or is cut short of its full length; `ALTERNATING` otherwise (the reweighted Laplacian's steps, and a smooth model's with sliding vertices, whose minimizers are not the measure's)}
  \cgalParamNEnd

  \cgalParamNBegin{use_harmonic_start}
    \cgalParamDescription{if `true`, the run starts from the harmonic map of the fixed vertices when it is valid
                          and better, or from the best safe point towards it
                          (`Distortion_optimization::parameters::use_harmonic_start()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`, except with `Distortion_optimization::Schedule::LOCAL`: then `false`}
  \cgalParamNEnd

  \cgalParamNBegin{untangle_first}
    \cgalParamDescription{if `true`, a start map with inverted or flat triangles is first untangled as by
                          `Distortion_optimization::untangle()`, then the measure is minimized from the untangled map
                          (`Distortion_optimization::parameters::untangle_first()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`: under a normalized measure such a start is an error}
    \cgalParamExtra{The untangling runs at most 1000 rounds (`number_of_iterations` applies to the minimization
                    only) and reports each round to the visitor. The result reports it in
                    `inverted_start_cells`, `untangle_iterations` and `untangle_seconds`.}
  \cgalParamNEnd

  \cgalParamNBegin{preserve_global_injectivity}
    \cgalParamDescription{if `true`, the map is kept globally injective when boundary vertices are free:
                          a move that would make the target boundary cross itself is shortened (exact predicates)
                          (`Distortion_optimization::parameters::preserve_global_injectivity()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
    \cgalParamExtra{The boundary of the start map must not cross itself, nor may a piece of the mesh lie inside another, otherwise
                    `Distortion_optimization::Crossing_start_boundary` is thrown (only when some free vertex
                    is on the boundary).}
  \cgalParamNEnd

  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the number of threads of the sweeps and global steps; `0` for all the hardware offers
                          (`Distortion_optimization::parameters::number_of_threads()`)}
    \cgalParamType{`int`}
    \cgalParamDefault{`1`}
    \cgalParamExtra{Used when the program links `CGAL::TBB_support` (`CGAL_LINKED_WITH_TBB`); sequential otherwise.
                    The output is deterministic for a given number of threads. A negative value is an error.}
  \cgalParamNEnd

  \cgalParamNBegin{parallel_sweep}
    \cgalParamDescription{how local sweeps are shared among threads, with more than one thread
                          (`Distortion_optimization::parameters::parallel_sweep()`)}
    \cgalParamType{`Distortion_optimization::Parallel_sweep`: `INDEPENDENT_SETS` or `PARTITION` (the paper's Algorithm 3)}
    \cgalParamDefault{`Distortion_optimization::Parallel_sweep::INDEPENDENT_SETS`}
  \cgalParamNEnd

  \cgalParamNBegin{global_solver}
    \cgalParamDescription{the system that gives the direction of a global step
                          (`Distortion_optimization::parameters::global_solver()`)}
    \cgalParamType{`Distortion_optimization::Global_solver`: `REWEIGHTED_LAPLACIAN` or `PROJECTED_NEWTON`}
    \cgalParamDefault{`Distortion_optimization::Global_solver::PROJECTED_NEWTON`}
    \cgalParamExtra{Newton steps need a measure with a `hessian()`, otherwise the step is the Laplacian's; sliding vertices take Newton's step restricted to their tangent planes.}
  \cgalParamNEnd

  \cgalParamNBegin{sliding_boundary}
    \cgalParamDescription{a surface on which the border vertices that are not constrained slide
                          (`Distortion_optimization::parameters::sliding_boundary()`)}
    \cgalParamType{a model of `SlidingSurface` in the plane (its `project()` is called with `std::array<double, 2>`),
                   e.g. `Distortion_optimization::Sphere_surface` (a circle)}
    \cgalParamDefault{unused: the border vertices are constrained, or, when `vertex_is_constrained_map`
                      frees them, move freely}
    \cgalParamExtra{With it, `vertex_is_constrained_map` defaults to no vertex.}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type of the vertex point map, using `CGAL::Kernel_traits`}
    \cgalParamExtra{Its `Orientation_2` decides, on the coordinates the optimizer uses (`double`), the orientation of
                    each planar source triangle and whether a target triangle is inverted; its `Collinear_3` whether a
                    surface source triangle is degenerate. Its points must be constructible from `double` coordinates.
                    With a kernel with exact predicates (e.g. `Exact_predicates_inexact_constructions_kernel` or
                    `Exact_predicates_exact_constructions_kernel`) the guarantee above is exact.}
  \cgalParamNEnd

  \cgalParamNBegin{visitor}
    \cgalParamDescription{a callable called after each iteration (numbered from 1) with the mean energy of the map
                          of that iteration and, if it takes a third argument, the number of its inverted or flat
                          cells; returning `false` stops the run with that map}
    \cgalParamType{a class with `bool operator()(std::size_t iteration, double energy) const` or
                   `bool operator()(std::size_t iteration, double energy, std::size_t inverted_cells) const`
                   (the result may be any type convertible to `bool`)}
    \cgalParamDefault{unused}
    \cgalParamExtra{The visitor is copied. With `untangle_first`, the untangling's rounds are reported first, as
                    by `Distortion_optimization::untangle()`, then the iterations are numbered from 1 again. A
                    run stopped before the map is untangled returns that map with energies that are not numbers.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Distortion_optimization::Result`

\throws Distortion_optimization::Invalid_input, leaving `target` unchanged, for the input
`compute_distortion()` rejects, non-positive or non-finite vertex weights, a negative or NaN
convergence threshold, a negative number of threads, a start map on which the measure is not a
number, and, when the measure is infinite on inverted cells (normalized), a start map with an
inverted or flat triangle (the message names it) unless `untangle_first` is set; with
`untangle_first`, when the untangling fails; and for a measure that decreases as the map shrinks
(Dirichlet, or a sum or product with it) when fewer than three vertices are constrained and none
slides, in the mesh or in one of its pieces (its minimum collapses the map or that piece).
\throws Distortion_optimization::Crossing_start_boundary (an `Invalid_input`) with
`preserve_global_injectivity` when the boundary of the start map crosses itself or one piece of it
lies inside another.
*/
template <class TriangleMesh, class TargetMap, class Measure,
          class NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Distortion_optimization::Result
#else
std::enable_if_t<!Distortion_optimization::internal::Is_c3t3<TriangleMesh>::value, Distortion_optimization::Result>
#endif
minimize_distortion(const TriangleMesh& tm, TargetMap target, const Measure& measure,
                    const NamedParameters& np = parameters::default_values())
{
  auto adapter = Distortion_optimization::internal::make_triangle_mesh_adapter(tm, target, np);
  return Distortion_optimization::internal::minimize_adapted(adapter, target, measure, np);
}

/*!
\ingroup PkgDistortionOptimizationRef

Minimizes the distortion of the simplicial map that sends each vertex `v` of the cells of the
complex `c3t3` from its position to `get(target, v)`, moving the free vertices' targets. Only the
cells in the complex count; the triangulation's other cells are ignored, and only vertices of
complex cells are read or written.

Same as the overload for triangle meshes, see
<code>\ref minimize_distortion_triangle_mesh "minimize_distortion()"</code>, for tetrahedra
(`n = 3`): the method, its guarantees and the result are the same, and only what differs is
documented here. No tetrahedron that is positive in the start map is ever inverted or flattened
(exact predicates). The source positions are the points of the triangulation.

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
\tparam TargetMap a model of `ReadWritePropertyMap` from `C3T3::Triangulation::Vertex_handle` to a
        `Point_3`, e.g. `boost::associative_property_map<std::unordered_map<Vertex_handle, Point_3>>`
\tparam Measure a model of `DistortionMeasure`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param c3t3 the source complex (not modified)
\param target the start map on input, the optimized map on output; written only on success, and
       only for free complex vertices
\param measure the distortion measure D
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters": those of
       the overload for triangle meshes but `vertex_point_map` (positions come from the
       triangulation), with `C3T3::Triangulation::Vertex_handle` as the key type of the vertex
       property maps (`vertex_is_constrained_map`, `vertex_weight_map`), which cover the vertices of
       the cells of `c3t3`; what differs further is listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDefault{the vertices on the boundary of the complex (on a facet between a cell of the complex and a
                      cell outside it) are constrained; with `sliding_boundary`, no vertex is}
  \cgalParamNEnd

  \cgalParamNBegin{global_solver}
    \cgalParamExtra{Besides the measures with a `hessian()`, with no vertex constrained or sliding,
                    `Conformal_dilatation` and `Condition_number` take the Newton steps of `MIPS`,
                    `Isometric_dilatation` those of `Symmetric_dirichlet` (the same minimizers, without the
                    kink there); with sliding vertices and none constrained, the model's Hessian is the metric of
                    the measure's own gradient. The line search decides on the measure itself. The Newton
                    system of a complex (3 unknowns per free vertex) fills in too much to factor: it is solved
                    inexactly, by Jacobi-preconditioned conjugate gradients (truncated Newton): 60 iterations at
                    most, up to 960 while 60 leave the residual above half the gradient (not for a model's steps
                    with nothing sliding, whose preconditioner may change instead).}
  \cgalParamNEnd

  \cgalParamNBegin{sliding_boundary}
    \cgalParamType{a model of `SlidingSurface` in space (its `project()` is called with `std::array<double, 3>`),
                   e.g. `Distortion_optimization::Sphere_surface` or `Distortion_optimization::Triangle_surface`}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDefault{`CGAL::Kernel_traits<C3T3::Triangulation::Geom_traits::Point_3>::Kernel`, the kernel of the
                      triangulation's points}
    \cgalParamExtra{Its `Orientation_3` decides, on the coordinates the optimizer uses (`double`), whether each source
                    tetrahedron is positive and whether a target tetrahedron is inverted. Its `Point_3` must be
                    constructible from three `double`s.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Distortion_optimization::Result`

\throws Distortion_optimization::Invalid_input, leaving `target` unchanged, as the triangle-mesh
overload (a measure that decreases as the map shrinks needs four constrained vertices in each piece here, or
sliding ones), and for a complex with no cell or with a source tetrahedron that is not positively
oriented.
\throws Distortion_optimization::Crossing_start_boundary (an `Invalid_input`) with
`preserve_global_injectivity` when the boundary of the start map crosses itself or one piece of it
lies inside another.
*/
template <class C3T3, class TargetMap, class Measure,
          class NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Distortion_optimization::Result
#else
std::enable_if_t<Distortion_optimization::internal::Is_c3t3<C3T3>::value, Distortion_optimization::Result>
#endif
minimize_distortion(const C3T3& c3t3, TargetMap target, const Measure& measure,
                    const NamedParameters& np = parameters::default_values())
{
  auto adapter = Distortion_optimization::internal::make_c3t3_adapter(c3t3, target, np);
  return Distortion_optimization::internal::minimize_adapted(adapter, target, measure, np);
}

} // namespace CGAL

#endif // CGAL_MINIMIZE_DISTORTION_H
