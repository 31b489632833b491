// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_COMPUTE_DISTORTION_H
#define CGAL_COMPUTE_DISTORTION_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Distortion_statistics.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/c3t3_adapter.h>
#include <CGAL/Distortion_optimization/internal/named_parameters.h>
#include <CGAL/Distortion_optimization/internal/statistics.h>
#include <CGAL/Distortion_optimization/internal/triangle_mesh_adapter.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Evaluates an adapter's map (Triangle_mesh_adapter or C3t3_adapter) with the given weights of the
// map's vertices, writing per-cell values to the named parameters' optional cell_distortion_map and
// inverted_cell_map. With `oriented` false (a surface-to-surface map, which has no orientation) no
// cell counts as inverted.
template <class Adapter, class Measure, class NamedParameters>
Distortion_statistics evaluate_adapted(const Adapter& adapter, const Measure& measure, const NamedParameters& np,
                                       const std::vector<double>& vertex_weights, bool oriented = true)
{
  auto cell_map = CGAL::parameters::get_parameter(np, internal_np::cell_distortion_map);
  auto inverted_map = CGAL::parameters::get_parameter(np, internal_np::inverted_cell_map);
  constexpr bool wants_cells = !std::is_same<decltype(cell_map), CGAL::internal_np::Param_not_found>::value;
  constexpr bool wants_inverted = !std::is_same<decltype(inverted_map), CGAL::internal_np::Param_not_found>::value;
  std::vector<double> per_cell;
  std::vector<unsigned char> inverted;
  Distortion_statistics stats = evaluate(adapter.map, measure, adapter.traits, vertex_weights,
                                         wants_cells ? &per_cell : nullptr, wants_inverted ? &inverted : nullptr, oriented);
  // Volume-weighted energies in the user's units: the adapter scaled coordinates (coordinate_scale).
  const double volume_unit = std::pow(1. / adapter.scale, Adapter::dimension);
  stats.energy_volume *= volume_unit;
  stats.energy_average_volume *= volume_unit;
  if constexpr(wants_cells)
    for(std::size_t c = 0; c < per_cell.size(); ++c) put(cell_map, adapter.cell_of[c], per_cell[c]);
  if constexpr(wants_inverted)
    for(std::size_t c = 0; c < inverted.size(); ++c) put(inverted_map, adapter.cell_of[c], inverted[c] != 0);
  return stats;
}

} // namespace internal
} // namespace Distortion_optimization

/*!
\ingroup PkgDistortionOptimizationRef
\anchor compute_distortion_triangle_mesh

Measures the distortion of the simplicial map that sends each vertex `v` of the triangle mesh
`tm` from its source position to `get(target, v)`.

Each face's Jacobian is computed in the face's own frame (eq. 20 of the paper; for a planar
`Point_2` source, in the plane itself), its signed singular values give the measure's value
(eq. 21), and the values are averaged with the weights of eq. 23.

The target may also be a `Point_3` (a surface-to-surface map, e.g. a surface carried through a
volume map by `Distortion_optimization::carry_surface()`): each target triangle is then measured in
its own plane, as the source triangles of a surface are, so that the Jacobian is the 2 x 2 map
between the two triangles' planes. Such a map has no orientation: `inverted_cells` is always 0, and
a flat (zero-area) target triangle has the measure's value on a flat cell (+infinity for a
normalized measure). Only this function accepts `Point_3` targets for a triangle mesh
(`minimize_distortion()` does not compile with them).

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam TargetMap a model of `ReadablePropertyMap` from vertex descriptors to a `Point_2` or a `Point_3`
\tparam Measure a model of `DistortionMeasure`, e.g. `Distortion_optimization::Conformal_dilatation`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param tm the source mesh; it is not modified
\param target the image of each vertex
\param measure the distortion measure
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating the source positions to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `%Point_2` (planar map) or `%Point_3` (surface to plane) as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
                    must be available in `TriangleMesh`.}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_weight_map}
    \cgalParamDescription{a property map associating a weight omega(v) to each vertex of `tm`
                          (`Distortion_optimization::parameters::vertex_weight_map()`)}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and a number type convertible to `double` as value type}
    \cgalParamDefault{omega(v) = 1 for every vertex}
    \cgalParamExtra{Every weight must be finite and positive.}
  \cgalParamNEnd

  \cgalParamNBegin{cell_distortion_map}
    \cgalParamDescription{a property map that receives the distortion D(J_c) of each face of `tm`
                          (`Distortion_optimization::parameters::cell_distortion_map()`)}
    \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
                   as key type and `double` as value type}
    \cgalParamDefault{unused: no per-face value is written}
    \cgalParamExtra{Written only when the function returns normally.}
  \cgalParamNEnd

  \cgalParamNBegin{inverted_cell_map}
    \cgalParamDescription{a property map that receives, for each face of `tm`, whether the map inverts or flattens
                          it: the faces counted in `inverted_cells`
                          (`Distortion_optimization::parameters::inverted_cell_map()`)}
    \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
                   as key type and `bool` as value type}
    \cgalParamDefault{unused}
    \cgalParamExtra{Written only when the function returns normally; `false` for every face with a `Point_3` target.
                    Some measures are finite on inverted cells (ARAP, Dirichlet): this map tells them apart.}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type of the vertex point map, using `CGAL::Kernel_traits`}
    \cgalParamExtra{Its `Orientation_2` decides, on `double` coordinates, the orientation of planar source faces and
                    which target faces are inverted; its `Collinear_3` whether a surface source face is degenerate.
                    Its points must be constructible from `double` coordinates.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the weighted means, energies, extreme values and the number of inverted faces (counted
with exact orientation predicates: a face is inverted when its image's orientation differs from
the source's; surface faces count as positively oriented in their own frames; always 0 for
`Point_3` targets).

\throws Distortion_optimization::Invalid_input for an empty mesh, a face that is not a triangle,
non-finite coordinates or weights, a non-positive weight, a degenerate source face, or a
non-finite Jacobian.
*/
template <class TriangleMesh, class TargetMap, class Measure,
          class NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Distortion_optimization::Distortion_statistics
