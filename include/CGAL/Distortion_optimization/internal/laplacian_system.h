// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The one Laplacian of the package: P = sum_c w(c) f(c) G_c^T G_c restricted to the free vertices,
// with G_c the gradients of cell c's hat functions (cell_derivatives.h) and w(c) the problem's
// cell weights. With f = 1 and volume weights it is the volume-weighted cotangent Laplacian of the
// source (the Hessian of the Dirichlet energy at rest), for triangles in their own frames and for
// tetrahedra alike; the global step reweights it per cell. This module builds its sparsity
// pattern once, refills its values, and solves with it by conjugate gradients, on all threads and
// with results that do not depend on their number. Users: the harmonic map (harmonic_targets
// below: the public harmonic_map() and the optimizer's harmonic start) and the global step. On
// the same vertex pattern it also assembles the global step's Newton system from the cells'
// Hessians (refill_hessian), n x n blocks per pair of vertices.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LAPLACIAN_SYSTEM_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LAPLACIAN_SYSTEM_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/optimization_problem.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>
#include <CGAL/Distortion_optimization/internal/sparse_cholesky.h>
#include <CGAL/assertions.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Runs f when it leaves its scope, an exception's exit included: the thread-local scratch arrays
// below are all clear again for the next call on their thread, whatever happened.
template <class F>
struct On_exit
{
  F f;
  ~On_exit() { f(); }
};
template <class F> On_exit(F) -> On_exit<F>;

template <int n>
class Laplacian_system
{
  using Vec = Vector<n>;

public:
  // The harmonic map's solve: relative residual and iteration cap of its conjugate gradients.
  static constexpr double harmonic_tolerance = 1e-10;
  static constexpr int harmonic_iterations = 2000;

  // The unknowns are the problem's free vertices, or those marked in `unknowns` (the harmonic
  // start keeps sliding vertices where they are).
  Laplacian_system(const Optimization_problem<n>& problem, const Workers& workers,
                   const std::vector<unsigned char>* unknowns = nullptr)
    : p_(problem), workers_(workers)
  {
    const std::vector<unsigned char>& is_unknown = unknowns ? *unknowns : p_.is_free;
    const std::size_t nv = p_.number_of_vertices();
    column_.assign(nv, -1);
    for(std::size_t v = 0; v < nv; ++v)
      if(is_unknown[v]) {
        column_[v] = size_++;
        column_vertex_.push_back(static_cast<std::uint32_t>(v));
      }
    for(std::size_t c = 0; c < p_.map.number_of_cells(); ++c) {
      bool moves = false;
      for(auto v : p_.map.cells[c]) moves = moves || is_unknown[v];
      if(moves) moving_cells_.push_back(static_cast<std::uint32_t>(c));
    }
    build_pattern();
  }

  // The number of unknowns (free vertices), and the column of vertex v (-1 if v is fixed).
  int size() const { return size_; }
  int column(std::size_t v) const { return column_[v]; }
  // The cells with a free vertex, in increasing order: the only ones a move of the free vertices changes.
  const std::vector<std::uint32_t>& moving_cells() const { return moving_cells_; }
  // The fill-reducing order of the unknown vertices that the harmonic map's factorization took,
  // for the factorizations of H (same graph of vertices); empty before, and where Eigen's
  // factorization (which computes its own cheaply) solved it.
  const std::vector<int>& fill_order() const { return fill_order_; }

