// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The local problem (26) for one vertex v: minimize the energy of its ring of cells over the
// position y of v, never leaving the kernel of the ring.
//
// Each incident cell's signed volume is affine in y, so along a direction d the largest step
// before some cell degenerates is exact: t_max = min over shrinking cells of vol / (-dvol/dt).
// Trial steps stay below 0.9 t_max and backtrack (Armijo); an accepted position is checked with
// CGAL's exact orientation predicate, so no cell that was positive is ever flipped or flattened.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LOCAL_STEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LOCAL_STEP_H

#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/cofactor.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n, class Measure>
class Local_step
{
  Optimization_problem<n>& p_;
  const Measure& measure_;
  Local_solver solver_;

public:
  using Vec = Vector<n>;
  static constexpr double armijo = 1e-4;
  static constexpr double safety = 0.5;   // fraction of the exact largest step tried first (0.9 backtracks more)
  static constexpr int max_backtracks = 40;
  static constexpr double rounding = 64 * std::numeric_limits<double>::epsilon();

  // The start's cell values and orientations are computed on the given workers.
  Local_step(Optimization_problem<n>& problem, const Measure& measure, Local_solver solver, const Workers& workers)
    : p_(problem), measure_(measure), solver_(solver),
      cell_value(problem.map.number_of_cells()), cell_ok(problem.map.number_of_cells()),
      last_step_(problem.number_of_vertices(), 0.)
  {
    workers.for_each_block(cell_value.size(), 1024, [&](std::size_t first, std::size_t size) {
      cell_distortions<n>(measure_, p_.map, size, [&](std::size_t i) { return first + i; }, &cell_value[first]);
      for(std::size_t c = first; c < first + size; ++c) cell_ok[c] = !is_inverted(p_.map, c);
    });
  }

  // D(J_c) of the current map, and whether cell c has the orientation of its source (exact).
  std::vector<double> cell_value;
  std::vector<unsigned char> cell_ok;

  const Optimization_problem<n>& problem() const { return p_; }

  // Global injectivity with free boundary vertices (none by default). The guard must have been
  // built for the current map; vertices on its boundary must then be optimized one at a time.
  void set_boundary_guard(Boundary_guard<n>* guard) { guard_ = guard; }
  Boundary_guard<n>* boundary_guard() const { return guard_; }

  // E = sum_c w(c) D(J_c) (eq. 25), summed with Neumaier's compensation so that its rounding error
  // stays near one ulp whatever the number of cells (sweep-to-sweep decreases can be that small).
  double energy() const
  {
    double sum = 0, compensation = 0;
    for(std::size_t c = 0; c < cell_value.size(); ++c) {
      const double term = p_.cell_weight[c] * cell_value[c], t = sum + term;
      compensation += std::abs(sum) >= std::abs(term) ? (sum - t) + term : (term - t) + sum;
      sum = t;
    }
    return sum + compensation;
  }

  // omega(v) dist_w(f, v) (eq. 22): the greedy order's key.
  double vertex_distortion(std::size_t v) const
  {
    double d = 0;
    for(std::uint32_t k = p_.ring_begin[v]; k < p_.ring_begin[v + 1]; ++k) {
      const std::uint32_t c = p_.ring[k].cell;
      d += p_.incidence_weight[c] * cell_value[c];
    }
    return p_.omega[v] * d;
  }

