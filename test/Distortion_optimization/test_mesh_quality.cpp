// Mesh quality from distortion (paper section 4.2): mesh_quality()'s statistics on known shapes, and
// improve_mesh_quality() on perturbed regular meshes, 2D and 3D, boundary fixed or sliding.

#include "test_complexes.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/mesh_quality.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/function_property_map.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace {

namespace DO = CGAL::Distortion_optimization;
using namespace test_complexes;
using Point_2 = K::Point_2;
using Mesh2 = CGAL::Surface_mesh<Point_2>;
using Cell_handle = Tr::Cell_handle;

// The triangular lattice of unit edges on (k + 1) rows of k + 1 points, every other row shifted
// by one half: equilateral triangles, counterclockwise.
Mesh2 equilateral_grid(int k)
{
  Mesh2 m;
  std::vector<Mesh2::Vertex_index> v;
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) v.push_back(m.add_vertex(Point_2(i + 0.5 * (j % 2), j * std::sqrt(3.) / 2)));
  const auto at = [&](int i, int j) { return v[j * (k + 1) + i]; };
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      if(j % 2 == 0) {   // the row above is shifted right
        m.add_face(at(i, j), at(i + 1, j), at(i, j + 1));
        m.add_face(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      } else {           // the row above is shifted left
        m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      }
    }
  return m;
}

std::vector<Vertex_handle> interior_vertices(const C3t3& c3t3)
{
  const auto boundary = boundary_vertices(c3t3);
  std::vector<Vertex_handle> inside;
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v)
    if(!boundary.count(v) && c3t3.in_dimension(v) != -1) inside.push_back(v);
  return inside;
}

} // namespace

TEST(MeshQuality, StatisticsOfKnownShapes)
{
  // An equilateral triangle, a right isosceles one, apart.
  Mesh2 m;
  const auto add = [&m](Point_2 a, Point_2 b, Point_2 c) { m.add_face(m.add_vertex(a), m.add_vertex(b), m.add_vertex(c)); };
  add(Point_2(0, 0), Point_2(1, 0), Point_2(0.5, std::sqrt(3.) / 2));
  DO::Mesh_quality q = DO::mesh_quality(m, m.points());
  EXPECT_EQ(q.cells, 1u);
  EXPECT_NEAR(q.min_angle, 60, 1e-12);
  EXPECT_NEAR(q.max_angle, 60, 1e-12);
  EXPECT_NEAR(q.min_radius_ratio, 1, 1e-12);
  EXPECT_EQ(q.slivers, 0u);
  EXPECT_EQ(q.inverted_cells, 0u);
  add(Point_2(2, 0), Point_2(3, 0), Point_2(2, 1));
  q = DO::mesh_quality(m, m.points());
  EXPECT_NEAR(q.max_angle, 90, 1e-12);
  EXPECT_NEAR(q.min_angle, 45, 1e-12);
  EXPECT_NEAR(q.mean_min_angle, 52.5, 1e-12);
  // Right isosceles: r = 1 / (2 + sqrt 2), R = sqrt 2 / 2, so 2 r / R = 2 (sqrt 2 - 1).
  EXPECT_NEAR(q.min_radius_ratio, 2 * (std::sqrt(2.) - 1), 1e-12);
  EXPECT_NEAR(q.mean_radius_ratio, (1 + 2 * (std::sqrt(2.) - 1)) / 2, 1e-12);
  // A flat triangle: ratio 0, a sliver, and inverted (its orientation is not the mesh's).
  add(Point_2(4, 0), Point_2(5, 0), Point_2(6, 0));
  q = DO::mesh_quality(m, m.points());
  EXPECT_EQ(q.inverted_cells, 1u);
  EXPECT_EQ(q.slivers, 1u);
  EXPECT_EQ(q.min_radius_ratio, 0);

  // The cube's Kuhn tetrahedra: dihedral angles 45, 60 and 90 degrees, 3 r / R = the same for all six.
  const C3t3 cube = cube_complex(1);
  Target_storage identity;
  DO::map_vertices(cube, Target_map(identity), [](const Point_3& p) { return p; });
  q = DO::mesh_quality(cube, Target_map(identity));
  EXPECT_EQ(q.cells, 6u);
  EXPECT_NEAR(q.min_angle, 45, 1e-9);
  EXPECT_NEAR(q.max_angle, 90, 1e-9);
  // Edges 1, sqrt 2, sqrt 3: V = 1/6, faces 2 (1/2) + 2 (sqrt 2 / 2), R = sqrt 3 / 2.
  const double faces = 1 + std::sqrt(2.), r = 3 * (1. / 6) / faces, R = std::sqrt(3.) / 2;
  EXPECT_NEAR(q.min_radius_ratio, 3 * r / R, 1e-12);
  EXPECT_NEAR(q.mean_radius_ratio, 3 * r / R, 1e-12);
  EXPECT_EQ(q.inverted_cells, 0u);
}