  // Refills P with the cell stiffnesses w(c) f(c) G^T G and, if asked, accumulates the weighted
  // vertex gradients w(c) dE_c/dx of the free vertices into the rows of g, or the fixed vertices'
  // contribution -P_free,fixed x_fixed into the rows of rhs. `cell_terms(cells, count, factor,
  // gradient)` gives, for the moving cells cells[0..count), f(c) and (when g is asked) the
  // unweighted vertex gradients; nullptr means f = 1. The sums do not depend on the number of
  // threads (assemble).
  template <class CellTerms>
  void refill(const CellTerms& cell_terms, Eigen::MatrixXd* g, Eigen::MatrixXd* rhs)
  {
    constexpr bool unit_factors = std::is_same<CellTerms, std::nullptr_t>::value;
    std::vector<double> factor(std::min(block<1>, moving_cells_.size()), 1.);
    assemble<1>(&P_, [&](std::size_t begin, const std::uint32_t* cells, std::size_t count,
                        Eigen::Matrix<double, n + 1, n + 1>* stiffness, std::array<Vec, n + 1>* gradient) {
      double* f = &factor[begin];
      if constexpr(!unit_factors) cell_terms(cells, count, f, gradient);
      for(std::size_t i = 0; i < count; ++i) {
        const Eigen::Matrix<double, n, n + 1> G = p_.map.hat_gradients(cells[i]);
        stiffness[i] = f[i] * (G.transpose() * G);
      }
    }, g, rhs);
  }

  // The projected Newton system: H = sum_c w(c) H_c over the free vertices' coordinates (vertex
  // v's n unknowns in consecutive rows), with the same sparsity as P in n x n blocks, and, if
  // asked, the weighted gradient into g as refill does. `cell_hessians(cells, count, hessian,
  // gradient)` gives each cell's unweighted n(n+1) x n(n+1) Hessian (vertex-major) and vertex gradients.
  template <class CellHessians>
  void refill_hessian(const CellHessians& cell_hessians, Eigen::MatrixXd* g)
  {
    if(H_.rows() != n * size_) build_block_pattern();
    assemble<n>(&H_, [&](std::size_t, const std::uint32_t* cells, std::size_t count,
                        Eigen::Matrix<double, n * (n + 1), n * (n + 1)>* hessian, std::array<Vec, n + 1>* gradient) {
      cell_hessians(cells, count, hessian, gradient);
    }, g, nullptr);
  }

  const Eigen::SparseMatrix<double>& hessian() const { return H_; }

  // Only the weighted gradient into g (zero on entry), as refill gathers it:
  // `cell_gradients(cells, count, gradient)` gives each cell's unweighted vertex gradients.
  template <class CellGradients>
  void refill_gradient(const CellGradients& cell_gradients, Eigen::MatrixXd& g)
  {
    assemble<1>(nullptr, [&](std::size_t, const std::uint32_t* cells, std::size_t count, Eigen::Matrix<double, n + 1, n + 1>*,
                             std::array<Vec, n + 1>* gradient) { cell_gradients(cells, count, gradient); }, &g, nullptr);
  }

  // Eigen's incomplete Cholesky factor of A scaled by a power of two (exactly) to a largest
  // diagonal entry in [1, 2): its square roots then see the same digits whatever the mesh's
  // units, and a preconditioner's scale changes no iterate of conjugate gradients, so that a mesh
  // scaled by 2 gives the same iterates scaled (unscaled, its results differed from the fifth
  // digit on with the boundary sliding).
  static void incomplete_cholesky(const Eigen::SparseMatrix<double>& A, Eigen::IncompleteCholesky<double>& factor)
  {
    const Eigen::SparseMatrix<double> scaled = (A.rows() > 0 ? unit_scale(A.diagonal().cwiseAbs().maxCoeff()) : 1.) * A;
    factor.compute(scaled);
  }

  // A preconditioner for H (hessian()) that does not depend on the map: an incomplete Cholesky
  // factor of the source's Laplacian (P with the unit factors), applied to each of a vertex's n
  // coordinates (on threads). Where H is nearly singular in directions that P is not (MIPS's
  // Hessian in every cell's scaling, the similarities being its minimizers), Jacobi-preconditioned
  // conjugate gradients stall and this one goes much further. Factored at construction (refills P).
  class Coordinatewise_laplacian
  {
  public:
    Coordinatewise_laplacian(Laplacian_system& system) : workers_(system.workers_)
    {
      system.refill(nullptr, nullptr, nullptr);
      incomplete_cholesky(system.P_, factor_);
    }
    bool ok() const { return factor_.info() == Eigen::Success; }
    Eigen::VectorXd solve(const Eigen::VectorXd& r) const
    {
      const Eigen::Index size = r.size() / n;
      Eigen::VectorXd z(r.size());
      workers_.for_each(n, 1, [&](std::size_t d) {
        const Eigen::VectorXd coordinate = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<n>>(r.data() + d, size);
        Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<n>>(z.data() + d, size) = factor_.solve(coordinate);
      });
      return z;
    }

