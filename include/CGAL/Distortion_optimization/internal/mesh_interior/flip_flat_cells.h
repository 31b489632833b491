// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A repair of mesh_interior()'s complex: cells flat to rounding inside it are flipped away.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_FLIP_FLAT_CELLS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_FLIP_FLAT_CELLS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/mesh_interior/complex_boundary.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Mesh_3 can leave cells flat to rounding inside the complex where four of its points are coplanar
// and cospherical (the square sections of a thin bar: all four vertices on the surface, which
// exudation does not move). No map of such a cell has a Jacobian.
// Each is flipped away among cells of the complex: an edge of it with three cells around goes by a
// 3-2 flip; one with four, by a 2-3 flip of a facet around it that is not the flat cell's, then the
// 3-2 flip. The triangulation stays valid, its cells positive (CGAL's flips test that), but is no
// longer the regular one. Boundary facets keep their surface patches. Returns the number of flat
// cells that remain (those whose edges all have more cells around).
template <class C3T3>
std::size_t flip_flat_cells(C3T3& c3t3)
{
  using Tr = typename C3T3::Triangulation;
  using Cell_handle = typename Tr::Cell_handle;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Triple = std::array<Vertex_handle, 3>;
  Tr& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  const auto is_flat = [&](Cell_handle c) {
    double longest = 0;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        longest = (std::max)(longest, CGAL::to_double(CGAL::squared_distance(point(tr.point(c, i)), point(tr.point(c, j)))));
    return std::abs(cell_volume(c3t3, c)) <= 1e-12 * longest * std::sqrt(longest);
  };
  const auto triple = [](Cell_handle c, int i) {
    Triple t{c->vertex((i + 1) % 4), c->vertex((i + 2) % 4), c->vertex((i + 3) % 4)};
    std::sort(t.begin(), t.end());
    return t;
  };
  const auto around = [&](Cell_handle c, int i, int j) {
    std::vector<Cell_handle> cells;
    auto cell = tr.incident_cells(typename Tr::Edge(c, i, j)), end = cell;
    do cells.push_back(cell); while(++cell != end);
    return cells;
  };
  // Takes `cells` out of the complex, remembering their boundary facets' patches; `flip` runs the
  // flip and returns the cells it made (none if it failed), which join the complex.
  const auto replace = [&](const std::vector<Cell_handle>& cells, const auto& flip) {
    const auto subdomain = c3t3.subdomain_index(cells.front());
    std::map<Triple, typename C3T3::Surface_patch_index> patch;
    for(Cell_handle c : cells) {
      if(tr.is_infinite(c) || !c3t3.is_in_complex(c) || c3t3.subdomain_index(c) != subdomain) return false;
      for(int i = 0; i < 4; ++i)
        if(c3t3.is_in_complex(c, i)) patch[triple(c, i)] = c3t3.surface_patch_index(c, i);
    }
    for(Cell_handle c : cells) {
      for(int i = 0; i < 4; ++i)
        if(c3t3.is_in_complex(c, i)) c3t3.remove_from_complex(c, i);
      c3t3.remove_from_complex(c);
    }
    std::vector<Cell_handle> made = flip();
    const bool flipped = !made.empty();
    if(!flipped) made = cells;
    for(Cell_handle c : made) c3t3.add_to_complex(c, subdomain);
    for(Cell_handle c : made)
      for(int i = 0; i < 4; ++i)
        if(const auto p = patch.find(triple(c, i)); p != patch.end()) c3t3.add_to_complex(c, i, p->second);
    return flipped;
  };
  // The 3-2 flip of the edge (c, i, j): the two new cells share the facet of its ring.
  const auto flip_edge = [&](Cell_handle c, int i, int j) {
    const std::vector<Cell_handle> cells = around(c, i, j);
    if(cells.size() != 3) return false;
    const Vertex_handle a = c->vertex(i), b = c->vertex(j);
    std::vector<Vertex_handle> ring;
    for(Cell_handle x : cells)
      for(int k = 0; k < 4; ++k)
        if(x->vertex(k) != a && x->vertex(k) != b && std::find(ring.begin(), ring.end(), x->vertex(k)) == ring.end())
          ring.push_back(x->vertex(k));
    return replace(cells, [&] {
      if(!tr.flip(c, i, j)) return std::vector<Cell_handle>();
      Cell_handle n;
      int u, v, w;
      tr.is_facet(ring[0], ring[1], ring[2], n, u, v, w);
      return std::vector<Cell_handle>{n, n->neighbor(6 - u - v - w)};
    });
  };
  // The 2-3 flip of facet k of cell x: the three new cells share the edge between the apexes.
  const auto flip_facet = [&](Cell_handle x, int k) {
    const Cell_handle y = x->neighbor(k);
    const Vertex_handle s = x->vertex(k), t = y->vertex(y->index(x));
    return replace({x, y}, [&] {
      if(!tr.flip(x, k)) return std::vector<Cell_handle>();
      Cell_handle n;
      int u, v;
      tr.is_edge(s, t, n, u, v);
      return around(n, u, v);
    });
  };

  // Flips c away; false where none of the flips above applies.
  const auto flip_away = [&](Cell_handle c) {
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(flip_edge(c, i, j)) return true;   // (false, untouched, unless three cells are around)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const Vertex_handle a = c->vertex(i), b = c->vertex(j);
        const std::vector<Cell_handle> cells = around(c, i, j);
        if(cells.size() != 4) continue;
        for(Cell_handle x : cells)
          for(int k = 0; k < 4; ++k)
            if(x != c && x->vertex(k) != a && x->vertex(k) != b && x->neighbor(k) != c &&
               std::count(cells.begin(), cells.end(), x->neighbor(k)) > 0 && flip_facet(x, k)) {
              Cell_handle e;
              int u, v;
              return tr.is_edge(a, b, e, u, v) && flip_edge(e, u, v);
            }
      }
    return false;
  };
  // A flip may take other flat cells with it, or make some: the cells flat at the start of a sweep
  // are flipped in turn where they still are (found by their vertices), then looked for again.
  // (Flips that keep making flat cells elsewhere are not followed beyond 100 sweeps.)
  using Quadruple = std::array<Vertex_handle, 4>;
  std::set<Quadruple> kept;
  for(int sweep = 0;; ++sweep) {
    std::vector<Quadruple> flat;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
      if(is_flat(c)) {
        Quadruple q{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
        std::sort(q.begin(), q.end());
        flat.push_back(q);
      }
    if(sweep == 100) return flat.size();
    bool flipped = false;
    for(const Quadruple& q : flat) {
      Cell_handle c;
      int i, j, k, l;
      if(kept.count(q) > 0 || !tr.is_cell(q[0], q[1], q[2], q[3], c, i, j, k, l) || !c3t3.is_in_complex(c) || !is_flat(c))
        continue;
      if(flip_away(c)) flipped = true;
      else kept.insert(q);
    }
    if(!flipped) return flat.size();
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_FLIP_FLAT_CELLS_H
