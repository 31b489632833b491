// compute_atlas() on closed surfaces of genus 0, 1 and 2 and on several pieces (CGAL's data):
// every chart of genus 0, valid UVs (exact orientation, no border crossing, in the unit square),
// seams that only split the UVs, and the surface unchanged.

#include "test_meshes.h"

#include <CGAL/Distortion_optimization/atlas.h>
#include <CGAL/Distortion_optimization/global_injectivity.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace test_meshes;

std::string data(const std::string& name) { return std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/" + name; }

struct Checked_atlas
{
  DO::Atlas_result result;
  std::size_t pieces_of_genus_zero = 0, pieces = 0, borders = 0;
  double uv_area = 0;   // the charts' share of the unit square
};

// Runs compute_atlas() on `mesh` and checks what holds for any atlas; returns the result and the
// genus count of the mesh the UV corners make (one vertex per distinct UV of a vertex).
// `min_chart_fill` 0: no chart split for packing.
Checked_atlas check_atlas(Mesh3& mesh, const std::vector<Mesh3::Edge_index>& user_seams = {}, double max_distortion = 0,
                          double min_chart_fill = 0.6)
{
  const std::vector<Point_3> before(mesh.points().begin(), mesh.points().end());
  auto uv = mesh.add_property_map<Mesh3::Halfedge_index, Point_2>("h:uv").first;
  auto chart = mesh.add_property_map<Mesh3::Face_index, std::size_t>("f:chart").first;
  auto seam = mesh.add_property_map<Mesh3::Edge_index, bool>("e:seam", false).first;
  for(auto e : user_seams) seam[e] = true;
  Checked_atlas c;
  c.result = DO::compute_atlas(mesh, uv, DO::Symmetric_dirichlet(),
                               DO::parameters::face_chart_map(chart, DO::parameters::edge_is_seam_map(seam, DO::parameters::max_distortion(max_distortion, DO::parameters::min_chart_fill(min_chart_fill)))));
  EXPECT_TRUE(std::equal(before.begin(), before.end(), mesh.points().begin()));
  EXPECT_EQ(c.result.inverted_faces, 0u);
  EXPECT_EQ(c.result.overlapping_charts, 0u);

  // Across an edge that is neither a seam nor a border, both faces give its ends the same UVs; a
  // seam gives one of them two.
  std::size_t seams = 0;
  for(auto e : mesh.edges()) {
    if(mesh.is_border(e)) continue;
    const auto h = mesh.halfedge(e), g = mesh.opposite(h);
    const bool same = uv[h] == uv[mesh.prev(g)] && uv[g] == uv[mesh.prev(h)];
    EXPECT_EQ(same, !seam[e]) << "edge " << std::size_t(e);
    EXPECT_EQ(chart[mesh.face(h)] == chart[mesh.face(g)] || seam[e], true);
    seams += seam[e];
  }
  EXPECT_EQ(seams > 0, c.result.seam_length_fraction > 0);
  for(auto e : user_seams) EXPECT_TRUE(seam[e]);

  // The cut mesh: every UV triangle positive (exact), inside the unit square, each piece of genus
  // 0, and no border crossing another.
  Mesh3 cut;
  std::vector<Point_2> cut_uv;
  std::map<std::tuple<std::size_t, double, double>, Mesh3::Vertex_index> corner;
  for(auto f : mesh.faces()) {
    std::vector<Mesh3::Vertex_index> t;
    std::vector<Point_2> p;
    for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const auto key = std::make_tuple(std::size_t(mesh.target(h)), uv[h].x(), uv[h].y());
      auto at = corner.find(key);
      if(at == corner.end()) {
        at = corner.emplace(key, cut.add_vertex(mesh.point(mesh.target(h)))).first;
        cut_uv.push_back(uv[h]);
      }
      t.push_back(at->second);
      p.push_back(uv[h]);
      EXPECT_TRUE(uv[h].x() >= 0 && uv[h].x() <= 1 && uv[h].y() >= 0 && uv[h].y() <= 1);
    }
    EXPECT_EQ(CGAL::orientation(p[0], p[1], p[2]), CGAL::LEFT_TURN);
    c.uv_area += CGAL::area(p[0], p[1], p[2]);
    EXPECT_NE(cut.add_face(t), Mesh3::null_face());
  }
  EXPECT_TRUE(DO::is_boundary_embedded(cut, CGAL::make_property_map(cut_uv)));
  auto piece = cut.add_property_map<Mesh3::Face_index, std::size_t>("f:piece").first;
  c.pieces = CGAL::Polygon_mesh_processing::connected_components(cut, piece);
  std::vector<long long> euler(c.pieces, 0), borders(c.pieces, 0);   // V - E + F and the borders of each piece
  const auto piece_of = [&](Mesh3::Halfedge_index h) {
    return piece[cut.is_border(h) ? cut.face(cut.opposite(h)) : cut.face(h)];
  };
  for(auto f : cut.faces()) ++euler[piece[f]];
  for(auto e : cut.edges()) --euler[piece_of(cut.halfedge(e))];
  for(auto v : cut.vertices()) ++euler[piece_of(cut.halfedge(v))];
  std::vector<Mesh3::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(cut, std::back_inserter(cycles));
  for(auto h : cycles) ++borders[piece[cut.face(cut.opposite(h))]];
  for(std::size_t k = 0; k < c.pieces; ++k) {
    EXPECT_GT(borders[k], 0);
    c.borders += std::size_t(borders[k]);
    c.pieces_of_genus_zero += euler[k] == 2 - borders[k];
  }
  EXPECT_EQ(c.pieces, c.result.charts);   // each chart's UVs apart from the others'
  EXPECT_EQ(c.pieces_of_genus_zero, c.pieces);
  return c;
}

