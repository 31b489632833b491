// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
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

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H

#include <CGAL/Distortion_optimization/internal/cofactor.h>
#include <CGAL/Distortion_optimization/internal/local_step.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The smallest root in (0, bound] of c0 + c1 t + c2 t^2 + c3 t^3 when c0 > 0 (bound if none): the
// first t at which a cell's signed volume reaches 0. Most cells are cleared at once by a lower
// bound of the polynomial on [0, bound]; roots are bracketed between the critical points and
// refined by bisection, which is robust to the cancellations of closed formulas.
inline double first_positive_root(double c0, double c1, double c2, double c3, double bound)
{
  if(c0 + std::min(c1, 0.) * bound + std::min(c2, 0.) * bound * bound + std::min(c3, 0.) * bound * bound * bound > 0)
    return bound;
  auto p = [&](double t) { return c0 + t * (c1 + t * (c2 + t * c3)); };
  // Critical points (roots of c1 + 2 c2 t + 3 c3 t^2), then the bound.
  std::array<double, 3> stops;
  std::size_t count = 0;
  const double a = 3 * c3, b = 2 * c2, c = c1;
  if(a != 0) {
    const double disc = b * b - 4 * a * c;
    if(disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if(q != 0) stops[count++] = c / q;
      stops[count++] = q / a;
    }
  } else if(b != 0) {
    stops[count++] = -c / b;
  }
  std::sort(stops.begin(), stops.begin() + count);
  stops[count++] = bound;
  double left = 0;
  for(std::size_t i = 0; i < count; ++i) {
    const double s = std::min(stops[i], bound);
    if(!(s > left)) continue;
    if(p(s) <= 0) {
      // Bisection to 1e-12 relative: callers take a fraction of the root anyway.
      double lo = left, hi = s;
      for(int k = 0; k < 100 && hi - lo > 1e-12 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (p(mid) > 0 ? lo : hi) = mid;
      }
      return lo;   // the side where the volume is still positive
    }
    left = s;
  }
  return bound;
}

template <int n, class Measure>
class Global_step
{
  using Vec = Vector<n>;

public:
  Global_step(Optimization_problem<n>& problem, const Measure& measure, Local_step<n, Measure>& local,
              const Workers& workers)
    : p_(problem), measure_(measure), local_(local), workers_(workers)
  {
    const std::size_t nv = p_.number_of_vertices();
    free_index_.assign(nv, -1);
    for(std::size_t v = 0; v < nv; ++v)
      if(p_.is_free[v]) free_index_[v] = free_count_++;
    for(std::size_t c = 0; c < p_.map.number_of_cells(); ++c) {
      bool moves = false;
      for(auto v : p_.map.cells[c]) moves = moves || p_.is_free[v];
      if(moves) moving_cells_.push_back(static_cast<std::uint32_t>(c));
    }
    build_pattern();
    previous_solution_ = Eigen::MatrixXd::Zero(free_count_, n);
  }

  // The harmonic start (see the file comment), solved on the global step's sparsity pattern with
  // the cell weights w(c) (for the default weights, the volume-weighted cotangent Laplacian).
  // Returns true if the map changed.
  bool harmonic_start()
  {
    // With nothing fixed the Dirichlet energy's minimizers are the constant maps: no start there.
    if(free_count_ == 0 || free_count_ == static_cast<int>(p_.number_of_vertices())) return false;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(free_count_, n), x(free_count_, n);
    refill(nullptr, &rhs);
    Eigen::IncompleteCholesky<double> preconditioner;
    preconditioner.compute(P_);
    if(preconditioner.info() != Eigen::Success) return false;
    std::vector<Vec> direction(p_.number_of_vertices(), Vec::Zero());
    for(std::size_t v = 0; v < direction.size(); ++v)
      if(free_index_[v] >= 0) x.row(free_index_[v]) = p_.map.target[v].transpose();
    solve(preconditioner, rhs, x, 2000, 1e-10);
    if(!x.allFinite()) return false;   // a free part with no fixed vertex: no harmonic map
    for(std::size_t v = 0; v < direction.size(); ++v)
      if(free_index_[v] >= 0) direction[v] = x.row(free_index_[v]).transpose() - p_.map.target[v];
    // The full step when it is safe; otherwise the largest safe fraction of it, halved until the
    // energy drops.
    const double t_max = max_step(direction, 1 / 0.9);
    double t = t_max > 1 ? 1. : 0.9 * t_max;
    return line_search(direction, t, 0.);
  }

