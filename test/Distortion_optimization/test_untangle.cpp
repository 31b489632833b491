// untangle() and minimize_distortion(untangle_first) on CGAL::Surface_mesh: tangled grids with
// fixed boundaries, constraints kept to the bit, starts with no injective map, and CGAL's ARAP
// parameterization of a real disk untangled with a free border.

#include "test_meshes.h"

#include <CGAL/Distortion_optimization/global_injectivity.h>
#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/untangle.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/property_map/function_property_map.hpp>
#include <gtest/gtest.h>

#include <string>


using namespace test_meshes;

namespace {

// A 16 x 16 grid whose border is the identity and whose interior vertices moved by up to `noise`
// (the spacing is 1/16): many triangles inverted.
struct Tangled_grid : Noisy_map
{
  explicit Tangled_grid(double noise, unsigned seed = 1) : Noisy_map([](const Point_2& p) { return p; }, noise, seed) {}
};

// CGAL's ARAP parameterization of lion-head (the longest border free) into uv; returns the
// number of flipped triangles (0 with a test failure if it cannot be made).
template <class UV>
std::size_t arap_lion_head(Mesh3& mesh, UV uv)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/lion-head.off", mesh));
  const auto status = SMP::parameterize(mesh, SMP::ARAP_parameterizer_3<Mesh3>(),
                                        CGAL::Polygon_mesh_processing::longest_border(mesh).first, uv);
  EXPECT_EQ(status, SMP::OK);
  return status == SMP::OK ? count_flipped(mesh, uv) : 0;
}

} // namespace

TEST(Untangle, TangledGridsWithAFixedBoundaryBecomeInjective)
{
  for(unsigned seed : {1u, 2u, 3u}) {
    Tangled_grid g(0.15, seed);
    // The border but its corner (0, 0) and every 9th interior vertex (put back at its source) are
    // constrained: they keep their targets to the bit. (With the whole border constrained the
    // rounds would start from its harmonic map, here the identity, untangled at once.)
    auto fixed = g.mesh.add_property_map<Mesh2::Vertex_index, bool>("v:fixed", false).first;
    std::size_t i = 0;
    for(auto v : g.mesh.vertices()) {
      fixed[v] = g.mesh.is_border(v) ? g.mesh.point(v) != Point_2(0, 0) : i++ % 9 == 0;
      if(fixed[v]) g.uv[v] = g.mesh.point(v);
    }
    const std::size_t tangled = count_flipped(g.mesh, g.uv);
    ASSERT_GT(tangled, 20u) << seed;
    const std::vector<Point_2> start = g.targets();
    std::vector<std::size_t> inverted_per_round;
    const DO::Untangle_result r = DO::untangle(g.mesh, g.uv, CGAL::parameters::vertex_is_constrained_map(fixed)
      .visitor([&](std::size_t round, double barrier, std::size_t inverted) {
        EXPECT_EQ(round, inverted_per_round.size() + 1);
        EXPECT_TRUE(std::isfinite(barrier));
        inverted_per_round.push_back(inverted);
        return true;
      }));
    EXPECT_EQ(r.inverted_before, tangled) << seed;
    EXPECT_EQ(r.inverted_after, 0u) << seed;
    EXPECT_EQ(count_flipped(g.mesh, g.uv), 0u) << seed;
    EXPECT_EQ(inverted_per_round.size(), r.iterations);
    EXPECT_EQ(inverted_per_round.back(), 0u);
    for(auto v : g.mesh.vertices())
      if(fixed[v]) { EXPECT_EQ(g.uv[v], start[v.idx()]) << seed; }

    // The same start through minimize_distortion: untangled, then optimized.
    for(auto v : g.mesh.vertices()) g.uv[v] = start[v.idx()];
    const DO::Result m = CGAL::minimize_distortion(g.mesh, g.uv, DO::Symmetric_dirichlet(),
      DO::parameters::untangle_first(true, CGAL::parameters::vertex_is_constrained_map(fixed)));
    EXPECT_EQ(m.inverted_start_cells, tangled);
    EXPECT_GT(m.untangle_iterations, 0u);
    EXPECT_EQ(m.inverted_cells, 0u);
    EXPECT_EQ(count_flipped(g.mesh, g.uv), 0u);
    EXPECT_TRUE(std::isfinite(m.final_energy));
    EXPECT_LE(m.final_energy, m.initial_energy);
    EXPECT_NEAR(brute_force_energy(g.mesh, g.uv, "symmetric_dirichlet"), m.final_energy, 1e-9 * m.final_energy);
    for(auto v : g.mesh.vertices())
      if(fixed[v]) { EXPECT_EQ(g.uv[v], start[v.idx()]) << seed; }

    // A visitor that stops at the first round, cells still inverted: that round's map, the count
    // it was told, and energies that are not numbers (the measure is infinite on inverted cells).
    if(inverted_per_round.front() == 0) continue;
    for(auto v : g.mesh.vertices()) g.uv[v] = start[v.idx()];
    std::size_t told = 0;
    const DO::Result stopped = CGAL::minimize_distortion(g.mesh, g.uv, DO::Symmetric_dirichlet(),
      DO::parameters::untangle_first(true, CGAL::parameters::vertex_is_constrained_map(fixed)
        .visitor([&](std::size_t, double, std::size_t inverted) { told = inverted; return false; })));
    EXPECT_TRUE(stopped.stopped_by_visitor);
    EXPECT_GT(stopped.inverted_cells, 0u);
    EXPECT_EQ(stopped.inverted_cells, told);
    EXPECT_EQ(count_flipped(g.mesh, g.uv), told);
    EXPECT_TRUE(std::isnan(stopped.final_energy));

    // Stopped at the round that untangles the map: no optimization, the untangled map's energy.
    for(auto v : g.mesh.vertices()) g.uv[v] = start[v.idx()];
    const DO::Result at_zero = CGAL::minimize_distortion(g.mesh, g.uv, DO::Symmetric_dirichlet(),
      DO::parameters::untangle_first(true, CGAL::parameters::vertex_is_constrained_map(fixed)
        .visitor([&](std::size_t, double, std::size_t inverted) { return inverted > 0; })));
    EXPECT_TRUE(at_zero.stopped_by_visitor);
    EXPECT_EQ(at_zero.iterations, 0u);
    EXPECT_EQ(at_zero.inverted_cells, 0u);
    EXPECT_EQ(count_flipped(g.mesh, g.uv), 0u);
    EXPECT_EQ(at_zero.final_energy, at_zero.initial_energy);
    EXPECT_NEAR(brute_force_energy(g.mesh, g.uv, "symmetric_dirichlet"), at_zero.final_energy, 1e-9 * at_zero.final_energy);
  }
}

