// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Algorithm 1, the whole optimization in one place: the state (optimizer_state.h), the steps that
// move it (local_step.h: one vertex; global_step.h: all free vertices, and the harmonic start),
// the sweeps that order the local steps (greedy_sweep.h: Algorithm 2; independent_set_sweep.h and
// partitioned_sweep.h, Algorithm 3, on threads), the boundary guard (boundary_guard.h), and the
// schedule: iterations until the energy decrease of one is below the threshold (relative to the
// part of the energy above the measure's minimum, when the measure is normalized) or the number of
// iterations is reached. An iteration is a sweep, a global step, or both, after an optional
// harmonic start.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MINIMIZE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MINIMIZE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/global_step.h>
#include <CGAL/Distortion_optimization/internal/greedy_sweep.h>
#include <CGAL/Distortion_optimization/internal/independent_set_sweep.h>
#include <CGAL/Distortion_optimization/internal/local_step.h>
#include <CGAL/Distortion_optimization/internal/named_parameters.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>
#include <CGAL/Distortion_optimization/internal/optimizer_state.h>
#include <CGAL/Distortion_optimization/internal/partitioned_sweep.h>
#include <CGAL/Distortion_optimization/internal/scaling.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The boundary guard of a run with global injectivity, built for the start map, where it has work:
// some free vertex on the boundary (null otherwise). Throws Crossing_start_boundary if the start's
// boundary intersects itself or one of its pieces lies inside another.
template <int n>
std::unique_ptr<Boundary_guard<n>> make_boundary_guard(const Optimization_problem<n>& problem, const Options& options)
{
  if(!options.global_injectivity) return nullptr;
  auto guard = std::make_unique<Boundary_guard<n>>(Boundary_guard<n>::boundary_faces(problem.map.cells),
                                                   problem.number_of_vertices(),
                                                   connected_pieces(problem.map.cells, problem.number_of_vertices()));
  bool has_work = false;
  for(std::size_t v = 0; v < problem.number_of_vertices() && !has_work; ++v)
    has_work = problem.is_free[v] && guard->is_on_boundary(v);
  if(!has_work) return nullptr;
  if(!guard->is_injective(problem.map.target))
    throw Crossing_start_boundary("the boundary of the start map intersects itself, or one of its pieces lies inside another: "
                                  "global injectivity cannot be preserved");
  guard->rebuild(problem.map.target);
  return guard;
}

// The steps on one state and the iteration of the schedule that runs them: a sweep of local
// steps, a global step, or both. Sets up the boundary guard where it has work (throws
// Invalid_input if the start's boundary crosses itself).
template <class State>
class Steps
{
  static constexpr int n = State::dimension;

public:
  Steps(State& state, Optimization_problem<n>& problem, const Options& options, const Workers& workers)
    : problem_(problem), options_(options), workers_(workers), free_(free_vertices(problem)),
      local_step_(state, options.solver)
  {
    // The vertices on the guarded boundary share the guard, so a parallel sweep optimizes them one
    // at a time: with Algorithm 3's interface, or after the independent sets.
    guard_ = make_boundary_guard(problem, options);
    for(std::uint32_t v : free_)
      (guard_ && guard_->is_on_boundary(v) ? guarded_vertices_ : parallel_vertices_).push_back(v);
    if(guard_) state.set_boundary_guard(guard_.get());
    if(options.schedule != Schedule::LOCAL || options.harmonic_start)
      global_step_ = std::make_unique<Global_step<State>>(state, options.global_solver,
                                                          options.iterations);
    // The default schedule: Newton's steps alone, where a local sweep between them costs more
    // than it gains; otherwise alternating, as the reweighted Laplacian's steps need the sweeps.
    // Also Newton's steps alone where they are a smooth model's with the measure's minimizers
    // (global_step/newton_direction.h), as the measure's local moves gain little near its kink.
    // With a sliding boundary the model's minimizers differ, and its Hessian is only a proxy
    // metric: the sweeps must go on (the steps alone stall at a higher energy).
    // A step that one cell's safe step holds back may gain almost nothing: a sweep then follows it
    // in the same iteration (minimize()), so that the run stops only when neither gains.
    const bool newton_alone = global_step_ && global_step_->is_newton() && !global_step_->model_misses_minimizers();
    schedule_ = options.schedule.value_or(newton_alone ? Schedule::GLOBAL : Schedule::ALTERNATING);
  }

