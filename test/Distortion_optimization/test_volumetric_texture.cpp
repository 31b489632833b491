// Volumetric textures (paper section 4.4): points and surfaces embedded in a complex of tetrahedra
// (eq. 18), carried through maps of it, and the distortion of the carried surface.

#include "test_complexes.h"

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/Distortion_optimization/volumetric_texture.h>
#include <CGAL/compute_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

namespace DO = CGAL::Distortion_optimization;
using namespace test_complexes;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Embedding = DO::Volume_embedding<C3t3>;

// A U in the (x, y) plane, 4 x 4 x 2 cubes without the notch x in [1, 3], y in [1, 4]: two arms
// joined at y < 1.
bool in_u(int i, int j, int k) { return k < 2 && !(i >= 1 && i <= 2 && j >= 1); }
C3t3 u_complex() { return cube_complex(4, in_u); }

// An L: a 3 x 3 x 3 block without the cubes x >= 1 and y >= 1.
C3t3 l_complex() { return cube_complex(3, [](int i, int j, int) { return i < 1 || j < 1; }); }

// The map x -> A x + b on every vertex of the complex.
struct Affine
{
  double A[3][3];
  double b[3];
  Point_3 operator()(const Point_3& p) const
  {
    double y[3];
    for(int r = 0; r < 3; ++r) y[r] = A[r][0] * p.x() + A[r][1] * p.y() + A[r][2] * p.z() + b[r];
    return Point_3(y[0], y[1], y[2]);
  }
};

const Affine shear{{{1.5, 0.3, -0.2}, {0.1, 0.8, 0.4}, {-0.3, 0.2, 1.2}}, {0.5, -2., 3.}};
const Affine identity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};

Target_storage targets(const C3t3& c3t3, const std::function<Point_3(const Point_3&)>& f)
{
  Target_storage storage;
  DO::map_vertices(c3t3, Target_map(storage), f);
  return storage;
}

std::vector<Point_3> carried(const Embedding& e, Target_storage& storage)
{
  std::vector<Point_3> out;
  DO::carry_points(e, Target_map(storage), std::back_inserter(out));
  return out;
}

double max_relative_error(const std::vector<Point_3>& a, const std::vector<Point_3>& b)
{
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for(std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const double scale = std::max(1., std::sqrt(CGAL::to_double((b[i] - CGAL::ORIGIN).squared_length())));
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(a[i], b[i])) / scale);
  }
  return worst;
}

// Random points of the union of the cubes kept by `keep` (n^3 block), strictly inside them.
std::vector<Point_3> random_points(int n, const std::function<bool(int, int, int)>& keep, std::size_t count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> cube(0, n - 1);
  std::uniform_real_distribution<double> u(1e-3, 1 - 1e-3);
  std::vector<Point_3> points;
  while(points.size() < count) {
    const int i = cube(rng), j = cube(rng), k = cube(rng);
    if(keep(i, j, k)) points.emplace_back(i + u(rng), j + u(rng), k + u(rng));
  }
  return points;
}

// Checks what an embedding promises: complex cells, coordinates >= 0 summing to 1, reproducing
// the point.
void expect_valid(const C3t3& c3t3, const Embedding& e, const std::vector<Point_3>& points)
{
  ASSERT_EQ(e.size(), points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_TRUE(c3t3.is_in_complex(e.cells[i])) << "point " << i;
    double sum = 0;
    for(double w : e.coordinates[i]) {
      EXPECT_GE(w, 0.);
      sum += w;
    }
    EXPECT_NEAR(sum, 1., 1e-15);
  }
  Target_storage source = targets(c3t3, identity);
  EXPECT_LT(max_relative_error(carried(e, source), points), 1e-14);
}

