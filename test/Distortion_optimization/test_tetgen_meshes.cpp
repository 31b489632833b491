// minimize_distortion on complexes built from TetGen meshes of the cube (tetrahedralize_with_tetgen):
// TetGen's files read back, c3t3_from_tetrahedra() and its converse, parallel runs, the free
// boundary, untangling, huge coordinates, sliding on a triangle surface. The tests of the
// TetrahedralMeshes suite that need TetGen: built only when CMake finds it (the others are in
// test_tetrahedral_meshes.cpp, built always).

#include "test_mesh_3.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/tetrahedralize_with_tetgen.h>
#include <CGAL/Distortion_optimization/untangle.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

using Surface = CGAL::Surface_mesh<K::Point_3>;

// The boundary of the cube [-1, 1]^3: vertex i at (+-1, +-1, +-1) by the bits of i, 12 triangles.
static Surface cube_surface()
{
  Surface cube;
  for(int i = 0; i < 8; ++i) cube.add_vertex(K::Point_3(i & 1 ? 1. : -1., i & 2 ? 1. : -1., i & 4 ? 1. : -1.));
  const std::vector<std::array<std::size_t, 3>> faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                         {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for(const auto& f : faces) cube.add_face(Surface::Vertex_index(f[0]), Surface::Vertex_index(f[1]), Surface::Vertex_index(f[2]));
  return cube;
}

// The cube [-1, 1]^3, given to TetGen as a closed triangle surface, with a tet volume bound.
static void tetgen_cube(double max_volume, std::vector<std::array<double, 3>>& points,
                        std::vector<std::array<std::size_t, 4>>& tets)
{
  DO::IO::Tetrahedron_soup soup = DO::tetrahedralize_with_tetgen(cube_surface(), DO::parameters::maximum_cell_volume(max_volume));
  points = std::move(soup.points);
  tets = std::move(soup.cells);
}

static C3t3 tetgen_cube_complex(double max_volume)
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tets;
  tetgen_cube(max_volume, points, tets);
  C3t3 c3t3;
  DO::c3t3_from_tetrahedra(c3t3, points, tets);
  return c3t3;
}

// tetrahedralize_with_tetgen() takes its bounds and maps by name: without a volume bound the
// tetrahedra are fewer; with one none is larger; a looser radius-edge bound is accepted; the
// surface's vertices come first, at their index (here numbered backwards) and where the point
// map puts them (here twice as far).
TEST(TetrahedralMeshes, TetgenTakesItsBoundsAndMapsByName)
{
  const Surface cube = cube_surface();
  const auto volume = [](const DO::IO::Tetrahedron_soup& s, const std::array<std::size_t, 4>& t) {
    const auto p = [&](int i) { return Point_3(s.points[t[i]][0], s.points[t[i]][1], s.points[t[i]][2]); };
    return CGAL::volume(p(0), p(1), p(2), p(3));
  };
  const DO::IO::Tetrahedron_soup bounded = DO::tetrahedralize_with_tetgen(cube, DO::parameters::maximum_cell_volume(0.05));
  const DO::IO::Tetrahedron_soup unbounded = DO::tetrahedralize_with_tetgen(cube);
  const DO::IO::Tetrahedron_soup loose =
    DO::tetrahedralize_with_tetgen(cube, DO::parameters::maximum_cell_volume(0.05, DO::parameters::cell_radius_edge_ratio(2.)));
  EXPECT_LT(unbounded.cells.size(), bounded.cells.size());
  for(const auto* s : {&bounded, &unbounded, &loose}) {
    double total = 0;
    for(const auto& t : s->cells) {
      EXPECT_GT(volume(*s, t), 0);
      if(s != &unbounded) {
        EXPECT_LE(volume(*s, t), 0.05);
      }
      total += volume(*s, t);
    }
    EXPECT_NEAR(total, 8, 1e-9);
  }
  const auto backwards = boost::make_function_property_map<Surface::Vertex_index>([](Surface::Vertex_index v) { return 7 - std::size_t(v); });
  const auto doubled = boost::make_function_property_map<Surface::Vertex_index>([&](Surface::Vertex_index v) {
    const K::Point_3& p = cube.point(v);
    return K::Point_3(2 * p.x(), 2 * p.y(), 2 * p.z());
  });
  const DO::IO::Tetrahedron_soup mapped = DO::tetrahedralize_with_tetgen(
    cube, DO::parameters::maximum_cell_volume(0.4, CGAL::parameters::vertex_index_map(backwards).vertex_point_map(doubled)));
  ASSERT_GE(mapped.points.size(), 8u);
  for(Surface::Vertex_index v : cube.vertices()) {
    const K::Point_3& p = cube.point(v);
    EXPECT_EQ(mapped.points[7 - std::size_t(v)], (std::array<double, 3>{2 * p.x(), 2 * p.y(), 2 * p.z()}));
  }
  double total = 0;
  for(const auto& t : mapped.cells) total += volume(mapped, t);
  EXPECT_NEAR(total, 64, 1e-9);
}

