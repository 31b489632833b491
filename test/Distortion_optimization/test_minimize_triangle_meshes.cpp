// minimize_distortion on CGAL::Surface_mesh: known minimizers, monotone energy, no flips,
// constraints, and real parametrizations from libcgal-demo.

#include "test_meshes.h"

#include <CGAL/Distortion_optimization/global_injectivity.h>
#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/named_parameters.h>
#include <CGAL/Distortion_optimization/internal/triangle_mesh_adapter.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <optional>
#include <random>

using namespace test_meshes;

namespace {

const Map rigid = [](const Point_2& p) {
  const double c = std::cos(0.6), s = std::sin(0.6);
  return Point_2(c * p.x() - s * p.y() + 3, s * p.x() + c * p.y() - 1);
};
const Map similarity = [](const Point_2& p) {
  const double c = 2.5 * std::cos(-1.1), s = 2.5 * std::sin(-1.1);
  return Point_2(c * p.x() - s * p.y() + 1, s * p.x() + c * p.y() + 2);
};
const Map affine = [](const Point_2& p) { return Point_2(2 * p.x() + 0.7 * p.y() + 1, -0.4 * p.x() + 0.8 * p.y()); };

// Every schedule reaches the known minimizer; the harmonic start is off so that the local and
// global steps do the work (for the affine boundaries here it would be the minimizer at once).
template <class Measure>
void expect_recovers(const Map& f, const Measure& measure, DO::Local_solver solver = DO::Local_solver::GRADIENT_DESCENT)
{
  // Pure global steps stall at the kinks of C = max(s1, 1/s2) (a Laplacian-preconditioned step
  // moves every vertex along one smooth model); alternating with local sweeps gets past them.
  // So do the own Newton steps of K and the condition number, whose Hessians grow without bound
  // at their minimum, the kink (they are only taken when asked for: newton_model.h).
  // Both global solvers (Newton only differs for measures with a Hessian).
  const bool kinked = measure.name() == "conformal" || measure.name() == "condition";
  const bool global_too = measure.name() != "isometric";
  for(auto schedule : {DO::Schedule::LOCAL, DO::Schedule::GLOBAL, DO::Schedule::ALTERNATING})
    for(auto global : {DO::Global_solver::REWEIGHTED_LAPLACIAN, DO::Global_solver::PROJECTED_NEWTON}) {
      if(schedule == DO::Schedule::GLOBAL && !global_too) continue;
      if(schedule == DO::Schedule::GLOBAL && kinked && global == DO::Global_solver::PROJECTED_NEWTON) continue;
      if(schedule == DO::Schedule::LOCAL && global == DO::Global_solver::PROJECTED_NEWTON) continue;
      Noisy_map m(f, 0.02);
      ASSERT_GT(m.max_error(), 1e-3);
      std::vector<double> energies;
      auto visitor = [&](std::size_t, double e) { energies.push_back(e); return true; };
      const auto r = CGAL::minimize_distortion(m.mesh, m.uv, measure,
        DO::parameters::convergence_threshold(0., DO::parameters::local_solver(solver, DO::parameters::schedule(schedule,
          DO::parameters::use_harmonic_start(false, DO::parameters::global_solver(global))))).number_of_iterations(4000).visitor(visitor));
      EXPECT_LE(m.max_error(), 1e-5 * m.diameter()) << measure.name() << " schedule " << int(schedule) << " solver "
                                                    << int(global) << " after " << r.iterations << " iterations";
      EXPECT_EQ(r.inverted_cells, 0u);
      EXPECT_EQ(count_flipped(m.mesh, m.uv), 0u);
      for(std::size_t i = 1; i < energies.size(); ++i) ASSERT_LE(energies[i], energies[i - 1]) << measure.name();
    }
}

std::string data(const std::string& name) { return std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/" + name; }

} // namespace

TEST(MinimizeDistortion, IsometricMeasuresRecoverARigidMap)
{
  expect_recovers(rigid, DO::Isometric_dilatation());
  expect_recovers(rigid, DO::ARAP());
  expect_recovers(rigid, DO::Symmetric_dirichlet());
}

// V = max(det, 1/det) is minimized by every area-preserving map, and its kinks at det = 1 stop
// one-vertex-at-a-time descent at points that are optimal for each vertex alone: with the
// paper's local schedule the energy decreases and nothing flips, but the rigid map is not reached
// (a known limit of local sweeps). The default schedule reaches it.
TEST(MinimizeDistortion, VolumeDistortionLocalSweepsDecreaseDefaultScheduleRecovers)
{
  Noisy_map local(rigid, 0.02);
  const auto r = CGAL::minimize_distortion(local.mesh, local.uv, DO::Volume_distortion(),
    DO::parameters::schedule(DO::Schedule::LOCAL, DO::parameters::convergence_threshold(0.)).number_of_iterations(200));
  EXPECT_LT(r.final_energy - 1, 0.5 * (r.initial_energy - 1));
  EXPECT_EQ(count_flipped(local.mesh, local.uv), 0u);
  EXPECT_NEAR(r.final_energy, brute_force_energy(local.mesh, local.uv, "volume"), 1e-9);

  Noisy_map by_default(rigid, 0.02);
  CGAL::minimize_distortion(by_default.mesh, by_default.uv, DO::Volume_distortion(),
                            DO::parameters::convergence_threshold(0.).number_of_iterations(200));
  EXPECT_LE(by_default.max_error(), 1e-5 * by_default.diameter());
  EXPECT_EQ(count_flipped(by_default.mesh, by_default.uv), 0u);
}

TEST(MinimizeDistortion, ConformalMeasuresRecoverASimilarity)
{
  expect_recovers(similarity, DO::Conformal_dilatation());
  expect_recovers(similarity, DO::Condition_number());
  expect_recovers(similarity, DO::MIPS());
}

TEST(MinimizeDistortion, PolyconvexMeasuresRecoverAnAffineMap)
{
  expect_recovers(affine, DO::MIPS());
  expect_recovers(affine, DO::Dirichlet());
}

TEST(MinimizeDistortion, BfgsLocalSolverRecoversTheMinimizerToo)
{
  expect_recovers(rigid, DO::Symmetric_dirichlet(), DO::Local_solver::BFGS);
  expect_recovers(similarity, DO::MIPS(), DO::Local_solver::BFGS);
}

TEST(MinimizeDistortion, EnergyDecreasesWithoutFlipsFromAHardStart)
{
  // Large noise: many triangles nearly flat, none inverted.
  Noisy_map m(rigid, 0.022, 5);
  ASSERT_EQ(count_flipped(m.mesh, m.uv), 0u);
  const double before = brute_force_energy(m.mesh, m.uv, "symmetric_dirichlet");
  std::vector<double> energies;
  const auto r = CGAL::minimize_distortion(m.mesh, m.uv, DO::Symmetric_dirichlet(),
    CGAL::parameters::number_of_iterations(30).visitor([&](std::size_t, double e) { energies.push_back(e); return true; }));
  EXPECT_NEAR(r.initial_energy, before, 1e-9 * before);
  for(std::size_t i = 1; i < energies.size(); ++i) EXPECT_LE(energies[i], energies[i - 1]);
  EXPECT_LT(r.final_energy - 1, 0.01 * (r.initial_energy - 1));   // symmetric Dirichlet is >= 1
  EXPECT_EQ(count_flipped(m.mesh, m.uv), 0u);
  // The reported energy is the independently recomputed area-weighted mean.
  EXPECT_NEAR(r.final_energy, brute_force_energy(m.mesh, m.uv, "symmetric_dirichlet"), 1e-9 * r.final_energy);
}

TEST(MinimizeDistortion, ConstrainedVerticesAreUnchangedBitForBit)
{
  Noisy_map m(affine, 0.02);
  auto fixed = m.mesh.add_property_map<Mesh2::Vertex_index, bool>("v:fixed", false).first;
  std::vector<std::pair<Mesh2::Vertex_index, Point_2>> kept;
  int i = 0;
  for(auto v : m.mesh.vertices())
    if(m.mesh.is_border(v) || (i++ % 7 == 0)) {
      fixed[v] = true;
      kept.emplace_back(v, m.uv[v]);
    }
  const auto r = CGAL::minimize_distortion(m.mesh, m.uv, DO::Conformal_dilatation(),
                                           CGAL::parameters::vertex_is_constrained_map(fixed));
  EXPECT_LT(r.final_energy, r.initial_energy);
  for(const auto& kv : kept) {
    EXPECT_EQ(m.uv[kv.first].x(), kv.second.x());
    EXPECT_EQ(m.uv[kv.first].y(), kv.second.y());
  }
}

TEST(MinimizeDistortion, HugeAndTinyCoordinatesGiveTheSameMap)
{
  // Products of coordinates overflow past about 1e154 in 2D (and underflow below 1e-154): the
  // adapters scale by a power of two, so a uniformly scaled problem has the scaled solution.
  Noisy_map reference(affine, 0.02);
  const auto r = CGAL::minimize_distortion(reference.mesh, reference.uv, DO::Symmetric_dirichlet());
  for(double factor : {1e155, 1e-155}) {
    Noisy_map m(affine, 0.02);
    for(auto v : m.mesh.vertices()) {
      m.mesh.point(v) = Point_2(factor * m.mesh.point(v).x(), factor * m.mesh.point(v).y());
      m.uv[v] = Point_2(factor * m.uv[v].x(), factor * m.uv[v].y());
    }
    const auto s = CGAL::compute_distortion(m.mesh, m.uv, DO::Symmetric_dirichlet());
    EXPECT_EQ(s.inverted_cells, 0u) << factor;
    EXPECT_NEAR(s.mean_volume, r.initial_energy, 1e-9 * r.initial_energy) << factor;
    const auto q = CGAL::minimize_distortion(m.mesh, m.uv, DO::Symmetric_dirichlet());
    EXPECT_EQ(q.inverted_cells, 0u) << factor;
    EXPECT_NEAR(q.final_energy, r.final_energy, 1e-6 * r.final_energy) << factor;
    for(auto v : m.mesh.vertices()) {
      EXPECT_NEAR(m.uv[v].x() / factor, reference.uv[v].x(), 1e-4) << factor;
      EXPECT_NEAR(m.uv[v].y() / factor, reference.uv[v].y(), 1e-4) << factor;
    }
  }
}

TEST(MinimizeDistortion, VisitorStopsTheRunAtAConsistentMap)
{
  Noisy_map m(affine, 0.02);
  double last = 0;
  const auto r = CGAL::minimize_distortion(m.mesh, m.uv, DO::ARAP(), DO::parameters::schedule(DO::Schedule::LOCAL,
    CGAL::parameters::visitor([&](std::size_t it, double e) { last = e; return it < 3; })));
  EXPECT_TRUE(r.stopped_by_visitor);
  EXPECT_EQ(r.iterations, 3u);
  EXPECT_EQ(r.final_energy, last);
  EXPECT_NEAR(brute_force_energy(m.mesh, m.uv, "arap"), last, 1e-9 * last);
}

TEST(MinimizeDistortion, HarmonicStartThatWouldInvertIsShortened)
{
  // A grid whose border is bent into a non-convex C shape: the harmonic map of that border
  // inverts triangles near the inner corner, so the start must stop short of it.
  Noisy_map m([](const Point_2& p) {
    const double angle = 4.5 * (p.x() - 0.5), radius = 1.6 - 0.6 * p.y();
    return Point_2(radius * std::cos(angle), radius * std::sin(angle));
  }, 0.);
  for(auto v : m.mesh.vertices())   // the interior starts at the bend of its straight grid, valid
    if(!m.mesh.is_border(v)) m.uv[v] = m.exact[v];
  ASSERT_EQ(count_flipped(m.mesh, m.uv), 0u);
  // The harmonic map of that border does invert triangles (checked with the package's own solve).
  auto adapter = DO::internal::make_triangle_mesh_adapter(m.mesh, m.uv, CGAL::parameters::default_values());
  const auto problem = DO::internal::make_problem(adapter, CGAL::parameters::default_values());
  const DO::internal::Workers workers;
  DO::internal::Laplacian_system<2> system(problem, workers);
  std::vector<DO::internal::Vector<2>> harmonic;
  ASSERT_TRUE(system.harmonic_targets(problem.map.target, harmonic));
  std::size_t harmonic_flips = 0;
  for(const auto& cell : problem.map.cells) {
    auto q = [&](int i) { return Point_2(harmonic[cell[i]][0], harmonic[cell[i]][1]); };
    if(CGAL::orientation(q(0), q(1), q(2)) != CGAL::LEFT_TURN) ++harmonic_flips;
  }
  ASSERT_GT(harmonic_flips, 0u);
  const auto r = CGAL::minimize_distortion(m.mesh, m.uv, DO::Symmetric_dirichlet(), CGAL::parameters::number_of_iterations(3));
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_EQ(count_flipped(m.mesh, m.uv), 0u);
  EXPECT_LT(r.final_energy, r.initial_energy);
}

TEST(MinimizeDistortion, GreedyAndSortedOrdersBothConverge)
{
  for(auto order : {DO::Vertex_order::GREEDY, DO::Vertex_order::SORTED_PER_SWEEP}) {
    Noisy_map m(similarity, 0.02);
    const auto r = CGAL::minimize_distortion(m.mesh, m.uv, DO::MIPS(), DO::parameters::vertex_order(order));
    EXPECT_TRUE(r.converged);
    EXPECT_LT(r.final_energy - 2., 1e-3 * (r.initial_energy - 2.));
  }
}

TEST(MinimizeDistortion, InvertedStartIsRejectedForANormalizedMeasure)
{
  Noisy_map m(rigid, 0.);
  Mesh2::Vertex_index v(5 * 17 + 5);
  m.uv[v] = Point_2(m.uv[v].x() + 0.2, m.uv[v].y() + 0.2);
  ASSERT_GT(count_flipped(m.mesh, m.uv), 0u);
  const Point_2 before = m.uv[v];
  try {
    CGAL::minimize_distortion(m.mesh, m.uv, DO::Symmetric_dirichlet());
    ADD_FAILURE() << "an inverted start was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("cell"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("inverted"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m.uv[v], before);   // nothing written
  // A measure that is not a number on some cell: the message blames it, not an overflow.
  const auto nan_when_stretched = DO::make_measure(
    [](const auto& s) { return s[0] > 1.05 ? std::numeric_limits<double>::quiet_NaN() : (s.array() - 1.).square().sum(); },
    [](const auto& s) { return (2. * (s.array() - 1.)).matrix().eval(); }, "nan_when_stretched", false, false);
  try {
    CGAL::minimize_distortion(m.mesh, m.uv, nan_when_stretched);
    ADD_FAILURE() << "a start where the measure is NaN was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("is not a number (the measure 'nan_when_stretched' gives NaN"), std::string::npos) << e.what();
  }
  EXPECT_EQ(m.uv[v], before);
  // ARAP is finite there: the run goes on, and flips nothing that was not flipped.
  const std::size_t flipped = count_flipped(m.mesh, m.uv);
  const auto r = CGAL::minimize_distortion(m.mesh, m.uv, DO::ARAP());
  EXPECT_LE(r.inverted_cells, flipped);
  EXPECT_LE(count_flipped(m.mesh, m.uv), flipped);
}

// Sources the exact predicates accept but no run can: a disk beside a closed surface (one border,
// Euler characteristic 1: a disk by its counts), whose closed piece no map into the plane keeps
// oriented; a needle whose rounded edges are collinear. Each refused with its reason.
TEST(MinimizeDistortion, ADiskBesideAClosedSurfaceAndANeedleAreRefusedAsSuch)
{
  Mesh3 mesh;
  std::vector<Mesh3::Vertex_index> v;
  for(const Point_3& p : {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(5, 0, 0), Point_3(6, 0, 0),
                          Point_3(5, 1, 0), Point_3(5, 0, 1)})
    v.push_back(mesh.add_vertex(p));
  mesh.add_face(v[0], v[1], v[2]);
  for(const std::array<int, 3>& f : {std::array<int, 3>{3, 5, 4}, {3, 4, 6}, {4, 5, 6}, {5, 3, 6}})
    ASSERT_NE(mesh.add_face(v[f[0]], v[f[1]], v[f[2]]), Mesh3::null_face());
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  const auto message = [](const auto& run) {
    try {
      run();
    } catch(const DO::Invalid_input& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { DO::initial_parameterization(mesh, uv); }).find("piece 2 of 2: the mesh has no border"), std::string::npos);

  // Its closed piece flattened (vertex 6 inside the image of the others): some of its triangles
  // are inverted, and must be.
  const std::array<Point_2, 7> flat = {Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), Point_2(5, 0), Point_2(6, 0),
                                       Point_2(5, 1), Point_2(5.3, 0.3)};
  for(int i = 0; i < 7; ++i) uv[v[i]] = flat[i];
  ASSERT_GT(count_flipped(mesh, uv), 0u);
  const std::string closed = "the piece of the mesh with cell 1 has no border (a closed surface)";
  EXPECT_NE(message([&] { CGAL::minimize_distortion(mesh, uv, DO::Conformal_dilatation()); }).find(closed), std::string::npos);
  auto none = mesh.add_property_map<Mesh3::Vertex_index, bool>("v:none", false).first;
  for(const bool fixed : {true, false}) {
    const std::string what = message([&] {
      if(fixed) CGAL::minimize_distortion(mesh, uv, DO::Conformal_dilatation(), DO::parameters::untangle_first(true));
      else CGAL::minimize_distortion(mesh, uv, DO::Conformal_dilatation(),
                                     DO::parameters::untangle_first(true, CGAL::parameters::vertex_is_constrained_map(none)));
    });
    EXPECT_EQ(what.find("untangling cannot succeed: " + closed), 0u) << what;
  }
  for(int i = 0; i < 7; ++i) EXPECT_EQ(uv[v[i]], flat[i]);   // nothing written
  // Measured, it is only what it is: ARAP is finite on inverted cells.
  EXPECT_GT(CGAL::compute_distortion(mesh, uv, DO::ARAP()).inverted_cells, 0u);

  // A torus with a triangle removed (genus 1, one border) flattened by projection, its border free
  // and kept from crossing: no injective map exists, and untangling says so at once.
  Mesh3 torus;
  std::vector<Mesh3::Vertex_index> w;
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) {
      const double phi = 2 * M_PI * i / 4 + 0.2, theta = 2 * M_PI * j / 4 + 0.3;
      w.push_back(torus.add_vertex(Point_3((3 + std::cos(theta)) * std::cos(phi), (3 + std::cos(theta)) * std::sin(phi), std::sin(theta))));
    }
  const auto at = [&](int i, int j) { return w[4 * (i % 4) + j % 4]; };
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) {
      if(i + j > 0) {   // the removed triangle: the border
        ASSERT_NE(torus.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1)), Mesh3::null_face());
      }
      ASSERT_NE(torus.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1)), Mesh3::null_face());
    }
  auto torus_uv = torus.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  for(auto u : torus.vertices()) torus_uv[u] = Point_2(torus.point(u).x(), torus.point(u).y());
  auto all_free = torus.add_property_map<Mesh3::Vertex_index, bool>("v:none", false).first;
  const std::string handles = message([&] {
    CGAL::minimize_distortion(torus, torus_uv, DO::Conformal_dilatation(), DO::parameters::untangle_first(true,
      DO::parameters::preserve_global_injectivity(true, CGAL::parameters::vertex_is_constrained_map(all_free))));
  });
  EXPECT_EQ(handles.find("untangling with global injectivity cannot succeed: the piece of the mesh with cell 0 has 1 handle "
                         "(genus 1)"), 0u) << handles;

  // The needle: exactly, its vertices are not collinear (the cross product of the decimals' doubles
  // is about 5e-17); in doubles, its edges' cross product is zero.
  Mesh3 needle;
  const auto a = needle.add_vertex(Point_3(0.154, -0.207, 0.953)), b = needle.add_vertex(Point_3(-0.907, 0.717, -0.421)),
             c = needle.add_vertex(Point_3(-0.3765, 0.255, 0.266));
  needle.add_face(a, b, c);
  ASSERT_FALSE(CGAL::collinear(needle.point(a), needle.point(b), needle.point(c)));
  auto needle_uv = needle.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  needle_uv[a] = Point_2(0, 0), needle_uv[b] = Point_2(1, 0), needle_uv[c] = Point_2(0, 1);
  EXPECT_EQ(message([&] { CGAL::minimize_distortion(needle, needle_uv, DO::ARAP()); }),
            "source face 0 is degenerate in double precision (its vertices are not exactly collinear, but so nearly "
            "that its rounded edges are)");
}

