// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The exact rescalings of a map, each by a power of two so that no result changes but the size
// of its numbers: the source and target coordinates alike (coordinate_scale(), in the adapters,
// where the largest is far from 1) and the cell weights (weight_scale(), in the optimizer, where
// the start's energy is large). scale_exactly() applies each.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SCALING_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SCALING_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/number_types.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The power of two by which an adapter scales source and target coordinates alike when the largest
// is far from 1: the kernels form products of up to 2n coordinates (volumes, squared cofactors),
// which overflow or underflow past about 1e50 in 3D. A common factor changes no Jacobian and no
// orientation, and a power of two is exact, so results are those of the unscaled map to the bit.
inline double coordinate_scale(double largest)
{
  return largest > 0x1p-60 && largest < 0x1p60 ? 1. : unit_scale(largest);
}

// The same for a map, from the largest source and target coordinates: when either is far from 1,
// the power of two that brings their geometric mean to 1. A source 2^-200 times the size of its
// target then lies at 2^-100 and the target at 2^100: unscaled, the source's rest volumes (2^-600
// in 3D) had squares that underflow, in the norms of gradients, and a scale-invariant measure
// optimized to another energy than on the unscaled map.
inline double coordinate_scale(double source_largest, double target_largest)
{
  const auto near_one = [](double x) { return x > 0x1p-60 && x < 0x1p60; };
  if(near_one(source_largest) && near_one(target_largest)) return 1.;
  if(!(source_largest > 0)) source_largest = target_largest;
  if(!(target_largest > 0)) target_largest = source_largest;
  return unit_scale(std::sqrt(source_largest) * std::sqrt(target_largest));
}

// The largest absolute coordinate of `points` (Eigen vectors; 0 for none).
template <class Point>
double largest_absolute_coordinate(const std::vector<Point>& points)
{
  double largest = 0;
  for(const Point& x : points) largest = std::max(largest, x.cwiseAbs().maxCoeff());
  return largest;
}

// The same for a map, from its source and target positions.
template <class SourcePoint, class TargetPoint>
double coordinate_scale(const std::vector<SourcePoint>& source, const std::vector<TargetPoint>& target)
{
  return coordinate_scale(largest_absolute_coordinate(source), largest_absolute_coordinate(target));
}

// The power of two by which the optimizer scales every cell weight when the start's energy is
// above 2: the one that brings the energy into [1, 2). A target 2^200 times smaller than its
// source has symmetric Dirichlet energies near 2^600 in 2D, whose gradients' squares overflowed,
// and the run stopped at once. 1 otherwise, and for an energy that is not finite.
inline double weight_scale(double start_energy)
{
  return start_energy > 2 && std::isfinite(start_energy) ? unit_scale(start_energy) : 1.;
}

// Multiplies each of `values` (points, weights) by `factor`, a power of two: exactly, so that
// only the size of what is computed from them changes.
template <class Values>
void scale_exactly(Values& values, double factor)
{
  if(factor != 1)
    for(auto& x : values) x *= factor;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SCALING_H
