// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Exact tests of boundary faces at their current positions (CGAL Epick predicates, on which the
// guarantee of injectivity rests): whether a face is degenerate, and whether two faces meet
// anywhere but where they share vertices, or, given a fraction of their clearance, come closer.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_EXACT_TESTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_EXACT_TESTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/boundary_guard/clearance.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard/face_geometry.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {
namespace boundary_guard {

template <int n>
struct Exact_tests : Clearance<n>
{
  using typename Face_geometry<n>::Face;
  using Face_geometry<n>::point;
  using Face_geometry<n>::face_box;
  using Clearance<n>::clearance;
  using Clearance<n>::too_close;
  using Clearance<n>::apart;

  // A face with coincident (2D) or collinear (3D) vertices: its cell is degenerate, so no injectivity.
  static bool is_degenerate(const Face& a, const std::vector<Vector<n>>& t)
  {
    if constexpr(n == 2) return t[a[0]] == t[a[1]];
    else return CGAL::collinear(point(a[0], t), point(a[1], t), point(a[2], t));
  }

  // Whether two non-degenerate faces meet anywhere but in the vertices (2D) or the edge/vertex (3D)
  // they share by index; with a positive `clearance_fraction`, faces with no common vertex also
  // when they are closer than that fraction of their clearance(). Shared vertices are first moved
  // to the front of both faces, same order.
  static bool improper(const Face& face_a, const Face& face_b, const std::vector<Vector<n>>& t,
                       double clearance_fraction = 0)
  {
    Face a = face_a, b = face_b;
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
        return CGAL::do_intersect(e, g) || too_close(e, g, clearance_fraction * clearance(face_a, face_b, t));
      }
      // (s, q) and (s, r) meet beyond s iff q and r lie on the same ray from s.
      return CGAL::orientation(s, q, r) == CGAL::COLLINEAR &&
             (CGAL::collinear_are_ordered_along_line(s, q, r) ||
              CGAL::collinear_are_ordered_along_line(s, r, q));
    } else {
      const K::Point_3 a0 = point(a[0], t), a1 = point(a[1], t), a2 = point(a[2], t);
      const K::Point_3 b0 = point(b[0], t), b1 = point(b[1], t), b2 = point(b[2], t);
      if(shared == 0) {
        const double c = clearance(face_a, face_b, t), d = clearance_fraction * c;
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
  static double clearance(const Face& a, const Face& b, const std::vector<Vector<n>>& t)
  {
    return clearance(face_box(a, t).merged(face_box(b, t)));
  }
};

} // namespace boundary_guard
} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_EXACT_TESTS_H
