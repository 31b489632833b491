// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Translates a triangle mesh (any FaceListGraph) with a source vertex point map (Point_2 or
// Point_3) and a target map (Point_2) into the flat arrays of Simplicial_map<2>, and writes the
// targets back. Everything a solver must not have to check is checked here, with the geometric
// traits' (exact) predicates.
// A Point_3 target (a surface-to-surface map, e.g. a surface carried through a volume map) is
// accepted for measuring only: each target triangle is then expressed in its own 2D frame, as
// source triangles of a surface are, so the map gets one vertex per face corner.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TRIANGLE_MESH_ADAPTER_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TRIANGLE_MESH_ADAPTER_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Dimension.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <class TriangleMesh, class VertexPointMap, class GeomTraits, int TargetDimension = 2>
class Triangle_mesh_adapter
{
  using GT = boost::graph_traits<TriangleMesh>;

public:
  static constexpr int dimension = 2;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Source_point = typename boost::property_traits<VertexPointMap>::value_type;
  static constexpr int source_dimension = CGAL::Ambient_dimension<Source_point>::value;
  static constexpr int target_dimension = TargetDimension;
  // Whether the map has one vertex per face corner (Point_3 targets, each triangle in its own
  // frame): map vertex 3c + k is then corner k of cell c, and vertex_of[corner_vertex[3c + k]] its
  // mesh vertex. Such a map has no orientation (no inverted cells) and cannot be optimized.
  static constexpr bool per_corner = TargetDimension == 3;
  using Geom_traits = GeomTraits;

  Simplicial_map<2> map;
  std::vector<vertex_descriptor> vertex_of;  // vertex index -> vertex
  std::vector<typename Simplicial_map<2>::Index> corner_vertex;   // per_corner only: map vertex -> vertex index
  std::vector<face_descriptor> cell_of;      // cell index -> face
  std::vector<unsigned char> on_boundary;    // border vertices: the default constraints
  GeomTraits traits;
  double scale = 1;                          // of map's coordinates (coordinate_scale)

  template <class TargetMap>
  Triangle_mesh_adapter(const TriangleMesh& tm, VertexPointMap vpm, const TargetMap& target, const GeomTraits& gt)
    : traits(gt)
  {
    static_assert(source_dimension == 2 || source_dimension == 3, "source points must be Point_2 or Point_3");
    static_assert(target_dimension == 2 || target_dimension == 3, "target points must be Point_2 or Point_3");
    if(num_faces(tm) == 0)
      throw Invalid_input("the mesh has no face");
    auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    std::vector<Vector<source_dimension>> source;
    std::vector<Vector<target_dimension>> targets;   // per_corner: the 3D targets, framed per face below
    auto& target_of_vertex = [&]() -> std::vector<Vector<target_dimension>>& {
      if constexpr(per_corner) return targets; else return map.target;
    }();
    for(vertex_descriptor v : vertices(tm)) {
      put(index, v, vertex_of.size());
      const auto& q = get(target, v);
      Vector<target_dimension> x;
      if constexpr(per_corner) x << CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z());
      else x << CGAL::to_double(q.x()), CGAL::to_double(q.y());
      if(!x.allFinite())
        throw Invalid_input("vertex " + std::to_string(vertex_of.size()) + " has a non-finite target coordinate");
      source.push_back(to_vector(get(vpm, v)));
      if(!source.back().allFinite())
        throw Invalid_input("vertex " + std::to_string(vertex_of.size()) + " has a non-finite source coordinate");
      target_of_vertex.push_back(x);
      vertex_of.push_back(v);
      on_boundary.push_back(CGAL::is_border(v, tm) ? 1 : 0);
    }
    scale = coordinate_scale(source, target_of_vertex);
    check_comparable_sizes<2>(largest_extent(source), largest_extent(target_of_vertex));
    scale_exactly(source, scale);
    scale_exactly(target_of_vertex, scale);
    for(face_descriptor f : faces(tm)) {
      const std::size_t c = cell_of.size();
      if(degree(f, tm) != 3)
        throw Invalid_input("face " + std::to_string(c) + " is not a triangle");
      typename Simplicial_map<2>::Cell cell;
      int i = 0;
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
        cell[i++] = static_cast<typename Simplicial_map<2>::Index>(get(index, v));
      const auto &p = source[cell[0]], &q = source[cell[1]], &r = source[cell[2]];
      const int sign = source_orientation(p, q, r);
      if(sign == 0)
        throw Invalid_input("source face " + std::to_string(c) + " is degenerate (zero area)");
      if constexpr(per_corner) {
        const Matrix<2> Ds = target_frame_edges(targets[cell[1]] - targets[cell[0]], targets[cell[2]] - targets[cell[0]]);
        map.target.push_back(Vector<2>::Zero());
        map.target.push_back(Ds.col(0));
        map.target.push_back(Ds.col(1));
        for(int k = 0; k < 3; ++k) {
          corner_vertex.push_back(cell[k]);
          cell[k] = static_cast<typename Simplicial_map<2>::Index>(3 * c + k);
        }
      }
      if(!map.add_cell(cell, rest_edges(p, q, r), sign))
        throw Invalid_input("source face " + std::to_string(c) + " is degenerate in double precision (its vertices are "
                            "not exactly collinear, but so nearly that its rounded edges are)");
      cell_of.push_back(f);
    }
  }

  // The weights of the map's vertices from those of the mesh's (read_vertex_weights: per vertex of
  // vertex_of): the same unless per_corner, where each corner has its vertex's.
  std::vector<double> map_vertex_weights(std::vector<double> w) const
  {
    if constexpr(per_corner)
      if(!w.empty()) {
        std::vector<double> corners(corner_vertex.size());
        for(std::size_t k = 0; k < corners.size(); ++k) corners[k] = w[corner_vertex[k]];
        return corners;
      }
    return w;
  }

  // Writes the targets x of the free vertices into the target map.
  template <class TargetMap>
  void write_targets(TargetMap target, const std::vector<Vector<2>>& x, const std::vector<unsigned char>& is_free) const
  {
    static_assert(!per_corner, "only Point_2 targets are written back");
    using Point_2 = typename boost::property_traits<TargetMap>::value_type;
    for(std::size_t i = 0; i < vertex_of.size(); ++i)
      if(is_free[i]) put(target, vertex_of[i], Point_2(x[i][0] / scale, x[i][1] / scale));
  }