// TetGen's own writer (tetgenio::save_nodes, save_elements: 1-based, as the tetgen program
// writes, with a region attribute per tetrahedron) read back by read_tetrahedron_soup.
TEST(TetrahedralMeshes, TetgenFilesAreReadBackInTheirOrder)
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tets;
  tetgen_cube(0.05, points, tets);
  tetgenio io;   // frees its lists
  io.firstnumber = 1;
  io.numberofpoints = static_cast<int>(points.size());
  io.pointlist = new REAL[3 * points.size()];
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int d = 0; d < 3; ++d) io.pointlist[3 * i + d] = points[i][d];
  io.numberoftetrahedra = static_cast<int>(tets.size());
  io.numberofcorners = 4;
  io.tetrahedronlist = new int[4 * tets.size()];
  io.numberoftetrahedronattributes = 1;
  io.tetrahedronattributelist = new REAL[tets.size()];
  for(std::size_t t = 0; t < tets.size(); ++t) {
    for(int k = 0; k < 4; ++k) io.tetrahedronlist[4 * t + k] = static_cast<int>(tets[t][k]) + 1;
    io.tetrahedronattributelist[t] = double(t % 3 + 1);
  }
  std::string stem = ::testing::TempDir() + "distortion_tetgen_cube";
  io.save_nodes(&stem[0]);
  io.save_elements(&stem[0]);
  for(const std::string& path : {stem + ".ele", stem + ".node"}) {
    const DO::IO::Tetrahedron_soup soup = DO::IO::read_tetrahedron_soup(path);
    ASSERT_EQ(soup.points.size(), points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      for(int d = 0; d < 3; ++d) EXPECT_NEAR(soup.points[i][d], points[i][d], 1e-15) << i;
    EXPECT_EQ(soup.cells, tets);
    ASSERT_EQ(soup.labels.size(), tets.size());
    for(std::size_t t = 0; t < tets.size(); ++t) EXPECT_EQ(soup.labels[t], int(t % 3 + 1));
  }
  std::remove((stem + ".node").c_str());
  EXPECT_THROW(DO::IO::read_tetrahedron_soup(stem + ".ele"), DO::Invalid_input);   // the pair is needed
  std::remove((stem + ".ele").c_str());
}

