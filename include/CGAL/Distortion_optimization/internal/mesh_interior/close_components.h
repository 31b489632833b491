// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A check of mesh_interior() before Mesh_3 runs: components of the surface closer than the facet
// distance, which Mesh_3 would not keep apart.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CLOSE_COMPONENTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CLOSE_COMPONENTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/checked_surface.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Two faces of different components of `surface` (numbered per face by `component`) closer than
// `distance` (the lowest pair of the closest), and how close they are; `distance` as the distance
// when there are none. Candidates
// are the pairs whose boxes, grown by `distance`, overlap (CGAL::box_self_intersection_d); two
// triangles that do not cross are as close as the closest of their vertex-triangle and edge-edge
// pairs.
template <class Surface>
std::tuple<std::size_t, std::size_t, double>
closest_components(const Surface& surface, const std::vector<std::size_t>& component, double distance)
{
  using K = typename Kernel_traits<typename Surface::Point>::Kernel;
  using Face = typename Surface::Face_index;
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<Box> boxes;
  for(Face f : faces(surface)) {
    const auto p = corners(surface, f);
    const Bbox_3 b = p[0].bbox() + p[1].bbox() + p[2].bbox();
    boxes.emplace_back(Bbox_3(b.xmin() - distance, b.ymin() - distance, b.zmin() - distance, b.xmax() + distance,
                              b.ymax() + distance, b.zmax() + distance), std::size_t(f));
  }
  std::tuple<std::size_t, std::size_t, double> closest(0, 0, distance);
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    if(component[a.info()] == component[b.info()]) return;
    const auto p = corners(surface, Face(a.info())), q = corners(surface, Face(b.info()));
    const typename K::Triangle_3 tp(p[0], p[1], p[2]), tq(q[0], q[1], q[2]);
    double d2 = std::numeric_limits<double>::infinity();
    for(int i = 0; i < 3; ++i) {
      d2 = (std::min)({d2, CGAL::to_double(CGAL::squared_distance(p[i], tq)), CGAL::to_double(CGAL::squared_distance(q[i], tp))});
      for(int j = 0; j < 3; ++j)
        d2 = (std::min)(d2, CGAL::to_double(CGAL::squared_distance(typename K::Segment_3(p[i], p[(i + 1) % 3]),
                                                                    typename K::Segment_3(q[j], q[(j + 1) % 3]))));
    }
    // The lowest pair among equally close ones: the error does not depend on the order of the calls.
    const std::tuple<std::size_t, std::size_t, double> pair((std::min)(a.info(), b.info()), (std::max)(a.info(), b.info()), std::sqrt(d2));
    if(std::get<2>(pair) < std::get<2>(closest) ||
       (std::get<2>(pair) == std::get<2>(closest) && std::get<2>(pair) < distance && pair < closest))
      closest = pair;
  });
  return closest;
}

// Components closer than the facet distance: Mesh_3's boundary, within that distance of the
// surface, need not keep them apart (and its edge protection may grow without end). Throws,
// naming a face of each.
template <class CheckedSurface>
void check_components_apart(const CheckedSurface& checked, double facet_distance)
{
  if(checked.component_volume.size() > 1) {
    const double scaled = checked.scale * facet_distance;   // in the units of the copy
    const auto [f, g, d] = closest_components(checked.surface, checked.component, scaled);
    if(d < scaled) {
      char text[200];
      std::snprintf(text, sizeof text, " are %.3g apart, less than the facet distance (%.3g)", d / checked.scale, facet_distance);
      throw Invalid_input("mesh_interior: faces " + std::to_string(checked.face_names[f]) + " and " +
                          std::to_string(checked.face_names[g]) + " of two components of the surface" + text +
                          ": Mesh_3 would not keep them apart; give sizes below their distance (facet distance, "
                          "facet size, cell size), or move them apart");
    }
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CLOSE_COMPONENTS_H