// The Dirichlet energy (and a sum or product with it) decreases as the map shrinks: with fewer than
// three vertices constrained its minimum is the map collapsed onto them, which is refused before
// anything runs; three hold the size.
TEST(MinimizeDistortion, AMeasureThatShrinksTheMapNeedsThreeConstrainedVertices)
{
  Noisy_map m(affine, 0.02);
  std::vector<Point_2> before;
  for(auto v : m.mesh.vertices()) before.push_back(m.uv[v]);
  auto pinned = m.mesh.add_property_map<Mesh2::Vertex_index, bool>("v:pinned", false).first;
  const auto dirichlet_sum = DO::Weighted_sum(1., DO::Conformal_dilatation(), 0.1, DO::Dirichlet());
  for(std::size_t pins = 0; pins < 3; ++pins) {
    if(pins > 0) pinned[Mesh2::Vertex_index(static_cast<Mesh2::size_type>(40 * pins))] = true;
    for(bool sum : {false, true}) {
      try {
        const auto np = CGAL::parameters::vertex_is_constrained_map(pinned);
        sum ? CGAL::minimize_distortion(m.mesh, m.uv, dirichlet_sum, np) : CGAL::minimize_distortion(m.mesh, m.uv, DO::Dirichlet(), np);
        ADD_FAILURE() << pins << " pins: the collapse was run";
      } catch(const DO::Invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("shrinks"), std::string::npos) << e.what();
      }
      std::size_t i = 0;
      for(auto v : m.mesh.vertices()) EXPECT_EQ(m.uv[v], before[i++]);   // nothing written
    }
  }
  pinned[Mesh2::Vertex_index(150)] = true;
  const auto r = CGAL::minimize_distortion(m.mesh, m.uv, DO::Dirichlet(), CGAL::parameters::vertex_is_constrained_map(pinned));
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_LE(r.final_energy, r.initial_energy);
  // ARAP and the isometric measures hold the size themselves: nothing constrained is fine.
  pinned[Mesh2::Vertex_index(40)] = pinned[Mesh2::Vertex_index(80)] = pinned[Mesh2::Vertex_index(150)] = false;
  EXPECT_NO_THROW(CGAL::minimize_distortion(m.mesh, m.uv, DO::ARAP(), CGAL::parameters::vertex_is_constrained_map(pinned)));
}