TEST(TetrahedralMeshes, TetrahedraFromC3t3IsTheConverseOfC3t3FromTetrahedra)
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tets;
  tetgen_cube(0.05, points, tets);
  C3t3 c3t3;
  const auto handles = DO::c3t3_from_tetrahedra(c3t3, points, tets);
  std::unordered_map<Vertex_handle, std::size_t> input_index;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Vertex_handle()) input_index[handles[i]] = i;

  std::vector<std::array<double, 3>> out_points = {{7, 7, 7}};   // cleared first
  std::vector<std::array<std::size_t, 4>> out_tets;
  const auto out_handles = DO::tetrahedra_from_c3t3(c3t3, out_points, out_tets);
  ASSERT_EQ(out_points.size(), input_index.size());
  ASSERT_EQ(out_handles.size(), out_points.size());
  ASSERT_EQ(out_tets.size(), tets.size());
  // Each point is its vertex's input point; the tetrahedra are the input's (as vertex sets),
  // positively oriented, and the points are numbered in the order the cells first reach them.
  std::vector<std::size_t> input_of(out_points.size());
  for(std::size_t i = 0; i < out_points.size(); ++i) {
    input_of[i] = input_index.at(out_handles[i]);
    EXPECT_EQ(out_points[i], points[input_of[i]]);
  }
  auto sorted = [](std::array<std::size_t, 4> t) { std::sort(t.begin(), t.end()); return t; };
  std::set<std::array<std::size_t, 4>> input_cells, output_cells;
  for(const auto& t : tets) input_cells.insert(sorted(t));
  std::size_t next = 0;
  for(const auto& t : out_tets) {
    auto P = [&](int k) { return Point_3(out_points[t[k]][0], out_points[t[k]][1], out_points[t[k]][2]); };
    EXPECT_EQ(CGAL::orientation(P(0), P(1), P(2), P(3)), CGAL::POSITIVE);
    for(std::size_t v : t) {
      ASSERT_LE(v, next);
      if(v == next) ++next;
    }
    output_cells.insert(sorted({input_of[t[0]], input_of[t[1]], input_of[t[2]], input_of[t[3]]}));
  }
  EXPECT_EQ(output_cells, input_cells);

  // With a target map: the image's points, the same tetrahedra.
  Target_storage image;
  for(Vertex_handle v : out_handles) image[v] = radial(v->point().point());
  std::vector<std::array<double, 3>> image_points;
  std::vector<std::array<std::size_t, 4>> image_tets;
  EXPECT_EQ(DO::tetrahedra_from_c3t3(c3t3, image_points, image_tets, CGAL::parameters::vertex_point_map(Target_map(image))),
            out_handles);
  EXPECT_EQ(image_tets, out_tets);
  for(std::size_t i = 0; i < image_points.size(); ++i) {
    const Point_3 q = radial(Point_3(out_points[i][0], out_points[i][1], out_points[i][2]));
    EXPECT_EQ(image_points[i], (std::array<double, 3>{q.x(), q.y(), q.z()}));
  }

  // A Mesh_3 complex: only the cells in the complex, not the triangulation's others outside it.
  const C3t3 sphere = mesh_sphere(0.3);
  ASSERT_LT(sphere.number_of_cells_in_complex(), sphere.triangulation().number_of_finite_cells());
  DO::tetrahedra_from_c3t3(sphere, out_points, out_tets);
  EXPECT_EQ(out_tets.size(), sphere.number_of_cells_in_complex());
}

