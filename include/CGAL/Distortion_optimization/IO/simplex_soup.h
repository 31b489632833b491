// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What the package's readers return and its writers take: a mesh as it appears in a file.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_SIMPLEX_SOUP_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_SIMPLEX_SOUP_H

#include <CGAL/license/Distortion_optimization.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// Vertices and cells of `k` vertices each (0-based indices) as they appear in a file, with a
/// label per cell where the format has one (Medit's reference of a tetrahedron, where CGAL writes
/// the subdomain index), else no label.
/// For Medit files, also the vertices' references and the Triangles section (0-based, with its
/// references: CGAL writes the surface patch indices there), carried through to the output of a
/// map of the same vertices; empty otherwise.
/// For OBJ files, also the texture coordinates ("vt u v") and, when the faces refer to them
/// ("f a/ta b/tb c/tc"), each cell's texture indices (0-based; `std::size_t(-1)` for a face vertex
/// without one); both empty otherwise.
template <std::size_t k>
struct Simplex_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, k>> cells;
  std::vector<int> labels;
  std::vector<int> point_labels;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<int> triangle_labels;
  std::vector<std::array<double, 2>> texture_coordinates;
  std::vector<std::array<std::size_t, k>> cell_texture_indices;
};

/// \ingroup PkgDistortionOptimizationIO
/// A triangle mesh as read from an OFF or OBJ file (no labels).
using Triangle_soup = Simplex_soup<3>;
/// \ingroup PkgDistortionOptimizationIO
/// A tetrahedral mesh as read from a Medit file (a label per tetrahedron).
using Tetrahedron_soup = Simplex_soup<4>;

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_SIMPLEX_SOUP_H
