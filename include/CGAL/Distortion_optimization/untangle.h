// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_DISTORTION_OPTIMIZATION_UNTANGLE_H
#define CGAL_DISTORTION_OPTIMIZATION_UNTANGLE_H

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/c3t3_adapter.h>
#include <CGAL/Distortion_optimization/internal/run_on_adapter.h>
#include <CGAL/Distortion_optimization/internal/triangle_mesh_adapter.h>

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
namespace Distortion_optimization {

/*!
\ingroup PkgDistortionOptimizationRef

Untangles the map that sends each vertex `v` of the triangle mesh `tm` from its source position to
`get(target, v)`: moves the free vertices' targets until every triangle has the orientation of its
source triangle (decided by the `geom_traits`' exact predicates), then stops.

The method is that of Garanzha, Kaporin, Kudryavtseva, Protais, Ray and Sokolov, "Foldover-free
maps in 50 lines of code" (2021): a barrier (`Untangling_barrier`) that is finite on inverted
cells is minimized for a decreasing regularization eps, each value by L-BFGS on the package's
kernel and threads; only the barrier keeps cells from folding, so that a fold can open through
flat states. Constrained vertices never move, and with `preserve_global_injectivity` a
boundary that does not cross itself never starts to. Every orientation is decided by the
`geom_traits`' exact predicates.
Use `CGAL::minimize_distortion()` afterwards (or its named parameter `untangle_first`) to optimize
a measure from the untangled map.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam TargetMap a model of `ReadWritePropertyMap` from vertex descriptors to a `Point_2`
\param tm the source mesh (not modified)
\param target the map to untangle; written only on success (or when the visitor stops the run),
       and only for free vertices
\param np the named parameters of `CGAL::minimize_distortion()` that define the problem and the
  run (`vertex_point_map`, `vertex_is_constrained_map`, `vertex_weight_map`, `cell_weighting`,
  `number_of_threads`, `preserve_global_injectivity`, `geom_traits`; the others are ignored), and:
  - `CGAL::parameters::number_of_iterations`: the largest number of rounds (values of eps);
    default 1000
  - `CGAL::parameters::visitor`: a callable `bool(std::size_t round, double inverted_cells)`
    called after each round; returning `false` stops the run and writes the map of that round

\returns the numbers of inverted cells before and after, the rounds and the time

\throws Distortion_optimization::Invalid_input, leaving `target` unchanged, for the input
`CGAL::compute_distortion()` rejects, for an inverted cell whose vertices are all constrained, and
when inverted cells remain after the rounds (the constraints may admit no injective map: e.g. a
fixed boundary that crosses itself); the message gives the number of cells still inverted.
*/
template <class TriangleMesh, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::enable_if_t<!internal::Is_c3t3<TriangleMesh>::value, Untangle_result>
untangle(const TriangleMesh& tm, TargetMap target, const NamedParameters& np = CGAL::parameters::default_values())
{
  auto adapter = internal::make_triangle_mesh_adapter(tm, target, np);
  return internal::untangle_adapted(adapter, target, np);
}

/*!
\ingroup PkgDistortionOptimizationRef

Untangles the map that sends each vertex of the cells of the complex `c3t3` to `get(target, v)`:
as the triangle-mesh overload, for tetrahedra, with property maps keyed by `Vertex_handle`; by
default the vertices on the complex boundary are constrained.
*/
template <class C3T3, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::enable_if_t<internal::Is_c3t3<C3T3>::value, Untangle_result>
untangle(const C3T3& c3t3, TargetMap target, const NamedParameters& np = CGAL::parameters::default_values())
{
  auto adapter = internal::make_c3t3_adapter(c3t3, target, np);
  return internal::untangle_adapted(adapter, target, np);
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_UNTANGLE_H
