// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The package's sparse direct solver for symmetric positive definite systems: the triangle maps'
// Newton systems (global_step/lagged_factorization.h), their harmonic starts
// (laplacian_system.h) and Tutte's embedding (tutte_embedding.h). With CHOLMOD (SuiteSparse; the CMake target
// Distortion_optimization::CHOLMOD_support defines CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD)
// a supernodal Cholesky factorization, whose dense blocks go through the BLAS: several times
// faster than a simplicial one from some ten thousand unknowns on (Chen, Davis, Hager and
// Rajamanickam, "Algorithm 887: CHOLMOD, supernodal sparse Cholesky factorization and
// update/downdate", 2008). Without it, Eigen's simplicial LDL^T. Either way the symbolic analysis
// is done once per pattern and each numeric factorization reuses it.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SPARSE_CHOLESKY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/block_amd_ordering.h>
#include <CGAL/Distortion_optimization/sparse_solver.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// How a factorization's fill-reducing order of the blocks is computed on CHOLMOD's path. METIS's
// nested dissection takes several times as long as the approximate minimum degree (AMD) and fills
// in less: it pays where one pattern is factored many times (Newton's steps), not for one solve
// (Tutte's maps). Eigen's path always takes the minimum degree.
enum class Fill_reducing_order { NESTED_DISSECTION, MINIMUM_DEGREE };

#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
// CHOLMOD's supernodal LL^T with a fill-reducing order of the graph of the blocks (a vertex's
// `block` unknowns kept together): METIS's nested dissection or CHOLMOD's AMD, or an order given
// by an earlier analysis. The graph is block^2 times smaller than the matrix, and an ordering,
// whose cost the analysis is, takes a fraction of the time it takes on the matrix, for a factor as
// sparse.
//
// The matrix is handed to CHOLMOD already permuted: given the lower triangle of A and a fill-reducing
// order, cholmod_factorize() builds the permuted matrix by two transposes at every factorization
// (its source: only an upper triangle in natural order is factored as it is). Here the order,
// postordered by the analysis, permutes A's pattern once, with the place of each of A's values in
// it; each factorization copies the values there and CHOLMOD factors the result in natural order.
// Solves permute the right-hand side and the solution.
template <int block>
class Block_ordered_supernodal_llt
{
public:
  Block_ordered_supernodal_llt()
  {
    cholmod_start(&common_);
    common_.final_asis = 1;
  }
  ~Block_ordered_supernodal_llt()
  {
    free_factor();
    cholmod_finish(&common_);
  }
  Block_ordered_supernodal_llt(const Block_ordered_supernodal_llt&) = delete;
  Block_ordered_supernodal_llt& operator=(const Block_ordered_supernodal_llt&) = delete;

  // `given_order`, if not empty, is the order of the blocks to eliminate them in, computed for
  // another matrix on the same graph of blocks (see block_order()); else `fill`'s.
  void analyze(const Eigen::SparseMatrix<double>& A, const std::vector<int>& given_order,
               Fill_reducing_order fill = Fill_reducing_order::NESTED_DISSECTION)
  {
    free_factor();
    info_ = Eigen::NumericalIssue;
    const Eigen::SparseMatrix<double>* C = compressed(A);
    const int n = static_cast<int>(C->rows()), blocks = n / block;
    bool ok = true;
    if(is_permutation(given_order, blocks)) {
      block_order_ = given_order;
    } else {
      // CHOLMOD reads its lower triangle; METIS ignores the diagonal.
      const Eigen::SparseMatrix<double> graph = block_graph<block>(*C);
      cholmod_sparse G = Eigen::viewAsCholmod(graph.selfadjointView<Eigen::Lower>());
      block_order_.assign(static_cast<std::size_t>(blocks), 0);
      ok = blocks == 0 || (fill == Fill_reducing_order::NESTED_DISSECTION
                             ? cholmod_metis(&G, nullptr, 0, 1, block_order_.data(), &common_)
                             : cholmod_amd(&G, nullptr, 0, block_order_.data(), &common_));
    }
    std::vector<int> order(static_cast<std::size_t>(n));
    for(int i = 0; i < blocks; ++i)
      for(int a = 0; a < block; ++a) order[static_cast<std::size_t>(block * i + a)] = block * block_order_[i] + a;
    // One supernodal analysis in that order, which CHOLMOD postorders by the elimination tree (its
    // final permutation, factor_->Perm): A's pattern is permuted once by it, and the factor then
    // takes the permuted matrix as it is (natural order, identity Perm; the symbolic factor is
    // that of the permuted matrix either way).
    if(ok) {
      cholmod_sparse M = Eigen::viewAsCholmod(C->selfadjointView<Eigen::Lower>());
      common_.nmethods = 1;
      common_.method[0].ordering = CHOLMOD_GIVEN;
      common_.postorder = 1;
      common_.supernodal = CHOLMOD_SUPERNODAL;
      factor_ = cholmod_analyze_p(&M, order.data(), nullptr, 0, &common_);
      ok = factor_ != nullptr && factor_->is_super && factor_->IPerm == nullptr;
    }
    if(ok) {
      int* perm = static_cast<int*>(factor_->Perm);
      permutation_.assign(perm, perm + n);
      std::iota(perm, perm + n, 0);
      factor_->ordering = CHOLMOD_NATURAL;
      permute_pattern(*C);
    }
    info_ = ok ? Eigen::Success : Eigen::NumericalIssue;
    if(!ok) {
      free_factor();
      block_order_.clear();
    }
  }

