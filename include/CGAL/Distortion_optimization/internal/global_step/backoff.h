// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The global step's rule for attempts that may fail (a lagged factorization's solve, a model's
// Newton step, a Laplacian step of a measure with kinks): retried less often after failures.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_BACKOFF_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_BACKOFF_H

#include <CGAL/license/Distortion_optimization.h>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// An attempt that may fail, retried less often after failures: after k in a row, the next
// 2^(k-1) occasions (at most 2^16) skip it.
struct Backoff
{
  std::size_t failures = 0, skips = 0;
  // Whether to make the attempt at this occasion; a skipped occasion uses up one skip.
  bool tries()
  {
    if(skips == 0) return true;
    --skips;
    return false;
  }
  void succeeded() { failures = 0; }
  void failed() { skips = std::size_t(1) << std::min<std::size_t>(failures++, 16); }
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_BACKOFF_H