Mesh3 read(const std::string& name)
{
  Mesh3 mesh;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(data(name), mesh)) << "missing " << data(name);
  return mesh;
}

TEST(Atlas, HandlesAreCutOpenByShortLoops)
{
  for(const auto& [name, genus] : {std::pair<std::string, int>{"eight.off", 2}, {"knot1.off", 1}}) {
    Mesh3 mesh = read(name);
    ASSERT_EQ(long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces()), 2 - 2 * genus);
    const Checked_atlas c = check_atlas(mesh, {}, 0, 0);   // not split for packing: the handles' seams alone
    EXPECT_EQ(c.result.charts, 1u) << name;
    EXPECT_GT(c.result.seam_length_fraction, 0) << name;
    // A handle's loops are short, and the surfaces flatten with little distortion.
    EXPECT_LT(c.result.seam_length_fraction, 0.08) << name;
    EXPECT_LT(c.result.mean_distortion, 1.1) << name;
  }
}

TEST(Atlas, AClosedSurfaceOfGenusZeroIsCutToItsCones)
{
  Mesh3 mesh = read("sphere.off");
  const Checked_atlas c = check_atlas(mesh, {}, 0, 0);
  EXPECT_GE(c.result.cones, 2u);
  EXPECT_EQ(c.result.charts, 1u);   // not split for packing: the cones' seams make one disk
  EXPECT_GT(c.result.seam_length_fraction, 0);
}

// CGAL's elephant (closed, genus 0): cut to its cones, its chart's border crosses itself at the
// optimum of the measure alone; the scaffold keeps it one-to-one at little cost.
TEST(Atlas, TheScaffoldKeepsAChartFromOverlappingItself)
{
  Mesh3 mesh = read("elephant.off");
  const Checked_atlas c = check_atlas(mesh);
  EXPECT_GE(c.result.cones, 2u);
  EXPECT_LT(c.result.mean_distortion, 1.1);
}

// An open cylinder of 24 x 8 unit squares, each split in two: developable, with two borders.
Mesh3 cylinder(std::vector<Mesh3::Edge_index>& rim_to_rim)
{
  const int n = 24, m = 8;
  const double radius = 0.5 / std::sin(M_PI / n);   // unit edges around
  Mesh3 mesh;
  for(int k = 0; k <= m; ++k)
    for(int i = 0; i < n; ++i)
      mesh.add_vertex(Point_3(radius * std::cos(2 * M_PI * i / n), radius * std::sin(2 * M_PI * i / n), k));
  const auto v = [&](int i, int k) { return Mesh3::Vertex_index(std::uint32_t(k * n + (i % n))); };
  for(int k = 0; k < m; ++k)
    for(int i = 0; i < n; ++i) {
      mesh.add_face(v(i, k), v(i + 1, k), v(i + 1, k + 1));
      mesh.add_face(v(i, k), v(i + 1, k + 1), v(i, k + 1));
    }
  rim_to_rim.clear();
  for(int k = 0; k < m; ++k) rim_to_rim.push_back(mesh.edge(mesh.halfedge(v(0, k), v(0, k + 1))));
  return mesh;
}

