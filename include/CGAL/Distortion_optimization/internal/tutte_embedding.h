// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Tutte's embedding of a triangulated disk: the boundary on a circle, in order, spaced by the
// source's edge lengths, and each inner vertex the mean of its neighbours (Tutte, "How to draw a
// graph", 1963; Floater, "Parametrization and smooth approximation of surface triangulations",
// 1997). It is injective with every triangle positively oriented (in exact arithmetic), whatever
// the start, and so it is with the boundary on any strictly convex polygon: the untangler's last
// resort. For a map with a free boundary when the boundary guard holds a fold in place: an ear of
// the boundary turned inside out can only come right by moving far through the outside, which no
// descent on the barrier finds; with the boundary guard it stays inverted. For a boundary fixed on
// a convex polygon, where the descent ends with cells still inverted (a vertex far outside the
// polygon can leave more cells inverted after the rounds than before them).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TUTTE_EMBEDDING_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TUTTE_EMBEDDING_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/optimization_problem.h>
#include <CGAL/Distortion_optimization/internal/sparse_cholesky.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Tutte's barycentric positions: each vertex v with column[v] >= 0 (the unknowns, numbered 0 to
// size - 1) at the mean of its neighbours, the others where x has them. One symmetric positive
// definite system (the uniform Laplacian of the unknowns) solved for both coordinates by the
// package's sparse Cholesky factorization; false if that fails. The one Tutte solve of the package:
// tutte_embedding() below and initial_parameterization()'s default start.
inline bool barycentric_positions(const std::vector<std::vector<std::uint32_t>>& neighbours, const std::vector<int>& column,
                                  int size, std::vector<Vector<2>>& x)
{
  if(size == 0) return true;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(size, 2);
  for(std::size_t v = 0; v < neighbours.size(); ++v) {
    if(column[v] < 0) continue;
    entries.emplace_back(column[v], column[v], double(neighbours[v].size()));
    for(std::uint32_t w : neighbours[v])
      if(column[w] >= 0) entries.emplace_back(column[v], column[w], -1.);
      else rhs.row(column[v]) += x[w].transpose();
  }
  Eigen::SparseMatrix<double> L(size, size);
  L.setFromTriplets(entries.begin(), entries.end());
  // One solve: the minimum degree's order, which costs less than nested dissection saves.
  Sparse_cholesky<1> factorization(Sparse_cholesky<1>::default_cholmod_from(), Fill_reducing_order::MINIMUM_DEGREE);
  if(!factorization.factorize(L)) return false;
  const Eigen::MatrixXd X = factorization.solve(rhs);
  if(!X.allFinite()) return false;
  for(std::size_t v = 0; v < neighbours.size(); ++v)
    if(column[v] >= 0) x[v] = X.row(column[v]).transpose();
  return true;
}

// Whether the constrained vertices of p are those of the boundary `loop` (`constrained` of them)
// and their targets, in the loop's order, never turn right nor back (exact predicate) and turn once
// around: a convex polygon, counterclockwise as the loop runs for positive cells. Straight
// continuations are allowed, as along the sides of a square: Tutte's embedding is then injective
// unless some inner edge joins two vertices of one side (Floater, "One-to-one piecewise linear
// mappings over triangulations", 2003), which leaves cells flat for the untangling rounds after it.
inline bool is_convex_loop(const Optimization_problem<2>& p, const std::vector<std::uint32_t>& loop, std::size_t constrained)
{
  if(loop.size() != constrained) return false;
  const auto target = [&](std::size_t i) -> const Vector<2>& { return p.map.target[loop[i % loop.size()]]; };
  const auto point = [&](std::size_t i) { return CGAL::Epick::Point_2(target(i)[0], target(i)[1]); };
  double turning = 0;
  for(std::size_t i = 0; i < loop.size(); ++i) {
    const Vector<2> a = target(i + 1) - target(i), b = target(i + 2) - target(i + 1);
    const CGAL::Orientation turn = CGAL::orientation(point(i), point(i + 1), point(i + 2));
    if(p.is_free[loop[i]] || turn == CGAL::RIGHT_TURN || (turn == CGAL::COLLINEAR && !(a.dot(b) > 0))) return false;
    turning += std::atan2(a[0] * b[1] - a[1] * b[0], a.dot(b));
  }
  return std::abs(turning - 2 * M_PI) < M_PI;   // 2 pi k for k turns around
}

