// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_DISTORTION_OPTIMIZATION_DISTORTION_STATISTICS_H
#define CGAL_DISTORTION_OPTIMIZATION_DISTORTION_STATISTICS_H

#include <CGAL/license/Distortion_optimization.h>

#include <cstddef>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// What `CGAL::compute_distortion()` measures. With cell weights
/// w(c) = sum_{v in c} omega(v) w(c, v) (eq. 23 and Algorithm 1, step 2), the energy is
/// E = sum_c w(c) D(J_c) (eq. 25) and the mean is E / sum_c w(c).
/// Volume and average-volume weights differ by the constant factor n + 1, so their means are equal
/// (`mean_volume` is both) and only their energies differ. A normalized measure is +infinity on an inverted cell, and so
/// are then the means and energies.
struct Distortion_statistics
{
  double mean_uniform = 0;          ///< w(c, v) = 1
  double mean_volume = 0;           ///< w(c, v) = volume(c) or volume(c) / |c|: the volume-weighted mean
  double energy_uniform = 0;        ///< eq. 25 with uniform weights
  double energy_volume = 0;         ///< eq. 25 with volume weights
  double energy_average_volume = 0; ///< eq. 25 with average-volume weights
  double min = 0;                   ///< smallest cell distortion
  double max = 0;                   ///< largest cell distortion
  std::size_t cells = 0;            ///< number of cells
  std::size_t inverted_cells = 0;   ///< cells whose image is inverted or flat (exact predicate)
};

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_DISTORTION_STATISTICS_H
