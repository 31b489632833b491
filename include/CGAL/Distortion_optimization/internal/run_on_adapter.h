// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The bodies of the public functions that change a map, on any adapter (triangle_mesh_adapter.h,
// c3t3_adapter.h): the problem from the named parameters, the run, and the free vertices' targets
// written back only once the run succeeded.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_RUN_ON_ADAPTER_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_RUN_ON_ADAPTER_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/internal/minimize.h>
#include <CGAL/Distortion_optimization/internal/named_parameters.h>
#include <CGAL/Distortion_optimization/internal/untangle.h>

#include <limits>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// minimize_distortion(): with untangle_first, an inverted start is untangled first. A measure whose
// minimum collapses the map is refused before anything runs (check_size_is_held).
template <class Adapter, class TargetMap, class Measure, class NamedParameters>
Result minimize_adapted(Adapter& adapter, TargetMap target, const Measure& measure, const NamedParameters& np)
{
  Optimization_problem<Adapter::dimension> problem = make_problem(adapter, np);
  check_size_is_held(problem, measure);
  const Options options = read_options(np);
  Untangle_result untangled;
  if(options.untangle_first) {
    Options untangle_options = options;
    untangle_options.iterations = default_untangle_rounds;
    untangled = untangle(problem, adapter.traits, untangle_options);
  }
  Result result;
  if(untangled.stopped_by_visitor && untangled.inverted_after > 0) {
    // Stopped while cells are still inverted: the measure may be infinite there, so the energies
    // are not numbers and the map is the untangler's last.
    result.initial_energy = result.final_energy = result.harmonic_start_energy = std::numeric_limits<double>::quiet_NaN();
    result.inverted_cells = untangled.inverted_after;
    result.stopped_by_visitor = true;
  } else if(untangled.stopped_by_visitor) {
    // Stopped at the round that untangled the map: its energy, no iteration.
    Options evaluate = options;
    evaluate.iterations = 0;
    evaluate.harmonic_start = false;
    result = minimize(problem, measure, adapter.traits, evaluate);
    result.stopped_by_visitor = true;
  } else {
    result = minimize(problem, measure, adapter.traits, options);
  }
  if(untangled.inverted_before > 0) result.inverted_start_cells = untangled.inverted_before;
  result.untangle_iterations = untangled.iterations;
  result.untangle_seconds = untangled.seconds;
  result.seconds += untangled.seconds;
  adapter.write_targets(target, problem.map.target, problem.is_free);
  return result;
}

// untangle(): number_of_iterations bounds the rounds.
template <class Adapter, class TargetMap, class NamedParameters>
Untangle_result untangle_adapted(Adapter& adapter, TargetMap target, const NamedParameters& np)
{
  Optimization_problem<Adapter::dimension> problem = make_problem(adapter, np);
  Options options = read_options(np);
  options.iterations = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::number_of_iterations), default_untangle_rounds);
  const Untangle_result result = untangle(problem, adapter.traits, options);
  adapter.write_targets(target, problem.map.target, problem.is_free);
  return result;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_RUN_ON_ADAPTER_H