// Tutte's embedding of p's mesh into x: with at most three constrained vertices, the boundary on a
// circle, scaled to the area p's cells have at det J = `typical_det`, then moved by the similarity
// (at most two) or the affine map (three) that puts the constrained vertices back on their
// targets; with more, the boundary on the constrained targets, which must then be the boundary's
// vertices on a convex polygon (is_convex_loop(): Tutte's theorem holds for any convex boundary).
// Returns false, x unspecified, where it does not apply: the mesh is not a disk (one piece, one
// boundary loop through every boundary vertex, Euler characteristic 1), more than three vertices are constrained
// and they are not a convex boundary, two constrained vertices share a target, three constrained
// vertices' targets are not as their embedding oriented (no affine map keeping orientations sends
// them there), or the solve fails.
inline bool tutte_embedding(const Optimization_problem<2>& p, double typical_det, std::vector<Vector<2>>& x)
{
  const std::size_t nv = p.number_of_vertices(), nc = p.map.number_of_cells();
  std::vector<std::uint32_t> constrained;
  for(std::uint32_t v = 0; v < nv; ++v)
    if(!p.is_free[v]) constrained.push_back(v);
  if(!p.is_sliding.empty() || nc == 0) return false;

  // Edges as (smaller vertex, larger vertex, cell, position of the edge's first vertex in it).
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, int>> edges;
  for(std::uint32_t c = 0; c < nc; ++c)
    for(int i = 0; i < 3; ++i) {
      const auto a = p.map.cells[c][i], b = p.map.cells[c][(i + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b), c, i);
    }
  std::sort(edges.begin(), edges.end());
  // Boundary edges, directed so that their cell lies on their left once it keeps its orientation.
  std::vector<std::int64_t> next(nv, -1);
  std::vector<double> length(nv, 0);
  std::vector<std::vector<std::uint32_t>> neighbours(nv);
  std::size_t number_of_edges = 0, boundary_edges = 0;
  for(std::size_t i = 0, j; i < edges.size(); i = j) {
    for(j = i + 1; j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
                   std::get<1>(edges[j]) == std::get<1>(edges[i]); ++j) {}
    const auto [u, w, c, k] = edges[i];
    ++number_of_edges;
    neighbours[u].push_back(w), neighbours[w].push_back(u);
    if(j - i > 2) return false;   // a non-manifold edge
    if(j - i == 2) continue;
    auto a = p.map.cells[c][k], b = p.map.cells[c][(k + 1) % 3];
    if(p.map.rest_sign[c] < 0) std::swap(a, b);
    if(next[a] >= 0) return false;   // two boundary loops meet at a
    next[a] = b;
    // The source edge's length, from the cell's rest shape: vertex 0 at the origin, vertex i at Dm's column i - 1.
    const Matrix<2> Dm = p.map.inverse_rest[c].inverse();
    const auto rest = [&](int m) { return m == 0 ? Vector<2>::Zero().eval() : Vector<2>(Dm.col(m - 1)); };
    length[a] = (rest((k + 1) % 3) - rest(k)).norm();
    ++boundary_edges;
  }
  if(boundary_edges == 0 || nv + nc != number_of_edges + 1) return false;
  std::vector<std::uint32_t> loop;
  double perimeter = 0;
  const auto start = static_cast<std::uint32_t>(std::find_if(next.begin(), next.end(), [](std::int64_t w) { return w >= 0; }) - next.begin());
  for(std::uint32_t v = start; loop.size() <= boundary_edges;) {
    loop.push_back(v);
    perimeter += length[v];
    if(next[v] < 0) return false;
    v = static_cast<std::uint32_t>(next[v]);
    if(v == start) break;
  }
  if(loop.size() != boundary_edges || !(perimeter > 0)) return false;   // more than one loop
  // One piece: every vertex joined to the loop (a disk beside a closed surface passes the counts
  // above, and the closed one would be collapsed).
  const std::vector<std::uint32_t> piece = connected_pieces(p.map.cells, nv);
  if(std::any_of(piece.begin(), piece.end(), [&](std::uint32_t r) { return r != piece[loop[0]]; })) return false;

  // More than three constrained vertices: the boundary's, exactly, on a convex polygon.
  const bool onto_targets = constrained.size() > 3;
  if(onto_targets && !is_convex_loop(p, loop, constrained.size())) return false;

  // The boundary on its targets, or on the circle of the area the cells cover at the typical
  // determinant.
  double area = 0;
  for(double a : p.map.rest_volume) area += a;
  const double radius = std::sqrt(area * typical_det / M_PI);
  x.assign(nv, Vector<2>::Zero());
  std::vector<int> column(nv, -1);
  double arc = 0;
  for(std::uint32_t v : loop) {
    const double angle = 2 * M_PI * arc / perimeter;
    x[v] = onto_targets ? p.map.target[v] : Vector<2>(radius * Vector<2>(std::cos(angle), std::sin(angle)));
    arc += length[v];
    column[v] = -2;
  }
  int size = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(column[v] == -1) column[v] = size++;
  if(!barycentric_positions(neighbours, column, size, x)) return false;

  // The affine map, or the similarity (rotation, scale, translation), back to the constrained
  // targets: orientations kept.
  if(constrained.size() == 3) {
    Matrix<2> from, to;
    for(int k = 0; k < 2; ++k) {
      from.col(k) = x[constrained[k + 1]] - x[constrained[0]];
      to.col(k) = p.map.target[constrained[k + 1]] - p.map.target[constrained[0]];
    }
    if(!(from.determinant() * to.determinant() > 0)) return false;
    const Matrix<2> A = to * from.inverse();
    if(!A.allFinite()) return false;
    const Vector<2> origin = x[constrained[0]];
    for(Vector<2>& y : x) y = p.map.target[constrained[0]] + A * (y - origin);
  } else if(constrained.size() == 2) {
    const Vector<2> from = x[constrained[1]] - x[constrained[0]];
    const Vector<2> to = p.map.target[constrained[1]] - p.map.target[constrained[0]];
    if(!(to.norm() > 0) || !(from.norm() > 0)) return false;
    const std::complex<double> z = std::complex<double>(to[0], to[1]) / std::complex<double>(from[0], from[1]);
    const Vector<2> origin = x[constrained[0]];
    for(Vector<2>& y : x) {
      const std::complex<double> r = z * std::complex<double>(y[0] - origin[0], y[1] - origin[1]);
      y = p.map.target[constrained[0]] + Vector<2>(r.real(), r.imag());
    }
  } else if(constrained.size() == 1) {
    const Vector<2> shift = p.map.target[constrained[0]] - x[constrained[0]];
    for(Vector<2>& y : x) y += shift;
  }
  for(std::uint32_t v : constrained) x[v] = p.map.target[v];   // bit-identical
  return true;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TUTTE_EMBEDDING_H
