// Tetrahedral complexes for the tests that need no Mesh_3 meshing (built from tetrahedra).

#ifndef DISTORTION_OPTIMIZATION_TEST_COMPLEXES_H
#define DISTORTION_OPTIMIZATION_TEST_COMPLEXES_H

#include "../../examples/Distortion_optimization/cube_tetrahedra.h"

#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace test_complexes {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = K::Point_3;
using Tr = CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<K>>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Vertex_handle = Tr::Vertex_handle;
using Target_storage = std::unordered_map<Vertex_handle, Point_3>;
using Target_map = boost::associative_property_map<Target_storage>;

// The vertices of the complex's boundary facets.
template <class Complex>
std::unordered_set<typename Complex::Triangulation::Vertex_handle> boundary_vertices(const Complex& c3t3)
{
  std::unordered_set<typename Complex::Triangulation::Vertex_handle> b;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(!c3t3.is_in_complex(c->neighbor(i)))
        for(int j = 1; j < 4; ++j) b.insert(c->vertex((i + j) % 4));
  return b;
}

// The unit cubes [i, i+1] x [j, j+1] x [k, k+1] of an n^3 block for which keep(i, j, k), each split
// into the 6 tetrahedra of Freudenthal's (Kuhn's) subdivision, which conform across cubes. All
// coordinates are integers (times `edge`): points on faces, edges and vertices are exact.
inline C3t3 cube_complex(int n, const std::function<bool(int, int, int)>& keep = [](int, int, int) { return true; },
                         double edge = 1)
{
  const auto block = volume_examples::cube_tetrahedra(n, [edge](int i) { return i * edge; }, keep);
  C3t3 c3t3;
  CGAL::Distortion_optimization::c3t3_from_tetrahedra(c3t3, block.points, block.cells);
  return c3t3;
}

} // namespace test_complexes

#endif // DISTORTION_OPTIMIZATION_TEST_COMPLEXES_H
