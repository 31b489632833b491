// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H
#define CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H

#include <CGAL/Distortion_optimization/errors.h>

#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/enum.h>
#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

namespace internal {

// The tetrahedra must form a manifold complex, and build_triangulation() only notices a facet
// shared by three of them: a tetrahedron listed twice, or two that meet only at an edge or a
// vertex, would make a complex whose boundary is not a surface. Around each edge and each vertex,
// the tetrahedra must be connected through facets containing it; the message names the cells.
inline void check_manifold_tetrahedra(const std::vector<std::array<std::size_t, 4>>& tetrahedra)
{
  using Key = std::array<std::size_t, 4>;
  std::map<Key, std::size_t> seen;
  std::map<std::array<std::size_t, 2>, std::vector<std::size_t>> edges;
  std::map<std::size_t, std::vector<std::size_t>> stars;
  for(std::size_t t = 0; t < tetrahedra.size(); ++t) {
    Key k = tetrahedra[t];
    std::sort(k.begin(), k.end());
    const auto [it, fresh] = seen.emplace(k, t);
    if(!fresh)
      throw Invalid_input("tetrahedra " + std::to_string(it->second) + " and " + std::to_string(t) + " have the same vertices");
    for(int i = 0; i < 4; ++i) {
      stars[k[i]].push_back(t);
      for(int j = i + 1; j < 4; ++j) edges[{k[i], k[j]}].push_back(t);
    }
  }
  // Tetrahedra a and b share a facet iff they share three vertices.
  const auto share_facet = [&](std::size_t a, std::size_t b) {
    int common = 0;
    for(std::size_t u : tetrahedra[a])
      for(std::size_t w : tetrahedra[b]) common += u == w;
    return common == 3;
  };
  // Whether the cells (around one edge or vertex) are connected through shared facets.
  const auto connected = [&](const std::vector<std::size_t>& cells, std::size_t& apart) {
    std::vector<char> reached(cells.size(), 0);
    std::vector<std::size_t> stack = {0};
    reached[0] = 1;
    while(!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      for(std::size_t j = 0; j < cells.size(); ++j)
        if(!reached[j] && share_facet(cells[i], cells[j])) {
          reached[j] = 1;
          stack.push_back(j);
        }
    }
    for(std::size_t j = 0; j < cells.size(); ++j)
      if(!reached[j]) { apart = cells[j]; return false; }
    return true;
  };
  std::size_t apart = 0;
  for(const auto& [edge, cells] : edges)
    if(!connected(cells, apart))
      throw Invalid_input("tetrahedra " + std::to_string(cells[0]) + " and " + std::to_string(apart) + " meet only at the edge (" +
                          std::to_string(edge[0]) + ", " + std::to_string(edge[1]) + "): the complex is not manifold there");
  for(const auto& [vertex, cells] : stars)
    if(!connected(cells, apart))
      throw Invalid_input("tetrahedra " + std::to_string(cells[0]) + " and " + std::to_string(apart) + " meet only at vertex " +
                          std::to_string(vertex) + ": the complex is not manifold there");
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationRef
/// Fills `c3t3` (a `CGAL::Mesh_complex_3_in_triangulation_3`, cleared first) with the given
/// tetrahedra, all in subdomain `label` (> 0), vertex `i` at `points[i]`: the way to hand a mesh
/// from TetGen or a Medit file to `CGAL::minimize_distortion()`. Negatively oriented tetrahedra
/// are stored with two vertices swapped (a simplicial map does not depend on the vertex order).
/// \returns the vertex handle of each point (`Vertex_handle()` for a point in no tetrahedron).
/// \throws Invalid_input for an index out of range, a non-finite point, a flat tetrahedron (exact
/// predicate, the message names it), a tetrahedron listed twice, or tetrahedra that do not form a
/// manifold complex: a facet in more than two, or two that meet only at an edge or a vertex (the
/// message names them).
template <class C3T3>
std::vector<typename C3T3::Triangulation::Vertex_handle>
c3t3_from_tetrahedra(const std::vector<std::array<double, 3>>& points,
                     const std::vector<std::array<std::size_t, 4>>& tetrahedra, C3T3& c3t3, int label = 1)
{
  using Tr = typename C3T3::Triangulation;
  using Bare_point = typename Tr::Geom_traits::Point_3;
  if(points.empty() || tetrahedra.empty()) throw Invalid_input("no tetrahedron");
  if(label <= 0) throw Invalid_input("the subdomain label must be positive");
  std::vector<typename Tr::Point> tr_points;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Invalid_input("point " + std::to_string(i) + " is not finite");
    tr_points.push_back(typename Tr::Point(Bare_point(p[0], p[1], p[2])));
  }
  std::vector<std::array<int, 5>> cells;
  for(std::size_t t = 0; t < tetrahedra.size(); ++t) {
    std::array<int, 5> cell;
    for(int j = 0; j < 4; ++j) {
      if(tetrahedra[t][j] >= points.size())
        throw Invalid_input("tetrahedron " + std::to_string(t) + " has a vertex index out of range");
      cell[j] = static_cast<int>(tetrahedra[t][j]);
    }
    cell[4] = label;
    auto bare = [&](int j) { return Bare_point(points[cell[j]][0], points[cell[j]][1], points[cell[j]][2]); };
    const CGAL::Orientation o = CGAL::orientation(bare(0), bare(1), bare(2), bare(3));
    if(o == CGAL::COPLANAR) throw Invalid_input("tetrahedron " + std::to_string(t) + " is flat (zero volume)");
    if(o == CGAL::NEGATIVE) std::swap(cell[2], cell[3]);
    cells.push_back(cell);
  }
  internal::check_manifold_tetrahedra(tetrahedra);
  Tr tr;
  std::vector<typename Tr::Vertex_handle> handles;
  const std::map<std::array<int, 3>, typename Tr::Cell::Surface_patch_index> no_patches;
  if(!CGAL::build_triangulation<Tr, true>(tr, tr_points, cells, no_patches, handles))
    throw Invalid_input("the tetrahedra do not form a manifold complex (a facet is shared by more than two)");
  c3t3.clear();
  c3t3.triangulation().swap(tr);
  c3t3.rescan_after_load_of_triangulation();
  handles.erase(handles.begin());   // the infinite vertex
  return handles;
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H