// Per piece: a second grid beside the first, none of its vertices constrained, would collapse alone.
TEST(MinimizeDistortion, AMeasureThatShrinksTheMapNeedsThreeConstrainedVerticesPerPiece)
{
  Mesh2 mesh = planar_grid(4);
  ASSERT_TRUE(mesh.join(grid<Mesh2>(4, [](double x, double y) { return Point_2(x + 2, y); })));
  auto uv = make_target(mesh, [](const Point_2& p) { return Point_2(1.1 * p.x(), p.y()); });
  auto pinned = mesh.add_property_map<Mesh2::Vertex_index, bool>("v:pinned", false).first;
  for(unsigned v : {0u, 4u, 24u}) pinned[Mesh2::Vertex_index(v)] = true;
  const std::vector<Point_2> before = targets_of(mesh, uv);
  try {
    CGAL::minimize_distortion(mesh, uv, DO::Dirichlet(), CGAL::parameters::vertex_is_constrained_map(pinned));
    ADD_FAILURE() << "the second piece's collapse was run";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("shrinks, and in the piece of the mesh with cell 32 no vertex is constrained: its "
                                         "minimum collapses that piece"), std::string::npos) << e.what();
  }
  EXPECT_EQ(targets_of(mesh, uv), before);
  // Three on one line hold nothing across it: the piece would collapse onto that line.
  for(unsigned v : {25u, 27u, 29u}) pinned[Mesh2::Vertex_index(v)] = true;
  try {
    CGAL::minimize_distortion(mesh, uv, DO::Dirichlet(), CGAL::parameters::vertex_is_constrained_map(pinned));
    ADD_FAILURE() << "the second piece's collapse onto a line was run";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("in the piece of the mesh with cell 32 the 3 constrained vertices lie on one line: its "
                                         "minimum collapses that piece (every cell flat); constrain at least 3 vertices not on "
                                         "one line in each piece"), std::string::npos) << e.what();
  }
  EXPECT_EQ(targets_of(mesh, uv), before);
  pinned[Mesh2::Vertex_index(49)] = true;
  const auto r = CGAL::minimize_distortion(mesh, uv, DO::Dirichlet(), CGAL::parameters::vertex_is_constrained_map(pinned));
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_LT(r.final_energy, r.initial_energy);
}

