// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_MINIMIZE_DISTORTION_H
#define CGAL_MINIMIZE_DISTORTION_H

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
    (the paper's live priority queue); with more than one thread the parallel sweeps always use
    the sorted order, and `GREEDY` applies to the one-thread sweep only
  - `CGAL::parameters::geom_traits`: a model of `Kernel` whose orientation predicates decide, on
    the coordinates the optimizer uses, the orientation of each source triangle (planar source)
    and whether a target triangle is inverted; default the kernel of the vertex point map's points.
    With a kernel with exact predicates (the default `Epick`, or `Epeck`) the guarantee below is exact.
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
  - `Distortion_optimization::parameters::sliding_boundary`: a model of `SlidingSurface`
    (`Distortion_optimization::Sphere_surface`, `Distortion_optimization::Triangle_surface` for
    tetrahedral maps) on which the boundary vertices that are not constrained slide; then no
    vertex is constrained by default. See sliding_surfaces.h.
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
  auto adapter = Distortion_optimization::internal::make_triangle_mesh_adapter(tm, target, np);
  return Distortion_optimization::internal::minimize_adapted(adapter, target, measure, np);
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
        cell and a cell outside the complex) is fixed, or, with `sliding_boundary`, slides on
        the given surface. `CGAL::parameters::geom_traits` defaults to
        the kernel of the triangulation's points; its `Orientation_3` decides source and target
        orientations.
*/
template <class C3T3, class TargetMap, class Measure,
          class NamedParameters = parameters::Default_named_parameters>
std::enable_if_t<Distortion_optimization::internal::Is_c3t3<C3T3>::value, Distortion_optimization::Result>
minimize_distortion(const C3T3& c3t3, TargetMap target, const Measure& measure,
                    const NamedParameters& np = parameters::default_values())
{
  auto adapter = Distortion_optimization::internal::make_c3t3_adapter(c3t3, target, np);
  return Distortion_optimization::internal::minimize_adapted(adapter, target, measure, np);
}

} // namespace CGAL

#endif // CGAL_MINIMIZE_DISTORTION_H
