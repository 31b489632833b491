// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Beyond the paper: steps that move all free vertices at once, alternated with the local sweeps
// (which carry information across a mesh only one ring per sweep).
//  - The harmonic start: the Dirichlet minimizer for the fixed vertices, taken if it is valid and
//    better, else approached by a line search within the exact largest safe step.
//  - The global step d = -P^-1 g, with P the volume-weighted cotangent Laplacian of the source
//    reweighted per cell by a factor of the cell's smallest singular value (the measure's
//    `laplacian_weight`, in the spirit of the reweighted proxies of SLIM, Rabinovich et al. 2017),
//    solved by warm-started Jacobi-preconditioned CG to a loose tolerance. The step is capped at
//    0.9 times the exact largest step before a cell degenerates (per cell, det(Ds + t dDs) is a
//    quadratic in 2D, a cubic in 3D: its smallest positive root), then backtracks (Armijo), and is
//    accepted only if CGAL's exact orientation predicate sees no flipped cell.
//  - Or, with Global_solver::PROJECTED_NEWTON and a measure that has a Hessian in its singular
//    values, the Newton direction d = -H^-1 g with H the sum of the cells' Hessians projected to be
//    positive semi-definite (cell_hessian.h). On triangle meshes: a few conjugate gradient
//    iterations preconditioned by the last factorization of H, or a new sparse LDL^T
//    factorization (ordering computed once) when they do not converge; on tetrahedral meshes,
//    whose factorizations fill in too much, truncated Newton (conjugate gradients preconditioned
//    by Jacobi's diagonal or, for a smooth model's steps, the Laplacian's, cut short). The step
//    is bounded and searched as the Laplacian's, and gives way to it when it cannot be taken.
//  Where the Newton steps are a smooth model's and some vertices slide, the right-hand side is
//  the measure's gradient (the model's Hessian as a proxy metric, assembled every third step,
//  see Newton_model).
//  Sliding vertices (named parameter sliding_boundary) take the step's part in their tangent
//  planes (Newton's: the step restricted to them; the Laplacian's: the solve for the gradient's
//  part in them) and are projected back onto their surface at every trial; the harmonic start
//  keeps them where they are.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/cell_hessian.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/newton_model.h>
#include <CGAL/Distortion_optimization/internal/sparse_cholesky.h>
#include <CGAL/Distortion_optimization/internal/step_bound.h>

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

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

template <class State>
class Global_step
{
  static constexpr int n = State::dimension;
  using Vec = Vector<n>;

public:
  // With `newton`, steps take the projected Newton direction where the measure has a Hessian (the
  // reweighted Laplacian's otherwise, and where a Newton solve fails).
  Global_step(State& state, bool newton)
    : state_(state), p_(state.problem()), system_(state.problem(), state.workers()),
      previous_solution_(Eigen::MatrixXd::Zero(system_.size(), n)),
      slides_(std::any_of(p_.is_sliding.begin(), p_.is_sliding.end(), [](unsigned char s) { return s != 0; })),
      model_(Newton_model<Measure>::of(state.measure())),
      newton_(newton && measures_internal::has_hessian<n>(model()) && (!model_ || every_vertex_moves())),
      proxy_(newton_ && model_ && slides_) {}

  // Whether the steps solve Newton's system (else the reweighted Laplacian's), and whether it is a
  // smooth model's rather than the measure's.
  bool is_newton() const { return newton_; }
  bool takes_model_steps() const { return newton_ && model_; }
  // Whether those are a model's whose minimizers are not the measure's (some vertex slides): its
  // Hessian is then the metric of the measure's gradient.
  bool model_misses_minimizers() const { return proxy_; }

