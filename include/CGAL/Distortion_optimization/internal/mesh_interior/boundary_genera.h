// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The last check of mesh_interior(): the boundary of the complex has the components, and the
// genera, of the input surface (details finer than the sizes can change them with a valid complex).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_BOUNDARY_GENERA_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_BOUNDARY_GENERA_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/complex_boundary.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The genera of the connected components of a closed, orientable 2-manifold surface given by its
// triangles (vertex numbers below n), sorted: a component's V - E + F = V - F / 2 is 2 - 2 genus.
inline std::vector<long> genera_of_components(std::size_t n, const std::vector<std::array<std::size_t, 3>>& triangles)
{
  std::vector<std::size_t> parent(n);
  for(std::size_t v = 0; v < n; ++v) parent[v] = v;
  const auto root = [&](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const auto& t : triangles)
    for(int k = 1; k < 3; ++k) parent[root(t[k])] = root(t[0]);
  std::vector<long> vertices(n, 0), faces(n, 0);
  std::vector<bool> used(n, false);
  for(const auto& t : triangles) {
    ++faces[root(t[0])];
    for(const std::size_t v : t) used[v] = true;
  }
  for(std::size_t v = 0; v < n; ++v)
    if(used[v]) ++vertices[root(v)];
  std::vector<long> genera;
  for(std::size_t r = 0; r < n; ++r)
    if(faces[r] > 0) genera.push_back(1 - (vertices[r] - faces[r] / 2) / 2);
  std::sort(genera.begin(), genera.end());
  return genera;
}

// The genera of the components of the boundary of the complex (a 2-manifold).
template <class C3T3>
std::vector<long> boundary_genera(const C3T3& c3t3)
{
  std::unordered_map<typename C3T3::Triangulation::Vertex_handle, std::size_t> number;
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(is_boundary_facet(c3t3, c, i)) {
        std::array<std::size_t, 3> t;
        for(int k = 1; k < 4; ++k) t[k - 1] = number.emplace(c->vertex((i + k) % 4), number.size()).first->second;
        triangles.push_back(t);
      }
  return genera_of_components(number.size(), triangles);
}

// The genera of the components of a closed triangle surface.
template <class Surface>
std::vector<long> surface_genera(const Surface& surface)
{
  std::vector<std::array<std::size_t, 3>> triangles;
  std::size_t n = 0;
  for(const auto f : faces(surface)) {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(const auto v : vertices_around_face(halfedge(f, surface), surface)) n = (std::max)(n, (t[k++] = std::size_t(v)) + 1);
    triangles.push_back(t);
  }
  return genera_of_components(n, triangles);
}

// "2 components of genera 0, 1" (up to six listed).
inline std::string describe_genera(const std::vector<long>& genera)
{
  std::string text = std::to_string(genera.size()) + (genera.size() == 1 ? " component of genus " : " components of genera ");
  for(std::size_t i = 0; i < genera.size() && i < 6; ++i) text += (i > 0 ? ", " : "") + std::to_string(genera[i]);
  return text + (genera.size() > 6 ? ", ..." : "");
}

// Throws if the boundary of the complex does not have the components and genera of `surface`:
// details finer than the sizes can change the topology with a valid complex (a narrow waist
// bridged into a torus, a thin neck dropped).
template <class C3T3, class Surface>
void check_boundary_genera(const C3T3& c3t3, const Surface& surface)
{
  if(const auto meshed = boundary_genera(c3t3), input = surface_genera(surface); meshed != input)
    throw Invalid_input("mesh_interior: the boundary of Mesh_3's tetrahedra has " + describe_genera(meshed) +
                        ", the surface " + describe_genera(input) +
                        ": a neck or gap of the surface finer than the sizes was cut or bridged; give smaller sizes");
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_BOUNDARY_GENERA_H
