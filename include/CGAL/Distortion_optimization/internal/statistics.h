// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Evaluation of a simplicial map: per-cell distortion and the weighted means of eq. 23-25.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_STATISTICS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_STATISTICS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Distortion_statistics.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// vertex_weights: omega(v), empty for omega = 1. per_cell (optional) receives D(J_c). The traits'
// orientation predicates count the inverted cells; inverted_per_cell (optional) receives 1 for
// each of them, 0 for the others. A map that is not `oriented` (surface to surface) has none, and
// the predicates are skipped.
template <int n, class Measure, class GeomTraits>
Distortion_statistics evaluate(const Simplicial_map<n>& map, const Measure& measure, const GeomTraits& traits,
                               const std::vector<double>& vertex_weights,
                               std::vector<double>* per_cell = nullptr,
                               std::vector<unsigned char>* inverted_per_cell = nullptr, bool oriented = true)
{
  Distortion_statistics s;
  s.cells = map.number_of_cells();
  s.min = std::numeric_limits<double>::infinity();
  s.max = -std::numeric_limits<double>::infinity();
  if(per_cell) per_cell->resize(s.cells);
  if(inverted_per_cell) inverted_per_cell->assign(s.cells, 0);
  double sum_uniform = 0, sum_volume = 0;
  std::vector<double> values(s.cells);
  cell_distortions<n>(measure, map, s.cells, [](std::size_t c) { return c; }, values.data());
  for(std::size_t c = 0; c < s.cells; ++c) {
    const double d = values[c];
    if(std::isnan(d))
      throw Invalid_input("the distortion of cell " + std::to_string(c) + " is not a number");
    if(per_cell) (*per_cell)[c] = d;
    double omega = n + 1;
    if(!vertex_weights.empty()) {
      omega = 0;
      for(auto v : map.cells[c]) omega += vertex_weights[v];
    }
    s.energy_uniform += omega * d;
    s.energy_volume += omega * map.rest_volume[c] * d;
    sum_uniform += omega;
    sum_volume += omega * map.rest_volume[c];
    s.min = std::min(s.min, d);
    s.max = std::max(s.max, d);
    if(oriented && is_inverted(map, c, traits)) {
      ++s.inverted_cells;
      if(inverted_per_cell) (*inverted_per_cell)[c] = 1;
    }
  }
  s.energy_average_volume = s.energy_volume / (n + 1);
  s.mean_uniform = s.energy_uniform / sum_uniform;
  s.mean_volume = s.energy_volume / sum_volume;
  if(s.cells == 0) s.min = s.max = s.mean_uniform = s.mean_volume = 0;
  return s;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_STATISTICS_H
