// minimize_distortion on Mesh_complex_3_in_triangulation_3: Mesh_3 meshes, the radial map of the
// paper's Fig. 5, start maps, write-back only to complex vertices. The tests of the
// TetrahedralMeshes suite that need TetGen are in test_tetgen_meshes.cpp (built only with TetGen).

#include "kuhn_block.h"
#include "test_complexes.h"
#include "test_mesh_3.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace {

// The ellipsoid x^2 / a^2 + y^2 + z^2 <= 1 with a = 1.6: star-shaped about the origin, and far
// enough from a ball that where its boundary lands on the sphere matters.
double ellipsoid(const Point_3& p) { return CGAL::to_double(p.x() * p.x() / 2.56 + p.y() * p.y() + p.z() * p.z()) - 1.; }

C3t3 mesh_ellipsoid(double size) { return mesh_implicit(ellipsoid, 3., size); }

} // namespace

TEST(TetrahedralMeshes, RadialMapOfAMesh3BallImprovesWithoutFlips)
{
  const C3t3 c3t3 = mesh_sphere(0.3);
  ASSERT_GT(c3t3.number_of_cells_in_complex(), 500u);
  // Mesh_3's cells in the complex are positively oriented.
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    ASSERT_EQ(CGAL::orientation(c->vertex(0)->point().point(), c->vertex(1)->point().point(),
                                c->vertex(2)->point().point(), c->vertex(3)->point().point()), CGAL::POSITIVE);

  Target_storage storage;
  DO::map_vertices(c3t3, Target_map(storage), radial);
  ASSERT_EQ(inverted(c3t3, storage), 0u);
  const Target_storage start = storage;
  std::unordered_set<Vertex_handle> written;

  std::vector<double> energies;
  const DO::Result r = CGAL::minimize_distortion(c3t3, Recording_map{&storage, &written}, DO::Conformal_dilatation(),
    CGAL::parameters::number_of_iterations(15).visitor([&](std::size_t, double e) { energies.push_back(e); return true; }));
  EXPECT_LT(r.final_energy, r.initial_energy);
  for(std::size_t i = 1; i < energies.size(); ++i) EXPECT_LE(energies[i], energies[i - 1]);
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_EQ(inverted(c3t3, storage), 0u);

  // Boundary vertices unchanged bit for bit; only interior vertices of complex cells written.
  const auto boundary = boundary_vertices(c3t3);
  for(Vertex_handle v : boundary) EXPECT_EQ(storage.at(v), start.at(v));
  EXPECT_FALSE(written.empty());
  for(Vertex_handle v : written) {
    EXPECT_TRUE(start.count(v)) << "a vertex outside the complex was written";
    EXPECT_FALSE(boundary.count(v)) << "a fixed vertex was written";
  }
  EXPECT_EQ(storage.size(), start.size());
}

TEST(TetrahedralMeshes, StarShapedBallAndHarmonicStartsAreValidAndImprove)
{
  // A Mesh_3 ball (a polyhedral approximation of the unit ball) onto the exact unit ball.
  const C3t3 c3t3 = mesh_sphere(0.25);
  Target_storage ball;
  DO::star_shaped_to_unit_ball(c3t3, Target_map(ball), DO::parameters::center(Point_3(0.01, -0.02, 0.03)));
  EXPECT_EQ(inverted(c3t3, ball), 0u);
  for(Vertex_handle v : boundary_vertices(c3t3)) {
    const Point_3& q = ball.at(v);
    EXPECT_NEAR(std::sqrt(CGAL::to_double(q.x() * q.x() + q.y() * q.y() + q.z() * q.z())), 1., 1e-9);
  }
  // The harmonic map for the radial boundary values, then optimized.
  Target_storage harmonic;
  DO::map_vertices(c3t3, Target_map(harmonic), radial);
  DO::harmonic_map(c3t3, Target_map(harmonic));
  EXPECT_EQ(inverted(c3t3, harmonic), 0u);
  const auto r = CGAL::minimize_distortion(c3t3, Target_map(harmonic), DO::Conformal_dilatation(),
                                           CGAL::parameters::number_of_iterations(5));
  EXPECT_LT(r.final_energy, r.initial_energy);
  EXPECT_EQ(inverted(c3t3, harmonic), 0u);
}

TEST(TetrahedralMeshes, HarmonicMapOfAnAffineBoundaryIsThatAffineMap)
{
  const C3t3 c3t3 = mesh_sphere(0.4);
  auto affine = [](const Point_3& p) {
    return Point_3(2 * p.x() + 0.3 * p.y() - 1, p.y() - 0.5 * p.z(), 0.7 * p.z() + 0.2 * p.x() + 4);
  };
  Target_storage exact, harmonic;
  DO::map_vertices(c3t3, Target_map(exact), affine);
  DO::map_vertices(c3t3, Target_map(harmonic), [](const Point_3& p) { return p; });
  for(Vertex_handle v : boundary_vertices(c3t3)) harmonic[v] = exact[v];
  DO::harmonic_map(c3t3, Target_map(harmonic));
  double error = 0;
  for(const auto& kv : exact) error = std::max(error, std::sqrt(CGAL::to_double(CGAL::squared_distance(kv.second, harmonic.at(kv.first)))));
  EXPECT_LT(error, 1e-9);   // affine maps are harmonic for the cotangent Laplacian
}