  // After the targets were replaced from outside the steps (untangling restores a better map).
  void targets_replaced()
  {
    if(guard_) guard_->rebuild(problem_.map.target);
  }

  // Returns true if the map changed.
  bool harmonic_start() { return global_step_ && global_step_->harmonic_start(); }

  void iterate()
  {
    if(schedule_ != Schedule::GLOBAL) sweep();
    if(schedule_ != Schedule::LOCAL) global_step_->step();
  }

  // Whether a local sweep follows an iteration that gained too little or whose Newton step was cut
  // short (the default schedule of global steps alone), and that sweep. Where a cell about to
  // flatten or the boundary guard blocks Newton's steps, the sweep moves the vertices around the
  // blocker one by one, which Newton's steps would otherwise keep running into.
  bool sweeps_on_stall() const { return !options_.schedule && schedule_ == Schedule::GLOBAL; }
  bool global_step_was_blocked() const { return global_step_ && global_step_->was_blocked(); }
  void sweep_after_stall() { sweep(); }

private:
  // One thread: the sequential sweep (Algorithm 2, in the chosen order). More: independent sets or
  // Algorithm 3 (both in the sorted order), set up at the first sweep (after the harmonic start,
  // which moves the map the partition is cut from).
  void sweep()
  {
    if(workers_.threads() == 1) return sequential_sweep(local_step_, free_, options_.order);
    if(options_.parallel_sweep == Parallel_sweep::PARTITION) {
      if(partition_.parts.empty())
        partition_ = partition_vertices(problem_, workers_.threads(), parallel_vertices_, guarded_vertices_);
      return partitioned_sweep(local_step_, partition_, workers_);
    }
    if(sets_.empty()) sets_ = independent_sets(problem_, parallel_vertices_);
    independent_set_sweep(local_step_, sets_, workers_);
    sorted_sweep(local_step_, guarded_vertices_);
  }

  const Optimization_problem<n>& problem_;
  const Options& options_;
  const Workers& workers_;
  const std::vector<std::uint32_t> free_;
  std::vector<std::uint32_t> parallel_vertices_, guarded_vertices_;
  std::unique_ptr<Boundary_guard<n>> guard_;
  Local_step<State> local_step_;
  std::unique_ptr<Global_step<State>> global_step_;
  Schedule schedule_;
  std::vector<std::vector<std::uint32_t>> sets_;
  Vertex_partition partition_;
};

// Throws unless something holds the map's size where the measure decreases as the map shrinks
// (Dirichlet, or a sum or product with it): then its infimum is the map collapsed onto the affine
// hull of its constrained vertices, every cell flat, and a run ends near that unless n + 1 of them
// are affinely independent (exact predicates) or some vertex slides on a surface. Per piece of the
// mesh (joined by no vertex): a piece with nothing held collapses alone.
template <int n, class Measure>
void check_size_is_held(const Optimization_problem<n>& problem, const Measure& measure)
{
  if(!(measure.template value<n>(Singular_values<n>::Constant(0.5)) < value_on_rigid_maps<n>(measure))) return;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto& x = problem.map.target;
  const auto point = [&](std::uint32_t v) { return to_point<K>(x[v]); };
  // Whether v is off the affine hull of s (k points, affinely independent).
  const auto independent = [&](const std::array<std::uint32_t, n + 1>& s, int k, std::uint32_t v) {
    if(k == 0) return true;
    if(k == 1) return x[v] != x[s[0]];
    if constexpr(n == 2) return CGAL::orientation(point(s[0]), point(s[1]), point(v)) != CGAL::COLLINEAR;
    else return k == 2 ? !CGAL::collinear(point(s[0]), point(s[1]), point(v))
                       : CGAL::orientation(point(s[0]), point(s[1]), point(s[2]), point(v)) != CGAL::COPLANAR;
  };
  const std::vector<std::uint32_t> piece = connected_pieces(problem.map.cells, problem.number_of_vertices());
  // Per piece's root: its constrained vertices, and up to n + 1 of them affinely independent (n + 1
  // where one slides: its surface holds the size).
  std::vector<std::size_t> constrained(piece.size(), 0);
  std::vector<std::array<std::uint32_t, n + 1>> span(piece.size());
  std::vector<int> rank(piece.size(), 0);
  for(std::uint32_t v = 0; v < piece.size(); ++v) {
    const std::uint32_t r = piece[v];
    if(problem.slides(v)) rank[r] = n + 1;
    if(problem.is_free[v]) continue;
    ++constrained[r];
    if(rank[r] <= n && independent(span[r], rank[r], v)) span[r][rank[r]++] = v;
  }
  const auto& cells = problem.map.cells;
  const auto weak = std::find_if(cells.begin(), cells.end(), [&](const auto& c) { return rank[piece[c[0]]] <= n; });
  if(weak == cells.end()) return;
  const std::size_t k = constrained[piece[(*weak)[0]]];
  const bool one_piece = std::all_of(cells.begin(), cells.end(), [&](const auto& c) { return piece[c[0]] == piece[cells[0][0]]; });
  const std::string hull = n == 2 ? "on one line" : "in one plane";
  throw Invalid_input("the measure " + measure.name() + " decreases as the map shrinks, and " +
                      (one_piece ? std::string() : "in the piece of the mesh with cell " + std::to_string(weak - cells.begin()) + " ") +
                      (k == 0 ? std::string("no vertex is constrained")
                       : k <= n ? "only " + std::to_string(k) + (k == 1 ? " vertex is" : " vertices are") + " constrained"
                                : "the " + std::to_string(k) + " constrained vertices lie " + hull) +
                      ": its minimum collapses " + (one_piece ? "the map" : "that piece") + " (every cell flat); constrain at least " +
                      std::to_string(n + 1) + " vertices not " + hull + (one_piece ? "" : " in each piece") + ", e.g. the boundary");
}