TEST(TetrahedralMeshes, TetgenCubeThroughC3t3FromTetrahedra)
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tets;
  tetgen_cube(0.01, points, tets);
  ASSERT_GT(tets.size(), 800u);
  double volume = 0;
  for(const auto& t : tets) {
    auto P = [&](int k) { return Point_3(points[t[k]][0], points[t[k]][1], points[t[k]][2]); };
    EXPECT_EQ(CGAL::orientation(P(0), P(1), P(2), P(3)), CGAL::POSITIVE);   // TetGen's output is positive
    volume += CGAL::to_double(CGAL::volume(P(0), P(1), P(2), P(3)));
  }
  EXPECT_NEAR(volume, 8., 1e-9);

  C3t3 c3t3;
  const auto handles = DO::c3t3_from_tetrahedra(c3t3, points, tets);
  ASSERT_EQ(c3t3.number_of_cells_in_complex(), tets.size());
  // A ball: with its infinite cells on the boundary facets, the data structure is a valid
  // triangulated 3-sphere (neighbours, vertex cells, orientation, Euler characteristic).
  EXPECT_TRUE(c3t3.triangulation().tds().is_valid());
  Target_storage storage;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(handles[i] != Vertex_handle()) storage[handles[i]] = radial(Point_3(points[i][0], points[i][1], points[i][2]));
  const auto r = CGAL::minimize_distortion(c3t3, Target_map(storage), DO::Symmetric_dirichlet(),
                                           CGAL::parameters::number_of_iterations(10));
  EXPECT_LT(r.final_energy, r.initial_energy);
  EXPECT_EQ(inverted(c3t3, storage), 0u);

  // Star-shaped cube -> unit ball: the boundary lands on the sphere, the inside strictly inside.
  // (Tetrahedra with four vertices on the cube's surface near its edges can flatten: the radial
  // construction does not promise a valid map, only a start to repair.)
  Target_storage ball;
  const std::size_t flat = DO::star_shaped_to_unit_ball(c3t3, Target_map(ball), DO::parameters::center(Point_3(0.01, 0.02, 0.03)));
  EXPECT_EQ(flat, inverted(c3t3, ball));
  const auto boundary = boundary_vertices(c3t3);
  for(const auto& kv : ball) {
    const Point_3& q = kv.second;
    const double r = std::sqrt(CGAL::to_double(q.x() * q.x() + q.y() * q.y() + q.z() * q.z()));
    if(boundary.count(kv.first)) {
      EXPECT_NEAR(r, 1., 1e-9);
    } else {
      EXPECT_LT(r, 1.);
    }
  }
  // Those cells are repaired by untangling with the boundary sliding on the sphere (Fig. 13).
  ASSERT_GT(flat, 0u);
  // They are scattered along the cube's edges, and their own vertices suffice to untangle them
  // (the first part untangle() tries): every other vertex stays where the ball map put it. (Without
  // the harmonic start: by default the rounds start from the harmonic map of the sphere's image,
  // below, which flattens fewer cells.)
  Target_storage untangled = ball;
  std::unordered_set<Vertex_handle> of_flat_cells;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    if(!is_positive(c, ball))
      for(int i = 0; i < 4; ++i) of_flat_cells.insert(c->vertex(i));
  const DO::Untangle_result t = DO::untangle(c3t3, Target_map(untangled), DO::parameters::use_harmonic_start(
                                                  false, DO::parameters::sliding_boundary(DO::Sphere_surface())));
  EXPECT_EQ(t.inverted_before, flat);
  EXPECT_EQ(t.inverted_after, 0u);
  EXPECT_EQ(inverted(c3t3, untangled), 0u);
  std::size_t moved = 0;
  for(const auto& kv : ball) {
    if(!(untangled.at(kv.first) == kv.second)) ++moved;
    if(!of_flat_cells.count(kv.first)) {
      EXPECT_EQ(untangled.at(kv.first), kv.second);
    }
  }
  EXPECT_GT(moved, 0u);
  const auto u = CGAL::minimize_distortion(c3t3, Target_map(ball), DO::Symmetric_dirichlet(),
                                           DO::parameters::untangle_first(true, DO::parameters::sliding_boundary(DO::Sphere_surface())));
  EXPECT_EQ(u.inverted_start_cells, flat);
  EXPECT_EQ(u.inverted_cells, 0u);
  EXPECT_EQ(inverted(c3t3, ball), 0u);
  for(Vertex_handle v : boundary) {
    const Point_3& q = ball.at(v);
    EXPECT_NEAR(std::sqrt(CGAL::to_double(q.x() * q.x() + q.y() * q.y() + q.z() * q.z())), 1., 1e-12);
  }
}

TEST(TetrahedralMeshes, ParallelRunsMatchOneThreadAndAreDeterministic)
{
  // The paper's Table 1 setting at about 6K tets: TetGen cube, radial start, boundary fixed, K.
  const C3t3 c3t3 = tetgen_cube_complex(0.002);
  auto run = [&](int threads, DO::Parallel_sweep method, Target_storage& storage) {
    storage.clear();
    DO::map_vertices(c3t3, Target_map(storage), radial);
    return CGAL::minimize_distortion(c3t3, Target_map(storage), DO::Conformal_dilatation(),
      DO::parameters::number_of_threads(threads, DO::parameters::parallel_sweep(method)).number_of_iterations(200));
  };
  Target_storage sequential_map;
  const auto sequential = run(1, DO::Parallel_sweep::INDEPENDENT_SETS, sequential_map);
  ASSERT_TRUE(sequential.converged);
  for(auto method : {DO::Parallel_sweep::INDEPENDENT_SETS, DO::Parallel_sweep::PARTITION}) {
    Target_storage first, second;
    const auto r = run(2, method, first);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.final_energy, sequential.final_energy, 1e-3 * sequential.final_energy);
    EXPECT_EQ(r.inverted_cells, 0u);
    EXPECT_EQ(inverted(c3t3, first), 0u);
    const auto again = run(2, method, second);
    EXPECT_EQ(r.energy_per_iteration, again.energy_per_iteration);
    EXPECT_TRUE(first == second) << "two runs with 2 threads differ";
  }
}

