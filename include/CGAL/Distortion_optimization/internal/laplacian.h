// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The volume-weighted cotangent Laplacian of the source, L_ij = sum_c vol(c) grad(l_i).grad(l_j)
// over the hat functions l_i (the Hessian of the Dirichlet energy at rest), for triangles in their
// own frames and for tetrahedra alike: with B = Dm^-1, grad l_i is row i-1 of B (i >= 1) and
// grad l_0 = -(sum of the rows). And the harmonic map it defines for fixed vertices.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LAPLACIAN_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LAPLACIAN_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>

#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n>
Eigen::SparseMatrix<double> cotangent_laplacian(const Simplicial_map<n>& map)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(map.number_of_cells() * (n + 1) * (n + 1));
  for(std::size_t c = 0; c < map.number_of_cells(); ++c) {
    const Eigen::Matrix<double, n, n + 1> G = map.hat_gradients(c);
    const Eigen::Matrix<double, n + 1, n + 1> K = map.rest_volume[c] * G.transpose() * G;
    for(int i = 0; i <= n; ++i)
      for(int j = 0; j <= n; ++j) entries.emplace_back(map.cells[c][i], map.cells[c][j], K(i, j));
  }
  Eigen::SparseMatrix<double> L(map.number_of_vertices(), map.number_of_vertices());
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

// The harmonic map: the targets of free vertices minimize sum_c vol(c) |J_c|^2 with the fixed
// vertices where they are. Returns the new targets (the map is not modified).
template <int n>
std::vector<Vector<n>> harmonic_targets(const Simplicial_map<n>& map, const std::vector<unsigned char>& is_free)
{
  const std::size_t nv = map.number_of_vertices();
  std::vector<int> free_index(nv, -1);
  int nf = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(is_free[v]) free_index[v] = nf++;
  std::vector<Vector<n>> result = map.target;
  if(nf == 0) return result;
  const Eigen::SparseMatrix<double> L = cotangent_laplacian(map);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, n);
  for(int k = 0; k < L.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(L, k); it; ++it) {
      const int i = free_index[it.row()];
      if(i < 0) continue;
      const int j = free_index[it.col()];
      if(j >= 0) entries.emplace_back(i, j, it.value());
      else rhs.row(i) -= it.value() * map.target[it.col()].transpose();
    }
  Eigen::SparseMatrix<double> A(nf, nf);
  A.setFromTriplets(entries.begin(), entries.end());
  // Conjugate gradients with an incomplete Cholesky preconditioner, from the current targets: a
  // direct factorization of a 3D Laplacian fills in badly (tens of seconds at 400K tetrahedra).
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                           Eigen::IncompleteCholesky<double>> solver;
  solver.setTolerance(1e-12);
  solver.setMaxIterations(2000);
  solver.compute(A);
  if(solver.info() != Eigen::Success)
    throw Invalid_input("the harmonic map is not defined: some free vertex is not connected to a fixed one");
  Eigen::MatrixXd guess(nf, n), x(nf, n);
  for(std::size_t v = 0; v < nv; ++v)
    if(free_index[v] >= 0) guess.row(free_index[v]) = map.target[v].transpose();
  for(int d = 0; d < n; ++d) x.col(d) = solver.solveWithGuess(rhs.col(d), guess.col(d));
  if(!x.allFinite())
    throw Invalid_input("the harmonic map is not defined: some free vertex is not connected to a fixed one");
  for(std::size_t v = 0; v < nv; ++v)
    if(free_index[v] >= 0) result[v] = x.row(free_index[v]).transpose();
  return result;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LAPLACIAN_H
