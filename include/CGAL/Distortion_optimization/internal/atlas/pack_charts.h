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
#include <cstdint>
#include <limits>
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

// Cells of a grid as bits, 64 to a word, each row `words` words long.
struct Cell_grid
{
  std::size_t width = 0, height = 0, words = 0;
  std::vector<std::uint64_t> bits;
  Cell_grid(std::size_t w, std::size_t h) : width(w), height(h), words(w / 64 + 1), bits(words * h, 0) {}
  std::uint64_t* row(std::size_t y) { return bits.data() + y * words; }
  const std::uint64_t* row(std::size_t y) const { return bits.data() + y * words; }
  void set(std::size_t x, std::size_t y) { row(y)[x / 64] |= std::uint64_t(1) << (x % 64); }
  bool get(std::size_t x, std::size_t y) const { return (row(y)[x / 64] >> (x % 64)) & 1; }
};

// Marks every cell [x, x + 1] x [y, y + 1] the triangle `p` (in cell units) meets, and a little
// more: a cell of its bounding box is left only if one of its edges' lines has the whole cell,
// grown by a millionth, strictly outside (the separating axis test). A chart's cells thus cover it.
inline void rasterize_triangle(const std::array<Vector<2>, 3>& p, Cell_grid& grid)
{
  const double turn = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
  const double sign = turn < 0 ? -1 : 1;
  const auto cell = [](double t, std::size_t n) { return (std::min)(std::size_t((std::max)(t, 0.)), n - 1); };
  const std::size_t x0 = cell((std::min)({p[0][0], p[1][0], p[2][0]}), grid.width), x1 = cell((std::max)({p[0][0], p[1][0], p[2][0]}), grid.width);
  const std::size_t y0 = cell((std::min)({p[0][1], p[1][1], p[2][1]}), grid.height), y1 = cell((std::max)({p[0][1], p[1][1], p[2][1]}), grid.height);
  const double e = 1e-6;
  for(std::size_t y = y0; y <= y1; ++y)
    for(std::size_t x = x0; x <= x1; ++x) {
      bool outside = false;
      for(int i = 0; i < 3 && !outside; ++i) {
        const Vector<2>& a = p[i];
        const Vector<2>& b = p[(i + 1) % 3];
        const double nx = (a[1] - b[1]) * sign, ny = (b[0] - a[0]) * sign;   // the edge's inward normal
        outside = (std::max)(nx * (x - e - a[0]), nx * (x + 1 + e - a[0])) + (std::max)(ny * (y - e - a[1]), ny * (y + 1 + e - a[1])) < 0;
      }
      if(!outside) grid.set(x, y);
    }
}

// Whether `mask`, its cell (0, 0) put on the grid's (x, y), meets none of the grid's cells.
inline bool fits(const Cell_grid& mask, const Cell_grid& grid, std::size_t x, std::size_t y)
{
  const std::size_t word = x / 64, shift = x % 64;
  for(std::size_t r = 0; r < mask.height; ++r) {
    const std::size_t row = (r + mask.height / 2) % mask.height;   // the middle first: a conflict shows early
    const std::uint64_t *a = mask.row(row), *b = grid.row(y + row) + word;
    std::uint64_t carry = 0;
    for(std::size_t i = 0; i < mask.words; ++i) {
      if((((a[i] << shift) | carry) & b[i]) != 0) return false;
      carry = shift ? a[i] >> (64 - shift) : 0;
    }
    if(carry && word + mask.words < grid.words && (carry & b[mask.words]) != 0) return false;
  }
  return true;
}