  Eigen::ComputationInfo info() const { return info_; }
  void setShift(double shift) { shift_ = shift; }

  // Factors A + shift I, A with the analyzed pattern.
  void factorize(const Eigen::SparseMatrix<double>& A)
  {
    const Eigen::SparseMatrix<double>* C = compressed(A);
    if(!factor_ || C->nonZeros() != static_cast<Eigen::Index>(place_.size())) {
      info_ = Eigen::InvalidInput;
      return;
    }
    const double* value = C->valuePtr();
    for(std::size_t k = 0; k < place_.size(); ++k)
      if(place_[k] >= 0) values_[static_cast<std::size_t>(place_[k])] = value[k];
    cholmod_sparse B = permuted();
    double beta[2] = {shift_, 0};
    cholmod_factorize_p(&B, beta, nullptr, 0, factor_, &common_);
    info_ = common_.status == CHOLMOD_OK && factor_->minor == factor_->n ? Eigen::Success : Eigen::NumericalIssue;
  }

  // (A + shift I)^-1 b, after a successful factorize().
  template <class Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    const std::size_t n = permutation_.size();
    Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> c(b.rows(), b.cols()), x(b.rows(), b.cols());
    for(std::size_t i = 0; i < n; ++i) c.row(Eigen::Index(i)) = b.row(permutation_[i]);
    cholmod_dense C;
    C.nrow = C.d = static_cast<std::size_t>(c.rows());
    C.ncol = static_cast<std::size_t>(c.cols());
    C.nzmax = C.nrow * C.ncol;
    C.x = c.data();
    C.z = nullptr;
    C.xtype = CHOLMOD_REAL;
    C.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* y = cholmod_solve(CHOLMOD_A, factor_, &C, &common_);
    if(!y) {
      x.setConstant(std::numeric_limits<double>::quiet_NaN());
      return x;
    }
    const Eigen::Map<const Eigen::MatrixXd> Y(static_cast<const double*>(y->x), Eigen::Index(y->nrow), Eigen::Index(y->ncol));
    for(std::size_t i = 0; i < n; ++i) x.row(permutation_[i]) = Y.row(Eigen::Index(i));
    cholmod_free_dense(&y, &common_);
    return x;
  }

  const cholmod_common& cholmod() const { return common_; }
  const std::vector<int>& block_order() const { return block_order_; }

