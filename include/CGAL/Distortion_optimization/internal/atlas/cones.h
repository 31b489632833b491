// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The cone vertices and the holes of a piece that its seams must reach for the piece to flatten
// with little distortion.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CONES_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CONES_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/atlas/cut_graph.h>
#include <CGAL/Distortion_optimization/internal/sparse_cholesky.h>

#include <CGAL/Surface_mesh.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The cotangent Laplacian's edge weights (the negative ones raised to a small positive floor, so
// that the system below stays positive definite) and each vertex's angle defect: 2 pi, or pi on a
// border, less the angles about it.
template <class Mesh>
void cotangent_weights_and_defects(const Mesh& m, std::vector<double>& weight, std::vector<double>& defect)
{
  weight.assign(m.number_of_edges(), 0);
  defect.assign(m.number_of_vertices(), 0);
  for(auto v : m.vertices()) defect[std::size_t(v)] = m.is_border(v) ? M_PI : 2 * M_PI;
  for(auto f : m.faces()) {
    auto h = m.halfedge(f);
    for(int i = 0; i < 3; ++i, h = m.next(h)) {
      // The angle at the corner opposite h's edge, at the target of next(h).
      const auto& a = m.point(m.source(h));
      const auto& b = m.point(m.target(h));
      const auto& c = m.point(m.target(m.next(h)));
      const double ux = CGAL::to_double(a.x() - c.x()), uy = CGAL::to_double(a.y() - c.y()), uz = CGAL::to_double(a.z() - c.z());
      const double wx = CGAL::to_double(b.x() - c.x()), wy = CGAL::to_double(b.y() - c.y()), wz = CGAL::to_double(b.z() - c.z());
      const double dot = ux * wx + uy * wy + uz * wz;
      const double cross = std::sqrt((uy * wz - uz * wy) * (uy * wz - uz * wy) + (uz * wx - ux * wz) * (uz * wx - ux * wz) +
                                     (ux * wy - uy * wx) * (ux * wy - uy * wx));
      weight[std::size_t(m.edge(h))] += cross > 0 ? 0.5 * dot / cross : 0;
      defect[std::size_t(m.target(m.next(h)))] -= std::atan2(cross, dot);
    }
  }
  for(double& w : weight) w = (std::max)(w, 1e-4);
}

// Seams that open the holes a flattening cannot keep as holes. A hole's border turns by -2 pi in
// the plane; one whose loop turns on the surface (the sum of pi less the angles at its vertices)
// by more than `tolerance` (radians) less or more would have the flattening make the difference
// up by scaling the chart about it, as about a cone, and the seams of the cones cannot help (the
// conformal flattening below keeps the borders' lengths). A shortest path from each such loop to
// the piece's outer border (the loop that turns most: +2 pi in the plane), or to the seams and
// loops already joined to it, frees its turning. `defect`: cotangent_weights_and_defects()'s.
template <class Mesh>
void add_hole_seams(const Mesh& m, const std::vector<double>& defect, double tolerance, std::vector<bool>& seam)
{
  using Vertex = typename Mesh::Vertex_index;
  std::vector<std::vector<Vertex>> loops;
  std::vector<double> turning;
  std::vector<bool> visited(m.number_of_halfedges(), false);
  for(auto h : m.halfedges()) {
    if(!m.is_border(h) || visited[std::size_t(h)]) continue;
    loops.emplace_back();
    turning.push_back(0);
    for(auto g : CGAL::halfedges_around_face(h, m)) {
      visited[std::size_t(g)] = true;
      loops.back().push_back(m.target(g));
      turning.back() += defect[std::size_t(m.target(g))];
    }
  }
  if(loops.size() < 2) return;
  const std::size_t outer = std::size_t(std::max_element(turning.begin(), turning.end()) - turning.begin());
  // Joined: the outer loop, and the seams and loops the seams so far (a user's) join to it.
  std::vector<std::size_t> loop_of(m.number_of_vertices(), loops.size());
  for(std::size_t i = 0; i < loops.size(); ++i)
    for(Vertex v : loops[i]) loop_of[std::size_t(v)] = i;
  std::vector<bool> joined(m.number_of_vertices(), false), loop_joined(loops.size(), false);
  std::vector<Vertex> reached;
  const auto join_loop = [&](std::size_t i) {
    loop_joined[i] = true;
    for(Vertex v : loops[i])
      if(!joined[std::size_t(v)]) joined[std::size_t(v)] = true, reached.push_back(v);
  };
  join_loop(outer);
  while(!reached.empty()) {
    const Vertex v = reached.back();
    reached.pop_back();
    const std::size_t i = loop_of[std::size_t(v)];
    if(i < loops.size() && !loop_joined[i]) join_loop(i);
    for(auto h : CGAL::halfedges_around_source(v, m))
      if(seam[std::size_t(m.edge(h))] && !joined[std::size_t(m.target(h))])
        joined[std::size_t(m.target(h))] = true, reached.push_back(m.target(h));
  }
  std::vector<bool> off(loops.size(), false);
  for(std::size_t i = 0; i < loops.size(); ++i) off[i] = !loop_joined[i] && std::abs(turning[i] + 2 * M_PI) > tolerance;
  // One search grown from the joined vertices, however many the loops: the first vertex of a loop
  // that is off to be reached joins that loop by the path it came by, and the path and the loop
  // then search on at distance 0 (so each loop is joined by a shortest path to what was joined
  // when the search reached it, the nearest first).
  std::vector<double> distance(m.number_of_vertices(), std::numeric_limits<double>::infinity());
  std::vector<typename Mesh::Halfedge_index> arrival(m.number_of_vertices(), Mesh::null_halfedge());
  Path_queue queue;
  const auto start_from = [&](Vertex v) {
    distance[std::size_t(v)] = 0;
    arrival[std::size_t(v)] = Mesh::null_halfedge();
    queue.emplace(0., std::uint32_t(v));
  };
  for(auto v : m.vertices())
    if(joined[std::size_t(v)]) start_from(v);
  std::vector<Vertex> path;
  while(!queue.empty()) {
    const auto [d, k] = queue.top();
    queue.pop();
    if(d > distance[k]) continue;
    const Vertex v(k);
    if(loop_of[k] < loops.size() && off[loop_of[k]]) {
      off[loop_of[k]] = false;
      path.clear();
      for(Vertex w = v; arrival[std::size_t(w)] != Mesh::null_halfedge(); w = m.source(arrival[std::size_t(w)])) {
        seam[std::size_t(m.edge(arrival[std::size_t(w)]))] = true;
        path.push_back(w);
      }
      for(Vertex w : path) start_from(w);
      for(Vertex w : loops[loop_of[k]]) start_from(w);
      continue;
    }
    relax_edges_from(m, v, d, distance, arrival, queue);
  }
}

