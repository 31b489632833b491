// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Whether a planar map's boundary is embedded: the exact test of the boundary guard.

#ifndef CGAL_DISTORTION_OPTIMIZATION_GLOBAL_INJECTIVITY_H
#define CGAL_DISTORTION_OPTIMIZATION_GLOBAL_INJECTIVITY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/*!
\ingroup PkgDistortionOptimizationRef

Whether the boundary of the planar map that sends each vertex `v` of the triangle mesh `tm` to
`get(target, v)` is embedded: no two boundary edges meet other than at their common vertex, and
no piece of the mesh (joined by no vertex) lies inside another. Decided with exact predicates on
the `double` coordinates of the targets. A map with no inverted or flat triangle (see
`CGAL::compute_distortion()`) whose boundary is embedded is globally injective, which
`minimize_distortion()` keeps with `parameters::preserve_global_injectivity()`.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam TargetMap a model of `ReadablePropertyMap` from vertex descriptors to a `Point_2`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param tm the triangle mesh (not modified)
\param target the image of each vertex
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and
                          `num_vertices(tm) - 1`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Invalid_input if a face of `tm` is not a triangle
*/
template <class TriangleMesh, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_boundary_embedded(const TriangleMesh& tm, const TargetMap& target,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using Guard = internal::Boundary_guard<2>;
  const auto index = CGAL::get_initialized_vertex_index_map(tm, np);
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for(auto f : faces(tm)) {
    std::array<std::uint32_t, 3> t;
    int i = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if(i == 3) throw Invalid_input("is_boundary_embedded(): a face is not a triangle");
      t[i++] = static_cast<std::uint32_t>(get(index, v));
    }
    triangles.push_back(t);
  }
  std::vector<internal::Vector<2>> x(num_vertices(tm));
  for(auto v : vertices(tm)) {
    const auto& p = get(target, v);
    x[get(index, v)] = internal::Vector<2>(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  }
  return Guard(Guard::boundary_faces(triangles), x.size(), internal::connected_pieces(triangles, x.size())).is_injective(x);
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_GLOBAL_INJECTIVITY_H