  // Solves (26) approximately for v; returns true if v moved.
  bool optimize(std::size_t v)
  {
    Vec g;
    double e = ring_gradient(v, g);
    const double g2 = g.squaredNorm();
    if(!(g2 > 0) || !std::isfinite(g2)) return false;

    // First trial step: twice the last accepted one, or half the distance to the nearest ring
    // neighbour for a first visit (the paper leaves this open; it decides most of the cost).
    double t0 = last_step_[v] > 0 ? 2 * last_step_[v] : 0.5 * nearest_neighbour_distance(v) / std::sqrt(g2);
    if(solver_ == Local_solver::GRADIENT_DESCENT) {
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

  // The trial half of every line search, local or global: the targets of cells cell_at(0),
  // ..., cell_at(count - 1) have just moved, the energy was e0. Accepts, and commits their
  // values, if the energy becomes at most e0 + bound (Armijo) by a decrease above the rounding
  // error of e0 (so that accepted moves really decrease the energy) and no positive cell flipped
  // or flattened (exact predicate). A local trial (workers == nullptr) may run concurrently with
  // others on disjoint rings; a global one spreads its cells over the workers.
  // A last check, e.g. the boundary guard's, runs before the commit.
  template <class CellAt, class Check = bool (*)()>
  bool accept_trial(std::size_t count, const CellAt& cell_at, double e0, double bound, const Workers* workers = nullptr,
                    const Check& check = [] { return true; })
  {
    static thread_local std::vector<double> ring_trial;
    std::vector<double>& trial = workers ? global_trial_ : ring_trial;
    trial.resize(count);
    if(workers)
      workers->for_each_block(count, 512, [&](std::size_t first, std::size_t size) {
        cell_distortions<n>(measure_, p_.map, size, [&](std::size_t i) { return cell_at(first + i); }, &trial[first]);
      });
    else
      cell_distortions<n>(measure_, p_.map, count, cell_at, trial.data());
    const auto value = [&](std::size_t i) {
      const std::uint32_t c = cell_at(i);
      return p_.cell_weight[c] * (trial[i] - cell_value[c]);
    };
    const auto flipped = [&](std::size_t i) { return cell_ok[cell_at(i)] && is_inverted(p_.map, cell_at(i)); };
    const auto commit = [&](std::size_t i) {
      const std::uint32_t c = cell_at(i);
      cell_value[c] = trial[i];
      if(!cell_ok[c]) cell_ok[c] = !is_inverted(p_.map, c);
    };
    double e = e0;
    if(workers) e += workers->sum(count, value);
    else for(std::size_t i = 0; i < count; ++i) e += value(i);
    if(!(e <= e0 + bound) || !(e0 - e > rounding * std::abs(e0))) return false;
    bool any_flipped = false;
    if(workers) any_flipped = workers->reduce(count, false, flipped, [](bool a, bool b) { return a || b; });
    else for(std::size_t i = 0; i < count && !any_flipped; ++i) any_flipped = flipped(i);
    if(any_flipped || !check()) return false;
    if(workers) workers->for_each(count, 1024, commit);
    else for(std::size_t i = 0; i < count; ++i) commit(i);
    return true;
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
    cell_distortions<n>(measure_, p_.map, count, [&](std::size_t i) { return p_.ring[begin + i].cell; }, value.data(), gradient.data());
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

  // Exact largest t such that no positive cell of the ring degenerates at y + t d.
  double max_step(std::size_t v, const Vec& d) const
  {
    double t_max = std::numeric_limits<double>::infinity();
    for(std::uint32_t k = p_.ring_begin[v]; k < p_.ring_begin[v + 1]; ++k) {
      const Incidence& in = p_.ring[k];
      if(!cell_ok[in.cell]) continue;
      const Cofactor_and_determinant<n> cd(p_.map.target_edges(in.cell));
      const Vec dvolume = in.local == 0 ? Vec(-cd.cofactor.rowwise().sum()) : Vec(cd.cofactor.col(in.local - 1));
      const double sign = p_.map.rest_sign[in.cell];
      const double rate = sign * dvolume.dot(d), volume = sign * cd.det;
      if(rate < 0) t_max = std::min(t_max, std::max(volume, 0.) / -rate);
    }
    return t_max;
  }

  double nearest_neighbour_distance(std::size_t v) const
  {
    double h2 = std::numeric_limits<double>::infinity();
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
    Vec& x = p_.map.target[v];
    const Vec x0 = x;
    const std::uint32_t begin = p_.ring_begin[v], end = p_.ring_begin[v + 1];
    const auto ring_cell = [&](std::size_t i) { return p_.ring[begin + i].cell; };
    // A free boundary vertex under the guard also keeps the boundary free of self-intersections.
    const bool guarded = guard_ && guard_->is_on_boundary(v);
    const auto boundary_ok = [&] { return !guarded || guard_->accepts_move(v, p_.map.target); };
    for(int k = 0; k < max_backtracks && t > 0; ++k, t *= 0.5) {
      x = x0 + t * d;
      if(x == x0) break;   // the step no longer changes the position
      if(accept_trial(end - begin, ring_cell, e0, armijo * t * slope, nullptr, boundary_ok)) {
        if(guarded) guard_->commit_move(v, p_.map.target);
        return true;
      }
    }
    x = x0;
    return false;
  }

  Boundary_guard<n>* guard_ = nullptr;
  std::vector<double> last_step_;   // last accepted step parameter of each vertex
  std::vector<double> global_trial_;   // cell values at a trial position of a global step
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LOCAL_STEP_H
