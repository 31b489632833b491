// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Algorithm 3 (ParallelGradDescent): the cells are cut into k parts by a spatial partition (slabs
// of equal cell counts along the longest axis of the map); the free vertices whose cells lie in
// more than one part (V_com) are swept first, then every part sweeps its own vertices in parallel
// with V_com frozen. A vertex of a part has all its cells in that part, so two parts never touch
// the same cell or vertex: the result depends on k only, never on the threads' timing.
// One sweep of each sub-problem per iteration: Algorithm 1's loop around this sweep plays the role
// of Algorithm 3's repeat loop.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_PARTITIONED_SWEEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_PARTITIONED_SWEEP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/greedy_sweep.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

struct Vertex_partition
{
  std::vector<std::uint32_t> interface;            // free vertices of V_com
  std::vector<std::vector<std::uint32_t>> parts;   // the other free vertices, by part
};

// Cuts the cells of the current map into k slabs along the longest axis of its bounding box and
// sorts the given vertices into parts and interface; `sequential` ones join the interface.
template <int n>
Vertex_partition partition_vertices(const Optimization_problem<n>& p, std::size_t k,
                                    const std::vector<std::uint32_t>& vertices,
                                    const std::vector<std::uint32_t>& sequential)
{
  const auto& map = p.map;
  const std::size_t nc = map.number_of_cells();
  Vector<n> lo = Vector<n>::Constant(infinity), hi = -lo;
  for(const auto& x : map.target) { lo = lo.cwiseMin(x); hi = hi.cwiseMax(x); }
  int axis;
  (hi - lo).maxCoeff(&axis);
  std::vector<double> key(nc);
  for(std::size_t c = 0; c < nc; ++c) {
    key[c] = 0;
    for(auto v : map.cells[c]) key[c] += map.target[v][axis];
  }
  std::vector<std::uint32_t> by_key(nc);
  std::iota(by_key.begin(), by_key.end(), 0u);
  std::stable_sort(by_key.begin(), by_key.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  std::vector<std::uint32_t> part_of(nc);
  for(std::size_t i = 0; i < nc; ++i) part_of[by_key[i]] = static_cast<std::uint32_t>(i * k / std::max<std::size_t>(nc, 1));

  Vertex_partition result;
  result.parts.resize(k);
  result.interface = sequential;
  for(std::uint32_t v : vertices) {
    const std::uint32_t begin = p.ring_begin[v], end = p.ring_begin[v + 1];
    bool shared = false;
    for(std::uint32_t r = begin; r < end; ++r) shared = shared || part_of[p.ring[r].cell] != part_of[p.ring[begin].cell];
    if(shared || begin == end) result.interface.push_back(v);
    else result.parts[part_of[p.ring[begin].cell]].push_back(v);
  }
  return result;
}

template <class LocalStep>
void partitioned_sweep(LocalStep& step, const Vertex_partition& partition, const Workers& workers)
{
  sorted_sweep(step, partition.interface);
  workers.for_each(partition.parts.size(), 1, [&](std::size_t i) { sorted_sweep(step, partition.parts[i]); });
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_PARTITIONED_SWEEP_H
