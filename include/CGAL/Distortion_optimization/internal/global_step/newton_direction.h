// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The projected Newton direction d = -H^-1 g of a global step, for a measure that has a Hessian
// in its singular values: H is the sum of the cells' Hessians projected to be positive
// semi-definite (cell_hessian.h), or those of a smooth model that the measure takes the steps of
// (newton_model.h). On triangle meshes H is solved by a lagged factorization
// (lagged_factorization.h), on tetrahedral meshes by truncated Newton (truncated_newton.h).
// Where the steps are a smooth model's and some vertices slide, the right-hand side is the
// measure's gradient (the model's Hessian as a proxy metric, assembled every third step). The
// sliding vertices' steps are restricted to their tangent planes (tangent_planes.h).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_NEWTON_DIRECTION_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_NEWTON_DIRECTION_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/cell_hessian.h>
#include <CGAL/Distortion_optimization/internal/global_step/lagged_factorization.h>
#include <CGAL/Distortion_optimization/internal/global_step/tangent_planes.h>
#include <CGAL/Distortion_optimization/internal/global_step/truncated_newton.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/newton_model.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The projected Newton direction of the global steps, with the model or proxy it is taken from
// and the solver of its system (on triangle meshes a lagged factorization, on tetrahedral meshes
// truncated Newton).
template <class State>
class Newton_direction
{
public:
  static constexpr int n = State::dimension;

private:
  using Vec = Vector<n>;
  using Measure = std::decay_t<decltype(std::declval<const State&>().measure())>;
  using Model = typename Newton_model<Measure>::type;
  using Solver = std::conditional_t<n == 2, Lagged_factorization<n>, Truncated_newton<n>>;

public:
  // `system`: the global steps' (its unknowns the free vertices). `solver`: the user's choice;
  // PROJECTED_NEWTON takes Newton's direction wherever the measure, or its model, has a Hessian,
  // the default (unset) only where the model's or the measure's own steps lead (newton_model.h).
  // `iterations`: the most the run takes.
  Newton_direction(State& state, Laplacian_system<n>& system, std::optional<Global_solver> solver, std::size_t iterations)
    : state_(state), p_(state.problem()), system_(system),
      slides_(std::any_of(p_.is_sliding.begin(), p_.is_sliding.end(), [](unsigned char s) { return s != 0; })),
      model_(every_vertex_moves() ? Newton_model<Measure>::of(state.measure()) : std::nullopt),
      on_(solver != Global_solver::REWEIGHTED_LAPLACIAN &&
          (model_ ? measures_internal::has_hessian<n>(*model_)
                  : measures_internal::has_hessian<n>(state.measure()) &&
                      (solver || Newton_model<Measure>::own_steps_lead(state.measure())))),
      proxy_(on_ && model_ && slides_),
      solver_(make_solver(system, on_ && model_ && !slides_, iterations)) {}

  // Whether the global steps take it (else the reweighted Laplacian's), and whether it is a
  // smooth model's rather than the measure's.
  bool taken() const { return on_; }
  bool by_model() const { return on_ && model_; }
  // Whether it is a model's whose minimizers are not the measure's (some vertex slides): its
  // Hessian is then the metric of the measure's gradient.
  bool by_proxy() const { return proxy_; }

  // A proxy's next direction assembles its metric anew (after a step that found no decrease).
  void renew_metric() { metric_steps_ = 0; }

