// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_DISTORTION_OPTIMIZATION_RESULT_H
#define CGAL_DISTORTION_OPTIMIZATION_RESULT_H

#include <CGAL/license/Distortion_optimization.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// What `CGAL::minimize_distortion()` returns. Energies are weighted means
/// sum_c w(c) D(J_c) / sum_c w(c) with the run's cell weights w(c) (Algorithm 1, step 2); with the
/// default uniform vertex weights and average-volume weighting this is the volume-weighted mean.
struct Result
{
  double initial_energy = 0;                 ///< energy of the start map (after the untangling, if any)
  double final_energy = 0;                   ///< energy of the returned map
  /// energy the iterations start from, which the convergence threshold measures the first one
  /// against: after the harmonic start (`use_harmonic_start`) where it was taken, else `initial_energy`
  double harmonic_start_energy = 0;
  std::vector<double> energy_per_iteration;  ///< energy after each iteration (sweep)
  std::size_t iterations = 0;                ///< iterations (sweeps over the free vertices) done
  double seconds = 0;                        ///< wall-clock time of the optimization, untangling included
  std::size_t inverted_cells = 0;            ///< inverted or flat cells of the returned map (exact predicate)
  bool converged = false;                    ///< the relative energy decrease fell below the threshold
  bool stopped_by_visitor = false;           ///< the visitor returned false
  std::size_t inverted_start_cells = 0;      ///< inverted or flat cells of the start map
  std::size_t untangle_iterations = 0;       ///< rounds of untangling (with `untangle_first`), 0 if none was needed
  double untangle_seconds = 0;               ///< wall-clock time of the untangling
};

/// \ingroup PkgDistortionOptimizationRef
/// What `Distortion_optimization::untangle()` returns.
struct Untangle_result
{
  std::size_t inverted_before = 0;  ///< inverted or flat cells of the start map (exact predicate)
  std::size_t inverted_after = 0;   ///< the same in the returned map: 0 unless the visitor stopped the run
  std::size_t iterations = 0;       ///< rounds of the barrier's decreasing eps
  double seconds = 0;               ///< wall-clock time
  bool stopped_by_visitor = false;  ///< the visitor returned false
};

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_RESULT_H
