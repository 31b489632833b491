// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Whether the boundary of a Mesh_3 complex is a 2-manifold, and where not: the place that
// separate_touching_tetrahedra() repairs and that mesh_interior() refuses when it remains.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MANIFOLD_BOUNDARY_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MANIFOLD_BOUNDARY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/complex_boundary.h>

#include <CGAL/number_utils.h>

#include <cstdio>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The boundary of the complex is made of the facets between its cells and the others (Mesh_3's
// facets in the complex, where the surface crosses their dual Voronoi edges, may differ in a few
// places). Whether that boundary is a 2-manifold at vertex v: the boundary facets at v, by their
// edges opposite v, must make one cycle. Returns (v, u) where an edge (v, u) has more than two
// boundary facets, (v, null) where every edge has two but the facets make several fans (two parts
// of the mesh touching at v), and (null, null) where the boundary is a 2-manifold at v.
template <class C3T3>
std::pair<typename C3T3::Triangulation::Vertex_handle, typename C3T3::Triangulation::Vertex_handle>
non_manifold_boundary_at(const C3T3& c3t3, typename C3T3::Triangulation::Vertex_handle v)
{
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  using Cell_handle = typename C3T3::Triangulation::Cell_handle;
  std::vector<Cell_handle> cells;
  c3t3.triangulation().incident_cells(v, std::back_inserter(cells));
  std::vector<std::pair<Vertex_handle, Vertex_handle>> link;
  for(Cell_handle c : cells) {
    if(!c3t3.is_in_complex(c)) continue;
    const int at = c->index(v);
    for(int i = 0; i < 4; ++i)
      if(i != at && is_boundary_facet(c3t3, c, i)) {
        Vertex_handle w[2];
        int k = 0;
        for(int j = 0; j < 4; ++j)
          if(j != i && j != at) w[k++] = c->vertex(j);
        link.emplace_back(w[0], w[1]);
      }
  }
  if(link.empty()) return {Vertex_handle(), Vertex_handle()};
  std::map<Vertex_handle, std::vector<Vertex_handle>> next;   // looked up only: the order does not matter
  for(const auto& [a, b] : link) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  // Around a boundary edge (v, u) the link has one edge per boundary facet at u.
  for(const auto& [a, b] : link)
    for(const Vertex_handle u : {a, b})
      if(next[u].size() != 2) return {v, u};
  std::size_t walked = 0;
  Vertex_handle previous = link.front().first, at = link.front().second;
  do {
    const auto& n = next[at];
    const Vertex_handle after = n[0] == previous ? n[1] : n[0];
    previous = at;
    at = after;
    ++walked;
  } while(previous != link.front().first && walked <= link.size());
  if(walked != link.size()) return {v, Vertex_handle()};
  return {Vertex_handle(), Vertex_handle()};
}

// The first place, in the order of the cells, where the boundary of the complex is not a
// 2-manifold (see non_manifold_boundary_at()); (null, null) if none.
template <class C3T3>
std::pair<typename C3T3::Triangulation::Vertex_handle, typename C3T3::Triangulation::Vertex_handle>
non_manifold_boundary_place(const C3T3& c3t3)
{
  for(const auto v : boundary_vertices_in_order(c3t3))
    if(const auto place = non_manifold_boundary_at(c3t3, v); place.first != decltype(v)()) return place;
  return {};
}

// Throws, giving the place, where the boundary of the complex is not a 2-manifold after the
// repairs: the maps of the package need one.
template <class C3T3>
void check_boundary_is_manifold(const C3T3& c3t3)
{
  if(const auto v = non_manifold_boundary_place(c3t3).first; v != typename C3T3::Triangulation::Vertex_handle()) {
    const auto p = c3t3.triangulation().geom_traits().construct_point_3_object()(v->point());
    char text[160];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    throw Invalid_input(std::string("mesh_interior: Mesh_3's tetrahedra touch at the vertex ") + text +
                        " without sharing a facet: their boundary is not a 2-manifold there (parts of the surface closer "
                        "than the sizes, or details finer than them); give smaller sizes");
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MANIFOLD_BOUNDARY_H
