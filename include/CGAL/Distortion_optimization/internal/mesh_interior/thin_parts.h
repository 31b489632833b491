// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A check of mesh_interior() before Mesh_3 runs: a volume, or a component of it, too thin for the
// sizes, whose boundary Mesh_3 would not recover.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/checked_surface.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// A domain thinner (mean thickness 2 V / A) than the facet distance passes Mesh_3's surface
// criteria with facets joining its two sides: the boundary is not recovered (the tetrahedra touch,
// or the refinement runs to the vertex limit), or only after a long refinement. So does a
// `slab` (see is_slab()) thinner than half the facet size: its sides are flat, and the facet
// distance, which bounds the facets of a curved surface, does not refine them. Throws if the part
// of volume `volume` and area `area`, named `what` in the message, is that thin; `lost` says what
// Mesh_3 would not recover and `remedy` ends the message.
inline void check_thickness(double volume, double area, bool slab, double facet_size, double facet_distance,
                            const std::string& what, const std::string& lost, const std::string& remedy)
{
  const double thickness = 2 * volume / area;
  if((!slab || thickness >= facet_size / 2) && thickness >= facet_distance) return;
  char text[240];
  if(slab && thickness < facet_size / 2)
    std::snprintf(text, sizeof text, " is thinner (2 volume / area = %.3g) than half the facet size (%.3g): Mesh_3 would not "
                  "recover %s; give a facet size below %.3g", thickness, facet_size / 2, lost.c_str(), 2 * thickness);
  else
    std::snprintf(text, sizeof text, " is thinner (2 volume / area = %.3g) than the facet distance (%.3g): Mesh_3 would not "
                  "recover %s; give a facet distance below %.3g", thickness, facet_distance, lost.c_str(), thickness);
  throw Invalid_input("mesh_interior: " + what + text + remedy);
}

// The whole volume, then each component (a cavity measured by the space it encloses): a thin
// component beside thick ones holds up Mesh_3's protection or refinement just as well, or gets no
// tetrahedron at all.
// Whether the surface spreads far less in one direction than in the others (a plate, a disc; not
// a needle): the smallest eigenvalue of the area-weighted second moments of its faces' centroids
// under a hundredth of the middle one. `moments` holds the area, the first moments and the second
// (xx, yy, zz, xy, xz, yz), summed over its faces.
inline bool is_slab(const std::array<double, 10>& moments)
{
  const double a = moments[0];
  Eigen::Matrix3d m;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      const int second = i == j ? 4 + i : 7 + i + j - 1;   // xy: 7, xz: 8, yz: 9
      m(i, j) = moments[second] / a - moments[1 + i] / a * moments[1 + j] / a;
    }
  const Eigen::Vector3d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues();
  return spread[0] < 1e-2 * spread[1];
}

template <class CheckedSurface>
void check_thickness_of_parts(const CheckedSurface& checked, double facet_size, double facet_distance)
{
  const std::size_t components = checked.component_volume.size();
  std::vector<std::array<double, 10>> moments(components + 1, std::array<double, 10>{});   // the last: all
  std::size_t f = 0;
  for(auto face : faces(checked.surface)) {
    const auto p = corners(checked.surface, face);
    const double w = std::sqrt(CGAL::to_double(CGAL::squared_area(p[0], p[1], p[2])));
    const double x[3] = {CGAL::to_double(p[0].x() + p[1].x() + p[2].x()) / 3, CGAL::to_double(p[0].y() + p[1].y() + p[2].y()) / 3,
                         CGAL::to_double(p[0].z() + p[1].z() + p[2].z()) / 3};
    for(const std::size_t c : {checked.component[f++], components}) {
      std::array<double, 10>& m = moments[c];
      const double terms[10] = {1, x[0], x[1], x[2], x[0] * x[0], x[1] * x[1], x[2] * x[2], x[0] * x[1], x[0] * x[2], x[1] * x[2]};
      for(int k = 0; k < 10; ++k) m[k] += w * terms[k];
    }
  }
  check_thickness(checked.volume, checked.area, is_slab(moments[components]), facet_size, facet_distance, "the volume",
                  "its boundary", "");
  std::vector<std::size_t> first_face(components, 0);   // of each component, to name it
  for(std::size_t g = checked.component.size(); g-- > 0;) first_face[checked.component[g]] = g;
  for(std::size_t c = 0; c < components && components > 1; ++c)
    check_thickness(std::abs(checked.component_volume[c]), checked.component_area[c], is_slab(moments[c]), facet_size,
                    facet_distance,
                    "the component of the surface with face " + std::to_string(checked.face_names[first_face[c]]), "it",
                    ", or remove it");
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H
