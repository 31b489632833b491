// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A repair of mesh_interior()'s complex: where its tetrahedra, or the space outside them, touch
// only at a vertex or along an edge, the smaller side changes sides, so that the boundary becomes a
// 2-manifold.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_SEPARATE_TOUCHING_TETRAHEDRA_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_SEPARATE_TOUCHING_TETRAHEDRA_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/mesh_interior/complex_boundary.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/manifold_boundary.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Where parts of the surface are closer than the sizes, Mesh_3's tetrahedra may touch only at a
// vertex or along an edge, or the space outside them may (a thin hole or slot closing at a
// vertex). There, the tetrahedra on that side at the vertex are grouped (joined through their
// facets at it; at an edge with more than two boundary facets, the fans of tetrahedra of the
// complex around it), and all but the group of largest volume change sides: touching parts are
// separated, a closing hole is filled at the vertex. Repeated while the boundary is not a
// 2-manifold, up to `limit` cells changed at 100 places (a few cells are the rule; beyond, the
// final check refuses the mesh). Returns the number of cells changed.
template <class C3T3>
std::size_t separate_touching_tetrahedra(C3T3& c3t3, std::size_t limit)
{
  using Tr = typename C3T3::Triangulation;
  using Cell_handle = typename Tr::Cell_handle;
  using Vertex_handle = typename Tr::Vertex_handle;
  const Tr& tr = c3t3.triangulation();
  const auto volume = [&](Cell_handle c) {
    return tr.is_infinite(c) ? std::numeric_limits<double>::infinity()   // the outside stays outside
                             : cell_volume(c3t3, c);
  };
  // The cells at v on one side (in the complex or not), joined through their facets at v.
  const auto groups_at = [&](Vertex_handle v, bool in) {
    std::vector<Cell_handle> cells;
    tr.incident_cells(v, std::back_inserter(cells));
    std::vector<std::vector<Cell_handle>> groups;
    std::unordered_set<Cell_handle> seen;
    for(Cell_handle c : cells) {
      if(c3t3.is_in_complex(c) != in || !seen.insert(c).second) continue;
      groups.push_back({c});
      for(std::size_t k = 0; k < groups.back().size(); ++k) {
        const Cell_handle a = groups.back()[k];
        for(int i = 0; i < 4; ++i) {
          const Cell_handle b = a->neighbor(i);
          if(i != a->index(v) && c3t3.is_in_complex(b) == in && seen.insert(b).second) groups.back().push_back(b);
        }
      }
    }
    return groups;
  };
  // The fans of cells of the complex around the edge (v, u), in the order of a circulation.
  const auto fans_around = [&](Vertex_handle v, Vertex_handle u) {
    std::vector<std::vector<Cell_handle>> fans;
    Cell_handle c;
    int i, j;
    if(!tr.is_edge(v, u, c, i, j)) return fans;
    auto around = tr.incident_cells(typename Tr::Edge(c, i, j)), end = around;
    // Start after a cell outside the complex, so that no fan is cut in two.
    while(c3t3.is_in_complex(around) && ++around != end) {}
    end = around;
    bool in_fan = false;
    do {
      const bool in = c3t3.is_in_complex(around);
      if(in && !in_fan) fans.emplace_back();
      if(in) fans.back().push_back(around);
      in_fan = in;
    } while(++around != end);
    return fans;
  };
  const auto first = *c3t3.facets_in_complex_begin();
  const auto patch = c3t3.surface_patch_index(first.first, first.second);
  const auto subdomain = c3t3.subdomain_index(c3t3.cells_in_complex_begin());
  std::size_t changed = 0;
  int places = 0;
  // Passes over the boundary's vertices, each place repaired where it is found; a repair can make
  // a neighbouring vertex a boundary vertex, which the next pass sees.
  for(bool repaired = true; repaired && changed <= limit && places < 100;) {
    repaired = false;
    for(const Vertex_handle w : boundary_vertices_in_order(c3t3)) {
      if(changed > limit || places >= 100) break;
      const auto [v, u] = non_manifold_boundary_at(c3t3, w);
      if(v == Vertex_handle()) continue;
      ++places;
      bool in = true;
      auto groups = u != Vertex_handle() ? fans_around(v, u) : groups_at(v, true);
      if(groups.size() < 2 && u == Vertex_handle()) {
        in = false;
        groups = groups_at(v, false);
      }
      if(groups.size() < 2) continue;   // not a touching: left to the final check
      std::size_t largest = 0;
      std::vector<double> size(groups.size(), 0.);
      for(std::size_t g = 0; g < groups.size(); ++g) {
        for(Cell_handle c : groups[g]) size[g] += volume(c);
        if(size[g] > size[largest]) largest = g;
      }
      for(std::size_t g = 0; g < groups.size(); ++g) {
        // (Two sides of the outside at a vertex of the triangulation's hull: neither is filled.)
        if(g == largest || (!in && std::isinf(size[g]))) continue;
        for(Cell_handle c : groups[g]) {
          set_in_complex(c3t3, c, !in, subdomain, patch);
          ++changed;
        }
      }
      repaired = true;
    }
  }
  return changed;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_SEPARATE_TOUCHING_TETRAHEDRA_H
