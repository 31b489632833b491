// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A chart flattened with a free border kept from crossing itself by a scaffold: the space about
// the chart (and in its holes) triangulated and optimized with it, as in Jiang, Schaefer, Zhu,
// Panozzo and Kaufman, "Simplicial Complex Augmentation Framework for Bijective Maps" (SCAF, 2017).
// No scaffold triangle may invert, so the border cannot cross itself, and the Newton steps are
// never shortened by a collision test: the border opens as freely as the inside moves.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_SCAFFOLD_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_SCAFFOLD_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/internal/minimize.h>
#include <CGAL/Distortion_optimization/internal/named_parameters.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>
#include <CGAL/Distortion_optimization/internal/triangle_mesh_adapter.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cstdint>
#include <list>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The scaffold of a chart at positions x: the triangles of the constrained Delaunay triangulation
// of the chart's border edges and of a box about it that lie outside the chart (an even number of
// border crossings from the outside: the holes are scaffolded too). The box's four corners are
// vertices first_corner to first_corner + 3.
inline std::vector<std::array<std::uint32_t, 3>> scaffold_triangles(const std::vector<Vector<2>>& x,
                                                                  const std::vector<std::array<std::uint32_t, 2>>& border,
                                                                  const std::array<Vector<2>, 4>& box,
                                                                  std::uint32_t first_corner)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
  CDT cdt;
  std::map<std::uint32_t, CDT::Vertex_handle> handle;
  const auto vertex = [&](std::uint32_t i, const Vector<2>& p) {
    auto [at, added] = handle.emplace(i, CDT::Vertex_handle());
    if(added) {
      at->second = cdt.insert(K::Point_2(p[0], p[1]));
      at->second->info() = i;
    }
    return at->second;
  };
  for(std::uint32_t k = 0; k < 4; ++k) vertex(first_corner + k, box[k]);
  for(const auto& e : border) cdt.insert_constraint(vertex(e[0], x[e[0]]), vertex(e[1], x[e[1]]));
  if(cdt.number_of_vertices() != handle.size())
    throw Invalid_input("the chart's border has two vertices at one point: no scaffold");
  // Nesting levels by a search from the outside, one more across each constrained edge.
  for(auto f : cdt.all_face_handles()) f->info() = -1;
  std::list<CDT::Edge> border_queue;
  const auto explore = [&](CDT::Face_handle start, int level) {
    std::list<CDT::Face_handle> queue{start};
    while(!queue.empty()) {
      CDT::Face_handle f = queue.front();
      queue.pop_front();
      if(f->info() != -1) continue;
      f->info() = level;
      for(int i = 0; i < 3; ++i) {
        CDT::Face_handle g = f->neighbor(i);
        if(g->info() != -1) continue;
        if(cdt.is_constrained(CDT::Edge(f, i))) border_queue.push_back(CDT::Edge(f, i));
        else queue.push_back(g);
      }
    }
  };
  explore(cdt.infinite_face(), 0);
  while(!border_queue.empty()) {
    const CDT::Edge e = border_queue.front();
    border_queue.pop_front();
    CDT::Face_handle g = e.first->neighbor(e.second);
    if(g->info() == -1) explore(g, e.first->info() + 1);
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for(auto f : cdt.finite_face_handles())
    if(f->info() % 2 == 0) triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return triangles;
}