  // The harmonic start (see the file comment), with the cell weights w(c) (for the default
  // weights, the volume-weighted cotangent Laplacian). Skipped where the harmonic map is not
  // defined (Laplacian_system::harmonic_targets). Returns true if the map changed.
  bool harmonic_start()
  {
    if(system_.size() == 0) return false;
    std::vector<Vec> direction;
    if(p_.is_sliding.empty()) {
      if(!system_.harmonic_targets(state_.targets(), direction)) return false;
    } else {
      std::vector<unsigned char> interior(p_.number_of_vertices());
      for(std::size_t v = 0; v < interior.size(); ++v) interior[v] = p_.is_free[v] && !p_.slides(v);
      Laplacian_system<n> system(p_, state_.workers(), &interior);
      if(!system.harmonic_targets(state_.targets(), direction)) return false;
    }
    for(std::size_t v = 0; v < direction.size(); ++v) direction[v] -= state_.targets()[v];
    if(std::all_of(direction.begin(), direction.end(), [](const Vec& d) { return d == Vec::Zero(); })) return false;   // already harmonic
    // The full step when it is safe; otherwise the largest safe fraction of it, halved until the
    // energy drops, three times at most: a smaller fraction is no longer a start, and where the
    // start is already better the 30 trials of a full line search are a costly share of the run.
    const double t_max = max_step(direction, 1 / 0.9);
    double t = t_max > 1 ? 1. : 0.9 * t_max;
    return line_search(direction, t, 0., [] { return 0.; }, 0., 4);
  }

  // One preconditioned global step. Returns true if the map changed. A Newton step that cannot be
  // taken (no descent, or no acceptable length) gives way to the Laplacian's in the same call.
  bool step()
  {
    if(system_.size() == 0) return false;
    blocked_ = newton_;
    // Where a model's step finds no decrease, the next 1, 2, 4, ... steps are the Laplacian's.
    const bool newton = newton_ && (!model_ || model_steps_.tries());
    if(newton && step_along(true)) {
      model_steps_.succeeded();
      return true;
    }
    if(newton && model_) {
      model_steps_.failed();
      metric_steps_ = 0;
    }
    // The Laplacian's steps of a measure with kinks may find no decrease for the rest of a run,
    // each costing a third of an iteration: after failures, the next 1, 2, 4, ... are skipped.
    if(!newton_ && !laplacian_steps_.tries()) return false;
    const bool moved = step_along(false);
    if(!newton_) moved ? laplacian_steps_.succeeded() : laplacian_steps_.failed();
    return moved;
  }

  // Whether the last step was to be Newton's and did not take its full length: a cell about to
  // flatten, the boundary guard or the line search cut it short (or it gave way to the Laplacian's).
  bool was_blocked() const { return blocked_; }

private:
  using Measure = std::decay_t<decltype(std::declval<const State&>().measure())>;
  using Model = typename Newton_model<Measure>::type;
  // Whether no vertex is fixed (some may slide), on a tetrahedral mesh.
  bool every_vertex_moves() const
  {
    if(n != 3) return false;
    for(std::size_t v = 0; v < p_.number_of_vertices(); ++v)
      if(!p_.is_free[v]) return false;
    return true;
  }
  // The measure whose Newton steps are taken: a smooth model's (model_), or the measure's own.
  const Model& model() const
  {
    if constexpr(std::is_same<Model, Measure>::value) return model_ ? *model_ : state_.measure();
    else return *model_;
  }