TEST(TetrahedralMeshes, FreeBoundaryRunKeepsTheBoundarySurfaceEmbedded)
{
  // The radial map of a TetGen cube with every vertex free: the boundary moves, the guard keeps
  // it from crossing itself. Checked by brute force: boundary triangles sharing no vertex must not
  // intersect (exact predicates).
  const C3t3 c3t3 = tetgen_cube_complex(0.01);
  std::vector<std::array<Vertex_handle, 3>> boundary;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(!c3t3.is_in_complex(c->neighbor(i)))
        boundary.push_back({c->vertex((i + 1) % 4), c->vertex((i + 2) % 4), c->vertex((i + 3) % 4)});
  auto crossings = [&](const Target_storage& target) {
    std::size_t count = 0;
    for(std::size_t a = 0; a < boundary.size(); ++a)
      for(std::size_t b = a + 1; b < boundary.size(); ++b) {
        bool shared = false;
        for(auto u : boundary[a])
          for(auto w : boundary[b]) shared = shared || u == w;
        if(shared) continue;
        auto triangle = [&](const std::array<Vertex_handle, 3>& t) {
          return K::Triangle_3(target.at(t[0]), target.at(t[1]), target.at(t[2]));
        };
        count += CGAL::do_intersect(triangle(boundary[a]), triangle(boundary[b]));
      }
    return count;
  };
  for(int threads : {1, 2}) {
    Target_storage storage;
    DO::map_vertices(c3t3, Target_map(storage), radial);
    ASSERT_EQ(crossings(storage), 0u);
    const auto none = boost::make_function_property_map<Vertex_handle>([](Vertex_handle) { return false; });
    const auto r = CGAL::minimize_distortion(c3t3, Target_map(storage), DO::Conformal_dilatation(),
      DO::parameters::preserve_global_injectivity(true, DO::parameters::number_of_threads(threads))
        .vertex_is_constrained_map(none).number_of_iterations(30));
    EXPECT_LT(r.final_energy - 1, 0.5 * (r.initial_energy - 1));
    EXPECT_EQ(r.inverted_cells, 0u);
    EXPECT_EQ(inverted(c3t3, storage), 0u);
    EXPECT_EQ(crossings(storage), 0u) << threads << " threads";
  }
}