  // One preconditioned global step. Returns true if the map changed.
  bool step()
  {
    if(free_count_ == 0) return false;
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(free_count_, n);
    refill(&g, nullptr);
    Eigen::DiagonalPreconditioner<double> preconditioner;
    preconditioner.compute(P_);
    Eigen::MatrixXd x = previous_solution_;
    solve(preconditioner, -g, x, 30, 1e-2);
    if(!x.allFinite()) return false;
    previous_solution_ = x;
    double slope = 0;
    for(int d = 0; d < n; ++d) slope += g.col(d).dot(x.col(d));
    // P is positive definite (semi-definite with nothing fixed, g then in its range), so only a
    // failed solve gets here.
    if(!(slope < 0)) return false;
    std::vector<Vec> direction(p_.number_of_vertices(), Vec::Zero());
    for(std::size_t v = 0; v < direction.size(); ++v)
      if(free_index_[v] >= 0) direction[v] = x.row(free_index_[v]).transpose();
    const double cap = last_t_ > 0 ? 2 * last_t_ : 1.;
    double t = std::min(cap, 0.9 * max_step(direction, cap / 0.9));
    const bool moved = line_search(direction, t, slope);
    if(moved) last_t_ = t;
    return moved;
  }

private:
  // The sparsity pattern of the free-free block of the Laplacian, and for each cell and pair of
  // its free vertices the slot of their entry, so that reweighting only rewrites values.
  void build_pattern()
  {
    // Column by column from the rings, straight into compressed storage (no triplet list: it
    // would be the peak of the whole run): the columns' sizes in parallel, their offsets, then
    // their rows in parallel, each column into its own segment.
    const std::vector<std::uint32_t> column_vertex = free_vertices(p_);   // free_index_'s inverse
    const auto free_neighbours = [&](std::size_t column) -> const std::vector<int>& {
      static thread_local std::vector<int> neighbours;
      neighbours.clear();
      const std::uint32_t a = column_vertex[column];
      for(std::uint32_t k = p_.ring_begin[a]; k < p_.ring_begin[a + 1]; ++k)
        for(auto b : p_.map.cells[p_.ring[k].cell])
          if(free_index_[b] >= 0) neighbours.push_back(free_index_[b]);
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      return neighbours;
    };
    std::vector<int> offset(free_count_ + 1, 0);
    workers_.for_each(free_count_, 1024, [&](std::size_t j) { offset[j + 1] = static_cast<int>(free_neighbours(j).size()); });
    for(int j = 0; j < free_count_; ++j) offset[j + 1] += offset[j];
    P_.resize(free_count_, free_count_);
    P_.resizeNonZeros(offset[free_count_]);
    std::copy(offset.begin(), offset.end(), P_.outerIndexPtr());
    std::fill(P_.valuePtr(), P_.valuePtr() + P_.nonZeros(), 0.);
    workers_.for_each(free_count_, 1024, [&](std::size_t j) {
      const std::vector<int>& rows = free_neighbours(j);
      std::copy(rows.begin(), rows.end(), P_.innerIndexPtr() + offset[j]);
    });
    // Where each entry of each cell's (n+1) x (n+1) stiffness goes in P (-1: a fixed vertex).
    constexpr std::size_t entries = (n + 1) * (n + 1);
    slots_.assign(moving_cells_.size() * entries, -1);
    workers_.for_each(moving_cells_.size(), 1024, [&](std::size_t i) {
      const auto& cell = p_.map.cells[moving_cells_[i]];
      int* slot = &slots_[i * entries];
      for(auto a : cell)
        for(auto b : cell) {
          if(free_index_[a] >= 0 && free_index_[b] >= 0) {
            const int* begin = P_.innerIndexPtr() + offset[free_index_[b]];
            const int* end = P_.innerIndexPtr() + offset[free_index_[b] + 1];
            *slot = static_cast<int>(std::lower_bound(begin, end, free_index_[a]) - P_.innerIndexPtr());
          }
          ++slot;
        }
    });
    // Each block's incidences of free vertices, by column of P and, within a column, in cell order:
    // what refill gathers.
    blocks_.assign((moving_cells_.size() + block - 1) / block, {});
    workers_.for_each(blocks_.size(), 1, [&](std::size_t b) {
      std::vector<std::uint64_t> keys;   // column in the high half, the incidence in the low one
      for(std::size_t i = b * block; i < std::min(moving_cells_.size(), (b + 1) * block); ++i)
        for(int a = 0; a <= n; ++a) {
          const int column = free_index_[p_.map.cells[moving_cells_[i]][a]];
          if(column >= 0) keys.push_back(std::uint64_t(column) << 32 | ((i - b * block) * (n + 1) + a));
        }
      std::sort(keys.begin(), keys.end());
      Block_incidences& incidences = blocks_[b];
      for(std::size_t k = 0; k < keys.size(); ++k) {
        if(k == 0 || keys[k] >> 32 != keys[k - 1] >> 32) {
          incidences.columns.push_back(static_cast<std::uint32_t>(keys[k] >> 32));
          incidences.begin.push_back(static_cast<std::uint32_t>(k));
        }
        incidences.entries.push_back(static_cast<std::uint32_t>(keys[k]));
      }
      incidences.begin.push_back(static_cast<std::uint32_t>(keys.size()));
    });
  }

