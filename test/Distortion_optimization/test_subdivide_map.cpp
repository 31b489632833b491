// subdivide_map() (paper section 4.3, Appendix D): linear subdivision keeps every measure's energy
// exactly, Loop's keeps affine maps affine and a real optimized parametrization injective.

#include "test_meshes.h"

#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/Distortion_optimization/subdivide_map.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

using namespace test_meshes;

namespace {

std::string data(const std::string& name) { return std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/" + name; }

// Every built-in measure's volume-weighted mean energy of the map.
template <class Mesh, class UV>
std::map<std::string, double> energies(const Mesh& mesh, const UV& uv)
{
  std::map<std::string, double> e;
  for(const std::string& name : DO::measure_names())
    e[name] = DO::with_measure(name, [&](const auto& measure) { return CGAL::compute_distortion(mesh, uv, measure); }).mean_volume;
  return e;
}

// lion-head of libcgal-demo, parametrized (Tutte) and optimized for the symmetric Dirichlet energy.
struct Optimized_parametrization
{
  Mesh3 mesh;
  Mesh3::Property_map<Mesh3::Vertex_index, Point_2> uv;
  Optimized_parametrization()
  {
    if(!CGAL::IO::read_polygon_mesh(data("lion-head.off"), mesh)) throw std::runtime_error("missing " + data("lion-head.off"));
    uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
    DO::initial_parameterization(mesh, uv);
    CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(), CGAL::parameters::number_of_iterations(20));
  }
};

} // namespace

TEST(SubdivideMap, LinearSubdivisionKeepsEveryEnergyExactly)
{
  Optimized_parametrization p;
  const auto before = energies(p.mesh, p.uv);
  const std::size_t v0 = p.mesh.number_of_vertices(), e0 = p.mesh.number_of_edges(), f0 = p.mesh.number_of_faces();
  std::vector<Point_3> points;
  std::vector<Point_2> targets;
  for(auto v : p.mesh.vertices()) {
    points.push_back(p.mesh.point(v));
    targets.push_back(p.uv[v]);
  }
  DO::subdivide_map(p.mesh, p.uv, DO::parameters::subdivision_scheme(DO::Subdivision_scheme::LINEAR).number_of_iterations(2));
  // Each level: one vertex per edge, four triangles per triangle.
  const std::size_t v1 = v0 + e0, e1 = 2 * e0 + 3 * f0, f1 = 4 * f0;
  EXPECT_EQ(p.mesh.number_of_faces(), 4 * f1);
  EXPECT_EQ(p.mesh.number_of_vertices(), v1 + e1);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(p.mesh));
  for(std::size_t i = 0; i < v0; ++i) {   // the old vertices keep their indices, points and targets
    EXPECT_EQ(p.mesh.point(Mesh3::Vertex_index(i)), points[i]);
    EXPECT_EQ(p.uv[Mesh3::Vertex_index(i)], targets[i]);
  }
  EXPECT_EQ(count_flipped(p.mesh, p.uv), 0u);
  const auto after = energies(p.mesh, p.uv);
  for(const auto& [name, e] : before) EXPECT_NEAR(after.at(name), e, 1e-12 * e) << name;

  // A planar deformation (Point_2 source) too.
  Noisy_map g([](const Point_2& q) { return Point_2(2 * q.x() + 0.3 * q.y() * q.y(), q.y() + 0.1 * q.x()); }, 0.01);
  const auto planar_before = energies(g.mesh, g.uv);
  DO::subdivide_map(g.mesh, g.uv);
  const auto planar_after = energies(g.mesh, g.uv);
  for(const auto& [name, e] : planar_before) EXPECT_NEAR(planar_after.at(name), e, 1e-12 * e) << name;
}

