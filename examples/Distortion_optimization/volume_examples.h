// What the volume examples (volume_to_ball, gyroid_texture) and the benchmark bench_volume share:
// their types, the cube and gyroid inputs, and the checks they print.

#ifndef DISTORTION_OPTIMIZATION_EXAMPLES_VOLUME_EXAMPLES_H
#define DISTORTION_OPTIMIZATION_EXAMPLES_VOLUME_EXAMPLES_H

#include <CGAL/Distortion_optimization/mesh_interior.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace volume_examples {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using Volume = CGAL::Distortion_optimization::Interior_mesh<K>::C3T3;   // what mesh_interior() returns
using Vertex_handle = Volume::Triangulation::Vertex_handle;
using Targets = std::unordered_map<Vertex_handle, Point>;
using Target_map = boost::associative_property_map<Targets>;

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The median of a benchmark's repeated times.
inline double median(std::vector<double> x)
{
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

// The cube [-h, h]^3 as 12 outward-oriented triangles.
inline Surface cube(double h)
{
  Surface s;
  std::vector<Surface::Vertex_index> v;
  for(int i = 0; i < 8; ++i) v.push_back(s.add_vertex(Point(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h)));
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for(const auto& f : faces) s.add_face(v[f[0]], v[f[1]], v[f[2]]);
  return s;
}

// The gyroid sin x cos y + sin y cos z + sin z cos x = 0 inside the box [-a, a]^3, with `periods`
// periods along the side 2 h of the cube. Mesh_3 meshes the interfaces of a labeled domain: label
// 1 where the gyroid function is negative, 2 where it is positive, 0 (outside) beyond the box. The
// gyroid is the interface between 1 and 2; the other facets (on the box) are dropped. The
// surface's border lies on the box's faces, and Mesh_3's facet criteria hold there too (no
// clipping slivers).
inline Surface mesh_gyroid(double h, int periods, double a)
{
  using Domain = CGAL::Labeled_mesh_domain_3<K>;
  using Tr = CGAL::Mesh_triangulation_3<Domain>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
  namespace params = CGAL::parameters;   // Mesh_3's keywords

  const double k = CGAL_PI * periods / h;   // 2 pi periods / (2 h)
  auto label = [k, a](const Point& p) {
    if(std::abs(p.x()) > a || std::abs(p.y()) > a || std::abs(p.z()) > a) return 0;
    const double x = k * p.x(), y = k * p.y(), z = k * p.z();
    return std::sin(x) * std::cos(y) + std::sin(y) * std::cos(z) + std::sin(z) * std::cos(x) < 0 ? 1 : 2;
  };
  // The bounding box only seeds the search: it must enclose the labeled box. The relative error
  // bound is the precision of the bisection that puts surface points on the gyroid (default 1e-3
  // of the box size: visible at this resolution).
  CGAL::Random random(0);   // a seeded domain makes the mesh the same on every run
  const double b = 1.05 * a;
  Domain domain(params::function = label, params::bounding_object = K::Iso_cuboid_3(-b, -b, -b, b, b, b),
                params::relative_error_bound = 1e-6, params::p_rng = &random);
  // Sizes relative to one period; no cell criterion: only the surface is wanted.
  const double size = 2 * h / periods / 25;
  const CGAL::Mesh_criteria_3<Tr> criteria(params::facet_angle = 25, params::facet_size = size,
                                           params::facet_distance = size / 10);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());

  std::vector<C3t3::Facet> box_facets;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    if(c3t3.surface_patch_index(*f) != C3t3::Surface_patch_index(1, 2)) box_facets.push_back(*f);
  for(const C3t3::Facet& f : box_facets) c3t3.remove_from_complex(f);
  // Oriented consistently: from label 2 to label 1 (or the reverse) on every facet.
  Surface gyroid;
  CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, gyroid);
  return gyroid;
}

// The vertices on the boundary of the complex: on a facet between a cell of the complex and one
// outside it (the triangulation also holds cells outside the surface).
inline std::unordered_set<Vertex_handle> boundary_vertices(const Volume& volume)
{
  std::unordered_set<Vertex_handle> boundary;
  for(auto c = volume.cells_in_complex_begin(); c != volume.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(!volume.is_in_complex(c->neighbor(i)))
        for(int j = 1; j < 4; ++j) boundary.insert(c->vertex((i + j) % 4));
  return boundary;
}

// How far the boundary's images are from the unit sphere (0 to rounding when they slide on it).
inline double largest_distance_to_unit_sphere(const std::unordered_set<Vertex_handle>& boundary, const Targets& target)
{
  double largest = 0;
  for(Vertex_handle v : boundary) {
    const Point& q = target.at(v);
    largest = std::max(largest, std::abs(std::sqrt(q.x() * q.x() + q.y() * q.y() + q.z() * q.z()) - 1));
  }
  return largest;
}

} // namespace volume_examples

#endif // DISTORTION_OPTIMIZATION_EXAMPLES_VOLUME_EXAMPLES_H
