// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The local problem (26) for one vertex v: minimize the energy of its ring of cells over the
// position y of v, never leaving the kernel of the ring.
//
// Each incident cell's signed volume is affine in y, so along a direction d the largest step
// before some cell degenerates is exact: t_max = min over shrinking cells of vol / (-dvol/dt).
// Trial steps stay below half of t_max and backtrack (Armijo); the state accepts a position only
// if no valid cell of the ring flipped or flattened (exact orientation predicate).
//
// A sliding vertex (named parameter sliding_boundary) descends along its gradient's part in the
// surface's tangent plane, and each trial position is projected back onto the surface: the volumes
// are then no longer affine along the path, so the exact bound only sets the first trial, and the
// state's exact check still decides.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LOCAL_STEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LOCAL_STEP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <class State>
class Local_step
{
  static constexpr int n = State::dimension;
  using Vec = Vector<n>;

public:
  static constexpr double safety = 0.5;   // fraction of the exact largest step tried first (0.9 backtracks more)
  static constexpr int max_backtracks = 40;

  Local_step(State& state, Local_solver solver)
    : state_(state), p_(state.problem()), solver_(solver), last_step_(p_.number_of_vertices(), 0.) {}

  const State& state() const { return state_; }

  // Solves (26) approximately for v; returns true if v moved.
  bool optimize(std::size_t v)
  {
    Vec g;
    double e = ring_gradient(v, g);
    const bool sliding = p_.slides(v);
    if(sliding) {
      Vec normal;
      p_.slide(v, state_.targets()[v], normal);
      g -= g.dot(normal) * normal;
    }
    const double g2 = g.squaredNorm();
    if(!(g2 > 0) || !std::isfinite(g2)) return false;

    // First trial step: twice the last accepted one, or half the distance to the nearest ring
    // neighbour for a first visit (the paper leaves this open; it decides most of the cost).
    double t0 = last_step_[v] > 0 ? 2 * last_step_[v] : 0.5 * nearest_neighbour_distance(v) / std::sqrt(g2);
    if(solver_ == Local_solver::GRADIENT_DESCENT || sliding) {
      const Vec d = -g;
      double t = std::min(t0, safety * max_step(v, d));
      if(!line_search(v, e, d, -g2, t)) return false;
      last_step_[v] = t;
      return true;
    }

    // BFGS on the n coordinates of v, with the inverse Hessian estimate started at t0 * I.
    Matrix<n> H = t0 * Matrix<n>::Identity();
    bool moved = false;
    for(int iteration = 0; iteration < 5; ++iteration) {
      Vec d = -H * g;
      double slope = g.dot(d);
      if(!(slope < 0)) { H = t0 * Matrix<n>::Identity(); d = -t0 * g; slope = -t0 * g2; }
      double t = std::min(1., safety * max_step(v, d));
      if(!line_search(v, e, d, slope, t)) break;
      moved = true;
      const Vec s = t * d;
      Vec g_new;
      e = ring_gradient(v, g_new);
      const Vec y = g_new - g;
      const double sy = s.dot(y);
      if(sy > 1e-12 * s.norm() * y.norm()) {
        const double rho = 1. / sy;
        const Matrix<n> A = Matrix<n>::Identity() - rho * s * y.transpose();
        H = A * H * A.transpose() + rho * s * s.transpose();
      }
      g = g_new;
      if(!(g.squaredNorm() > 1e-24 * g2)) break;
    }
    if(moved) last_step_[v] = t0;
    return moved;
  }

private:
  // The ring's energy sum_c w(c) D(J_c) at the current position of v and its gradient in v.
  double ring_gradient(std::size_t v, Vec& g) const
  {
    static thread_local std::vector<double> value;
    static thread_local std::vector<std::array<Vec, n + 1>> gradient;
    const std::uint32_t begin = p_.ring_begin[v], count = p_.ring_begin[v + 1] - begin;
    value.resize(count);
    gradient.resize(count);
    cell_distortions<n>(state_.measure(), p_.map, count, [&](std::size_t i) { return p_.ring[begin + i].cell; }, value.data(), gradient.data());
    g.setZero();
    double e = 0;
    for(std::uint32_t i = 0; i < count; ++i) {
      const Incidence& in = p_.ring[begin + i];
      const double w = p_.cell_weight[in.cell];
      e += w * value[i];
      g += w * gradient[i][in.local];
    }
    return e;
  }

  // Exact largest t such that no valid cell of the ring degenerates at y + t d.
  double max_step(std::size_t v, const Vec& d) const
  {
    double t_max = infinity;
    if(!state_.keeps_valid_cells()) return t_max;
    for(std::uint32_t k = p_.ring_begin[v]; k < p_.ring_begin[v + 1]; ++k) {
      const Incidence& in = p_.ring[k];
      if(!state_.is_valid(in.cell)) continue;
      const Cofactor_and_determinant<n> cd(p_.map.target_edges(in.cell));
      const double sign = p_.map.rest_sign[in.cell];
      const double rate = sign * vertex_derivative(cd.cofactor, in.local).dot(d), volume = sign * cd.det;
      if(rate < 0) t_max = std::min(t_max, std::max(volume, 0.) / -rate);
    }
    return t_max;
  }

  double nearest_neighbour_distance(std::size_t v) const
  {
    double h2 = infinity;
    const Vec& y = p_.map.target[v];
    for(std::uint32_t k = p_.ring_begin[v]; k < p_.ring_begin[v + 1]; ++k)
      for(auto u : p_.map.cells[p_.ring[k].cell])
        if(u != v) h2 = std::min(h2, (p_.map.target[u] - y).squaredNorm());
    return std::sqrt(h2);
  }

  // Backtracking from t along d (slope = g.d < 0) until the ring energy decreases enough and no
  // positive cell flips (exact predicate). On success v stays at the new position, t is the step.
  bool line_search(std::size_t v, double e0, const Vec& d, double slope, double& t)
  {
    Vec& x = state_.targets()[v];
    const Vec x0 = x;
    const bool sliding = p_.slides(v);
    Vec normal;
    const std::uint32_t begin = p_.ring_begin[v], end = p_.ring_begin[v + 1];
    const auto ring_cell = [&](std::size_t i) { return p_.ring[begin + i].cell; };
    // A free boundary vertex under the guard also keeps the boundary free of self-intersections.
    auto* guard = state_.boundary_guard();
    const bool guarded = guard && guard->is_on_boundary(v);
    const auto boundary_ok = [&] { return !guarded || guard->accepts_move(v, state_.targets()); };
    for(int k = 0; k < max_backtracks && t > 0; ++k, t *= 0.5) {
      x = x0 + t * d;
      if(sliding) x = p_.slide(v, x, normal);
      if(x == x0) break;   // the step no longer changes the position
      if(state_.accept_trial(end - begin, ring_cell, e0, State::armijo * t * slope, false, boundary_ok)) {
        if(guarded) guard->commit_move(v, state_.targets());
        return true;
      }
    }
    x = x0;
    return false;
  }

  State& state_;
  const Optimization_problem<n>& p_;
  Local_solver solver_;
  std::vector<double> last_step_;   // last accepted step parameter of each vertex
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LOCAL_STEP_H
