// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// c3t3_from_tetrahedra()'s checks on a manifold complex: no two tetrahedra fold over a facet, no parts overlap.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_CELL_CHECKS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_CELL_CHECKS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/internal/c3t3_from_tetrahedra/manifold_tetrahedra.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Positively oriented tetrahedra sharing a facet must lie on its two sides; two on the same side
// overlap (a folded mesh, or one whose cells' orientations disagree). Replacing the vertex of t
// off the facet by that of its neighbour t' gives t' in another order, which must be an odd
// permutation of it (negative): a parity count, exact without any predicate.
inline void check_cells_do_not_fold(const std::vector<std::array<std::size_t, 4>>& cells,
                                    const std::vector<std::uint32_t>& across, const Workers& workers = Workers())
{
  constexpr std::size_t block = 8192;
  std::vector<First_failure> failures((cells.size() + block - 1) / block);
  workers.for_each_block(cells.size(), block, [&](std::size_t begin, std::size_t size) {
    for(std::size_t t = begin; t < begin + size; ++t)
      for(int j = 0; j < 4; ++j) {
        const std::uint32_t other = across[4 * t + j];
        if(other == no_tetrahedron || other / 4 < t) continue;
        std::array<std::size_t, 4> swapped = cells[t];
        swapped[j] = cells[other / 4][other % 4];
        int position[4], inversions = 0;
        for(int i = 0; i < 4; ++i)
          position[i] = int(std::find(cells[other / 4].begin(), cells[other / 4].end(), swapped[i]) - cells[other / 4].begin());
        for(int a = 0; a < 4; ++a)
          for(int b = a + 1; b < 4; ++b) inversions += position[a] > position[b];
        if(inversions % 2 == 0) {
          failures[begin / block] = {t, "tetrahedra " + std::to_string(t) + " and " + std::to_string(other / 4) +
                                            " lie on the same side of their common facet: they overlap (a folded mesh)"};
          return;
        }
      }
  });
  First_failure::throw_lowest(failures);
}

// Positively oriented tetrahedra that form a manifold complex and do not fold may still overlap:
// separate parts one across or inside another, or a part whose boundary passes through itself.
// Such a map is not injective, which its boundary tells (Aigerman and Lipman 2013): the boundary
// guard's exact test, with the nesting of the parts.
inline void check_cells_do_not_overlap(const std::vector<std::array<double, 3>>& points,
                                       const std::vector<std::array<std::size_t, 4>>& cells)
{
  using Guard = Boundary_guard<3>;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra(cells.size());
  for(std::size_t t = 0; t < cells.size(); ++t)
    for(int i = 0; i < 4; ++i) tetrahedra[t][i] = static_cast<std::uint32_t>(cells[t][i]);
  std::vector<Vector<3>> x(points.size());
  for(std::size_t v = 0; v < points.size(); ++v) x[v] = Vector<3>(points[v][0], points[v][1], points[v][2]);
  bool nested = false;
  if(!Guard(Guard::boundary_faces(tetrahedra), x.size(), connected_pieces(tetrahedra, x.size())).is_injective(x, nullptr, 0, &nested))
    throw Invalid_input(nested ? "the tetrahedra overlap: a part of the mesh lies inside another (separate parts must be apart)"
                               : "the tetrahedra overlap: their boundary passes through itself (separate parts must be apart)");
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_CELL_CHECKS_H
