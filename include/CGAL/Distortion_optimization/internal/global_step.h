// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Beyond the paper: steps that move all free vertices at once, alternated with the local sweeps
// (which carry information across a mesh only one ring per sweep). Their parts are in
// global_step/, and a step is, in this order:
//  - the tangent planes of the sliding vertices (named parameter sliding_boundary) where they are
//    (global_step/tangent_planes.h: the steps' parts in them);
//  - a direction: with Global_solver::PROJECTED_NEWTON and a measure that has a Hessian in its
//    singular values, or a smooth model that has one, Newton's (global_step/newton_direction.h,
//    solved by global_step/lagged_factorization.h on triangle meshes and
//    global_step/truncated_newton.h on tetrahedral ones); else, or where Newton's cannot be
//    taken, the reweighted Laplacian's (global_step/laplacian_direction.h);
//  - a first trial length, capped at 0.9 times the exact largest step before a cell degenerates
//    (step_bound.h);
//  - the line search (global_step/line_search.h): backtracking (Armijo), each trial accepted only
//    if CGAL's exact orientation predicate sees no flipped cell.
// Before the first step, the harmonic start (global_step/harmonic_start.h). Attempts that may
// fail are retried less often after failures (global_step/backoff.h).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/global_step/backoff.h>
#include <CGAL/Distortion_optimization/internal/global_step/harmonic_start.h>
#include <CGAL/Distortion_optimization/internal/global_step/laplacian_direction.h>
#include <CGAL/Distortion_optimization/internal/global_step/line_search.h>
#include <CGAL/Distortion_optimization/internal/global_step/newton_direction.h>
#include <CGAL/Distortion_optimization/internal/global_step/tangent_planes.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/step_bound.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The global steps of one optimization, and its harmonic start.
template <class State>
class Global_step
{
  static constexpr int n = State::dimension;
  using Vec = Vector<n>;

public:
  // `solver`: the user's choice, unset for the default. Steps take the projected Newton direction
  // where newton_direction.h says (the reweighted Laplacian's otherwise, and where a Newton solve
  // fails); `iterations`: the most the run takes.
  Global_step(State& state, std::optional<Global_solver> solver, std::size_t iterations)
    : state_(state), p_(state.problem()), system_(state.problem(), state.workers()), laplacian_(state, system_),
      newton_(state, system_, solver, iterations) {}

  // Whether the steps solve Newton's system (else the reweighted Laplacian's).
  bool is_newton() const { return newton_.taken(); }
  // Whether those are a model's whose minimizers are not the measure's (some vertex slides): its
  // Hessian is then the metric of the measure's gradient.
  bool model_misses_minimizers() const { return newton_.by_proxy(); }

  // The harmonic start (global_step/harmonic_start.h). Returns true if the map changed.
  bool harmonic_start() { return internal::harmonic_start(state_, system_); }

  // One preconditioned global step. Returns true if the map changed. A Newton step that cannot be
  // taken (no descent, or no acceptable length) gives way to the Laplacian's in the same call.
  bool step()
  {
    if(system_.size() == 0) return false;
    blocked_ = newton_.taken();
    // Where a model's step finds no decrease, the next 1, 2, 4, ... steps are the Laplacian's.
    const bool newton = newton_.taken() && (!newton_.by_model() || model_steps_.tries());
    if(newton && step_along(true)) {
      model_steps_.succeeded();
      return true;
    }
    if(newton && newton_.by_model()) {
      model_steps_.failed();
      newton_.renew_metric();
    }
    // The Laplacian's steps of a measure with kinks may find no decrease for the rest of a run,
    // each costing a third of an iteration: after failures, the next 1, 2, 4, ... are skipped.
    if(!newton_.taken() && !laplacian_steps_.tries()) return false;
    const bool moved = step_along(false);
    if(!newton_.taken()) moved ? laplacian_steps_.succeeded() : laplacian_steps_.failed();
    return moved;
  }

  // Whether the last step was to be Newton's and did not take its full length: a cell about to
  // flatten, the boundary guard or the line search cut it short (or it gave way to the Laplacian's).
  bool was_blocked() const { return blocked_; }

private:
  // A step along Newton's direction or the Laplacian's; true if the map changed.
  bool step_along(bool newton)
  {
    // The tangent planes of the sliding vertices.
    const std::vector<Vec> normal = sliding_normals(state_);
    // The direction x and the gradient g, one row per free vertex.
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(system_.size(), n), x;
    if(!(newton ? newton_(normal, g, x) : laplacian_(normal, g, x))) return false;
    // The direction per vertex, the sliding vertices' in their tangent planes, and its slope.
    std::vector<Vec> direction(p_.number_of_vertices(), Vec::Zero());
    for(std::size_t v = 0; v < direction.size(); ++v)
      if(system_.column(v) >= 0) direction[v] = x.row(system_.column(v)).transpose();
    double slope = 0;
    for(int d = 0; d < n; ++d) slope += g.col(d).dot(x.col(d));
    const auto slope_of = [&] {
      double s = 0;
      for(std::size_t v = 0; v < direction.size(); ++v)
        if(system_.column(v) >= 0) s += g.row(system_.column(v)).dot(direction[v].transpose());
      return s;
    };
    if(!p_.is_sliding.empty()) slope = restrict_direction_to_tangent_planes(p_, state_.workers(), normal, direction, slope_of);
    // P is positive definite (semi-definite with nothing fixed, g then in its range), so only a
    // failed solve gets here.
    if(!(slope < 0)) return false;
    // The first trial length, within the step bound. The Laplacian's step has no natural length,
    // nor has a proxy's (the model's Newton length is not the measure's): twice the last accepted
    // one. Newton's is 1, but far from the minimum barrier-like terms (s^-2) make it short: 2, up
    // to 8 after long steps, then 1 if that fails.
    double& last = newton ? last_newton_t_ : last_t_;
    const bool natural = newton && !newton_.by_proxy();
    const double cap = !(last > 0) ? 1. : natural ? std::clamp(2 * last, 2., 8.) : 2 * last;
    double t = std::min(cap, 0.9 * largest_safe_step(state_, system_.moving_cells(), direction, cap / 0.9));
    // The line search. A model's slope is not the measure's: then any decrease is taken, within 8
    // trials (a model's step shorter than that is not worth the trials: the Laplacian's follows).
    // A proxy's step has the measure's slope.
    const bool model = newton && newton_.by_model() && !newton_.by_proxy();
    const bool moved = line_search(state_, system_.moving_cells(), direction, t, model ? 0. : slope, slope_of,
                                   natural ? 1. : 0., model ? 8 : 30);
    if(moved) last = t;
    if(newton) blocked_ = !(moved && t >= 1);
    return moved;
  }

  State& state_;
  const Optimization_problem<n>& p_;
  Laplacian_system<n> system_;   // the free vertices' systems, which every part fills and solves
  Laplacian_direction<State> laplacian_;
  Newton_direction<State> newton_;
  double last_t_ = 0, last_newton_t_ = 0;   // the last accepted step of each direction
  bool blocked_ = false;
  // A model's steps, a measure's own Laplacian steps.
  Backoff model_steps_, laplacian_steps_;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H
