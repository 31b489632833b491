// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Global injectivity with a free boundary (section 3.2, Fig. 7): a positively oriented simplicial
// map is injective iff its boundary (segments in 2D, triangles in 3D) does not self-intersect
// (Aigerman and Lipman 2013). The guard tells the line search whether a trial position keeps it so.
//
// Moving boxes. A small bounding volume hierarchy stores, per face, its box enlarged by a margin
// (a quarter of its size) at rebuild(). Invariant: each face's current box lies in its stored box,
// except for the faces of the vertex on trial. A query tests the CURRENT box of the moved vertex's
// faces against the STORED ones, so no face that may touch them is missed, then runs exact tests
// (CGAL Epick predicates) on current positions. commit_move() restores the invariant: a face that
// left its stored box gets a fresh enlarged one and its ancestors grow to contain it (O(log B)
// refit). Boxes only grow, so after B/4 refits the tree is rebuilt: O(log B) amortized per commit.
// CGAL::AABB_tree cannot refit a single leaf (and is 3D only), hence this tree; is_injective() runs
// CGAL::box_self_intersection_d on current boxes. Not thread-safe: queries share scratch space.
//
// Several pieces. For one connected piece, positive cells and a boundary that does not cross itself
// imply injectivity; pieces apart can still come to lie one inside another without any crossing.
// Given the pieces (per-vertex labels), is_injective() also asks whether a boundary component of
// one piece lies inside another, by the parity of a ray's crossings with that piece's boundary
// (one vertex per component is enough: components that do not cross are inside or outside whole;
// boxes keep the tests to the faces near each ray).
// A move of v changes its piece's image only by the simplices its ring's faces sweep (the
// triangles (old v, new v, w) in 2D, the tetrahedra (old v, new v, w1, w2) in 3D: their sum is the
// difference of the new and old stars as chains), so accepts_move() refuses a move whose swept
// simplices hold a boundary vertex of another piece: a component that comes to lie inside had all
// its vertices swept over; a piece cannot come inside another by one move, as the faces of its
// components away from v keep their place.
//
// Clearance. Moves also keep faces without a common vertex apart by more than 64 units in the last
// place of their coordinates (clearance()): a vertex that stops 1e-19 from another boundary edge
// is outside it in doubles, but may be on it or across once the map is written in decimal and
// read back (a free border that wants to overlap itself pushes vertices that close). Unless the
// map had two faces that close at the last rebuild(): then the exact tests only.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/simplicial_map.h>
#include <CGAL/Distortion_optimization/internal/svd.h>

#include <CGAL/Distance_2/Segment_2_Segment_2.h>
#include <CGAL/Distance_3/Point_3_Triangle_3.h>
#include <CGAL/Distance_3/Segment_3_Segment_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n>
class Boundary_guard
{
  static_assert(n == 2 || n == 3, "segments of a planar triangle map or triangles of a tet map");

public:
  using Face = std::array<std::uint32_t, n>;