// A 24 x 24 grid with its border on an L-shaped domain ([0, 1]^2 minus [0.5, 1]^2, by arc length:
// both perimeters are 4, the square's corner (1, 1) goes to the inner corner) and fixed there.
// Whatever its inside's start, the untangling starts from the harmonic map of that border, which
// folds only about the inner corner: the start inside left where it was (its triangles over the
// missing quarter fold back a band of others), mirrored about the diagonal (every triangle off the
// border inverted) and collapsed to a point (all flat) give the same injective map, to the bit.
TEST(Untangle, AFixedBorderStartsFromItsHarmonicMapWhereThatFoldsLess)
{
  const auto on_l = [](double t) {   // the L's border at arc length t from (0, 0), counter-clockwise
    return t < 1 ? Point_2(t, 0) : t < 1.5 ? Point_2(1, t - 1) : t < 2 ? Point_2(2.5 - t, 0.5)
         : t < 2.5 ? Point_2(0.5, t - 1.5) : t < 3 ? Point_2(3 - t, 1) : Point_2(0, 4 - t);
  };
  const auto border = [&](const Point_2& p) {
    const double x = p.x(), y = p.y();
    return y == 0 ? on_l(x) : x == 1 ? on_l(1 + y) : y == 1 ? on_l(3 - x) : on_l(4 - y);
  };
  std::vector<std::vector<Point_2>> results;
  std::vector<std::size_t> tangled;
  for(int start = 0; start < 3; ++start) {
    Mesh2 mesh = planar_grid(24);
    auto uv = make_target(mesh, [&](const Point_2& p) {
      const bool inside = p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 1;
      return !inside ? border(p) : start == 0 ? p : start == 1 ? Point_2(p.y(), p.x()) : Point_2(0.25, 0.25);
    });
    tangled.push_back(count_flipped(mesh, uv));
    const DO::Untangle_result r = DO::untangle(mesh, uv);
    EXPECT_GE(r.inverted_before, tangled.back()) << start;   // (and the cells flat to rounding)
    EXPECT_EQ(r.inverted_after, 0u) << start;
    EXPECT_EQ(count_flipped(mesh, uv), 0u) << start;
    for(auto v : mesh.vertices())
      if(mesh.is_border(v)) { EXPECT_EQ(uv[v], border(mesh.point(v))) << start; }
    results.push_back(targets_of(mesh, uv));
  }
  // The inside left in place tangles fewest triangles, but folds the most area.
  EXPECT_GT(tangled[0], 0u);
  EXPECT_LT(tangled[0], tangled[1]);
  EXPECT_EQ(tangled[2], 2u * 24 * 24 - 4 * 24);
  EXPECT_EQ(results[0], results[1]);
  EXPECT_EQ(results[0], results[2]);
}