TEST(MinimizeDistortion, ImprovesTutteParametrizationsOfRealDisks)
{
  for(const char* name : {"nefertiti.off", "mushroom.off"}) {
    Mesh3 mesh;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data(name), mesh)) << "missing " << data(name)
      << " (installed by scripts/install_dependencies.sh from libcgal-demo)";
    auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
    DO::initial_parameterization(mesh, uv);
    ASSERT_EQ(count_flipped(mesh, uv), 0u) << name;
    // With a square border too: CGAL's runs clockwise, and every face came out mirrored.
    auto square = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:square").first;
    DO::initial_parameterization(mesh, square, DO::parameters::border_shape(DO::Border_shape::SQUARE));
    EXPECT_EQ(count_flipped(mesh, square), 0u) << name;
    DO::initial_parameterization(mesh, square, DO::parameters::initial_map(DO::Initial_map::DISCRETE_CONFORMAL,
                                                                         DO::parameters::border_shape(DO::Border_shape::SQUARE)));
    EXPECT_LT(count_flipped(mesh, square), mesh.number_of_faces() / 10) << name;
    auto tutte = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:tutte").first;
    for(auto v : mesh.vertices()) tutte[v] = uv[v];

    auto run = [&](const auto& measure, const std::string& label) {
      for(auto v : mesh.vertices()) uv[v] = tutte[v];
      const double start = brute_force_energy(mesh, uv, label);
      const auto r = CGAL::minimize_distortion(mesh, uv, measure, CGAL::parameters::number_of_iterations(20));
      EXPECT_NEAR(r.initial_energy, start, 1e-9 * start) << name << " " << label;
      EXPECT_LT(brute_force_energy(mesh, uv, label), start) << name << " " << label;
      EXPECT_EQ(r.inverted_cells, 0u) << name << " " << label;
      EXPECT_EQ(count_flipped(mesh, uv), 0u) << name << " " << label;
    };
    run(DO::Conformal_dilatation(), "conformal");
    run(DO::Isometric_dilatation(), "isometric");
    run(DO::Symmetric_dirichlet(), "symmetric_dirichlet");
    run(DO::Product<DO::Conformal_dilatation, DO::Isometric_dilatation>(), "conformal*isometric");
  }
}

