// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Packing flattened charts into the unit square.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_PACK_CHARTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_PACK_CHARTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The rectangle of least area bounding `uv` among those with a side along an edge of its convex
// hull (one of them is the least of all: Freeman and Shapira, "Determining the minimum-area
// encasing rectangle for an arbitrary closed curve", 1975): the direction (c, s) of its longer
// side, and its area.
struct Bounding_rectangle
{
  double c = 1, s = 0, area = 0;
};

inline Bounding_rectangle least_bounding_rectangle(const std::vector<Vector<2>>& uv)
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
  std::vector<Point> points, hull;
  for(const auto& p : uv) points.emplace_back(p[0], p[1]);
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  Bounding_rectangle best;
  if(hull.size() < 3) return best;
  best.area = std::numeric_limits<double>::infinity();
  double width = 0, height = 0;
  for(std::size_t i = 0; i < hull.size(); ++i) {
    const Point &a = hull[i], &b = hull[(i + 1) % hull.size()];
    const double dx = b.x() - a.x(), dy = b.y() - a.y(), length = std::hypot(dx, dy);
    if(!(length > 0)) continue;
    const double c = dx / length, s = dy / length;   // the edge's direction
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    for(const Point& p : hull) {
      const double u = c * p.x() + s * p.y(), v = -s * p.x() + c * p.y();
      u0 = (std::min)(u0, u), u1 = (std::max)(u1, u), v0 = (std::min)(v0, v), v1 = (std::max)(v1, v);
    }
    if((u1 - u0) * (v1 - v0) < best.area) best = {c, s, (u1 - u0) * (v1 - v0)}, width = u1 - u0, height = v1 - v0;
  }
  if(height > width) best = {-best.s, best.c, best.area};   // a quarter turn more: the longer side along u
  return best;
}

// Turns `uv` about the origin so that its least bounding rectangle is axis-aligned, its longer
// side along u. A rotation: no chart is mirrored.
inline void turn_to_least_bounding_rectangle(std::vector<Vector<2>>& uv)
{
  const Bounding_rectangle r = least_bounding_rectangle(uv);
  for(auto& p : uv) p = Vector<2>(r.c * p[0] + r.s * p[1], -r.s * p[0] + r.c * p[1]);
}

// Places the charts (each a list of UVs, turned to their least bounding rectangle) side by side in
// shelves, the tallest first, the shelves as wide as the square the charts' rectangles would fill,
// `gutter` apart (a fraction of the final square's side), then scales them all by one factor into
// the unit square: every chart keeps the texel density of the others. Returns the charts' UV
// area over that of the rectangle bounding them all.
inline double pack_charts(std::vector<std::vector<Vector<2>>>& charts, const std::vector<double>& chart_area, double gutter)
{
  const std::size_t n = charts.size();
  std::vector<double> x0(n), y0(n), w(n), h(n);
  double rectangles = 0, widest = 0;
  for(std::size_t k = 0; k < n; ++k) {
    turn_to_least_bounding_rectangle(charts[k]);
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    for(const auto& p : charts[k]) u0 = (std::min)(u0, p[0]), u1 = (std::max)(u1, p[0]), v0 = (std::min)(v0, p[1]), v1 = (std::max)(v1, p[1]);
    x0[k] = u0, y0[k] = v0, w[k] = u1 - u0, h[k] = v1 - v0;
    rectangles += w[k] * h[k];
    widest = (std::max)(widest, w[k]);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h[a] > h[b]; });
  // Shelves of the width (of eleven tried, from the widest chart up to twice the square the
  // rectangles would fill) whose layout fills its bounding rectangle best, among those no more
  // than twice as long as wide (the texture is square). The gap is a fraction of the
  // final side, which depends on the gap: two passes settle it.
  double side = std::sqrt(rectangles), extent_u = 0, extent_v = 0;
  std::vector<double> at_u(n), at_v(n);
  const auto shelve = [&](double shelf_width, double gap, std::vector<double>& x, std::vector<double>& y, double& eu, double& ev) {
    double u = 0, v = 0, shelf_height = 0;
    eu = ev = 0;
    for(std::size_t k : order) {
      if(u > 0 && u + w[k] > shelf_width) u = 0, v += shelf_height + gap, shelf_height = 0;
      x[k] = u, y[k] = v;
      u += w[k] + gap;
      shelf_height = (std::max)(shelf_height, h[k]);
      eu = (std::max)(eu, x[k] + w[k]);
      ev = (std::max)(ev, y[k] + h[k]);
    }
  };
  for(int pass = 0; pass < 2; ++pass) {
    const double gap = gutter * side;
    double best = -1;
    std::vector<double> x(n), y(n);
    for(int i = 0; i <= 10; ++i) {
      const double shelf_width = (std::max)(widest, std::sqrt(rectangles) * (1 + 0.1 * i));
      double eu = 0, ev = 0;
      shelve(shelf_width, gap, x, y, eu, ev);
      const double fill = rectangles / (eu * ev);
      if((i == 0 || (std::max)(eu, ev) <= 2 * (std::min)(eu, ev)) && fill > best)
        best = fill, at_u = x, at_v = y, extent_u = eu, extent_v = ev;
    }
    side = (std::max)(extent_u, extent_v) / (1 - 2 * gutter);
  }
  const double margin = gutter * side;
  for(std::size_t k = 0; k < n; ++k)
    for(auto& p : charts[k])
      p = Vector<2>((p[0] - x0[k] + at_u[k] + margin) / side, (p[1] - y0[k] + at_v[k] + margin) / side);
  const double area = std::accumulate(chart_area.begin(), chart_area.end(), 0.);
  return area / (extent_u * extent_v);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_PACK_CHARTS_H