TEST(Untangle, AnInjectiveStartIsLeftAsItIs)
{
  Tangled_grid g(0.01, 4);
  ASSERT_EQ(count_flipped(g.mesh, g.uv), 0u);
  const std::vector<Point_2> start = g.targets();
  const DO::Untangle_result r = DO::untangle(g.mesh, g.uv);
  EXPECT_EQ(r.inverted_before, 0u);
  EXPECT_EQ(r.iterations, 0u);
  EXPECT_EQ(g.targets(), start);
}

TEST(Untangle, NoInjectiveMapGivesAnErrorAndLeavesTheMapUnchanged)
{
  // The border fixed, and the middle vertex fixed outside it: an orientation-preserving map with
  // this border covers the square exactly once, so none has a vertex outside.
  Tangled_grid outside(0., 1);
  auto center = outside.mesh.add_property_map<Mesh2::Vertex_index, bool>("v:center", false).first;
  const Mesh2::Vertex_index middle(8 * 17 + 8);
  for(auto v : outside.mesh.vertices()) center[v] = outside.mesh.is_border(v) || v == middle;
  outside.uv[middle] = Point_2(3, 0.5);
  // An inverted triangle whose three vertices are constrained: one vertex reflected through the
  // midpoint of the opposite edge.
  Tangled_grid pinned(0., 1);
  auto fixed = pinned.mesh.add_property_map<Mesh2::Vertex_index, bool>("v:fixed", false).first;
  const auto h = pinned.mesh.halfedge(Mesh2::Face_index(100));
  const auto a = pinned.mesh.source(h), b = pinned.mesh.target(h), c = pinned.mesh.target(pinned.mesh.next(h));
  for(auto v : {a, b, c}) fixed[v] = true;
  pinned.uv[c] = Point_2(pinned.uv[a].x() + pinned.uv[b].x() - pinned.uv[c].x(),
                         pinned.uv[a].y() + pinned.uv[b].y() - pinned.uv[c].y());
  for(Tangled_grid* g : {&outside, &pinned}) {
    const std::size_t tangled = count_flipped(g->mesh, g->uv);
    ASSERT_GT(tangled, 0u);
    const std::vector<Point_2> start = g->targets();
    try {
      if(g == &outside) DO::untangle(g->mesh, g->uv, CGAL::parameters::vertex_is_constrained_map(center));
      else DO::untangle(g->mesh, g->uv, CGAL::parameters::vertex_is_constrained_map(fixed));
      ADD_FAILURE() << "no injective map exists, yet untangle() returned";
    } catch(const DO::Invalid_input& e) {
      const std::string what = e.what();
      const auto* unmovable = dynamic_cast<const DO::Unmovable_inverted_cell*>(&e);
      EXPECT_EQ(unmovable != nullptr, g != &outside) << what;
      if(unmovable) {
        EXPECT_EQ(unmovable->cell(), 100u);
      }
      if(g == &outside) {
        EXPECT_NE(what.find("untangling failed"), std::string::npos) << what;
        EXPECT_NE(what.find(" remain"), std::string::npos) << what;
      } else {
        // Named by its index in the whole map (the first attempt untangles a part, numbered its own way).
        EXPECT_NE(what.find("cell 100 is inverted or flat and all its vertices are constrained"), std::string::npos) << what;
      }
    }
    EXPECT_EQ(g->targets(), start);
  }
}