// Minimizes `measure` on `chart` (a Surface_mesh of genus 0, a disk or a disk with holes) from the
// map `uv` (one-to-one), every vertex free: rounds of two of minimize()'s iterations on the chart
// with its scaffold, the scaffold made anew from each round's map, until a round gains less than
// the threshold of `optimizer` (relative), its iterations are done or its visitor returns false;
// its other options (schedule, solvers, threads) are each round's. The scaffold's triangles
// measure against their own shape when made, with a small weight (a hundredth of the chart's,
// spread evenly), so that they only resist being flattened.
template <class Mesh, class UVMap, class Measure>
Result flatten_with_scaffold(const Mesh& chart, UVMap uv, const Measure& measure, const Options& optimizer,
                             Cell_weighting weighting = Cell_weighting::AVERAGE_VOLUME)
{
  const auto start = std::chrono::steady_clock::now();
  const CGAL::Constant_property_map<typename Mesh::Vertex_index, bool> constrained(false);
  const auto np = parameters::number_of_threads(optimizer.threads).vertex_is_constrained_map(constrained);
  auto adapter = make_triangle_mesh_adapter(chart, uv, np);
  const Optimization_problem<2> base = make_problem(adapter, np);
  const std::size_t n = base.number_of_vertices(), chart_cells = base.map.number_of_cells();
  // The border edges, each once, as the boundary guard finds them (in the order of their sorted
  // ends, each from its smaller end: the order the triangulation inserts them in).
  std::vector<std::array<std::uint32_t, 2>> border = Boundary_guard<2>::boundary_faces(base.map.cells);
  for(auto& e : border) std::sort(e.begin(), e.end());

  Options options = optimizer;
  options.iterations = (std::min)(optimizer.iterations, std::size_t(2));
  options.harmonic_start = false;
  options.global_injectivity = options.untangle_first = false;
  std::vector<Vector<2>> x = base.map.target;
  Result result;
  double previous = std::numeric_limits<double>::infinity();
  for(std::size_t round = 0; result.iterations < optimizer.iterations; ++round) {
    Optimization_problem<2> p;
    p.map.cells = base.map.cells;
    p.map.inverse_rest = base.map.inverse_rest;
    p.map.rest_volume = base.map.rest_volume;
    p.map.rest_sign = base.map.rest_sign;
    p.map.target = x;
    // A box twice the chart's extent about its centre.
    Eigen::AlignedBox<double, 2> bounds;
    for(std::size_t v = 0; v < n; ++v) bounds.extend(x[v]);
    const Vector<2> centre = bounds.center(), half = bounds.sizes();
    const std::array<Vector<2>, 4> box = {centre + Vector<2>(-half[0], -half[1]), centre + Vector<2>(half[0], -half[1]),
                                          centre + Vector<2>(half[0], half[1]), centre + Vector<2>(-half[0], half[1])};
    for(const auto& corner : box) p.map.target.push_back(corner);
    for(const auto& t : scaffold_triangles(x, border, box, static_cast<std::uint32_t>(n))) {
      const Vector<2>& a = p.map.target[t[0]];
      Matrix<2> Dm;
      Dm.col(0) = p.map.target[t[1]] - a;
      Dm.col(1) = p.map.target[t[2]] - a;
      p.map.add_cell({t[0], t[1], t[2]}, Dm, 1);
    }
    p.omega.assign(n + 4, 1.);
    p.is_free.assign(n + 4, 1);
    std::fill(p.is_free.begin() + n, p.is_free.end(), 0);
    p.finalize(weighting);
    double chart_weight = 0;
    for(std::size_t c = 0; c < chart_cells; ++c) chart_weight += p.cell_weight[c];
    const std::size_t scaffold_cells = p.map.number_of_cells() - chart_cells;
    p.total_weight = chart_weight;
    for(std::size_t c = chart_cells; c < p.map.number_of_cells(); ++c) {
      const double w = 0.01 * chart_weight / double(scaffold_cells);
      p.incidence_weight[c] = w / 3;
      p.cell_weight[c] = w;
      p.total_weight += w;
    }
    const Result r = minimize(p, measure, adapter.traits, options);
    std::copy(p.map.target.begin(), p.map.target.begin() + n, x.begin());
    result.iterations += r.iterations;
    if(round == 0) result.initial_energy = r.initial_energy;
    result.final_energy = r.final_energy;
    result.energy_per_iteration.push_back(r.final_energy);
    result.inverted_cells = r.inverted_cells;
    if(r.stopped_by_visitor) {
      result.stopped_by_visitor = true;
      break;
    }
    if(!(previous - r.final_energy > optimizer.threshold * std::abs(r.final_energy))) {
      result.converged = true;
      break;
    }
    previous = r.final_energy;
  }
  adapter.write_targets(uv, x, std::vector<unsigned char>(n, 1));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_SCAFFOLD_H