// The maxima K, the condition number, C and V have Hessians, but by default keep the reweighted
// Laplacian's steps (their kinks make poor Newton models: newton_model.h); asked for, their own
// projected Newton steps are taken, descend and never flip a triangle. Products of measures take
// their own Newton steps by default.
TEST(MinimizeDistortion, MaximaTakeTheirOwnNewtonStepsWhenAskedProductsByDefault)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("mushroom.off"), mesh)) << "missing " << data("mushroom.off");
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  DO::initial_parameterization(mesh, uv);
  std::vector<Point_2> tutte;
  for(auto v : mesh.vertices()) tutte.push_back(uv[v]);
  // The map after 15 iterations from Tutte's, with the solver given or the default.
  const auto run = [&](const auto& measure, std::optional<DO::Global_solver> solver) {
    std::size_t i = 0;
    for(auto v : mesh.vertices()) uv[v] = tutte[i++];
    std::vector<double> energies;
    const auto visitor = [&](std::size_t, double e) { energies.push_back(e); return true; };
    const auto r = CGAL::minimize_distortion(mesh, uv, measure,
      DO::parameters::global_solver(solver, CGAL::parameters::number_of_iterations(15)).visitor(visitor));
    for(std::size_t k = 1; k < energies.size(); ++k) EXPECT_LE(energies[k], energies[k - 1]) << measure.name();
    EXPECT_LT(r.final_energy, r.initial_energy) << measure.name();
    EXPECT_EQ(count_flipped(mesh, uv), 0u) << measure.name();
    std::vector<Point_2> result;
    for(auto v : mesh.vertices()) result.push_back(uv[v]);
    return result;
  };
  const auto maxima = std::make_tuple(DO::Conformal_dilatation(), DO::Condition_number(), DO::Isometric_dilatation(),
                                      DO::Volume_distortion());
  std::apply([&](const auto&... m) {
    ([&] {
      const auto laplacian = run(m, DO::Global_solver::REWEIGHTED_LAPLACIAN);
      EXPECT_TRUE(run(m, std::nullopt) == laplacian) << m.name();
      EXPECT_FALSE(run(m, DO::Global_solver::PROJECTED_NEWTON) == laplacian) << m.name();
    }(), ...);
  }, maxima);
  const DO::Product<DO::Conformal_dilatation, DO::Isometric_dilatation> product;
  const auto newton = run(product, DO::Global_solver::PROJECTED_NEWTON);
  EXPECT_TRUE(run(product, std::nullopt) == newton);
  EXPECT_FALSE(run(product, DO::Global_solver::REWEIGHTED_LAPLACIAN) == newton);
}


