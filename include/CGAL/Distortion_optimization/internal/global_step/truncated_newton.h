// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The solve of a tetrahedral mesh's Newton system H x = b (newton_direction.h). It fills in far
// too much for a factorization at every step: truncated Newton (Nash, "Newton-type minimization
// via the Lanczos method", 1984), preconditioned conjugate gradients from 0, cut at 60 iterations
// (more where they fall short, below) or a residual of 1e-2; every iterate from 0 descends.
// Jacobi's preconditioner, except that a model's steps (nothing fixed) take the Laplacian's for
// the rest of the run once a Jacobi solve did not converge: MIPS's Hessian is nearly singular in
// each cell's scaling, where the Laplacian's preconditioner converges in far fewer iterations.
// Where cells' stiffnesses differ by orders of magnitude (after untangling), the Laplacian's is
// the worse of the two: the measures' own steps keep Jacobi's. So do a model's with sliding
// vertices, whose tangent planes the coordinatewise Laplacian does not see.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_TRUNCATED_NEWTON_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_TRUNCATED_NEWTON_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/laplacian_system.h>

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <memory>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n>
class Truncated_newton
{
public:
  // `system`: the global steps' (H is its hessian()). With `may_take_laplacian`, the steps are a
  // smooth model's with nothing fixed and nothing sliding: the Laplacian's preconditioner may
  // take over.
  Truncated_newton(Laplacian_system<n>& system, bool may_take_laplacian)
    : system_(system), may_take_laplacian_(may_take_laplacian) {}

  // The solution of H x = b (`solution`, 0 on entry), cut short.
  void solve(const Eigen::SparseMatrix<double>& H, const Eigen::MatrixXd& b, Eigen::MatrixXd& solution)
  {
    if(laplacian_preconditioner_) {
      system_.solve(H, *laplacian_preconditioner_, b, solution, newton_iterations, 1e-2);
      return;
    }
    Eigen::DiagonalPreconditioner<double> jacobi;
    jacobi.compute(H);
    typename Laplacian_system<n>::Solve_outcome outcome;
    const bool solved = system_.solve(H, jacobi, b, solution, jacobi_iterations_, 1e-2, &outcome);
    if(may_take_laplacian_) {
      if(!solved) {
        laplacian_preconditioner_ = std::make_unique<typename Laplacian_system<n>::Coordinatewise_laplacian>(system_);
        if(!laplacian_preconditioner_->ok()) laplacian_preconditioner_.reset();
      }
    } else {   // a measure's own steps, or a proxy's
      // A direction cut short while its residual is still above half the gradient's is hardly
      // Newton's (inexact Newton methods need it below: Dembo, Eisenstat and Steihaug, "Inexact
      // Newton methods", 1982): the next solves may take twice the iterations, and give them back
      // once the residual is below a tenth. Where cells' stiffnesses differ by orders of
      // magnitude (a start untangled in the large), 60 iterations may not even lower it, and a
      // run with a fixed count stalls far above the minimum. A proxy's direction (the measure's
      // gradient in the model's metric) needs them as much, though its solves stay above a half.
      if(outcome.iterations >= jacobi_iterations_ && outcome.residual > 0.5)
        jacobi_iterations_ = std::min(2 * jacobi_iterations_, 16 * newton_iterations);
      else if(outcome.residual < 0.1)
        jacobi_iterations_ = std::max(jacobi_iterations_ / 2, newton_iterations);
    }
  }

private:
  // The iterations of a solve, and of the next Jacobi-preconditioned one.
  static constexpr int newton_iterations = 60;
  Laplacian_system<n>& system_;
  bool may_take_laplacian_;
  int jacobi_iterations_ = newton_iterations;
  std::unique_ptr<typename Laplacian_system<n>::Coordinatewise_laplacian> laplacian_preconditioner_;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_TRUNCATED_NEWTON_H