  bool step_along(bool newton)
  {
    const int size = system_.size();
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(size, n), x;
    // The unit normals of the sliding vertices' surfaces where they are (empty without sliding).
    std::vector<Vec> normal(p_.is_sliding.empty() ? 0 : p_.number_of_vertices());
    state_.workers().for_each(normal.size(), 1024, [&](std::size_t v) {
      if(p_.slides(v)) p_.slide(v, state_.targets()[v], normal[v]);
    });
    if(newton) {
      if(!newton_direction(normal, g, x)) return false;
    } else {
      system_.refill([&](const std::uint32_t* cells, std::size_t count, double* factor, std::array<Vec, n + 1>* gradient) {
        cell_terms(cells, count, factor, gradient);
      }, &g, nullptr);
      project_on_tangent_planes(normal, g);
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
    }
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
    if(!p_.is_sliding.empty()) {
      // In the tangent planes the step may no longer descend: then the sliding vertices stay.
      state_.workers().for_each(direction.size(), 1024, [&](std::size_t v) {
        if(p_.slides(v)) direction[v] -= direction[v].dot(normal[v]) * normal[v];
      });
      slope = slope_of();
      if(!(slope < 0)) {
        for(std::size_t v = 0; v < direction.size(); ++v)
          if(p_.slides(v)) direction[v].setZero();
        slope = slope_of();
      }
    }
    // P is positive definite (semi-definite with nothing fixed, g then in its range), so only a
    // failed solve gets here.
    if(!(slope < 0)) return false;
    // The Laplacian's step has no natural length, nor has a proxy's (the model's Newton length is
    // not the measure's): twice the last accepted one. Newton's is 1, but far from the minimum
    // barrier-like terms (s^-2) make it short: 2, up to 8 after long steps, then 1 if that fails.
    double& last = newton ? last_newton_t_ : last_t_;
    const bool natural = newton && !proxy_;
    const double cap = !(last > 0) ? 1. : natural ? std::clamp(2 * last, 2., 8.) : 2 * last;
    double t = std::min(cap, 0.9 * max_step(direction, cap / 0.9));
    // A model's slope is not the measure's: then any decrease is taken, within 8 trials (a
    // model's step shorter than that is not worth the trials: the Laplacian's follows). A
    // proxy's step has the measure's slope.
    const bool model = newton && model_ && !proxy_;
    const bool moved = line_search(direction, t, model ? 0. : slope, slope_of, natural ? 1. : 0., model ? 8 : 30);
    if(moved) last = t;
    if(newton) blocked_ = !(moved && t >= 1);
    return moved;
  }

  // The projected Newton direction x = -H^-1 g (rows: free vertices) and the gradient g, in the
  // tangent planes of the sliding vertices (`normal`); false where some moving cell has no finite
  // gradient or the factorization fails. A proxy's H may be up to two steps old, restricted to
  // the tangent planes of then: still positive definite, so x descends (step_along projects it).
  bool newton_direction(const std::vector<Vec>& normal, Eigen::MatrixXd& g, Eigen::MatrixXd& x)
  {
    if constexpr(!measures_internal::Has_hessian<Model, n>::value) {
      return false;
    } else {
      std::atomic<bool> finite(true);
      // A proxy's right-hand side: the measure's own gradient.
      const auto measure_gradients = [&](const std::uint32_t* cells, std::size_t count, std::array<Vec, n + 1>* gradient) {
        static thread_local std::vector<double> value;
        value.resize(count);
        cell_distortions<n>(state_.measure(), p_.map, count, [&](std::size_t i) { return cells[i]; }, value.data(), gradient);
        for(std::size_t i = 0; i < count; ++i)
          for(const Vec& v : gradient[i])
            if(!v.allFinite()) finite = false;
      };
      // A proxy's metric changes slowly from step to step, and the measure's kinks, not the
      // metric, hold its steps short: its assembly (two thirds of a step) is renewed every
      // proxy_metric_steps steps, and after a failed one (newton_model.h).
      if(proxy_ && metric_steps_ > 0 && metric_steps_ < proxy_metric_steps) {
        ++metric_steps_;
        system_.refill_gradient(measure_gradients, g);
        if(!finite) return false;
        project_on_tangent_planes(normal, g);
        return solve_newton_system(g, x);
      }
      metric_steps_ = 1;
      system_.refill_hessian([&](const std::uint32_t* cells, std::size_t count, Cell_hessian<n>* H,
                                 std::array<Vec, n + 1>* gradient) {
        static thread_local std::vector<std::array<Vec, n + 1>> own_gradient;
        if(proxy_) {
          own_gradient.resize(count);
          measure_gradients(cells, count, own_gradient.data());
        }
        for(std::size_t i = 0; i < count; ++i) {
          const std::uint32_t c = cells[i];
          if(!cell_hessian<n>(model(), p_.map.jacobian(c), p_.map.inverse_rest[c], H[i], gradient[i])) {
            // An inverted or flat cell (where a measure that is not normalized is finite): the
            // kernel's gradient (a proxy's is the measure's, below), and the Laplacian's stiffness
            // in each coordinate.
            if(!proxy_) {
              double value;
              cell_distortions<n>(model(), p_.map, 1, [c](std::size_t) { return c; }, &value, &gradient[i]);
              for(const Vec& v : gradient[i])
                if(!v.allFinite()) finite = false;
            }
            const Eigen::Matrix<double, n, n + 1> G = p_.map.hat_gradients(c);
            const Matrix<n + 1> stiffness = G.transpose() * G;
            H[i].setZero();
            for(int a = 0; a <= n; ++a)
              for(int b = 0; b <= n; ++b) H[i].template block<n, n>(n * a, n * b).diagonal().setConstant(stiffness(a, b));
          }
          if(proxy_) gradient[i] = own_gradient[i];
          if(!normal.empty()) restrict_to_tangent_planes(p_.map.cells[c], normal, H[i], gradient[i]);
        }
      }, &g);
      if(!finite) return false;
      return solve_newton_system(g, x);
    }
  }