TEST(TetrahedralMeshes, PolyhedralDomainFromAClosedSurfaceMesh)
{
  Surface_mesh_3 octahedron;
  CGAL::make_icosahedron(octahedron, Point_3(0, 0, 0), 1.);
  const Polyhedral_c3t3 c3t3 = mesh_polyhedral(octahedron);
  ASSERT_GT(c3t3.number_of_cells_in_complex(), 50u);
  std::unordered_map<Polyhedral_tr::Vertex_handle, Point_3> storage;
  boost::associative_property_map<decltype(storage)> target(storage);
  DO::map_vertices(c3t3, target, [](const Point_3& p) { return Point_3(p.x() + 0.1 * p.y() * p.y(), p.y(), p.z()); });
  const auto r = CGAL::minimize_distortion(c3t3, target, DO::MIPS(), CGAL::parameters::number_of_iterations(5));
  EXPECT_LE(r.final_energy, r.initial_energy);
  EXPECT_EQ(r.inverted_cells, 0u);
}

// With threads, c3t3_from_tetrahedra() builds the complex beside its last manifold checks: on a
// block of 5^3 cubes and on random damaged subsets of it (edges and vertices pinched, a cell
// repeated, a facet shared by three), one, two and three threads give the same complex or the same
// message, and a refused input leaves the complex as it was; so for a fold.
TEST(TetrahedralMeshes, ComplexFromTetrahedraIsTheSameOnAnyNumberOfThreads)
{
  const DO::IO::Tetrahedron_soup block = kuhn_block(5);
  std::mt19937 random(5);
  std::size_t failures = 0;
  for(int trial = 0; trial < 40; ++trial) {
    const std::vector<std::array<std::size_t, 4>> cells = damaged_cells(block.cells, trial, random);
    std::vector<std::string> messages;
    std::vector<std::vector<std::array<double, 3>>> points;
    std::vector<std::vector<std::array<std::size_t, 4>>> tetrahedra;
    for(int threads : {1, 2, 3}) {
      C3t3 c3t3;
      DO::c3t3_from_tetrahedra(c3t3, block.points, {block.cells[0]});   // replaced, or kept on a refusal
      try {
        const auto handles = DO::c3t3_from_tetrahedra(c3t3, block.points, cells, DO::parameters::number_of_threads(threads));
        messages.push_back("");
        EXPECT_TRUE(c3t3.triangulation().tds().is_valid()) << trial;
        EXPECT_TRUE(c3t3.triangulation().is_valid()) << trial;
        for(std::size_t i = 0; i < handles.size(); ++i) {
          if(handles[i] == Vertex_handle()) continue;
          EXPECT_EQ(handles[i]->point().point(), Point_3(block.points[i][0], block.points[i][1], block.points[i][2]));
        }
      } catch(const DO::Invalid_input& e) {
        messages.push_back(e.what());
        EXPECT_EQ(c3t3.number_of_cells_in_complex(), 1u) << trial;
      }
      points.emplace_back();
      tetrahedra.emplace_back();
      DO::tetrahedra_from_c3t3(c3t3, points.back(), tetrahedra.back());
    }
    for(int k : {1, 2}) {
      EXPECT_EQ(messages[k], messages[0]) << trial;
      EXPECT_EQ(points[k], points[0]) << trial;
      EXPECT_EQ(tetrahedra[k], tetrahedra[0]) << trial;
    }
    if(messages[0].empty()) {
      EXPECT_EQ(tetrahedra[0].size(), cells.size()) << trial;
    }
    failures += !messages[0].empty();
  }
  EXPECT_GT(failures, 20u);
  // Two cells on the same side of their common facet: the fold check, beside the manifold checks.
  const std::vector<std::array<double, 3>> fan = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 1}};
  for(int threads : {1, 2}) {
    C3t3 c3t3;
    try {
      DO::c3t3_from_tetrahedra(c3t3, fan, {{0, 1, 2, 3}, {2, 1, 0, 4}}, DO::parameters::number_of_threads(threads));
      ADD_FAILURE() << "a folded pair of tetrahedra was accepted on " << threads << " threads";
    } catch(const DO::Invalid_input& e) {
      EXPECT_NE(std::string(e.what()).find("tetrahedra 0 and 1 lie on the same side of their common facet"), std::string::npos) << e.what();
    }
  }
}

