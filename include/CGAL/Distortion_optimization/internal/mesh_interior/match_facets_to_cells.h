// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The first repair of mesh_interior()'s complex: its facets become exactly the boundary of its
// cells, which the other repairs and the maps of the package read.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MATCH_FACETS_TO_CELLS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MATCH_FACETS_TO_CELLS_H

#include <CGAL/license/Distortion_optimization.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Makes the facets of the complex the boundary of its cells: Mesh_3's facets are those whose dual
// Voronoi edge crosses the surface, and its cells those whose circumcentre is inside, which
// disagree in a few places (edges of its facets with four facets or more). A facet added takes the
// surface patch index of a facet of the complex that shares a cell with it, or else the first
// facet's. Returns the number of facets added or removed.
template <class C3T3>
std::size_t match_facets_to_cells(C3T3& c3t3)
{
  using Facet = typename C3T3::Triangulation::Facet;
  if(c3t3.number_of_facets_in_complex() == 0) return 0;
  const auto first = *c3t3.facets_in_complex_begin();
  const auto default_patch = c3t3.surface_patch_index(first.first, first.second);
  std::vector<Facet> extra, missing;
  for(auto f = c3t3.triangulation().finite_facets_begin(); f != c3t3.triangulation().finite_facets_end(); ++f) {
    const bool boundary = c3t3.is_in_complex(f->first) != c3t3.is_in_complex(f->first->neighbor(f->second));
    if(boundary != c3t3.is_in_complex(*f)) (boundary ? missing : extra).push_back(*f);
  }
  for(const Facet& f : extra) c3t3.remove_from_complex(f);
  for(const Facet& f : missing) {
    auto patch = default_patch;
    for(const auto c : {f.first, f.first->neighbor(f.second)})
      for(int i = 0; i < 4; ++i)
        if(c3t3.is_in_complex(c, i)) patch = c3t3.surface_patch_index(c, i);
    c3t3.add_to_complex(f, patch);
  }
  return extra.size() + missing.size();
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MATCH_FACETS_TO_CELLS_H