  // The (n-1)-faces that belong to exactly one cell, found by sorting facets by their vertex sets.
  static std::vector<Face> boundary_faces(const std::vector<std::array<std::uint32_t, n + 1>>& cells)
  {
    std::vector<std::pair<Face, Face>> facets;   // (sorted vertices, facet as in its cell)
    facets.reserve(cells.size() * (n + 1));
    for(const auto& cell : cells)
      for(int skip = 0; skip <= n; ++skip) {
        Face f;
        for(int j = 0, k = 0; j <= n; ++j)
          if(j != skip) f[k++] = cell[j];
        Face key = f;
        std::sort(key.begin(), key.end());
        facets.emplace_back(key, f);
      }
    std::sort(facets.begin(), facets.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Face> result;
    for(std::size_t i = 0, j; i < facets.size(); i = j) {
      for(j = i + 1; j < facets.size() && facets[j].first == facets[i].first; ++j) {}
      if(j == i + 1) result.push_back(facets[i].second);
    }
    return result;
  }

  // `faces`: the boundary faces (boundary_faces()); `piece`: per vertex, a label of its piece of
  // cells (connected_pieces()), or empty for one piece.
  Boundary_guard(std::vector<Face> faces, std::size_t number_of_vertices, const std::vector<std::uint32_t>& piece = {})
    : faces_(std::move(faces)), first_face_(number_of_vertices + 1, 0)
  {
    for(const Face& f : faces_)
      for(std::uint32_t v : f) {
        CGAL_precondition(v < number_of_vertices);
        ++first_face_[v + 1];
      }
    std::partial_sum(first_face_.begin(), first_face_.end(), first_face_.begin());
    vertex_faces_.resize(first_face_.back());
    std::vector<std::size_t> next(first_face_.begin(), first_face_.end() - 1);
    for(std::uint32_t f = 0; f < faces_.size(); ++f)
      for(std::uint32_t v : faces_[f]) vertex_faces_[next[v]++] = f;
    if(!piece.empty()) find_components(piece);
  }

  bool empty() const { return faces_.empty(); }
  bool is_on_boundary(std::size_t v) const { return first_face_[v + 1] > first_face_[v]; }

  // Needed before the first query; any time after (e.g. after a global step). `clear`: the caller
  // has just found `target` injective with its faces a clearance apart (is_injective(target,
  // nullptr, 1.)), which spares that test here.
  void rebuild(const std::vector<Vector<n>>& target, bool clear = false)
  {
    const std::size_t B = faces_.size();
    std::vector<Box> boxes(B);
    std::vector<Vector<n>> centres(B);
    degenerate_.resize(B);
    for(std::uint32_t f = 0; f < B; ++f) {
      boxes[f] = enlarged(face_box(f, target));
      centres[f] = boxes[f].center();
      degenerate_[f] = is_degenerate(f, target);
    }
    std::vector<std::uint32_t> order(B);
    std::iota(order.begin(), order.end(), 0u);
    nodes_.clear();
    nodes_.reserve(2 * B);
    leaf_.assign(B, 0);
    refits_ = 0;
    if(B > 0) build(order.data(), order.data() + B, -1, boxes, centres);
    if(several_pieces()) committed_ = target;
    // A map whose boundary is already closer to itself than that (given so) keeps the exact tests:
    // below a quarter of the clearance, as distances so small are computed to a few percent. A map
    // with faces between a quarter and the whole of it (moves in exact tests brought them there)
    // keeps it for moves, and the whole boundary's checks take the quarter (clearance_fraction()):
    // at the whole, every trial of a global step fails on that pair (with holds: 38 trials a step).
    if(clear || is_injective(target, nullptr, 1.)) clearance_fraction_ = 1;
    else clearance_fraction_ = is_injective(target, nullptr, 0.25) ? 0.25 : 0.;
  }

  // Whether moves keep faces apart by their clearance (see the header), as the map had them at the
  // last rebuild().
  bool keeps_clearance() const { return clearance_fraction_ > 0; }
  // The fraction of the clearance that the map kept at the last rebuild() (1, 0.25 or 0), which
  // moves keep: what a check of the whole boundary after moves of many vertices asks for.
  double clearance_fraction() const { return clearance_fraction_; }

  // Whether the trial position target[v] keeps the boundary injective. Only v may have moved since
  // the last rebuild() or commit_move(): the state then is assumed injective.
  bool accepts_move(std::size_t v, const std::vector<Vector<n>>& target)
  {
    CGAL_precondition(nodes_.size() == 2 * faces_.size() - (faces_.empty() ? 0 : 1));
    if(!is_on_boundary(v)) return true;
    if(!target[v].allFinite()) return false;
    const std::uint32_t* ring = vertex_faces_.data() + first_face_[v];
    const std::uint32_t* ring_end = vertex_faces_.data() + first_face_[v + 1];
    const double fraction = keeps_clearance() ? 1. : 0.;   // of the clearance moves keep
    // The ring's faces may have left their stored boxes: test them against each other directly.
    for(const std::uint32_t* f = ring; f != ring_end; ++f) {
      if(is_degenerate(*f, target)) return false;
      for(const std::uint32_t* g = ring; g != f; ++g)
        if(improper(*f, *g, target, fraction)) return false;
    }
    // Then one traversal for the whole ring (the star's box), each candidate against each ring
    // face; boxes grown by twice the ring's clearance, which bounds any candidate's near it.
    ring_boxes_.clear();
    Box star;
    for(const std::uint32_t* f = ring; f != ring_end; ++f) {
      ring_boxes_.push_back(face_box(*f, target));
      star.extend(ring_boxes_.back());
    }
    const double near = 2 * fraction * clearance(star);
    for(Box& b : ring_boxes_) b = grown(b, near);
    star = grown(star, near);
    const bool apart = visit(star, [&](std::uint32_t g) {   // false stops the traversal
      if(contains(g, v)) return true;
      const Box box = face_box(g, target);
      if(!box.intersects(star)) return true;
      if(degenerate_[g]) return false;
      for(std::size_t i = 0; i < ring_boxes_.size(); ++i)
        if(box.intersects(ring_boxes_[i]) && improper(ring[i], g, target, fraction)) return false;
      return true;
    });
    return apart && (!several_pieces() || sweeps_no_other_piece(v, target));
  }

  // To call once a move of v is accepted (target holds v's new position).
  void commit_move(std::size_t v, const std::vector<Vector<n>>& target)
  {
    if(several_pieces()) committed_[v] = target[v];
    for(std::size_t i = first_face_[v]; i < first_face_[v + 1]; ++i) {
      const std::uint32_t f = vertex_faces_[i];
      degenerate_[f] = is_degenerate(f, target);
      const Box now = face_box(f, target);
      std::int32_t node = leaf_[f];
      if(nodes_[node].box.contains(now)) continue;
      const Box stored = enlarged(now);
      nodes_[node].box = stored;
      // Ancestors grow until one already holds the new box (then all above it do too).
      for(node = nodes_[node].parent; node >= 0 && !nodes_[node].box.contains(stored);
          node = nodes_[node].parent)
        nodes_[node].box.extend(stored);
      ++refits_;
    }
    if(refits_ > faces_.size() / 4 + 16) rebuild(target);
  }

  // The whole boundary, for moves of many vertices at once: O(B log B) boxes plus exact tests, and
  // with several pieces, when nothing crosses, the ray tests of each component against the pieces
  // whose box holds it. If `crossing` is given, it receives the vertices of every face that is
  // degenerate or meets another improperly (not only the first found), or else of the boundaries of
  // two pieces one inside the other, so that a caller may hold them back. With a positive
  // `clearance_fraction` (a move's check: 1), faces closer than that fraction of their clearance()
  // count as meeting. `nested`, if given, tells whether it fails by two pieces one inside the other
  // only (then `crossing` holds the whole boundaries of both).
  bool is_injective(const std::vector<Vector<n>>& target, std::vector<std::uint32_t>* crossing = nullptr,
                    double clearance_fraction = 0, bool* nested = nullptr) const
  {
    if(crossing) crossing->clear();
    if(nested) *nested = false;
    const auto report = [&](std::uint32_t f) {
      if(crossing) crossing->insert(crossing->end(), faces_[f].begin(), faces_[f].end());
    };
    std::vector<Box_d> boxes;
    boxes.reserve(faces_.size());
    bool injective = true;
    for(std::uint32_t f = 0; f < faces_.size(); ++f) {
      bool finite = true;
      for(std::uint32_t v : faces_[f]) finite = finite && target[v].allFinite();
      if(!finite || is_degenerate(f, target)) {
        injective = false;
        report(f);
        if(!crossing) return false;
        continue;
      }
      const Box b = face_box(f, target);
      boxes.push_back(box_d(grown(b, clearance_fraction * clearance(b)), f));
    }
    // A callback cannot stop box_self_intersection_d: without `crossing`, it skips the tests once
    // one crossing is found.
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box_d& a, const Box_d& b) {
      if((injective || crossing) && improper(a.info(), b.info(), target, clearance_fraction)) {
        injective = false;
        report(a.info());
        report(b.info());
      }
    });
    if(!injective || !several_pieces()) return injective;
    const std::pair<std::uint32_t, std::uint32_t> pair = nested_pieces(target);
    if(pair.first == pair.second) return true;
    if(nested) *nested = true;
    for(std::uint32_t f = 0; f < faces_.size(); ++f)
      if(face_piece_[f] == pair.first || face_piece_[f] == pair.second) report(f);
    return false;
  }

  // Whether the guard knows of two or more pieces with boundary.
  bool several_pieces() const { return !components_.empty(); }

  // The squared distance of two faces that do not meet, the same for (e, g) and (g, e): a move's
  // check and the whole boundary's see a pair in either order. Triangles: the least over each
  // vertex to the other triangle and each edge to each edge of the other, each of those both ways:
  // CGAL 5.5's distances in doubles depend on the order of their arguments (two segments 1e-13
  // apart: 43% of random pairs differ, some by the whole distance). Faces of a free boundary
  // pressed together were 4.6e-13 apart one way and 0 the other (64 ulps were 1.5e-13 there); on
  // CGAL's femur.off (--start radial --boundary slide) local moves brought a pair within the
  // clearance one way that the global step's check then saw the other way, at its start: every
  // later trial failed (38 trials, 8 s a step, from iteration 51 on).
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  static double squared_distance(const K::Segment_2& e, const K::Segment_2& g)
  {
    return std::min(CGAL::squared_distance(e, g), CGAL::squared_distance(g, e));
  }
  static double squared_distance(const K::Triangle_3& e, const K::Triangle_3& g)
  {
    double d = infinity;
    for(int i = 0; i < 3; ++i) {
      d = std::min({d, CGAL::squared_distance(e.vertex(i), g), CGAL::squared_distance(g.vertex(i), e)});
      const K::Segment_3 edge(e.vertex(i), e.vertex((i + 1) % 3));
      for(int j = 0; j < 3; ++j) {
        const K::Segment_3 other(g.vertex(j), g.vertex((j + 1) % 3));
        d = std::min({d, CGAL::squared_distance(edge, other), CGAL::squared_distance(other, edge)});
      }
    }
    return d;
  }

  // Whether two triangles are certainly more than d >= 0 apart (so that they neither meet nor
  // come within d), by a separating axis in doubles: a triangle's normal, or the normal of one of
  // its edges within its plane, which parts the disjoint and nearly coplanar faces that a smooth
  // boundary puts side by side. `rounding` bounds the rounding of the projections and is added to
  // d: 64 units in the last place of the largest coordinate of the six points (the error analysis
  // gives under 25), or more, as the clearance() of their box. A yes is certain; a no leaves the
  // pair to the exact tests (Gottschalk, Lin and Manocha's separating axes, 1996, with a margin).
  static bool apart(const std::array<Vector<3>, 3>& a, const std::array<Vector<3>, 3>& b, double d, double rounding)
  {
    const double slack = d + rounding;
    const auto separates = [&](const Vector<3>& axis) {
      double a_low = infinity, a_high = -infinity, b_low = infinity, b_high = -infinity;
      for(int i = 0; i < 3; ++i) {
        const double x = axis.dot(a[i] - a[0]), y = axis.dot(b[i] - a[0]);
        a_low = std::min(a_low, x), a_high = std::max(a_high, x);
        b_low = std::min(b_low, y), b_high = std::max(b_high, y);
      }
      const double margin = slack * axis.norm();
      return b_low - a_high > margin || a_low - b_high > margin;
    };
    const Vector<3> na = (a[1] - a[0]).cross(a[2] - a[0]), nb = (b[1] - b[0]).cross(b[2] - b[0]);
    if(separates(na) || separates(nb)) return true;
    for(int i = 0; i < 3; ++i)
      if(separates(na.cross(a[(i + 1) % 3] - a[i])) || separates(nb.cross(b[(i + 1) % 3] - b[i]))) return true;
    return false;
  }

