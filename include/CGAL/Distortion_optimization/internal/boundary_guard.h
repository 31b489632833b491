// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Global injectivity with a free boundary (section 3.2, Fig. 7): a positively oriented simplicial
// map is injective iff its boundary (segments in 2D, triangles in 3D) does not self-intersect
// (Aigerman and Lipman 2013). The guard tells the line search whether a trial position keeps it so.
//
// Moving boxes. A box tree (boundary_guard/box_tree.h) stores, per face, its box enlarged by a
// margin at rebuild(). Invariant: each face's current box lies in its stored box, except for the
// faces of the vertex on trial. A query tests the CURRENT box of the moved vertex's faces against
// the STORED ones, so no face that may touch them is missed, then runs exact tests
// (boundary_guard/exact_tests.h) on current positions. commit_move() restores the invariant by
// refitting the faces that left their stored boxes, and rebuilds the tree after B/4 refits.
// is_injective() runs CGAL::box_self_intersection_d on current boxes. Not thread-safe: queries
// share scratch space.
//
// Several pieces. Given the pieces (per-vertex labels), is_injective() also asks whether a
// boundary component of one piece lies inside another, and accepts_move() refuses a move whose
// swept simplices hold a boundary vertex of another piece (boundary_guard/nesting.h).
//
// Clearance. Moves also keep faces without a common vertex apart by their clearance
// (boundary_guard/clearance.h), unless the map had two faces that close at the last rebuild():
// then the exact tests only.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/boundary_guard/box_tree.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard/clearance.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard/exact_tests.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard/face_geometry.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard/nesting.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>
#include <CGAL/Distortion_optimization/internal/svd.h>

#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>

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

template <int n>
class Boundary_guard : private boundary_guard::Exact_tests<n>
{
  using Geometry = boundary_guard::Face_geometry<n>;
  using Tests = boundary_guard::Exact_tests<n>;

public:
  using typename Geometry::Face;
  using K = boundary_guard::K;
  // Public for the tests: the order-independent distance and the separating axes (clearance.h).
  using Tests::squared_distance;
  using Tests::apart;

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
    if(!piece.empty())
      pieces_.find_components(faces_, piece, first_face_.size() - 1, [&](std::size_t v) { return is_on_boundary(v); });
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
    degenerate_.resize(B);
    for(std::uint32_t f = 0; f < B; ++f) {
      boxes[f] = face_box(faces_[f], target);
      degenerate_[f] = is_degenerate(faces_[f], target);
    }
    tree_.build(std::move(boxes));
    if(several_pieces()) committed_ = target;
    // A map whose boundary is already closer to itself than that (given so) keeps the exact tests:
    // below a quarter of the clearance, as distances so small are computed to a few percent. A map
    // with faces between a quarter and the whole of it (moves in exact tests brought them there)
    // keeps it for moves, and the whole boundary's checks take the quarter (clearance_fraction()):
    // at the whole, every trial of a global step fails on that pair.
    if(clear || is_injective(target, nullptr, 1.)) clearance_fraction_ = 1;
    else clearance_fraction_ = is_injective(target, nullptr, 0.25) ? 0.25 : 0.;
  }

  // Whether moves keep faces apart by their clearance (clearance.h), as the map had them at the
  // last rebuild().
  bool keeps_clearance() const { return clearance_fraction_ > 0; }
  // The fraction of the clearance that the map kept at the last rebuild() (1, 0.25 or 0), which
  // moves keep: what a check of the whole boundary after moves of many vertices asks for.
  double clearance_fraction() const { return clearance_fraction_; }

  // Whether the trial position target[v] keeps the boundary injective. Only v may have moved since
  // the last rebuild() or commit_move(): the state then is assumed injective.
  bool accepts_move(std::size_t v, const std::vector<Vector<n>>& target)
  {
    CGAL_precondition(tree_.holds(faces_.size()));
    if(!is_on_boundary(v)) return true;
    if(!target[v].allFinite()) return false;
    const std::uint32_t* ring = vertex_faces_.data() + first_face_[v];
    const std::uint32_t* ring_end = vertex_faces_.data() + first_face_[v + 1];
    const double fraction = keeps_clearance() ? 1. : 0.;   // of the clearance moves keep
    // The ring's faces may have left their stored boxes: test them against each other directly.
    for(const std::uint32_t* f = ring; f != ring_end; ++f) {
      if(is_degenerate(faces_[*f], target)) return false;
      for(const std::uint32_t* g = ring; g != f; ++g)
        if(improper(faces_[*f], faces_[*g], target, fraction)) return false;
    }
    // Then one traversal for the whole ring (the star's box), each candidate against each ring
    // face; boxes grown by twice the ring's clearance, which bounds any candidate's near it.
    ring_boxes_.clear();
    Box star;
    for(const std::uint32_t* f = ring; f != ring_end; ++f) {
      ring_boxes_.push_back(face_box(faces_[*f], target));
      star.extend(ring_boxes_.back());
    }
    const double near = 2 * fraction * clearance(star);
    for(Box& b : ring_boxes_) b = grown(b, near);
    star = grown(star, near);
    const bool apart = tree_.visit(star, [&](std::uint32_t g) {   // false stops the traversal
      if(contains(g, v)) return true;
      const Box box = face_box(faces_[g], target);
      if(!box.intersects(star)) return true;
      if(degenerate_[g]) return false;
      for(std::size_t i = 0; i < ring_boxes_.size(); ++i)
        if(box.intersects(ring_boxes_[i]) && improper(faces_[ring[i]], faces_[g], target, fraction)) return false;
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
      degenerate_[f] = is_degenerate(faces_[f], target);
      tree_.refit(f, face_box(faces_[f], target));
    }
    if(tree_.refits() > faces_.size() / 4 + 16) rebuild(target);
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
      if(!finite || is_degenerate(faces_[f], target)) {
        injective = false;
        report(f);
        if(!crossing) return false;
        continue;
      }
      const Box b = face_box(faces_[f], target);
      boxes.push_back(box_d(grown(b, clearance_fraction * clearance(b)), f));
    }
    // A callback cannot stop box_self_intersection_d: without `crossing`, it skips the tests once
    // one crossing is found.
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box_d& a, const Box_d& b) {
      if((injective || crossing) && improper(faces_[a.info()], faces_[b.info()], target, clearance_fraction)) {
        injective = false;
        report(a.info());
        report(b.info());
      }
    });
    if(!injective || !several_pieces()) return injective;
    const std::pair<std::uint32_t, std::uint32_t> pair =
        pieces_.nested(faces_, target, [&](std::size_t v) { return piece_of(v); });
    if(pair.first == pair.second) return true;
    if(nested) *nested = true;
    for(std::uint32_t f = 0; f < faces_.size(); ++f)
      if(pieces_.of_face(f) == pair.first || pieces_.of_face(f) == pair.second) report(f);
    return false;
  }

  // Whether the guard knows of two or more pieces with boundary.
  bool several_pieces() const { return pieces_.several(); }