TEST(TetrahedralMeshes, TangledCubeWithAFixedBoundaryIsUntangledThenOptimized)
{
  // A TetGen cube, boundary fixed at the identity, interior vertices moved at random by about the
  // edge length: hundreds of inverted tetrahedra.
  const C3t3 c3t3 = tetgen_cube_complex(0.01);
  const auto boundary = boundary_vertices(c3t3);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  Target_storage start;
  DO::map_vertices(c3t3, Target_map(start), [](const Point_3& p) { return p; });
  for(auto& [v, p] : start)
    if(!boundary.count(v)) p = Point_3(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
  const std::size_t tangled = inverted(c3t3, start);
  ASSERT_GT(tangled, 50u);
  // compute_distortion's inverted_cell_map names the same cells, under a measure finite on them.
  std::unordered_map<Tr::Cell_handle, bool> flagged;
  const auto arap = CGAL::compute_distortion(c3t3, Target_map(start), DO::ARAP(),
                                             DO::parameters::inverted_cell_map(boost::make_assoc_property_map(flagged)));
  EXPECT_EQ(arap.inverted_cells, tangled);
  ASSERT_EQ(flagged.size(), c3t3.number_of_cells_in_complex());
  for(const auto& [cell, is_flagged] : flagged) EXPECT_EQ(is_flagged, !is_positive(cell, start));
  for(int threads : {1, 2}) {
    Target_storage storage = start;
    std::unordered_set<Vertex_handle> written;
    const DO::Untangle_result r = DO::untangle(c3t3, Recording_map{&storage, &written},
                                               DO::parameters::number_of_threads(threads));
    EXPECT_EQ(r.inverted_before, tangled);
    EXPECT_EQ(r.inverted_after, 0u);
    EXPECT_EQ(inverted(c3t3, storage), 0u) << threads << " threads";
    for(Vertex_handle v : boundary) {
      EXPECT_EQ(written.count(v), 0u);
      EXPECT_EQ(storage.at(v), start.at(v));
    }
    // Through minimize_distortion: untangled, then optimized for the conformal dilatation.
    storage = start;
    const DO::Result m = CGAL::minimize_distortion(c3t3, Target_map(storage), DO::Conformal_dilatation(),
      DO::parameters::untangle_first(true, DO::parameters::number_of_threads(threads)).number_of_iterations(30));
    EXPECT_EQ(m.inverted_start_cells, tangled);
    EXPECT_EQ(m.inverted_cells, 0u);
    EXPECT_EQ(inverted(c3t3, storage), 0u);
    EXPECT_TRUE(std::isfinite(m.final_energy));
    for(Vertex_handle v : boundary) EXPECT_EQ(storage.at(v), start.at(v));
  }
}

// A cell whose orientation is right by the exact predicate but whose floating-point det J is not
// positive: a normalized measure is infinite there, so untangling must not count it as done (else
// minimize_distortion(untangle_first) would throw on the map untangle returns).
TEST(TetrahedralMeshes, ACellValidOnlyByAHairIsUntangledToo)
{
  const C3t3 c3t3 = tetgen_cube_complex(0.01);
  const auto boundary = boundary_vertices(c3t3);
  Target_storage identity;
  DO::map_vertices(c3t3, Target_map(identity), [](const Point_3& p) { return p; });
  const auto minimize = [&](Target_storage& map, bool untangle_first) {
    return CGAL::minimize_distortion(c3t3, Target_map(map), DO::Symmetric_dirichlet(),
                                     DO::parameters::untangle_first(untangle_first).number_of_iterations(5));
  };
  // An interior vertex moved almost onto the opposite facet of one of its cells, closer and closer
  // until that cell is valid by the exact predicate yet infinite for the measure.
  Target_storage start;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end() && start.empty(); ++c) {
    if(boundary.count(c->vertex(0))) continue;
    const Point_3 v = c->vertex(0)->point().point();
    const Point_3 g = CGAL::centroid(c->vertex(1)->point().point(), c->vertex(2)->point().point(), c->vertex(3)->point().point());
    for(double t = 1e-12; t > 1e-22 && start.empty(); t /= 2) {
      Target_storage trial = identity;
      trial[c->vertex(0)] = g + t * (v - g);
      if(inverted(c3t3, trial) != 0) break;
      try {
        minimize(trial, false);
      } catch(const DO::Invalid_input&) {
        start = trial;
      }
    }
  }
  ASSERT_FALSE(start.empty()) << "no cell valid by a hair was found";
  ASSERT_EQ(inverted(c3t3, start), 0u);

  Target_storage untangled = start;
  const DO::Untangle_result u = DO::untangle(c3t3, Target_map(untangled));
  EXPECT_GE(u.inverted_before, 1u);
  EXPECT_EQ(u.inverted_after, 0u);
  EXPECT_NO_THROW(minimize(untangled, false));

  Target_storage optimized = start;
  DO::Result r;
  ASSERT_NO_THROW(r = minimize(optimized, true));
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_EQ(inverted(c3t3, optimized), 0u);
  EXPECT_TRUE(std::isfinite(r.final_energy));
  for(Vertex_handle v : boundary) EXPECT_EQ(optimized.at(v), start.at(v));
}

