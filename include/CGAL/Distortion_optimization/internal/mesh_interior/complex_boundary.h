// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The cells of a Mesh_3 complex and the boundary they make, as the repairs of mesh_interior()
// read and change them: which facets are on the boundary, moving a cell in or out with its facets,
// the boundary's vertices, the volume of a cell.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_COMPLEX_BOUNDARY_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_COMPLEX_BOUNDARY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>

#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Whether facet i of cell c, in the complex, is on its boundary (the cell across is not).
template <class C3T3>
bool is_boundary_facet(const C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c, int i)
{
  return !c3t3.is_in_complex(c->neighbor(i));
}

// Takes cell c out of the complex (`in` false) or into it (`in` true, with the subdomain index
// `subdomain`), and makes its facets follow: a facet between a cell of the complex and another
// is a facet of the complex (a new one with the surface patch index `patch`), and no other.
template <class C3T3>
void set_in_complex(C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c, bool in,
                    const typename C3T3::Subdomain_index& subdomain, const typename C3T3::Surface_patch_index& patch)
{
  if(in) c3t3.add_to_complex(c, subdomain);
  else c3t3.remove_from_complex(c);
  for(int i = 0; i < 4; ++i) {
    const bool boundary = in != c3t3.is_in_complex(c->neighbor(i));
    if(c3t3.is_in_complex(c, i) && !boundary) c3t3.remove_from_complex(c, i);
    else if(!c3t3.is_in_complex(c, i) && boundary) c3t3.add_to_complex(c, i, patch);
  }
}

// The vertices on the boundary of the complex, first seen first in the order of its cells.
template <class C3T3>
std::vector<typename C3T3::Triangulation::Vertex_handle> boundary_vertices_in_order(const C3T3& c3t3)
{
  std::vector<typename C3T3::Triangulation::Vertex_handle> order;
  std::unordered_set<typename C3T3::Triangulation::Vertex_handle> seen;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(is_boundary_facet(c3t3, c, i))
        for(int k = 1; k < 4; ++k)
          if(seen.insert(c->vertex((i + k) % 4)).second) order.push_back(c->vertex((i + k) % 4));
  return order;
}

// The signed volume of cell c of the triangulation of the complex (finite).
template <class C3T3>
double cell_volume(const C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c)
{
  const auto& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  return CGAL::to_double(CGAL::volume(point(tr.point(c, 0)), point(tr.point(c, 1)), point(tr.point(c, 2)), point(tr.point(c, 3))));
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_COMPLEX_BOUNDARY_H
