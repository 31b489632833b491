// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The components of the surface that Mesh_3's initial points missed, found after the refinement,
// and the seeds that make the refinement mesh them.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MISSED_COMPONENTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MISSED_COMPONENTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/checked_surface.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Mesh_3 finds the surface from its initial points, the hits of rays cast from the centre of the
// bounding box, or, where sharp edges are protected, only from the protecting balls; it then refines
// around the facets they make. A component of the surface that none of them reaches (a small sphere
// beside a large one or beside a cube, an island in a hollow ball) gets no facet and no tetrahedron.
// Returns, for each component of `surface` (the domain's; `component` numbers them per face) that
// bounds no tetrahedron of `c3t3` (no boundary facet of it has a cell of the complex on a side),
// points of it with their indices in `domain`: where short segments across its faces that lie
// outermost along +-x, +-y, +-z and +-(1, 1, 1) meet the surface; `missed` gets the index of one
// face of each such component.
template <class C3T3, class Domain, class Surface>
std::vector<std::pair<typename Domain::Point_3, typename Domain::Index>>
seeds_of_missed_components(const C3T3& c3t3, const Domain& domain, const Surface& surface,
                           const std::vector<std::size_t>& component, std::vector<std::size_t>& missed)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point_3 = typename Domain::Point_3;
  using K = typename Kernel_traits<Point_3>::Kernel;
  using Vector_3 = typename K::Vector_3;
  using Face = typename boost::graph_traits<Surface>::face_descriptor;
  std::vector<std::pair<Point_3, typename Domain::Index>> seeds;
  missed.clear();
  const std::size_t count = component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  if(count < 2) return seeds;

  // A facet of the complex lies on the component of the face nearest to its first vertex. A facet
  // with no cell of the complex on either side bounds nothing (the two sides of a flat component).
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Surface>>>;
  const Tree tree(faces(surface).first, faces(surface).second, surface);
  std::vector<bool> meshed(count, false);
  const auto point = c3t3.triangulation().geom_traits().construct_point_3_object();
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    if(c3t3.is_in_complex(f->first) || c3t3.is_in_complex(f->first->neighbor(f->second)))
      meshed[component[tree.closest_point_and_primitive(point(f->first->vertex((f->second + 1) % 4)->point())).second]] = true;

  const Vector_3 directions[8] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}, {-1, -1, -1}};
  std::vector<std::array<Face, 8>> outermost(count);
  std::vector<std::array<double, 8>> extent(count);
  for(auto& e : extent) e.fill(-std::numeric_limits<double>::infinity());
  const auto centroid = [&](Face f) {
    const auto p = corners(surface, f);
    return CGAL::centroid(p[0], p[1], p[2]);
  };
  for(Face f : faces(surface)) {
    const std::size_t c = component[f];
    if(meshed[c]) continue;
    if(extent[c][0] == -std::numeric_limits<double>::infinity()) missed.push_back(std::size_t(f));   // its first face
    const Vector_3 m = centroid(f) - CGAL::ORIGIN;
    for(int d = 0; d < 8; ++d) {
      const double along = CGAL::to_double(m * directions[d]);
      if(along > extent[c][d]) { extent[c][d] = along; outermost[c][d] = f; }
    }
  }
  const auto intersection = domain.construct_intersection_object();
  for(std::size_t c = 0; c < count; ++c) {
    if(meshed[c]) continue;
    for(int d = 0; d < 8; ++d) {
      const Face f = outermost[c][d];
      if(d > 0 && std::find(outermost[c].begin(), outermost[c].begin() + d, f) != outermost[c].begin() + d) continue;
      // Across the face at its centroid, a hundredth of its size to each side.
      const Vector_3 across = 0.01 * std::sqrt(CGAL::to_double(PMP::face_area(f, surface))) * PMP::compute_face_normal(f, surface);
      const Point_3 middle = centroid(f);
      const auto hit = intersection(typename K::Segment_3(middle - across, middle + across));
      if(std::get<2>(hit) != 0) seeds.emplace_back(std::get<0>(hit), std::get<1>(hit));
    }
  }
  return seeds;
}

// Inserts `seeds` (from seeds_of_missed_components()) into the triangulation as surface vertices,
// after taking every cell and facet out of the complex: refine_mesh_3() with no_reset_c3t3() then
// classifies the whole triangulation again, as after a load, and refines around the seeds.
template <class C3T3, class Seeds>
void insert_seeds(C3T3& c3t3, const Seeds& seeds)
{
  c3t3.clear_cells_and_facets_from_c3t3();
  auto& tr = c3t3.triangulation();
  const auto weighted = tr.geom_traits().construct_weighted_point_3_object();
  for(const auto& [p, index] : seeds) {
    const auto v = tr.insert(weighted(p));
    if(v != typename C3T3::Triangulation::Vertex_handle()) {   // null when a protecting ball hides p
      c3t3.set_dimension(v, 2);
      c3t3.set_index(v, index);
    }
  }
}

// Throws if the seeds did not help: names a face (by `face_names`, the input's indices) of the
// first component still `missed`.
inline void check_no_missed_component(const std::vector<std::size_t>& missed, const std::vector<std::size_t>& face_names)
{
  if(!missed.empty())
    throw Invalid_input("mesh_interior: Mesh_3 left the component of the surface with face " +
                        std::to_string(face_names[missed.front()]) +
                        " without tetrahedra (is it much smaller than the sizes?); give smaller sizes");
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MISSED_COMPONENTS_H
