// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A simplicial map as flat arrays (section 2.2 of the paper): cells, the inverse of each source
// cell's edge matrix (so that J = Ds * Dm^-1, eq. 20), rest volumes and target positions.
// No CGAL mesh type appears here: adapters fill it, the kernel and solvers read it.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SIMPLICIAL_MAP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SIMPLICIAL_MAP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>
#include <CGAL/Distortion_optimization/internal/scaling.h>
#include <CGAL/Distortion_optimization/number_types.h>

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The largest extent of the bounding box of `points` (0 for none).
template <class Point>
double largest_extent(const std::vector<Point>& points)
{
  if(points.empty()) return 0;
  Point low = points[0], high = points[0];
  for(const Point& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).maxCoeff();
}

// Throws unless the source and the target are of sizes within 2^largest_size_ratio_exponent<n>:
// the kernels form products of up to 3n singular values of the Jacobian, about the size ratio
// each, whatever the common scale of coordinate_scale().
template <int n>
void check_comparable_sizes(double source_size, double target_size)
{
  constexpr int limit = largest_size_ratio_exponent<n>;
  if(source_size > 0 && target_size > 0 && std::isfinite(source_size) && std::isfinite(target_size) &&
     std::abs(std::ilogb(source_size) - std::ilogb(target_size)) > limit)
    throw Invalid_input("the target's size (about 2^" + std::to_string(std::ilogb(target_size)) + ") and the source's (2^" +
                        std::to_string(std::ilogb(source_size)) + ") differ by more than 2^" + std::to_string(limit) +
                        ": distortions cannot be evaluated in double precision; scale one of them");
}

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

  void reserve(std::size_t cell_count, std::size_t vertex_count)
  {
    cells.reserve(cell_count);
    inverse_rest.reserve(cell_count);
    rest_volume.reserve(cell_count);
    rest_sign.reserve(cell_count);
    target.reserve(vertex_count);
  }

  // `sign` is the orientation of the source cell (+1 or -1), decided by the adapter with an exact
  // predicate (a floating-point determinant may get a nearly flat cell's wrong). Returns false,
  // adding nothing, where the cell is flat in doubles: its edges Dm, rounded, have a zero
  // determinant or no finite inverse (vertices so nearly collinear or coplanar that no measure can
  // be evaluated on the cell).
  bool add_cell(const Cell& cell, const Matrix<n>& Dm, int sign)
  {
    resize_cells(cells.size() + 1);
    if(set_cell(cells.size() - 1, cell, Dm, sign)) return true;
    resize_cells(cells.size() - 1);
    return false;
  }

  // The cells' arrays sized for `count` cells, for set_cell() to fill.
  void resize_cells(std::size_t count)
  {
    cells.resize(count);
    inverse_rest.resize(count);
    rest_volume.resize(count);
    rest_sign.resize(count);
  }
  // add_cell() in place, for cell k of arrays sized by resize_cells() (the complex's adapter sizes
  // them once). Returns false, leaving cell k as it was, where add_cell() would.
  bool set_cell(std::size_t k, const Cell& cell, const Matrix<n>& Dm, int sign)
  {
    const double det = Dm.determinant();
    const Matrix<n> inverse = Dm.inverse();
    if(!(det != 0) || !inverse.allFinite()) return false;
    cells[k] = cell;
    inverse_rest[k] = inverse;
    rest_volume[k] = std::abs(det) / (n == 2 ? 2. : 6.);
    rest_sign[k] = static_cast<signed char>(sign > 0 ? 1 : -1);
    return true;
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
  // det J_c, positive when the image keeps the source's orientation.
  double jacobian_determinant(std::size_t c) const { return target_edges(c).determinant() * inverse_rest[c].determinant(); }

  // The gradients of the hat functions of cell c's vertices (columns): vertex_derivative of Dm^-T.
  Eigen::Matrix<double, n, n + 1> hat_gradients(std::size_t c) const
  {
    const Matrix<n> M = inverse_rest[c].transpose();
    Eigen::Matrix<double, n, n + 1> G;
    for(int i = 0; i <= n; ++i) G.col(i) = vertex_derivative(M, i);
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

// The point of the traits' kernel at x (a Point_2 or a Point_3).
template <class GeomTraits, int n>
auto to_point(const Vector<n>& x)
{
  if constexpr(n == 2) return typename GeomTraits::Point_2(x[0], x[1]);
  else return typename GeomTraits::Point_3(x[0], x[1], x[2]);
}

// Orientation of the target image of cell c by the geometric traits' predicate (exact with CGAL's
// kernels, which is what the guarantees rest on): +1, 0 or -1.
template <int n, class GeomTraits>
int target_orientation(const Simplicial_map<n>& map, std::size_t c, const GeomTraits& traits)
{
  const auto& cell = map.cells[c];
  const auto& x = map.target;
  const auto p = [&](int i) { return to_point<GeomTraits>(x[cell[i]]); };
  if constexpr(n == 2) return static_cast<int>(traits.orientation_2_object()(p(0), p(1), p(2)));
  else return static_cast<int>(traits.orientation_3_object()(p(0), p(1), p(2), p(3)));
}

// A target cell is inverted (or degenerate) unless its orientation is the source's.
template <int n, class GeomTraits>
bool is_inverted(const Simplicial_map<n>& map, std::size_t c, const GeomTraits& traits)
{
  return target_orientation(map, c, traits) != map.rest_sign[c];
}

// Whether cell c, valid or not by the exact predicate, is too close to flat for the measures'
// floating-point det J_c (of the Jacobian as they compute it) to have a reliable sign: det J_c at
// most 1e-12 |J_c|^n, a thousand times the rounding error of the determinant. A normalized
// measure may be infinite on such a cell although its orientation is right.
template <int n>
bool is_numerically_flat(const Simplicial_map<n>& map, std::size_t c)
{
  const Matrix<n> J = map.jacobian(c);
  const double norm2 = J.squaredNorm();
  return !(J.determinant() > 1e-12 * (n == 2 ? norm2 : norm2 * std::sqrt(norm2)));
}

// Whether cell c's image, valid or not, is so thin that moving its vertices by a few units in the
// last place of their coordinates (decimal output read back, a change of units) could invert it:
// its signed volume, in its source's orientation, is at most 64 such moves' worth (the change of
// det E under moves of length d is at most d times the sum of the gradients' norms, the opposite
// edges' lengths in 2D, twice the opposite faces' areas in 3D).
template <int n>
bool is_fragile(const Simplicial_map<n>& map, std::size_t c)
{
  const auto& cell = map.cells[c];
  const Matrix<n> E = map.target_edges(c);
  double largest = 0;
  for(auto v : cell) largest = std::max(largest, map.target[v].cwiseAbs().maxCoeff());
  double gradients;
  if constexpr(n == 2) {
    gradients = E.col(0).norm() + E.col(1).norm() + (E.col(1) - E.col(0)).norm();
  } else {
    const Vector<3> a = E.col(0), b = E.col(1), d = E.col(2);
    gradients = a.cross(b).norm() + b.cross(d).norm() + d.cross(a).norm() + (b - a).cross(d - a).norm();
  }
  const double move = 64 * std::numeric_limits<double>::epsilon() * largest * std::sqrt(double(n));
  return !(map.rest_sign[c] * E.determinant() > move * gradients);
}

// Union-find's root, halving the path on the way.
inline std::uint32_t find_root(std::vector<std::uint32_t>& root, std::uint32_t v)
{
  while(root[v] != v) v = root[v] = root[root[v]];
  return v;
}

// Per vertex, the root of its piece: the vertices of cells joined through shared vertices share it
// (a vertex in no cell is its own).
template <std::size_t k>
std::vector<std::uint32_t> connected_pieces(const std::vector<std::array<std::uint32_t, k>>& cells, std::size_t nv)
{
  std::vector<std::uint32_t> piece(nv);
  for(std::uint32_t v = 0; v < nv; ++v) piece[v] = v;
  for(const auto& cell : cells)
    for(std::size_t i = 1; i < k; ++i) piece[find_root(piece, cell[i])] = find_root(piece, cell[0]);
  for(std::uint32_t v = 0; v < nv; ++v) piece[v] = find_root(piece, v);
  return piece;
}

// Pieces of a triangle map's mesh that no map into the plane can take: one without border (a closed
// surface) keeps the orientation of all its triangles under no map (the image of a locally
// injective map would be open, and it is compact), so no untangling can succeed; one with handles
// (genus > 0) under no injective map (keeping orientations, its border would have to cross
// itself), so none can keep its free border from crossing: counted where `is_free` (if given) has
// a vertex of its border free. Each piece by its lowest cell (-1 for none); genus from its Euler
// characteristic V - E + F = 2 - 2 genus - borders.
struct Planar_obstruction
{
  std::int64_t closed = -1, handles = -1;
  long long genus = 0;   // of the piece with handles
};

inline Planar_obstruction planar_obstruction(const Simplicial_map<2>& map, const std::vector<unsigned char>* is_free = nullptr)
{
  const std::size_t nv = map.target.size(), nc = map.number_of_cells();
  // The cells' pieces, and apart (union-find over the vertices) the border loops.
  std::vector<std::uint32_t> piece = connected_pieces(map.cells, nv), loop(nv);
  for(std::uint32_t v = 0; v < nv; ++v) loop[v] = v;
  // Per piece (at its root): vertices - edges + cells, and border loops.
  std::vector<long long> euler(nv, 0), loops(nv, 0);
  std::vector<unsigned char> free_border(nv, 0);   // per root
  std::vector<unsigned char> used(nv, 0);
  for(const auto& cell : map.cells) {
    ++euler[piece[cell[0]]];
    for(auto v : cell) used[v] = 1;
  }
  for(std::uint32_t v = 0; v < nv; ++v)
    if(used[v]) ++euler[piece[v]];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;   // (smaller vertex, larger vertex)
  edges.reserve(3 * nc);
  for(const auto& cell : map.cells)
    for(int i = 0; i < 3; ++i) edges.emplace_back(std::minmax(cell[i], cell[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::vector<unsigned char> on_border(nv, 0);
  for(std::size_t i = 0, j; i < edges.size(); i = j) {
    for(j = i + 1; j < edges.size() && edges[j] == edges[i]; ++j) {}
    --euler[piece[edges[i].first]];
    if(j == i + 1) {   // a border edge
      loop[find_root(loop, edges[i].first)] = find_root(loop, edges[i].second);
      on_border[edges[i].first] = on_border[edges[i].second] = 1;
    }
  }
  for(std::uint32_t v = 0; v < nv; ++v) {
    if(on_border[v] && find_root(loop, v) == v) ++loops[piece[v]];
    if(on_border[v] && (!is_free || (*is_free)[v])) free_border[piece[v]] = 1;
  }
  Planar_obstruction o;
  for(std::size_t c = 0; c < nc; ++c) {
    const std::uint32_t root = piece[map.cells[c][0]];
    const long long genus = (2 - euler[root] - loops[root]) / 2;
    if(o.closed < 0 && loops[root] == 0) o.closed = static_cast<std::int64_t>(c);
    if(o.handles < 0 && free_border[root] && genus > 0) o.handles = static_cast<std::int64_t>(c), o.genus = genus;
  }
  return o;
}

// Why a map with the closed piece of cell `c` cannot be untangled.
inline std::string closed_piece_message(std::int64_t c)
{
  return "the piece of the mesh with cell " + std::to_string(c) + " has no border (a closed surface), and no map of a "
         "closed surface into the plane keeps the orientation of all its triangles: no untangling can help (cut it open)";
}

// Why no injective map of the piece with cell `c` and `genus` handles into the plane exists.
inline std::string handles_message(std::int64_t c, long long genus)
{
  return "the piece of the mesh with cell " + std::to_string(c) + " has " + std::to_string(genus) +
         (genus == 1 ? " handle" : " handles") + " (genus " + std::to_string(genus) + "), and no map of it into the plane "
         "is injective: its free border cannot be kept from crossing itself (fix the border, or cut the handles open)";
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_SIMPLICIAL_MAP_H