TEST(SubdivideMap, LoopKeepsAffineMapsAffine)
{
  // The unit square grid, its target an affine image: Loop's weights sum to one, so the refined
  // target is the same affine image of the refined source, and they are convex: the source stays
  // in the square (whose corners Loop's border rule rounds off).
  Mesh2 mesh = planar_grid(6);
  auto uv = mesh.add_property_map<Mesh2::Vertex_index, Point_2>("v:uv").first;
  const auto affine = [](const Point_2& q) { return Point_2(1.5 * q.x() - 0.4 * q.y() + 0.2, 0.3 * q.x() + 0.8 * q.y()); };
  for(auto v : mesh.vertices()) uv[v] = affine(mesh.point(v));
  const double k = DO::with_measure("conformal", [&](const auto& m) { return CGAL::compute_distortion(mesh, uv, m); }).max;
  DO::subdivide_map(mesh, uv, DO::parameters::subdivision_scheme(DO::Subdivision_scheme::LOOP).number_of_iterations(2));
  EXPECT_EQ(count_flipped(mesh, uv), 0u);
  for(auto v : mesh.vertices()) {
    const Point_2& q = mesh.point(v);
    EXPECT_LT(std::sqrt(CGAL::squared_distance(uv[v], affine(q))), 1e-12);
    EXPECT_TRUE(q.x() >= -1e-15 && q.x() <= 1 + 1e-15 && q.y() >= -1e-15 && q.y() <= 1 + 1e-15);
  }
  // Every triangle has the affine map's Jacobian.
  const auto s = DO::with_measure("conformal", [&](const auto& m) { return CGAL::compute_distortion(mesh, uv, m); });
  EXPECT_NEAR(s.min, k, 1e-9);
  EXPECT_NEAR(s.max, k, 1e-9);
}

TEST(SubdivideMap, LoopStencilsOnTheOldVertices)
{
  // A quadratic target: the old vertices' new targets are Loop's averages of the old ones, with
  // beta = 1/16 at the grid's valence-6 inner vertices and 3/4, 1/8, 1/8 on the border.
  Mesh2 mesh = planar_grid(4);
  auto uv = mesh.add_property_map<Mesh2::Vertex_index, Point_2>("v:uv").first;
  for(auto v : mesh.vertices()) uv[v] = Point_2(mesh.point(v).x() * mesh.point(v).x(), mesh.point(v).x() * mesh.point(v).y());
  std::vector<Point_2> expected;
  for(auto v : mesh.vertices()) {
    double x = 0, y = 0, w = 0;
    const auto add = [&](Mesh2::Vertex_index u, double weight) {
      x += weight * uv[u].x();
      y += weight * uv[u].y();
      w += weight;
    };
    std::size_t n = 0;
    for(auto h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
      if(!mesh.is_border(v)) {
        add(mesh.source(h), 1. / 16);
        ++n;
      } else if(mesh.is_border(mesh.edge(h))) {
        add(mesh.source(h), 1. / 8);
      }
    }
    ASSERT_TRUE(mesh.is_border(v) || n == 6);
    add(v, 1 - w);
    expected.push_back(Point_2(x, y));
  }
  DO::subdivide_map(mesh, uv, DO::parameters::subdivision_scheme(DO::Subdivision_scheme::LOOP));
  for(std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_LT(std::sqrt(CGAL::squared_distance(uv[Mesh2::Vertex_index(i)], expected[i])), 1e-15) << i;
}

TEST(SubdivideMap, LoopKeepsARealOptimizedParametrizationInjective)
{
  Optimized_parametrization p;
  const double coarse = CGAL::compute_distortion(p.mesh, p.uv, DO::Symmetric_dirichlet()).mean_volume;
  DO::subdivide_map(p.mesh, p.uv, DO::parameters::subdivision_scheme(DO::Subdivision_scheme::LOOP).number_of_iterations(2));
  EXPECT_EQ(count_flipped(p.mesh, p.uv), 0u);
  const double fine = CGAL::compute_distortion(p.mesh, p.uv, DO::Symmetric_dirichlet()).mean_volume;
  EXPECT_TRUE(std::isfinite(fine));
  EXPECT_LT(std::abs(fine - coarse), 0.2 * coarse);   // the smooth map's distortion, near the coarse one's
}

TEST(SubdivideMap, FacesThatAreNotTrianglesAreRefused)
{
  Mesh2 quad;
  const auto a = quad.add_vertex(Point_2(0, 0)), b = quad.add_vertex(Point_2(1, 0)), c = quad.add_vertex(Point_2(1, 1)),
             d = quad.add_vertex(Point_2(0, 1));
  quad.add_face(a, b, c, d);
  auto uv = quad.add_property_map<Mesh2::Vertex_index, Point_2>("v:uv").first;
  EXPECT_THROW(DO::subdivide_map(quad, uv), DO::Invalid_input);
  EXPECT_EQ(quad.number_of_faces(), 1u);
}
