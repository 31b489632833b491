// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A check of mesh_interior() before Mesh_3 runs: a volume, or a component of it, thinner than the
// facet distance, whose boundary Mesh_3 would not recover.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// A domain thinner than the facet distance (its mean thickness 2 V / A, the thickness of a slab)
// passes Mesh_3's surface criteria with facets joining its two sides: the boundary is not
// recovered, and the protection of its rim's edges does not end. Throws if the part of volume
// `volume` and area `area`, named `what` in the message, is that thin; `lost` says what Mesh_3
// would not recover and `remedy` ends the message.
inline void check_thickness(double volume, double area, double facet_distance, const std::string& what,
                            const std::string& lost, const std::string& remedy)
{
  const double thickness = 2 * volume / area;
  if(thickness >= facet_distance) return;
  char text[200];
  std::snprintf(text, sizeof text, " is thinner (2 volume / area = %.3g) than the facet distance (%.3g)", thickness,
                facet_distance);
  throw Invalid_input("mesh_interior: " + what + text + ": Mesh_3 would not recover " + lost +
                      "; give sizes below its thickness (facet distance, facet size, cell size)" + remedy);
}

// The whole volume, then each component (a cavity measured by the space it encloses): a thin
// component beside thick ones holds up Mesh_3's protection or refinement just as well, or gets no
// tetrahedron at all.
template <class CheckedSurface>
void check_thickness_of_parts(const CheckedSurface& checked, double facet_distance)
{
  check_thickness(checked.volume, checked.area, facet_distance, "the volume", "its boundary", "");
  const std::size_t components = checked.component_volume.size();
  std::vector<std::size_t> first_face(components, 0);   // of each component, to name it
  for(std::size_t f = checked.component.size(); f-- > 0;) first_face[checked.component[f]] = f;
  for(std::size_t c = 0; c < components && components > 1; ++c)
    check_thickness(std::abs(checked.component_volume[c]), checked.component_area[c], facet_distance,
                    "the component of the surface with face " + std::to_string(checked.face_names[first_face[c]]), "it",
                    ", or remove it");
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H