// The adapter numbers the vertices in the order the cells first reach them (tetrahedra_from_c3t3()'s),
// marks those of the block's faces as on the boundary, and of two vertices with non-finite targets
// names the first by that number.
TEST(TetrahedralMeshes, AdapterNamesTheFirstNonFiniteTarget)
{
  const DO::IO::Tetrahedron_soup block = kuhn_block(3);
  C3t3 c3t3;
  const auto handles = DO::c3t3_from_tetrahedra(c3t3, block.points, block.cells);
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tets;
  const auto order = DO::tetrahedra_from_c3t3(c3t3, points, tets);
  Target_storage storage;
  for(std::size_t i = 0; i < handles.size(); ++i) storage[handles[i]] = handles[i]->point().point();
  const auto adapter = DO::internal::make_c3t3_adapter(c3t3, Target_map(storage), CGAL::parameters::default_values());
  ASSERT_EQ(adapter.vertex_of, order);
  for(std::size_t i = 0; i < order.size(); ++i) {
    const auto& p = points[i];
    const bool face = std::any_of(p.begin(), p.end(), [](double x) { return x == 0 || x == 3; });
    EXPECT_EQ(adapter.on_boundary[i] != 0, face) << i;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(std::size_t i : {std::size_t(40), std::size_t(17)}) storage[order[i]] = Point_3(nan, 0, 0);
  try {
    CGAL::compute_distortion(c3t3, Target_map(storage), DO::MIPS());
    ADD_FAILURE() << "non-finite targets were accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 17 has a non-finite target coordinate"), std::string::npos) << e.what();
  }
}

