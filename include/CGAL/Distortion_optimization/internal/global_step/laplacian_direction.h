// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The reweighted Laplacian's direction d = -P^-1 g of a global step, with P the volume-weighted
// cotangent Laplacian of the source reweighted per cell by a factor of the cell's smallest
// singular value (the measure's `laplacian_weight`, in the spirit of the reweighted proxies of
// SLIM, Rabinovich et al. 2017), solved by warm-started Jacobi-preconditioned conjugate gradients
// to a loose tolerance. Every measure can take it; the measures without a Hessian take only it.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LAPLACIAN_DIRECTION_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LAPLACIAN_DIRECTION_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/global_step/tangent_planes.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>

#include <Eigen/IterativeLinearSolvers>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The reweighted Laplacian's direction of the global steps, warm-started from the last one.
template <class State>
class Laplacian_direction
{
public:
  static constexpr int n = State::dimension;

private:
  using Vec = Vector<n>;

public:
  // `system`: the global steps' (its unknowns the free vertices).
  Laplacian_direction(State& state, Laplacian_system<n>& system)
    : state_(state), p_(state.problem()), system_(system), previous_solution_(Eigen::MatrixXd::Zero(system.size(), n)) {}

  // The direction x and the gradient g (zero on entry; rows: the system's unknowns), with the
  // sliding vertices' rows of g in their tangent planes (`normal`, see tangent_planes.h); false
  // where the solve fails.
  bool operator()(const std::vector<Vec>& normal, Eigen::MatrixXd& g, Eigen::MatrixXd& x)
  {
    system_.refill([&](const std::uint32_t* cells, std::size_t count, double* factor, std::array<Vec, n + 1>* gradient) {
      cell_terms(cells, count, factor, gradient);
    }, &g, nullptr);
    project_on_tangent_planes(p_, system_, normal, g);
    Eigen::DiagonalPreconditioner<double> preconditioner;
    preconditioner.compute(system_.matrix());
    x = previous_solution_;
    system_.solve(system_.matrix(), preconditioner, -g, x, 30, 1e-2);
    // Cut short, conjugate gradients from the last step's solution may not descend (a run
    // then ends as if converged); from 0 every iterate does: g.x < -x.Px / 2 < 0.
    if(!x.allFinite() || !((g.array() * x.array()).sum() < 0)) {
      x.setZero();
      system_.solve(system_.matrix(), preconditioner, -g, x, 30, 1e-2);
    }
    if(!x.allFinite()) return false;
    previous_solution_ = x;
    return true;
  }

private:
  // For the refill: each cell's energy gradient and its measure's laplacian_weight.
  void cell_terms(const std::uint32_t* cells, std::size_t count, double* factor, std::array<Vec, n + 1>* gradient) const
  {
    const bool reweighted = measures_internal::has_laplacian_weight<n>(state_.measure());
    static thread_local std::vector<double> value;
    static thread_local std::vector<Vec> sigma;
    value.resize(count);
    sigma.resize(reweighted ? count : 0);
    cell_distortions<n>(state_.measure(), p_.map, count, [&](std::size_t i) { return cells[i]; }, value.data(), gradient,
                        reweighted ? sigma.data() : nullptr);
    if(reweighted)
      for(std::size_t i = 0; i < count; ++i) factor[i] = measures_internal::laplacian_weight<n>(state_.measure(), sigma[i]);
  }

  State& state_;
  const Optimization_problem<n>& p_;
  Laplacian_system<n>& system_;
  Eigen::MatrixXd previous_solution_;   // the last direction, the next solve's start
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_LAPLACIAN_DIRECTION_H
