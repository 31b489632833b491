// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// c3t3_from_tetrahedra()'s construction: the triangulation of checked tetrahedra and their adjacency.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_BUILD_TRIANGULATION_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_BUILD_TRIANGULATION_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/c3t3_from_tetrahedra/manifold_tetrahedra.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Builds `tr` from positively oriented tetrahedra and their adjacency (check_manifold_tetrahedra()),
// the way CGAL's build_triangulation() does (tet_soup_to_c3t3.h), but from the adjacency already
// found rather than from a hash map of facets, which took most of its time.
// Each boundary facet gets an infinite cell, and those meet across the boundary's edges. A point
// in no tetrahedron gets no vertex: its handle is Vertex_handle(). With threads it runs beside the
// edge and vertex checks, on input they may still refuse (an edge or vertex pinched): it must then
// at most throw or build a triangulation that is thrown away, never assume a manifold.
template <class Tr>
std::vector<typename Tr::Vertex_handle> build_triangulation(Tr& tr, const std::vector<typename Tr::Point>& points,
                                                            const std::vector<std::array<std::size_t, 4>>& cells,
                                                            const std::vector<std::uint32_t>& across, int label)
{
  using Vertex_handle = typename Tr::Vertex_handle;
  using Cell_handle = typename Tr::Cell_handle;
  auto& tds = tr.tds();
  tds.clear();   // not tr.clear(), which would create an infinite vertex of a 0-dimensional triangulation
  tds.set_dimension(3);   // before any adjacency: set_adjacency() asserts that the facet index is within it
  const Vertex_handle infinite = tds.create_vertex();
  infinite->set_dimension(-1);
  tr.set_infinite_vertex(infinite);
  std::vector<Vertex_handle> handles(points.size());
  for(const auto& cell : cells)
    for(std::size_t v : cell)
      if(handles[v] == Vertex_handle()) {
        handles[v] = tds.create_vertex();
        handles[v]->set_point(points[v]);
        handles[v]->set_dimension(3);
      }
  std::vector<Cell_handle> finite(cells.size());
  for(std::size_t t = 0; t < cells.size(); ++t) {
    const auto& k = cells[t];
    finite[t] = tds.create_cell(handles[k[0]], handles[k[1]], handles[k[2]], handles[k[3]]);
    finite[t]->set_subdomain_index(label);
    for(std::size_t v : k)
      if(handles[v]->cell() == Cell_handle()) handles[v]->set_cell(finite[t]);
  }
  // Each facet between two tetrahedra, set once from its lower one; a boundary facet gets an
  // infinite cell, oriented as CGAL's, whose facets through the infinite vertex are keyed by
  // their boundary edge (smaller point index in the high bits).
  std::vector<std::pair<std::uint64_t, std::pair<Cell_handle, int>>> edges;
  for(std::size_t t = 0; t < cells.size(); ++t)
    for(int j = 0; j < 4; ++j) {
      const std::uint32_t other = across[4 * t + j];
      if(other != no_tetrahedron) {
        if(other / 4 > t) tds.set_adjacency(finite[t], j, finite[other / 4], other % 4);
        continue;
      }
      const auto& k = cells[t];
      const std::array<std::size_t, 3> f = (j == 0 || j == 2) ? std::array<std::size_t, 3>{k[(j + 2) % 4], k[(j + 1) % 4], k[(j + 3) % 4]}
                                                              : std::array<std::size_t, 3>{k[(j + 3) % 4], k[(j + 1) % 4], k[(j + 2) % 4]};
      const Cell_handle c = tds.create_cell(infinite, handles[f[0]], handles[f[1]], handles[f[2]]);
      tds.set_adjacency(c, 0, finite[t], j);
      for(int m = 1; m < 4; ++m) {
        const std::size_t a = f[m % 3], b = f[(m + 1) % 3];
        edges.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), {c, m}});
      }
    }
  // Tetrahedra in space have a boundary; without one (the five of a 4-simplex's boundary, say)
  // they overlap and there is no infinite cell to give the infinite vertex.
  if(edges.empty()) throw Invalid_input("every facet is shared by two tetrahedra: the complex has no boundary, so its cells overlap");
  infinite->set_cell(edges.front().second.first);
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for(std::size_t e = 0; e < edges.size(); e += 2) {
    if(e + 1 == edges.size() || edges[e + 1].first != edges[e].first || (e + 2 < edges.size() && edges[e + 2].first == edges[e].first))
      throw Invalid_input("the boundary of the tetrahedra is not a surface at the edge (" + std::to_string(edges[e].first >> 32) +
                          ", " + std::to_string(edges[e].first & 0xffffffffu) + ")");
    tds.set_adjacency(edges[e].second.first, edges[e].second.second, edges[e + 1].second.first, edges[e + 1].second.second);
  }
  return handles;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_BUILD_TRIANGULATION_H