TEST(VolumetricTexture, AffineMapsCarryPointsExactlyInAConvexCube)
{
  const C3t3 c3t3 = cube_complex(4, [](int, int, int) { return true; });
  ASSERT_EQ(c3t3.number_of_cells_in_complex(), 6u * 64u);
  const auto all = [](int, int, int) { return true; };
  const std::vector<Point_3> points = random_points(4, all, 2000, 1);
  const Embedding e = DO::embed_in_volume(c3t3, points);
  expect_valid(c3t3, e, points);
  EXPECT_TRUE(e.snapped_points.empty());

  Target_storage storage = targets(c3t3, shear);
  std::vector<Point_3> expected;
  for(const Point_3& p : points) expected.push_back(shear(p));
  EXPECT_LT(max_relative_error(carried(e, storage), expected), 1e-12);
}

TEST(VolumetricTexture, NonConvexComplexesFindEveryPointWhereTheWalkFails)
{
  const C3t3 c3t3 = u_complex();
  const Tr& tr = c3t3.triangulation();
  // The walk from the left arm to a point of the right arm leaves the complex through the notch:
  // the triangulation of a non-convex tetrahedron soup is not a triangulation of its hull.
  const Point_3 left(0.5, 3.5, 1.), right(3.5, 3.5, 1.);
  Tr::Locate_type lt;
  int li, lj;
  const Tr::Cell_handle start = DO::embed_in_volume(c3t3, std::vector<Point_3>{left}).cells[0];
  const Tr::Cell_handle walked = tr.locate(Tr::Point(right), lt, li, lj, start);
  EXPECT_FALSE(c3t3.is_in_complex(walked)) << "the walk happened to succeed: the fallback is not exercised";

  // Alternate arms, so that every walk has to cross the notch; and random points.
  std::vector<Point_3> points;
  for(int s = 0; s < 50; ++s) {
    const double t = (s + 0.5) / 50;
    points.emplace_back(0.2 + 0.6 * t, 1.1 + 2.8 * t, 0.3 + 1.4 * t);
    points.emplace_back(3.8 - 0.6 * t, 3.9 - 2.8 * t, 1.7 - 1.4 * t);
  }
  for(const Point_3& p : random_points(4, [](int i, int j, int k) { return in_u(i, j, k); }, 1000, 2)) points.push_back(p);
  const Embedding e = DO::embed_in_volume(c3t3, points);
  expect_valid(c3t3, e, points);

  Target_storage storage = targets(c3t3, shear);
  std::vector<Point_3> expected;
  for(const Point_3& p : points) expected.push_back(shear(p));
  EXPECT_LT(max_relative_error(carried(e, storage), expected), 1e-12);

  // The L as well.
  const C3t3 l = l_complex();
  const std::vector<Point_3> l_points = random_points(3, [](int i, int j, int) { return i < 1 || j < 1; }, 500, 3);
  expect_valid(l, DO::embed_in_volume(l, l_points), l_points);
}