// A case with a known answer: the open cylinder's two borders each turn by 0 on the surface,
// where a hole in the plane turns by -2 pi: the shortest seam from rim to rim (8 unit edges)
// opens it into a disk that unrolls without distortion; a user's seam there leaves no other.
TEST(Atlas, AnOpenCylinderIsCutFromRimToRimAndUnrolls)
{
  std::vector<Mesh3::Edge_index> seam;
  Mesh3 tube = cylinder(seam);
  double length = 0;
  for(auto e : tube.edges()) length += std::sqrt(CGAL::to_double(CGAL::squared_distance(tube.point(tube.vertex(e, 0)), tube.point(tube.vertex(e, 1)))));
  const Checked_atlas automatic = check_atlas(tube);
  EXPECT_EQ(automatic.result.cones, 0u);
  EXPECT_EQ(automatic.borders, 1u);
  EXPECT_NEAR(automatic.result.seam_length_fraction, 8 / length, 1e-12);
  EXPECT_LT(automatic.result.mean_distortion, 1.001);
  Mesh3 strip = cylinder(seam);
  const Checked_atlas cut = check_atlas(strip, seam);
  EXPECT_EQ(cut.borders, 1u);
  EXPECT_NEAR(cut.result.seam_length_fraction, 8 / length, 1e-12);
  EXPECT_LT(cut.result.mean_distortion, 1.001);
}

// A surface of genus 0 with several borders (CGAL's holes.off, 7) is a planar domain: one chart
// with its holes open where their borders turn as holes in the plane do (by -2 pi, to 5 degrees);
// the three that turn further off (by 33, 7 and 7 degrees) are joined to the outer border by seams.
TEST(Atlas, ASurfaceWithHolesIsOneChartWithItsHolesOpen)
{
  Mesh3 mesh = read("holes.off");
  const Checked_atlas c = check_atlas(mesh);
  EXPECT_EQ(c.result.charts, 1u);
  EXPECT_EQ(c.borders, 4u);
  EXPECT_GT(c.result.seam_length_fraction, 0);
  EXPECT_LT(c.result.seam_length_fraction, 0.0075);   // xatlas's seams on it
  EXPECT_LT(c.result.mean_distortion, 1.003);         // and its distortion
}

// CGAL's `name` not split for packing and split by default, both checked: the same map either
// way, in more charts when split.
std::pair<Checked_atlas, Checked_atlas> whole_and_split(const std::string& name)
{
  Mesh3 whole = read(name);
  Checked_atlas one = check_atlas(whole, {}, 0, 0);
  Mesh3 mesh = read(name);
  Checked_atlas split = check_atlas(mesh);
  EXPECT_GT(split.result.charts, one.result.charts) << name;
  EXPECT_EQ(split.result.mean_distortion, one.result.mean_distortion) << name;
  EXPECT_EQ(split.result.max_distortion, one.result.max_distortion) << name;
  return {one, split};
}

// A branched chart (the elephant's, flattened: limbs about a body) fills its bounding rectangle
// poorly: split along straight lines, its parts pack more densely, with the same map.
TEST(Atlas, ABranchedChartIsSplitForPackingItsMapUnchanged)
{
  const auto [one, split] = whole_and_split("elephant.off");
  EXPECT_EQ(one.result.charts, 1u);
  EXPECT_GT(split.result.packing_efficiency, one.result.packing_efficiency + 0.05);
  EXPECT_GT(split.uv_area, 0.45);   // of the unit square: the parts' limbs settle into each other's hollows
  EXPECT_GT(split.result.seam_length_fraction, one.result.seam_length_fraction);
}

