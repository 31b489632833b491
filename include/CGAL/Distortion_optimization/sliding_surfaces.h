// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Surfaces on which boundary vertices slide (named parameter `sliding_boundary`): the paper's
// Fig. 13 maps a cube onto a ball with the boundary kept on the sphere, not fixed where the start
// map put it. A surface only answers one question, the closest point to a position and the unit
// normal there; the optimizer moves a sliding vertex in the tangent plane and projects it back.

#ifndef CGAL_DISTORTION_OPTIMIZATION_SLIDING_SURFACES_H
#define CGAL_DISTORTION_OPTIMIZATION_SLIDING_SURFACES_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/*!
\ingroup PkgDistortionOptimizationRef
A sphere (a circle for planar maps) as a sliding surface, with an exact-to-rounding projection:
the default unit sphere centred at the origin is the boundary of the image of
`star_shaped_to_unit_ball()`. Its `project()` takes points of dimension d = 2 or 3, and gives
the outward unit normal; it takes no hint.

\cgalModels `SlidingSurface`
*/
class Sphere_surface
{
public:
  /// The unit sphere centred at the origin.
  Sphere_surface() = default;
  /// The sphere of the given centre (its first d coordinates are used) and radius > 0.
  /// \throws Invalid_input unless the radius is positive and everything is finite.
  Sphere_surface(const std::array<double, 3>& center, double radius) : center_(center), radius_(radius)
  {
    if(!(radius > 0) || !std::isfinite(radius) || !std::isfinite(center[0]) || !std::isfinite(center[1]) ||
       !std::isfinite(center[2]))
      throw Invalid_input("a sliding sphere needs a finite centre and a finite positive radius");
  }

  /// The closest point of the sphere to `x` and the outward unit normal there (for `x` at the
  /// centre, where every point is closest: the point in the direction of the first axis).
  template <std::size_t d>
  std::array<double, d> project(const std::array<double, d>& x, std::array<double, d>& normal) const
  {
    static_assert(d == 2 || d == 3, "a sphere in the plane or in space");
    double r2 = 0;
    for(std::size_t i = 0; i < d; ++i) {
      normal[i] = x[i] - center_[i];
      r2 += normal[i] * normal[i];
    }
    const double r = std::sqrt(r2);
    if(!(r > 0)) {
      normal.fill(0.);
      normal[0] = 1;
    } else {
      for(double& u : normal) u /= r;
    }
    std::array<double, d> y;
    for(std::size_t i = 0; i < d; ++i) y[i] = center_[i] + radius_ * normal[i];
    return y;
  }

private:
  std::array<double, 3> center_ = {0., 0., 0.};
  double radius_ = 1.;
};