  private:
    const Workers& workers_;
    Eigen::IncompleteCholesky<double> factor_;
  };

  const Eigen::SparseMatrix<double>& matrix() const { return P_; }

  // Solves A X = B by preconditioned conjugate gradients (the recurrences of Eigen's
  // conjugate_gradient) from the guess in X, to the given relative residual or number of
  // iterations, with A = P (or the Newton system H, matrix()'s or hessian()'s). The columns are
  // independent solves, one per thread; the products with A run by rows (A is symmetric) on all
  // threads, so that a thread done with its column helps the others. Returns false if some column
  // did not reach the residual within the iterations. If asked, `outcome` gets the largest
  // relative residual |r| / |b| of the columns and the most iterations one took. `give_up`
  // WHEN_TOO_SLOW stops a column as soon as the residual's mean reduction per iteration so far would
  // not reach the tolerance in twice the iterations allowed: for a solve worth trying only where
  // it converges fast (a lagged preconditioner, where each iteration costs a good part of a new
  // factorization); conjugate gradients speed up as they go, so a long solve must not stop early.
  struct Solve_outcome
  {
    double residual = 0;
    int iterations = 0;
  };
  enum class Give_up { AT_THE_LIMIT, WHEN_TOO_SLOW };
  template <class Preconditioner>
  bool solve(const Eigen::SparseMatrix<double>& A, const Preconditioner& preconditioner, const Eigen::MatrixXd& B,
             Eigen::MatrixXd& X, int iterations, double tolerance, Solve_outcome* outcome = nullptr,
             Give_up give_up = Give_up::AT_THE_LIMIT) const
  {
    const std::size_t size = static_cast<std::size_t>(A.rows());
    // A's arrays in locals: the compiler cannot otherwise tell that writing pu leaves them alone.
    const int *outer = A.outerIndexPtr(), *inner = A.innerIndexPtr();
    const double* values = A.valuePtr();
    // H's entries come in n x n blocks on P's pattern (build_block_pattern): its product reads one
    // index of P per block, and each vertex's n coordinates of u together (much less time than
    // entry by entry).
    const bool blocks = &A == &H_;
    const int *block_outer = P_.outerIndexPtr(), *block_inner = P_.innerIndexPtr();
    const auto product = [&](const Eigen::VectorXd& u, Eigen::VectorXd& pu) {
      const double* ud = u.data();
      double* pud = pu.data();
      if(blocks) {
        workers_.for_each(static_cast<std::size_t>(size_), 1024, [&](std::size_t j) {
          const int begin = block_outer[j], count = block_outer[j + 1] - begin;
          const double* column = values + n * n * begin;   // column n j + q starts at q n count
          Vec sum = Vec::Zero();
          for(int e = 0; e < count; ++e) {
            const Eigen::Map<const Vec> x(ud + n * block_inner[begin + e]);
            for(int q = 0; q < n; ++q) sum[q] += Eigen::Map<const Vec>(column + q * n * count + n * e).dot(x);
          }
          Eigen::Map<Vec>(pud + n * j) = sum;
        });
        return;
      }
      workers_.for_each(size, 2048, [&](std::size_t i) {
        double sum = 0;
        for(int k = outer[i]; k < outer[i + 1]; ++k) sum += values[k] * ud[inner[k]];
        pud[i] = sum;
      });
    };
    std::vector<unsigned char> converged(B.cols(), 1);
    std::vector<Solve_outcome> outcomes(B.cols());
    workers_.for_each(B.cols(), 1, [&](std::size_t d) {
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
      if(r.squaredNorm() < threshold) {
        outcomes[d].residual = std::sqrt(r.squaredNorm() / b2);
        return;
      }
      p = preconditioner.solve(r);
      double rz = r.dot(p);
      converged[d] = 0;
      for(int it = 0; it < iterations && !converged[d]; ++it) {
        outcomes[d].iterations = it + 1;
        product(p, q);
        const double alpha = rz / p.dot(q);
        x += alpha * p;
        r -= alpha * q;
        converged[d] = r.squaredNorm() < threshold;
        if(converged[d]) break;
        // |r| / |b| = rate^(it + 1); rate^(2 iterations) > tolerance:
        if(give_up == Give_up::WHEN_TOO_SLOW && iterations * std::log(r.squaredNorm() / b2) > (it + 1) * std::log(tolerance))
          break;
        z = preconditioner.solve(r);
        const double rz_old = rz;
        rz = r.dot(z);
        p = z + (rz / rz_old) * p;
      }
      X.col(d) = x;
      outcomes[d].residual = std::sqrt(r.squaredNorm() / b2);
    });
    if(outcome) {
      *outcome = Solve_outcome();
      for(const Solve_outcome& o : outcomes) {
        outcome->residual = std::max(outcome->residual, o.residual);
        outcome->iterations = std::max(outcome->iterations, o.iterations);
      }
    }
    return std::find(converged.begin(), converged.end(), 0) == converged.end();
  }