TEST(VolumetricTexture, PointsOnFacesEdgesAndVerticesGetAContainingCell)
{
  const C3t3 c3t3 = u_complex();
  std::vector<Point_3> points;
  std::vector<int> zeros;   // the number of coordinates that must be exactly 0
  // Vertices of the complex: interior, on the boundary, at the concave corners of the notch.
  for(const Point_3& p : {Point_3(1, 0, 1), Point_3(0, 0, 0), Point_3(1, 1, 1), Point_3(3, 1, 1), Point_3(3, 4, 2), Point_3(1, 2, 1)}) {
    points.push_back(p);
    zeros.push_back(3);
  }
  // Midpoints of edges (axis-parallel lattice edges are tetrahedron edges), inside and on the boundary.
  for(const Point_3& p : {Point_3(0.5, 0, 1), Point_3(1, 0.5, 1), Point_3(1, 1, 0.5), Point_3(3, 2.5, 1), Point_3(0, 3, 1.5)}) {
    points.push_back(p);
    zeros.push_back(2);
  }
  // Points on facets: the faces x = const of a cube are split along a diagonal, so (x, y, z) with
  // y + z off the diagonal lies inside one triangle; inside and on the boundary (the notch walls).
  for(const Point_3& p : {Point_3(1, 0.25, 0.5), Point_3(1, 1.75, 1.5), Point_3(3, 2.25, 0.5), Point_3(0.25, 0.5, 2)}) {
    points.push_back(p);
    zeros.push_back(1);
  }
  const Embedding e = DO::embed_in_volume(c3t3, points);
  expect_valid(c3t3, e, points);
  Target_storage storage = targets(c3t3, shear);
  for(std::size_t i = 0; i < points.size(); ++i) {
    int z = 0;
    for(double w : e.coordinates[i]) z += w == 0.;
    EXPECT_EQ(z, zeros[i]) << "point " << i << " " << points[i];
    if(zeros[i] == 3)   // exactly the vertex's target
      for(int j = 0; j < 4; ++j)
        if(e.coordinates[i][j] == 1.) {
          EXPECT_EQ(e.image(i, Target_map(storage)), storage.at(e.cells[i]->vertex(j)));
        }
  }
}

TEST(VolumetricTexture, PointsOutsideAreNamedOrSnapped)
{
  const C3t3 c3t3 = u_complex();
  const std::vector<Point_3> points = {Point_3(0.5, 0.5, 0.5), Point_3(1.8, 3, 1),   // in the notch
                                       Point_3(3.5, 3.5, 1.5), Point_3(-1, 0.5, 0.5),   // left of x = 0
                                       Point_3(0.5, 0.5, 2.25), Point_3(1.2, 2.5, 1.)};  // above; in the notch near its wall
  try {
    DO::embed_in_volume(c3t3, points);
    ADD_FAILURE() << "no exception";
  } catch(const DO::Points_outside_volume& error) {
    EXPECT_EQ(error.indices(), (std::vector<std::size_t>{1, 3, 4, 5}));
    const std::string message = error.what();
    EXPECT_NE(message.find("4 points are outside the volume"), std::string::npos) << message;
    EXPECT_NE(message.find("1, 3, 4, 5"), std::string::npos) << message;
    EXPECT_NE(message.find("snap_to_volume"), std::string::npos) << message;
  }
  // Many outside: the message lists the first ten.
  std::vector<Point_3> far(25, Point_3(10, 10, 10));
  try {
    DO::embed_in_volume(c3t3, far);
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& error) {
    EXPECT_NE(std::string(error.what()).find("25 points are outside the volume (in no cell of the complex): 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, ..."),
              std::string::npos) << error.what();
  }

  const Embedding e = DO::embed_in_volume(c3t3, points, DO::parameters::snap_to_volume(true));
  EXPECT_EQ(e.snapped_points, (std::vector<std::size_t>{1, 3, 4, 5}));
  ASSERT_EQ(e.snap_distances.size(), 4u);
  // The closest points of the complex: on a notch wall (x = 1 or 3), or the nearest face.
  const std::vector<Point_3> closest = {Point_3(0.5, 0.5, 0.5), Point_3(1, 3, 1), Point_3(3.5, 3.5, 1.5), Point_3(0, 0.5, 0.5),
                                        Point_3(0.5, 0.5, 2), Point_3(1, 2.5, 1)};
  const double distances[4] = {0.8, 1, 0.25, 0.2};
  Target_storage source = targets(c3t3, identity);
  const std::vector<Point_3> snapped = carried(e, source);
  for(std::size_t i = 0; i < points.size(); ++i) EXPECT_LT(std::sqrt(CGAL::squared_distance(snapped[i], closest[i])), 1e-14) << i;
  for(std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(e.snap_distances[k], distances[k], 1e-14);
    const std::size_t i = e.snapped_points[k];
    EXPECT_TRUE(c3t3.is_in_complex(e.cells[i]));
    // On the boundary: the vertex opposite a boundary facet of the cell has weight 0.
    bool on_boundary = false;
    for(int j = 0; j < 4; ++j)
      on_boundary |= e.coordinates[i][j] == 0. && !c3t3.is_in_complex(e.cells[i]->neighbor(j));
    EXPECT_TRUE(on_boundary) << i;
  }
}