// Cone vertices, chosen as in Ben-Chen, Gotsman and Bunin, "Conformal flattening by curvature
// prescription and metric scaling" (2008): the log scale factor u of the conformal flattening
// that keeps the lengths on the borders, the seams and the cones so far (u = 0 there; L u = -K
// elsewhere, L the cotangent Laplacian and K the angle defects) is largest in magnitude where the
// flattening would stretch or shrink the piece most; that vertex becomes the next cone, until
// |u| <= `max_log_scale` everywhere or `max_cones` are placed. A closed piece without seams gets
// two cones at least: a cut needs both ends. `weight`, `defect`: cotangent_weights_and_defects()'s.
template <class Mesh>
std::vector<typename Mesh::Vertex_index> place_cones(const Mesh& m, const std::vector<double>& weight, const std::vector<double>& defect,
                                                     const std::vector<bool>& seam, double max_log_scale, std::size_t max_cones)
{
  using Vertex = typename Mesh::Vertex_index;
  std::vector<bool> fixed = vertices_on_cuts(m, seam);
  std::vector<Vertex> cones;
  if(std::find(fixed.begin(), fixed.end(), true) == fixed.end()) {
    Vertex sharpest = *m.vertices().begin();
    for(auto v : m.vertices())
      if(std::abs(defect[std::size_t(v)]) > std::abs(defect[std::size_t(sharpest)])) sharpest = v;
    cones.push_back(sharpest);
    fixed[std::size_t(sharpest)] = true;
  }
  const bool needs_a_cut = cones.size() == 1;
  // One factorization: a cone c added later is a point source at c whose strength makes u(c) = 0,
  // so that u = u0 + sum_j a_j g_j, with g_j the solution for a unit source at cone j (one solve
  // each with the same factor) and a the small system G_CC a = -u0_C.
  std::vector<int> column(m.number_of_vertices());
  int size = 0;
  for(auto v : m.vertices()) column[std::size_t(v)] = fixed[std::size_t(v)] ? -1 : size++;
  if(size == 0) return cones;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs(size);
  for(auto v : m.vertices())
    if(column[std::size_t(v)] >= 0) rhs[column[std::size_t(v)]] = -defect[std::size_t(v)];
  for(auto e : m.edges()) {
    const int a = column[std::size_t(m.vertex(e, 0))], b = column[std::size_t(m.vertex(e, 1))];
    const double w = weight[std::size_t(e)];
    if(a >= 0) entries.emplace_back(a, a, w);
    if(b >= 0) entries.emplace_back(b, b, w);
    if(a >= 0 && b >= 0) entries.emplace_back((std::max)(a, b), (std::min)(a, b), -w);
  }
  Eigen::SparseMatrix<double> L(size, size);
  L.setFromTriplets(entries.begin(), entries.end());
  Sparse_cholesky<1> factorization(Sparse_cholesky<1>::default_cholmod_from(), Fill_reducing_order::MINIMUM_DEGREE);
  if(!factorization.factorize(L)) return cones;
  const Eigen::VectorXd u0 = factorization.solve(rhs);
  Eigen::VectorXd u = u0;
  std::vector<int> source;          // the later cones' columns
  std::vector<bool> is_source(size, false);
  std::vector<Eigen::VectorXd> green;
  while(cones.size() < max_cones) {
    Vertex largest = Mesh::null_vertex();
    double magnitude = 0;
    for(auto v : m.vertices()) {
      const int i = column[std::size_t(v)];
      if(i >= 0 && !is_source[i] && std::abs(u[i]) > magnitude)
        magnitude = std::abs(u[i]), largest = v;
    }
    if(largest == Mesh::null_vertex() || !(magnitude > max_log_scale || (needs_a_cut && cones.size() < 2))) break;
    cones.push_back(largest);
    source.push_back(column[std::size_t(largest)]);
    is_source[source.back()] = true;
    green.push_back(factorization.solve(Eigen::VectorXd::Unit(size, source.back())));
    const std::size_t k = source.size();
    Eigen::MatrixXd G(k, k);
    Eigen::VectorXd b(k);
    for(std::size_t i = 0; i < k; ++i) {
      b[i] = -u0[source[i]];
      for(std::size_t j = 0; j < k; ++j) G(i, j) = green[j][source[i]];
    }
    const Eigen::VectorXd strength = G.ldlt().solve(b);
    u = u0;
    for(std::size_t j = 0; j < k; ++j) u += strength[j] * green[j];
  }
  return cones;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_CONES_H