TEST(MeshQuality, InvertedCellMapMarksTheTrianglesMeshQualityCounts)
{
  // Two clockwise triangles (the mesh's orientation), one counterclockwise, one flat; then the
  // counterclockwise one enlarged until it outweighs the others, so that the other three count.
  std::vector<Point_2> points = {{0, 0}, {0, 1}, {1, 0}, {3, 0}, {3, 2}, {5, 0}, {6, 0}, {7, 0}, {8, 0}, {9, 0}, {9, 1}, {10, 0}};
  const std::vector<std::array<std::size_t, 3>> cells = {{0, 1, 2}, {3, 4, 5}, {9, 11, 10}, {6, 7, 8}};
  Mesh2 m;
  for(const auto& p : points) m.add_vertex(p);
  for(const auto& c : cells) m.add_face(Mesh2::Vertex_index(c[0]), Mesh2::Vertex_index(c[1]), Mesh2::Vertex_index(c[2]));
  auto inverted = m.add_property_map<Mesh2::Face_index, bool>("f:inverted", false).first;
  const auto marked = [&] {
    std::vector<bool> v;
    for(auto f : m.faces()) v.push_back(inverted[f]);
    return v;
  };
  EXPECT_EQ(DO::mesh_quality(m, m.points(), DO::parameters::inverted_cell_map(inverted)).inverted_cells, 2u);
  EXPECT_EQ(marked(), std::vector<bool>({false, false, true, true}));
  m.point(Mesh2::Vertex_index(10)) = Point_2(9, 6);
  m.point(Mesh2::Vertex_index(11)) = Point_2(15, 0);
  EXPECT_EQ(DO::mesh_quality(m, m.points(), DO::parameters::inverted_cell_map(inverted)).inverted_cells, 3u);
  EXPECT_EQ(marked(), std::vector<bool>({true, true, false, true}));
  // The kernel's predicates by name give the same answer.
  EXPECT_EQ(DO::mesh_quality(m, m.points(), CGAL::parameters::geom_traits(K())).inverted_cells, 3u);
}

