// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the volume benchmarks share beyond the examples' volume_examples.h: timing, the checks they
// print, and the gyroid of the paper's Fig. 13 (examples/Distortion_optimization/data/gyroid.off is
// mesh_gyroid(h, 1, 0.95 h) with h = cbrt(4 pi / 3) / 2, written with 9 digits).

#ifndef DISTORTION_OPTIMIZATION_BENCHMARK_BENCH_HELPERS_H
#define DISTORTION_OPTIMIZATION_BENCHMARK_BENCH_HELPERS_H

#include "../../examples/Distortion_optimization/volume_examples.h"

#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_set>
#include <vector>

namespace volume_examples {

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

// The gyroid sin x cos y + sin y cos z + sin z cos x = 0 inside the box [-a, a]^3, with `periods`
// periods along the side 2 h of the cube, meshed by Mesh_3 as the interface between label 1
// (function < 0) and label 2 (function > 0); the facets on the box (label 0 beyond it) are dropped.
inline Surface mesh_gyroid(double h, int periods, double a)
{
  using Domain = CGAL::Labeled_mesh_domain_3<K>;
  using Tr = CGAL::Mesh_triangulation_3<Domain>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
  namespace params = CGAL::parameters;

  const double k = CGAL_PI * periods / h;   // 2 pi periods / (2 h)
  auto label = [k, a](const Point& p) {
    if(std::abs(p.x()) > a || std::abs(p.y()) > a || std::abs(p.z()) > a) return 0;
    const double x = k * p.x(), y = k * p.y(), z = k * p.z();
    return std::sin(x) * std::cos(y) + std::sin(y) * std::cos(z) + std::sin(z) * std::cos(x) < 0 ? 1 : 2;
  };
  // A seeded domain gives the same mesh on every run; the default relative error bound (1e-3 of
  // the box) would put surface points visibly off the gyroid.
  CGAL::Random random(0);
  const double b = 1.05 * a;
  Domain domain(params::function = label, params::bounding_object = K::Iso_cuboid_3(-b, -b, -b, b, b, b),
                params::relative_error_bound = 1e-6, params::p_rng = &random);
  const double size = 2 * h / periods / 25;   // relative to one period; no cell criterion: only the surface is wanted
  const CGAL::Mesh_criteria_3<Tr> criteria(params::facet_angle = 25, params::facet_size = size,
                                           params::facet_distance = size / 10);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());

  std::vector<C3t3::Facet> box_facets;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    if(c3t3.surface_patch_index(*f) != C3t3::Surface_patch_index(1, 2)) box_facets.push_back(*f);
  for(const C3t3::Facet& f : box_facets) c3t3.remove_from_complex(f);
  Surface gyroid;
  CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, gyroid);
  return gyroid;
}

} // namespace volume_examples

#endif // DISTORTION_OPTIMIZATION_BENCHMARK_BENCH_HELPERS_H
