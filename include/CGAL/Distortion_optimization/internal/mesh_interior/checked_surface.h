// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Step 1 of mesh_interior(): the checks of the input surface (never modified) and the canonical,
// oriented copy, scaled to unit size, that Mesh_3's domain holds.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CHECKED_SURFACE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CHECKED_SURFACE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/number_types.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// A checked copy of the input surface for the domain, oriented to bound its volume, moved by
// -offset (exactly, where the surface is far from the origin for its size; else 0) and scaled by
// `scale`, the power of two that brings its largest extent into [1, 2). The copy is
// rebuilt from a canonical soup (points and triangles in the input's order, each triangle starting
// at its smallest vertex), so that it, and the mesh, depend only on the geometry and that order:
// not on the input's orientation or on which halfedge each face stores. `SurfaceMesh` is the
// domain's surface type, `Interior_mesh<GeomTraits>::Surface`.
template <class SurfaceMesh, class TriangleMesh>
struct Checked_surface
{
  using Surface = SurfaceMesh;
  using Point_3 = typename Surface::Point;
  using Triangle = std::array<std::size_t, 3>;

  Surface surface;   // the input moved by -offset, then scaled by `scale`
  std::vector<std::size_t> face_names;   // the input's index of each face of `surface`
  std::vector<std::size_t> vertex_names; // the input's index of each vertex of `surface`
  std::vector<std::size_t> component;    // the connected component of each face of `surface`
  std::vector<double> component_volume, component_area;   // unscaled; a cavity's volume is negative
  double scale = 1;
  std::array<double, 3> offset = {0, 0, 0};
  double volume = 0; // of the input, unscaled
  double area = 0;   // of the input, unscaled

