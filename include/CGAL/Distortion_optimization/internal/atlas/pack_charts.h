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
#include <array>
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

// A chart to pack: its UVs and its triangles (indices into them), and its UV area.
struct Chart_to_pack
{
  std::vector<Vector<2>> uv;
  std::vector<std::array<std::size_t, 3>> triangles;
  double area = 0;
};

// The segments bounding a chart: its triangles' edges that no other triangle of it shares.
inline std::vector<std::array<Vector<2>, 2>> outline(const Chart_to_pack& chart)
{
  std::vector<std::array<std::size_t, 2>> edges;
  for(const auto& t : chart.triangles)
    for(int i = 0; i < 3; ++i) edges.push_back({(std::min)(t[i], t[(i + 1) % 3]), (std::max)(t[i], t[(i + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  std::vector<std::array<Vector<2>, 2>> result;
  for(std::size_t i = 0; i < edges.size(); ++i) {
    if((i + 1 < edges.size() && edges[i + 1] == edges[i]) || (i > 0 && edges[i - 1] == edges[i])) continue;
    result.push_back({chart.uv[edges[i][0]], chart.uv[edges[i][1]]});
  }
  return result;
}

// The lowest and highest v a chart reaches in each column [c d, (c + 1) d) of u, given its outline
// (its least u at 0). Within a vertical slab a polygon reaches its extremes on its outline, so the
// outline's segments clipped to each column give the exact extents.
inline void column_profile(const std::vector<std::array<Vector<2>, 2>>& segments, double width, double d,
                           std::vector<double>& bottom, std::vector<double>& top)
{
  const std::size_t columns = std::size_t(width / d) + 1;
  bottom.assign(columns, std::numeric_limits<double>::infinity());
  top.assign(columns, -std::numeric_limits<double>::infinity());
  const auto column = [&](double u) { return (std::min)(std::size_t((std::max)(u, 0.) / d), columns - 1); };
  for(auto [p, q] : segments) {
    if(q[0] < p[0]) std::swap(p, q);
    for(std::size_t c = column(p[0]), last = column(q[0]); c <= last; ++c) {
      double v0 = p[1], v1 = q[1];   // a vertical segment: both ends
      if(q[0] > p[0]) {
        const auto at = [&](double u) { return p[1] + (q[1] - p[1]) * (std::min)(1., (std::max)(0., (u - p[0]) / (q[0] - p[0]))); };
        v0 = at((std::max)(p[0], c * d)), v1 = at((std::min)(q[0], (c + 1) * d));
      }
      bottom[c] = (std::min)(bottom[c], (std::min)(v0, v1));
      top[c] = (std::max)(top[c], (std::max)(v0, v1));
    }
  }
  for(std::size_t c = 0; c < columns; ++c)   // a column the chart only grazes
    if(bottom[c] > top[c]) bottom[c] = top[c] = 0;
}

// Packs the charts into the unit square at one scale (every chart keeps the texel density of the
// others), turned (never mirrored), `gutter` apart (a fraction of the square's side). Each chart,
// the largest first, in the best of its four quarter turns from its least bounding rectangle's
// frame, is dropped like a Tetris piece onto the horizon of those before it, where it raises the
// packing least and then wastes least space below it (Levy, Petitjean, Ray and Maillot, "Least
// squares conformal maps for automatic texture atlas generation", 2002). The strip's width is
// the one, of those tried, whose layout fills the square about it best (the unit square's share
// the charts take: their texel density). Returns the charts' UV area over that of the rectangle
// bounding them all.
inline double pack_charts(std::vector<Chart_to_pack>& charts, double gutter)
{
  const std::size_t n = charts.size(), columns = 256;
  double rectangles = 0, narrowest = 0, longest = 0, area = 0;
  std::vector<std::array<double, 2>> size(n);
  for(std::size_t k = 0; k < n; ++k) {
    turn_to_least_bounding_rectangle(charts[k].uv);
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    for(const auto& p : charts[k].uv) u0 = (std::min)(u0, p[0]), u1 = (std::max)(u1, p[0]), v0 = (std::min)(v0, p[1]), v1 = (std::max)(v1, p[1]);
    for(auto& p : charts[k].uv) p = Vector<2>(p[0] - u0, p[1] - v0);
    size[k] = {u1 - u0, v1 - v0};
    rectangles += size[k][0] * size[k][1];
    narrowest = (std::max)(narrowest, size[k][1]);   // the strip must take every chart some way
    longest = (std::max)(longest, size[k][0]);
    area += charts[k].area;
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return size[a][0] * size[a][1] > size[b][0] * size[b][1]; });

  // Each chart's outline in its four turns (about its rectangle's centre, back to u, v >= 0),
  // turned once for all the strips tried.
  const auto turned = [&](std::size_t k, int turn, const Vector<2>& p) {
    const double w = size[k][0], h = size[k][1], u = p[0], v = p[1];
    return turn == 0 ? p : turn == 1 ? Vector<2>(h - v, u) : turn == 2 ? Vector<2>(w - u, h - v) : Vector<2>(v, w - u);
  };
  std::vector<std::array<std::vector<std::array<Vector<2>, 2>>, 4>> outlines(n);
  for(std::size_t k = 0; k < n; ++k)
    for(const auto& [p, q] : outline(charts[k]))
      for(int turn = 0; turn < 4; ++turn) outlines[k][turn].push_back({turned(k, turn, p), turned(k, turn, q)});
  struct Placement { int turn = 0; std::size_t column = 0; double v = 0; };
  std::vector<Placement> placed(n);
  // One packing in a strip `strip` wide: the charts' places and the extents of their union.
  const auto drop = [&](double strip, double gap, std::vector<Placement>& at, double& extent_u, double& extent_v) {
    const double d = strip / columns;
    const std::size_t spread = std::size_t(std::ceil(gap / d));
    std::vector<double> horizon(columns, 0), bottom, top;
    extent_u = extent_v = 0;
    for(std::size_t k : order) {
      double best = std::numeric_limits<double>::infinity();
      std::vector<double> best_top;
      for(int turn = 0; turn < 4; ++turn) {
        column_profile(outlines[k][turn], size[k][turn % 2], d, bottom, top);
        if(bottom.size() > columns) continue;
        for(std::size_t x = 0; x + bottom.size() <= columns; ++x) {
          double v = 0, waste = 0;
          for(std::size_t c = 0; c < bottom.size(); ++c) v = (std::max)(v, horizon[x + c] - bottom[c]);
          for(std::size_t c = 0; c < bottom.size(); ++c) waste += v + bottom[c] - horizon[x + c];
          double high = 0;
          for(std::size_t c = 0; c < top.size(); ++c) high = (std::max)(high, v + top[c]);
          const double score = (std::max)(high, extent_v) * strip + waste * d;
          if(score < best) best = score, at[k] = {turn, x, v}, best_top = top;
        }
      }
      const Placement& p = at[k];
      for(std::size_t c = 0; c < best_top.size(); ++c)
        for(std::size_t j = p.column + c >= spread ? p.column + c - spread : 0; j <= (std::min)(columns - 1, p.column + c + spread); ++j)
          horizon[j] = (std::max)(horizon[j], p.v + best_top[c] + gap);
      const bool across = p.turn % 2 == 1;
      extent_u = (std::max)(extent_u, p.column * d + size[k][across ? 1 : 0]);
      extent_v = (std::max)(extent_v, p.v + size[k][across ? 0 : 1]);
    }
  };
  // The gap is a fraction of the final side, which depends on the gap: two passes settle it.
  double side = std::sqrt(rectangles), extent_u = 0, extent_v = 0, strip_used = 0;
  for(int pass = 0; pass < 2; ++pass) {
    const double gap = gutter * side;
    double best = -1;
    std::vector<Placement> at(n);
    for(int i = 0; i <= 12; ++i) {
      // Near the square the rectangles would fill, or near the longest chart's length (which a
      // narrower strip would stand on end).
      const double strip = (std::max)(narrowest * (1 + 1e-9) + gap, i <= 8 ? std::sqrt(rectangles) * (0.8 + 0.1 * i)
                                                                             : longest * (1 + 0.1 * (i - 9)) + gap);
      double eu = 0, ev = 0;
      drop(strip, gap, at, eu, ev);
      const double square = area / ((std::max)(eu, ev) * (std::max)(eu, ev));
      if(square > best) best = square, placed = at, extent_u = eu, extent_v = ev, strip_used = strip;
    }
    side = (std::max)(extent_u, extent_v) / (1 - 2 * gutter);
  }
  const double margin = gutter * side, d = strip_used / columns;
  for(std::size_t k = 0; k < n; ++k) {
    const Placement& p = placed[k];
    for(auto& q : charts[k].uv) {
      const Vector<2> t = turned(k, p.turn, q);
      q = Vector<2>((t[0] + p.column * d + margin) / side, (t[1] + p.v + margin) / side);
    }
  }
  return area / (extent_u * extent_v);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_PACK_CHARTS_H