#else
std::enable_if_t<!Distortion_optimization::internal::Is_c3t3<TriangleMesh>::value, Distortion_optimization::Distortion_statistics>
#endif
compute_distortion(const TriangleMesh& tm, const TargetMap& target, const Measure& measure,
                   const NamedParameters& np = parameters::default_values())
{
  namespace DOI = Distortion_optimization::internal;
  const auto adapter = DOI::make_triangle_mesh_adapter(tm, target, np, std::true_type());
  // A triangle measured in its own plane has no orientation to lose: its frame makes det J >= 0,
  // and a flat image would only be counted for being flat.
  return DOI::evaluate_adapted(adapter, measure, np, adapter.map_vertex_weights(DOI::read_vertex_weights(adapter, np)),
                               !std::decay_t<decltype(adapter)>::per_corner);
}

/*!
\ingroup PkgDistortionOptimizationRef

Measures the distortion of the simplicial map that sends each vertex `v` of the cells of the
complex `c3t3` (only the cells in the complex) from its position in the triangulation to
`get(target, v)`.

Same as the overload for triangle meshes, see
<code>\ref compute_distortion_triangle_mesh "compute_distortion()"</code>, for tetrahedra
(`n = 3`), and only what differs is documented here. The target is a `Point_3` in space: unlike
a `Point_3` target of a triangle mesh, it keeps an orientation, and inverted cells are counted.

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
\tparam TargetMap a model of `ReadablePropertyMap` from `C3T3::Triangulation::Vertex_handle` to a `Point_3`
\tparam Measure a model of `DistortionMeasure`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param c3t3 the source complex; it is not modified
\param target the image of each vertex of the cells of the complex
\param measure the distortion measure
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters": those of
       the overload for triangle meshes but `vertex_point_map` (positions come from the
       triangulation), with `C3T3::Triangulation::Vertex_handle` as the key type of
       `vertex_weight_map` (the vertices of the cells of `c3t3`) and
       `C3T3::Triangulation::Cell_handle` as the key type of `cell_distortion_map` and
       `inverted_cell_map` (the cells of the complex); what differs further is listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{geom_traits}
    \cgalParamDefault{`CGAL::Kernel_traits<C3T3::Triangulation::Geom_traits::Point_3>::Kernel`, the kernel of the
                      triangulation's points}
    \cgalParamExtra{Its `Orientation_3` decides, on `double` coordinates, whether each source tetrahedron is positive
                    and which target tetrahedra are inverted. Its `Point_3` must be constructible from three `double`s.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the weighted means, energies, extreme values and the number of inverted cells (exact
orientation predicates).

\throws Distortion_optimization::Invalid_input for a complex with no cell, a source tetrahedron that
is not positively oriented, non-finite target coordinates or weights, a non-positive weight, or a
non-finite Jacobian.
*/
template <class C3T3, class TargetMap, class Measure,
          class NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Distortion_optimization::Distortion_statistics
#else
std::enable_if_t<Distortion_optimization::internal::Is_c3t3<C3T3>::value, Distortion_optimization::Distortion_statistics>
#endif
compute_distortion(const C3T3& c3t3, const TargetMap& target, const Measure& measure,
                   const NamedParameters& np = parameters::default_values())
{
  const auto adapter = Distortion_optimization::internal::make_c3t3_adapter(c3t3, target, np);
  return Distortion_optimization::internal::evaluate_adapted(adapter, measure, np,
                                                             Distortion_optimization::internal::read_vertex_weights(adapter, np));
}

} // namespace CGAL

#endif // CGAL_COMPUTE_DISTORTION_H