// Packs the charts into the unit square at one scale (every chart keeps the texel density of the
// others), turned (never mirrored), `gutter` apart (a fraction of the square's side). The charts
// are rasterized, conservatively, on a grid of about 256 cells across the root of their area
// (growing to 384 from 32 to 72 charts, for small charts to keep their shape; falling as the root
// of 300 over their number beyond 133 charts, down to 64, to bound the time); each, the largest
// first, in the best of its four quarter turns from its least bounding rectangle's frame, goes
// where its cells meet none taken and the packing's bounding box grows least, then lowest, then
// leftmost. Unlike dropping charts onto a horizon (Levy, Petitjean, Ray and Maillot, "Least
// squares conformal maps for automatic texture atlas generation", 2002), this fills the hollows
// of the charts placed before, as the bitmap packing of game engines' atlas tools does. Taken
// cells are grown by the cells nearer than the gutter (a rounded square; the cells about at
// least): charts never meet and stay the gutter apart (with very many charts no gap of that size
// may exist: then the densest packing is kept). Two ways of weighing the growth are tried (the
// larger side, then the area; the area with a toll on elongation) and the denser kept. Returns
// the charts' UV area over that of the rectangle bounding them all.
inline double pack_charts(std::vector<Chart_to_pack>& charts, double gutter)
{
  const std::size_t n = charts.size();
  double area = 0;
  std::vector<std::array<double, 2>> size(n);
  for(std::size_t k = 0; k < n; ++k) {
    turn_to_least_bounding_rectangle(charts[k].uv);
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    for(const auto& p : charts[k].uv) u0 = (std::min)(u0, p[0]), u1 = (std::max)(u1, p[0]), v0 = (std::min)(v0, p[1]), v1 = (std::max)(v1, p[1]);
    for(auto& p : charts[k].uv) p = Vector<2>(p[0] - u0, p[1] - v0);
    size[k] = {u1 - u0, v1 - v0};
    area += charts[k].area;
  }
  if(n == 0 || !(area > 0)) return 0;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return size[a][0] * size[a][1] > size[b][0] * size[b][1]; });

  // Each chart in its four turns (about its rectangle's centre, back to u, v >= 0), as cells.
  const auto turned = [&](std::size_t k, int turn, const Vector<2>& p) {
    const double w = size[k][0], h = size[k][1], u = p[0], v = p[1];
    return turn == 0 ? p : turn == 1 ? Vector<2>(h - v, u) : turn == 2 ? Vector<2>(w - u, h - v) : Vector<2>(v, w - u);
  };
  const double across = 256 * (std::min)(std::clamp(std::sqrt(double(n) / 32), 1., 1.5), std::sqrt(300. / double(n)));
  const double d = std::sqrt(area) / (std::max)(64., across);   // a cell's side
  std::vector<std::vector<Cell_grid>> masks(n);
  std::vector<std::array<std::size_t, 2>> extent(n);   // in cells
  std::size_t longest = 0;
  for(std::size_t k = 0; k < n; ++k) {
    const std::size_t w = std::size_t(size[k][0] / d) + 1, h = std::size_t(size[k][1] / d) + 1;
    for(int turn = 0; turn < 4; ++turn) {
      masks[k].emplace_back(turn % 2 ? h : w, turn % 2 ? w : h);
      for(const auto& t : charts[k].triangles) {
        std::array<Vector<2>, 3> p;
        for(int i = 0; i < 3; ++i) p[i] = turned(k, turn, charts[k].uv[t[i]]) / d;
        rasterize_triangle(p, masks[k][turn]);
      }
    }
    extent[k] = {w, h}, longest = (std::max)(longest, (std::max)(w, h));
  }

  struct Placement { int turn = 0; std::size_t x = 0, y = 0; };
  // Every chart placed at least `gap` cells from the others, the growth weighed one of two ways, in
  // a square of `cap` cells; false if one did not fit.
  const auto place = [&](double gap, int weighing, std::size_t cap, std::vector<Placement>& at) {
    Cell_grid grid(cap, cap);
    // Cells (x + dx, y + dy) about a taken cell (x, y) that a point nearer than `gap` cells to it can
    // lie in: those whose squares are nearer than that, |dx| <= reach[|dy|] (a rounded square: a
    // square of side 2 g + 1 would keep charts further apart than asked along the diagonals).
    const std::size_t g = (std::max)(std::size_t(1), std::size_t(std::ceil(gap)));
    std::vector<std::size_t> reach(g + 1, 0);
    for(std::size_t dy = 0; dy <= g; ++dy)
      for(std::size_t dx = 0; dx <= g; ++dx) {
        const double a = dx > 0 ? double(dx - 1) : 0., b = dy > 0 ? double(dy - 1) : 0.;
        if(a * a + b * b < (std::max)(gap * gap, 1e-12)) reach[dy] = dx;
      }
    std::size_t W = 0, H = 0;
    // The growth of the packing's bounding box (W, H) by a chart put at (x, y), then lower, then
    // more to the left; as a lexicographic key.
    const auto score = [&](std::size_t x, std::size_t y, const Cell_grid& m) {
      const std::size_t u = (std::max)(W, x + m.width), v = (std::max)(H, y + m.height);
      const std::size_t large = (std::max)(u, v), small = (std::min)(u, v);
      return weighing == 0 ? std::array<std::size_t, 4>{large, u * v, y, x}
                           : std::array<std::size_t, 4>{u * v + (large - small) * large / 4, large, y, x};
    };
    for(std::size_t k : order) {
      std::array<std::size_t, 4> best{std::size_t(-1), 0, 0, 0};
      for(int turn = 0; turn < 4; ++turn) {
        const Cell_grid& m = masks[k][turn];
        std::size_t first = 0;   // a cell of the chart (its first): where it lands must be free
        while(first + 1 < m.width * m.height && !m.get(first % m.width, first / m.width)) ++first;
        const std::size_t c0 = first % m.width, r0 = first / m.width;
        for(std::size_t y = 0; y <= H + g && y + m.height <= cap; ++y) {
          if(!(score(0, y, m) < best)) break;   // the least score a row can give only grows with y
          const std::uint64_t* row = grid.row(y + r0);
          for(std::size_t x = 0; x <= W + g && x + m.width <= cap; ++x) {
            // the next x whose (c0, r0) lands on a free cell, skipping taken cells 64 at a time
            std::size_t c = x + c0, word = c / 64;
            std::uint64_t free = ~row[word] & (~std::uint64_t(0) << (c % 64));
            while(free == 0 && ++word < grid.words) free = ~row[word];
            if(free == 0) break;
            x = word * 64 + std::size_t(std::ilogb(double(free & (~free + 1)))) - c0;   // its lowest bit
            if(x > W + g || x + m.width > cap) break;
            const std::array<std::size_t, 4> s = score(x, y, m);
            if(s < best && fits(m, grid, x, y)) best = s, at[k] = {turn, x, y};
          }
        }
      }
      if(best[0] == std::size_t(-1)) return false;
      const Placement& p = at[k];
      const Cell_grid& m = masks[k][p.turn];
      for(std::size_t r = 0; r < m.height; ++r)
        for(std::size_t c = 0; c < m.width; ++c)
          if(m.get(c, r))
            for(std::size_t y = p.y + r >= g ? p.y + r - g : 0; y <= (std::min)(cap - 1, p.y + r + g); ++y) {
              const std::size_t dx = reach[y > p.y + r ? y - p.y - r : p.y + r - y];
              for(std::size_t x = p.x + c >= dx ? p.x + c - dx : 0; x <= (std::min)(cap - 1, p.x + c + dx); ++x) grid.set(x, y);
            }
      W = (std::max)(W, p.x + m.width), H = (std::max)(H, p.y + m.height);
    }
    return true;
  };
  const auto extents = [&](const std::vector<Placement>& at) {
    std::array<double, 2> e{0, 0};
    for(std::size_t k = 0; k < n; ++k)
      for(const auto& q : charts[k].uv) {
        const Vector<2> t = turned(k, at[k].turn, q);
        e = {(std::max)(e[0], t[0] + at[k].x * d), (std::max)(e[1], t[1] + at[k].y * d)};
      }
    return e;
  };
  // The gap is a fraction of the final side, which depends on the gap: a second pass settles it
  // (with very many charts no gap of that size may exist: the densest second pass is kept).
  std::vector<Placement> placed(n);
  double best = -1, side = 0;
  bool best_apart = false;
  for(int weighing = 0; weighing < 2; ++weighing) {
    double guess = std::sqrt(area / 0.6) / (1 - 2 * gutter);
    for(int pass = 0; pass < 2; ++pass) {
      const double gap = 1.02 * gutter * guess / d;   // in cells, with a little to spare for the next side
      const std::size_t g = (std::max)(std::size_t(1), std::size_t(std::ceil(gap)));
      double cells = 0;   // twice the side of a square holding every chart's rectangle with its gap should do
      for(const auto& [w, h] : extent) cells += double(w + g) * double(h + g);
      std::size_t cap = 2 * std::size_t(std::sqrt(cells)) + longest + g;
      std::vector<Placement> at(n);
      while(!place(gap, weighing, cap, at)) cap *= 2;
      const std::array<double, 2> e = extents(at);
      guess = (std::max)(e[0], e[1]) / (1 - 2 * gutter);
      // A packing that keeps the gutter at its final side beats one that does not.
      const bool apart = gutter * guess <= gap * d;
      if((apart || pass == 1) && std::make_pair(apart, area / (e[0] * e[1])) > std::make_pair(best_apart, best))
        best = area / (e[0] * e[1]), best_apart = apart, placed = at, side = guess;
      if(apart) break;
    }
  }
  const double margin = gutter * side;
  for(std::size_t k = 0; k < n; ++k)
    for(auto& q : charts[k].uv) {
      const Vector<2> t = turned(k, placed[k].turn, q);
      q = Vector<2>((t[0] + placed[k].x * d + margin) / side, (t[1] + placed[k].y * d + margin) / side);
    }
  return best;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_PACK_CHARTS_H