// CGAL's elephant-with-holes (106 borders, most joined to the outer one by seams) flattens into
// a lacy chart with limbs; each rule of splitting it is packed and the densest kept, with seams
// shorter than xatlas's on it (8.5%). Cuts in 4 directions pack it best (0.58 against 0.49 across
// the longer side alone), cuts across the longer side alone pack lion best (0.69 against 0.57).
TEST(Atlas, TheSplitThatPacksDensestIsKept)
{
  const auto [one, split] = whole_and_split("elephant-with-holes.off");
  EXPECT_GT(split.result.packing_efficiency, 0.55);
  EXPECT_GT(split.result.packing_efficiency, one.result.packing_efficiency + 0.1);
  EXPECT_LT(split.result.seam_length_fraction, 0.085);
  Mesh3 lion = read("lion.off");
  EXPECT_GT(check_atlas(lion).result.packing_efficiency, 0.65);
}

// CGAL's lion (a mask, 5 borders): the seams from its eyes and mouth, whose borders turn unlike
// holes in the plane, bring it to a mean of 1.015 (1.5 with its holes open; xatlas: 1.11, seams
// 4%); under a tighter bound it is cut into charts of nearly constant normal that meet it.
TEST(Atlas, ADistortionBoundCutsAPieceIntoFlatterCharts)
{
  Mesh3 mesh = read("lion.off");
  const Checked_atlas loose = check_atlas(mesh);
  EXPECT_LT(loose.result.mean_distortion, 1.03);
  EXPECT_GT(loose.result.mean_distortion, 1.01);
  EXPECT_LT(loose.result.seam_length_fraction, 0.02);
  Mesh3 again = read("lion.off");
  const Checked_atlas bounded = check_atlas(again, {}, 1.01);
  EXPECT_LE(bounded.result.mean_distortion, 1.01);
  EXPECT_GT(bounded.result.charts, loose.result.charts);
  EXPECT_GT(bounded.result.seam_length_fraction, loose.result.seam_length_fraction);
  EXPECT_LT(bounded.result.seam_length_fraction, 0.04);
}

// A chart shaped like a C and four squares that fit in its mouth: the packer puts them there,
// denser than any packing of the charts' bounding rectangles could be, each chart at the common
// scale, turned but not mirrored, inside the unit square and at least the gutter from the others.
TEST(Atlas, PackingFillsTheHollowsOfCharts)
{
  using Vec = DO::internal::Vector<2>;
  // A chart made of the unit cells `cells` of a grid, each as two counterclockwise triangles.
  const auto chart_of = [](const std::vector<std::array<int, 2>>& cells, double side) {
    DO::internal::Chart_to_pack c;
    for(const auto& [i, j] : cells) {
      const std::size_t first = c.uv.size();
      for(const auto& [di, dj] : {std::array<int, 2>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) c.uv.push_back(side * Vec(i + di, j + dj));
      c.triangles.push_back({first, first + 1, first + 2});
      c.triangles.push_back({first, first + 2, first + 3});
      c.area += side * side;
    }
    return c;
  };
  std::vector<std::array<int, 2>> c_shape;   // 10 x 10, open on the right over rows 2 to 7
  for(int i = 0; i < 10; ++i)
    for(int j = 0; j < 10; ++j)
      if(i < 2 || j < 2 || j >= 8) c_shape.push_back({i, j});
  std::vector<DO::internal::Chart_to_pack> charts{chart_of(c_shape, 1)};
  for(int k = 0; k < 4; ++k) charts.push_back(chart_of({{0, 0}}, 2.5));
  const auto packed_area = [](const DO::internal::Chart_to_pack& c) {
    double a = 0;
    for(const auto& t : c.triangles) a += CGAL::area(Point_2(c.uv[t[0]][0], c.uv[t[0]][1]), Point_2(c.uv[t[1]][0], c.uv[t[1]][1]), Point_2(c.uv[t[2]][0], c.uv[t[2]][1]));
    return a;
  };
  const double gutter = 0.01, efficiency = DO::internal::pack_charts(charts, gutter);
  EXPECT_GT(efficiency, 0.7);   // the rectangles (100 + 4 x 6.25) hold 77: at most 0.62
  const double scale = packed_area(charts[0]) / 52;
  std::vector<CGAL::Triangle_2<K>> triangles;
  std::vector<std::size_t> owner;
  for(std::size_t k = 0; k < charts.size(); ++k) {
    EXPECT_NEAR(packed_area(charts[k]) / charts[k].area, scale, 1e-9 * scale);
    for(const Vec& p : charts[k].uv) EXPECT_TRUE(p[0] >= 0 && p[0] <= 1 && p[1] >= 0 && p[1] <= 1);
    for(const auto& t : charts[k].triangles) {
      triangles.emplace_back(Point_2(charts[k].uv[t[0]][0], charts[k].uv[t[0]][1]), Point_2(charts[k].uv[t[1]][0], charts[k].uv[t[1]][1]),
                             Point_2(charts[k].uv[t[2]][0], charts[k].uv[t[2]][1]));
      owner.push_back(k);
      EXPECT_EQ(triangles.back().orientation(), CGAL::COUNTERCLOCKWISE);
    }
  }
  double nearest = std::numeric_limits<double>::infinity();
  std::size_t inside = 0;   // squares in the C's bounding box
  for(std::size_t a = 0; a < triangles.size(); ++a)
    for(std::size_t b = a + 1; b < triangles.size(); ++b) {
      if(owner[a] == owner[b]) continue;
      ASSERT_FALSE(CGAL::do_intersect(triangles[a], triangles[b]));
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j)
          nearest = (std::min)(nearest, CGAL::squared_distance(CGAL::Segment_2<K>(triangles[a][i], triangles[a][i + 1]),
                                                               CGAL::Segment_2<K>(triangles[b][j], triangles[b][j + 1])));
    }
  EXPECT_GE(std::sqrt(nearest), gutter * (1 - 1e-9));
  const auto squares = triangles.begin() + std::ptrdiff_t(2 * c_shape.size());
  const auto box = CGAL::bbox_2(triangles.begin(), squares);
  for(std::size_t k = 0; k + 1 < charts.size(); ++k) inside += CGAL::do_overlap(box, CGAL::bbox_2(squares + 2 * k, squares + 2 * k + 2));
  EXPECT_GE(inside, 3u);
}

