// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_DISTORTION_OPTIMIZATION_UNTANGLE_H
#define CGAL_DISTORTION_OPTIMIZATION_UNTANGLE_H

#include <CGAL/license/Distortion_optimization.h>

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
Where every border vertex is constrained, the rounds first start from the harmonic map of the
border over the inside (see `harmonic_map()`) if it has fewer inverted triangles than the start or
covers less area with them: its folds lie only about the border's reflex corners, where a start's
may lie anywhere (an inside mirrored, or pushed across the border); from the start if that fails,
or with `use_harmonic_start(false)`.
When the rounds end with triangles still inverted and `tm` is a disk (one boundary loop) with at
most three constrained vertices, the untangling starts again from Tutte's embedding of `tm` (the
boundary on a circle, each inner vertex the mean of its neighbours), moved onto the constrained
vertices by a similarity (at most two) or an affine map keeping orientations (three, where their
targets allow one): an injective map, for folds no descent opens (an ear of a free boundary turned
inside out). So it does when exactly the boundary vertices are constrained and their targets, in the
boundary's order, form a convex polygon (a circle, or a square with vertices along its sides):
Tutte's embedding with the boundary there is injective, but for triangles with their three
vertices on one side, which the rounds that follow it then open.
Use `CGAL::minimize_distortion()` afterwards (or its named parameter `untangle_first`) to optimize
a measure from the untangled map.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam TargetMap a model of `ReadWritePropertyMap` from vertex descriptors to a `Point_2`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param tm the source mesh (not modified)
\param target the map to untangle; written only on success (or when the visitor stops the run),
       and only for free vertices
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below; the other named parameters of `CGAL::minimize_distortion()` are ignored

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating the source positions to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `%Point_2` or `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
                    must be available in `TriangleMesh`.}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{a property map containing the constrained-or-not status of each vertex of `tm`:
                          a constrained vertex never moves}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `bool` as value type}
    \cgalParamDefault{the border vertices of `tm` are constrained; with `sliding_boundary`, no vertex is}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_weight_map}
    \cgalParamDescription{a property map associating a weight omega(v) to each vertex, which weighs the cells of the
                          barrier's energy as in `CGAL::minimize_distortion()`
                          (`Distortion_optimization::parameters::vertex_weight_map()`)}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and a number type convertible to `double` as value type}
    \cgalParamDefault{omega(v) = 1 for every vertex}
    \cgalParamExtra{Every weight must be finite and positive.}
  \cgalParamNEnd

  \cgalParamNBegin{cell_weighting}
    \cgalParamDescription{the cell weights w(c, v) of the barrier's energy
                          (`Distortion_optimization::parameters::cell_weighting()`)}
    \cgalParamType{`Distortion_optimization::Cell_weighting`}
    \cgalParamDefault{`Distortion_optimization::Cell_weighting::AVERAGE_VOLUME`}
  \cgalParamNEnd

  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of rounds (values of eps) of each untangling attempt: the map is first
                          untangled in growing neighbourhoods of its inverted cells, then as a whole if cells remain
                          inverted (and, with `preserve_global_injectivity`, first without the boundary guard)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`1000`}
  \cgalParamNEnd

  \cgalParamNBegin{use_harmonic_start}
    \cgalParamDescription{if `true`, where every border vertex is constrained, the rounds first start from the
                          harmonic map of the border when it tangles fewer triangles or less area than the start
                          (`Distortion_optimization::parameters::use_harmonic_start()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd

  \cgalParamNBegin{preserve_global_injectivity}
    \cgalParamDescription{if `true`, a boundary that does not cross itself in the start map never starts to
                          (exact predicates) (`Distortion_optimization::parameters::preserve_global_injectivity()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
    \cgalParamExtra{When some free vertex is on the boundary and the start's boundary crosses itself (or
                    a piece of the mesh lies inside another),
                    `Distortion_optimization::Crossing_start_boundary` is thrown.}
  \cgalParamNEnd

  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the number of threads; `0` for all the hardware offers
                          (`Distortion_optimization::parameters::number_of_threads()`)}
    \cgalParamType{`int`}
    \cgalParamDefault{`1`}
    \cgalParamExtra{Used when the program links `CGAL::TBB_support` (`CGAL_LINKED_WITH_TBB`); sequential otherwise.
                    A negative value is an error.}
  \cgalParamNEnd

  \cgalParamNBegin{sliding_boundary}
    \cgalParamDescription{a surface on which the boundary vertices that are not constrained slide
                          (`Distortion_optimization::parameters::sliding_boundary()`)}
    \cgalParamType{a model of `SlidingSurface` in the plane (its `project()` is called with `std::array<double, 2>`),
                   e.g. `Distortion_optimization::Sphere_surface` (a circle)}
    \cgalParamDefault{unused}
    \cgalParamExtra{With it, `vertex_is_constrained_map` defaults to no vertex.}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type of the vertex point map, using `CGAL::Kernel_traits`}
    \cgalParamExtra{Its `Orientation_2` decides, on `double` coordinates, the orientation of planar source triangles and
                    which target triangles are inverted; its `Collinear_3` whether a surface source triangle is
                    degenerate. Its points must be constructible from `double` coordinates.}
  \cgalParamNEnd

  \cgalParamNBegin{visitor}
    \cgalParamDescription{a callable called after each round (numbered from 1 over all attempts) with the mean
                          untangling barrier of the part of the map being untangled and, if it takes a third
                          argument, the number of inverted or flat cells left in that part; returning `false`
                          stops the run and writes the map of that round}
    \cgalParamType{a class with `bool operator()(std::size_t round, double barrier) const` or
                   `bool operator()(std::size_t round, double barrier, std::size_t inverted_cells) const`
                   (the result may be any type convertible to `bool`)}
    \cgalParamDefault{unused}
    \cgalParamExtra{The visitor is copied.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the numbers of inverted cells before and after, the rounds and the time

\throws Distortion_optimization::Invalid_input, leaving `target` unchanged, for the input
`CGAL::compute_distortion()` rejects, non-positive or non-finite vertex weights, a negative number
of threads, and when inverted cells remain after the rounds when Tutte's embedding does not apply
(the constraints may admit no injective map: e.g. a fixed boundary that crosses itself, or the
descent found none: e.g. one in a boundary fixed on a polygon that is not convex); the message
gives the number of cells still inverted. Before any round for a triangle mesh with a piece without
border (no map of a closed surface into the plane keeps its triangles' orientation) or, with
`preserve_global_injectivity`, a piece with handles and free border vertices.
\throws Distortion_optimization::Unmovable_inverted_cell (an `Invalid_input`) for an inverted
cell whose vertices are all constrained, before any round.
\throws Distortion_optimization::Crossing_start_boundary (an `Invalid_input`) with
`preserve_global_injectivity` when the boundary of the start map crosses itself or one piece of it
lies inside another.
*/
template <class TriangleMesh, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Untangle_result
#else
std::enable_if_t<!internal::Is_c3t3<TriangleMesh>::value, Untangle_result>
#endif
untangle(const TriangleMesh& tm, TargetMap target, const NamedParameters& np = CGAL::parameters::default_values())
{
  auto adapter = internal::make_triangle_mesh_adapter(tm, target, np);
  return internal::untangle_adapted(adapter, target, np);
}

/*!
\ingroup PkgDistortionOptimizationRef

Untangles the map that sends each vertex `v` of the cells of the complex `c3t3` from its position
in the triangulation to `get(target, v)` (only the cells in the complex count).

Same as the overload for triangle meshes, see `untangle()`, for tetrahedra, and only what differs
is documented here: the rounds are the same, and so is the first attempt from the harmonic map of
the boundary, made where every boundary vertex is constrained or slides (sliding ones held where
they are for it), but there is no second attempt from Tutte's embedding (which the triangle-mesh
overload makes for disks).

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
\tparam TargetMap a model of `ReadWritePropertyMap` from `C3T3::Triangulation::Vertex_handle` to a `Point_3`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param c3t3 the source complex (not modified)
\param target the map to untangle; written only on success (or when the visitor stops the run),
       and only for free complex vertices
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters": those of
       the overload for triangle meshes but `vertex_point_map` (positions come from the
       triangulation), with `C3T3::Triangulation::Vertex_handle` as the key type of the vertex
       property maps (`vertex_is_constrained_map`, `vertex_weight_map`), which cover the vertices of
       the cells of `c3t3`; what differs further is listed below. The other named parameters of
       `CGAL::minimize_distortion()` are ignored.

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDefault{the vertices on the boundary of the complex (on a facet between a cell of the complex and a
                      cell outside it) are constrained; with `sliding_boundary`, no vertex is}
  \cgalParamNEnd

  \cgalParamNBegin{sliding_boundary}
    \cgalParamType{a model of `SlidingSurface` in space (its `project()` is called with `std::array<double, 3>`),
                   e.g. `Distortion_optimization::Sphere_surface` or `Distortion_optimization::Triangle_surface`}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDefault{`CGAL::Kernel_traits<C3T3::Triangulation::Geom_traits::Point_3>::Kernel`, the kernel of the
                      triangulation's points}
    \cgalParamExtra{Its `Orientation_3` decides, on `double` coordinates, whether each source tetrahedron is positive
                    and which target tetrahedra are inverted. Its `Point_3` must be constructible from three `double`s.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the numbers of inverted cells before and after, the rounds and the time

\throws Distortion_optimization::Invalid_input, leaving `target` unchanged, as the triangle-mesh
overload, and for a complex with no cell or with a source tetrahedron that is not positively
oriented.
\throws Distortion_optimization::Crossing_start_boundary (an `Invalid_input`) with
`preserve_global_injectivity` when the boundary of the start map crosses itself or one piece of it
lies inside another.
*/
template <class C3T3, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Untangle_result
#else
std::enable_if_t<internal::Is_c3t3<C3T3>::value, Untangle_result>
#endif
untangle(const C3T3& c3t3, TargetMap target, const NamedParameters& np = CGAL::parameters::default_values())
{
  auto adapter = internal::make_c3t3_adapter(c3t3, target, np);
  return internal::untangle_adapted(adapter, target, np);
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_UNTANGLE_H
