// compute_distortion on CGAL::Surface_mesh: planar maps and surface-to-plane maps.

#include "test_meshes.h"

#include <CGAL/compute_distortion.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace test_meshes;

namespace {

// Expected values of every measure for the singular values (2, 1) of (x, y) -> (2x, y).
struct Expected_stretch
{
  const char* name;
  double value;
};
const Expected_stretch stretch_values[] = {{"conformal", 2}, {"condition", 2}, {"mips", 2.5},
  {"isometric", 2}, {"arap", 1}, {"symmetric_dirichlet", (4 + 1 + 0.25 + 1) / 4.}, {"volume", 2},
  {"dirichlet", 2.5}};

template <class Mesh>
void check_stretch(Mesh& m)
{
  auto uv = make_target(m, [](const auto& p) { return Point_2(2 * p.x(), p.y()); });
  auto check = [&](const auto& measure) {
    const DO::Distortion_statistics s = CGAL::compute_distortion(m, uv, measure);
    double expected = -1;
    for(const auto& e : stretch_values)
      if(measure.name() == e.name) expected = e.value;
    EXPECT_NEAR(s.mean_volume, expected, 1e-12) << measure.name();
    EXPECT_NEAR(s.mean_uniform, expected, 1e-12) << measure.name();
    EXPECT_NEAR(s.min, expected, 1e-12) << measure.name();
    EXPECT_NEAR(s.max, expected, 1e-12) << measure.name();
    EXPECT_EQ(s.inverted_cells, 0u);
    EXPECT_EQ(s.cells, m.number_of_faces());
  };
  check(DO::Conformal_dilatation());
  check(DO::Condition_number());
  check(DO::MIPS());
  check(DO::Isometric_dilatation());
  check(DO::ARAP());
  check(DO::Symmetric_dirichlet());
  check(DO::Volume_distortion());
  check(DO::Dirichlet());
}

} // namespace

TEST(ComputeDistortion, AffineStretchOfAPlanarMesh)
{
  Mesh2 m = planar_grid(4);
  check_stretch(m);
}

TEST(ComputeDistortion, AffineStretchOfAFlatSurfaceMesh)
{
  Mesh3 m = flat_grid(4);
  check_stretch(m);
}

TEST(ComputeDistortion, IsometricFlatteningOfATiltedSurfaceIsRigid)
{
  // The grid bent along a crease x = 0.5 into 3D; unfolding it is an isometry.
  const double a = 0.7;
  Mesh3 m = grid<Mesh3>(6, [&](double x, double y) {
    return x <= 0.5 ? Point_3(x, y, 0) : Point_3(0.5 + (x - 0.5) * std::cos(a), y, (x - 0.5) * std::sin(a));
  });
  auto uv = make_target(m, [&](const Point_3& p) {
    const double x = p.x() <= 0.5 + 1e-12 && p.z() == 0 ? p.x() : 0.5 + std::hypot(p.x() - 0.5, p.z());
    return Point_2(x, p.y());
  });
  EXPECT_NEAR(CGAL::compute_distortion(m, uv, DO::Symmetric_dirichlet()).max, 1., 1e-12);
  EXPECT_NEAR(CGAL::compute_distortion(m, uv, DO::Isometric_dilatation()).max, 1., 1e-12);
  EXPECT_NEAR(CGAL::compute_distortion(m, uv, DO::ARAP()).max, 0., 1e-12);
  EXPECT_NEAR(CGAL::compute_distortion(m, uv, DO::MIPS()).max, 2., 1e-12);
}

