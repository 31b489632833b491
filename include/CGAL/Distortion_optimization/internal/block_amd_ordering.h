// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The fill-reducing ordering of the triangle meshes' Newton systems
// (global_step/lagged_factorization.h).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BLOCK_AMD_ORDERING_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BLOCK_AMD_ORDERING_H

#include <CGAL/license/Distortion_optimization.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The graph of the n x n blocks of A (the vertices, where A has n unknowns per vertex): entry (i, j)
// where block (i, j) of A has its first column's first entry, diagonal included. The fill-reducing
// orderings of the blocks (below, and CHOLMOD's in sparse_cholesky.h) order it.
template <int n, class MatrixType>
Eigen::SparseMatrix<double> block_graph(const MatrixType& A)
{
  const int blocks = static_cast<int>(A.rows()) / n;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(A.nonZeros()) / (n * n) + 1);
  for(int j = 0; j < blocks; ++j)
    for(typename MatrixType::InnerIterator it(A, n * j); it; ++it)
      if(it.index() % n == 0) entries.emplace_back(static_cast<int>(it.index()) / n, j, 1.);
  Eigen::SparseMatrix<double> graph(blocks, blocks);
  graph.setFromTriplets(entries.begin(), entries.end());
  return graph;
}

// The fill-reducing ordering of a matrix of n x n blocks (the Newton system, n unknowns per
// vertex): Eigen's approximate minimum degree on the graph of the blocks, each block's unknowns
// kept together. An n times smaller graph is ordered about n^2 times faster, with less fill.
template <int n>
struct Block_AMD_ordering
{
  template <class MatrixType>
  void operator()(const MatrixType& A, Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>& permutation) const
  {
    const int blocks = static_cast<int>(A.rows()) / n;
    const Eigen::SparseMatrix<double> graph = block_graph<n>(A);
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> block_permutation;
    Eigen::AMDOrdering<int>()(graph, block_permutation);
    permutation.resize(n * blocks);
    for(int i = 0; i < blocks; ++i)
      for(int a = 0; a < n; ++a) permutation.indices()[n * i + a] = n * block_permutation.indices()[i] + a;
  }
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BLOCK_AMD_ORDERING_H
