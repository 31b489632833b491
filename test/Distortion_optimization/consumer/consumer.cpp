// Outside consumer of the installed Distortion_optimization package, built as a user's debug
// build (CGAL's and Eigen's assertions on): the map (x, y) -> (2x, y) of a unit square made of two
// triangles has quasi-conformal dilatation K = 2 on both triangles; then a noisy grid is optimized
// with number_of_threads(2) in this build without TBB (it links only CGAL::Distortion_optimization),
// which must run, sequentially; last, a cube coned from its centre is handed to Mesh_3's complex by
// c3t3_from_tetrahedra() and its centre, moved off, is optimized back.
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <iostream>
#include <unordered_map>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Vertex_index = Mesh::Vertex_index;

int main()
{
  Mesh mesh;
  const Vertex_index v0 = mesh.add_vertex(Point_3(0, 0, 0));
  const Vertex_index v1 = mesh.add_vertex(Point_3(1, 0, 0));
  const Vertex_index v2 = mesh.add_vertex(Point_3(1, 1, 0));
  const Vertex_index v3 = mesh.add_vertex(Point_3(0, 1, 0));
  if(mesh.add_face(v0, v1, v2) == Mesh::null_face() ||
     mesh.add_face(v0, v2, v3) == Mesh::null_face())
  {
    std::cerr << "consumer: could not build the square\n";
    return 1;
  }

  auto uv = mesh.add_property_map<Vertex_index, Point_2>("v:uv", Point_2(0, 0)).first;
  for(const Vertex_index v : mesh.vertices())
  {
    const Point_3& p = mesh.point(v);
    uv[v] = Point_2(2 * p.x(), p.y());
  }

  const auto stats =
    CGAL::compute_distortion(mesh, uv, CGAL::Distortion_optimization::Conformal_dilatation());

  std::cout.precision(17);
  std::cout << "mean_volume = " << stats.mean_volume << '\n'
            << "min = " << stats.min << '\n'
            << "max = " << stats.max << '\n'
            << "inverted_cells = " << stats.inverted_cells << '\n';

  // A 6 x 6 grid with its inner vertices pushed off their place, border fixed.
  Mesh grid;
  const int k = 6;
  std::vector<Vertex_index> at;
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) at.push_back(grid.add_vertex(Point_3(double(i) / k, double(j) / k, 0)));
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      const Vertex_index a = at[j * (k + 1) + i], b = at[j * (k + 1) + i + 1];
      const Vertex_index c = at[(j + 1) * (k + 1) + i], d = at[(j + 1) * (k + 1) + i + 1];
      grid.add_face(a, b, d);
      grid.add_face(a, d, c);
    }
  auto target = grid.add_property_map<Vertex_index, Point_2>("v:target", Point_2(0, 0)).first;
  for(const Vertex_index v : grid.vertices()) {
    const Point_3& p = grid.point(v);
    const double shift = grid.is_border(v) ? 0. : 0.03 * std::sin(7. * std::size_t(v));
    target[v] = Point_2(p.x() + shift, p.y() - shift);
  }
  const auto result = CGAL::minimize_distortion(grid, target, CGAL::Distortion_optimization::Symmetric_dirichlet(),
                                                CGAL::Distortion_optimization::parameters::number_of_threads(2));
  std::cout << "grid: " << result.initial_energy << " -> " << result.final_energy << ", inverted "
            << result.inverted_cells << '\n';

  // The unit cube coned from its centre (point 8): two tetrahedra per face.
  using Tr = CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<Kernel>>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
  std::vector<std::array<double, 3>> points;
  for(int i = 0; i < 8; ++i) points.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  points.push_back({0.5, 0.5, 0.5});
  std::vector<std::array<std::size_t, 4>> tetrahedra;
  for(const std::array<std::size_t, 4>& q : {std::array<std::size_t, 4>{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}}) {
    tetrahedra.push_back({q[0], q[1], q[2], 8});
    tetrahedra.push_back({q[0], q[2], q[3], 8});
  }
  C3t3 c3t3;
  const auto handles = CGAL::Distortion_optimization::c3t3_from_tetrahedra(c3t3, points, tetrahedra);
  std::unordered_map<Tr::Vertex_handle, Point_3> positions;
  for(std::size_t i = 0; i < points.size(); ++i) positions[handles[i]] = Point_3(points[i][0], points[i][1], points[i][2]);
  positions[handles[8]] = Point_3(0.65, 0.4, 0.55);
  boost::associative_property_map<std::unordered_map<Tr::Vertex_handle, Point_3>> cube_target(positions);
  const auto cube = CGAL::minimize_distortion(c3t3, cube_target, CGAL::Distortion_optimization::Conformal_dilatation());
  const Point_3 centre = positions[handles[8]];
  std::cout << "cube: " << c3t3.number_of_cells_in_complex() << " tetrahedra, K " << cube.initial_energy << " -> "
            << cube.final_energy << ", centre (" << centre << "), inverted " << cube.inverted_cells << '\n';

  const bool ok = std::abs(stats.mean_volume - 2.0) < 1e-12 && stats.inverted_cells == 0 &&
                  result.final_energy < 1 + 1e-6 && result.inverted_cells == 0 &&
                  c3t3.number_of_cells_in_complex() == 12 && cube.final_energy < cube.initial_energy &&
                  cube.inverted_cells == 0 && CGAL::squared_distance(centre, Point_3(0.5, 0.5, 0.5)) < 1e-4;
  std::cout << (ok ? "consumer: OK\n" : "consumer: FAILED (expected K = 2, a grid optimized to SD 1 and the cube's centre "
                                         "back near the middle, no inverted cell)\n");
  return ok ? 0 : 1;
}