  // x = -H^-1 g with the last assembled H (see newton_direction); false if the solve fails.
  bool solve_newton_system(const Eigen::MatrixXd& g, Eigen::MatrixXd& x)
  {
    const Eigen::SparseMatrix<double>& H = system_.hessian();
    Eigen::MatrixXd b(H.rows(), 1), solution = Eigen::MatrixXd::Zero(H.rows(), 1);
    for(int j = 0; j < g.rows(); ++j) b.col(0).template segment<n>(n * j) = -g.row(j).transpose();
    if constexpr(n == 3) {
      // A tetrahedral mesh's Newton system fills in far too much for a factorization at every step:
      // truncated Newton (Nash, "Newton-type minimization via the Lanczos method", 1984),
      // preconditioned conjugate gradients from 0, cut at 60 iterations (more where they fall
      // short, below) or a residual of 1e-2; every iterate from 0 descends. Jacobi's
      // preconditioner, except that a model's steps (nothing fixed) take the Laplacian's for the
      // rest of the run once a Jacobi solve did not converge: MIPS's Hessian is nearly singular in
      // each cell's scaling, where the Laplacian's preconditioner converges in far fewer
      // iterations. Where cells' stiffnesses differ by orders of magnitude (after untangling), the
      // Laplacian's is the worse of the two: the measures' own steps keep Jacobi's. So do a model's
      // with sliding vertices, whose tangent planes the coordinatewise Laplacian does not see.
      if(!laplacian_preconditioner_) {
        Eigen::DiagonalPreconditioner<double> jacobi;
        jacobi.compute(H);
        typename Laplacian_system<n>::Solve_outcome outcome;
        const bool solved = system_.solve(H, jacobi, b, solution, jacobi_iterations_, 1e-2, &outcome);
        if(takes_model_steps() && !slides_) {
          if(!solved) {
            laplacian_preconditioner_ = std::make_unique<typename Laplacian_system<n>::Coordinatewise_laplacian>(system_);
            if(!laplacian_preconditioner_->ok()) laplacian_preconditioner_.reset();
          }
        } else {   // a measure's own steps, or a proxy's
          // A direction cut short while its residual is still above half the gradient's is
          // hardly Newton's (inexact Newton methods need it below: Dembo, Eisenstat and
          // Steihaug, "Inexact Newton methods", 1982): the next solves may take twice the
          // iterations, and give them back once the residual is below a tenth. Where cells'
          // stiffnesses differ by orders of magnitude (a start untangled in the large), 60
          // iterations may not even lower it, and a run with a fixed count stalls far above the
          // minimum. A proxy's direction (the measure's gradient in the model's metric) needs
          // them as much, though its solves stay above a half.
          if(outcome.iterations >= jacobi_iterations_ && outcome.residual > 0.5)
            jacobi_iterations_ = std::min(2 * jacobi_iterations_, 16 * newton_iterations);
          else if(outcome.residual < 0.1)
            jacobi_iterations_ = std::max(jacobi_iterations_ / 2, newton_iterations);
        }
      } else {
        system_.solve(H, *laplacian_preconditioner_, b, solution, newton_iterations, 1e-2);
      }
    } else {
      solve_by_factorization(H, b, solution);
    }
    if(!solution.allFinite()) return false;
    x.resize(g.rows(), n);
    for(int j = 0; j < g.rows(); ++j) x.row(j) = solution.col(0).template segment<n>(n * j).transpose();
    return true;
  }

