// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Translates the cells of a Mesh_complex_3_in_triangulation_3 (only those in the complex) and a
// target map keyed by Vertex_handle into the flat arrays of Simplicial_map<3>, and back.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// True for the complexes of CGAL's Mesh_3 (what the C3T3 overloads accept).
template <class T, class = void>
struct Is_c3t3 : std::false_type {};
template <class T>
struct Is_c3t3<T, std::void_t<typename T::Triangulation, typename T::Cells_in_complex_iterator>> : std::true_type {};

template <class C3T3>
class C3t3_adapter
{
public:
  using Triangulation = typename C3T3::Triangulation;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell_handle = typename Triangulation::Cell_handle;

  Simplicial_map<3> map;
  std::vector<Vertex_handle> vertex_of;       // vertex index -> handle (vertices of complex cells)
  std::vector<Cell_handle> cell_of;           // cell index -> handle
  std::vector<unsigned char> on_boundary;     // vertex on a facet shared with a cell not in the complex

  template <class TargetMap>
  C3t3_adapter(const C3T3& c3t3, const TargetMap& target)
  {
    const Triangulation& tr = c3t3.triangulation();
    auto point = tr.geom_traits().construct_point_3_object();
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      typename Simplicial_map<3>::Cell cell;
      for(int i = 0; i < 4; ++i) cell[i] = index(c->vertex(i), point, target);
      const auto &p = point(tr.point(c, 0)), &q = point(tr.point(c, 1)), &r = point(tr.point(c, 2)),
                 &s = point(tr.point(c, 3));
      if(CGAL::orientation(p, q, r, s) != CGAL::POSITIVE)
        throw Invalid_input("source cell " + std::to_string(cell_of.size()) + " of the complex is not positively oriented "
                            "(degenerate)");
      Matrix<3> Dm;
      Dm << q.x() - p.x(), r.x() - p.x(), s.x() - p.x(),
            q.y() - p.y(), r.y() - p.y(), s.y() - p.y(),
            q.z() - p.z(), r.z() - p.z(), s.z() - p.z();
      map.add_cell(cell, Dm);
      cell_of.push_back(Cell_handle(c));
      for(int i = 0; i < 4; ++i)
        if(!c3t3.is_in_complex(c->neighbor(i)))
          for(int j = 0; j < 4; ++j)
            if(j != i) on_boundary[cell[j]] = 1;
    }
    if(cell_of.empty())
      throw Invalid_input("the complex has no cell");
  }

  std::size_t index(Vertex_handle v) const { return index_.at(v); }

private:
  template <class ConstructPoint, class TargetMap>
  std::uint32_t index(Vertex_handle v, const ConstructPoint&, const TargetMap& target)
  {
    auto inserted = index_.emplace(v, static_cast<std::uint32_t>(vertex_of.size()));
    if(inserted.second) {
      const auto& y = get(target, v);
      Vector<3> x(CGAL::to_double(y.x()), CGAL::to_double(y.y()), CGAL::to_double(y.z()));
      if(!x.allFinite())
        throw Invalid_input("vertex " + std::to_string(vertex_of.size()) + " has a non-finite target coordinate");
      map.target.push_back(x);
      vertex_of.push_back(v);
      on_boundary.push_back(0);
    }
    return inserted.first->second;
  }

  std::unordered_map<Vertex_handle, std::uint32_t> index_;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H
