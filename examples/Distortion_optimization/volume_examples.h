// What the volume examples (volume_to_ball, gyroid_texture) and benchmarks share: their types, and
// the cube of the paper's Figs. 13 and 14.

#ifndef DISTORTION_OPTIMIZATION_EXAMPLES_VOLUME_EXAMPLES_H
#define DISTORTION_OPTIMIZATION_EXAMPLES_VOLUME_EXAMPLES_H

#include "cube_tetrahedra.h"

#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/mesh_interior.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

namespace volume_examples {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using Volume = CGAL::Distortion_optimization::Interior_mesh<K>::C3T3;   // what mesh_interior() returns
using Vertex_handle = Volume::Triangulation::Vertex_handle;
using Targets = std::unordered_map<Vertex_handle, Point>;   // a map of the volume's vertices
using Target_map = boost::associative_property_map<Targets>;

// The cube [-h, h]^3 as 12 outward-oriented triangles.
inline Surface cube(double h)
{
  Surface s;
  std::vector<Surface::Vertex_index> v;
  for(int i = 0; i < 8; ++i) v.push_back(s.add_vertex(Point(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h)));
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for(const auto& f : faces) s.add_face(v[f[0]], v[f[1]], v[f[2]]);
  return s;
}

// The cube [-h, h]^3 as n^3 small cubes, each cut into six tetrahedra (cube_tetrahedra.h).
inline Volume cube_volume(double h, int n)
{
  const Cube_tetrahedra block = cube_tetrahedra(n, [h, n](int i) { return h * (2. * i / n - 1); });
  Volume volume;
  CGAL::Distortion_optimization::c3t3_from_tetrahedra(volume, block.points, block.cells);
  return volume;
}

} // namespace volume_examples

#endif // DISTORTION_OPTIMIZATION_EXAMPLES_VOLUME_EXAMPLES_H
