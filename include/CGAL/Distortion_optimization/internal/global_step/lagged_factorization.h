// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The solve of a triangle mesh's Newton system H x = b (newton_direction.h). Inexact: conjugate
// gradients on H preconditioned by the sparse factorization of an earlier H (sparse_cholesky.h),
// to a loose residual; H is factored again when they need many iterations, or would at the rate
// of their first ones. Far from the minimum H changes much from step to step: after a failed
// attempt, the next 1, 2, 4, ... steps factor at once. A run of a few iterations (the atlas's
// rounds of two, each on a new scaffold) factors at every step: its steps are the long ones from
// a start, after which an old factor hardly ever preconditions H well enough.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LAGGED_FACTORIZATION_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LAGGED_FACTORIZATION_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/global_step/backoff.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/sparse_cholesky.h>

#include <cstddef>
#include <limits>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n>
class Lagged_factorization
{
public:
  // `system`: the global steps' (H is its hessian()); `iterations`: the most the run takes.
  Lagged_factorization(const Laplacian_system<n>& system, std::size_t iterations)
    : system_(system), long_run_(iterations > few_iterations),
      factorization_(Sparse_cholesky<n>::default_cholmod_from(),
                     long_run_ ? Fill_reducing_order::NESTED_DISSECTION : Fill_reducing_order::MINIMUM_DEGREE)
  {}

  // The solution of H x = b (`solution`, 0 on entry); NaN where the factorization fails.
  void solve(const Eigen::SparseMatrix<double>& H, const Eigen::MatrixXd& b, Eigen::MatrixXd& solution)
  {
    bool solved = false;
    if(long_run_ && lagged_.tries() && factorization_.is_factored()) {
      solved = system_.solve(H, factorization_, b, solution, 6, 1e-3, nullptr, Laplacian_system<n>::Give_up::WHEN_TOO_SLOW) &&
               solution.allFinite();
      solved ? lagged_.succeeded() : lagged_.failed();
    }
    if(!solved) {
      // A shift of 1e-10 of the mean diagonal keeps H definite where whole modes were dropped or
      // nothing is fixed (translations). The pattern is analyzed at the first factorization only,
      // in the harmonic start's order of the vertices if it has one.
      if(factorization_.needs_analysis()) factorization_.analyze(H, system_.fill_order());
      if(!factorization_.factorize(H, 1e-10 * H.diagonal().mean())) {
        solution.setConstant(std::numeric_limits<double>::quiet_NaN());
        return;
      }
      solution = factorization_.solve(b);
    }
  }

private:
  static constexpr std::size_t few_iterations = 4;
  const Laplacian_system<n>& system_;
  // A run of more than a few iterations: METIS's ordering, dearer than the minimum degree's, pays
  // off over its factorizations, and a solve may be preconditioned by an old one.
  const bool long_run_;
  Sparse_cholesky<n> factorization_;
  Backoff lagged_;   // the solves preconditioned by the last factorization
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LAGGED_FACTORIZATION_H
