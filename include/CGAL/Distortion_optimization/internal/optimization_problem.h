// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Everything Algorithm 1 needs, built once from a Simplicial_map: vertex weights omega(v), the
// cell weights w(c) = sum_{v in c} omega(v) w(c, v) (step 2), which vertices are free, and each
// vertex's ring of incident cells stored contiguously (vertex -> cells, CSR).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_OPTIMIZATION_PROBLEM_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_OPTIMIZATION_PROBLEM_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/scaling.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

struct Incidence
{
  std::uint32_t cell;
  std::uint32_t local;   // position of the vertex in the cell, 0..n
};

template <int n>
struct Optimization_problem
{
  Simplicial_map<n> map;
  std::vector<double> omega;               // vertex weights, 1 by default
  std::vector<unsigned char> is_free;      // 0 for constrained vertices
  std::vector<double> incidence_weight;    // w(c, v), equal for all vertices of c (eq. 23)
  std::vector<double> cell_weight;         // w(c)
  double total_weight = 0;                 // sum_c w(c)
  std::vector<std::uint32_t> ring_begin;   // ring of v: ring[ring_begin[v] .. ring_begin[v+1])
  std::vector<Incidence> ring;
  // A sliding boundary (named parameter sliding_boundary): these free vertices move on a surface;
  // slide(v, x, normal) is its closest point to x, a position of vertex v (which the surface may
  // use as a hint of where to search), and sets the unit normal there. Empty: none.
  std::vector<unsigned char> is_sliding;
  std::function<Vector<n>(std::size_t, const Vector<n>&, Vector<n>&)> slide;

  std::size_t number_of_vertices() const { return map.number_of_vertices(); }
  bool slides(std::size_t v) const { return !is_sliding.empty() && is_sliding[v]; }

  // Call once map, omega (may be empty) and is_free are set.
  void finalize(Cell_weighting weighting)
  {
    const std::size_t nv = map.number_of_vertices(), nc = map.number_of_cells();
    if(omega.empty()) omega.assign(nv, 1.);
    if(omega.size() != nv || is_free.size() != nv)
      throw Invalid_input("vertex weights or constraints do not match the number of vertices");
    incidence_weight.resize(nc);
    cell_weight.resize(nc);
    total_weight = 0;
    for(std::size_t c = 0; c < nc; ++c) {
      const double v = map.rest_volume[c];
      incidence_weight[c] = weighting == Cell_weighting::UNIFORM ? 1.
                          : weighting == Cell_weighting::VOLUME ? v : v / (n + 1);
      double omega_sum = 0;
      for(auto i : map.cells[c]) omega_sum += omega[i];
      cell_weight[c] = omega_sum * incidence_weight[c];
      total_weight += cell_weight[c];
    }
    build_rings();
  }

  // Multiplies every cell weight by `factor`, a power of two: exactly, so that no step of the
  // optimizer changes, only the size of its energies and derivatives.
  void scale_weights(double factor)
  {
    scale_exactly(incidence_weight, factor);
    scale_exactly(cell_weight, factor);
    total_weight *= factor;
  }

  // The rings, from the map's cells.
  void build_rings()
  {
    const std::size_t nv = map.number_of_vertices(), nc = map.number_of_cells();
    ring_begin.assign(nv + 1, 0);
    for(const auto& cell : map.cells)
      for(auto i : cell) ++ring_begin[i + 1];
    for(std::size_t v = 0; v < nv; ++v) ring_begin[v + 1] += ring_begin[v];
    ring.resize(ring_begin[nv]);
    std::vector<std::uint32_t> fill(ring_begin.begin(), ring_begin.end() - 1);
    for(std::size_t c = 0; c < nc; ++c)
      for(int i = 0; i <= n; ++i)
        ring[fill[map.cells[c][i]]++] = Incidence{static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(i)};
  }
};

// The part of a problem made of the cells with a vertex in `region`: those vertices keep their
// freedom (and sliding), the other vertices of these cells are fixed; weights are the problem's.
// Vertex i of the part is vertex global[i] of the problem. The part's energy differs from the
// problem's by a constant (the cells left out do not move).
template <int n>
Optimization_problem<n> part_of(const Optimization_problem<n>& p, const std::vector<unsigned char>& region,
                                std::vector<std::uint32_t>& global)
{
  Optimization_problem<n> part;
  std::vector<std::int64_t> local(p.number_of_vertices(), -1);
  global.clear();
  for(std::size_t c = 0; c < p.map.number_of_cells(); ++c) {
    bool inside = false;
    for(auto v : p.map.cells[c]) inside = inside || region[v];
    if(!inside) continue;
    typename Simplicial_map<n>::Cell cell;
    for(int i = 0; i <= n; ++i) {
      const auto v = p.map.cells[c][i];
      if(local[v] < 0) {
        local[v] = static_cast<std::int64_t>(global.size());
        global.push_back(v);
        part.map.target.push_back(p.map.target[v]);
        part.omega.push_back(p.omega[v]);
        part.is_free.push_back(region[v] && p.is_free[v]);
        if(!p.is_sliding.empty()) part.is_sliding.push_back(region[v] && p.is_sliding[v]);
      }
      cell[i] = static_cast<typename Simplicial_map<n>::Index>(local[v]);
    }
    part.map.cells.push_back(cell);
    part.map.inverse_rest.push_back(p.map.inverse_rest[c]);
    part.map.rest_volume.push_back(p.map.rest_volume[c]);
    part.map.rest_sign.push_back(p.map.rest_sign[c]);
    part.incidence_weight.push_back(p.incidence_weight[c]);
    part.cell_weight.push_back(p.cell_weight[c]);
    part.total_weight += p.cell_weight[c];
  }
  if(p.slide)
    part.slide = [slide = p.slide, global](std::size_t v, const Vector<n>& x, Vector<n>& normal) {
      return slide(global[v], x, normal);
    };
  part.build_rings();
  return part;
}

// The free vertices in increasing order (the global step numbers its unknowns in this order).
template <int n>
std::vector<std::uint32_t> free_vertices(const Optimization_problem<n>& p)
{
  std::vector<std::uint32_t> vertices;
  for(std::size_t v = 0; v < p.number_of_vertices(); ++v)
    if(p.is_free[v]) vertices.push_back(static_cast<std::uint32_t>(v));
  return vertices;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_OPTIMIZATION_PROBLEM_H