// CGAL's ARAP parameterizer returns OK with flipped triangles on real disks. Untangled with every
// vertex free and the guard, no triangle stays flipped, the border (which did not cross itself)
// still does not, and minimize_distortion(untangle_first) then optimizes from there.
TEST(Untangle, CgalArapOutputOfARealDiskIsUntangledWithAFreeBorder)
{
  Mesh3 mesh;
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  const std::size_t flipped = arap_lion_head(mesh, uv);
  ASSERT_GT(flipped, 10u);
  ASSERT_EQ(border_self_intersections(mesh, uv), 0u);
  auto none = mesh.add_property_map<Mesh3::Vertex_index, bool>("v:none", false).first;
  const std::vector<Point_2> start = targets_of(mesh, uv);

  const DO::Untangle_result r = DO::untangle(mesh, uv, DO::parameters::preserve_global_injectivity(true).vertex_is_constrained_map(none));
  EXPECT_GE(r.inverted_before, flipped);
  EXPECT_EQ(r.inverted_after, 0u);
  EXPECT_EQ(count_flipped(mesh, uv), 0u);
  EXPECT_EQ(border_self_intersections(mesh, uv), 0u);

  for(auto v : mesh.vertices()) uv[v] = start[v.idx()];
  const DO::Result m = CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
                                                 DO::parameters::untangle_first(true, DO::parameters::preserve_global_injectivity(true))
                                                   .vertex_is_constrained_map(none));
  EXPECT_EQ(m.inverted_start_cells, r.inverted_before);
  EXPECT_EQ(m.inverted_cells, 0u);
  EXPECT_EQ(count_flipped(mesh, uv), 0u);
  EXPECT_EQ(border_self_intersections(mesh, uv), 0u);
  EXPECT_NEAR(brute_force_energy(mesh, uv, "symmetric_dirichlet"), m.final_energy, 1e-9 * m.final_energy);
  EXPECT_LT(m.final_energy, 2.);   // a Tutte start reaches about 1.6 with a free border
}

// When the rounds end with triangles inverted (here: one round allowed, on CGAL's ARAP map of
// lion-head), a disk with at most three constrained vertices is untangled from its Tutte
// embedding: every triangle valid, the border uncrossed and (up to two constrained vertices, moved
// by a similarity) on a circle, the constrained vertices where they were. With four constrained
// vertices that does not apply: an error, the map unchanged.
TEST(Untangle, ADiskWhoseRoundsEndTangledStartsAgainFromItsTutteEmbedding)
{
  Mesh3 mesh;
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  const std::size_t flipped = arap_lion_head(mesh, uv);
  ASSERT_GT(flipped, 10u);
  const std::vector<Point_2> start = targets_of(mesh, uv);
  std::vector<Mesh3::Vertex_index> border;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h)) border.push_back(mesh.target(h));
  ASSERT_GT(border.size(), 30u);
  auto pinned = mesh.add_property_map<Mesh3::Vertex_index, bool>("v:pinned", false).first;

  for(std::size_t pins : {0, 2, 3, 4}) {
    for(auto v : mesh.vertices()) uv[v] = start[v.idx()], pinned[v] = false;
    for(std::size_t i = 0; i < pins; ++i) pinned[border[i * border.size() / 4]] = true;
    const auto untangle = [&] {
      return DO::untangle(mesh, uv, DO::parameters::preserve_global_injectivity(true)
                                      .vertex_is_constrained_map(pinned).number_of_iterations(1));
    };
    if(pins == 4) {
      EXPECT_THROW(untangle(), DO::Invalid_input);
      EXPECT_EQ(targets_of(mesh, uv), start);
      continue;
    }
    const DO::Untangle_result r = untangle();
    EXPECT_EQ(r.inverted_before, flipped) << pins << " pins";
    EXPECT_EQ(r.inverted_after, 0u);
    EXPECT_EQ(count_flipped(mesh, uv), 0u);
    EXPECT_EQ(border_self_intersections(mesh, uv), 0u);
    for(auto v : mesh.vertices()) {
      if(pinned[v]) {
        EXPECT_EQ(uv[v], start[v.idx()]);
      }
    }
    if(pins == 3) continue;   // an affine image of the circle
    // On a circle: every border vertex as far from the circumcentre of three of them.
    const Point_2 centre = CGAL::circumcenter(uv[border[0]], uv[border[border.size() / 3]], uv[border[2 * border.size() / 3]]);
    const double radius = std::sqrt(CGAL::squared_distance(centre, uv[border[0]]));
    EXPECT_GT(radius, 0.);
    for(auto v : border) EXPECT_NEAR(std::sqrt(CGAL::squared_distance(centre, uv[v])), radius, 1e-9 * radius);
  }
}