TEST(VolumetricTexture, RejectsNonFiniteInput)
{
  const C3t3 c3t3 = l_complex();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  try {
    DO::embed_in_volume(c3t3, std::vector<Point_3>{Point_3(0.5, 0.5, 0.5), Point_3(nan, 0.5, 0.5)});
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& error) {
    EXPECT_NE(std::string(error.what()).find("point 1 has a non-finite coordinate"), std::string::npos) << error.what();
  }
  const Embedding e = DO::embed_in_volume(c3t3, std::vector<Point_3>{Point_3(0.5, 0.5, 0.5), Point_3(0.25, 2.5, 0.5)});
  Target_storage storage = targets(c3t3, [&](const Point_3& p) { return p.y() > 2 ? Point_3(nan, 0, 0) : p; });
  std::vector<Point_3> out;
  try {
    DO::carry_points(e, Target_map(storage), std::back_inserter(out));
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& error) {
    EXPECT_NE(std::string(error.what()).find("image of point 1 is not finite"), std::string::npos) << error.what();
  }
}

// A closed triangulated box surface [lo, hi]^3 (2 (m^2) triangles per side), outward.
Mesh box_surface(double lo, double hi, int m)
{
  Mesh mesh;
  const auto add_side = [&](int axis, bool upper) {
    std::vector<Mesh::Vertex_index> v;
    for(int b = 0; b <= m; ++b)
      for(int a = 0; a <= m; ++a) {
        double x[3];
        x[axis] = upper ? hi : lo;
        x[(axis + 1) % 3] = lo + (hi - lo) * a / m;
        x[(axis + 2) % 3] = lo + (hi - lo) * b / m;
        v.push_back(mesh.add_vertex(Point_3(x[0], x[1], x[2])));
      }
    const auto at = [&](int a, int b) { return v[b * (m + 1) + a]; };
    for(int b = 0; b < m; ++b)
      for(int a = 0; a < m; ++a) {
        if(upper) {
          mesh.add_face(at(a, b), at(a + 1, b), at(a + 1, b + 1));
          mesh.add_face(at(a, b), at(a + 1, b + 1), at(a, b + 1));
        } else {
          mesh.add_face(at(a, b), at(a + 1, b + 1), at(a + 1, b));
          mesh.add_face(at(a, b), at(a, b + 1), at(a + 1, b + 1));
        }
      }
  };
  // Each side is its own patch (vertices along the box edges are repeated): a valid surface mesh
  // with borders, enough to carry and measure.
  for(int axis = 0; axis < 3; ++axis) {
    add_side(axis, false);
    add_side(axis, true);
  }
  return mesh;
}