  // The harmonic map: the targets x of the free vertices that minimize sum_c w(c) |J_c|^2 with the
  // fixed vertices where `targets` has them: in 2D by a sparse factorization, in 3D by conjugate
  // gradients with Jacobi's preconditioner (a direct factorization of a 3D Laplacian fills in
  // badly) from the free vertices' current targets, to harmonic_tolerance. An incomplete Cholesky
  // factor takes a third of the iterations, but its factorization and triangular solves are
  // sequential and saved no time, where every step of Jacobi's runs on the threads. Returns false,
  // with x unspecified, where the harmonic map is not defined: some set of free vertices is
  // connected to no fixed one (in particular when no vertex is fixed: the minimizers are then the
  // constant maps). Refills P with the unit factors.
  bool harmonic_targets(const std::vector<Vec>& targets, std::vector<Vec>& x)
  {
    x = targets;
    if(size_ == 0) return true;
    if(size_ == static_cast<int>(p_.number_of_vertices()) || !every_unknown_reaches_a_known_vertex()) return false;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(size_, n), X(size_, n);
    refill(nullptr, nullptr, &rhs);
    if constexpr(n == 2) {
      // A planar Laplacian fills in little: a sparse LDL^T is several times faster than the
      // conjugate gradients below.
      Sparse_cholesky<1> factorization;
      factorization.analyze(P_, fill_order_);
      if(!factorization.factorize(P_)) return false;
      fill_order_ = factorization.block_order();
      X = factorization.solve(rhs);
    } else {
      for(std::size_t v = 0; v < x.size(); ++v)
        if(column_[v] >= 0) X.row(column_[v]) = targets[v].transpose();
      // A start that is already harmonic (one an earlier run wrote) needs no solve: one residual
      // tells.
      const Eigen::MatrixXd residual = rhs - P_ * X;
      const double tolerance2 = harmonic_tolerance * harmonic_tolerance;
      if(((residual.colwise().squaredNorm().array() <= tolerance2 * rhs.colwise().squaredNorm().array())).all()) return true;
      Eigen::DiagonalPreconditioner<double> jacobi;
      jacobi.compute(P_);
      solve(P_, jacobi, rhs, X, harmonic_iterations, harmonic_tolerance);
    }
    if(!X.allFinite()) return false;
    for(std::size_t v = 0; v < x.size(); ++v)
      if(column_[v] >= 0) x[v] = X.row(column_[v]).transpose();
    return true;
  }

private:
  // assemble's blocks of moving cells, small enough for their cell matrices to stay in the L2
  // cache (in 3D, 1 MB of Laplacian parts, or 1.2 MB of 12 x 12 Hessians: with P's 8192 cells a
  // block, the Hessians would make a costly round trip through memory), and for
  // each block the incidences of its cells' free vertices: the columns of P they fall in and, per
  // column, (position of the cell in the block) * (n + 1) + (the vertex's place in the cell)
  template <int k> static constexpr std::size_t block = k == 1 ? 8192 : 1024;
  struct Block_incidences
  {
    std::vector<std::uint32_t> columns, begin, entries;
  };