private:
  void free_factor()
  {
    if(factor_) cholmod_free_factor(&factor_, &common_);
    factor_ = nullptr;
  }

  const Eigen::SparseMatrix<double>* compressed(const Eigen::SparseMatrix<double>& A)
  {
    if(A.isCompressed()) return &A;
    compressed_ = A;
    compressed_.makeCompressed();
    return &compressed_;
  }

  // The lower triangle of A(p, p), p = permutation_, its rows sorted in each column, and where
  // each stored value of A goes in it (-1: above the diagonal, not read).
  void permute_pattern(const Eigen::SparseMatrix<double>& A)
  {
    const int n = static_cast<int>(A.rows());
    std::vector<int> inverse(static_cast<std::size_t>(n));
    for(int i = 0; i < n; ++i) inverse[static_cast<std::size_t>(permutation_[i])] = i;
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    place_.assign(static_cast<std::size_t>(A.nonZeros()), -1);
    column_start_.assign(static_cast<std::size_t>(n) + 1, 0);
    for(int c = 0; c < n; ++c)
      for(int k = outer[c]; k < outer[c + 1]; ++k)
        if(inner[k] >= c) ++column_start_[static_cast<std::size_t>(std::min(inverse[inner[k]], inverse[c])) + 1];
    for(int j = 0; j < n; ++j) column_start_[j + 1] += column_start_[j];
    const std::size_t stored = static_cast<std::size_t>(column_start_[n]);
    std::vector<std::pair<int, int>> entries(stored);   // (row, source) by column
    std::vector<int> next(column_start_.begin(), column_start_.end() - 1);
    for(int c = 0; c < n; ++c)
      for(int k = outer[c]; k < outer[c + 1]; ++k)
        if(inner[k] >= c) {
          const int i = inverse[inner[k]], j = inverse[c];
          entries[static_cast<std::size_t>(next[std::min(i, j)]++)] = {std::max(i, j), k};
        }
    rows_.resize(stored);
    values_.assign(stored, 0.);
    for(int j = 0; j < n; ++j) {
      std::sort(entries.begin() + column_start_[j], entries.begin() + column_start_[j + 1]);
      for(int e = column_start_[j]; e < column_start_[j + 1]; ++e) {
        rows_[static_cast<std::size_t>(e)] = entries[static_cast<std::size_t>(e)].first;
        place_[static_cast<std::size_t>(entries[static_cast<std::size_t>(e)].second)] = e;
      }
    }
  }

  // CHOLMOD's view of the permuted lower triangle.
  cholmod_sparse permuted()
  {
    cholmod_sparse B;
    B.nrow = B.ncol = permutation_.size();
    B.nzmax = values_.size();
    B.p = column_start_.data();
    B.i = rows_.data();
    B.nz = nullptr;
    B.x = values_.data();
    B.z = nullptr;
    B.stype = -1;
    B.itype = CHOLMOD_INT;
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    B.sorted = 1;
    B.packed = 1;
    return B;
  }

  // Whether `order` holds each of 0 .. size - 1 once (an order from another analysis, checked
  // rather than trusted: CHOLMOD would read out of bounds).
  static bool is_permutation(const std::vector<int>& order, int size)
  {
    if(order.size() != static_cast<std::size_t>(size)) return false;
    std::vector<unsigned char> seen(order.size(), 0);
    for(int k : order) {
      if(k < 0 || k >= size || seen[static_cast<std::size_t>(k)]) return false;
      seen[static_cast<std::size_t>(k)] = 1;
    }
    return true;
  }

  mutable cholmod_common common_;   // CHOLMOD takes it, with its workspace, in solves too
  cholmod_factor* factor_ = nullptr;
  Eigen::ComputationInfo info_ = Eigen::InvalidInput;
  double shift_ = 0;
  std::vector<int> block_order_, permutation_;
  std::vector<int> column_start_, rows_, place_;
  std::vector<double> values_;
  Eigen::SparseMatrix<double> compressed_;
};
#endif

// A Cholesky factorization of a symmetric positive definite matrix whose unknowns come in groups
// of `block` (a vertex's coordinates), kept together by the fill-reducing ordering. Reads the lower
// triangle. Usable as a preconditioner (solve). Below `cholmod_from` unknowns Eigen's simplicial
// LDL^T is used even with CHOLMOD: a supernodal factorization's overhead outweighs its dense
// blocks there, unless the program removed that overhead (set_cholmod_threshold(); the figures
// are in the manual's section on the sparse solver).
template <int block>
class Sparse_cholesky
{
public:
  // The program's setting, cholmod_threshold().
  static std::ptrdiff_t default_cholmod_from()
  {
    return static_cast<std::ptrdiff_t>(std::min<std::size_t>(cholmod_threshold(), PTRDIFF_MAX));
  }

