// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The pieces of a map's boundary and whether one lies inside another. For one connected piece,
// positive cells and a boundary that does not cross itself imply injectivity; pieces apart can
// still come to lie one inside another without any crossing.
//
// The whole boundary (nested()): when no faces cross, a boundary component (faces joined by
// vertices) is inside or outside another piece whole, so one vertex per component is enough: it
// is inside iff a ray from it crosses that piece's boundary an odd number of times. Boxes keep the
// tests to the faces near each ray.
//
// One move (in_closed_simplex()): a move of v changes its piece's image only by the simplices its
// ring's faces sweep (the triangles (old v, new v, w) in 2D, the tetrahedra (old v, new v, w1, w2)
// in 3D: their sum is the difference of the new and old stars as chains), so a move is refused if
// a swept simplex holds a boundary vertex of another piece: a component that comes to lie inside
// had all its vertices swept over; a piece cannot come inside another by one move, as the faces of
// its components away from v keep their place.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_NESTING_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_NESTING_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/boundary_guard/face_geometry.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {
namespace boundary_guard {

// Per face its piece (0, 1, ...) and per boundary component one vertex; all empty with fewer than
// two pieces with boundary.
template <int n>
class Pieces : private Face_geometry<n>
{
  using typename Face_geometry<n>::Face;
  using typename Face_geometry<n>::Box;
  using typename Face_geometry<n>::Box_d;
  using Face_geometry<n>::point;
  using Face_geometry<n>::face_box;
  using Face_geometry<n>::box_d;

public:
  using Simplex = std::array<Vector<n>, n + 1>;   // swept by a face of a moving vertex's ring

  // `piece`: per vertex (of `nv`), a label of its piece of cells (connected_pieces());
  // `is_on_boundary(v)`: whether vertex v is on a face.
  template <class Is_on_boundary>
  void find_components(const std::vector<Face>& faces, const std::vector<std::uint32_t>& piece, std::size_t nv,
                       const Is_on_boundary& is_on_boundary)
  {
    CGAL_precondition(piece.size() == nv);
    std::vector<std::uint32_t> label(nv, 0), root(nv);   // label: 1 + the piece's number
    std::uint32_t pieces = 0;
    face_piece_.resize(faces.size());
    for(std::uint32_t f = 0; f < faces.size(); ++f) {
      std::uint32_t& l = label[piece[faces[f][0]]];
      if(l == 0) l = ++pieces;
      face_piece_[f] = l - 1;
    }
    if(pieces < 2) {
      face_piece_.clear();
      return;
    }
    pieces_ = pieces;
    std::iota(root.begin(), root.end(), 0u);
    for(const Face& f : faces)
      for(int i = 1; i < n; ++i) root[find_root(root, f[i])] = find_root(root, f[0]);
    for(std::uint32_t v = 0; v < nv; ++v)
      if(is_on_boundary(v) && find_root(root, v) == v) components_.push_back(v);
  }

  // Whether there are two or more pieces with boundary.
  bool several() const { return !components_.empty(); }

  std::uint32_t of_face(std::uint32_t f) const { return face_piece_[f]; }

