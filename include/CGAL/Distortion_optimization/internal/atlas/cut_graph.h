// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The atlas's seams on one piece (a connected Surface_mesh): the loops that open its handles, and
// the shortest paths that join cone vertices to the seams. Seams are edge flags; the piece itself
// is never modified.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CUT_GRAPH_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CUT_GRAPH_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <class Mesh>
double edge_length(const Mesh& m, typename Mesh::Edge_index e)
{
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)))));
}

// Dijkstra's queue of (distance, vertex) entries, nearest first, and one step of the search: the
// edges from `v`, reached at distance `d`, relaxed.
using Path_queue = std::priority_queue<std::pair<double, std::uint32_t>, std::vector<std::pair<double, std::uint32_t>>,
                                       std::greater<std::pair<double, std::uint32_t>>>;

template <class Mesh>
void relax_edges_from(const Mesh& m, typename Mesh::Vertex_index v, double d, std::vector<double>& distance,
                      std::vector<typename Mesh::Halfedge_index>& arrival, Path_queue& queue)
{
  for(auto h : CGAL::halfedges_around_source(v, m)) {
    const std::size_t w = std::size_t(m.target(h));
    const double through = d + edge_length(m, m.edge(h));
    if(through < distance[w]) {
      distance[w] = through;
      arrival[w] = h;
      queue.emplace(through, std::uint32_t(w));
    }
  }
}

// Dijkstra's shortest paths along the edges from the vertices `sources`: each vertex's distance,
// and the halfedge by which its path arrives (null at the sources and where nothing reaches).
// With `goal`, the search ends at the first vertex reached for which it holds, and returns it
// (the null vertex if none is reached); the paths found so far are kept.
template <class Mesh>
typename Mesh::Vertex_index shortest_paths(const Mesh& m, const std::vector<typename Mesh::Vertex_index>& sources,
                                           std::vector<double>& distance, std::vector<typename Mesh::Halfedge_index>& arrival,
                                           const std::function<bool(typename Mesh::Vertex_index)>& goal = {})
{
  distance.assign(m.number_of_vertices(), std::numeric_limits<double>::infinity());
  arrival.assign(m.number_of_vertices(), Mesh::null_halfedge());
  Path_queue queue;
  for(auto s : sources) {
    distance[std::size_t(s)] = 0;
    queue.emplace(0., std::uint32_t(s));
  }
  while(!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    const typename Mesh::Vertex_index v(i);
    if(d > distance[i] || m.halfedge(v) == Mesh::null_halfedge()) continue;
    if(goal && goal(v)) return v;
    relax_edges_from(m, v, d, distance, arrival, queue);
  }
  return Mesh::null_vertex();
}

// Whether each vertex lies on a seam or a border.
template <class Mesh>
std::vector<bool> vertices_on_cuts(const Mesh& m, const std::vector<bool>& seam)
{
  std::vector<bool> on(m.number_of_vertices(), false);
  for(auto e : m.edges())
    if(seam[std::size_t(e)] || m.is_border(e)) on[std::size_t(m.vertex(e, 0))] = on[std::size_t(m.vertex(e, 1))] = true;
  return on;
}

