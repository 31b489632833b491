// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Algorithm 1: iterations until the energy decrease of one is below the threshold (relative to
// the part of the energy above the measure's minimum, when the measure is normalized) or the
// number of iterations is reached. An iteration is a greedy sweep (Algorithm 2), a global step, or
// both (see global_step.h), after an optional harmonic start.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MINIMIZE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MINIMIZE_H

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/global_step.h>
#include <CGAL/Distortion_optimization/internal/greedy_sweep.h>
#include <CGAL/Distortion_optimization/internal/independent_set_sweep.h>
#include <CGAL/Distortion_optimization/internal/local_step.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>
#include <CGAL/Distortion_optimization/internal/partitioned_sweep.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

struct Options
{
  std::size_t iterations = 100;
  double threshold = 1e-4;
  Local_solver solver = Local_solver::GRADIENT_DESCENT;
  Vertex_order order = Vertex_order::SORTED_PER_SWEEP;
  Schedule schedule = Schedule::ALTERNATING;
  bool harmonic_start = true;   // false by default with Schedule::LOCAL (read_options)
  bool global_injectivity = false;   // guard the boundary of free boundary vertices
  int threads = 1;
  Parallel_sweep parallel_sweep = Parallel_sweep::INDEPENDENT_SETS;
  std::function<bool(std::size_t, double)> visitor;   // (iteration, energy) -> continue?
};

// Minimizes in place the target positions of problem.map; throws Invalid_input for a start the
// measure cannot be evaluated on.
template <int n, class Measure>
Result minimize(Optimization_problem<n>& problem, const Measure& measure, const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  const Workers workers(options.threads);
  Local_step<n, Measure> step(problem, measure, options.solver, workers);
  for(std::size_t c = 0; c < step.cell_value.size(); ++c) {
    if(std::isnan(step.cell_value[c]))
      throw Invalid_input("the distortion of cell " + std::to_string(c) + " is not a number");
    if(!std::isfinite(step.cell_value[c]))
      throw Invalid_input("cell " + std::to_string(c) + " of the start map is inverted or degenerate, and the "
                          "measure '" + measure.name() + "' is infinite there: untangle the map first");
  }

  // The guard, only where it has work: some free vertex on the boundary. Those vertices share the
  // guard, so a parallel sweep optimizes them one at a time: with Algorithm 3's interface, or after
  // the independent sets.
  std::unique_ptr<Boundary_guard<n>> guard;
  if(options.global_injectivity)
    guard = std::make_unique<Boundary_guard<n>>(Boundary_guard<n>::boundary_faces(problem.map.cells),
                                                problem.number_of_vertices());
  std::vector<std::uint32_t> parallel_vertices, guarded_vertices;
  for(std::uint32_t v : free_vertices(problem))
    (guard && guard->is_on_boundary(v) ? guarded_vertices : parallel_vertices).push_back(v);
  if(guarded_vertices.empty()) {
    guard.reset();
  } else {
    if(!guard->is_injective(problem.map.target))
      throw Invalid_input("the boundary of the start map intersects itself: global injectivity cannot be preserved");
    guard->rebuild(problem.map.target);
    step.set_boundary_guard(guard.get());
  }

  Result result;
  const double normalization = problem.total_weight > 0 ? 1. / problem.total_weight : 0.;
  double energy = step.energy() * normalization;
  result.initial_energy = energy;
  // A normalized measure is >= its value on rigid maps: measure progress against what is above it.
  const double floor = measure.is_normalized() ? value_on_rigid_maps<n>(measure) : 0.;

  const bool local = options.schedule != Schedule::GLOBAL, global = options.schedule != Schedule::LOCAL;
  std::unique_ptr<Global_step<n, Measure>> global_step;
  if(global || options.harmonic_start) {
    global_step = std::make_unique<Global_step<n, Measure>>(problem, measure, step, workers);
    if(options.harmonic_start && global_step->harmonic_start())
      energy = std::min(energy, step.energy() * normalization);
  }
  // One thread: the sequential sweep (Algorithm 2). More: independent sets or Algorithm 3, set up
  // at the first sweep (after the harmonic start, which moves the map the partition is cut from).
  std::vector<std::vector<std::uint32_t>> sets;
  Vertex_partition partition;
  const auto sweep = [&] {
    if(workers.threads() == 1) return greedy_sweep(step, options.order);
    if(options.parallel_sweep == Parallel_sweep::PARTITION) {
      if(partition.parts.empty()) partition = partition_vertices(problem, workers.threads(), parallel_vertices, guarded_vertices);
      return partitioned_sweep(step, partition, workers);
    }
    if(sets.empty()) sets = independent_sets(problem, parallel_vertices);
    independent_set_sweep(step, sets, workers);
    sorted_sweep(step, guarded_vertices);
  };
  while(result.iterations < options.iterations) {
    if(local) sweep();
    if(global) global_step->step();
    ++result.iterations;
    const double previous = energy;
    // Every accepted move decreases the exact energy; a recomputed sum can still exceed the last
    // one by its own rounding when an iteration gains less than that: keep the smaller.
    energy = std::min(previous, step.energy() * normalization);
    result.energy_per_iteration.push_back(energy);
    if(options.visitor && !options.visitor(result.iterations, energy)) {
      result.stopped_by_visitor = true;
      break;
    }
    // With a positive threshold, an energy within 1e-9 (relative) of the floor has nothing left
    // to gain: near a kink (K, C, V at their minimum) the last digits come only linearly.
    const double above = std::abs(previous - floor);
    if(!(previous - energy > options.threshold * above) ||
       (options.threshold > 0 && above <= 1e-9 * std::abs(previous))) {
      result.converged = true;
      break;
    }
  }
  result.final_energy = energy;
  for(std::size_t c = 0; c < step.cell_ok.size(); ++c)
    if(!step.cell_ok[c]) ++result.inverted_cells;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MINIMIZE_H