  template <class NamedParameters>
  Checked_surface(const TriangleMesh& tm, const NamedParameters& np)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, tm));
    // Elements are named by their indices (for a Surface_mesh, v.idx() and f.idx()).
    const auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np);
    const auto face_index = CGAL::get_initialized_face_index_map(tm, np);
    auto vertex_name = [&](auto v) { return "vertex " + std::to_string(std::size_t(get(vertex_index, v))); };
    auto face_name = [&](auto f) { return std::to_string(std::size_t(get(face_index, f))); };

    if(faces(tm).begin() == faces(tm).end())
      throw Invalid_input("mesh_interior: the surface is empty (it has no face)");
    for(auto f : faces(tm)) {
      const std::size_t degree = halfedges_around_face(halfedge(f, tm), tm).size();
      if(degree != 3)
        throw Invalid_input("mesh_interior: the surface is not a triangle mesh: face " + face_name(f) + " has " +
                            std::to_string(degree) + " vertices");
    }
    // The soup numbers vertices in iteration order: index maps may have gaps (a Surface_mesh with
    // removed elements), `compact` closes them.
    std::vector<Point_3> points;
    std::vector<std::size_t> compact;
    for(auto v : vertices(tm)) {
      const auto& p = get(vpm, v);
      const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
      if(const std::string problem = coordinate_problem(x, y, z); !problem.empty())
        throw Invalid_input("mesh_interior: " + vertex_name(v) + " has " + problem);
      const std::size_t i = get(vertex_index, v);
      if(compact.size() <= i) compact.resize(i + 1);
      compact[i] = points.size();
      points.emplace_back(x, y, z);
      vertex_names.push_back(i);
    }
    for(auto h : halfedges(tm))
      if(is_border(h, tm))
        throw Invalid_input("mesh_interior: the surface is not closed: the edge from " + vertex_name(source(h, tm)) +
                            " to " + vertex_name(target(h, tm)) + " is on a border");
    // One halfedge per umbrella of each non-manifold vertex.
    std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> umbrellas;
    PMP::non_manifold_vertices(tm, std::back_inserter(umbrellas));
    if(!umbrellas.empty())
      throw Invalid_input("mesh_interior: the surface is not 2-manifold: the faces around " +
                          vertex_name(target(umbrellas.front(), tm)) + " do not form a single disk");
    // The first pair found is enough to name (a degenerate face comes as the pair (f, f)).
    using Input_face = typename boost::graph_traits<TriangleMesh>::face_descriptor;
    std::vector<std::pair<Input_face, Input_face>> crossing;
    PMP::self_intersections(tm, std::back_inserter(crossing),
                            CGAL::parameters::vertex_point_map(vpm).maximum_number(1));
    if(!crossing.empty()) {
      const auto& [f, g] = crossing.front();
      if(f == g)
        throw Invalid_input("mesh_interior: face " + face_name(f) + " of the surface is degenerate (flat)");
      throw Invalid_input("mesh_interior: the surface intersects itself: faces " + face_name(f) + " and " +
                          face_name(g) + " cross");
    }

    std::vector<Triangle> triangles;
    for(auto f : faces(tm)) {
      Triangle t;
      std::size_t k = 0;
      for(auto h : halfedges_around_face(halfedge(f, tm), tm)) t[k++] = compact[get(vertex_index, target(h, tm))];
      triangles.push_back(t);
      face_names.push_back(get(face_index, f));
    }
    // Half extents: a surface from -2^1023 to 2^1023 has an extent of 2^1024, beyond doubles.
    const Bbox_3 box = bbox_3(points.begin(), points.end());
    double half_extent = 0;
    for(int k = 0; k < 3; ++k) half_extent = (std::max)(half_extent, box.max_coord(k) / 2 - box.min_coord(k) / 2);
    scale = unit_scale(half_extent) / 2;
    // Along an axis where the box lies within [m, 2 m] for its lower bound m > 0 (or [2 m, m] for
    // its upper bound m < 0), p - m is exact (Sterbenz): the copy starts there. Elsewhere the box
    // is at most its extent from the origin, near enough.
    for(int k = 0; k < 3; ++k) {
      const double low = box.min_coord(k), high = box.max_coord(k);
      if(low > 0 && high <= 2 * low) offset[k] = low;
      if(high < 0 && low >= 2 * high) offset[k] = high;
    }
    std::vector<Point_3> scaled;
    for(const Point_3& p : points)
      scaled.emplace_back(scale * (CGAL::to_double(p.x()) - offset[0]), scale * (CGAL::to_double(p.y()) - offset[1]),
                          scale * (CGAL::to_double(p.z()) - offset[2]));
    // Mesh_3 tells inside from outside by ray parity, so orientation does not change the volume
    // it meshes; orienting makes the volume below positive and the copy independent of the input's
    // orientation (orient a first build, then read its triangles back).
    Surface first = build(scaled, triangles);
    PMP::orient_to_bound_a_volume(first);
    for(auto f : faces(first)) {
      Triangle& t = triangles[std::size_t(f)];
      std::size_t k = 0;
      for(auto v : vertices_around_face(halfedge(f, first), first)) t[k++] = std::size_t(v);
    }
    surface = build(scaled, triangles);
    // The volume, as tetrahedra from the centre of the bounding box in units of its largest extent:
    // PMP::volume() sums them from the origin, where far from it rounding swamps the volume.
    const auto unit = [&](std::size_t i) {
      std::array<double, 3> u;
      for(int k = 0; k < 3; ++k)
        u[k] = (CGAL::to_double(points[i][k]) / 2 - (box.min_coord(k) / 2 + box.max_coord(k) / 2) / 2) / half_extent;
      return u;
    };
    component.resize(triangles.size());
    const std::size_t components = PMP::connected_components(surface, CGAL::make_property_map(component));
    std::vector<double> unit_volumes(components, 0.);
    component_area.assign(components, 0.);
    double scaled_area = 0;   // PMP::area(surface), summed in its order
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      const Triangle& t = triangles[i];
      const auto a = unit(t[0]), b = unit(t[1]), c = unit(t[2]);
      unit_volumes[component[i]] += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
      const double face_area = CGAL::to_double(PMP::face_area(typename Surface::Face_index(i), surface));
      scaled_area += face_area;
      component_area[component[i]] += face_area;
    }
    for(double& a : component_area) a = a / scale / scale;
    double unit_volume = 0;
    for(double v : unit_volumes) {
      unit_volume += v;
      component_volume.push_back(v * (2 * half_extent) * (2 * half_extent) * (2 * half_extent));
    }
    if(!(unit_volume > 0) || !std::isfinite(unit_volume))
      throw Invalid_input("mesh_interior: the surface encloses no volume");
    volume = unit_volume * (2 * half_extent) * (2 * half_extent) * (2 * half_extent);
    area = scaled_area / scale / scale;
    if(!(volume > 0) || !std::isfinite(volume) || !(area > 0) || !std::isfinite(area))
    {
      char size[32];
      std::snprintf(size, sizeof size, "%g", 2 * half_extent);
      throw Invalid_input(std::string("mesh_interior: the surface's size (") + size +
                          ") is too large or too small for its volume in double precision: scale it");
    }
  }

  // The surface of the triangles, each rotated to start at its smallest index (vertex i of the
  // result is points[i]).
  static Surface build(const std::vector<Point_3>& points, std::vector<Triangle> triangles)
  {
    for(Triangle& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(triangles))
      throw Invalid_input("mesh_interior: the triangles of the surface do not form an oriented 2-manifold");
    Surface s;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, s);
    return s;
  }
};

// The three corners of face f of `surface` (a Surface_mesh of triangles).
template <class Surface>
std::array<typename Surface::Point, 3> corners(const Surface& surface, typename Surface::Face_index f)
{
  std::array<typename Surface::Point, 3> p;
  std::size_t k = 0;
  for(auto v : vertices_around_face(halfedge(f, surface), surface)) p[k++] = surface.point(v);
  return p;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CHECKED_SURFACE_H