// The per-cell maps on real meshes: lion-head's Tutte map (a disk of 16.6K triangles) with some
// vertices thrown about until triangles fold, and CGAL's sphere.mesh with perturbed positions.
// The radius ratios written are those whose smallest and mean the statistics report, the cells
// marked inverted those they count; asking for the maps changes no statistic.
TEST(MeshQuality, CellMapsAgreeWithTheStatisticsOnRealMeshes)
{
  const auto expect_same = [](const DO::Mesh_quality& a, const DO::Mesh_quality& b) {
    const auto figures = [](const DO::Mesh_quality& q) {
      return std::make_tuple(q.cells, q.min_angle, q.max_angle, q.mean_min_angle, q.min_radius_ratio, q.mean_radius_ratio,
                             q.slivers, q.inverted_cells);
    };
    EXPECT_EQ(figures(a), figures(b));
  };
  // The smallest, the sum in the statistics' order, and the number marked.
  const auto summary = [](const auto& cells, const auto& ratio, const auto& inverted) {
    double smallest = 1, sum = 0;
    std::size_t marked = 0;
    for(const auto& c : cells) {
      smallest = std::min(smallest, ratio(c));
      sum += ratio(c);
      marked += inverted(c);
    }
    return std::make_tuple(smallest, sum, marked);
  };

  using Surface = CGAL::Surface_mesh<Point_3>;
  Surface lion;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/lion-head.off", lion));
  auto uv = lion.add_property_map<Surface::Vertex_index, Point_2>("v:uv").first;
  DO::initial_parameterization(lion, uv);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for(auto v : lion.vertices())
    if(!lion.is_border(v) && std::size_t(v) % 7 == 0) uv[v] = Point_2(uv[v].x() + u(rng), uv[v].y() + u(rng));
  auto ratio = lion.add_property_map<Surface::Face_index, double>("f:ratio", -1.).first;
  auto inverted = lion.add_property_map<Surface::Face_index, bool>("f:inverted", false).first;
  const DO::Mesh_quality q2 =
    DO::mesh_quality(lion, uv, DO::parameters::cell_radius_ratio_map(ratio, DO::parameters::inverted_cell_map(inverted)));
  expect_same(q2, DO::mesh_quality(lion, uv));
  ASSERT_EQ(q2.cells, lion.number_of_faces());
  EXPECT_GT(q2.inverted_cells, 10u);
  EXPECT_LT(q2.inverted_cells, q2.cells / 2);
  const auto [smallest2, sum2, marked2] =
    summary(lion.faces(), [&](Surface::Face_index f) { return ratio[f]; }, [&](Surface::Face_index f) { return inverted[f]; });
  EXPECT_EQ(smallest2, q2.min_radius_ratio);
  EXPECT_EQ(sum2 / q2.cells, q2.mean_radius_ratio);
  EXPECT_EQ(marked2, q2.inverted_cells);
  for(auto f : lion.faces()) EXPECT_TRUE(ratio[f] >= 0 && ratio[f] <= 1 + 1e-12) << f;

  const DO::IO::Tetrahedron_soup sphere = DO::IO::read_tetrahedron_soup(DISTORTION_OPTIMIZATION_DATA_DIR "/sphere.mesh");
  C3t3 c3t3;
  DO::c3t3_from_tetrahedra(c3t3, sphere.points, sphere.cells);
  Target_storage positions;
  DO::map_vertices(c3t3, Target_map(positions), [](const Point_3& p) { return p; });
  std::uniform_real_distribution<double> w(-0.03, 0.03);
  for(auto& [v, p] : positions) p = Point_3(p.x() + w(rng), p.y() + w(rng), p.z() + w(rng));
  std::unordered_map<Cell_handle, double> cell_ratio;
  std::unordered_map<Cell_handle, bool> cell_inverted;
  const DO::Mesh_quality q3 = DO::mesh_quality(c3t3, Target_map(positions),
    DO::parameters::inverted_cell_map(boost::make_assoc_property_map(cell_inverted),
      DO::parameters::cell_radius_ratio_map(boost::make_assoc_property_map(cell_ratio))));
  expect_same(q3, DO::mesh_quality(c3t3, Target_map(positions)));
  ASSERT_EQ(q3.cells, 3586u);
  EXPECT_EQ(cell_ratio.size(), q3.cells);
  EXPECT_EQ(cell_inverted.size(), q3.cells);
  EXPECT_GT(q3.inverted_cells, 0u);
  std::vector<Cell_handle> cells;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) cells.push_back(Cell_handle(c));
  const auto [smallest3, sum3, marked3] =
    summary(cells, [&](Cell_handle c) { return cell_ratio.at(c); }, [&](Cell_handle c) { return cell_inverted.at(c); });
  EXPECT_EQ(smallest3, q3.min_radius_ratio);
  EXPECT_EQ(sum3 / q3.cells, q3.mean_radius_ratio);
  EXPECT_EQ(marked3, q3.inverted_cells);
  // A cell is inverted exactly where its positions are not positively oriented.
  for(Cell_handle c : cells)
    EXPECT_EQ(cell_inverted.at(c), CGAL::orientation(positions.at(c->vertex(0)), positions.at(c->vertex(1)),
                                                     positions.at(c->vertex(2)), positions.at(c->vertex(3))) != CGAL::POSITIVE);
}

