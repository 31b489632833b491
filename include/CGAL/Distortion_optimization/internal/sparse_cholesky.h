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
#include <memory>
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
// sparse. Eigen's CholmodSupernodalLLT but for the analysis.
template <int block>
class Block_ordered_supernodal_llt
  : public Eigen::CholmodBase<Eigen::SparseMatrix<double>, Eigen::Lower, Block_ordered_supernodal_llt<block>>
{
  using Base = Eigen::CholmodBase<Eigen::SparseMatrix<double>, Eigen::Lower, Block_ordered_supernodal_llt<block>>;
  using Base::m_analysisIsOk;
  using Base::m_cholmod;
  using Base::m_cholmodFactor;
  using Base::m_factorizationIsOk;
  using Base::m_info;

public:
  Block_ordered_supernodal_llt()
  {
    m_cholmod.final_asis = 1;
    m_cholmod.supernodal = CHOLMOD_SUPERNODAL;
  }

  // `given_order`, if not empty, is the order of the blocks to eliminate them in, computed for
  // another matrix on the same graph of blocks (see block_order()); else `fill`'s.
  void analyze(const Eigen::SparseMatrix<double>& A, const std::vector<int>& given_order,
               Fill_reducing_order fill = Fill_reducing_order::NESTED_DISSECTION)
  {
    if(m_cholmodFactor) cholmod_free_factor(&m_cholmodFactor, &m_cholmod);
    m_cholmodFactor = nullptr;
    const int blocks = static_cast<int>(A.rows()) / block;
    bool ok = true;
    if(is_permutation(given_order, blocks)) {
      block_order_ = given_order;
    } else {
      // CHOLMOD reads its lower triangle; METIS ignores the diagonal.
      const Eigen::SparseMatrix<double> graph = block_graph<block>(A);
      cholmod_sparse G = Eigen::viewAsCholmod(graph.selfadjointView<Eigen::Lower>());
      block_order_.assign(static_cast<std::size_t>(blocks), 0);
      ok = blocks == 0 || (fill == Fill_reducing_order::NESTED_DISSECTION
                             ? cholmod_metis(&G, nullptr, 0, 1, block_order_.data(), &m_cholmod)
                             : cholmod_amd(&G, nullptr, 0, block_order_.data(), &m_cholmod));
    }
    std::vector<int> order(static_cast<std::size_t>(A.rows()));
    for(int i = 0; i < blocks; ++i)
      for(int a = 0; a < block; ++a) order[static_cast<std::size_t>(block * i + a)] = block * block_order_[i] + a;
    if(ok) {
      cholmod_sparse M = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
      m_cholmod.nmethods = 1;
      m_cholmod.method[0].ordering = CHOLMOD_GIVEN;
      m_cholmodFactor = cholmod_analyze_p(&M, order.data(), nullptr, 0, &m_cholmod);
      ok = m_cholmodFactor != nullptr;
    }
    this->m_isInitialized = true;
    m_info = ok ? Eigen::Success : Eigen::NumericalIssue;
    m_analysisIsOk = ok;
    m_factorizationIsOk = false;
    if(!ok) block_order_.clear();
  }

  void analyzePattern(const Eigen::SparseMatrix<double>& A) { analyze(A, {}); }

  const std::vector<int>& block_order() const { return block_order_; }

private:
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

  std::vector<int> block_order_;
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