  // Whether every unknown vertex is joined through cells to a vertex that is not one: where a
  // part is not, P is singular, and a factorization may see a rounding error for its zero pivot.
  bool every_unknown_reaches_a_known_vertex() const
  {
    std::vector<unsigned char> reached(p_.number_of_vertices(), 0);
    std::vector<std::uint32_t> stack;
    for(std::size_t v = 0; v < reached.size(); ++v)
      if(column_[v] < 0) {
        reached[v] = 1;
        stack.push_back(static_cast<std::uint32_t>(v));
      }
    while(!stack.empty()) {
      const std::uint32_t v = stack.back();
      stack.pop_back();
      for(std::uint32_t k = p_.ring_begin[v]; k < p_.ring_begin[v + 1]; ++k)
        for(auto b : p_.map.cells[p_.ring[k].cell])
          if(!reached[b]) {
            reached[b] = 1;
            stack.push_back(b);
          }
    }
    return std::find(reached.begin(), reached.end(), 0) == reached.end();
  }

  // Fills A (P for k = 1, H for k = n: k unknowns per free vertex; none if null) with the
  // weighted cell matrices w(c) M_c that `cell_matrices(begin, cells, count, M, gradient)` computes
  // for the moving cells cells[0..count) (at `begin` in their block; M null without A), and g, rhs
  // as refill() says. Block by block of cells, the cells' parts are computed in parallel, then
  // gathered in parallel by column: column j of A and rows j of g and rhs take their contributions
  // in cell order, so that every sum has the sequential order whatever the number of threads.
  template <int k, class CellMatrices>
  void assemble(Eigen::SparseMatrix<double>* A, const CellMatrices& cell_matrices, Eigen::MatrixXd* g, Eigen::MatrixXd* rhs)
  {
    using Cell_matrix = Eigen::Matrix<double, k * (n + 1), k * (n + 1)>;
    CGAL_precondition(A != nullptr || rhs == nullptr);   // rhs takes the cell matrices
    if(A) std::fill(A->valuePtr(), A->valuePtr() + A->nonZeros(), 0.);
    constexpr std::size_t block = Laplacian_system::block<k>;
    const std::vector<Block_incidences>& blocks = k == 1 ? blocks_ : hessian_blocks_;
    const std::size_t capacity = std::min(block, moving_cells_.size());
    std::vector<Cell_matrix> local(A ? capacity : 0);
    std::vector<std::array<Vec, n + 1>> gradient(g ? capacity : 0);
    const int* outer = P_.outerIndexPtr();
    for(std::size_t first = 0; first < moving_cells_.size(); first += block) {
      const std::size_t count = std::min(block, moving_cells_.size() - first);
      workers_.for_each_block(count, 256, [&](std::size_t begin, std::size_t size) {
        cell_matrices(begin, &moving_cells_[first + begin], size, A ? &local[begin] : nullptr, g ? &gradient[begin] : nullptr);
        for(std::size_t i = begin; i < begin + size; ++i) {
          const double w = p_.cell_weight[moving_cells_[first + i]];
          if(A) local[i] *= w;
          if(g)
            for(Vec& x : gradient[i]) x = w * x;
        }
      });
      const Block_incidences& incidences = blocks[first / block];
      workers_.for_each(incidences.columns.size(), 64, [&](std::size_t t) {
        const std::uint32_t j = incidences.columns[t];
        for(std::uint32_t e = incidences.begin[t]; e < incidences.begin[t + 1]; ++e) {
          const std::uint32_t i = incidences.entries[e] / (n + 1), a = incidences.entries[e] % (n + 1);
          if(g && gradient[i][a].allFinite())
            g->row(j) += gradient[i][a].transpose();
          const int* slot = &slots_[(first + i) * (n + 1) * (n + 1)];
          for(int b = 0; b <= n && A; ++b) {
            const int s = slot[b * (n + 1) + a];   // entry (b, a): row of cell vertex b in column j
            if(s < 0) continue;
            // Block (b, a) of the cell's matrix: in column j * k + q of A, the entries of P's
            // column j come k rows each.
            const int column_size = outer[j + 1] - outer[j];
            for(int q = 0; q < k; ++q)
              for(int r = 0; r < k; ++r)
                A->valuePtr()[k * k * outer[j] + q * k * column_size + (s - outer[j]) * k + r] += local[i](b * k + r, a * k + q);
          }
          if(rhs)
            for(int b = 0; b <= n; ++b)
              if(slot[a * (n + 1) + b] < 0)   // vertex b is fixed
                rhs->row(j) -= local[i](a, b) * p_.map.target[p_.map.cells[moving_cells_[first + i]][b]].transpose();
        }
      });
    }
  }