TEST(TetrahedralMeshes, BadInput)
{
  std::vector<std::array<double, 3>> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}};
  C3t3 c3t3;
  try {
    DO::c3t3_from_tetrahedra(c3t3, points, {{0, 1, 2, 3}});
    ADD_FAILURE() << "a flat tetrahedron was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("tetrahedron 0 is flat"), std::string::npos) << e.what();
  }
  EXPECT_THROW(DO::c3t3_from_tetrahedra(c3t3, points, {{0, 1, 2, 7}}), DO::Invalid_input);

  // Complexes that are not manifold, each named with its cells: a tetrahedron listed twice (in
  // another vertex order), two that meet only at an edge, two that meet only at a vertex.
  const std::vector<std::array<double, 3>> star = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                                   {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  const std::vector<std::pair<std::vector<std::array<std::size_t, 4>>, std::string>> bad = {
    {{{0, 1, 2, 3}, {1, 0, 3, 2}}, "tetrahedra 0 and 1 have the same vertices"},
    {{{0, 1, 2, 3}, {0, 1, 5, 6}}, "tetrahedra 0 and 1 meet only at the edge (0, 1)"},
    {{{0, 1, 2, 3}, {0, 4, 5, 6}}, "tetrahedra 0 and 1 meet only at vertex 0"}};
  for(const auto& [tets, message] : bad) {
    try {
      DO::c3t3_from_tetrahedra(c3t3, star, tets);
      ADD_FAILURE() << "accepted: " << message;
    } catch(const DO::Invalid_input& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  // Three tetrahedra on one facet (a point above the facet (0, 1, 2) besides vertex 3).
  std::vector<std::array<double, 3>> fan = star;
  fan.push_back({0.2, 0.2, 1});
  try {
    DO::c3t3_from_tetrahedra(c3t3, fan, {{0, 1, 2, 3}, {0, 2, 1, 6}, {2, 1, 0, 7}});
    ADD_FAILURE() << "three tetrahedra on one facet were accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("tetrahedra 0, 1 and 2 share the facet (0, 1, 2)"), std::string::npos) << e.what();
  }
  // Two tetrahedra above the same facet (a fold): each is positive, but they overlap.
  try {
    DO::c3t3_from_tetrahedra(c3t3, fan, {{0, 1, 2, 3}, {2, 1, 0, 7}});
    ADD_FAILURE() << "a folded pair of tetrahedra was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("tetrahedra 0 and 1 lie on the same side of their common facet"), std::string::npos) << e.what();
  }
  // The five tetrahedra of a 4-simplex's boundary: every facet in two of them, every edge and
  // vertex star connected, but no boundary: they overlap in space, the outer one folded over the
  // four inside it.
  const std::vector<std::array<double, 3>> five = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.3, 0.3, 0.3}};
  try {
    DO::c3t3_from_tetrahedra(c3t3, five, {{1, 2, 3, 4}, {0, 2, 3, 4}, {0, 1, 3, 4}, {0, 1, 2, 4}, {0, 1, 2, 3}});
    ADD_FAILURE() << "a complex without boundary was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("tetrahedra 0 and 4 lie on the same side of their common facet"), std::string::npos) << e.what();
  }
  // Separate tetrahedra that overlap without folding: one across the other, one
  // inside the other; apart, they are two parts of a valid complex.
  const std::vector<std::array<double, 3>> two = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                                  {0.2, 0.2, 0.2}, {1.2, 0.2, 0.2}, {0.2, 1.2, 0.2}, {0.2, 0.2, 1.2},
                                                  {0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}, {0.1, 0.2, 0.1}, {0.1, 0.1, 0.2},
                                                  {3, 0, 0}, {4, 0, 0}, {3, 1, 0}, {3, 0, 1}};
  for(const auto& [second, message] : std::vector<std::pair<std::array<std::size_t, 4>, std::string>>{
        {{4, 5, 6, 7}, "the tetrahedra overlap: their boundary passes through itself"},
        {{8, 9, 10, 11}, "the tetrahedra overlap: a part of the mesh lies inside another"}}) {
    try {
      DO::c3t3_from_tetrahedra(c3t3, two, {{0, 1, 2, 3}, second});
      ADD_FAILURE() << "accepted: " << message;
    } catch(const DO::Invalid_input& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(DO::c3t3_from_tetrahedra(c3t3, two, {{0, 1, 2, 3}, {12, 13, 14, 15}}).size(), two.size());
  EXPECT_EQ(c3t3.number_of_cells_in_complex(), 2u);
  // Two tetrahedra sharing a facet are a manifold complex; the points in neither get no vertex.
  const auto pair = DO::c3t3_from_tetrahedra(c3t3, star, {{0, 1, 2, 3}, {0, 2, 1, 6}});
  ASSERT_EQ(pair.size(), star.size());
  EXPECT_EQ(pair[4], Vertex_handle());
  EXPECT_EQ(pair[5], Vertex_handle());
  EXPECT_EQ(c3t3.triangulation().number_of_vertices(), 5u);
  EXPECT_EQ(c3t3.number_of_cells_in_complex(), 2u);
  EXPECT_TRUE(c3t3.triangulation().tds().is_valid());
  const auto first = pair[3]->cell();   // the tetrahedron (0, 1, 2, 3), across (0, 1, 2) from the other
  EXPECT_TRUE(first->neighbor(first->index(pair[3]))->has_vertex(pair[6]));

  // An inverted start under a normalized measure names the cell and writes nothing.
  const auto handles = DO::c3t3_from_tetrahedra(c3t3, points, {{0, 1, 2, 4}, {1, 3, 2, 4}});
  Target_storage storage;
  for(std::size_t i = 0; i < points.size(); ++i) storage[handles[i]] = Point_3(points[i][0], points[i][1], points[i][2]);
  storage[handles[4]] = Point_3(0.2, 0.2, -1);   // below the base: both tetrahedra inverted
  const Target_storage before = storage;
  try {
    CGAL::minimize_distortion(c3t3, Target_map(storage), DO::Conformal_dilatation(),
                              CGAL::parameters::vertex_is_constrained_map(boost::make_function_property_map<Vertex_handle>(
                                [](Vertex_handle) { return false; })));
    ADD_FAILURE() << "an inverted start was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("inverted"), std::string::npos) << e.what();
  }
  EXPECT_EQ(storage, before);
}

// The star-shaped map of `c3t3` onto the unit ball about the origin, which must not invert a cell.
static Target_storage onto_unit_ball(const C3t3& c3t3)
{
  Target_storage start;
  DO::star_shaped_to_unit_ball(c3t3, Target_map(start), DO::parameters::center(CGAL::ORIGIN));
  EXPECT_EQ(inverted(c3t3, start), 0u);
  return start;
}

// Paper Fig. 13's setting: a volume onto the ball with its boundary sliding on the sphere. Sliding
// must reach a lower energy than the fixed boundary of the same start, keep every boundary vertex
// on the sphere (to rounding) and never invert a cell, on one thread and two.
TEST(TetrahedralMeshes, BoundarySlidingOnTheUnitSphere)
{
  const C3t3 c3t3 = mesh_ellipsoid(0.3);
  const Target_storage start = onto_unit_ball(c3t3);
  const auto boundary = boundary_vertices(c3t3);

  Target_storage fixed = start;
  const auto f = CGAL::minimize_distortion(c3t3, Target_map(fixed), DO::Conformal_dilatation());
  for(int threads : {1, 2}) {
    Target_storage sliding = start;
    const auto r = CGAL::minimize_distortion(c3t3, Target_map(sliding), DO::Conformal_dilatation(),
                                             DO::parameters::sliding_boundary(DO::Sphere_surface(),
                                               DO::parameters::number_of_threads(threads)));
    EXPECT_EQ(r.inverted_cells, 0u);
    EXPECT_EQ(inverted(c3t3, sliding), 0u);
    EXPECT_LT(r.final_energy, f.final_energy - 0.05 * (f.final_energy - 1)) << threads << " threads";
    std::size_t moved = 0;
    for(Vertex_handle v : boundary) {
      const Point_3& p = sliding.at(v);
      EXPECT_NEAR(std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z())), 1., 1e-12);
      moved += p != start.at(v);
    }
    EXPECT_GT(moved, boundary.size() / 2);
  }
}

