// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Translates a triangle mesh (any FaceListGraph) with a source vertex point map (Point_2 or
// Point_3) and a target map (Point_2) into the flat arrays of Simplicial_map<2>, and back.
// Everything a solver must not have to check is checked here, with CGAL's exact predicates.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TRIANGLE_MESH_ADAPTER_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TRIANGLE_MESH_ADAPTER_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Dimension.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <class TriangleMesh, class VertexPointMap>
class Triangle_mesh_adapter
{
  using GT = boost::graph_traits<TriangleMesh>;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Source_point = typename boost::property_traits<VertexPointMap>::value_type;
  static constexpr int source_dimension = CGAL::Ambient_dimension<Source_point>::value;
  using Index_map = typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t>>::const_type;

  Simplicial_map<2> map;
  std::vector<vertex_descriptor> vertex_of;  // vertex index -> vertex
  std::vector<face_descriptor> cell_of;      // cell index -> face

  template <class TargetMap>
  Triangle_mesh_adapter(const TriangleMesh& tm, VertexPointMap vpm, const TargetMap& target)
    : index_(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm))
  {
    static_assert(source_dimension == 2 || source_dimension == 3, "source points must be Point_2 or Point_3");
    if(num_faces(tm) == 0)
      throw Invalid_input("the mesh has no face");
    for(vertex_descriptor v : vertices(tm)) {
      put(index_, v, vertex_of.size());
      const auto& q = get(target, v);
      Vector<2> x(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
      if(!x.allFinite())
        throw Invalid_input("vertex " + std::to_string(vertex_of.size()) + " has a non-finite target coordinate");
      if(!is_finite(get(vpm, v)))
        throw Invalid_input("vertex " + std::to_string(vertex_of.size()) + " has a non-finite source coordinate");
      map.target.push_back(x);
      vertex_of.push_back(v);
    }
    for(face_descriptor f : faces(tm)) {
      const std::size_t c = cell_of.size();
      if(degree(f, tm) != 3)
        throw Invalid_input("face " + std::to_string(c) + " is not a triangle");
      typename Simplicial_map<2>::Cell cell;
      int i = 0;
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
        cell[i++] = static_cast<typename Simplicial_map<2>::Index>(get(index_, v));
      const Source_point &p = get(vpm, vertex_of[cell[0]]), &q = get(vpm, vertex_of[cell[1]]),
                         &r = get(vpm, vertex_of[cell[2]]);
      if(CGAL::collinear(p, q, r))
        throw Invalid_input("source face " + std::to_string(c) + " is degenerate (zero area)");
      map.add_cell(cell, rest_edges(p, q, r));
      cell_of.push_back(f);
    }
  }

  std::size_t index(vertex_descriptor v) const { return get(index_, v); }

private:
  Index_map index_;

  template <class P>
  static bool is_finite(const P& p)
  {
    for(int i = 0; i < source_dimension; ++i)
      if(!std::isfinite(CGAL::to_double(p[i]))) return false;
    return true;
  }

  static Vector<source_dimension> to_vector(const Source_point& p)
  {
    Vector<source_dimension> x;
    for(int i = 0; i < source_dimension; ++i) x[i] = CGAL::to_double(p[i]);
    return x;
  }

  static Matrix<2> rest_edges(const Source_point& p, const Source_point& q, const Source_point& r)
  {
    const auto x0 = to_vector(p);
    if constexpr(source_dimension == 2) {
      Matrix<2> Dm;
      Dm.col(0) = to_vector(q) - x0;
      Dm.col(1) = to_vector(r) - x0;
      return Dm;
    } else {
      return triangle_frame_edges(to_vector(q) - x0, to_vector(r) - x0);
    }
  }
};

// The adapter for the source positions named by `vertex_point_map` (default: the mesh's points).
template <class TriangleMesh, class TargetMap, class NamedParameters>
auto make_triangle_mesh_adapter(const TriangleMesh& tm, const TargetMap& target, const NamedParameters& np)
{
  auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm));
  return Triangle_mesh_adapter<TriangleMesh, decltype(vpm)>(tm, vpm, target);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_TRIANGLE_MESH_ADAPTER_H