  // The direction of a Newton step on a triangle mesh, x = H^-1 b (NaN where the factorization
  // fails). Inexact: conjugate gradients on H preconditioned by the factorization of an earlier H,
  // to a loose residual; H is factored again when they need many iterations. Far from the minimum
  // H changes much from step to step: after a failed attempt, the next 1, 2, 4, ... steps factor
  // at once.
  void solve_by_factorization(const Eigen::SparseMatrix<double>& H, const Eigen::MatrixXd& b, Eigen::MatrixXd& solution)
  {
    bool solved = false;
    if(lagged_.tries() && factorization_.is_factored()) {
      solved = system_.solve(H, factorization_, b, solution, 6, 1e-3) && solution.allFinite();
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

  // Each sliding vertex's row of g in its tangent plane. Its part along the normal is a force the
  // surface holds: solved for, it would spread through the interior and the step would no longer
  // descend.
  void project_on_tangent_planes(const std::vector<Vec>& normal, Eigen::MatrixXd& g) const
  {
    for(std::size_t v = 0; v < normal.size(); ++v)
      if(p_.slides(v) && system_.column(v) >= 0) {
        auto row = g.row(system_.column(v));
        row -= row.dot(normal[v].transpose()) * normal[v].transpose();
      }
  }

  // A cell's Hessian and gradient for Newton's step with its sliding vertices in their tangent
  // planes: with P_v = I - n_v n_v^T (P_v = I for the others), P H P and P g, plus a stiffness
  // along each sliding vertex's normal (the mean of its diagonal block's, for the scale). The
  // normal components then decouple from the rest, with a zero right-hand side, so the direction
  // is exactly Newton's restricted to the tangent planes, on the same sparsity pattern.
  void restrict_to_tangent_planes(const typename Simplicial_map<n>::Cell& cell, const std::vector<Vec>& normal,
                                  Cell_hessian<n>& H, std::array<Vec, n + 1>& gradient) const
  {
    for(int a = 0; a <= n; ++a) {
      if(!p_.slides(cell[a])) continue;
      const Vec& u = normal[cell[a]];
      const Matrix<n> P = Matrix<n>::Identity() - u * u.transpose();
      const double stiffness = H.template block<n, n>(n * a, n * a).trace() / n;
      H.template middleRows<n>(n * a) = P * H.template middleRows<n>(n * a);
      H.template middleCols<n>(n * a) = H.template middleCols<n>(n * a) * P;
      H.template block<n, n>(n * a, n * a) += stiffness * u * u.transpose();
      gradient[a] = P * gradient[a];
    }
  }

  // For the Laplacian's refill: each cell's energy gradient and its measure's laplacian_weight.
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

  // The exact largest t <= bound such that no valid cell degenerates at X + t D (step_bound.h).
  double max_step(const std::vector<Vec>& direction, double bound) const
  {
    return largest_safe_step(state_, system_.moving_cells(), direction, bound);
  }

  // Backtracks from t along D until the energy decreases (Armijo with the given slope, or any
  // decrease above rounding if slope is 0) with no valid cell flipped; then commits. After a
  // first failure above `natural` (> 0), the next trial is `natural` rather than t / 2.
  // A trial whose boundary the guard finds crossing itself (not only a piece inside another) holds
  // the vertices of the crossing faces where they are (their direction zeroed; slope_of() then
  // gives the slope left) and tries the same length again, up to max_holds times: near a fold of
  // the boundary that moves closed to within rounding, every step of those few vertices crosses,
  // and halving the whole step for them would stall the rest of the map.
  template <class SlopeOf>
  bool line_search(std::vector<Vec>& direction, double& t, double slope, const SlopeOf& slope_of, double natural = 0,
                   int trials = 30)
  {
    std::vector<Vec>& x = state_.targets();
    const std::vector<Vec> x0 = x;
    const double e0 = state_.energy();
    const std::vector<std::uint32_t>& moving = system_.moving_cells();
    const auto moving_cell = [&](std::size_t i) { return moving[i]; };
    auto* guard = state_.boundary_guard();
    std::vector<std::uint32_t> crossing;
    bool nested = false;
    const auto boundary_ok = [&] {
      return !guard || guard->is_injective(x, &crossing, guard->clearance_fraction(), &nested);
    };
    const auto place = [&](double length) {
      state_.workers().for_each(x.size(), 4096, [&](std::size_t v) {
        if(!p_.is_free[v]) return;
        x[v] = x0[v] + length * direction[v];
        Vec normal;
        if(p_.slides(v) && direction[v] != Vec::Zero()) x[v] = p_.slide(v, x[v], normal);
      });
    };
    for(int k = 0, holds = 0; k < trials && t > 0;) {
      place(t);
      crossing.clear();
      if(state_.accept_trial(moving.size(), moving_cell, e0, State::armijo * t * slope, true, boundary_ok)) {
        // On tetrahedra a trial beyond the natural length can pass with little gain: twice a
        // Newton step of K's model lands across K's kink about as far as it started, and of a
        // measure's own convex part back where it started. The natural length is tried too; the
        // lower is kept, which saves iterations. Triangle meshes keep the longer step (their
        // Newton directions come from a factorization, nearly exact: the second trial costs more
        // than it gains).
        if(n == 3 && natural > 0 && t > natural) {
          place(natural);
          if(state_.accept_trial(moving.size(), moving_cell, state_.energy(), 0., true, boundary_ok)) t = natural;
          else place(t);   // the same bits as the committed trial
        }
        // The committed trial passed boundary_ok(): with the whole clearance, if the guard asked it.
        if(guard) guard->rebuild(x, guard->clearance_fraction() == 1);
        return true;
      }
      if(!crossing.empty() && !nested && holds < max_holds) {
        ++holds;
        for(std::uint32_t v : crossing) direction[v] = Vec::Zero();
        if(slope != 0 && !((slope = slope_of()) < 0)) break;
        continue;
      }
      ++k;
      t = k == 1 && natural > 0 && t > natural ? natural : 0.5 * t;
    }
    x = x0;
    return false;
  }
  static constexpr int max_holds = 8;

  State& state_;
  const Optimization_problem<n>& p_;
  Laplacian_system<n> system_;
  Eigen::MatrixXd previous_solution_;
  double last_t_ = 0, last_newton_t_ = 0;   // the last accepted step of each direction
  bool slides_;   // whether some vertex slides on a surface
  std::optional<Model> model_;   // the smooth model whose Newton steps the measure takes; empty: its own
  bool newton_, proxy_, blocked_ = false;   // proxy_: the model's Hessian, the measure's gradient
  // The steps a proxy's assembled Hessian served (0: none to serve), and how many it serves.
  int metric_steps_ = 0;
  static constexpr int proxy_metric_steps = 3;
  // The iterations of a tetrahedral Newton solve, and of the next Jacobi-preconditioned one
  // (see solve_newton_system).
  static constexpr int newton_iterations = 60;
  int jacobi_iterations_ = newton_iterations;
  Sparse_cholesky<n> factorization_;
  std::unique_ptr<typename Laplacian_system<n>::Coordinatewise_laplacian> laplacian_preconditioner_;
  // The lagged factorization's solves, a model's steps, a measure's own Laplacian steps.
  Backoff lagged_, model_steps_, laplacian_steps_;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H
