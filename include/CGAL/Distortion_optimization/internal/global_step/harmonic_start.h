// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The harmonic start, the first move of an optimization: the Dirichlet minimizer for the fixed
// vertices (with the cell weights w(c): for the default weights, the volume-weighted cotangent
// Laplacian's), taken if it is valid and better, else approached by a line search within the
// exact largest safe step. Sliding vertices stay where they are.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_HARMONIC_START_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_HARMONIC_START_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/global_step/line_search.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/step_bound.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Moves the state's map towards its harmonic map; `system` is the global steps' (its unknowns the
// free vertices). Skipped where the harmonic map is not defined
// (Laplacian_system::harmonic_targets). Returns true if the map changed.
template <class State>
bool harmonic_start(State& state, Laplacian_system<State::dimension>& system)
{
  constexpr int n = State::dimension;
  using Vec = Vector<n>;
  const auto& p = state.problem();
  if(system.size() == 0) return false;
  std::vector<Vec> direction;
  if(p.is_sliding.empty()) {
    if(!system.harmonic_targets(state.targets(), direction)) return false;
  } else {
    std::vector<unsigned char> interior(p.number_of_vertices());
    for(std::size_t v = 0; v < interior.size(); ++v) interior[v] = p.is_free[v] && !p.slides(v);
    Laplacian_system<n> interior_system(p, state.workers(), &interior);
    if(!interior_system.harmonic_targets(state.targets(), direction)) return false;
  }
  for(std::size_t v = 0; v < direction.size(); ++v) direction[v] -= state.targets()[v];
  if(std::all_of(direction.begin(), direction.end(), [](const Vec& d) { return d == Vec::Zero(); })) return false;   // already harmonic
  // The full step when it is safe; otherwise the largest safe fraction of it, halved until the
  // energy drops, three times at most: a smaller fraction is no longer a start, and where the
  // start is already better the 30 trials of a full line search are a costly share of the run.
  const double t_max = largest_safe_step(state, system.moving_cells(), direction, 1 / 0.9);
  double t = t_max > 1 ? 1. : 0.9 * t_max;
  return line_search(state, system.moving_cells(), direction, t, 0., [] { return 0.; }, 0., 4);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_HARMONIC_START_H