private:
  using typename Geometry::Box;
  using typename Geometry::Box_d;
  using Geometry::face_box;
  using Geometry::box_d;
  using Tests::clearance;
  using Tests::grown;
  using Tests::is_degenerate;
  using Tests::improper;

  std::vector<Face> faces_;
  std::vector<std::size_t> first_face_;      // faces of v: vertex_faces_[first_face_[v], first_face_[v + 1])
  std::vector<std::uint32_t> vertex_faces_;
  boundary_guard::Box_tree<n> tree_;         // leaf f: face f
  std::vector<unsigned char> degenerate_;    // per face, as of its last rebuild() or commit_move()
  double clearance_fraction_ = 0;
  std::vector<Box> ring_boxes_;              // scratch of accepts_move()
  // With several pieces (empty otherwise): the pieces, and the positions of the last rebuild() or
  // commit_move(), where accepts_move()'s sweeps start.
  boundary_guard::Pieces<n> pieces_;
  std::vector<Vector<n>> committed_;
  std::vector<std::array<Vector<n>, n + 1>> swept_;   // scratch of accepts_move()

  std::uint32_t piece_of(std::size_t v) const { return pieces_.of_face(vertex_faces_[first_face_[v]]); }

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
    return tree_.visit(region, [&](std::uint32_t g) {
      if(pieces_.of_face(g) == own) return true;
      for(std::uint32_t u : faces_[g])
        if(region.contains(target[u]))
          for(const auto& s : swept_)
            if(pieces_.in_closed_simplex(s, target[u])) return false;
      return true;
    });
  }

  bool contains(std::uint32_t f, std::size_t v) const
  {
    return std::find(faces_[f].begin(), faces_[f].end(), v) != faces_[f].end();
  }
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_H
