// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Untangling: from a start with inverted or flat cells to a map whose every cell has its source's
// orientation, by the method of Garanzha, Kaporin, Kudryavtseva, Protais, Ray and Sokolov,
// "Foldover-free maps in 50 lines of code" (SIGGRAPH 2021): minimize the barrier F_eps of
// measures.h (Untangling_barrier) for a decreasing eps. Their eps rule: after each round, with E
// and E_prev the energies after and before it and D- the smallest relative determinant,
// sigma = max(1 - E / E_prev, 0.1), mu = (1 - sigma) chi(D-, eps), and the new eps makes
// chi(D-, eps) = mu, i.e. eps = 2 sqrt(mu (mu - D-)) while D- < mu; so the worst cell's stand-in
// determinant shrinks by at least 10% a round, faster when the round gained much.
//
// A cell is untangled when its orientation is its source's (exact predicate) and it is not
// numerically flat (simplicial_map.h): a cell valid by a hair would make a normalized measure
// infinite when the optimizer takes over.
//
// Unlike their L-BFGS, each round here is iterations of the package's own steps on the package's
// own state: constrained vertices never move, and with the boundary guard the boundary never starts
// crossing itself. While eps falls only the barrier keeps cells from folding; from its floor on, no
// valid cell (exact predicate) is flipped or flattened any more. The run stops as soon as every
// cell is valid; the regular measure takes over from there.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_UNTANGLE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_UNTANGLE_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/minimize.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

struct Untangle_report
{
  std::size_t inverted_before = 0, inverted_after = 0, iterations = 0;
  double seconds = 0;
  bool stopped_by_visitor = false;
};

// The rounds untangle() and minimize_distortion(untangle_first) run at most by default.
constexpr std::size_t default_untangle_rounds = 1000;

// Whether cell c still needs untangling: inverted or flat (exact predicate), or numerically flat.
template <int n, class GeomTraits>
bool is_tangled(const Simplicial_map<n>& map, std::size_t c, const GeomTraits& traits)
{
  return is_inverted(map, c, traits) || is_numerically_flat(map, c);
}

// The smallest det J_c of the map, in parallel.
template <int n>
double smallest_jacobian_determinant(const Simplicial_map<n>& map, const Workers& workers)
{
  return workers.reduce(map.number_of_cells(), infinity, [&](std::size_t c) { return map.jacobian_determinant(c); },
                        [](double a, double b) { return std::min(a, b); });
}

// The map's typical det J: the ratio of its signed volume to the source's, or, for a map that is
// mostly inverted, the mean |det J|; the barrier measures determinants relative to it.
template <int n>
double typical_jacobian_determinant(const Simplicial_map<n>& map)
{
  double signed_sum = 0, absolute_sum = 0, volume = 0;
  for(std::size_t c = 0; c < map.number_of_cells(); ++c) {
    const double det = map.jacobian_determinant(c);
    signed_sum += map.rest_volume[c] * det;
    absolute_sum += map.rest_volume[c] * std::abs(det);
    volume += map.rest_volume[c];
  }
  const double typical = signed_sum > 0 ? signed_sum / volume : absolute_sum / volume;
  return std::isfinite(typical) && typical > 0 ? typical : 1.;
}