// Seams along which a piece with handles opens into one of genus 0: the loops of a tree-cotree
// decomposition (Eppstein, "Dynamic generators of topologically embedded graphs", 2003), with
// the tree of shortest paths from one vertex and the dual tree spanning the longest loops, so that
// the 2g loops left are short (Erickson and Whittlesey, "Greedy optimal homotopy and homology
// generators", 2005); the tree's branches that lead to no loop are pruned. Each border is one
// node of the dual graph (the hole capped), so that a loop about a hole is not taken for a handle.
// Nothing on a piece of genus 0.
template <class Mesh>
std::vector<bool> handle_seams(const Mesh& m)
{
  const std::size_t E = m.number_of_edges(), F = m.number_of_faces();
  std::vector<bool> cut(E, false);
  if(m.number_of_vertices() == 0) return cut;
  std::vector<double> distance;
  std::vector<typename Mesh::Halfedge_index> arrival;
  shortest_paths(m, {*m.vertices().begin()}, distance, arrival);
  std::vector<bool> tree(E, false);
  for(auto h : arrival)
    if(h != Mesh::null_halfedge()) tree[std::size_t(m.edge(h))] = true;

  // The dual nodes: the faces, then one per border.
  std::vector<std::size_t> node(m.number_of_halfedges(), 0);
  std::size_t nodes = F;
  for(auto h : m.halfedges())
    if(!m.is_border(h)) node[std::size_t(h)] = std::size_t(m.face(h));
  std::vector<bool> labelled(m.number_of_halfedges(), false);
  for(auto h : m.halfedges()) {
    if(!m.is_border(h) || labelled[std::size_t(h)]) continue;
    for(auto g : CGAL::halfedges_around_face(h, m)) {
      node[std::size_t(g)] = nodes;
      labelled[std::size_t(g)] = true;
    }
    ++nodes;
  }
  // The dual tree: Kruskal's maximum spanning tree over the edges not in the primal tree, each
  // weighing the length of its loop through the primal tree.
  std::vector<typename Mesh::Edge_index> rest;
  for(auto e : m.edges())
    if(!tree[std::size_t(e)]) rest.push_back(e);
  const auto loop_length = [&](typename Mesh::Edge_index e) {
    return distance[std::size_t(m.vertex(e, 0))] + distance[std::size_t(m.vertex(e, 1))] + edge_length(m, e);
  };
  std::vector<double> weight(E, 0);
  for(auto e : rest) weight[std::size_t(e)] = loop_length(e);
  std::sort(rest.begin(), rest.end(), [&](auto a, auto b) { return weight[std::size_t(a)] > weight[std::size_t(b)]; });
  std::vector<std::size_t> parent(nodes);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for(auto e : rest) {
    const std::size_t a = find(node[std::size_t(m.halfedge(e, 0))]), b = find(node[std::size_t(m.halfedge(e, 1))]);
    if(a != b) parent[a] = b;
    else cut[std::size_t(e)] = true;   // a loop: neither tree holds it
  }
  bool any_loop = false;
  for(std::size_t e = 0; e < E; ++e) any_loop = any_loop || cut[e];
  if(!any_loop) return cut;
  // The tree's paths joining the loops to the root: the tree pruned of the branches that end at a
  // vertex on no loop.
  std::vector<int> degree(m.number_of_vertices(), 0);
  for(auto e : m.edges())
    if(tree[std::size_t(e)] || cut[std::size_t(e)]) ++degree[std::size_t(m.vertex(e, 0))], ++degree[std::size_t(m.vertex(e, 1))];
  std::vector<bool> kept = tree;
  std::vector<typename Mesh::Vertex_index> leaves;
  for(auto v : m.vertices())
    if(degree[std::size_t(v)] == 1) leaves.push_back(v);
  while(!leaves.empty()) {
    const auto v = leaves.back();
    leaves.pop_back();
    if(degree[std::size_t(v)] != 1) continue;
    for(auto h : CGAL::halfedges_around_source(v, m)) {
      const std::size_t e = std::size_t(m.edge(h));
      if(!kept[e]) continue;
      kept[e] = false;
      --degree[std::size_t(v)];
      if(--degree[std::size_t(m.target(h))] == 1) leaves.push_back(m.target(h));
      break;
    }
  }
  for(std::size_t e = 0; e < E; ++e) cut[e] = cut[e] || kept[e];
  return cut;
}

// Adds to `seam` the shortest path from `cone` to the seams and borders (to `other` where there
// are none: the first cut of a closed piece of genus 0). The search starts from the cone and ends
// where it meets them: it explores only the ball the path's length spans.
template <class Mesh>
void add_seam_to(const Mesh& m, typename Mesh::Vertex_index cone, typename Mesh::Vertex_index other, std::vector<bool>& seam)
{
  const std::vector<bool> on = vertices_on_cuts(m, seam);
  const bool none = std::find(on.begin(), on.end(), true) == on.end();
  std::vector<double> distance;
  std::vector<typename Mesh::Halfedge_index> arrival;
  auto v = shortest_paths(m, {cone}, distance, arrival,
                          [&](typename Mesh::Vertex_index w) { return none ? w == other : bool(on[std::size_t(w)]); });
  if(v == Mesh::null_vertex()) return;
  for(; arrival[std::size_t(v)] != Mesh::null_halfedge(); v = m.source(arrival[std::size_t(v)]))
    seam[std::size_t(m.edge(arrival[std::size_t(v)]))] = true;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CUT_GRAPH_H