// A disk with holes (CGAL's lion.off: one piece of genus 0, 5 borders): Tutte's start fills each
// hole for its solve, so that no triangle flips and the borders do not cross (without the fill,
// triangles along the holes flip); with the outer
// border fixed and the holes free under the guard, the optimization opens the holes and keeps the
// map one-to-one. A surface with a handle and a border is refused, and so are holes for the
// discrete conformal start.
TEST(MinimizeDistortion, DisksWithHolesGetAOneToOneStartAndStayOneToOne)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("lion.off"), mesh)) << "missing " << data("lion.off");
  std::vector<Mesh3::Halfedge_index> borders;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(borders));
  ASSERT_GT(borders.size(), 2u);
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  DO::initial_parameterization(mesh, uv);
  EXPECT_EQ(count_flipped(mesh, uv), 0u);
  EXPECT_TRUE(DO::is_boundary_embedded(mesh, uv));
  auto fixed = mesh.add_property_map<Mesh3::Vertex_index, bool>("v:fixed", false).first;
  for(auto h : CGAL::halfedges_around_face(CGAL::Polygon_mesh_processing::longest_border(mesh).first, mesh))
    fixed[mesh.target(h)] = true;
  const DO::Result r = CGAL::minimize_distortion(
    mesh, uv, DO::Symmetric_dirichlet(),
    DO::parameters::preserve_global_injectivity(true).vertex_is_constrained_map(fixed).number_of_iterations(10));
  EXPECT_LT(r.final_energy, 0.75 * r.initial_energy);
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_EQ(count_flipped(mesh, uv), 0u);
  EXPECT_TRUE(DO::is_boundary_embedded(mesh, uv));
  EXPECT_THROW(DO::initial_parameterization(mesh, uv, DO::parameters::initial_map(DO::Initial_map::DISCRETE_CONFORMAL)),
               DO::Invalid_input);

  // Two pieces, the disk with holes and a disk (nefertiti.off, moved onto it): each its own start,
  // side by side, so that no triangle flips and no border crosses another.
  Mesh3 two = mesh, disk;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("nefertiti.off"), disk));
  CGAL::copy_face_graph(disk, two);
  auto two_uv = two.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv2").first;
  DO::initial_parameterization(two, two_uv);
  EXPECT_EQ(count_flipped(two, two_uv), 0u);
  EXPECT_TRUE(DO::is_boundary_embedded(two, two_uv));

  // A torus with a square hole: genus 1, one border.
  Mesh3 torus;
  const int m = 8, k = 6;
  std::vector<Mesh3::Vertex_index> v;
  for(int i = 0; i < m; ++i)
    for(int j = 0; j < k; ++j) {
      const double a = 2 * M_PI * i / m, b = 2 * M_PI * j / k;
      v.push_back(torus.add_vertex(Point_3((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b))));
    }
  for(int i = 0; i < m; ++i)
    for(int j = 0; j < k; ++j) {
      if(i == 0 && j == 0) continue;   // the hole
      const auto p = v[i * k + j], q = v[((i + 1) % m) * k + j], r2 = v[((i + 1) % m) * k + (j + 1) % k], s2 = v[i * k + (j + 1) % k];
      torus.add_face(p, q, r2);
      torus.add_face(p, r2, s2);
    }
  auto torus_uv = torus.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  try {
    DO::initial_parameterization(torus, torus_uv);
    ADD_FAILURE() << "a torus with a hole was parameterized";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("the mesh has 1 handle"), std::string::npos) << e.what();
  }
}

// Projected Newton steps and the reweighted Laplacian's reach the same minimum of symmetric
// Dirichlet (border fixed, and free with the guard) on a real disk.
TEST(MinimizeDistortion, NewtonAndLaplacianGlobalStepsReachTheSameMinimum)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("nefertiti.off"), mesh));
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  DO::initial_parameterization(mesh, uv);
  auto tutte = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:tutte").first;
  for(auto v : mesh.vertices()) tutte[v] = uv[v];
  auto none = mesh.add_property_map<Mesh3::Vertex_index, bool>("v:none", false).first;
  for(const bool fixed : {true, false}) {
    std::array<DO::Result, 2> results;
    for(int k = 0; k < 2; ++k) {
      for(auto v : mesh.vertices()) uv[v] = tutte[v];
      const auto np = DO::parameters::global_solver(k == 0 ? DO::Global_solver::REWEIGHTED_LAPLACIAN : DO::Global_solver::PROJECTED_NEWTON,
        DO::parameters::convergence_threshold(1e-9)).number_of_iterations(1000);
      results[k] = fixed ? CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(), np)
                         : CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
                             DO::parameters::preserve_global_injectivity(true, np.vertex_is_constrained_map(none)));
      EXPECT_EQ(count_flipped(mesh, uv), 0u) << fixed << k;
      EXPECT_NEAR(brute_force_energy(mesh, uv, "symmetric_dirichlet"), results[k].final_energy, 1e-9 * results[k].final_energy);
      if(!fixed) { EXPECT_EQ(border_self_intersections(mesh, uv), 0u) << k; }
    }
    EXPECT_NEAR(results[1].final_energy, results[0].final_energy, 1e-6 * results[0].final_energy) << fixed;
  }
}