// Newton's global steps on a complex (the default: truncated conjugate gradients on the projected
// Hessian) and the reweighted Laplacian's reach the same minimum of symmetric Dirichlet, with the
// boundary fixed and sliding on the sphere (Newton's step restricted to the tangent planes);
// Newton's in fewer iterations.
TEST(TetrahedralMeshes, NewtonAndLaplacianStepsReachTheSameMinimum)
{
  const C3t3 c3t3 = mesh_ellipsoid(0.3);
  const Target_storage start = onto_unit_ball(c3t3);
  const auto boundary = boundary_vertices(c3t3);
  for(const bool slide : {false, true}) {
    std::array<DO::Result, 2> results;
    for(int k = 0; k < 2; ++k) {
      Target_storage map = start;
      const auto np = DO::parameters::global_solver(k == 0 ? DO::Global_solver::REWEIGHTED_LAPLACIAN : DO::Global_solver::PROJECTED_NEWTON,
        DO::parameters::convergence_threshold(1e-9)).number_of_iterations(3000);
      results[k] = slide ? CGAL::minimize_distortion(c3t3, Target_map(map), DO::Symmetric_dirichlet(),
                                                     DO::parameters::sliding_boundary(DO::Sphere_surface(), np))
                         : CGAL::minimize_distortion(c3t3, Target_map(map), DO::Symmetric_dirichlet(), np);
      EXPECT_EQ(inverted(c3t3, map), 0u) << slide << k;
      double farthest = 0;
      for(Vertex_handle v : boundary) {
        const Point_3& p = map.at(v);
        farthest = std::max(farthest, std::abs(std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z())) - 1));
      }
      EXPECT_LT(farthest, 1e-12) << slide << k;
    }
    EXPECT_LT(results[1].final_energy, results[1].initial_energy) << slide;
    EXPECT_NEAR(results[1].final_energy, results[0].final_energy, 1e-6 * results[0].final_energy) << slide;
    EXPECT_LT(results[1].iterations, results[0].iterations) << slide;
  }
}

// The reweighted Laplacian's steps alone (no sweep) with the boundary sliding on the sphere: each
// solves for the gradient's part in the tangent planes, so the steps descend to the minimum of
// symmetric Dirichlet that Newton's steps reach (within 0.1%). Solved for the whole gradient, the
// normal forces the sphere holds would spread through the interior, and the steps would not
// descend.
TEST(TetrahedralMeshes, LaplacianStepsAloneDescendWithTheBoundarySliding)
{
  const C3t3 c3t3 = mesh_ellipsoid(0.3);
  const Target_storage start = onto_unit_ball(c3t3);
  std::array<double, 2> energy;
  for(int k = 0; k < 2; ++k) {
    Target_storage map = start;
    const auto r = CGAL::minimize_distortion(c3t3, Target_map(map), DO::Symmetric_dirichlet(),
      DO::parameters::sliding_boundary(DO::Sphere_surface(), DO::parameters::schedule(DO::Schedule::GLOBAL,
        DO::parameters::global_solver(k == 0 ? DO::Global_solver::REWEIGHTED_LAPLACIAN : DO::Global_solver::PROJECTED_NEWTON,
          DO::parameters::convergence_threshold(1e-9)).number_of_iterations(3000))));
    EXPECT_EQ(inverted(c3t3, map), 0u) << k;
    energy[k] = r.final_energy;
  }
  EXPECT_LT(std::abs(energy[0] - energy[1]), 1e-3 * energy[1]);
}

// With the boundary sliding, the Newton steps of K are MIPS's Hessian applied to K's own gradient
// (a proxy metric, so each step descends on K): the ellipsoid onto the ball reaches a lower K than
// with the reweighted Laplacian's steps, in fewer iterations, no cell inverted, the reported
// energy the map's. Their default schedule is
// ALTERNATING (the model's minimizers are not K's): the same map, to the bit, as asked explicitly.
TEST(TetrahedralMeshes, ProxyNewtonStepsLeadWithTheBoundarySliding)
{
  const C3t3 c3t3 = mesh_ellipsoid(0.3);
  const Target_storage start = onto_unit_ball(c3t3);
  std::array<DO::Result, 3> r;
  std::array<Target_storage, 3> maps;
  for(int k = 0; k < 3; ++k) {
    maps[k] = start;
    const auto np = DO::parameters::global_solver(k == 0 ? DO::Global_solver::REWEIGHTED_LAPLACIAN : DO::Global_solver::PROJECTED_NEWTON,
                                                  DO::parameters::convergence_threshold(1e-6)).number_of_iterations(300);
    r[k] = k < 2 ? CGAL::minimize_distortion(c3t3, Target_map(maps[k]), DO::Conformal_dilatation(),
                                             DO::parameters::sliding_boundary(DO::Sphere_surface(), np))
                 : CGAL::minimize_distortion(c3t3, Target_map(maps[k]), DO::Conformal_dilatation(),
                                             DO::parameters::sliding_boundary(DO::Sphere_surface(),
                                               DO::parameters::schedule(DO::Schedule::ALTERNATING, np)));
    EXPECT_EQ(inverted(c3t3, maps[k]), 0u) << k;
    EXPECT_NEAR(r[k].final_energy, CGAL::compute_distortion(c3t3, Target_map(maps[k]), DO::Conformal_dilatation()).mean_volume,
                1e-12) << k;
  }
  EXPECT_LT(r[1].final_energy, r[0].final_energy);
  EXPECT_LT(r[1].iterations, r[0].iterations);
  EXPECT_EQ(maps[2], maps[1]);
  EXPECT_EQ(r[2].iterations, r[1].iterations);
}

