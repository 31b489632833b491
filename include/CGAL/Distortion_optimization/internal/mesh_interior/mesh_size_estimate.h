// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// mesh_interior()'s defaults and its estimate of the mesh that sizes ask for: what its checks
// before Mesh_3 (the vertex budget, the advice for thin parts) compare with what memory holds.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MESH_SIZE_ESTIMATE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MESH_SIZE_ESTIMATE_H

#include <CGAL/license/Distortion_optimization.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The defaults of mesh_interior(), measured on real surfaces (see mesh_interior()).
struct Interior_mesh_defaults
{
  static constexpr double cells = 3e4;              // the target number of tetrahedra
  static constexpr double volume_per_cell = 0.2;     // tetrahedron volume / cell_size^3 observed
  static constexpr double area_per_facet = 0.3;      // boundary facet area / facet_size^2 observed
  static constexpr double cells_per_vertex = 5.5;    // in a Delaunay tetrahedral mesh
  static constexpr double boundary_facets = 8e3;     // at most this many boundary facets by default
  static constexpr double distance_ratio = 0.1;      // facet_distance / facet_size
  static constexpr double facet_angle = 25;
  static constexpr double radius_edge_ratio = 3;
  static constexpr double sharp_edge_angle = 60;
  // Without exude_slivers, Mesh_3's exudation still runs on the cells with a dihedral angle below
  // this (degrees): that costs little and removes the flattest cells (see mesh_interior()).
  static constexpr double sliver_bound = 2;
  // Without maximum_number_of_vertices, sizes that ask for more vertices are refused: Mesh_3 and
  // the maps of the package take a few kilobytes a vertex (see mesh_interior()).
  static constexpr double affordable_vertices = 2e6;
};

// About as many vertices as Mesh_3 makes for a part of volume `volume` and boundary area `area`:
// the interior's from the cell size, the boundary's from the facet size.
inline double asked_vertices(double volume, double area, double cell_size, double facet_size)
{
  using D = Interior_mesh_defaults;
  return volume / (D::volume_per_cell * std::pow(cell_size, 3)) / D::cells_per_vertex +
         area / (D::area_per_facet * facet_size * facet_size) / 2;
}

// The most vertices the sizes may ask for: the given maximum (none where it is 0), else
// Interior_mesh_defaults::affordable_vertices.
inline double affordable_vertices(bool maximum_given, std::size_t maximum_vertices)
{
  if(!maximum_given) return Interior_mesh_defaults::affordable_vertices;
  return maximum_vertices > 0 ? double(maximum_vertices) : 1e300;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MESH_SIZE_ESTIMATE_H