TEST(MeshQuality, PerturbedEquilateralGridReturnsToTheGrid)
{
  const Mesh2 grid = equilateral_grid(8);
  Mesh2 mesh = grid;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for(auto v : mesh.vertices())
    if(!mesh.is_border(v)) mesh.point(v) = Point_2(mesh.point(v).x() + u(rng), mesh.point(v).y() + u(rng));
  const DO::Mesh_quality before = DO::mesh_quality(mesh, mesh.points());
  ASSERT_EQ(before.inverted_cells, 0u);
  ASSERT_LT(before.min_angle, 35);

  const DO::Result r = DO::improve_mesh_quality(mesh, mesh.points(), DO::Conformal_dilatation(),
    DO::parameters::convergence_threshold(1e-14, CGAL::parameters::number_of_iterations(500)));
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_LT(r.final_energy, r.initial_energy);
  EXPECT_NEAR(r.final_energy, 1, 1e-9);   // every triangle equilateral: K = 1
  double error = 0;
  for(auto v : mesh.vertices()) error = std::max(error, std::sqrt(CGAL::squared_distance(mesh.point(v), grid.point(v))));
  EXPECT_LT(error, 1e-6);
  for(auto v : mesh.vertices()) {
    if(mesh.is_border(v)) {
      EXPECT_EQ(mesh.point(v), grid.point(v));
    }
  }
  const DO::Mesh_quality after = DO::mesh_quality(mesh, mesh.points());
  EXPECT_NEAR(after.min_angle, 60, 1e-4);
  EXPECT_NEAR(after.min_radius_ratio, 1, 1e-8);
}