// With nothing fixed, K and C are minimal (1) at the source's similarities and rigid motions,
// where their kinks make the Laplacian's steps crawl: Newton steps on a smooth model with the
// same minimizers (MIPS, symmetric Dirichlet) reach them. The ellipsoid onto the ball, no vertex
// fixed: the model's steps get K and C within 1e-9 of 1 (where the schedule stops: within its
// resolution of the minimum) in a few iterations, no cell inverted; after 30 the Laplacian's
// are still at least ten times further.
TEST(TetrahedralMeshes, DilatationsTakeTheNewtonStepsOfASmoothModelWithNothingFixed)
{
  const C3t3 c3t3 = mesh_ellipsoid(0.3);
  const Target_storage start = onto_unit_ball(c3t3);
  const auto nothing_fixed = boost::make_function_property_map<Vertex_handle>([](Vertex_handle) { return false; });
  const auto run = [&](const auto& measure, DO::Global_solver solver) {
    Target_storage map = start;
    const DO::Result r = CGAL::minimize_distortion(c3t3, Target_map(map), measure,
      DO::parameters::global_solver(solver).vertex_is_constrained_map(nothing_fixed).number_of_iterations(30));
    EXPECT_EQ(inverted(c3t3, map), 0u) << measure.name();
    EXPECT_NEAR(r.final_energy, CGAL::compute_distortion(c3t3, Target_map(map), measure).mean_volume, 1e-12) << measure.name();
    return r.final_energy;
  };
  const auto check = [&](const auto& measure) {
    const double newton = run(measure, DO::Global_solver::PROJECTED_NEWTON);
    const double laplacian = run(measure, DO::Global_solver::REWEIGHTED_LAPLACIAN);
    EXPECT_LT(newton - 1, 1e-9 * newton) << measure.name();
    EXPECT_GT(laplacian - 1, 10 * std::max(newton - 1, 1e-9)) << measure.name();
  };
  check(DO::Conformal_dilatation());
  check(DO::Isometric_dilatation());
}