  // H's pattern: P's, each entry an n x n block.
  void build_block_pattern()
  {
    const int* outer = P_.outerIndexPtr();
    const int* inner = P_.innerIndexPtr();
    H_.resize(n * size_, n * size_);
    H_.resizeNonZeros(n * n * P_.nonZeros());
    workers_.for_each(size_, 1024, [&](std::size_t j) {
      const int column_size = outer[j + 1] - outer[j];
      for(int q = 0; q < n; ++q) {
        const int start = n * n * outer[j] + q * n * column_size;
        H_.outerIndexPtr()[n * j + q] = start;
        for(int e = 0; e < column_size; ++e)
          for(int r = 0; r < n; ++r) H_.innerIndexPtr()[start + e * n + r] = n * inner[outer[j] + e] + r;
      }
    });
    H_.outerIndexPtr()[n * size_] = n * n * P_.nonZeros();
    std::fill(H_.valuePtr(), H_.valuePtr() + H_.nonZeros(), 0.);
    build_blocks(block<n>, hessian_blocks_);
  }

  // The sparsity pattern of the free-free block, and for each cell and pair of its free vertices
  // the slot of their entry, so that refills only rewrite values.
  void build_pattern()
  {
    // Column by column from the rings, straight into compressed storage (no triplet list: it
    // would be the peak of the whole run): the columns' sizes in parallel, their offsets, then
    // their rows in parallel, each column into its own segment.
    // A ring lists each neighbour several times: marks (all clear between calls) keep one of each
    // for the sort.
    const auto free_neighbours = [&](std::size_t column) -> const std::vector<int>& {
      static thread_local std::vector<int> neighbours;
      static thread_local std::vector<char> marked;
      if(marked.size() < static_cast<std::size_t>(size_)) marked.resize(size_, 0);
      neighbours.clear();
      const On_exit clear_marks{[&] { for(int c : neighbours) marked[c] = 0; }};
      const std::uint32_t a = column_vertex_[column];
      for(std::uint32_t k = p_.ring_begin[a]; k < p_.ring_begin[a + 1]; ++k)
        for(auto b : p_.map.cells[p_.ring[k].cell])
          if(column_[b] >= 0 && !marked[column_[b]]) {
            neighbours.push_back(column_[b]);   // before the mark: every mark is in the list
            marked[column_[b]] = 1;
          }
      std::sort(neighbours.begin(), neighbours.end());
      return neighbours;
    };
    std::vector<int> offset(size_ + 1, 0);
    workers_.for_each(size_, 1024, [&](std::size_t j) { offset[j + 1] = static_cast<int>(free_neighbours(j).size()); });
    for(int j = 0; j < size_; ++j) offset[j + 1] += offset[j];
    P_.resize(size_, size_);
    P_.resizeNonZeros(offset[size_]);
    std::copy(offset.begin(), offset.end(), P_.outerIndexPtr());
    std::fill(P_.valuePtr(), P_.valuePtr() + P_.nonZeros(), 0.);
    workers_.for_each(size_, 1024, [&](std::size_t j) {
      const std::vector<int>& rows = free_neighbours(j);
      std::copy(rows.begin(), rows.end(), P_.innerIndexPtr() + offset[j]);
    });
    // Where each entry of each cell's (n+1) x (n+1) stiffness goes in P (-1: a fixed vertex): column
    // by column, the ring of its vertex read against the column's rows, marked in a dense array
    // (no search: this was half of the pattern's time).
    constexpr std::size_t entries = (n + 1) * (n + 1);
    std::vector<std::uint32_t> moving_index(p_.map.number_of_cells());
    for(std::size_t i = 0; i < moving_cells_.size(); ++i) moving_index[moving_cells_[i]] = static_cast<std::uint32_t>(i);
    slots_.assign(moving_cells_.size() * entries, -1);
    workers_.for_each(size_, 1024, [&](std::size_t j) {
      static thread_local std::vector<int> position;   // of each row in column j, for its rows only
      if(position.size() < static_cast<std::size_t>(size_)) position.resize(size_);
      for(int e = offset[j]; e < offset[j + 1]; ++e) position[P_.innerIndexPtr()[e]] = e;
      const std::uint32_t b = column_vertex_[j];
      for(std::uint32_t k = p_.ring_begin[b]; k < p_.ring_begin[b + 1]; ++k) {
        const Incidence& in = p_.ring[k];
        const auto& cell = p_.map.cells[in.cell];
        int* slot = &slots_[moving_index[in.cell] * entries + in.local];
        for(int a = 0; a <= n; ++a)
          if(column_[cell[a]] >= 0) slot[a * (n + 1)] = position[column_[cell[a]]];
      }
    });
    build_blocks(block<1>, blocks_);
  }