  // Refills P with the cell stiffnesses w(c) G^T G, reweighted by the measure's laplacian_weight
  // for a global step (with the energy gradient accumulated into g), or not for the harmonic map
  // (with the fixed vertices' contribution accumulated into rhs). Block by block of cells, the
  // cells' parts are computed in parallel, then gathered in parallel by column: column j of P and
  // rows j of g and rhs take their contributions in cell order, so that every sum has the
  // sequential order whatever the number of threads.
  void refill(Eigen::MatrixXd* g, Eigen::MatrixXd* rhs)
  {
    std::fill(P_.valuePtr(), P_.valuePtr() + P_.nonZeros(), 0.);
    std::vector<Eigen::Matrix<double, n + 1, n + 1>> stiffness(std::min(block, moving_cells_.size()));
    std::vector<std::array<Vec, n + 1>> gradient(g ? stiffness.size() : 0);
    constexpr bool reweighted = measures_internal::Has_laplacian_weight<Measure, n>::value;
    std::vector<Vec> sigma(g && reweighted ? stiffness.size() : 0);
    std::vector<double> value(g ? stiffness.size() : 0);
    for(std::size_t first = 0; first < moving_cells_.size(); first += block) {
      const std::size_t count = std::min(block, moving_cells_.size() - first);
      workers_.for_each_block(count, 256, [&](std::size_t begin, std::size_t size) {
        if(g)
          cell_distortions<n>(measure_, p_.map, size, [&](std::size_t i) { return moving_cells_[first + begin + i]; },
                              &value[begin], &gradient[begin], reweighted ? &sigma[begin] : nullptr);
        for(std::size_t i = begin; i < begin + size; ++i) {
          const std::uint32_t c = moving_cells_[first + i];
          const double w = p_.cell_weight[c];
          double factor = 1;
          if constexpr(reweighted) if(g) factor = measures_internal::laplacian_weight<n>(measure_, sigma[i]);
          const Eigen::Matrix<double, n, n + 1> G = p_.map.hat_gradients(c);
          stiffness[i] = (w * factor) * (G.transpose() * G);
          if(g)
            for(Vec& x : gradient[i]) x = w * x;
        }
      });
      const Block_incidences& incidences = blocks_[first / block];
      workers_.for_each(incidences.columns.size(), 64, [&](std::size_t t) {
        const std::uint32_t j = incidences.columns[t];
        for(std::uint32_t k = incidences.begin[t]; k < incidences.begin[t + 1]; ++k) {
          const std::uint32_t local = incidences.entries[k] / (n + 1), a = incidences.entries[k] % (n + 1);
          if(g && gradient[local][a].allFinite())
            g->row(j) += gradient[local][a].transpose();
          const int* slot = &slots_[(first + local) * (n + 1) * (n + 1)];
          for(int b = 0; b <= n; ++b) {
            const int s = slot[b * (n + 1) + a];   // entry (b, a): row of cell vertex b in column j
            if(s >= 0) P_.valuePtr()[s] += stiffness[local](b, a);
          }
          if(rhs)
            for(int b = 0; b <= n; ++b)
              if(slot[a * (n + 1) + b] < 0)   // vertex b is fixed
                rhs->row(j) -= stiffness[local](a, b) * p_.map.target[p_.map.cells[moving_cells_[first + local]][b]].transpose();
        }
      });
    }
  }