private:
  static Vector<source_dimension> to_vector(const Source_point& p)
  {
    Vector<source_dimension> x;
    for(int i = 0; i < source_dimension; ++i) x[i] = CGAL::to_double(p[i]);
    return x;
  }

  // The orientation of a source triangle, decided by the traits on the coordinates the map uses:
  // a planar source's own (+1 or -1), always +1 for a surface triangle in its own frame; 0 for a
  // degenerate one.
  int source_orientation(const Vector<source_dimension>& p, const Vector<source_dimension>& q,
                         const Vector<source_dimension>& r) const
  {
    if constexpr(source_dimension == 2) {
      using P = typename GeomTraits::Point_2;
      return static_cast<int>(traits.orientation_2_object()(P(p[0], p[1]), P(q[0], q[1]), P(r[0], r[1])));
    } else {
      using P = typename GeomTraits::Point_3;
      return traits.collinear_3_object()(P(p[0], p[1], p[2]), P(q[0], q[1], q[2]), P(r[0], r[1], r[2])) ? 0 : 1;
    }
  }

  // A target triangle of R^3 in its own frame, as a source triangle (triangle_frame_edges, so that
  // det J >= 0), also when its first edge has zero length: a flat image is a flat cell (det J = 0,
  // the measure's value there), never a non-finite Jacobian.
  static Matrix<2> target_frame_edges(const Vector<3>& e1, const Vector<3>& e2)
  {
    if(e1.norm() > 0) return triangle_frame_edges(e1, e2);
    Matrix<2> Ds;
    Ds << 0., e2.norm(),
          0., 0.;
    return Ds;
  }

  static Matrix<2> rest_edges(const Vector<source_dimension>& p, const Vector<source_dimension>& q,
                              const Vector<source_dimension>& r)
  {
    if constexpr(source_dimension == 2) {
      Matrix<2> Dm;
      Dm.col(0) = q - p;
      Dm.col(1) = r - p;
      return Dm;
    } else {
      return triangle_frame_edges(q - p, r - p);
    }
  }
};

// 3 for target points with a z() coordinate (Point_3), 2 otherwise (Point_2).
template <class Point, class = void>
struct Target_dimension : std::integral_constant<int, 2> {};
template <class Point>
struct Target_dimension<Point, std::void_t<decltype(std::declval<const Point&>().z())>> : std::integral_constant<int, 3> {};

template <class TargetMap>
constexpr int target_dimension_of()
{
  return Target_dimension<std::decay_t<typename boost::property_traits<TargetMap>::value_type>>::value;
}

// The adapter for the source positions named by `vertex_point_map` (default: the mesh's points)
// and the predicates of `geom_traits` (default: the kernel of those points), for a Point_2 target
// map (Point_3 too if measuring_only: compute_distortion).
template <class TriangleMesh, class TargetMap, class NamedParameters, bool measuring_only = false>
auto make_triangle_mesh_adapter(const TriangleMesh& tm, const TargetMap& target, const NamedParameters& np,
                                std::integral_constant<bool, measuring_only> = {})
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  constexpr int target_dimension = target_dimension_of<TargetMap>();
  static_assert(target_dimension == 2 || (measuring_only && target_dimension == 3),
                "a triangle mesh's target map must give Point_2; a Point_3 target (a surface-to-surface map) "
                "can be measured by CGAL::compute_distortion(), not optimized or untangled");
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  using GT = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  return Triangle_mesh_adapter<TriangleMesh, decltype(vpm), GT, target_dimension>(tm, vpm, target, gt);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TRIANGLE_MESH_ADAPTER_H
