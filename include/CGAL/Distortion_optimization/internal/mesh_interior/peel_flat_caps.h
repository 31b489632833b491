// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A repair of mesh_interior()'s complex: the flat caps that Mesh_3 leaves on the surface leave the
// complex.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_PEEL_FLAT_CAPS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_PEEL_FLAT_CAPS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/mesh_interior/complex_boundary.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Mesh_3 leaves a few flat caps on the surface: cells with two boundary facets and all four
// vertices on the surface, their two other facets nearly in the same place (the two diagonals of
// a nearly flat quadrilateral). They hold no volume, and a start map that bends the surface (the
// radial map, the ball map) can turn one over with all its vertices fixed, where no optimization
// can undo it. A cap thinner than `thickness` (3 volume / the area A of its boundary facets; the
// facet distance: the surface stays as close) and than a tenth of its width (sqrt(A): a regular
// tetrahedron's is 0.44, and a small cell across a sharp edge stays) leaves the complex, its two
// inner facets becoming boundary facets, unless the edge they share is already on the boundary
// (the surface would no longer be a manifold there). Repeated while some cap goes: a peeled cap
// may uncover another. Returns the number of cells removed.
template <class C3T3>
std::size_t peel_flat_caps(C3T3& c3t3, double thickness)
{
  using Cell_handle = typename C3T3::Triangulation::Cell_handle;
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  const auto& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  const auto area = [&](Cell_handle c, int i) {
    return std::sqrt(CGAL::to_double(CGAL::squared_area(point(tr.point(c, (i + 1) % 4)), point(tr.point(c, (i + 2) % 4)),
                                                        point(tr.point(c, (i + 3) % 4)))));
  };
  // Whether the edge (c, a, b) has a boundary facet.
  const auto on_boundary = [&](Cell_handle c, int a, int b) {
    auto f = tr.incident_facets(typename C3T3::Triangulation::Edge(c, a, b)), end = f;
    do {
      if(c3t3.is_in_complex(f->first) != c3t3.is_in_complex(f->first->neighbor(f->second))) return true;
    } while(++f != end);
    return false;
  };
  // Peeling keeps these: a cap's new boundary facets have its four vertices, already on the surface.
  const auto boundary_vertices = boundary_vertices_in_order(c3t3);
  const std::unordered_set<Vertex_handle> surface_vertex(boundary_vertices.begin(), boundary_vertices.end());
  // A cap's peeling can make caps only of its neighbours: after a pass over every cell, the passes
  // look at those alone (a pass over every cell after each peeled cap would cost a pass per cap).
  std::vector<Cell_handle> candidates;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) candidates.push_back(c);
  std::size_t peeled = 0;
  while(!candidates.empty()) {
    std::vector<Cell_handle> caps;
    for(Cell_handle c : candidates) {
      if(!c3t3.is_in_complex(c)) continue;
      int facets = 0;
      for(int i = 0; i < 4; ++i) facets += is_boundary_facet(c3t3, c, i) ? 1 : 0;
      if(facets != 2) continue;
      bool all_on_surface = true;
      for(int i = 0; i < 4 && all_on_surface; ++i) all_on_surface = surface_vertex.count(c->vertex(i)) > 0;
      if(!all_on_surface) continue;
      double boundary_area = 0;
      for(int i = 0; i < 4; ++i)
        if(is_boundary_facet(c3t3, c, i)) boundary_area += area(c, i);
      const double volume = std::abs(cell_volume(c3t3, c));
      if(3 * volume < (std::min)(thickness, 0.1 * std::sqrt(boundary_area)) * boundary_area) caps.push_back(c);
    }
    std::vector<Cell_handle> next;
    std::unordered_set<Cell_handle> queued;
    for(Cell_handle c : caps) {
      // The vertices opposite the boundary facets span the edge that the inner facets share.
      int opposite[2], k = 0;
      for(int i = 0; i < 4; ++i)
        if(is_boundary_facet(c3t3, c, i) && k < 2) opposite[k++] = i;
      if(k != 2 || !c3t3.is_in_complex(c) || on_boundary(c, opposite[0], opposite[1])) continue;   // (an earlier peel may have changed it)
      set_in_complex(c3t3, c, false, c3t3.subdomain_index(c), c3t3.surface_patch_index(c, opposite[0]));
      ++peeled;
      for(int i = 0; i < 4; ++i)
        if(c3t3.is_in_complex(c->neighbor(i)) && queued.insert(c->neighbor(i)).second) next.push_back(c->neighbor(i));
    }
    candidates.swap(next);
  }
  return peeled;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_PEEL_FLAT_CAPS_H