/*!
\ingroup PkgDistortionOptimizationRef
A closed triangle surface as a sliding surface, a model of `SlidingSurface` in 3D: closest points
from an AABB tree of its triangles (built once, with its distance-query acceleration, so that
queries can run on several threads). The normal at the closest point depends only on where that
point lies: inside a triangle, the triangle's unit normal; on an edge, the normalized sum of the
unit normals of the triangles along it; at a vertex, their mean weighted by the triangles'
angles there (the pseudo-normal of Thurmer and Wuthrich, "Computing vertex normals from polygonal
facets", 1998), not the normal of whichever of the equally close triangles answered. A vertex or
edge is shared by the triangles with the same corner coordinates; normals are oriented by the
triangles' vertex order, so that a consistently oriented surface gets consistent ones (where its
triangles' normals cancel, as on a fold, the answering triangle's is taken). The surface is
copied: the mesh it was made from may change or go away. It takes hints (the triangle of the last
answer), which spare most of a query for a point near the last one.

\cgalModels `SlidingSurface`
*/
class Triangle_surface
{
  // The tree in plain doubles: its closest points are constructions in doubles anyway, and with
  // Epick the filtered comparisons of distances to the nodes' boxes took most of each query
  // (degeneracy is still decided exactly).
  using K = CGAL::Simple_cartesian<double>;
  using Triangles = std::vector<K::Triangle_3>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>>;

public:
  /// The surface of the given triangles (each as three points, `std::array<double, 3>`).
  /// \throws Invalid_input for no triangle, a degenerate one or a non-finite coordinate.
  explicit Triangle_surface(const std::vector<std::array<std::array<double, 3>, 3>>& triangles)
    : triangles_(std::make_shared<Triangles>())
  {
    if(triangles.empty()) throw Invalid_input("a sliding surface needs at least one triangle");
    // The tree holds the surface scaled by a power of two (exactly) to coordinates of about 1: its
    // closest-point constructions multiply several lengths, which overflow or underflow far from
    // unit size (1e80 or 1e-80), where every query would fail.
    double largest = 0;
    for(std::size_t i = 0; i < triangles.size(); ++i)
      for(const auto& p : triangles[i]) {
        if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
          throw Invalid_input("triangle " + std::to_string(i) + " of the sliding surface has a non-finite coordinate");
        largest = (std::max)({largest, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
      }
    scale_ = internal::unit_scale(largest);
    triangles_->reserve(triangles.size());
    for(const auto& t : triangles) {
      const auto point = [&](const std::array<double, 3>& p) { return K::Point_3(p[0] * scale_, p[1] * scale_, p[2] * scale_); };
      triangles_->emplace_back(point(t[0]), point(t[1]), point(t[2]));
      const auto exact = [&](int i) { return CGAL::Epick::Point_3(t[i][0], t[i][1], t[i][2]); };
      if(CGAL::collinear(exact(0), exact(1), exact(2)))
        throw Invalid_input("triangle " + std::to_string(triangles_->size() - 1) + " of the sliding surface is degenerate");
    }
    tree_ = std::make_shared<Tree>(triangles_->begin(), triangles_->end());
    tree_->accelerate_distance_queries();
    normals_ = std::make_shared<const std::vector<Normals>>(feature_normals(*triangles_));
  }

  /// The surface of the faces of a triangle mesh.
  ///
  /// \tparam TriangleMesh a model of `FaceListGraph`
  /// \tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"
  ///
  /// \param tm the triangle mesh (copied; not modified)
  /// \param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
  ///        ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
  ///                    as key type and a 3D point type (with `x()`, `y()`, `z()` convertible by `CGAL::to_double()`)
  ///                    as value type}
  ///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  ///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
  ///                     must be available in `TriangleMesh`.}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Invalid_input as above, or for a face that is not a triangle.
  template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
  static Triangle_surface from_mesh(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
  {
    const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                        get_const_property_map(CGAL::vertex_point, tm));
    std::vector<std::array<std::array<double, 3>, 3>> triangles;
    for(auto f : faces(tm)) {
      std::array<std::array<double, 3>, 3> t;
      std::size_t k = 0;
      for(auto v : vertices_around_face(halfedge(f, tm), tm)) {
        if(k == 3) throw Invalid_input("a face of the sliding surface is not a triangle");
        const auto& p = get(vpm, v);
        t[k++] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
      }
      if(k != 3) throw Invalid_input("a face of the sliding surface is not a triangle");
      triangles.push_back(t);
    }
    return Triangle_surface(triangles);
  }

  /// The image of the boundary of a `Mesh_complex_3_in_triangulation_3` under a map of its
  /// vertices (a readable property map from `Vertex_handle` to `Point_3`, e.g. the start map):
  /// its boundary facets, those between a cell of the complex and one outside it, oriented
  /// outward (facing away from their cell in the source, as under any map that inverts no cell).
  /// \throws Invalid_input as the constructor (a complex without boundary has no triangle).
  template <class C3T3, class TargetMap>
  static Triangle_surface from_complex_boundary(const C3T3& c3t3, const TargetMap& target)
  {
    std::vector<std::array<std::array<double, 3>, 3>> triangles;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
      for(int i = 0; i < 4; ++i)
        if(!c3t3.is_in_complex(c->neighbor(i))) {
          // The vertices after i in cyclic order face away from it for even i, towards it for odd.
          int order[3] = {(i + 1) % 4, (i + 2) % 4, (i + 3) % 4};
          if(i % 2 == 1) std::swap(order[1], order[2]);
          std::array<std::array<double, 3>, 3> t;
          for(int j = 0; j < 3; ++j) {
            const auto& p = get(target, c->vertex(order[j]));
            t[j] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
          }
          triangles.push_back(t);
        }
    return Triangle_surface(triangles);
  }

  /// The closest point of the surface to `x` and the unit normal there (see the class: its
  /// triangle's inside a triangle, the edge's or vertex's pseudo-normal on an edge or a vertex).
  std::array<double, 3> project(const std::array<double, 3>& x, std::array<double, 3>& normal) const
  {
    std::ptrdiff_t triangle = -1;
    return project(x, normal, triangle);
  }

  /// The same, where `triangle` is a hint: on entry the index of a triangle near `x` (say the
  /// answer for a nearby point) or -1, on return the index of the closest point's triangle. The
  /// search starts from the hint's closest point, so that it visits only the triangles about as
  /// near: the closest point is the same, up to the choice among equally close triangles.
  std::array<double, 3> project(const std::array<double, 3>& x, std::array<double, 3>& normal, std::ptrdiff_t& triangle) const
  {
    const K::Point_3 q(x[0] * scale_, x[1] * scale_, x[2] * scale_);
    const auto hit = triangle >= 0 && triangle < std::ptrdiff_t(triangles_->size())
                         ? tree_->closest_point_and_primitive(q, start(q, triangles_->begin() + triangle))
                         : tree_->closest_point_and_primitive(q);
    triangle = hit.second - triangles_->cbegin();
    const K::Vector_3& u = (*normals_)[triangle][feature(*hit.second, hit.first)];
    normal = {u.x(), u.y(), u.z()};
    return {hit.first.x() / scale_, hit.first.y() / scale_, hit.first.z() / scale_};
  }

  /// The number of triangles.
  std::size_t size() const { return triangles_->size(); }

private:
  // Per triangle, the unit normals of its features: [0] its own, [1 + i] at its vertex i, [4 + i]
  // on its edge from vertex i to vertex i + 1.
  using Normals = std::array<K::Vector_3, 7>;

  // Where p, a closest point of t, lies: 0 inside, 1 + i at vertex i, 4 + i on the edge from
  // vertex i. A closest point on an edge or at a vertex is computed there up to a few roundings
  // of its coordinates: a barycentric coordinate (p's distance to the opposite edge over the
  // triangle's height there) within 64 of them over that height counts as 0.
  static int feature(const K::Triangle_3& t, const K::Point_3& p)
  {
    const K::Vector_3 u = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    const double area = u.squared_length(), length = std::sqrt(area);
    double coordinate = std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
    for(int i = 0; i < 3; ++i) coordinate = std::max({coordinate, std::abs(t[i].x()), std::abs(t[i].y()), std::abs(t[i].z())});
    const double rounding = 64 * std::numeric_limits<double>::epsilon() * coordinate;
    int zeros = 0, off = 0, largest = 0;
    double b[3];
    for(int i = 0; i < 3; ++i) {   // b[i]: the coordinate of vertex i
      const K::Vector_3 edge = t[(i + 2) % 3] - t[(i + 1) % 3];
      b[i] = CGAL::cross_product(t[(i + 1) % 3] - p, t[(i + 2) % 3] - p) * u / area;
      if(b[i] <= rounding * std::sqrt(edge.squared_length()) / length) ++zeros, off = i;
      if(b[i] > b[largest]) largest = i;
    }
    if(zeros >= 2) return 1 + largest;
    if(zeros == 1) return 4 + (off + 1) % 3;   // the edge opposite vertex `off`
    return 0;
  }

  // The features' normals of a triangle soup whose vertices are shared by their coordinates.
  static std::vector<Normals> feature_normals(const Triangles& triangles)
  {
    // A sum of weighted unit normals, normalized; where it is much shorter than its weights (normals
    // that nearly cancel, as across a fold), `otherwise`.
    struct Sum { K::Vector_3 v = K::Vector_3(0, 0, 0); double weight = 0; };
    const auto unit = [](const Sum& sum, const K::Vector_3& otherwise) {
      const double length = std::sqrt(sum.v.squared_length());
      return length > 1e-3 * sum.weight ? sum.v / length : otherwise;
    };
    std::vector<Normals> normals(triangles.size());
    std::map<std::array<double, 3>, std::size_t> index;   // a vertex's number by its coordinates
    std::vector<std::array<std::size_t, 3>> corners(triangles.size());
    for(std::size_t f = 0; f < triangles.size(); ++f) {
      const K::Triangle_3& t = triangles[f];
      const K::Vector_3 u = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
      normals[f][0] = u / std::sqrt(u.squared_length());
      for(int i = 0; i < 3; ++i)
        corners[f][i] = index.emplace(std::array<double, 3>{t[i].x(), t[i].y(), t[i].z()}, index.size()).first->second;
    }
    // Sums of unit normals: per vertex weighted by the angles, per edge (lower vertex first) plain.
    std::vector<Sum> at_vertex(index.size());
    std::map<std::pair<std::size_t, std::size_t>, Sum> along_edge;
    for(std::size_t f = 0; f < triangles.size(); ++f)
      for(int i = 0; i < 3; ++i) {
        const K::Triangle_3& t = triangles[f];
        const K::Vector_3 a = t[(i + 1) % 3] - t[i], b = t[(i + 2) % 3] - t[i];
        const double angle = std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
        Sum& vertex = at_vertex[corners[f][i]];
        vertex.v = vertex.v + angle * normals[f][0];
        vertex.weight += angle;
        Sum& edge = along_edge[std::minmax(corners[f][i], corners[f][(i + 1) % 3])];
        edge.v = edge.v + normals[f][0];
        edge.weight += 1;
      }
    for(std::size_t f = 0; f < triangles.size(); ++f)
      for(int i = 0; i < 3; ++i) {
        normals[f][1 + i] = unit(at_vertex[corners[f][i]], normals[f][0]);
        normals[f][4 + i] = unit(along_edge.at(std::minmax(corners[f][i], corners[f][(i + 1) % 3])), normals[f][0]);
      }
    return normals;
  }

  // The closest point of one triangle to q, as the tree's search needs it to start from.
  static std::pair<K::Point_3, Triangles::const_iterator> start(const K::Point_3& q, Triangles::const_iterator t)
  {
    return {K::Construct_projected_point_3()(*t, q), t};
  }

  // Shared, so that copies (the named parameter is taken by value) share one tree.
  std::shared_ptr<Triangles> triangles_;
  std::shared_ptr<Tree> tree_;
  std::shared_ptr<const std::vector<Normals>> normals_;
  double scale_ = 1;   // a power of two: the tree's coordinates are the surface's times scale_
};

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_SLIDING_SURFACES_H
