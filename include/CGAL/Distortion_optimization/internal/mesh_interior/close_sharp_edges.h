// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A check of mesh_interior() before Mesh_3 runs: sharp edges closer than the facet distance that
// meet only farther away (the sides of a slit), whose protection by Mesh_3 would not end.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CLOSE_SHARP_EDGES_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CLOSE_SHARP_EDGES_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/squared_distance_3.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Mesh_3 protects the sharp edges with balls that must not overlap unless they are neighbours on a
// curve: where two parts of the sharp edges come closer than the sizes without meeting nearby (the
// two sides of a thin slit, a hairpin), the balls shrink to the gap and their number grows without
// bound. Short close stretches are harmless (scanned surfaces have sharp edges far closer than the
// facet distance over a fraction of the edge size).
// Returns the lowest pair of sharp edges (by `surface`'s edge indices) closer than `distance` along
// more than `length` of each, neither joined through sharp edges that come within 3 `distance` of
// the one's point nearest the other, and their distance; (0, 0, distance) if none. The sharp edges
// are those the domain protects (PMP::detect_sharp_edges(), `angle`).
template <class Surface>
std::tuple<std::size_t, std::size_t, double> close_sharp_edges(const Surface& surface, double angle, double distance,
                                                               double length)
{
  using K = typename Kernel_traits<typename Surface::Point>::Kernel;
  using Edge = typename Surface::Edge_index;
  using Vertex = typename Surface::Vertex_index;
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::tuple<std::size_t, std::size_t, double> closest(0, 0, distance);
  std::unordered_map<Edge, bool> sharp_of;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(surface, angle, boost::make_assoc_property_map(sharp_of));
  std::vector<Edge> sharp;
  std::unordered_map<Vertex, std::vector<Edge>> at;   // the sharp edges at each vertex
  for(Edge e : edges(surface))
    if(sharp_of[e]) {
      sharp.push_back(e);
      for(int k = 0; k < 2; ++k) at[surface.vertex(e, k)].push_back(e);
    }
  const auto segment = [&](Edge e) { return typename K::Segment_3(surface.point(surface.vertex(e, 0)), surface.point(surface.vertex(e, 1))); };
  std::vector<Box> boxes;
  for(Edge e : sharp) {
    const Bbox_3 b = segment(e).bbox();
    boxes.emplace_back(Bbox_3(b.xmin() - distance, b.ymin() - distance, b.zmin() - distance, b.xmax() + distance,
                              b.ymax() + distance, b.zmax() + distance), std::size_t(e));
  }
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    const Edge e(a.info()), f(b.info());
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j)
        if(surface.vertex(e, i) == surface.vertex(f, j)) return;
    const auto se = segment(e), sf = segment(f);
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(se, sf)));
    const std::tuple<std::size_t, std::size_t, double> pair((std::min)(a.info(), b.info()), (std::max)(a.info(), b.info()), d);
    if(!(d < std::get<2>(closest) || (d == std::get<2>(closest) && d < distance && pair < closest))) return;
    // The length of each within `distance` of the other and the point of e nearest to f, sampled
    // (a sample suffices: the walk's ball is 3 times the gap).
    typename K::Point_3 near = se.source();
    double best = std::numeric_limits<double>::infinity();
    std::size_t close_e = 0, close_f = 0;
    constexpr int samples = 64;
    const auto sample = [&](const typename K::Segment_3& g, int n) {
      return g.source() + (g.target() - g.source()) * (double(n) / samples);
    };
    for(int n = 0; n <= samples; ++n) {
      const auto p = sample(se, n);
      const double d2 = CGAL::to_double(CGAL::squared_distance(p, sf));
      if(d2 < best) { best = d2; near = p; }
      close_e += d2 < distance * distance ? 1 : 0;
      close_f += CGAL::to_double(CGAL::squared_distance(sample(sf, n), se)) < distance * distance ? 1 : 0;
    }
    const auto run = [&](const typename K::Segment_3& g, std::size_t close) {
      return std::sqrt(CGAL::to_double(g.squared_length())) * close / (samples + 1);
    };
    if(run(se, close_e) <= length || run(sf, close_f) <= length) return;
    const double reach = 3 * distance;
    std::vector<Edge> stack{e};
    std::unordered_set<Edge> seen{e};
    while(!stack.empty()) {
      const Edge g = stack.back();
      stack.pop_back();
      if(g == f) return;
      for(int k = 0; k < 2; ++k)
        for(Edge h : at[surface.vertex(g, k)])
          if(seen.insert(h).second && CGAL::to_double(CGAL::squared_distance(near, segment(h))) < reach * reach) stack.push_back(h);
    }
    closest = pair;
  });
  return closest;
}

// Throws, naming their vertices, where close_sharp_edges() finds sharp edges closer than the facet
// distance along more than the edge size (none are protected at a `sharp_edge_angle` of 180).
template <class CheckedSurface>
void check_sharp_edges_apart(const CheckedSurface& checked, double sharp_edge_angle, double facet_distance,
                             double edge_size)
{
  if(sharp_edge_angle < 180) {
    const double scaled = checked.scale * facet_distance;
    const auto [e, f, d] = close_sharp_edges(checked.surface, sharp_edge_angle, scaled, checked.scale * edge_size);
    if(d < scaled) {
      const auto name = [&](std::size_t edge) {
        const auto h = checked.surface.halfedge(typename CheckedSurface::Surface::Edge_index(edge));
        return "vertices " + std::to_string(checked.vertex_names[std::size_t(source(h, checked.surface))]) + ", " +
               std::to_string(checked.vertex_names[std::size_t(target(h, checked.surface))]);
      };
      char text[200];
      std::snprintf(text, sizeof text, " are %.3g apart, less than the facet distance (%.3g), along more than the edge size (%.3g), and meet only farther away",
                    d / checked.scale, facet_distance, edge_size);
      throw Invalid_input("mesh_interior: the sharp edges of the surface at " + name(e) + " and at " + name(f) + text +
                          " (the sides of a slit?): Mesh_3 would protect them with balls no larger than the gap, for "
                          "minutes or without end; give sizes below their distance (facet distance, facet size, cell "
                          "size), or a larger sharp_edge_angle (180 protects no edge)");
    }
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_CLOSE_SHARP_EDGES_H
