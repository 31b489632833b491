// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Beyond the paper: a parallel sweep over independent sets. The free vertices are coloured
// greedily so that no two vertices of one colour share a cell; a sweep visits the colours in turn
// and optimizes all vertices of a colour at once. Each vertex reads and writes only its own ring,
// and the rings of one colour are disjoint, so the result is the same for every number of threads
// (unlike Algorithm 3 there is no sequential interface band, and every thread has work until the
// last colour).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_INDEPENDENT_SET_SWEEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_INDEPENDENT_SET_SWEEP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/greedy_sweep.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Greedy colouring of the given vertices in their order: each takes the smallest colour that no
// vertex sharing a cell with it has. Returns the colour classes, each in the given order.
template <int n>
std::vector<std::vector<std::uint32_t>> independent_sets(const Optimization_problem<n>& p,
                                                         const std::vector<std::uint32_t>& vertices)
{
  std::vector<int> colour(p.number_of_vertices(), -1);
  std::vector<std::uint32_t> used_by;   // used_by[c] == v + 1: a neighbour of v has colour c
  std::vector<std::vector<std::uint32_t>> sets;
  for(std::uint32_t v : vertices) {
    for(std::uint32_t r = p.ring_begin[v]; r < p.ring_begin[v + 1]; ++r)
      for(auto u : p.map.cells[p.ring[r].cell])
        if(u != v && colour[u] >= 0) used_by[colour[u]] = v + 1;
    int c = 0;
    while(c < static_cast<int>(used_by.size()) && used_by[c] == v + 1) ++c;
    if(c == static_cast<int>(sets.size())) { sets.emplace_back(); used_by.push_back(0); }
    colour[v] = c;
    sets[c].push_back(v);
  }
  return sets;
}

template <class LocalStep>
void independent_set_sweep(LocalStep& step, const std::vector<std::vector<std::uint32_t>>& sets,
                           const Workers& workers)
{
  for(const auto& set : sets)
    workers.for_each(set.size(), 16, [&](std::size_t i) { step.optimize(set[i]); });
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_INDEPENDENT_SET_SWEEP_H