TEST(VolumetricTexture, CarriesASurfaceMeshWithItsVerticesAndFaces)
{
  const C3t3 c3t3 = cube_complex(4, [](int, int, int) { return true; });
  const Mesh surface = box_surface(0.3, 3.7, 5);
  const Embedding e = DO::embed_surface_in_volume(c3t3, surface);
  ASSERT_EQ(e.size(), surface.number_of_vertices());
  Target_storage storage = targets(c3t3, shear);

  Mesh out;
  DO::carry_surface(surface, e, Target_map(storage), out);
  ASSERT_EQ(out.number_of_vertices(), surface.number_of_vertices());
  ASSERT_EQ(out.number_of_faces(), surface.number_of_faces());
  for(auto v : surface.vertices()) {
    const Point_3 expected = shear(surface.point(v));
    EXPECT_LT(std::sqrt(CGAL::squared_distance(out.point(v), expected)), 1e-12 * std::sqrt(CGAL::to_double((expected - CGAL::ORIGIN).squared_length())));
  }
  for(auto f : surface.faces())
    EXPECT_EQ(out.target(out.halfedge(f)), surface.target(surface.halfedge(f)));

  // Another mesh type: built vertex by vertex and face by face, in the same order.
  using Other_kernel = CGAL::Simple_cartesian<double>;
  CGAL::Polyhedron_3<Other_kernel> polyhedron;
  DO::carry_surface(surface, e, Target_map(storage), polyhedron);
  ASSERT_EQ(polyhedron.size_of_vertices(), surface.number_of_vertices());
  ASSERT_EQ(polyhedron.size_of_facets(), surface.number_of_faces());
  auto pv = polyhedron.vertices_begin();
  for(auto v : surface.vertices()) {
    EXPECT_LT(std::sqrt(CGAL::squared_distance(pv->point(), Other_kernel::Point_3(out.point(v).x(), out.point(v).y(), out.point(v).z()))), 1e-15);
    ++pv;
  }

  // A vertex map of the surface.
  Mesh copy = surface;
  auto image = copy.add_property_map<Mesh::Vertex_index, Point_3>("v:image").first;
  DO::carry_surface_vertices(surface, e, Target_map(storage), image);
  for(auto v : surface.vertices()) EXPECT_EQ(image[v], out.point(v));

  // An embedding of other points is refused.
  const Embedding fewer = DO::embed_in_volume(c3t3, std::vector<Point_3>{Point_3(1, 1, 1)});
  EXPECT_THROW(DO::carry_surface(surface, fewer, Target_map(storage), out), DO::Invalid_input);
  EXPECT_EQ(out.number_of_vertices(), surface.number_of_vertices());   // unchanged
}

TEST(VolumetricTexture, OneEmbeddingServesSeveralMaps)
{
  const C3t3 c3t3 = u_complex();
  const std::vector<Point_3> points = random_points(4, [](int i, int j, int k) { return in_u(i, j, k); }, 300, 4);
  const Embedding e = DO::embed_in_volume(c3t3, points);
  const Embedding before = e;
  const Affine other{{{0.2, -1, 0}, {1, 0.2, 0}, {0, 0, 3}}, {-1, 1, 0}};
  const auto radial = [](const Point_3& p) {   // not affine: only vertices are mapped exactly
    const double r = std::sqrt(CGAL::to_double((p - CGAL::ORIGIN).squared_length()));
    return Point_3(r * p.x(), r * p.y(), r * p.z());
  };
  Target_storage a = targets(c3t3, shear), b = targets(c3t3, other), c = targets(c3t3, radial);
  std::vector<Point_3> expected_a, expected_b;
  for(const Point_3& p : points) {
    expected_a.push_back(shear(p));
    expected_b.push_back(other(p));
  }
  EXPECT_LT(max_relative_error(carried(e, a), expected_a), 1e-12);
  EXPECT_LT(max_relative_error(carried(e, b), expected_b), 1e-12);
  const std::vector<Point_3> first = carried(e, c);
  EXPECT_EQ(carried(e, c), first);
  EXPECT_EQ(e.cells, before.cells);
  EXPECT_EQ(e.coordinates, before.coordinates);
  // The image under a map is that of a fresh embedding.
  const std::vector<Point_3> fresh = carried(DO::embed_in_volume(c3t3, points), c);
  EXPECT_LT(max_relative_error(first, fresh), 1e-15);
}

// The distortion of each triangle of a carried surface, by compute_distortion with Point_3 targets.
template <class Measure>
std::vector<double> carried_distortions(const Mesh& surface, const Mesh& out, const Measure& measure,
                                        DO::Distortion_statistics* stats = nullptr)
{
  Mesh copy = surface;
  auto per_face = copy.add_property_map<Mesh::Face_index, double>("f:distortion", -1.).first;
  const DO::Distortion_statistics s =
    CGAL::compute_distortion(surface, out.points(), measure, DO::parameters::cell_distortion_map(per_face));
  if(stats) *stats = s;
  std::vector<double> values;
  for(auto f : surface.faces()) values.push_back(per_face[f]);
  return values;
}