// A border fixed on a convex polygon whose inside the rounds do not untangle (one inner vertex of
// lion-head's Tutte map moved far outside the disk) is untangled
// from Tutte's embedding with the border where it is, on the circle and on a square.
TEST(Untangle, ABorderFixedOnAConvexPolygonIsUntangledFromTutteEmbeddingThere)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/lion-head.off", mesh));
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  for(const DO::Border_shape shape : {DO::Border_shape::CIRCLE, DO::Border_shape::SQUARE}) {
    DO::initial_parameterization(mesh, uv, DO::parameters::border_shape(shape));
    ASSERT_EQ(count_flipped(mesh, uv), 0u);
    const std::vector<Point_2> tutte = targets_of(mesh, uv);
    double radius = 0;
    for(auto v : mesh.vertices()) radius = std::max(radius, std::abs(uv[v].x()) + std::abs(uv[v].y()));
    Mesh3::Vertex_index inner;
    for(auto v : mesh.vertices())
      if(!mesh.is_border(v)) inner = v;
    uv[inner] = Point_2(uv[inner].x() + 100 * radius, uv[inner].y());
    const std::size_t tangled = count_flipped(mesh, uv);
    ASSERT_GT(tangled, 0u);
    const DO::Untangle_result r = DO::untangle(mesh, uv);
    EXPECT_EQ(r.inverted_before, tangled);
    EXPECT_EQ(r.inverted_after, 0u);
    EXPECT_EQ(count_flipped(mesh, uv), 0u);
    for(auto v : mesh.vertices())
      if(mesh.is_border(v)) {
        EXPECT_EQ(uv[v], tutte[v.idx()]);
      }
  }
}

// is_boundary_embedded() on lion-head's Tutte map, whose border is a circle: embedded; with one
// border vertex pulled across the disk, its border crosses itself. A vertex index map given by
// name (here the vertices numbered backwards) gives the same answers.
TEST(Untangle, BoundaryEmbeddingOfLionHeadsTutteMapWithAnyVertexIndices)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/lion-head.off", mesh));
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  DO::initial_parameterization(mesh, uv);
  const std::size_t n = mesh.number_of_vertices();
  const auto backwards = boost::make_function_property_map<Mesh3::Vertex_index>(
    [n](Mesh3::Vertex_index v) { return n - 1 - std::size_t(v.idx()); });
  EXPECT_TRUE(DO::is_boundary_embedded(mesh, uv));
  EXPECT_TRUE(DO::is_boundary_embedded(mesh, uv, CGAL::parameters::vertex_index_map(backwards)));
  // One border vertex taken through the centre of the circle to beyond its other side.
  Mesh3::Vertex_index border;
  double x = 0, y = 0, count = 0;
  for(auto v : mesh.vertices())
    if(mesh.is_border(v)) {
      border = v;
      x += uv[v].x();
      y += uv[v].y();
      ++count;
    }
  ASSERT_GT(count, 2);
  const Point_2 centre(x / count, y / count);
  uv[border] = centre + 2 * (centre - uv[border]);
  EXPECT_FALSE(DO::is_boundary_embedded(mesh, uv));
  EXPECT_FALSE(DO::is_boundary_embedded(mesh, uv, CGAL::parameters::vertex_index_map(backwards)));
}