  // Two pieces, the first with a boundary component inside the second, or (0, 0); piece_of(v):
  // the piece of boundary vertex v. Assumes that no faces cross: a component is then inside or
  // outside another piece whole. Boxes (CGAL::box_intersection_d) pair each component with the
  // pieces whose box holds its vertex, then each such pair's ray, up to the piece's box, with the
  // piece's faces it may meet.
  template <class Piece_of>
  std::pair<std::uint32_t, std::uint32_t> nested(const std::vector<Face>& faces, const std::vector<Vector<n>>& target,
                                                 const Piece_of& piece_of) const
  {
    std::vector<Box> piece_box(pieces_);
    std::vector<Box_d> face_boxes, boxes, points;
    face_boxes.reserve(faces.size());
    for(std::uint32_t f = 0; f < faces.size(); ++f) {
      const Box b = face_box(faces[f], target);
      piece_box[face_piece_[f]].extend(b);
      face_boxes.push_back(box_d(b, f));
    }
    for(std::uint32_t q = 0; q < pieces_; ++q) boxes.push_back(box_d(piece_box[q], q));
    for(std::uint32_t c = 0; c < components_.size(); ++c) points.push_back(box_d(Box(target[components_[c]]), c));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;   // (component, another piece whose box holds it)
    CGAL::box_intersection_d(points.begin(), points.end(), boxes.begin(), boxes.end(), [&](const Box_d& point, const Box_d& piece) {
      if(piece.info() != piece_of(components_[point.info()])) pairs.emplace_back(point.info(), piece.info());
    });
    std::vector<Box_d> rays;
    for(std::uint32_t k = 0; k < pairs.size(); ++k) {
      Box ray(target[components_[pairs[k].first]]);
      ray.max()[0] = piece_box[pairs[k].second].max()[0];
      rays.push_back(box_d(ray, k));
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> hits;   // (pair, face of its piece)
    CGAL::box_intersection_d(rays.begin(), rays.end(), face_boxes.begin(), face_boxes.end(), [&](const Box_d& ray, const Box_d& face) {
      if(face_piece_[face.info()] == pairs[ray.info()].second) hits.emplace_back(ray.info(), face.info());
    });
    std::sort(hits.begin(), hits.end());
    for(std::size_t i = 0, j; i < hits.size(); i = j) {
      const auto [c, q] = pairs[hits[i].first];
      int crossings = 0;
      bool on = false;
      for(j = i; j < hits.size() && hits[j].first == hits[i].first; ++j) {
        const int x = ray_crossing(target[components_[c]], faces[hits[j].second], target);
        on = on || x == 2;
        crossings += x == 1;
      }
      if(on || crossings % 2 == 1) return {piece_of(components_[c]), q};
    }
    return {0, 0};
  }

  // Whether the ray from x along +x crosses face f (1) or not (0), x raised by an infinitesimal (eps
  // in y; in 3D, (eps, eps^2) in (y, z)) so that the ray meets no face's vertex or edge (Edelsbrunner
  // and Muecke's simulation of simplicity); 2 when x lies on f. An odd number of crossings with a
  // piece's faces: x inside it.
  static int ray_crossing(const Vector<n>& x, const Face& f, const std::vector<Vector<n>>& t)
  {
    if constexpr(n == 2) {
      const Vector<2>& a = t[f[0]];
      const Vector<2>& b = t[f[1]];
      if((a[1] <= x[1]) == (b[1] <= x[1])) return 0;   // the raised ray passes above or below
      const CGAL::Orientation o = CGAL::orientation(point(f[0], t), point(f[1], t), point(x));
      if(o == CGAL::COLLINEAR) return 2;
      return o == (b[1] > a[1] ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN);   // the face is ahead of x
    } else {
      const auto yz = [](const Vector<3>& p) { return K::Point_2(p[1], p[2]); };
      const CGAL::Orientation s = CGAL::orientation(yz(t[f[0]]), yz(t[f[1]]), yz(t[f[2]]));
      if(s == CGAL::COLLINEAR) return 0;   // parallel to the ray: the raised ray misses it
      // The side of the raised x from each projected edge: the terms of eps and eps^2 break ties.
      const auto side = [&](const Vector<3>& a, const Vector<3>& b) {
        const CGAL::Orientation o = CGAL::orientation(yz(a), yz(b), yz(x));
        if(o != CGAL::COLLINEAR) return o;
        if(a[2] != b[2]) return a[2] > b[2] ? CGAL::POSITIVE : CGAL::NEGATIVE;
        return b[1] > a[1] ? CGAL::POSITIVE : CGAL::NEGATIVE;
      };
      if(side(t[f[0]], t[f[1]]) != s || side(t[f[1]], t[f[2]]) != s || side(t[f[2]], t[f[0]]) != s) return 0;
      // The ray meets the face's plane ahead of x iff x is on the side that +x leaves.
      const CGAL::Orientation o = CGAL::orientation(point(f[0], t), point(f[1], t), point(f[2], t), point(x));
      if(o == CGAL::COPLANAR) return 2;
      return o == -s;
    }
  }

  // Whether x is in the closed convex hull of the n + 1 points of s (exact).
  static bool in_closed_simplex(const Simplex& s, const Vector<n>& x)
  {
    if constexpr(n == 2) {
      const CGAL::Orientation o = CGAL::orientation(point(s[0]), point(s[1]), point(s[2]));
      if(o != CGAL::COLLINEAR) {
        for(int i = 0; i < 3; ++i)
          if(CGAL::orientation(point(s[i]), point(s[(i + 1) % 3]), point(x)) == -o) return false;
        return true;
      }
    } else {
      const CGAL::Orientation o = CGAL::orientation(point(s[0]), point(s[1]), point(s[2]), point(s[3]));
      if(o != CGAL::COPLANAR) {
        for(int i = 0; i < 4; ++i) {
          std::array<Vector<n>, 4> r = s;
          r[i] = x;
          if(CGAL::orientation(point(r[0]), point(r[1]), point(r[2]), point(r[3])) == -o) return false;
        }
        return true;
      }
      // Flat: the union of its non-degenerate triangles, in their plane.
      bool flat = false, in = false;
      for(int skip = 0; skip < 4 && !in; ++skip) {
        std::array<K::Point_3, 3> tri;
        for(int j = 0, k = 0; j < 4; ++j)
          if(j != skip) tri[k++] = point(s[j]);
        if(CGAL::collinear(tri[0], tri[1], tri[2])) continue;
        if(!flat && CGAL::orientation(tri[0], tri[1], tri[2], point(x)) != CGAL::COPLANAR) return false;
        flat = true;
        in = CGAL::coplanar_orientation(tri[0], tri[1], tri[2], point(x)) != CGAL::NEGATIVE &&
             CGAL::coplanar_orientation(tri[1], tri[2], tri[0], point(x)) != CGAL::NEGATIVE &&
             CGAL::coplanar_orientation(tri[2], tri[0], tri[1], point(x)) != CGAL::NEGATIVE;
      }
      if(flat) return in;
    }
    // All on one line: x on it, within the points' box.
    Box hull;
    std::size_t other = 0;
    for(std::size_t i = 0; i <= n; ++i) {
      hull.extend(s[i]);
      if(other == 0 && s[i] != s[0]) other = i;
    }
    if(other == 0) return x == s[0];
    return hull.contains(x) && CGAL::collinear(point(s[0]), point(s[other]), point(x));
  }
private:
  std::vector<std::uint32_t> face_piece_;
  std::uint32_t pieces_ = 0;
  std::vector<std::uint32_t> components_;
};

} // namespace boundary_guard
} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_NESTING_H