template <class Measure>
void expect_all(const Mesh& surface, const Mesh& out, const Measure& measure, double value, const char* name)
{
  DO::Distortion_statistics s;
  for(double d : carried_distortions(surface, out, measure, &s)) EXPECT_NEAR(d, value, 1e-12 * std::max(1., value)) << name;
  EXPECT_EQ(s.inverted_cells, 0u) << name;
  EXPECT_EQ(s.cells, surface.number_of_faces()) << name;
}

TEST(VolumetricTexture, DistortionOfACarriedSurface)
{
  const C3t3 c3t3 = cube_complex(4, [](int, int, int) { return true; });
  const Mesh surface = box_surface(0.3, 3.7, 4);
  const Embedding e = DO::embed_surface_in_volume(c3t3, surface);
  // Rigid maps (a rotation, a reflection: no orientation is measured) give the measures' minima;
  // a uniform scaling by s gives their values at (s, s).
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Affine rotation{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}, {1, 2, 3}};
  const Affine reflection{{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
  for(const Affine* rigid : {&identity, &rotation, &reflection}) {
    Target_storage storage = targets(c3t3, *rigid);
    Mesh out;
    DO::carry_surface(surface, e, Target_map(storage), out);
    expect_all(surface, out, DO::Conformal_dilatation(), 1., "K");
    expect_all(surface, out, DO::MIPS(), 2., "MIPS");
    expect_all(surface, out, DO::Isometric_dilatation(), 1., "C");
    expect_all(surface, out, DO::Symmetric_dirichlet(), 1., "SD");
    expect_all(surface, out, DO::Volume_distortion(), 1., "V");
    expect_all(surface, out, DO::Dirichlet(), 1., "Dirichlet");
    expect_all(surface, out, DO::ARAP(), 0., "ARAP");
  }
  const double k = 2.5;
  const Affine scaling{{{k, 0, 0}, {0, k, 0}, {0, 0, k}}, {-1, 0, 1}};
  Target_storage storage = targets(c3t3, scaling);
  Mesh out;
  DO::carry_surface(surface, e, Target_map(storage), out);
  expect_all(surface, out, DO::Conformal_dilatation(), 1., "K");
  expect_all(surface, out, DO::MIPS(), 2., "MIPS");
  expect_all(surface, out, DO::Isometric_dilatation(), k, "C");
  expect_all(surface, out, DO::Symmetric_dirichlet(), (k * k + 1 / (k * k)) / 2, "SD");
  expect_all(surface, out, DO::Volume_distortion(), k * k, "V");
  expect_all(surface, out, DO::Dirichlet(), k * k, "Dirichlet");
  expect_all(surface, out, DO::ARAP(), 2 * (k - 1) * (k - 1), "ARAP");

  // A stretch along x: sides x = const keep their shape, the others are stretched by 3 along x.
  const Affine stretch{{{3, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
  storage = targets(c3t3, stretch);
  DO::carry_surface(surface, e, Target_map(storage), out);
  const std::vector<double> K = carried_distortions(surface, out, DO::Conformal_dilatation());
  std::size_t f = 0;
  for(auto face : surface.faces()) {
    const bool x_side = surface.point(surface.target(surface.halfedge(face))).x() ==
                        surface.point(surface.target(surface.next(surface.halfedge(face)))).x() &&
                        surface.point(surface.target(surface.halfedge(face))).x() ==
                        surface.point(surface.source(surface.halfedge(face))).x();
    EXPECT_NEAR(K[f++], x_side ? 1. : 3., 1e-12);
  }
}

TEST(VolumetricTexture, SurfaceToSurfaceMapsOfFlatTrianglesAndWeights)
{
  // One triangle, measured directly with Point_3 targets: a flat image is a flat cell.
  Mesh mesh;
  const auto a = mesh.add_vertex(Point_3(0, 0, 0)), b = mesh.add_vertex(Point_3(1, 0, 0)), c = mesh.add_vertex(Point_3(0, 1, 0));
  mesh.add_face(a, b, c);
  auto target = mesh.add_property_map<Mesh::Vertex_index, Point_3>("v:target").first;
  const auto measure_with = [&](const Point_3& pa, const Point_3& pb, const Point_3& pc, auto measure) {
    target[a] = pa, target[b] = pb, target[c] = pc;
    return CGAL::compute_distortion(mesh, target, measure);
  };
  const Point_3 o(1, 1, 1);
  // Collinear image (scaled by 2 along the first edge, the third vertex on it).
  DO::Distortion_statistics s = measure_with(o, Point_3(1, 1, 3), Point_3(1, 1, 2), DO::MIPS());
  EXPECT_EQ(s.max, std::numeric_limits<double>::infinity());
  EXPECT_EQ(s.inverted_cells, 0u);
  s = measure_with(o, Point_3(1, 1, 3), Point_3(1, 1, 2), DO::Dirichlet());
  EXPECT_NEAR(s.max, (4. + 1.) / 2., 1e-15);   // J = [2 1; 0 0]: |J|^2 / 2
  // The first two vertices on one point (zero first edge): finite, flat.
  s = measure_with(o, o, Point_3(1, 3, 1), DO::Dirichlet());
  EXPECT_NEAR(s.max, 4. / 2., 1e-15);   // J = [0 2; 0 0]
  s = measure_with(o, o, o, DO::ARAP());
  EXPECT_NEAR(s.max, 2., 1e-15);
  s = measure_with(o, o, Point_3(1, 3, 1), DO::Symmetric_dirichlet());
  EXPECT_EQ(s.max, std::numeric_limits<double>::infinity());
  // Non-finite targets and weights are named by vertex.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  try {
    measure_with(o, Point_3(1, nan, 1), o, DO::MIPS());
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& error) {
    EXPECT_NE(std::string(error.what()).find("vertex 1 has a non-finite target"), std::string::npos) << error.what();
  }

  // Vertex weights: per vertex, as for planar targets (two triangles sharing an edge).
  const auto d = mesh.add_vertex(Point_3(1, 1, 0));
  mesh.add_face(b, d, c);
  target[a] = Point_3(0, 0, 0), target[b] = Point_3(0, 0, 1), target[c] = Point_3(0, 1, 0), target[d] = Point_3(0, 1, 2);
  auto omega = mesh.add_property_map<Mesh::Vertex_index, double>("v:omega", 1.).first;
  omega[d] = 5;
  const auto per_face = mesh.add_property_map<Mesh::Face_index, double>("f:d", 0.).first;
  s = CGAL::compute_distortion(mesh, target, DO::Dirichlet(),
                               DO::parameters::cell_distortion_map(per_face, DO::parameters::vertex_weight_map(omega)));
  const double d0 = per_face[Mesh::Face_index(0)], d1 = per_face[Mesh::Face_index(1)];
  EXPECT_NEAR(s.energy_uniform, 3 * d0 + 7 * d1, 1e-14);
  EXPECT_NEAR(s.mean_uniform, (3 * d0 + 7 * d1) / 10, 1e-14);
  omega[c] = -1;
  try {
    CGAL::compute_distortion(mesh, target, DO::Dirichlet(), DO::parameters::vertex_weight_map(omega));
    ADD_FAILURE() << "no exception";
  } catch(const DO::Invalid_input& error) {
    EXPECT_NE(std::string(error.what()).find("vertex 2 has a weight"), std::string::npos) << error.what();
  }
}

} // namespace
