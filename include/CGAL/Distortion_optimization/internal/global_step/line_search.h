// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The line search of the global steps and of the harmonic start: backtracking (Armijo) from a
// first trial length within the step bound (step_bound.h), each trial accepted only if CGAL's
// exact orientation predicate sees no flipped cell and the boundary guard sees no crossing.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LINE_SEARCH_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LINE_SEARCH_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Backtracks from t along D (`direction`, one per vertex; `moving`: the cells it changes) until
// the energy decreases (Armijo with the given slope, or any decrease above rounding if slope is
// 0) with no valid cell flipped; then commits, t the length taken. After a first failure above
// `natural` (> 0), the next trial is `natural` rather than t / 2.
// A trial whose boundary the guard finds crossing itself (not only a piece inside another) holds
// the vertices of the crossing faces where they are (their direction zeroed; slope_of() then
// gives the slope left) and tries the same length again, up to max_holds times: near a fold of
// the boundary that moves closed to within rounding, every step of those few vertices crosses,
// and halving the whole step for them would stall the rest of the map.
template <class State, class SlopeOf>
bool line_search(State& state, const std::vector<std::uint32_t>& moving, std::vector<Vector<State::dimension>>& direction,
                 double& t, double slope, const SlopeOf& slope_of, double natural = 0, int trials = 30)
{
  constexpr int n = State::dimension;
  constexpr int max_holds = 8;
  using Vec = Vector<n>;
  const auto& p = state.problem();
  std::vector<Vec>& x = state.targets();
  const std::vector<Vec> x0 = x;
  const double e0 = state.energy();
  const auto moving_cell = [&](std::size_t i) { return moving[i]; };
  auto* guard = state.boundary_guard();
  std::vector<std::uint32_t> crossing;
  bool nested = false;
  const auto boundary_ok = [&] {
    return !guard || guard->is_injective(x, &crossing, guard->clearance_fraction(), &nested);
  };
  const auto place = [&](double length) {
    state.workers().for_each(x.size(), 4096, [&](std::size_t v) {
      if(!p.is_free[v]) return;
      x[v] = x0[v] + length * direction[v];
      Vec normal;
      if(p.slides(v) && direction[v] != Vec::Zero()) x[v] = p.slide(v, x[v], normal);
    });
  };
  for(int k = 0, holds = 0; k < trials && t > 0;) {
    place(t);
    crossing.clear();
    if(state.accept_trial(moving.size(), moving_cell, e0, State::armijo * t * slope, true, boundary_ok)) {
      // On tetrahedra a trial beyond the natural length can pass with little gain: twice a
      // Newton step of K's model lands across K's kink about as far as it started, and of a
      // measure's own convex part back where it started. The natural length is tried too; the
      // lower is kept, which saves iterations. Triangle meshes keep the longer step (their
      // Newton directions come from a factorization, nearly exact: the second trial costs more
      // than it gains).
      if(n == 3 && natural > 0 && t > natural) {
        place(natural);
        if(state.accept_trial(moving.size(), moving_cell, state.energy(), 0., true, boundary_ok)) t = natural;
        else place(t);   // the same bits as the committed trial
      }
      // The committed trial passed boundary_ok(): with the whole clearance, if the guard asked it.
      if(guard) guard->rebuild(x, guard->clearance_fraction() == 1);
      return true;
    }
    if(!crossing.empty() && !nested && holds < max_holds) {
      ++holds;
      for(std::uint32_t v : crossing) direction[v] = Vec::Zero();
      if(slope != 0 && !((slope = slope_of()) < 0)) break;
      continue;
    }
    ++k;
    t = k == 1 && natural > 0 && t > natural ? natural : 0.5 * t;
  }
  x = x0;
  return false;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LINE_SEARCH_H