TEST(ComputeDistortion, WeightedMeansAgreeWithABruteForceSum)
{
  // Graded along x, so that face areas differ and the weightings give different means.
  Mesh3 m = grid<Mesh3>(5, [](double x, double y) { return Point_3(x + 0.8 * x * x, y, 0); });
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-0.03, 0.03), weight(0.5, 2.);
  auto uv = make_target(m, [&](const Point_3& p) { return Point_2(p.x() + noise(rng), p.y() * 1.5 + noise(rng)); });
  auto omega = m.add_property_map<Mesh3::Vertex_index, double>("v:omega").first;
  for(auto v : m.vertices()) omega[v] = weight(rng);
  auto per_face = m.add_property_map<Mesh3::Face_index, double>("f:distortion").first;

  const DO::Conformal_dilatation measure;
  const DO::Distortion_statistics s = CGAL::compute_distortion(m, uv, measure,
    DO::parameters::cell_distortion_map(per_face, DO::parameters::vertex_weight_map(omega)));

  // Brute force: each triangle's K from its own 2x2 Jacobian in closed form.
  double eu = 0, wu = 0, ev = 0, wv = 0, mn = 1e300, mx = 0;
  for(auto f : m.faces()) {
    double area;
    const auto sv = brute_force_singular_values(m, uv, f, &area);
    const double k = brute_force_measure("conformal", sv.first, sv.second);
    EXPECT_NEAR(per_face[f], k, 1e-10 * k);
    double w = 0;
    for(auto v : m.vertices_around_face(m.halfedge(f))) w += omega[v];
    eu += w * k; wu += w; ev += w * area * k; wv += w * area;
    mn = std::min(mn, k); mx = std::max(mx, k);
  }
  EXPECT_NEAR(s.mean_uniform, eu / wu, 1e-12 * s.mean_uniform);
  EXPECT_NEAR(s.mean_volume, ev / wv, 1e-12 * s.mean_volume);
  EXPECT_NEAR(s.energy_uniform, eu, 1e-12 * eu);
  EXPECT_NEAR(s.energy_volume, ev, 1e-12 * ev);
  EXPECT_NEAR(s.energy_average_volume, ev / 3, 1e-12 * ev);
  EXPECT_NE(s.mean_uniform, s.mean_volume);
  EXPECT_NEAR(s.min, mn, 1e-12 * mn);
  EXPECT_NEAR(s.max, mx, 1e-12 * mx);
}

TEST(ComputeDistortion, InvertedTrianglesAreCountedExactly)
{
  Mesh2 m = planar_grid(3);
  auto uv = make_target(m, [](const Point_2& p) { return p; });
  // Move an interior vertex across its neighbours: some triangles flip.
  Mesh2::Vertex_index moved(5);   // (1/3, 1/3)
  uv[moved] = Point_2(0.9, 0.9);
  const auto s = CGAL::compute_distortion(m, uv, DO::Conformal_dilatation());
  EXPECT_GT(s.inverted_cells, 0u);
  EXPECT_EQ(s.max, std::numeric_limits<double>::infinity());
  EXPECT_EQ(s.mean_volume, std::numeric_limits<double>::infinity());
  // ARAP is finite on inverted cells, the count is the same; inverted_cell_map names those cells.
  auto inverted = m.add_property_map<Mesh2::Face_index, bool>("f:inverted", true).first;
  const auto a = CGAL::compute_distortion(m, uv, DO::ARAP(), DO::parameters::inverted_cell_map(inverted));
  EXPECT_EQ(a.inverted_cells, s.inverted_cells);
  EXPECT_LT(a.max, std::numeric_limits<double>::infinity());
  std::size_t flagged = 0;
  for(auto f : m.faces()) {
    const auto h = m.halfedge(f);
    const auto p = m.source(h), q = m.target(h), r = m.target(m.next(h));
    ASSERT_EQ(CGAL::orientation(m.point(p), m.point(q), m.point(r)), CGAL::LEFT_TURN);
    EXPECT_EQ(inverted[f], CGAL::orientation(uv[p], uv[q], uv[r]) != CGAL::LEFT_TURN) << f;
    flagged += inverted[f];
  }
  EXPECT_EQ(flagged, a.inverted_cells);

  // A triangle mapped to a segment is degenerate: counted, and K is infinite.
  auto flat = make_target(m, [](const Point_2& p) { return Point_2(p.x(), 0); });
  const auto d = CGAL::compute_distortion(m, flat, DO::Conformal_dilatation(), DO::parameters::inverted_cell_map(inverted));
  EXPECT_EQ(d.inverted_cells, m.number_of_faces());
  for(auto f : m.faces()) EXPECT_TRUE(inverted[f]) << f;
}