private:
  using Box = Eigen::AlignedBox<double, n>;
  using Box_d = CGAL::Box_intersection_d::Box_with_info_d<double, n, std::uint32_t>;   // box_intersection_d's
  struct Node
  {
    Box box;
    std::int32_t parent;
    std::array<std::int32_t, 2> child;   // a leaf holds child[0] = -1 - face
  };
  static constexpr double margin = 0.25;   // of a face's largest box extent

  std::vector<Face> faces_;
  std::vector<std::size_t> first_face_;      // faces of v: vertex_faces_[first_face_[v], first_face_[v + 1])
  std::vector<std::uint32_t> vertex_faces_;
  std::vector<Node> nodes_;                  // root is nodes_[0]
  std::vector<std::int32_t> leaf_;           // node of each face
  std::vector<unsigned char> degenerate_;    // per face, as of its last rebuild() or commit_move()
  std::size_t refits_ = 0;
  double clearance_fraction_ = 0;
  std::vector<std::int32_t> stack_;          // scratch of accepts_move()
  std::vector<Box> ring_boxes_;
  // With several pieces (all empty otherwise): per face its piece (0, 1, ...), per boundary
  // component (faces joined by vertices) one vertex, and the positions of the last rebuild() or
  // commit_move(), where accepts_move()'s sweeps start.
  std::vector<std::uint32_t> face_piece_;
  std::uint32_t pieces_ = 0;
  std::vector<std::uint32_t> components_;
  std::vector<Vector<n>> committed_;
  std::vector<std::array<Vector<n>, n + 1>> swept_;   // scratch of accepts_move()

  void find_components(const std::vector<std::uint32_t>& piece)
  {
    const std::size_t nv = first_face_.size() - 1;
    CGAL_precondition(piece.size() == nv);
    std::vector<std::uint32_t> label(nv, 0), root(nv);   // label: 1 + the piece's number
    std::uint32_t pieces = 0;
    face_piece_.resize(faces_.size());
    for(std::uint32_t f = 0; f < faces_.size(); ++f) {
      std::uint32_t& l = label[piece[faces_[f][0]]];
      if(l == 0) l = ++pieces;
      face_piece_[f] = l - 1;
    }
    if(pieces < 2) {
      face_piece_.clear();
      return;
    }
    pieces_ = pieces;
    std::iota(root.begin(), root.end(), 0u);
    for(const Face& f : faces_)
      for(int i = 1; i < n; ++i) root[find_root(root, f[i])] = find_root(root, f[0]);
    for(std::uint32_t v = 0; v < nv; ++v)
      if(is_on_boundary(v) && find_root(root, v) == v) components_.push_back(v);
  }

  std::uint32_t piece_of(std::size_t v) const { return face_piece_[vertex_faces_[first_face_[v]]]; }

  // Two pieces, the first with a boundary component inside the second, or (0, 0). Assumes that no
  // faces cross: a component is then inside or outside another piece whole. Boxes
  // (CGAL::box_intersection_d) pair each component with the pieces whose box holds its vertex, then
  // each such pair's ray, up to the piece's box, with the piece's faces it may meet.
  std::pair<std::uint32_t, std::uint32_t> nested_pieces(const std::vector<Vector<n>>& target) const
  {
    std::vector<Box> piece_box(pieces_);
    std::vector<Box_d> face_boxes, boxes, points;
    face_boxes.reserve(faces_.size());
    for(std::uint32_t f = 0; f < faces_.size(); ++f) {
      const Box b = face_box(f, target);
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
        const int x = ray_crossing(target[components_[c]], faces_[hits[j].second], target);
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
  int ray_crossing(const Vector<n>& x, const Face& f, const std::vector<Vector<n>>& t) const
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

  // Whether the simplices the ring of v sweeps from committed_[v] to target[v] hold no boundary
  // vertex of another piece (closed simplices).
  bool sweeps_no_other_piece(std::size_t v, const std::vector<Vector<n>>& target)
  {
    swept_.clear();
    Box region;
    for(std::size_t i = first_face_[v]; i < first_face_[v + 1]; ++i) {
      std::array<Vector<n>, n + 1> s;
      s[0] = committed_[v];
      s[1] = target[v];
      for(int j = 0, k = 2; j < n; ++j)
        if(faces_[vertex_faces_[i]][j] != v) s[k++] = target[faces_[vertex_faces_[i]][j]];
      for(const Vector<n>& p : s) region.extend(p);
      swept_.push_back(s);
    }
    const std::uint32_t own = piece_of(v);
    return visit(region, [&](std::uint32_t g) {
      if(face_piece_[g] == own) return true;
      for(std::uint32_t u : faces_[g])
        if(region.contains(target[u]))
          for(const auto& s : swept_)
            if(in_closed_simplex(s, target[u])) return false;
      return true;
    });
  }

  // Whether x is in the closed convex hull of the n + 1 points of s (exact).
  static bool in_closed_simplex(const std::array<Vector<n>, n + 1>& s, const Vector<n>& x)
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

  static Box_d box_d(const Box& b, std::uint32_t info)
  {
    double lo[n], hi[n];
    for(int i = 0; i < n; ++i) lo[i] = b.min()[i], hi[i] = b.max()[i];
    return Box_d(lo, hi, info);
  }

  Box face_box(std::uint32_t f, const std::vector<Vector<n>>& target) const
  {
    Box b(target[faces_[f][0]]);
    for(int i = 1; i < n; ++i) b.extend(target[faces_[f][i]]);
    return b;
  }

  // 64 units in the last place of the box's largest coordinate, times sqrt(n): the distance a few
  // roundings of each coordinate can move a point.
  static double clearance(const Box& b)
  {
    const double largest = std::max(b.min().cwiseAbs().maxCoeff(), b.max().cwiseAbs().maxCoeff());
    return 64 * std::numeric_limits<double>::epsilon() * largest * std::sqrt(double(n));
  }

  static Box grown(Box b, double d)
  {
    b.min().array() -= d;
    b.max().array() += d;
    return b;
  }

  static Box enlarged(Box b)
  {
    const double m = margin * b.sizes().maxCoeff();
    b.min().array() -= m;
    b.max().array() += m;
    return b;
  }

  bool contains(std::uint32_t f, std::size_t v) const
  {
    return std::find(faces_[f].begin(), faces_[f].end(), v) != faces_[f].end();
  }

  // Median split on the longest axis of the centres: depth ceil(log2 B).
  std::int32_t build(std::uint32_t* begin, std::uint32_t* end, std::int32_t parent,
                     const std::vector<Box>& boxes, const std::vector<Vector<n>>& centres)
  {
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(Node{Box(), parent, {{0, 0}}});
    if(end - begin == 1) {
      nodes_[index].box = boxes[*begin];
      nodes_[index].child[0] = -1 - static_cast<std::int32_t>(*begin);
      leaf_[*begin] = index;
      return index;
    }
    Box span;
    for(const std::uint32_t* f = begin; f != end; ++f) span.extend(centres[*f]);
    int axis = 0;
    span.sizes().maxCoeff(&axis);
    std::uint32_t* mid = begin + (end - begin) / 2;
    std::nth_element(begin, mid, end,
                     [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
    const std::int32_t left = build(begin, mid, index, boxes, centres);
    const std::int32_t right = build(mid, end, index, boxes, centres);
    nodes_[index].child = {{left, right}};
    nodes_[index].box = nodes_[left].box.merged(nodes_[right].box);
    return index;
  }

  // Calls report(face) for each face whose stored box meets `query` (closed boxes) until it
  // returns false; returns false iff stopped.
  template <class Report>
  bool visit(const Box& query, const Report& report)
  {
    if(nodes_.empty()) return true;
    stack_.assign(1, 0);
    while(!stack_.empty()) {
      const Node& node = nodes_[stack_.back()];
      stack_.pop_back();
      if(!node.box.intersects(query)) continue;
      if(node.child[0] < 0) {
        if(!report(static_cast<std::uint32_t>(-1 - node.child[0]))) return false;
      } else {
        stack_.push_back(node.child[0]);
        stack_.push_back(node.child[1]);
      }
    }
    return true;
  }

  static auto point(const Vector<n>& x) { return to_point<K>(x); }
  static auto point(std::uint32_t v, const std::vector<Vector<n>>& t) { return point(t[v]); }

  // A face with coincident (2D) or collinear (3D) vertices: its cell is degenerate, so no injectivity.
  bool is_degenerate(std::uint32_t f, const std::vector<Vector<n>>& t) const
  {
    const Face& a = faces_[f];
    if constexpr(n == 2) return t[a[0]] == t[a[1]];
    else return CGAL::collinear(point(a[0], t), point(a[1], t), point(a[2], t));
  }

  // Whether two non-degenerate faces meet anywhere but in the vertices (2D) or the edge/vertex (3D)
  // they share by index; with a positive `clearance_fraction`, faces with no common vertex also
  // when they are closer than that fraction of their clearance(). Shared vertices are first moved
  // to the front of both faces, same order.
  bool improper(std::uint32_t fi, std::uint32_t gi, const std::vector<Vector<n>>& t, double clearance_fraction = 0) const
  {
    Face a = faces_[fi], b = faces_[gi];
    int shared = 0;
    for(int i = 0; i < n; ++i)
      for(int j = shared; j < n; ++j)
        if(a[i] == b[j]) {
          std::swap(a[i], a[shared]);
          std::swap(b[j], b[shared]);
          ++shared;
          break;
        }
    if(shared == n) return false;   // the same face listed twice
    if constexpr(n == 2) {
      const K::Point_2 s = point(a[0], t), q = point(a[1], t), r = point(b[1], t);
      if(shared == 0) {
        const K::Segment_2 e(s, q), g(r, point(b[0], t));
        return CGAL::do_intersect(e, g) || too_close(e, g, clearance_fraction * clearance(fi, gi, t));
      }
      // (s, q) and (s, r) meet beyond s iff q and r lie on the same ray from s.
      return CGAL::orientation(s, q, r) == CGAL::COLLINEAR &&
             (CGAL::collinear_are_ordered_along_line(s, q, r) ||
              CGAL::collinear_are_ordered_along_line(s, r, q));
    } else {
      const K::Point_3 a0 = point(a[0], t), a1 = point(a[1], t), a2 = point(a[2], t);
      const K::Point_3 b0 = point(b[0], t), b1 = point(b[1], t), b2 = point(b[2], t);
      if(shared == 0) {
        const double c = clearance(fi, gi, t), d = clearance_fraction * c;
        if(apart({t[a[0]], t[a[1]], t[a[2]]}, {t[b[0]], t[b[1]], t[b[2]]}, d, c)) return false;
        const K::Triangle_3 e(a0, a1, a2), g(b0, b1, b2);
        return CGAL::do_intersect(e, g) || too_close(e, g, d);
      }
      // Sharing edge a0a1: unless coplanar the planes meet in that edge's line only; coplanar, the
      // triangles overlap iff a2 and b2 are not strictly on opposite sides of it.
      if(shared == 2)
        return CGAL::orientation(a0, a1, a2, b2) == CGAL::COPLANAR &&
               CGAL::coplanar_orientation(a0, a1, a2, b2) != CGAL::NEGATIVE;
      // Sharing vertex a0: one triangle strictly on one side of the other's plane but for a0 is fine.
      const CGAL::Orientation o1 = CGAL::orientation(a0, a1, a2, b1);
      if(o1 != CGAL::COPLANAR && o1 == CGAL::orientation(a0, a1, a2, b2)) return false;
      const CGAL::Orientation o2 = CGAL::orientation(b0, b1, b2, a1);
      if(o2 != CGAL::COPLANAR && o2 == CGAL::orientation(b0, b1, b2, a2)) return false;
      // Otherwise, if they meet at x != a0, the shorter of the two chords from a0 towards x ends on
      // its triangle's edge opposite a0, inside the other triangle (and conversely).
      return CGAL::do_intersect(K::Segment_3(a1, a2), K::Triangle_3(b0, b1, b2)) ||
             CGAL::do_intersect(K::Segment_3(b1, b2), K::Triangle_3(a0, a1, a2));
    }
  }

  // The clearance of two faces, from the box of both.
  double clearance(std::uint32_t fi, std::uint32_t gi, const std::vector<Vector<n>>& t) const
  {
    return clearance(face_box(fi, t).merged(face_box(gi, t)));
  }

  // Whether faces e and g (segments or triangles) are at most d > 0 apart (never with d = 0).
  template <class Face_object>
  static bool too_close(const Face_object& e, const Face_object& g, double d)
  {
    return d > 0 && !(squared_distance(e, g) > d * d);
  }
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_H
