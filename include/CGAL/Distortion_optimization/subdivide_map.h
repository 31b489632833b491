// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Subdivision of a triangle map: the source mesh and its target map refined together with one
// connectivity (Naitsat, Saucan and Zeevi, "Geometry-based distortion measures for space
// deformation", section 4.3 and Appendix D).

#ifndef CGAL_DISTORTION_OPTIMIZATION_SUBDIVIDE_MAP_H
#define CGAL_DISTORTION_OPTIMIZATION_SUBDIVIDE_MAP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// How `subdivide_map()` places the new vertices.
enum class Subdivision_scheme
{
  LINEAR,   ///< edge midpoints, old vertices kept: the map is unchanged on every point
  LOOP      ///< Loop's stencils (with its border rules) on the source and the target alike
};

namespace internal_np {
enum subdivision_scheme_t { subdivision_scheme };
} // namespace internal_np

namespace parameters {
/// A `Subdivision_scheme` for `subdivide_map()`; default `Subdivision_scheme::LINEAR`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(subdivision_scheme_t, subdivision_scheme)
} // namespace parameters

namespace internal {

template <class Point>
constexpr int point_dimension()
{
  return std::is_same_v<Point, typename Kernel_traits<Point>::Kernel::Point_3> ? 3 : 2;
}

template <int d, class Point>
Eigen::Matrix<double, d, 1> coordinates(const Point& p)
{
  Eigen::Matrix<double, d, 1> x;
  for(int k = 0; k < d; ++k) x[k] = CGAL::to_double(p[k]);
  return x;
}

template <class Point, int d>
Point make_point(const Eigen::Matrix<double, d, 1>& x)
{
  if constexpr(d == 3) return Point(x[0], x[1], x[2]);
  else return Point(x[0], x[1]);
}

// One level of 1-to-4 subdivision of the values x (one per vertex, in vertex order) of the mesh:
// the new values of the old vertices, then one per edge (in edge order).
template <class Mesh, int d>
std::vector<Eigen::Matrix<double, d, 1>> subdivided_values(const Mesh& mesh,
                                                           const std::vector<Eigen::Matrix<double, d, 1>>& x,
                                                           const std::vector<std::size_t>& index, Subdivision_scheme scheme)
{
  using Vec = Eigen::Matrix<double, d, 1>;
  std::vector<Vec> out(x.size() + mesh.number_of_edges());
  for(auto v : mesh.vertices()) {
    const Vec& p = x[index[v]];
    Vec& q = out[index[v]];
    q = p;
    if(scheme == Subdivision_scheme::LINEAR || mesh.is_isolated(v)) continue;
    if(mesh.is_border(v)) {   // Loop's border rule: the border curve's cubic B-spline
      Vec sum = Vec::Zero();
      for(auto h : halfedges_around_target(mesh.halfedge(v), mesh))
        if(mesh.is_border(mesh.edge(h))) sum += x[index[mesh.source(h)]];
      q = 0.75 * p + 0.125 * sum;
    } else {
      Vec sum = Vec::Zero();
      std::size_t n = 0;
      for(auto u : vertices_around_target(mesh.halfedge(v), mesh)) {
        sum += x[index[u]];
        ++n;
      }
      const double c = 0.375 + 0.25 * std::cos(2 * CGAL_PI / n), beta = (0.625 - c * c) / n;
      q = (1 - n * beta) * p + beta * sum;
    }
  }
  std::size_t k = x.size();
  for(auto e : mesh.edges()) {
    const auto h = mesh.halfedge(e);
    const Vec& a = x[index[mesh.source(h)]];
    const Vec& b = x[index[mesh.target(h)]];
    if(scheme == Subdivision_scheme::LINEAR || mesh.is_border(e))
      out[k++] = 0.5 * (a + b);
    else
      out[k++] = 0.375 * (a + b) + 0.125 * (x[index[mesh.target(mesh.next(h))]] +
                                            x[index[mesh.target(mesh.next(mesh.opposite(h)))]]);
  }
  return out;
}

} // namespace internal