// Untangles problem.map in place (the whole map; untangle() below first tries the tangle's
// surroundings). options.iterations bounds the rounds (values of eps); a round
// runs the schedule's iterations until one gains less than 1e-5 of the barrier, at most 200; the
// visitor is called after each round with the round and the number of cells still inverted, and
// may stop the run there. Throws Invalid_input, with the map unchanged, when some inverted cell
// has only constrained vertices, or when the rounds end with inverted cells (no injective map may
// exist with these constraints).
template <int n, class GeomTraits>
Untangle_report untangle_everywhere(Optimization_problem<n>& problem, const GeomTraits& traits, Options options,
                                    bool throw_on_failure = true)
{
  const auto start = std::chrono::steady_clock::now();
  const Workers workers(options.threads);
  Untangling_barrier barrier;
  barrier.reference_det = typical_jacobian_determinant(problem.map);
  using State = Optimizer_state<n, Untangling_barrier, GeomTraits>;
  // First as Garanzha et al.: only the barrier keeps cells from folding, so that a fold can open
  // through flat states. Once eps is at its floor, no valid cell may flip any more (the optimizer's
  // own guarantee), so that the count of inverted cells only falls.
  State state(problem, barrier, traits, workers, false);
  // The state counts the cells inverted by the exact predicate; those valid but numerically flat
  // are untangled too.
  const auto tangled = [&] {
    return state.number_of_inverted_cells() +
           workers.reduce(problem.map.number_of_cells(), std::size_t(0),
                          [&](std::size_t c) { return std::size_t(state.is_valid(c) && is_numerically_flat(problem.map, c)); },
                          [](std::size_t a, std::size_t b) { return a + b; });
  };
  Untangle_report report;
  report.inverted_before = report.inverted_after = tangled();
  if(report.inverted_before == 0) return report;
  for(std::size_t c = 0; c < problem.map.number_of_cells(); ++c) {
    bool moves = false;
    for(auto v : problem.map.cells[c]) moves = moves || problem.is_free[v];
    if(!moves && (!state.is_valid(c) || is_numerically_flat(problem.map, c)))
      throw Invalid_input("cell " + std::to_string(c) + " is inverted or flat and all its vertices are constrained: "
                          "no map with these constraints is injective");
  }
  const std::vector<Vector<n>> start_targets = problem.map.target;
  std::vector<Vector<n>> best_targets = start_targets;
  std::size_t fewest = report.inverted_before;
  options.harmonic_start = false;
  Steps<State> steps(state, problem, options, workers);

  // eps is relative to the typical determinant, as D- below; the floor is the paper's.
  const double floor = n == 2 ? 1e-9 : 1e-10;
  std::size_t rounds_without_progress = 0;
  while(report.iterations < options.iterations) {
    ++report.iterations;
    const double before = state.energy();
    const std::size_t inverted_before = report.inverted_after;
    double energy = before;
    for(int k = 0; k < 200; ++k) {
      const double previous = energy;
      steps.iterate();
      energy = state.energy();
      if(tangled() == 0 || !(previous - energy > 1e-5 * std::abs(previous))) break;
    }
    report.inverted_after = tangled();
    if(options.visitor && !options.visitor(report.iterations, static_cast<double>(report.inverted_after))) {
      report.stopped_by_visitor = true;
      break;
    }
    if(report.inverted_after == 0) break;
    // The paper's eps rule, on determinants relative to the typical one; our rounds converge less
    // far than their L-BFGS, so eps falls at most tenfold a round (a faster fall collapses folds
    // into flat strips that no later round opens).
    const double worst = smallest_jacobian_determinant(problem.map, workers) / barrier.reference_det;
    const double e = barrier.epsilon, root = std::sqrt(e * e + worst * worst);
    const double chi = Untangling_barrier::regularized_determinant(worst, e * e, root);
    const double sigma = std::max(before > 0 ? 1 - energy / before : 0., 0.1), mu = (1 - sigma) * chi;
    barrier.epsilon = std::max({floor, 0.1 * e, worst < mu ? 2 * std::sqrt(mu * (mu - worst)) : floor});
    if(report.inverted_after < fewest) {
      fewest = report.inverted_after;
      best_targets = problem.map.target;
    }
    if(barrier.epsilon <= floor && !state.keeps_valid_cells()) {
      // The protected phase starts from the map with the fewest inverted cells seen, so that the
      // run never ends with more than the start had.
      problem.map.target = best_targets;
      state.keep_valid_cells(true);
      state.revalidate();
      steps.targets_replaced();
    }
    state.refresh();
    // Stuck: eps at its floor and no cell untangled for a while.
    rounds_without_progress = barrier.epsilon <= floor && report.inverted_after >= inverted_before ? rounds_without_progress + 1 : 0;
    if(rounds_without_progress >= 20) break;
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(report.inverted_after > 0 && !report.stopped_by_visitor && !throw_on_failure) {
    // The map with the fewest inverted cells: a start for a wider attempt.
    problem.map.target = best_targets;
    report.inverted_after = fewest;
  } else if(report.inverted_after > 0 && !report.stopped_by_visitor) {
    const std::size_t still = report.inverted_after;
    problem.map.target = start_targets;
    throw Invalid_input("untangling failed: " + std::to_string(still) + " of " + std::to_string(report.inverted_before) +
                        " inverted or flat cells remain after " + std::to_string(report.iterations) +
                        " rounds; the constraints may admit no injective map");
  }
  return report;
}

// Untangles problem.map in place, as untangle_everywhere(). A few inverted cells in a large map
// (the tangles of a deformation, the flat cells a ball map leaves along the sharp edges of a
// domain) are first untangled in the part of the map within one ring of them, a problem the size
// of the tangle, then within two and three rings of those still inverted, each attempt starting
// from the best map of the last; the whole map only if cells remain inverted. Not with the
// boundary guard, which must see the whole boundary.
template <int n, class GeomTraits>
Untangle_report untangle(Optimization_problem<n>& problem, const GeomTraits& traits, const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  const auto inverted_vertices = [&](std::vector<unsigned char>& region) {
    std::size_t inverted = 0;
    region.assign(problem.number_of_vertices(), 0);
    for(std::size_t c = 0; c < problem.map.number_of_cells(); ++c)
      if(is_tangled(problem.map, c, traits)) {
        ++inverted;
        for(auto v : problem.map.cells[c]) region[v] = 1;
      }
    return inverted;
  };
  std::vector<unsigned char> region;
  Untangle_report report;
  report.inverted_before = report.inverted_after = inverted_vertices(region);
  if(report.inverted_before == 0 || options.global_injectivity || 20 * report.inverted_before > problem.map.number_of_cells())
    return untangle_everywhere(problem, traits, options);
  const std::vector<Vector<n>> start_targets = problem.map.target;
  for(int rings = 1; rings <= 3 && report.inverted_after > 0; ++rings) {
    if(rings > 1) inverted_vertices(region);
    for(int k = 0; k < rings; ++k) {
      // One more ring: every vertex of a cell that touches the region.
      std::vector<unsigned char> grown = region;
      for(const auto& cell : problem.map.cells) {
        bool touches = false;
        for(auto v : cell) touches = touches || region[v];
        if(touches)
          for(auto v : cell) grown[v] = 1;
      }
      region.swap(grown);
    }
    std::vector<std::uint32_t> global;
    Optimization_problem<n> part = part_of(problem, region, global);
    if(2 * part.map.number_of_cells() > problem.map.number_of_cells()) break;   // hardly smaller than the map
    const Untangle_report r = untangle_everywhere(part, traits, options, false);
    for(std::size_t i = 0; i < global.size(); ++i) problem.map.target[global[i]] = part.map.target[i];
    report.iterations += r.iterations;
    report.inverted_after = r.inverted_after;
    report.stopped_by_visitor = r.stopped_by_visitor;
    if(r.stopped_by_visitor) break;
  }
  if(report.inverted_after > 0 && !report.stopped_by_visitor) {
    try {
      const Untangle_report r = untangle_everywhere(problem, traits, options);
      report.iterations += r.iterations;
      report.inverted_after = r.inverted_after;
      report.stopped_by_visitor = r.stopped_by_visitor;
    } catch(const Invalid_input&) {
      problem.map.target = start_targets;
      throw;
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_UNTANGLE_H
