// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The clearance that moves keep between boundary faces with no common vertex: more than 64 units
// in the last place of their coordinates. A vertex that stops a hair's breadth from another
// boundary face is outside it in doubles, but may be on it or across once the map is written in
// decimal and read back (a free border that wants to overlap itself pushes vertices that close).
// Here: the clearance of a box, the distance of two faces the same in either order, and a cheap
// certificate that two triangles are farther apart than a distance.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_CLEARANCE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_CLEARANCE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/number_types.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard/face_geometry.h>

#include <CGAL/Distance_2/Segment_2_Segment_2.h>
#include <CGAL/Distance_3/Point_3_Triangle_3.h>
#include <CGAL/Distance_3/Segment_3_Segment_3.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {
namespace boundary_guard {

template <int n>
struct Clearance : Face_geometry<n>
{
  using typename Face_geometry<n>::Box;

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

  // The squared distance of two faces that do not meet, the same for (e, g) and (g, e): a move's
  // check and the whole boundary's see a pair in either order. Triangles: the least over each
  // vertex to the other triangle and each edge to each edge of the other, each of those both ways:
  // CGAL's distances in doubles (5.5) depend on the order of their arguments, for nearly touching
  // faces by up to the whole distance. Local moves could then bring a pair within the clearance
  // one way that a global step's check sees the other way, at its start: every later trial fails.
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

  // Whether faces e and g (segments or triangles) are at most d > 0 apart (never with d = 0).
  template <class Face_object>
  static bool too_close(const Face_object& e, const Face_object& g, double d)
  {
    return d > 0 && !(squared_distance(e, g) > d * d);
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
};

} // namespace boundary_guard
} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_CLEARANCE_H