/*!
\ingroup PkgDistortionOptimizationRef

Subdivides a triangle map (`number_of_iterations` times, once by default): each triangle of `mesh` becomes four (one new vertex
per edge), in the source (the mesh's points) and in the target alike, so that the result is a
map between the two refined meshes with the same connectivity. The paper (section 4.3, Fig. 11)
subdivides an optimized map this way to approximate the optimal map at a higher resolution for
a fraction of the cost of optimizing there.

- `Subdivision_scheme::LINEAR` puts the new vertices at the edge midpoints: every child triangle
  has its parent's Jacobian, so every measure's energy (`compute_distortion()`'s means) is
  exactly that of the coarse map (the paper's Appendix D), and no triangle flips.
- `Subdivision_scheme::LOOP` applies Loop's stencils, with its border rules, to the source and to
  the target: the source approaches a smooth surface and the map a smooth map. Loop's averages
  do not guarantee injectivity, but they rarely flip a triangle of a smooth map.

CGAL's `Subdivision_method_3::Loop_subdivision()` refines one point map and the connectivity in
place, so it cannot refine a source and a target with one connectivity change; this function
refines both with the same stencils and rebuilds the mesh once per level.

\tparam Point the point type of the `Surface_mesh` (`Point_2` or `Point_3`)
\tparam TargetMap a `ReadWritePropertyMap` from `Surface_mesh<Point>::Vertex_index` to `Point_2`
        or `Point_3`, which accepts the new vertices (e.g. a property map of `mesh`)
\param mesh a triangle mesh; it is rebuilt: its old vertices keep their indices when it has no
       removed elements (otherwise they are renumbered in iteration order), the new vertices
       follow, one per edge; its faces and edges are renumbered, and their properties dropped
\param target the target of each vertex, written for every vertex of the refined mesh
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the ones below

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the number of refinements (each multiplies the triangles by four; 0 leaves the map as it is)}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{subdivision_scheme}
    \cgalParamDescription{the scheme, as above (`Distortion_optimization::parameters::subdivision_scheme()`)}
    \cgalParamType{`Distortion_optimization::Subdivision_scheme`}
    \cgalParamDefault{`Subdivision_scheme::LINEAR`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Invalid_input if a face is not a triangle
*/
template <class Point, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void subdivide_map(CGAL::Surface_mesh<Point>& mesh, TargetMap target, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const unsigned levels = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 1u);
  const Subdivision_scheme scheme =
    choose_parameter(get_parameter(np, internal_np::subdivision_scheme), Subdivision_scheme::LINEAR);
  using Mesh = CGAL::Surface_mesh<Point>;
  using Target = typename boost::property_traits<TargetMap>::value_type;
  constexpr int ds = internal::point_dimension<Point>(), dt = internal::point_dimension<Target>();
  for(auto f : mesh.faces())
    if(mesh.degree(f) != 3) throw Invalid_input("face " + std::to_string(std::size_t(f)) + " is not a triangle");
  for(unsigned level = 0; level < levels; ++level) {
    // Values in the mesh's iteration order; edge vertices follow the old ones.
    std::vector<std::size_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
    std::vector<Eigen::Matrix<double, ds, 1>> source;
    std::vector<Eigen::Matrix<double, dt, 1>> image;
    for(auto v : mesh.vertices()) {
      index[v] = source.size();
      source.push_back(internal::coordinates<ds>(mesh.point(v)));
      image.push_back(internal::coordinates<dt>(get(target, v)));
    }
    std::vector<std::size_t> edge_vertex(mesh.number_of_edges() + mesh.number_of_removed_edges());
    std::size_t k = source.size();
    for(auto e : mesh.edges()) edge_vertex[e] = k++;
    std::vector<std::array<std::size_t, 6>> faces;   // corners, then the edge vertices opposite them
    for(auto f : mesh.faces()) {
      const auto h = mesh.halfedge(f);
      const auto hs = std::array<typename Mesh::Halfedge_index, 3>{h, mesh.next(h), mesh.next(mesh.next(h))};
      // Corner i is the target of halfedge i; the edge opposite corner i is that of halfedge i + 2.
      std::array<std::size_t, 6> face;
      for(int i = 0; i < 3; ++i) {
        face[i] = index[mesh.target(hs[i])];
        face[3 + i] = edge_vertex[mesh.edge(hs[(i + 2) % 3])];
      }
      faces.push_back(face);
    }
    const auto new_source = internal::subdivided_values<Mesh, ds>(mesh, source, index, scheme);
    const auto new_image = internal::subdivided_values<Mesh, dt>(mesh, image, index, scheme);

    mesh.clear_without_removing_property_maps();
    std::vector<typename Mesh::Vertex_index> vertex;
    for(std::size_t i = 0; i < new_source.size(); ++i) {
      vertex.push_back(mesh.add_vertex(internal::make_point<Point, ds>(new_source[i])));
      put(target, vertex.back(), internal::make_point<Target, dt>(new_image[i]));
    }
    for(const auto& f : faces) {
      // Corners a, b, c (targets of h, next h, next next h); m_a is on the edge opposite a.
      const auto a = vertex[f[0]], b = vertex[f[1]], c = vertex[f[2]], ma = vertex[f[3]], mb = vertex[f[4]], mc = vertex[f[5]];
      mesh.add_face(a, mc, mb);
      mesh.add_face(b, ma, mc);
      mesh.add_face(c, mb, ma);
      mesh.add_face(ma, mb, mc);
    }
  }
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_SUBDIVIDE_MAP_H