// Minimizes in place the target positions of problem.map; throws Invalid_input for a start the
// measure cannot be evaluated on. The traits' orientation predicates decide which cells are valid.
template <int n, class Measure, class GeomTraits>
Result minimize(Optimization_problem<n>& problem, const Measure& measure, const GeomTraits& traits, const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  const Workers workers(options.threads);
  using State = Optimizer_state<n, Measure, GeomTraits>;
  State state(problem, measure, traits, workers);
  // A start energy above 2 is brought into [1, 2) by scaling the weights (weight_scale()).
  problem.scale_weights(weight_scale(state.energy()));
  Steps<State> steps(state, problem, options, workers);

  Result result;
  result.inverted_start_cells = state.number_of_inverted_cells();
  const double normalization = problem.total_weight > 0 ? 1. / problem.total_weight : 0.;
  double energy = state.energy() * normalization;
  result.initial_energy = energy;
  // A normalized measure is >= its value on rigid maps: measure progress against what is above it.
  const double floor = measure.is_normalized() ? value_on_rigid_maps<n>(measure) : 0.;
  // The harmonic start is the first move of the optimization: no iteration, no move (the start is
  // only evaluated, as after the untangling that untangle_first may have done).
  if(options.harmonic_start && options.iterations > 0 && steps.harmonic_start())
    energy = std::min(energy, state.energy() * normalization);
  result.harmonic_start_energy = energy;

  // The schedule (Algorithm 1).
  while(result.iterations < options.iterations) {
    steps.iterate();
    ++result.iterations;
    const double previous = energy;
    // Every accepted move decreases the exact energy; a recomputed sum can still exceed the last
    // one by its own rounding when an iteration gains less than that: keep the smaller.
    energy = std::min(previous, state.energy() * normalization);
    // With a positive threshold, an energy within 1e-9 (relative) of the floor has nothing left
    // to gain: near a kink (K, C, V at their minimum) the last digits come only linearly. No
    // sweep follows it either: it would cost a share of the run for nothing.
    const double above = std::abs(previous - floor);
    const auto at_floor = [&] { return options.threshold > 0 && std::abs(energy - floor) <= 1e-9 * std::abs(energy); };
    const auto has_converged = [&] { return at_floor() || !(previous - energy > options.threshold * above); };
    if(steps.sweeps_on_stall() && !at_floor() && (has_converged() || steps.global_step_was_blocked())) {
      steps.sweep_after_stall();
      energy = std::min(energy, state.energy() * normalization);
    }
    result.energy_per_iteration.push_back(energy);
    if(options.visitor && !options.visitor(result.iterations, energy, state.number_of_inverted_cells())) {
      result.stopped_by_visitor = true;
      break;
    }
    if(has_converged()) {
      result.converged = true;
      break;
    }
  }
  result.final_energy = energy;
  result.inverted_cells = state.number_of_inverted_cells();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MINIMIZE_H