TEST(MeshQuality, PerturbedCubeGridImprovesWithTheBoundaryFixedOrSliding)
{
  const C3t3 c3t3 = cube_complex(5);
  Target_storage grid;
  DO::map_vertices(c3t3, Target_map(grid), [](const Point_3& p) { return p; });
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  Target_storage start = grid;
  for(Vertex_handle v : interior_vertices(c3t3)) {
    const Point_3& p = grid.at(v);
    start[v] = Point_3(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
  }
  const DO::Mesh_quality before = DO::mesh_quality(c3t3, Target_map(start));
  ASSERT_EQ(before.inverted_cells, 0u);

  // Fixed boundary: the boundary stays to the bit, the quality rises, its minimum too.
  Target_storage fixed = start;
  const DO::Result r = DO::improve_mesh_quality(c3t3, Target_map(fixed));
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_LT(r.final_energy, r.initial_energy);
  const DO::Mesh_quality after = DO::mesh_quality(c3t3, Target_map(fixed));
  EXPECT_EQ(after.inverted_cells, 0u);
  EXPECT_GT(after.mean_radius_ratio, before.mean_radius_ratio);
  EXPECT_GE(after.min_radius_ratio, before.min_radius_ratio);
  EXPECT_GE(after.min_angle, before.min_angle);
  const auto inside = interior_vertices(c3t3);
  std::unordered_set<Vertex_handle> interior(inside.begin(), inside.end());
  for(const auto& [v, p] : fixed) {
    if(!interior.count(v)) {
      EXPECT_EQ(p, start.at(v));
    }
  }

  // Sliding on the cube's own boundary, its corners and edges fixed (they are sharp): the boundary
  // vertices move on the faces, and the quality rises further.
  Target_storage sliding = start;
  const auto on_sharp_edge = [&](Vertex_handle v) {
    const Point_3& p = grid.at(v);
    int on_faces = 0;
    for(int k = 0; k < 3; ++k) on_faces += p[k] == 0 || p[k] == 5;
    return on_faces >= 2;
  };
  const auto sharp = DO::sharp_boundary_vertices(c3t3, Target_map(start));
  std::size_t on_edges = 0;
  for(const auto& [v, p] : grid) {
    EXPECT_EQ(sharp.count(v), std::size_t(on_sharp_edge(v)));
    on_edges += on_sharp_edge(v);
  }
  // The cube's faces meet at 90 degrees (each face flat): the same vertices with a threshold of
  // 89 degrees, none with 91.
  EXPECT_EQ(DO::sharp_boundary_vertices(c3t3, Target_map(start), DO::parameters::sharp_edge_angle(89.)), sharp);
  EXPECT_TRUE(DO::sharp_boundary_vertices(c3t3, Target_map(start), DO::parameters::sharp_edge_angle(91.)).empty());
  EXPECT_EQ(on_edges, 8u + 12u * 4u);   // corners, and 4 inner points on each of the 12 edges
  const auto slide = DO::improve_mesh_quality(c3t3, Target_map(sliding), DO::Conformal_dilatation(),
    DO::parameters::sliding_boundary(DO::Triangle_surface::from_complex_boundary(c3t3, Target_map(start)),
                                     CGAL::parameters::vertex_is_constrained_map(
                                       boost::make_function_property_map<Vertex_handle>([&](Vertex_handle v) { return sharp.count(v) > 0; }))));
  EXPECT_EQ(slide.inverted_cells, 0u);
  EXPECT_LT(slide.final_energy, r.final_energy);
  std::size_t moved = 0;
  for(const auto& [v, p] : sliding) {
    if(interior.count(v)) continue;
    const Point_3& g = grid.at(v);
    // On the face of the cube it started on.
    int kept = 0;
    for(int k = 0; k < 3; ++k) kept += (g[k] == 0 || g[k] == 5) && std::abs(p[k] - g[k]) <= 1e-12;
    EXPECT_GE(kept, 1);
    if(on_sharp_edge(v)) {
      EXPECT_EQ(p, g);
    }
    moved += p != g;
  }
  EXPECT_GT(moved, 0u);
  EXPECT_EQ(DO::mesh_quality(c3t3, Target_map(sliding)).inverted_cells, 0u);
}

TEST(MeshQuality, AnInvertedStartIsRejectedUnlessUntangledFirst)
{
  const Mesh2 grid = equilateral_grid(4);
  Mesh2 mesh = grid;
  // An interior vertex pushed across its ring: some of its triangles invert.
  for(auto v : mesh.vertices())
    if(!mesh.is_border(v)) {
      mesh.point(v) = Point_2(mesh.point(v).x() + 1.2, mesh.point(v).y());
      break;
    }
  ASSERT_GT(DO::mesh_quality(mesh, mesh.points()).inverted_cells, 0u);
  const Mesh2 copy = mesh;
  EXPECT_THROW(DO::improve_mesh_quality(mesh, mesh.points()), DO::Invalid_input);
  for(auto v : mesh.vertices()) EXPECT_EQ(mesh.point(v), copy.point(v));
  const DO::Result r = DO::improve_mesh_quality(mesh, mesh.points(), DO::Conformal_dilatation(),
                                                DO::parameters::untangle_first(true));
  EXPECT_GT(r.inverted_start_cells, 0u);
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_EQ(DO::mesh_quality(mesh, mesh.points()).inverted_cells, 0u);
}

// Angles and radius ratios do not depend on the mesh's units: at 1e80 or 1e-80 they once
// overflowed (a 90 degree minimum angle, every cell a sliver), in 2D and in 3D.
TEST(MeshQuality, FiguresDoNotDependOnUnits)
{
  Mesh2 grid = equilateral_grid(6);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for(auto v : grid.vertices())
    if(!grid.is_border(v)) grid.point(v) = Point_2(grid.point(v).x() + u(rng), grid.point(v).y() + u(rng));
  const DO::Mesh_quality unit = DO::mesh_quality(grid, grid.points());
  const auto expect_same = [](const DO::Mesh_quality& a, const DO::Mesh_quality& b, double scale) {
    EXPECT_NEAR(a.min_angle, b.min_angle, 1e-9 * b.min_angle) << scale;
    EXPECT_NEAR(a.max_angle, b.max_angle, 1e-9 * b.max_angle) << scale;
    EXPECT_NEAR(a.mean_min_angle, b.mean_min_angle, 1e-9 * b.mean_min_angle) << scale;
    EXPECT_NEAR(a.min_radius_ratio, b.min_radius_ratio, 1e-9 * b.min_radius_ratio) << scale;
    EXPECT_NEAR(a.mean_radius_ratio, b.mean_radius_ratio, 1e-9 * b.mean_radius_ratio) << scale;
    EXPECT_EQ(a.slivers, b.slivers) << scale;
    EXPECT_EQ(a.inverted_cells, b.inverted_cells) << scale;
  };
  for(double scale : {1e80, 1e-80, 1e150, 1e-150}) {
    Mesh2 scaled = grid;
    for(auto v : scaled.vertices()) scaled.point(v) = Point_2(grid.point(v).x() * scale, grid.point(v).y() * scale);
    expect_same(DO::mesh_quality(scaled, scaled.points()), unit, scale);
  }

  const C3t3 c3t3 = cube_complex(3);
  Target_storage start;
  DO::map_vertices(c3t3, Target_map(start), [&](const Point_3& p) { return Point_3(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng)); });
  const DO::Mesh_quality unit3 = DO::mesh_quality(c3t3, Target_map(start));
  ASSERT_EQ(unit3.inverted_cells, 0u);
  for(double scale : {1e40, 1e-40, 1e100}) {
    Target_storage scaled;
    for(const auto& [v, p] : start) scaled[v] = Point_3(p.x() * scale, p.y() * scale, p.z() * scale);
    expect_same(DO::mesh_quality(c3t3, Target_map(scaled)), unit3, scale);
  }
}