  // Solves P X = B by preconditioned conjugate gradients (the recurrences of Eigen's
  // conjugate_gradient) from the guess in X, to the given relative residual or number of
  // iterations. The n columns are independent solves, one per thread; the products with P run by
  // rows (P is symmetric) on all threads, so that a thread done with its column helps the others.
  template <class Preconditioner>
  void solve(const Preconditioner& preconditioner, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
             int iterations, double tolerance) const
  {
    const std::size_t size = static_cast<std::size_t>(free_count_);
    const auto product = [&](const Eigen::VectorXd& u, Eigen::VectorXd& pu) {
      workers_.for_each(size, 2048, [&](std::size_t i) {
        double sum = 0;
        for(int k = P_.outerIndexPtr()[i]; k < P_.outerIndexPtr()[i + 1]; ++k) sum += P_.valuePtr()[k] * u[P_.innerIndexPtr()[k]];
        pu[i] = sum;
      });
    };
    workers_.for_each(n, 1, [&](std::size_t d) {
      const Eigen::VectorXd b = B.col(d);
      Eigen::VectorXd x = X.col(d), r(size), z(size), p(size), q(size);
      const double b2 = b.squaredNorm();
      if(b2 == 0) {
        X.col(d).setZero();
        return;
      }
      const double threshold = std::max(tolerance * tolerance * b2, (std::numeric_limits<double>::min)());
      product(x, q);
      r = b - q;
      if(r.squaredNorm() < threshold) return;
      p = preconditioner.solve(r);
      double rz = r.dot(p);
      for(int it = 0; it < iterations; ++it) {
        product(p, q);
        const double alpha = rz / p.dot(q);
        x += alpha * p;
        r -= alpha * q;
        if(r.squaredNorm() < threshold) break;
        z = preconditioner.solve(r);
        const double rz_old = rz;
        rz = r.dot(z);
        p = z + (rz / rz_old) * p;
      }
      X.col(d) = x;
    });
  }

  // The exact largest t <= bound such that no valid cell degenerates at X + t D.
  double max_step(const std::vector<Vec>& direction, double bound) const
  {
    const auto cell_bound = [&](std::size_t i) {
      const std::uint32_t c = moving_cells_[i];
      if(!local_.cell_ok[c]) return bound;
      const auto& cell = p_.map.cells[c];
      Matrix<n> A = p_.map.target_edges(c), B;
      for(int k = 0; k < n; ++k) B.col(k) = direction[cell[k + 1]] - direction[cell[0]];
      const double sign = p_.map.rest_sign[c];
      const Cofactor_and_determinant<n> a(A), b(B);
      const double c0 = sign * a.det, c1 = sign * (a.cofactor.array() * B.array()).sum();
      double c2, c3 = 0;
      if constexpr(n == 2) c2 = sign * b.det;
      else { c2 = sign * (b.cofactor.array() * A.array()).sum(); c3 = sign * b.det; }
      return c0 > 0 ? first_positive_root(c0, c1, c2, c3, bound) : bound;
    };
    return workers_.reduce(moving_cells_.size(), bound, cell_bound, [](double a, double b) { return std::min(a, b); });
  }

  // Backtracks from t along D until the energy decreases (Armijo with the given slope, or any
  // decrease above rounding if slope is 0) with no valid cell flipped; then commits.
  bool line_search(const std::vector<Vec>& direction, double& t, double slope)
  {
    std::vector<Vec>& x = p_.map.target;
    const std::vector<Vec> x0 = x;
    const double e0 = local_.energy();
    const auto moving_cell = [&](std::size_t i) { return moving_cells_[i]; };
    Boundary_guard<n>* guard = local_.boundary_guard();
    const auto boundary_ok = [&] { return !guard || guard->is_injective(x); };
    for(int k = 0; k < 30 && t > 0; ++k, t *= 0.5) {
      workers_.for_each(x.size(), 4096, [&](std::size_t v) { if(p_.is_free[v]) x[v] = x0[v] + t * direction[v]; });
      if(local_.accept_trial(moving_cells_.size(), moving_cell, e0, Local_step<n, Measure>::armijo * t * slope, &workers_,
                             boundary_ok)) {
        if(guard) guard->rebuild(x);
        return true;
      }
    }
    x = x0;
    return false;
  }

  Optimization_problem<n>& p_;
  const Measure& measure_;
  Local_step<n, Measure>& local_;
  const Workers& workers_;
  std::vector<int> free_index_;
  int free_count_ = 0;
  std::vector<std::uint32_t> moving_cells_;
  // refill's blocks of moving cells, small enough for their parts to stay in the L2 cache, and
  // for each block the incidences of its cells' free vertices: the columns of P they fall in and,
  // per column, (position of the cell in the block) * (n + 1) + (the vertex's place in the cell)
  static constexpr std::size_t block = 8192;
  struct Block_incidences
  {
    std::vector<std::uint32_t> columns, begin, entries;
  };
  std::vector<Block_incidences> blocks_;
  Eigen::SparseMatrix<double> P_;
  std::vector<int> slots_;
  Eigen::MatrixXd previous_solution_;
  double last_t_ = 0;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_H