TEST(TetrahedralMeshes, HugeCoordinatesGiveTheScaledMap)
{
  // A cube of side 2e110 (volumes near 1e330 would overflow): the same map as the unit cube's.
  std::vector<std::array<double, 3>> points, scaled;
  std::vector<std::array<std::size_t, 4>> tets;
  tetgen_cube(0.05, points, tets);
  for(const auto& p : points) scaled.push_back({1e110 * p[0], 1e110 * p[1], 1e110 * p[2]});
  C3t3 unit, huge;
  const auto a = DO::c3t3_from_tetrahedra(unit, points, tets), b = DO::c3t3_from_tetrahedra(huge, scaled, tets);
  Target_storage x, y;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Point_3 p = radial(Point_3(points[i][0], points[i][1], points[i][2]));
    x[a[i]] = p;
    y[b[i]] = Point_3(1e110 * p.x(), 1e110 * p.y(), 1e110 * p.z());
  }
  const auto s = CGAL::compute_distortion(unit, Target_map(x), DO::Symmetric_dirichlet());
  const auto t = CGAL::compute_distortion(huge, Target_map(y), DO::Symmetric_dirichlet());
  EXPECT_EQ(t.inverted_cells, 0u);
  EXPECT_NEAR(t.mean_volume, s.mean_volume, 1e-9 * s.mean_volume);
  const auto r = CGAL::minimize_distortion(unit, Target_map(x), DO::Symmetric_dirichlet(), CGAL::parameters::number_of_iterations(5));
  const auto q = CGAL::minimize_distortion(huge, Target_map(y), DO::Symmetric_dirichlet(), CGAL::parameters::number_of_iterations(5));
  EXPECT_EQ(q.inverted_cells, 0u);
  EXPECT_NEAR(q.final_energy, r.final_energy, 1e-6 * r.final_energy);
  for(std::size_t i = 0; i < points.size(); ++i) EXPECT_NEAR(CGAL::to_double(y.at(b[i]).x()) / 1e110, CGAL::to_double(x.at(a[i]).x()), 1e-4);
}

// A user surface (AABB tree): the boundary slides on the polyhedral boundary of the start map,
// here the image of a TetGen cube under a shear, so the surface has corners and flat faces.
// Constrained vertices stay where they were, to the bit.
TEST(TetrahedralMeshes, BoundarySlidingOnATriangleSurface)
{
  const C3t3 c3t3 = tetgen_cube_complex(0.01);
  const auto shear = [](const Point_3& p) { return Point_3(p.x() + 0.6 * p.y() * p.y(), p.y(), p.z() + 0.3 * p.x()); };
  Target_storage start;
  DO::map_vertices(c3t3, Target_map(start), shear);
  const auto surface = DO::Triangle_surface::from_complex_boundary(c3t3, Target_map(start));
  // The vertices at x = 1 stay fixed.
  std::unordered_set<Vertex_handle> anchored;
  for(Vertex_handle v : boundary_vertices(c3t3))
    if(v->point().x() == 1) anchored.insert(v);
  ASSERT_GT(anchored.size(), 4u);
  auto is_anchored = boost::make_function_property_map<Vertex_handle>([&](Vertex_handle v) { return anchored.count(v) > 0; });

  Target_storage sliding = start;
  const auto r = CGAL::minimize_distortion(c3t3, Target_map(sliding), DO::Symmetric_dirichlet(),
                                           DO::parameters::sliding_boundary(surface).vertex_is_constrained_map(is_anchored));
  EXPECT_EQ(inverted(c3t3, sliding), 0u);
  EXPECT_LT(r.final_energy, r.initial_energy);
  std::size_t moved = 0;
  for(Vertex_handle v : boundary_vertices(c3t3)) {
    const Point_3& p = sliding.at(v);
    if(anchored.count(v)) {
      EXPECT_EQ(p, start.at(v));
      continue;
    }
    std::array<double, 3> normal;
    const auto q = surface.project({p.x(), p.y(), p.z()}, normal);
    EXPECT_LE(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Point_3(q[0], q[1], q[2])))), 1e-12);
    moved += p != start.at(v);
  }
  EXPECT_GT(moved, 0u);
}
