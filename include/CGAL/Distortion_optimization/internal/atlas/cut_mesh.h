// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A piece cut open along its seams: the chart mesh the flattening works on.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CUT_MESH_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CUT_MESH_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>

#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// `piece` cut along the edges flagged in `seam`: each vertex becomes one vertex per wedge (the run
// of its faces between two seam or border edges, going around it; one wedge if no seam or border
// meets it), at the same point. `corner[f][i]` receives the cut mesh's vertex at the i-th corner
// of the piece's face f (the corners in the order of vertices_around_face from its halfedge), and
// the cut mesh has the piece's faces in their order.
template <class Mesh>
Mesh cut_along(const Mesh& piece, const std::vector<bool>& seam, std::vector<std::array<std::uint32_t, 3>>& corner)
{
  using Halfedge = typename Mesh::Halfedge_index;
  Mesh cut;
  std::vector<std::uint32_t> wedge(piece.number_of_halfedges(), 0);   // by the halfedge whose target is the corner
  const auto cuts = [&](Halfedge h) { return seam[std::size_t(piece.edge(h))] || piece.is_border(piece.edge(h)); };
  for(auto v : piece.vertices()) {
    if(piece.halfedge(v) == Mesh::null_halfedge()) continue;
    // Go around v (h, then opposite(next(h)): into the face across the edge of the next h), from a
    // cut if there is one; each crossing of a cut into a face starts a wedge.
    Halfedge start = piece.halfedge(v);
    for(auto h : CGAL::halfedges_around_target(piece.halfedge(v), piece))
      if(cuts(h)) { start = h; break; }
    std::uint32_t current = 0;
    bool new_wedge = true;
    for(auto h : CGAL::halfedges_around_target(start, piece)) {
      new_wedge = new_wedge || cuts(h);
      if(piece.is_border(h)) continue;
      if(new_wedge) current = std::uint32_t(cut.add_vertex(piece.point(v)));
      new_wedge = false;
      wedge[std::size_t(h)] = current;
    }
  }
  corner.assign(piece.number_of_faces(), {0, 0, 0});
  for(auto f : piece.faces()) {
    std::array<typename Mesh::Vertex_index, 3> t;
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(piece.halfedge(f), piece)) {
      corner[std::size_t(f)][i] = wedge[std::size_t(h)];
      t[i++] = typename Mesh::Vertex_index(wedge[std::size_t(h)]);
    }
    if(cut.add_face(t[0], t[1], t[2]) == Mesh::null_face()) throw Invalid_input("cutting a piece open failed");
  }
  return cut;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CUT_MESH_H
