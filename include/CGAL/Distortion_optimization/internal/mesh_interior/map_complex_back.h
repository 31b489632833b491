// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The last change of mesh_interior()'s complex: back from the scaled, moved copy that Mesh_3
// meshed to the units and place of the input.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MAP_COMPLEX_BACK_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MAP_COMPLEX_BACK_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <array>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Maps the complex that Mesh_3 made by x -> factor x + offset (factor a power of two): the points
// and their weights (squared lengths), the facets' surface centres and the sizes Mesh_3's
// optimizers keep in the vertices; the cells' cached circumcentres are dropped, to be computed
// again when asked for. Exact without offset. With one, the points are rounded to the input's
// coordinates: throws if a cell of the complex is then no longer positively oriented.
template <class C3T3>
void map_complex_back(C3T3& c3t3, double factor, const std::array<double, 3>& offset)
{
  using Tr = typename C3T3::Triangulation;
  using Bare_point = typename Tr::Bare_point;
  using Weighted_point = typename Tr::Weighted_point;
  const bool moved = offset != std::array<double, 3>{0, 0, 0};
  if(factor == 1 && !moved) return;
  Tr& tr = c3t3.triangulation();
  const auto mapped = [&](const Bare_point& p) {
    return Bare_point(factor * CGAL::to_double(p.x()) + offset[0], factor * CGAL::to_double(p.y()) + offset[1],
                      factor * CGAL::to_double(p.z()) + offset[2]);
  };
  const auto point = tr.geom_traits().construct_point_3_object();
  for(auto v : tr.finite_vertex_handles()) {
    const Weighted_point& p = v->point();
    v->set_point(Weighted_point(mapped(point(p)), factor * factor * CGAL::to_double(p.weight())));
    v->set_meshing_info(factor * v->meshing_info());
  }
  for(auto c : tr.all_cell_handles()) {
    c->invalidate_weighted_circumcenter_cache();
    for(int i = 0; i < 4; ++i) c->set_facet_surface_center(i, mapped(c->get_facet_surface_center(i)));
  }
  if(!moved) return;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    if(CGAL::orientation(point(tr.point(c, 0)), point(tr.point(c, 1)), point(tr.point(c, 2)), point(tr.point(c, 3))) != CGAL::POSITIVE)
      throw Invalid_input("mesh_interior: the surface is too far from the origin for its size: its tetrahedra, rounded "
                          "to its coordinates' precision, are no longer all positively oriented; move it nearer to the origin");
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MAP_COMPLEX_BACK_H
