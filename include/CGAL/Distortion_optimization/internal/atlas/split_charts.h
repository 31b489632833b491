// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Splitting a flattened chart that fills its bounding rectangle poorly (a branched piece: limbs
// spread about a body), so that its parts pack more densely.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_SPLIT_CHARTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_SPLIT_CHARTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/atlas/pack_charts.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// How a part is cut: by straight lines across `directions` directions evenly turned from its least
// bounding rectangle's longer side (1: across that side only), each at `places` places evenly
// spread over the middle half of the part's extent along it.
struct Split_rule
{
  int directions = 1, places = 5;
};

// The parts of a flattened chart (its faces by their vertices, the vertices' UVs), as a part
// number per face: its connected pieces (faces joined across edges; seams may close about a
// region), each cut further where it fills its least bounding rectangle poorly. A part that fills
// less than `min_fill` of its least bounding rectangle is cut by the line of `rule` where its
// pieces fill their own rectangles best, if that gains a twentieth at least; each piece is one
// part (a line may cut a branch into several), split again in turn, to 3 levels, while a part has
// 128 faces or more. The parts keep the chart's map: its distortion and injectivity are
// unchanged, and the edges between parts become seams.
inline std::vector<std::uint32_t> split_for_packing(const std::vector<std::array<std::uint32_t, 3>>& faces,
                                                    const std::vector<Vector<2>>& uv, double min_fill, Split_rule rule = {})
{
  const std::size_t F = faces.size();
  std::vector<std::uint32_t> part(F, 0);
  if(F == 0) return part;
  // Faces across each edge: the (edge, face) pairs sorted by edge; an edge that two faces share
  // joins them.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> sides;   // ends of the edge, face
  sides.reserve(3 * F);
  for(std::uint32_t f = 0; f < F; ++f)
    for(int i = 0; i < 3; ++i) {
      const std::uint32_t a = faces[f][i], b = faces[f][(i + 1) % 3];
      sides.emplace_back((std::min)(a, b), (std::max)(a, b), f);
    }
  std::sort(sides.begin(), sides.end());
  std::vector<std::vector<std::uint32_t>> neighbours(F);
  for(std::size_t i = 0, j; i < sides.size(); i = j) {
    for(j = i + 1; j < sides.size() && std::get<0>(sides[j]) == std::get<0>(sides[i]) && std::get<1>(sides[j]) == std::get<1>(sides[i]);) ++j;
    if(j - i == 2) {
      const std::uint32_t f = std::get<2>(sides[i]), g = std::get<2>(sides[i + 1]);
      neighbours[f].push_back(g), neighbours[g].push_back(f);
    }
  }
  const auto area = [&](std::uint32_t f) {
    const Vector<2> a = uv[faces[f][1]] - uv[faces[f][0]], b = uv[faces[f][2]] - uv[faces[f][0]];
    return 0.5 * std::abs(a[0] * b[1] - a[1] * b[0]);
  };
  // A set of faces' area and its least bounding rectangle's. The rectangle bounds the set's border:
  // the vertices of its faces with a side not shared within the set, fewer to sort for the hull.
  std::vector<std::uint32_t> seen(uv.size(), std::uint32_t(-1)), in(F, std::uint32_t(-1));
  std::uint32_t stamp = 0;
  const auto fill = [&](const std::vector<std::uint32_t>& set, Bounding_rectangle* frame = nullptr) {
    ++stamp;
    for(std::uint32_t f : set) in[f] = stamp;
    std::vector<Vector<2>> points;
    double a = 0;
    for(std::uint32_t f : set) {
      a += area(f);
      if(std::count_if(neighbours[f].begin(), neighbours[f].end(), [&](std::uint32_t g) { return in[g] == stamp; }) == 3) continue;
      for(std::uint32_t v : faces[f])
        if(seen[v] != stamp) seen[v] = stamp, points.push_back(uv[v]);
    }
    const Bounding_rectangle r = least_bounding_rectangle(points);
    if(frame) *frame = r;
    return std::make_pair(a, r.area);
  };
  // The connected pieces of a set (faces joined across edges).
  std::vector<std::uint32_t> member(F, std::uint32_t(-1));
  std::uint32_t label = 0;
  const auto pieces = [&](const std::vector<std::uint32_t>& set) {
    ++label;
    for(std::uint32_t f : set) member[f] = label;
    std::vector<std::vector<std::uint32_t>> result;
    for(std::uint32_t f : set) {
      if(member[f] != label) continue;
      result.emplace_back();
      std::vector<std::uint32_t> stack{f};
      member[f] = 0;
      while(!stack.empty()) {
        const std::uint32_t g = stack.back();
        stack.pop_back();
        result.back().push_back(g);
        for(std::uint32_t h : neighbours[g])
          if(member[h] == label) member[h] = 0, stack.push_back(h);
      }
    }
    return result;
  };

  std::vector<std::pair<std::vector<std::uint32_t>, int>> queue;   // a part and its level
  for(auto& p : pieces([&] { std::vector<std::uint32_t> all(F); for(std::uint32_t f = 0; f < F; ++f) all[f] = f; return all; }()))
    queue.emplace_back(std::move(p), 0);
  std::uint32_t parts = 0;
  while(!queue.empty()) {
    auto [set, level] = std::move(queue.back());
    queue.pop_back();
    Bounding_rectangle frame;
    const auto [a, r] = fill(set, &frame);
    std::vector<std::vector<std::uint32_t>> best;
    double best_fill = r > 0 ? a / r : 1;
    const bool splittable = best_fill < min_fill && level < 3 && set.size() >= 128;
    best_fill += 0.05;   // the gain a cut must make
    for(int d = 0; splittable && d < rule.directions; ++d) {
      const double turn = M_PI * d / rule.directions;
      const double c = frame.c * std::cos(turn) - frame.s * std::sin(turn), s = frame.s * std::cos(turn) + frame.c * std::sin(turn);
      std::vector<double> along(set.size());
      double u0 = std::numeric_limits<double>::infinity(), u1 = -u0;
      for(std::size_t k = 0; k < set.size(); ++k) {
        const auto& t = faces[set[k]];
        const Vector<2> centre = (uv[t[0]] + uv[t[1]] + uv[t[2]]) / 3;
        along[k] = c * centre[0] + s * centre[1];
        u0 = (std::min)(u0, along[k]), u1 = (std::max)(u1, along[k]);
      }
      for(int i = 0; i < rule.places; ++i) {
        const double t = rule.places > 1 ? 0.25 + 0.5 * i / (rule.places - 1) : 0.5;
        std::vector<std::uint32_t> below, above;
        for(std::size_t k = 0; k < set.size(); ++k) (along[k] < u0 + t * (u1 - u0) ? below : above).push_back(set[k]);
        std::vector<std::vector<std::uint32_t>> split = pieces(below), other = pieces(above);
        split.insert(split.end(), other.begin(), other.end());
        double total_area = 0, total_rectangle = 0;
        for(const auto& p : split) {
          const auto [pa, pr] = fill(p);
          total_area += pa, total_rectangle += pr;
        }
        if(total_rectangle > 0 && total_area / total_rectangle > best_fill)
          best_fill = total_area / total_rectangle, best = std::move(split);
      }
    }
    if(best.empty()) {
      for(std::uint32_t f : set) part[f] = parts;
      ++parts;
    } else {
      for(auto& p : best) queue.emplace_back(std::move(p), level + 1);
    }
  }
  return part;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_SPLIT_CHARTS_H