  // The direction x and the gradient g (zero on entry; rows: the system's unknowns), in the
  // tangent planes of the sliding vertices (`normal`); false where some moving cell has no finite
  // gradient or the solve fails. A proxy's H may be up to two steps old, restricted to the tangent
  // planes of then: still positive definite, so x descends (the global step projects it).
  bool operator()(const std::vector<Vec>& normal, Eigen::MatrixXd& g, Eigen::MatrixXd& x)
  {
    if constexpr(!measures_internal::Has_hessian<Model, n>::value && !measures_internal::Has_hessian<Measure, n>::value) {
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
        project_on_tangent_planes(p_, system_, normal, g);
        return solve(g, x);
      }
      metric_steps_ = 1;
      system_.refill_hessian([&](const std::uint32_t* cells, std::size_t count, Cell_hessian<n>* H,
                                 std::array<Vec, n + 1>* gradient) {
        static thread_local std::vector<std::array<Vec, n + 1>> own_gradient;
        if(proxy_) {
          own_gradient.resize(count);
          measure_gradients(cells, count, own_gradient.data());
        }
        with_steps_measure([&](const auto& model) {
          for(std::size_t i = 0; i < count; ++i) {
            const std::uint32_t c = cells[i];
            if(!cell_hessian<n>(model, p_.map.jacobian(c), p_.map.inverse_rest[c], H[i], gradient[i])) {
              // An inverted or flat cell (where a measure that is not normalized is finite): the
              // kernel's gradient (a proxy's is the measure's, below), and the Laplacian's stiffness
              // in each coordinate.
              if(!proxy_) {
                double value;
                cell_distortions<n>(model, p_.map, 1, [c](std::size_t) { return c; }, &value, &gradient[i]);
                for(const Vec& v : gradient[i])
                  if(!v.allFinite()) finite = false;
              }
              const Eigen::Matrix<double, n, n + 1> G = p_.map.hat_gradients(c);
              const Matrix<n + 1> stiffness = G.transpose() * G;
              H[i].setZero();
              for(int a = 0; a <= n; ++a)
                for(int b = 0; b <= n; ++b)
                  H[i].template block<n, n>(n * a, n * b).diagonal().setConstant(stiffness(a, b));
            }
            if(proxy_) gradient[i] = own_gradient[i];
            if(!normal.empty()) restrict_to_tangent_planes(p_, p_.map.cells[c], normal, H[i], gradient[i]);
          }
        });
      }, &g);
      if(!finite) return false;
      return solve(g, x);
    }
  }

private:
  static Solver make_solver(Laplacian_system<n>& system, bool may_take_laplacian, std::size_t iterations)
  {
    if constexpr(n == 2) return Solver(system, iterations);
    else return Solver(system, may_take_laplacian);
  }

  // Whether no vertex is fixed (some may slide), on a tetrahedral mesh: where a measure's smooth
  // model has the measure's minimizers or serves as its metric (newton_model.h).
  bool every_vertex_moves() const
  {
    if(n != 3) return false;
    for(std::size_t v = 0; v < p_.number_of_vertices(); ++v)
      if(!p_.is_free[v]) return false;
    return true;
  }

  // f(the measure whose Newton steps are taken): the smooth model (model_), or the measure itself.
  template <class F>
  void with_steps_measure(F f) const
  {
    if(model_) {
      if constexpr(measures_internal::Has_hessian<Model, n>::value) f(*model_);
    } else {
      if constexpr(measures_internal::Has_hessian<Measure, n>::value) f(state_.measure());
    }
  }

  // x = -H^-1 g with the last assembled H; false if the solve fails.
  bool solve(const Eigen::MatrixXd& g, Eigen::MatrixXd& x)
  {
    const Eigen::SparseMatrix<double>& H = system_.hessian();
    Eigen::MatrixXd b(H.rows(), 1), solution = Eigen::MatrixXd::Zero(H.rows(), 1);
    for(int j = 0; j < g.rows(); ++j) b.col(0).template segment<n>(n * j) = -g.row(j).transpose();
    solver_.solve(H, b, solution);
    if(!solution.allFinite()) return false;
    x.resize(g.rows(), n);
    for(int j = 0; j < g.rows(); ++j) x.row(j) = solution.col(0).template segment<n>(n * j).transpose();
    return true;
  }

  State& state_;
  const Optimization_problem<n>& p_;
  Laplacian_system<n>& system_;
  bool slides_;   // whether some vertex slides on a surface
  std::optional<Model> model_;   // the smooth model whose Newton steps the measure takes; empty: its own
  bool on_, proxy_;   // proxy_: the model's Hessian, the measure's gradient
  // The steps a proxy's assembled Hessian served (0: none to serve), and how many it serves.
  int metric_steps_ = 0;
  static constexpr int proxy_metric_steps = 3;
  Solver solver_;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_NEWTON_DIRECTION_H