TEST(ComputeDistortion, ClockwiseSourceKeepsItsOrientation)
{
  // A planar mesh whose faces are clockwise: the identity map is not inverted, a mirror is.
  Mesh2 m;
  auto a = m.add_vertex(Point_2(0, 0)), b = m.add_vertex(Point_2(0, 1)), c = m.add_vertex(Point_2(1, 0));
  m.add_face(a, b, c);
  auto same = make_target(m, [](const Point_2& p) { return p; });
  auto s = CGAL::compute_distortion(m, same, DO::Conformal_dilatation());
  EXPECT_EQ(s.inverted_cells, 0u);
  EXPECT_NEAR(s.max, 1., 1e-14);
  auto mirror = make_target(m, [](const Point_2& p) { return Point_2(-p.x(), p.y()); });
  EXPECT_EQ(CGAL::compute_distortion(m, mirror, DO::Conformal_dilatation()).inverted_cells, 1u);
}

TEST(ComputeDistortion, SourceOrientationIsDecidedExactly)
{
  // A nearly flat clockwise triangle whose floating-point determinant of source edges
  // (q - p, r - p) comes out positive: only an exact predicate sees that the identity keeps its
  // orientation.
  const Point_2 p(0.1707908905576534, 0.18294937963584712), q(1.1707908905576534, 1.182949379635847),
                r(3.1494963939535907, 3.161654883031784);
  ASSERT_EQ(CGAL::orientation(p, q, r), CGAL::RIGHT_TURN);
  ASSERT_GT((q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x()), 0.);
  Mesh2 m;
  m.add_face(m.add_vertex(p), m.add_vertex(q), m.add_vertex(r));
  auto same = make_target(m, [](const Point_2& x) { return x; });
  EXPECT_EQ(CGAL::compute_distortion(m, same, DO::ARAP()).inverted_cells, 0u);
  auto mirror = make_target(m, [](const Point_2& x) { return Point_2(-x.x(), x.y()); });
  EXPECT_EQ(CGAL::compute_distortion(m, mirror, DO::ARAP()).inverted_cells, 1u);
}

TEST(ComputeDistortion, BadInputIsRejectedWithAClearMessage)
{
  auto expect_error = [](auto&& f, const std::string& fragment) {
    try {
      f();
      ADD_FAILURE() << "no exception; expected one about '" << fragment << "'";
    } catch(const DO::Invalid_input& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  Mesh2 empty;
  auto empty_uv = make_target(empty, [](const Point_2& p) { return p; });
  expect_error([&] { CGAL::compute_distortion(empty, empty_uv, DO::MIPS()); }, "no face");

  Mesh2 m = planar_grid(2);
  auto uv = make_target(m, [](const Point_2& p) { return p; });
  uv[Mesh2::Vertex_index(4)] = Point_2(std::numeric_limits<double>::quiet_NaN(), 0);
  expect_error([&] { CGAL::compute_distortion(m, uv, DO::MIPS()); }, "vertex 4 has a non-finite target");

  Mesh2 degenerate;
  auto a = degenerate.add_vertex(Point_2(0, 0)), b = degenerate.add_vertex(Point_2(1, 1)),
       c = degenerate.add_vertex(Point_2(2, 2));
  degenerate.add_face(a, b, c);
  auto duv = make_target(degenerate, [](const Point_2& p) { return p; });
  expect_error([&] { CGAL::compute_distortion(degenerate, duv, DO::MIPS()); }, "source face 0 is degenerate");

  Mesh2 quad;
  std::vector<Mesh2::Vertex_index> q = {quad.add_vertex(Point_2(0, 0)), quad.add_vertex(Point_2(1, 0)),
                                        quad.add_vertex(Point_2(1, 1)), quad.add_vertex(Point_2(0, 1))};
  quad.add_face(q);
  auto quv = make_target(quad, [](const Point_2& p) { return p; });
  expect_error([&] { CGAL::compute_distortion(quad, quv, DO::MIPS()); }, "face 0 is not a triangle");

  Mesh2 w = planar_grid(2);
  auto wuv = make_target(w, [](const Point_2& p) { return p; });
  auto omega = w.add_property_map<Mesh2::Vertex_index, double>("v:w", 1.).first;
  omega[Mesh2::Vertex_index(2)] = 0;
  expect_error([&] { CGAL::compute_distortion(w, wuv, DO::MIPS(), DO::parameters::vertex_weight_map(omega)); },
               "vertex 2 has a weight");
}
