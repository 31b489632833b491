// Outside consumer of the installed Distortion_optimization package: the map (x, y) -> (2x, y)
// of a unit square made of two triangles has quasi-conformal dilatation K = 2 on both triangles;
// then a noisy grid is optimized with number_of_threads(2) in this build without TBB (it links
// only CGAL::Distortion_optimization), which must run, sequentially.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <cmath>
#include <vector>
#include <iostream>

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

  const bool ok = std::abs(stats.mean_volume - 2.0) < 1e-12 && stats.inverted_cells == 0 &&
                  result.final_energy < 1 + 1e-6 && result.inverted_cells == 0;
  std::cout << (ok ? "consumer: OK\n" : "consumer: FAILED (expected K = 2 and a grid optimized to SD 1, no inverted cell)\n");
  return ok ? 0 : 1;
}