  // Each block's incidences of free vertices, by column of P and, within a column, in cell order:
  // what assemble gathers. A counting sort by column, stable, so each column keeps the cell order.
  void build_blocks(std::size_t block, std::vector<Block_incidences>& blocks) const
  {
    blocks.assign((moving_cells_.size() + block - 1) / block, {});
    workers_.for_each(blocks.size(), 1, [&](std::size_t b) {
      static thread_local std::vector<std::uint32_t> count;   // per column, zero between blocks
      if(count.size() < static_cast<std::size_t>(size_)) count.resize(size_, 0);
      Block_incidences& incidences = blocks[b];
      const std::size_t first = b * block, last = std::min(moving_cells_.size(), first + block);
      const On_exit clear_counts{[&] {
        for(std::size_t i = first; i < last; ++i)
          for(auto v : p_.map.cells[moving_cells_[i]])
            if(column_[v] >= 0) count[column_[v]] = 0;
      }};
      for(std::size_t i = first; i < last; ++i)
        for(auto v : p_.map.cells[moving_cells_[i]])
          if(column_[v] >= 0 && count[column_[v]]++ == 0) incidences.columns.push_back(static_cast<std::uint32_t>(column_[v]));
      std::sort(incidences.columns.begin(), incidences.columns.end());
      std::uint32_t total = 0;
      for(std::uint32_t j : incidences.columns) {
        incidences.begin.push_back(total);
        total += std::exchange(count[j], total);   // count[j] is now the column's next place
      }
      incidences.begin.push_back(total);
      incidences.entries.resize(total);
      for(std::size_t i = first; i < last; ++i)
        for(int a = 0; a <= n; ++a) {
          const int column = column_[p_.map.cells[moving_cells_[i]][a]];
          if(column >= 0) incidences.entries[count[column]++] = static_cast<std::uint32_t>((i - first) * (n + 1) + a);
        }
    });
  }

  const Optimization_problem<n>& p_;
  const Workers& workers_;
  std::vector<int> column_;
  std::vector<std::uint32_t> column_vertex_;   // column_'s inverse
  int size_ = 0;
  std::vector<std::uint32_t> moving_cells_;
  std::vector<Block_incidences> blocks_, hessian_blocks_;
  Eigen::SparseMatrix<double> P_, H_;
  std::vector<int> slots_;
  std::vector<int> fill_order_;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LAPLACIAN_SYSTEM_H
