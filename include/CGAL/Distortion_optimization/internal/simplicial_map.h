// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A simplicial map as flat arrays (section 2.2 of the paper): cells, the inverse of each source
// cell's edge matrix (so that J = Ds * Dm^-1, eq. 20), rest volumes and target positions.
// No CGAL mesh type appears here: adapters fill it, the kernel and solvers read it.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SIMPLICIAL_MAP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SIMPLICIAL_MAP_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/svd.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/LU>

#include <array>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n>
struct Simplicial_map
{
  using Index = std::uint32_t;
  using Cell = std::array<Index, n + 1>;

  std::vector<Cell> cells;
  std::vector<Matrix<n>> inverse_rest;   // Dm^-1, Dm = source edges (v_i - v_0) in the cell's frame
  std::vector<double> rest_volume;       // |det Dm| / n!
  std::vector<signed char> rest_sign;    // sign of det Dm: the orientation a non-inverted image keeps
  std::vector<Vector<n>> target;         // one position per vertex

  std::size_t number_of_cells() const { return cells.size(); }
  std::size_t number_of_vertices() const { return target.size(); }

  // Dm must be invertible (adapters check source cells with exact predicates first).
  void add_cell(const Cell& cell, const Matrix<n>& Dm)
  {
    const double det = Dm.determinant();
    cells.push_back(cell);
    inverse_rest.push_back(Dm.inverse());
    rest_volume.push_back(std::abs(det) / (n == 2 ? 2. : 6.));
    rest_sign.push_back(det > 0 ? 1 : -1);
  }

  Matrix<n> target_edges(std::size_t c) const
  {
    const Cell& cell = cells[c];
    Matrix<n> Ds;
    for(int i = 0; i < n; ++i)
      Ds.col(i) = target[cell[i + 1]] - target[cell[0]];
    return Ds;
  }

  Matrix<n> jacobian(std::size_t c) const { return target_edges(c) * inverse_rest[c]; }

  // The gradients of the hat functions of cell c's vertices (columns): with B = Dm^-1, row i-1 of
  // B for vertex i >= 1, and minus their sum for vertex 0.
  Eigen::Matrix<double, n, n + 1> hat_gradients(std::size_t c) const
  {
    Eigen::Matrix<double, n, n + 1> G;
    G.template rightCols<n>() = inverse_rest[c].transpose();
    G.col(0) = -G.template rightCols<n>().rowwise().sum();
    return G;
  }
};

// The edges of a triangle of R^3 in its own 2D frame: e1 along the x axis, the triangle in the
// upper half plane, so the frame orientation is always positive (surfaces carry no other).
inline Matrix<2> triangle_frame_edges(const Vector<3>& e1, const Vector<3>& e2)
{
  const double l1 = e1.norm();
  Matrix<2> Dm;
  Dm << l1, e1.dot(e2) / l1,
        0., e1.cross(e2).norm() / l1;
  return Dm;
}

// omega(v) for the vertices of a map (handles in index order) from a vertex property map; throws
// unless every weight is finite and positive.
template <class Handles, class VertexWeightMap>
std::vector<double> vertex_weights(const Handles& vertex_of, const VertexWeightMap& weights)
{
  std::vector<double> w;
  w.reserve(vertex_of.size());
  for(const auto& v : vertex_of) {
    w.push_back(static_cast<double>(get(weights, v)));
    if(!(w.back() > 0) || !std::isfinite(w.back()))
      throw Invalid_input("vertex " + std::to_string(w.size() - 1) + " has a weight that is not finite and positive");
  }
  return w;
}

// Orientation of the target image of cell c with CGAL's exact predicate: +1, 0 or -1.
template <int n>
int exact_target_orientation(const Simplicial_map<n>& map, std::size_t c)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto& cell = map.cells[c];
  const auto& x = map.target;
  if constexpr(n == 2) {
    auto p = [&](int i) { return K::Point_2(x[cell[i]][0], x[cell[i]][1]); };
    return static_cast<int>(CGAL::orientation(p(0), p(1), p(2)));
  } else {
    auto p = [&](int i) { return K::Point_3(x[cell[i]][0], x[cell[i]][1], x[cell[i]][2]); };
    return static_cast<int>(CGAL::orientation(p(0), p(1), p(2), p(3)));
  }
}

// A target cell is inverted (or degenerate) unless its exact orientation is the source's.
template <int n>
bool is_inverted(const Simplicial_map<n>& map, std::size_t c)
{
  return exact_target_orientation(map, c) != map.rest_sign[c];
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SIMPLICIAL_MAP_H
