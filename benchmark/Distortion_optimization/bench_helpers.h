// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the volume benchmarks share beyond the examples' volume_examples.h: timing and the checks
// they print.

#ifndef DISTORTION_OPTIMIZATION_BENCHMARK_BENCH_HELPERS_H
#define DISTORTION_OPTIMIZATION_BENCHMARK_BENCH_HELPERS_H

#include "../../examples/Distortion_optimization/volume_examples.h"
#include "../../test/Distortion_optimization/instantiations/extern_mesh_interior.h"

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

} // namespace volume_examples

#endif // DISTORTION_OPTIMIZATION_BENCHMARK_BENCH_HELPERS_H