  explicit Sparse_cholesky(std::ptrdiff_t cholmod_from = default_cholmod_from(),
                           Fill_reducing_order fill = Fill_reducing_order::NESTED_DISSECTION)
    : cholmod_from_(cholmod_from), fill_(fill)
  {}

  // The symbolic analysis of A's pattern: once, before the first factorize (again if the pattern
  // changes). `block_order`, if given, is the fill-reducing order of A's blocks that a solver
  // computed for another matrix on the same graph of blocks (its block_order()), which a CHOLMOD
  // factorization takes instead of computing METIS's again (the larger share of an analysis); on
  // Eigen's path, whose ordering is cheap, it is not needed.
  void analyze(const Eigen::SparseMatrix<double>& A, const std::vector<int>& block_order = {})
  {
    factored_ = false;
    simplicial_.reset();
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
    supernodal_.reset();
    if(A.rows() >= cholmod_from_) {
      supernodal_ = std::make_unique<Supernodal>();
      supernodal_->analyze(A, block_order, fill_);
      analyzed_ = supernodal_->info() == Eigen::Success;
      return;
    }
#endif
    (void)block_order;
    simplicial_ = std::make_unique<Simplicial>();
    simplicial_->analyzePattern(A);
    analyzed_ = simplicial_->info() == Eigen::Success;
  }

  // Whether the analyzed pattern is factored by CHOLMOD.
  bool uses_cholmod() const
  {
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
    return supernodal_ != nullptr;
#else
    return false;
#endif
  }

  // Factors A + shift I, A with the analyzed pattern (analyzes it if that was not done); false if
  // that fails: A + shift I not positive definite to rounding (Eigen's LDL^T would go on with
  // negative pivots; it is refused as CHOLMOD's LL^T refuses it), or out of memory.
  bool factorize(const Eigen::SparseMatrix<double>& A, double shift = 0)
  {
    if(A.rows() == 0) return factored_ = true;
    if(needs_analysis()) analyze(A);
    if(!analyzed_) return factored_ = false;
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
    if(supernodal_) {
      supernodal_->setShift(shift);
      supernodal_->factorize(A);
      return factored_ = supernodal_->info() == Eigen::Success;
    }
#endif
    simplicial_->setShift(shift);
    simplicial_->factorize(A);
    return factored_ = simplicial_->info() == Eigen::Success && simplicial_->vectorD().minCoeff() > 0;
  }

  // Whether no analysis was made yet (successful or not): factorize() would make one.
  bool needs_analysis() const { return !simplicial_ && !uses_cholmod(); }
  bool is_factored() const { return factored_; }

  // The order in which CHOLMOD eliminates the blocks (block_order[k] is the k-th), for another
  // analysis on the same graph of blocks; empty on Eigen's path.
  const std::vector<int>& block_order() const
  {
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
    if(supernodal_) return supernodal_->block_order();
#endif
    static const std::vector<int> none;
    return none;
  }

  // (A + shift I)^-1 b, after a successful factorize.
  template <class Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    if(b.rows() == 0) return b;
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
    if(supernodal_) return supernodal_->solve(b);
#endif
    return simplicial_->solve(b);
  }

  // The nonzeros of the factor (for benchmarks).
  double factor_nonzeros() const
  {
    if(!factored_) return 0;
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
    if(supernodal_) return supernodal_->cholmod().lnz;
#endif
    return simplicial_ ? double(simplicial_->matrixL().nestedExpression().nonZeros()) : 0.;
  }

private:
  using Simplicial = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Block_AMD_ordering<block>>;
  std::ptrdiff_t cholmod_from_;
  Fill_reducing_order fill_;
  std::unique_ptr<Simplicial> simplicial_;
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
  using Supernodal = Block_ordered_supernodal_llt<block>;
  std::unique_ptr<Supernodal> supernodal_;
#endif
  bool analyzed_ = false, factored_ = false;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SPARSE_CHOLESKY_H