// Writes the Tutte map of the disk `mesh` (circle border) into `uv` and returns it.
template <class UV>
std::vector<Point_2> tutte_start(const Mesh3& mesh, UV uv)
{
  DO::initial_parameterization(mesh, uv);
  return targets_of(mesh, uv);
}

// A border sliding on a circle (the Tutte start's): Newton's steps restricted to the tangent
// lines reach the minimum the Laplacian's steps reach, in far fewer iterations, with the border
// on the circle and no triangle flipped.
TEST(MinimizeDistortion, NewtonStepsSlideTheBorderOnACircle)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("nefertiti.off"), mesh));
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  const std::vector<Point_2> tutte = tutte_start(mesh, uv);
  std::vector<Mesh3::Vertex_index> border;
  for(auto v : mesh.vertices())
    if(mesh.is_border(v)) border.push_back(v);
  ASSERT_GE(border.size(), 3u);
  // The circle through three border vertices far apart: the one the start's border lies on.
  const Point_2 center = CGAL::circumcenter(uv[border[0]], uv[border[border.size() / 3]], uv[border[2 * border.size() / 3]]);
  const double radius = std::sqrt(CGAL::squared_distance(center, uv[border[0]]));
  const DO::Sphere_surface circle({center.x(), center.y(), 0.}, radius);
  std::array<DO::Result, 2> results;
  for(int k = 0; k < 2; ++k) {
    for(auto v : mesh.vertices()) uv[v] = tutte[v.idx()];
    results[k] = CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
      DO::parameters::global_solver(k == 0 ? DO::Global_solver::REWEIGHTED_LAPLACIAN : DO::Global_solver::PROJECTED_NEWTON,
        DO::parameters::sliding_boundary(circle, DO::parameters::convergence_threshold(1e-9))).number_of_iterations(1000));
    EXPECT_EQ(count_flipped(mesh, uv), 0u) << k;
    EXPECT_NEAR(brute_force_energy(mesh, uv, "symmetric_dirichlet"), results[k].final_energy, 1e-9 * results[k].final_energy);
    double farthest = 0;
    for(auto v : border) farthest = std::max(farthest, std::abs(std::sqrt(CGAL::squared_distance(center, uv[v])) - radius));
    EXPECT_LT(farthest, 1e-12 * radius) << k;
  }
  EXPECT_LT(results[1].final_energy, results[1].initial_energy);
  EXPECT_NEAR(results[1].final_energy, results[0].final_energy, 1e-6 * results[0].final_energy);
  EXPECT_LT(2 * results[1].iterations, results[0].iterations);
}

// The default schedule: Newton's global steps alone for a measure with a Hessian (the same map as
// Schedule::GLOBAL), alternating with sweeps otherwise (as Schedule::ALTERNATING); and when a
// step gains too little to go on (here, less than 99% of the excess), a sweep follows it in the
// same iteration: the map of a GLOBAL iteration, then of a LOCAL one.
TEST(MinimizeDistortion, DefaultScheduleIsNewtonStepsAloneWithASweepWhereTheyStall)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("nefertiti.off"), mesh));
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  const std::vector<Point_2> tutte = tutte_start(mesh, uv);
  const auto run = [&](const auto& measure, std::optional<DO::Schedule> schedule, double threshold, std::size_t iterations) {
    const DO::Result r = CGAL::minimize_distortion(mesh, uv, measure,
      DO::parameters::schedule(schedule, DO::parameters::convergence_threshold(threshold)).number_of_iterations(iterations));
    return std::make_pair(targets_of(mesh, uv), r);
  };
  const auto restart = [&] { for(auto v : mesh.vertices()) uv[v] = tutte[v.idx()]; };

  restart();
  const auto by_default = run(DO::Symmetric_dirichlet(), std::nullopt, 1e-4, 3);
  restart();
  EXPECT_EQ(run(DO::Symmetric_dirichlet(), DO::Schedule::GLOBAL, 1e-4, 3).first, by_default.first);
  restart();
  EXPECT_NE(run(DO::Symmetric_dirichlet(), DO::Schedule::ALTERNATING, 1e-4, 3).first, by_default.first);
  restart();
  const auto conformal = run(DO::Conformal_dilatation(), std::nullopt, 1e-4, 3);
  restart();
  EXPECT_EQ(run(DO::Conformal_dilatation(), DO::Schedule::ALTERNATING, 1e-4, 3).first, conformal.first);

  restart();
  const auto stalled = run(DO::Symmetric_dirichlet(), std::nullopt, 0.99, 1);
  EXPECT_EQ(stalled.second.iterations, 1u);
  restart();
  const auto step = run(DO::Symmetric_dirichlet(), DO::Schedule::GLOBAL, 0.99, 1);
  EXPECT_LT(stalled.second.final_energy, step.second.final_energy);
  const auto then_sweep = run(DO::Symmetric_dirichlet(), DO::Schedule::LOCAL, 0.99, 1);
  EXPECT_EQ(then_sweep.first, stalled.first);
}

// Where cells about to flatten cut Newton's steps short (mannequin-devil's Tutte map, border
// fixed), the default schedule adds a sweep after each such step: in 10 iterations it gets below
// the energy libigl's SLIM reaches in 20 (1.9166, issue 18's reference), which Newton's steps
// alone do not.
TEST(MinimizeDistortion, DefaultScheduleSweepsWhereNewtonStepsAreCutShort)
{
  Mesh3 mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("mannequin-devil.off"), mesh));
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  const std::vector<Point_2> tutte = tutte_start(mesh, uv);
  std::array<DO::Result, 2> results;
  for(int k = 0; k < 2; ++k) {
    for(auto v : mesh.vertices()) uv[v] = tutte[v.idx()];
    const std::optional<DO::Schedule> schedule = k == 0 ? std::optional<DO::Schedule>() : DO::Schedule::GLOBAL;
    results[k] = CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
      DO::parameters::schedule(schedule, DO::parameters::convergence_threshold(1e-9)).number_of_iterations(10));
    EXPECT_EQ(count_flipped(mesh, uv), 0u) << k;
  }
  EXPECT_EQ(results[0].iterations, 10u);
  EXPECT_LT(results[0].final_energy, 1.9166);
  EXPECT_GT(results[1].final_energy, 1.9166);
}