// A sliding boundary in units far from 1 (1e80): the closest points of the surface once
// overflowed, and every boundary vertex stayed where it was, as if fixed.
TEST(MeshQuality, SlidingDoesNotDependOnUnits)
{
  double unit_energy = 0;
  for(double scale : {1., 1e80, 1e-80}) {
    const C3t3 c3t3 = cube_complex(4, [](int, int, int) { return true; }, scale);
    Target_storage start;
    DO::map_vertices(c3t3, Target_map(start), [](const Point_3& p) { return p; });
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.15, 0.15);
    const auto inside = interior_vertices(c3t3);
    for(Vertex_handle v : inside) {
      const Point_3 p = start.at(v);
      start[v] = Point_3(p.x() + scale * u(rng), p.y() + scale * u(rng), p.z() + scale * u(rng));
    }
    Target_storage positions = start;
    const auto sharp = DO::sharp_boundary_vertices(c3t3, Target_map(start));
    ASSERT_EQ(sharp.size(), 8u + 12u * 3u) << scale;
    const DO::Result r = DO::improve_mesh_quality(c3t3, Target_map(positions), DO::Conformal_dilatation(),
      DO::parameters::sliding_boundary(DO::Triangle_surface::from_complex_boundary(c3t3, Target_map(start)),
                                       CGAL::parameters::vertex_is_constrained_map(boost::make_function_property_map<Vertex_handle>(
                                         [&](Vertex_handle v) { return sharp.count(v) > 0; }))));
    if(scale == 1) unit_energy = r.final_energy;
    EXPECT_NEAR(r.final_energy, unit_energy, 1e-6 * unit_energy) << scale;
    const std::unordered_set<Vertex_handle> interior(inside.begin(), inside.end());
    std::size_t moved = 0;   // boundary vertices
    for(const auto& [v, p] : positions) {
      const Point_3& s = start.at(v);
      if(interior.count(v)) continue;
      moved += p != s;
      for(int k = 0; k < 3; ++k) {   // on the face of the cube where they started
        if(s[k] == 0 || s[k] == 4 * scale) {
          EXPECT_NEAR(p[k], s[k], 1e-12 * scale) << scale;
        }
      }
    }
    EXPECT_GT(moved, 10u) << scale;
  }
}

// Shapes are improved under measures infinite on flat cells only: ARAP and Dirichlet traded
// some tetrahedra down to 1e-13 of their volume.
TEST(MeshQuality, AMeasureFiniteOnFlatCellsIsRefused)
{
  Mesh2 mesh = equilateral_grid(3);
  const Mesh2 copy = mesh;
  EXPECT_THROW(DO::improve_mesh_quality(mesh, mesh.points(), DO::ARAP()), DO::Invalid_input);
  EXPECT_THROW(DO::improve_mesh_quality(mesh, mesh.points(), DO::Dirichlet()), DO::Invalid_input);
  for(auto v : mesh.vertices()) EXPECT_EQ(mesh.point(v), copy.point(v));
  try {
    DO::improve_mesh_quality(mesh, mesh.points(), DO::ARAP());
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("the measure arap is finite on flat cells"), std::string::npos) << e.what();
  }
}
