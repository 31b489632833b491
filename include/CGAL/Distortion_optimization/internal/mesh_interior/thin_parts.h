// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A check of mesh_interior() before Mesh_3 runs: a volume, or a component of it, too thin for the
// sizes, whose boundary Mesh_3 would not recover.

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

// A domain thinner (mean thickness 2 V / A) than the facet distance passes Mesh_3's surface
// criteria with facets joining its two sides: the boundary is not recovered (the tetrahedra touch,
// or the refinement runs to the vertex limit), or only after minutes of refinement. So does a slab
// (thinner than a tenth of its size, the cube root of its volume) thinner than half the facet
// size: its sides are flat, and the facet distance, which bounds the facets of a curved surface,
// does not refine them. Throws if the part of volume `volume` and area `area`, named `what` in the
// message, is that thin; `lost` says what Mesh_3 would not recover and `remedy` ends the message.
inline void check_thickness(double volume, double area, double facet_size, double facet_distance, const std::string& what,
                            const std::string& lost, const std::string& remedy)
{
  const double thickness = 2 * volume / area;
  const bool slab = thickness < 0.1 * std::cbrt(volume);
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
template <class CheckedSurface>
void check_thickness_of_parts(const CheckedSurface& checked, double facet_size, double facet_distance)
{
  check_thickness(checked.volume, checked.area, facet_size, facet_distance, "the volume", "its boundary", "");
  const std::size_t components = checked.component_volume.size();
  std::vector<std::size_t> first_face(components, 0);   // of each component, to name it
  for(std::size_t f = checked.component.size(); f-- > 0;) first_face[checked.component[f]] = f;
  for(std::size_t c = 0; c < components && components > 1; ++c)
    check_thickness(std::abs(checked.component_volume[c]), checked.component_area[c], facet_size, facet_distance,
                    "the component of the surface with face " + std::to_string(checked.face_names[first_face[c]]), "it",
                    ", or remove it");
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H