// Why a model's Newton steps switch to the Laplacian's preconditioner: near a similarity, with
// nothing fixed, MIPS's Hessian is nearly singular in every cell's scaling, and Jacobi's
// preconditioned conjugate gradients do not reach the truncated solve's residual (1e-2) within its
// 60 iterations; with an incomplete Cholesky factor of the Laplacian on each coordinate, the same
// 60 iterations lower the quadratic model more than tenfold further, along a descent direction.
TEST(TetrahedralMeshes, LaplacianPreconditionerGoesFurtherOnMipsNewtonSystemsNearASimilarity)
{
  const C3t3 c3t3 = mesh_ellipsoid(0.2);
  Target_storage map;   // twice the source, slightly bent: a similarity up to 1e-2
  DO::map_vertices(c3t3, Target_map(map), [](const Point_3& p) {
    return Point_3(2 * p.x() + 0.02 * std::sin(3 * p.y()), 2 * p.y() + 0.02 * std::sin(3 * p.z()), 2 * p.z() + 0.02 * std::sin(3 * p.x()));
  });
  ASSERT_EQ(inverted(c3t3, map), 0u);
  const auto nothing_fixed = boost::make_function_property_map<Vertex_handle>([](Vertex_handle) { return false; });
  const auto np = CGAL::parameters::vertex_is_constrained_map(nothing_fixed);
  const auto adapter = DO::internal::make_c3t3_adapter(c3t3, Target_map(map), np);
  const auto problem = DO::internal::make_problem(adapter, np);
  const DO::internal::Workers workers;
  DO::internal::Laplacian_system<3> system(problem, workers);
  ASSERT_EQ(system.size(), static_cast<int>(problem.number_of_vertices()));
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(system.size(), 3);
  system.refill_hessian([&](const std::uint32_t* cells, std::size_t count, DO::internal::Cell_hessian<3>* H,
                            std::array<DO::internal::Vector<3>, 4>* gradient) {
    for(std::size_t i = 0; i < count; ++i)
      ASSERT_TRUE(DO::internal::cell_hessian<3>(DO::MIPS(), problem.map.jacobian(cells[i]), problem.map.inverse_rest[cells[i]], H[i], gradient[i]));
  }, &g);
  const Eigen::SparseMatrix<double>& H = system.hessian();
  Eigen::MatrixXd b(H.rows(), 1);
  for(int j = 0; j < g.rows(); ++j) b.col(0).segment<3>(3 * j) = -g.row(j).transpose();
  const auto descends = [&](const Eigen::MatrixXd& x) { return x.allFinite() && b.col(0).dot(x.col(0)) > 0; };

  Eigen::MatrixXd by_jacobi = Eigen::MatrixXd::Zero(H.rows(), 1), by_laplacian = by_jacobi;
  Eigen::DiagonalPreconditioner<double> jacobi;
  jacobi.compute(H);
  EXPECT_FALSE(system.solve(H, jacobi, b, by_jacobi, 60, 1e-2));
  EXPECT_TRUE(descends(by_jacobi));
  const DO::internal::Laplacian_system<3>::Coordinatewise_laplacian laplacian(system);
  ASSERT_TRUE(laplacian.ok());
  system.solve(H, laplacian, b, by_laplacian, 60, 1e-2);
  EXPECT_TRUE(descends(by_laplacian));
  // The quadratic model g.x + x.Hx / 2 that the truncated solve minimizes over its iterates.
  const auto model = [&](const Eigen::MatrixXd& x) { return -b.col(0).dot(x.col(0)) + 0.5 * x.col(0).dot(H * x.col(0)); };
  EXPECT_LT(model(by_laplacian), 10 * model(by_jacobi));
  EXPECT_LT(model(by_jacobi), 0.);

  // A solve that is only worth it where it converges fast (a lagged factorization's) gives up
  // Jacobi's as soon as its rate so far cannot reach the residual, long before the 60 iterations
  // (the iterate it stops at still descends); a factorization of H itself reaches it at once.
  using Give_up = DO::internal::Laplacian_system<3>::Give_up;
  DO::internal::Laplacian_system<3>::Solve_outcome outcome;
  Eigen::MatrixXd given_up = Eigen::MatrixXd::Zero(H.rows(), 1), factored = given_up;
  EXPECT_FALSE(system.solve(H, jacobi, b, given_up, 60, 1e-2, &outcome, Give_up::WHEN_TOO_SLOW));
  EXPECT_LT(outcome.iterations, 20);
  EXPECT_GT(outcome.residual, 1e-2);
  EXPECT_TRUE(descends(given_up));
  DO::internal::Sparse_cholesky<3> factorization;
  ASSERT_TRUE(factorization.factorize(H, 1e-10 * H.diagonal().mean()));
  EXPECT_TRUE(system.solve(H, factorization, b, factored, 60, 1e-2, &outcome, Give_up::WHEN_TOO_SLOW));
  EXPECT_LE(outcome.iterations, 2);
  EXPECT_TRUE(descends(factored));
}

