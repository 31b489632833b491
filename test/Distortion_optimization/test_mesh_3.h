// The Mesh_3 complexes and the helpers on maps of complexes that test_tetrahedral_meshes.cpp (built
// always) and test_tetgen_meshes.cpp (built only with TetGen) share: Mesh_3 meshes of implicit
// domains, the radial start map, inverted cells, a property map that records what is written.

#ifndef DISTORTION_OPTIMIZATION_TEST_MESH_3_H
#define DISTORTION_OPTIMIZATION_TEST_MESH_3_H

#include "test_complexes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <unordered_set>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = K::Point_3;
using Implicit_domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Implicit_domain>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
using Vertex_handle = Tr::Vertex_handle;
using Target_storage = std::unordered_map<Vertex_handle, Point_3>;
using Target_map = boost::associative_property_map<Target_storage>;

// A Mesh_3 mesh of {f < 0} inside the ball of the given radius, at the given size (no perturbation
// or exudation): compiled once, in mesh_implicit.cpp (make_mesh_3 is slow to compile).
C3t3 mesh_implicit(double (*f)(const Point_3&), double radius, double size);

// Complexes of another domain type: Mesh_3 on the polyhedral domain bounded by a closed surface
// (facet distance 0.05, cell size 0.25, radius-edge ratio 3), compiled once, in mesh_polyhedral.cpp.
using Surface_mesh_3 = CGAL::Surface_mesh<Point_3>;
using Polyhedral_domain = CGAL::Polyhedral_mesh_domain_3<Surface_mesh_3, K>;
using Polyhedral_tr = CGAL::Mesh_triangulation_3<Polyhedral_domain>::type;
using Polyhedral_c3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Polyhedral_tr>;
Polyhedral_c3t3 mesh_polyhedral(const Surface_mesh_3& surface);

namespace {

inline double unit_sphere(const Point_3& p) { return CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()) - 1.; }

inline C3t3 mesh_sphere(double size) { return mesh_implicit(unit_sphere, 2., size); }

inline Point_3 radial(const Point_3& p)   // f0(x) = x |x|, the start map of the paper's Fig. 5
{
  const double r = std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()));
  return Point_3(r * p.x(), r * p.y(), r * p.z());
}

// Whether the cell (a handle or an iterator) keeps its orientation under the map (exact predicate).
template <class Cell>
bool is_positive(const Cell& c, const Target_storage& target)
{
  return CGAL::orientation(target.at(c->vertex(0)), target.at(c->vertex(1)), target.at(c->vertex(2)),
                           target.at(c->vertex(3))) == CGAL::POSITIVE;
}

inline std::size_t inverted(const C3t3& c3t3, const Target_storage& target)
{
  std::size_t count = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    if(!is_positive(c, target)) ++count;
  return count;
}

using test_complexes::boundary_vertices;

// A property map that records which keys are written.
struct Recording_map
{
  Target_storage* storage;
  std::unordered_set<Vertex_handle>* written;
  using key_type = Vertex_handle;
  using value_type = Point_3;
  using reference = const Point_3&;
  using category = boost::read_write_property_map_tag;
  friend const Point_3& get(const Recording_map& m, Vertex_handle v) { return m.storage->at(v); }
  friend void put(const Recording_map& m, Vertex_handle v, const Point_3& p)
  {
    m.written->insert(v);
    (*m.storage)[v] = p;
  }
};

} // namespace

#endif // DISTORTION_OPTIMIZATION_TEST_MESH_3_H