TEST(Atlas, SeveralPiecesArePackedApartAtOneScale)
{
  Mesh3 mesh = read("eight.off");
  Mesh3 knot = read("knot1.off");
  CGAL::copy_face_graph(knot, mesh);
  const Checked_atlas c = check_atlas(mesh, {}, 0, 0);
  EXPECT_EQ(c.result.charts, 2u);   // one by piece, not split for packing
  EXPECT_GT(c.result.packing_efficiency, 0.3);
  EXPECT_LE(c.result.packing_efficiency, 1);
}

TEST(Atlas, BadParametersAreRefused)
{
  Mesh3 mesh = read("eight.off");
  auto uv = mesh.add_property_map<Mesh3::Halfedge_index, Point_2>("h:uv").first;
  EXPECT_THROW(DO::compute_atlas(mesh, uv, DO::Symmetric_dirichlet(), DO::parameters::atlas_gutter(0.3)), DO::Invalid_input);
  EXPECT_THROW(DO::compute_atlas(mesh, uv, DO::Symmetric_dirichlet(), DO::parameters::cone_log_scale(0.)), DO::Invalid_input);
  // A closed surface with a face of zero area, named by its index.
  Mesh3 flat;
  const auto p0 = flat.add_vertex(Point_3(0, 0, 0)), p1 = flat.add_vertex(Point_3(1, 0, 0)), p2 = flat.add_vertex(Point_3(2, 0, 0)),
             p3 = flat.add_vertex(Point_3(0, 0, 1));
  flat.add_face(p0, p2, p1), flat.add_face(p0, p1, p3), flat.add_face(p1, p2, p3), flat.add_face(p0, p3, p2);
  auto flat_uv = flat.add_property_map<Mesh3::Halfedge_index, Point_2>("h:uv").first;
  try {
    DO::compute_atlas(flat, flat_uv, DO::Symmetric_dirichlet());
    ADD_FAILURE() << "a degenerate face was accepted";
  } catch(const DO::Invalid_input& e) {
    EXPECT_EQ(std::string(e.what()), "face 0 is degenerate (its corners are collinear)");
  }
  Mesh3 empty;
  auto none = empty.add_property_map<Mesh3::Halfedge_index, Point_2>("h:uv").first;
  EXPECT_THROW(DO::compute_atlas(empty, none, DO::Symmetric_dirichlet()), DO::Invalid_input);
}

} // namespace