// A torus is not star-shaped about a point of its tube: the ball map must refuse it, name a cell
// and leave the target alone. The radial map of Table 1 keeps the unit sphere.
TEST(TetrahedralMeshes, BallMapRefusesADomainThatIsNotStarShaped)
{
  const auto torus = [](const Point_3& p) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    const double rho = std::sqrt(x * x + y * y) - 1;
    return rho * rho + z * z - 0.16;
  };
  const C3t3 c3t3 = mesh_implicit(+torus, 2., 0.2);
  Target_storage ball;
  try {
    DO::star_shaped_to_unit_ball(c3t3, Target_map(ball), DO::parameters::center(Point_3(1, 0, 0)));
    ADD_FAILURE() << "a torus was mapped onto the ball";
  } catch(const DO::Domain_not_star_shaped& e) {
    EXPECT_NE(std::string(e.what()).find("not star-shaped about the centre: the boundary facet of cell"), std::string::npos)
      << e.what();
  }
  EXPECT_TRUE(ball.empty());
  // The centre of the hole is outside the domain.
  try {
    DO::star_shaped_to_unit_ball(c3t3, Target_map(ball), DO::parameters::center(Point_3(0, 0, 0)));
    ADD_FAILURE() << "a centre outside the domain was accepted";
  } catch(const DO::Center_outside_domain& e) {
    EXPECT_NE(std::string(e.what()).find("not strictly inside"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(ball.empty());

  const C3t3 sphere = mesh_sphere(0.4);
  Target_storage radial_start;
  // About a point outside the sphere the radial map is refused, its target untouched.
  EXPECT_THROW(DO::radial_map(sphere, Target_map(radial_start), DO::parameters::center(Point_3(2, 0, 0))), DO::Center_outside_domain);
  EXPECT_TRUE(radial_start.empty());
  // Nor on its boundary: at a boundary vertex (in cells whose facets through it may all be inner
  // ones), or at the midpoint of a boundary edge (where the rounded midpoint is on it).
  std::size_t tried = 0;
  for(auto c = sphere.cells_in_complex_begin(); c != sphere.cells_in_complex_end() && tried < 20; ++c)
    for(int i = 0; i < 4 && tried < 20; ++i)
      if(!sphere.is_in_complex(c->neighbor(i))) {
        const Point_3 a = c->vertex((i + 1) % 4)->point().point(), b = c->vertex((i + 2) % 4)->point().point();
        EXPECT_THROW(DO::radial_map(sphere, Target_map(radial_start), DO::parameters::center(a)), DO::Center_outside_domain) << a;
        const Point_3 mid((a.x() + b.x()) / 2, (a.y() + b.y()) / 2, (a.z() + b.z()) / 2);
        if(CGAL::collinear(a, b, mid)) {
          EXPECT_THROW(DO::radial_map(sphere, Target_map(radial_start), DO::parameters::center(mid)), DO::Center_outside_domain) << mid;
        }
        ++tried;
      }
  EXPECT_EQ(tried, 20u);
  EXPECT_TRUE(radial_start.empty());
  DO::radial_map(sphere, Target_map(radial_start), DO::parameters::center(Point_3(0, 0, 0)));
  for(const auto& [v, q] : radial_start)
    EXPECT_EQ(q, radial(v->point().point()));
}

// The start maps take their centre by name: without it, the volume centroid (the same map, bit
// for bit, as with the centroid given); about another point inside, the map of that point (the
// radial map is (p - c) |p - c| exactly; the ball map moves every vertex and still puts the
// boundary on the unit sphere, the rest inside); CGAL::ORIGIN is a centre. On CGAL's sphere.mesh.
TEST(TetrahedralMeshes, StartMapsTakeTheirCentreByName)
{
  const DO::IO::Tetrahedron_soup soup = DO::IO::read_tetrahedron_soup(DISTORTION_OPTIMIZATION_DATA_DIR "/sphere.mesh");
  C3t3 c3t3;
  DO::c3t3_from_tetrahedra(c3t3, soup.points, soup.cells);
  const Point_3 g = DO::volume_centroid(c3t3), off = g + K::Vector_3(0.15, -0.05, 0.1);
  const auto boundary = boundary_vertices(c3t3);

  Target_storage by_default, at_centroid, about_off, at_origin, about_zero;
  const std::size_t flat = DO::star_shaped_to_unit_ball(c3t3, Target_map(by_default));
  EXPECT_EQ(DO::star_shaped_to_unit_ball(c3t3, Target_map(at_centroid), DO::parameters::center(g)), flat);
  EXPECT_EQ(by_default, at_centroid);
  ASSERT_EQ(by_default.size(), 757u);
  DO::star_shaped_to_unit_ball(c3t3, Target_map(about_off), DO::parameters::center(off));
  ASSERT_EQ(about_off.size(), by_default.size());
  const auto norm = [](const Point_3& q) { return std::sqrt(CGAL::to_double(q.x() * q.x() + q.y() * q.y() + q.z() * q.z())); };
  std::size_t moved = 0;
  for(const auto& [v, q] : about_off) {
    moved += q != by_default.at(v);
    EXPECT_LE(norm(q), 1 + 1e-12);
    if(boundary.count(v)) {
      EXPECT_NEAR(norm(q), 1, 1e-12);
    }
  }
  EXPECT_EQ(moved, about_off.size());
  DO::star_shaped_to_unit_ball(c3t3, Target_map(at_origin), DO::parameters::center(CGAL::ORIGIN));
  DO::star_shaped_to_unit_ball(c3t3, Target_map(about_zero), DO::parameters::center(Point_3(0, 0, 0)));
  EXPECT_EQ(at_origin, about_zero);

  Target_storage radial_default, radial_centroid, radial_off;
  DO::radial_map(c3t3, Target_map(radial_default));
  DO::radial_map(c3t3, Target_map(radial_centroid), DO::parameters::center(g));
  EXPECT_EQ(radial_default, radial_centroid);
  DO::radial_map(c3t3, Target_map(radial_off), DO::parameters::center(off));
  ASSERT_EQ(radial_off.size(), 757u);
  for(const auto& [v, q] : radial_off) {
    const K::Vector_3 u = v->point().point() - off;
    const double r = std::sqrt(u.squared_length());
    EXPECT_EQ(q, Point_3(r * u.x(), r * u.y(), r * u.z()));
    EXPECT_NE(q, radial_default.at(v));
  }
  // A centre outside the domain is refused whichever map takes it.
  EXPECT_THROW(DO::radial_map(c3t3, Target_map(radial_off), DO::parameters::center(Point_3(3, 0, 0))), DO::Center_outside_domain);
  EXPECT_THROW(DO::star_shaped_to_unit_ball(c3t3, Target_map(about_off), DO::parameters::center(Point_3(3, 0, 0))),
               DO::Center_outside_domain);
}