// A helical ramp of 1.2 turns (r in [1, 2], z = 0.3 theta): a disk whose flattening wants an
// annular sector of more than 360 degrees, so an unguarded free-boundary run overlaps its ends.
static Mesh3 helical_ramp(double turns)
{
  return grid<Mesh3>(6, 120, [turns](double u, double w) {
    const double r = 1 + u, t = 2 * CGAL_PI * turns * w;
    return Point_3(r * std::cos(t), r * std::sin(t), 0.3 * t);
  });
}

TEST(MinimizeDistortion, FreeBoundaryParametrizationStaysGloballyInjective)
{
  std::vector<Mesh3> meshes(2);
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("mushroom.off"), meshes[0]));
  meshes[1] = helical_ramp(1.2);
  for(std::size_t k = 0; k < meshes.size(); ++k) {
    Mesh3* mesh = &meshes[k];
    auto uv = mesh->add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
    DO::initial_parameterization(*mesh, uv);
    ASSERT_EQ(border_self_intersections(*mesh, uv), 0u);
    auto none = mesh->add_property_map<Mesh3::Vertex_index, bool>("v:none", false).first;
    auto tutte = mesh->add_property_map<Mesh3::Vertex_index, Point_2>("v:tutte").first;
    for(auto v : mesh->vertices()) tutte[v] = uv[v];
    for(int threads : {1, 2}) {
      for(auto v : mesh->vertices()) uv[v] = tutte[v];
      const auto r = CGAL::minimize_distortion(*mesh, uv, DO::Symmetric_dirichlet(),
        DO::parameters::preserve_global_injectivity(true, DO::parameters::number_of_threads(threads))
          .vertex_is_constrained_map(none).number_of_iterations(300));
      EXPECT_LT(r.final_energy - 1, 0.2 * (r.initial_energy - 1));
      EXPECT_EQ(r.inverted_cells, 0u);
      EXPECT_EQ(count_flipped(*mesh, uv), 0u);
      EXPECT_EQ(border_self_intersections(*mesh, uv), 0u) << threads << " threads";
    }
    if(k == 0) continue;   // the real disk's free-boundary optimum is injective anyway
    // Without the guard the ramp's ends cross: the guard is what prevents it.
    for(auto v : mesh->vertices()) uv[v] = tutte[v];
    CGAL::minimize_distortion(*mesh, uv, DO::Symmetric_dirichlet(),
                              CGAL::parameters::vertex_is_constrained_map(none).number_of_iterations(300));
    EXPECT_EQ(count_flipped(*mesh, uv), 0u);
    EXPECT_GT(border_self_intersections(*mesh, uv), 0u);
  }
}

// The map as another program reads it: each coordinate rounded to 15 significant digits (a few
// units in the last place), as a decimal file written with fewer digits, or one read as exact
// decimals, may do.
template <class Mesh, class UV>
void round_to_15_digits(const Mesh& mesh, UV uv)
{
  const auto round = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", x);
    return std::strtod(text, nullptr);
  };
  for(auto v : mesh.vertices()) uv[v] = Point_2(round(uv[v].x()), round(uv[v].y()));
}

// A measure finite on flat cells (ARAP) once squeezed triangles to areas of 1e-19, valid in
// doubles but inverted by the rounding of a decimal output; with a free border, the guard let a
// vertex stop 1e-19 from another border edge. Cells and the border now keep a margin: the map
// stays valid and globally injective once rounded.
TEST(MinimizeDistortion, ResultsSurviveTheRoundingOfTheirCoordinates)
{
  std::vector<Mesh3> meshes(2);
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("mushroom.off"), meshes[0]));
  meshes[1] = helical_ramp(1.3);
  for(std::size_t k = 0; k < meshes.size(); ++k) {
    Mesh3& mesh = meshes[k];
    auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
    auto none = mesh.add_property_map<Mesh3::Vertex_index, bool>("v:none", false).first;
    for(bool free_border : {false, true}) {
      DO::initial_parameterization(mesh, uv);
      const auto r = free_border
        ? CGAL::minimize_distortion(mesh, uv, DO::ARAP(), DO::parameters::preserve_global_injectivity(true,
                                      DO::parameters::schedule(DO::Schedule::LOCAL)).vertex_is_constrained_map(none))
        : CGAL::minimize_distortion(mesh, uv, DO::ARAP(), DO::parameters::schedule(DO::Schedule::LOCAL));
      EXPECT_LT(r.final_energy, r.initial_energy);
      EXPECT_EQ(count_flipped(mesh, uv), 0u) << k << " " << free_border;
      round_to_15_digits(mesh, uv);
      EXPECT_EQ(count_flipped(mesh, uv), 0u) << k << " " << free_border;
      if(free_border) {
        EXPECT_EQ(border_self_intersections(mesh, uv), 0u) << k;
      }
    }
  }
}

TEST(MinimizeDistortion, GuardRejectsAStartWhoseBoundaryCrossesItself)
{
  Mesh3 mesh = helical_ramp(1.2);
  auto uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
  auto none = mesh.add_property_map<Mesh3::Vertex_index, bool>("v:none", false).first;
  DO::initial_parameterization(mesh, uv);
  CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
                            CGAL::parameters::vertex_is_constrained_map(none).number_of_iterations(300));
  ASSERT_GT(border_self_intersections(mesh, uv), 0u);
  std::vector<Point_2> before;
  for(auto v : mesh.vertices()) before.push_back(uv[v]);
  try {
    CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
                              DO::parameters::preserve_global_injectivity(true).vertex_is_constrained_map(none));
    ADD_FAILURE() << "a self-intersecting start was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("intersects itself"), std::string::npos) << e.what();
  }
  for(auto v : mesh.vertices()) EXPECT_EQ(uv[v], before[v.idx()]);
}
