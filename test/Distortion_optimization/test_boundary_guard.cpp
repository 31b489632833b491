// Boundary_guard: boundary extraction, exact accept/reject of boundary moves, soundness after the
// stored boxes drift, and agreement with a brute-force all-pairs check (exact constructions).

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/internal/minimize.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/Intersections_2/Triangle_2_Triangle_2.h>
#include <CGAL/Intersections_3/Tetrahedron_3_Tetrahedron_3.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace {

namespace DOI = CGAL::Distortion_optimization::internal;
using DOI::Vector;
using Guard2 = DOI::Boundary_guard<2>;
using Guard3 = DOI::Boundary_guard<3>;
using Index = std::uint32_t;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;

template <int n>
struct Map
{
  std::vector<Vector<n>> target;
  std::vector<std::array<Index, n + 1>> cells;
};

// k x k vertices at integer points (i, j), vertex i + k j, two triangles per square.
Map<2> grid_2(int k)
{
  Map<2> m;
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) m.target.emplace_back(i, j);
  for(int j = 0; j + 1 < k; ++j)
    for(int i = 0; i + 1 < k; ++i) {
      const Index a = i + k * j, b = a + 1, c = a + k, d = c + 1;
      m.cells.push_back({a, b, d});
      m.cells.push_back({a, d, c});
    }
  return m;
}

// k^3 unit cubes at integer points, vertex i + (k+1) (j + (k+1) l), each cube split into the 6
// Kuhn tetrahedra along its main diagonal (a conforming mesh).
Map<3> grid_3(int k)
{
  Map<3> m;
  const int s = k + 1;
  for(int l = 0; l < s; ++l)
    for(int j = 0; j < s; ++j)
      for(int i = 0; i < s; ++i) m.target.emplace_back(i, j, l);
  auto id = [s](int i, int j, int l) { return Index(i + s * (j + s * l)); };
  for(int l = 0; l < k; ++l)
    for(int j = 0; j < k; ++j)
      for(int i = 0; i < k; ++i) {
        std::array<int, 3> axes = {0, 1, 2};
        do {
          std::array<int, 3> c = {i, j, l};
          std::array<Index, 4> cell;
          cell[0] = id(c[0], c[1], c[2]);
          for(int step = 0; step < 3; ++step) {
            ++c[axes[step]];
            cell[step + 1] = id(c[0], c[1], c[2]);
          }
          m.cells.push_back(cell);
        } while(std::next_permutation(axes.begin(), axes.end()));
      }
  return m;
}

template <std::size_t m>
std::set<std::array<Index, m>> sorted_set(const std::vector<std::array<Index, m>>& faces)
{
  std::set<std::array<Index, m>> result;
  for(auto f : faces) {
    std::sort(f.begin(), f.end());
    result.insert(f);
  }
  return result;
}

// Brute force: every pair of faces intersected with exact constructions; a pair is improper unless
// the intersection is empty or exactly the vertex / edge the two faces share by index.
bool brute_force_injective(const std::vector<Guard2::Face>& faces, const std::vector<Vector<2>>& t)
{
  auto p = [&](Index v) { return EK::Point_2(t[v][0], t[v][1]); };
  auto box = [&](const Guard2::Face& f) { return p(f[0]).bbox() + p(f[1]).bbox(); };   // exact: double input
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(std::size_t j = i + 1; j < faces.size(); ++j) {
      const auto &a = faces[i], &b = faces[j];
      std::vector<Index> shared;
      for(Index u : a)
        if(std::find(b.begin(), b.end(), u) != b.end()) shared.push_back(u);
      if(shared.size() == 2 || !CGAL::do_overlap(box(a), box(b))) continue;
      const auto x = CGAL::intersection(EK::Segment_2(p(a[0]), p(a[1])), EK::Segment_2(p(b[0]), p(b[1])));
      if(!x) continue;
      const EK::Point_2* point = boost::get<EK::Point_2>(&*x);
      if(point == nullptr || shared.empty() || *point != p(shared[0])) return false;
    }
  return true;
}

// Whether faces with no common vertex are farther apart than 1e-12 of the largest coordinate:
// the guard's moves keep a clearance of 64 units in the last place (a vertex moved to the rounded
// midpoint of a segment is 1e-16 off it: injective, yet refused).
template <int n, class Face>
bool clear_of_each_other(const std::vector<Face>& faces, const std::vector<Vector<n>>& t)
{
  using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
  double largest = 0;
  for(const auto& x : t) largest = std::max(largest, x.cwiseAbs().maxCoeff());
  const auto object = [&](const Face& f) {
    if constexpr(n == 2) return IK::Segment_2(IK::Point_2(t[f[0]][0], t[f[0]][1]), IK::Point_2(t[f[1]][0], t[f[1]][1]));
    else {
      auto p = [&](Index v) { return IK::Point_3(t[v][0], t[v][1], t[v][2]); };
      return IK::Triangle_3(p(f[0]), p(f[1]), p(f[2]));
    }
  };
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(std::size_t j = i + 1; j < faces.size(); ++j) {
      bool shared = false;
      for(Index u : faces[i]) shared = shared || std::find(faces[j].begin(), faces[j].end(), u) != faces[j].end();
      if(!shared && !(CGAL::squared_distance(object(faces[i]), object(faces[j])) > std::pow(1e-12 * largest, 2))) return false;
    }
  return true;
}

// Only the pairs with a face of `moved` when given (the exact constructions are slow in 3D).
bool brute_force_injective(const std::vector<Guard3::Face>& faces, const std::vector<Vector<3>>& t,
                           const Index* moved = nullptr)
{
  auto p = [&](Index v) { return EK::Point_3(t[v][0], t[v][1], t[v][2]); };
  auto box = [&](const Guard3::Face& f) { return p(f[0]).bbox() + p(f[1]).bbox() + p(f[2]).bbox(); };   // exact too
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(std::size_t j = i + 1; j < faces.size(); ++j) {
      const auto &a = faces[i], &b = faces[j];
      auto has_moved = [&](const Guard3::Face& f) { return std::find(f.begin(), f.end(), *moved) != f.end(); };
      if(moved != nullptr && !has_moved(a) && !has_moved(b)) continue;
      std::vector<Index> shared;
      for(Index u : a)
        if(std::find(b.begin(), b.end(), u) != b.end()) shared.push_back(u);
      const EK::Triangle_3 ta(p(a[0]), p(a[1]), p(a[2])), tb(p(b[0]), p(b[1]), p(b[2]));
      if(ta.is_degenerate() || tb.is_degenerate()) return false;
      if(!CGAL::do_overlap(box(a), box(b))) continue;
      const auto x = CGAL::intersection(ta, tb);
      if(!x) continue;
      if(shared.size() == 1) {
        const EK::Point_3* point = boost::get<EK::Point_3>(&*x);
        if(point == nullptr || *point != p(shared[0])) return false;
      } else if(shared.size() == 2) {
        const EK::Segment_3* segment = boost::get<EK::Segment_3>(&*x);
        const EK::Segment_3 edge(p(shared[0]), p(shared[1]));
        if(segment == nullptr || (*segment != edge && *segment != edge.opposite())) return false;
      } else {
        return false;
      }
    }
  return true;
}

template <class Guard>
std::vector<Index> boundary_vertices(std::size_t number_of_vertices, const Guard& guard)
{
  std::vector<Index> result;
  for(Index v = 0; v < number_of_vertices; ++v)
    if(guard.is_on_boundary(v)) result.push_back(v);
  return result;
}


// Random moves of the boundary vertices of m (move(v) changes m.target[v]): the guard's answers,
// accepts_move and is_injective, must both be `expected(v)`; an injective move is committed, any
// other undone. Counts the accepted and rejected moves.
template <int n, class Move, class Expected>
void check_random_moves(Map<n>& m, DOI::Boundary_guard<n>& guard, const std::vector<Index>& boundary,
                        std::mt19937& rng, int moves, const Move& move, const Expected& expected,
                        int& accepted, int& rejected)
{
  std::uniform_int_distribution<std::size_t> pick(0, boundary.size() - 1);
  accepted = rejected = 0;
  for(int k = 0; k < moves; ++k) {
    const Index v = boundary[pick(rng)];
    const Vector<n> before = m.target[v];
    move(v);
    const bool injective = expected(v);
    ASSERT_EQ(guard.accepts_move(v, m.target), injective) << "move " << k;
    ASSERT_EQ(guard.is_injective(m.target, nullptr, guard.keeps_clearance() ? 1. : 0.), injective) << "move " << k;
    if(injective) {
      guard.commit_move(v, m.target);
      ++accepted;
    } else {
      m.target[v] = before;
      ++rejected;
    }
  }
}

// The square annulus [0, 3]^2 minus the hole [1, 2]^2: grid_2(4) without its middle square.
Map<2> annulus_2()
{
  Map<2> m = grid_2(4);
  m.cells.erase(m.cells.begin() + 8, m.cells.begin() + 10);
  return m;
}

// The cube [0, 3]^3 with the cavity [1, 2]^3: grid_3(3) without its middle cube.
Map<3> hollow_cube()
{
  Map<3> m = grid_3(3);
  m.cells.erase(m.cells.begin() + 6 * 13, m.cells.begin() + 6 * 14);
  return m;
}

// Appends a piece of one cell on new vertices at `corners`.
template <int n>
void add_simplex(Map<n>& m, const std::array<Vector<n>, n + 1>& corners)
{
  std::array<Index, n + 1> cell;
  for(int i = 0; i <= n; ++i) {
    cell[i] = Index(m.target.size());
    m.target.push_back(corners[i]);
  }
  m.cells.push_back(cell);
}

template <int n>
DOI::Boundary_guard<n> guard_of_pieces(const Map<n>& m)
{
  return DOI::Boundary_guard<n>(DOI::Boundary_guard<n>::boundary_faces(m.cells), m.target.size(),
                                DOI::connected_pieces(m.cells, m.target.size()));
}

// Whether the guard finds `m` with a piece of one cell at `corners` added injective.
template <int n>
bool injective_with(Map<n> m, const std::array<Vector<n>, n + 1>& corners)
{
  add_simplex(m, corners);
  return guard_of_pieces(m).is_injective(m.target);
}

// Brute force: no two cells of different pieces meet (closed cells, exact constructions).
template <int n>
bool pieces_apart(const Map<n>& m)
{
  const auto piece = DOI::connected_pieces(m.cells, m.target.size());
  const auto simplex = [&](const std::array<Index, n + 1>& c) {
    const auto& t = m.target;
    if constexpr(n == 2) {
      auto p = [&](Index v) { return EK::Point_2(t[v][0], t[v][1]); };
      return EK::Triangle_2(p(c[0]), p(c[1]), p(c[2]));
    } else {
      auto p = [&](Index v) { return EK::Point_3(t[v][0], t[v][1], t[v][2]); };
      return EK::Tetrahedron_3(p(c[0]), p(c[1]), p(c[2]), p(c[3]));
    }
  };
  for(std::size_t i = 0; i < m.cells.size(); ++i)
    for(std::size_t j = i + 1; j < m.cells.size(); ++j)
      if(piece[m.cells[i][0]] != piece[m.cells[j][0]] && CGAL::do_intersect(simplex(m.cells[i]), simplex(m.cells[j])))
        return false;
  return true;
}

// The orientation of each cell (exact).
template <int n>
std::vector<CGAL::Orientation> orientations(const Map<n>& m)
{
  using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<CGAL::Orientation> result;
  for(const auto& c : m.cells) {
    const auto& t = m.target;
    if constexpr(n == 2)
      result.push_back(CGAL::orientation(IK::Point_2(t[c[0]][0], t[c[0]][1]), IK::Point_2(t[c[1]][0], t[c[1]][1]),
                                         IK::Point_2(t[c[2]][0], t[c[2]][1])));
    else {
      auto p = [&](Index v) { return IK::Point_3(t[v][0], t[v][1], t[v][2]); };
      result.push_back(CGAL::orientation(p(c[0]), p(c[1]), p(c[2]), p(c[3])));
    }
  }
  return result;
}

// Random moves of all boundary vertices of a map in pieces, each cell kept in its orientation (the
// guard's precondition: moves that flip one are undone unasked). is_injective() must agree with
// the brute force, and a move that accepts_move() takes must be injective. Counts the accepted
// moves, the refused that nest pieces without any crossing, and the refused that were injective
// (the sweeps' test is conservative); the first two must exceed their minimums.
template <int n>
void check_random_moves_of_pieces(Map<n>& m, unsigned seed, int moves, double step, int min_accepted, int min_nested)
{
  std::mt19937 rng(seed);
  int accepted = 0, nested = 0, conservative = 0;
  const auto faces = DOI::Boundary_guard<n>::boundary_faces(m.cells);
  DOI::Boundary_guard<n> guard = guard_of_pieces(m);
  guard.rebuild(m.target);
  ASSERT_TRUE(guard.several_pieces());
  ASSERT_TRUE(guard.is_injective(m.target));
  const std::vector<Index> boundary = boundary_vertices(m.target.size(), guard);
  const std::vector<CGAL::Orientation> signs = orientations(m);
  std::uniform_int_distribution<std::size_t> pick(0, boundary.size() - 1);
  std::normal_distribution<double> normal(0, step);
  std::uniform_real_distribution<double> reach(0.5, 1.5);
  const std::vector<Index> piece = DOI::connected_pieces(m.cells, m.target.size());
  for(int k = 0; k < moves; ++k) {
    Index v = boundary[pick(rng)];
    // Every other move: the boundary vertex of another piece nearest to v goes towards, onto or
    // past v, to sweep over pieces often.
    const Index lure = v;
    if(k % 2)
      for(Index u : boundary)
        if(piece[u] != piece[lure] && (v == lure || (m.target[u] - m.target[lure]).norm() < (m.target[v] - m.target[lure]).norm()))
          v = u;
    const Vector<n> before = m.target[v];
    if(v != lure) m.target[v] += reach(rng) * (m.target[lure] - before);
    for(int i = 0; i < n; ++i) m.target[v][i] += normal(rng);
    if(orientations(m) != signs) {
      m.target[v] = before;
      continue;
    }
    bool crossing_free;
    if constexpr(n == 2) crossing_free = brute_force_injective(faces, m.target);
    else crossing_free = brute_force_injective(faces, m.target, &v);
    const bool apart = pieces_apart(m);
    ASSERT_EQ(guard.is_injective(m.target), crossing_free && apart) << "move " << k;
    const bool accepts = guard.accepts_move(v, m.target);
    ASSERT_TRUE(!accepts || (crossing_free && apart)) << "move " << k;
    if(accepts) {
      guard.commit_move(v, m.target);
      ++accepted;
    } else {
      m.target[v] = before;
      nested += crossing_free && !apart;
      conservative += crossing_free && apart;
    }
  }
  std::printf("%dD pieces: %d accepted, %d refused nested, %d refused injective\n", n, accepted, nested, conservative);
  EXPECT_GT(accepted, min_accepted);
  EXPECT_GT(nested, min_nested);
}

} // namespace

TEST(BoundaryGuard, BoundaryFacesOfTwoTrianglesAndTwoTets)
{
  const auto square = Guard2::boundary_faces({{0, 1, 2}, {0, 2, 3}});
  EXPECT_EQ(square.size(), 4u);
  EXPECT_EQ(sorted_set(square), (std::set<std::array<Index, 2>>{{0, 1}, {1, 2}, {2, 3}, {0, 3}}));

  const auto tets = Guard3::boundary_faces({{0, 1, 2, 3}, {1, 2, 3, 4}});
  EXPECT_EQ(tets.size(), 6u);
  EXPECT_EQ(sorted_set(tets), (std::set<std::array<Index, 3>>{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 4},
                                                              {1, 3, 4}, {2, 3, 4}}));
  EXPECT_EQ(Guard3::boundary_faces(grid_3(2).cells).size(), 6u * 4 * 2);

  Guard2 guard(square, 5);
  EXPECT_FALSE(guard.empty());
  EXPECT_TRUE(guard.is_on_boundary(3));
  EXPECT_FALSE(guard.is_on_boundary(4));
  EXPECT_TRUE(Guard2({}, 3).empty());
}

TEST(BoundaryGuard, PlanarCrossingAndSmallMove)
{
  Map<2> m = grid_2(5);   // [0, 4]^2
  Guard2 guard(Guard2::boundary_faces(m.cells), m.target.size());
  ASSERT_EQ(boundary_vertices(m.target.size(), guard).size(), 16u);
  guard.rebuild(m.target);
  EXPECT_TRUE(guard.is_injective(m.target));

  const Index left_middle = 0 + 5 * 2;
  const Vector<2> rest = m.target[left_middle];
  m.target[left_middle] = Vector<2>(5, 2);   // beyond the right side
  EXPECT_FALSE(guard.accepts_move(left_middle, m.target));
  EXPECT_FALSE(guard.is_injective(m.target));
  m.target[left_middle] = Vector<2>(4, 2);   // onto the right side's vertex
  EXPECT_FALSE(guard.accepts_move(left_middle, m.target));
  m.target[left_middle] = Vector<2>(3.999, 2);   // inside, touching nothing
  EXPECT_TRUE(guard.accepts_move(left_middle, m.target));
  m.target[left_middle] = rest + Vector<2>(-0.1, 0.05);
  EXPECT_TRUE(guard.accepts_move(left_middle, m.target));
  EXPECT_TRUE(guard.is_injective(m.target));
  EXPECT_TRUE(guard.accepts_move(2 * 5 + 2, m.target));   // an interior vertex never matters
}

TEST(BoundaryGuard, AdjacentSegmentsOverlappingCollinearly)
{
  // One triangle: its three boundary segments are pairwise adjacent.
  std::vector<Vector<2>> t = {Vector<2>(0, 0), Vector<2>(4, 0), Vector<2>(0, 4)};
  Guard2 guard(Guard2::boundary_faces({{0, 1, 2}}), 3);
  guard.rebuild(t);
  t[2] = Vector<2>(2, 0);   // folded onto segment 01
  EXPECT_FALSE(guard.accepts_move(2, t));
  EXPECT_FALSE(guard.is_injective(t));
  t[2] = Vector<2>(6, 0);   // beyond vertex 1 on the same line
  EXPECT_FALSE(guard.accepts_move(2, t));
  t[2] = Vector<2>(0, 0);   // onto vertex 0
  EXPECT_FALSE(guard.accepts_move(2, t));
  t[2] = Vector<2>(2, 1e-300);   // exact predicates see it off the line
  EXPECT_TRUE(guard.accepts_move(2, t));
  EXPECT_TRUE(guard.is_injective(t));
  t[2] = Vector<2>(2, -1e-300);   // inverted, but the boundary alone is still a simple polygon
  EXPECT_TRUE(guard.accepts_move(2, t));

  // An open polyline: the only pair is the moved vertex's own two segments.
  std::vector<Vector<2>> line = {Vector<2>(0, 0), Vector<2>(1, 0), Vector<2>(2, 0)};
  Guard2 open({{0, 1}, {1, 2}}, 3);
  open.rebuild(line);
  EXPECT_TRUE(open.accepts_move(1, line));
  line[1] = Vector<2>(3, 0);   // both segments now leave vertex 1 towards -x
  EXPECT_FALSE(open.accepts_move(1, line));
  EXPECT_FALSE(open.is_injective(line));
  line[1] = Vector<2>(3, 1e-300);
  EXPECT_TRUE(open.accepts_move(1, line));

  // A collapsed segment is rejected even with nothing else around (its cell is degenerate).
  std::vector<Vector<2>> ends = {Vector<2>(0, 0), Vector<2>(1, 0)};
  Guard2 single({{0, 1}}, 2);
  single.rebuild(ends);
  EXPECT_TRUE(single.is_injective(ends));
  ends[1] = ends[0];
  EXPECT_FALSE(single.accepts_move(1, ends));
  EXPECT_FALSE(single.is_injective(ends));

  // Collinear neighbours on opposite sides of the shared vertex are fine (the grid's straight sides).
  Map<2> m = grid_2(3);
  Guard2 grid(Guard2::boundary_faces(m.cells), m.target.size());
  grid.rebuild(m.target);
  EXPECT_TRUE(grid.accepts_move(1, m.target));
  m.target[1] = Vector<2>(-0.5, 0);   // bottom middle slides past the corner: its two segments fold
  EXPECT_FALSE(grid.accepts_move(1, m.target));
}

TEST(BoundaryGuard, SoundAfterDriftBeyondTheMargin)
{
  Map<2> m = grid_2(6);   // [0, 5]^2, 20 boundary segments
  Guard2 guard(Guard2::boundary_faces(m.cells), m.target.size());
  guard.rebuild(m.target);
  const std::vector<Index> boundary = boundary_vertices(m.target.size(), guard);
  // Translate the boundary by (40, 25) in small accepted moves, one vertex at a time: every stored
  // box is left behind many times (refits, then rebuilds).
  for(int round = 0; round < 400; ++round)
    for(Index v : boundary) {
      m.target[v] += Vector<2>(0.1, 0.0625);
      ASSERT_TRUE(guard.accepts_move(v, m.target)) << round;
      guard.commit_move(v, m.target);
    }
  EXPECT_TRUE(guard.is_injective(m.target));
  const Index left_middle = 0 + 6 * 2, right_middle = 5 + 6 * 2;
  m.target[left_middle] = m.target[right_middle] + Vector<2>(1, 0);
  EXPECT_FALSE(guard.accepts_move(left_middle, m.target));
  m.target[left_middle] = m.target[right_middle] - Vector<2>(0.5, 0);
  EXPECT_TRUE(guard.accepts_move(left_middle, m.target));

  // A chunk of the bottom side of a long polygon sinks by 15 (its faces are refit, too few of them
  // for a rebuild); the tree must then find them where they are, far from any box built at first.
  const int k = 300;
  std::vector<Vector<2>> p;
  std::vector<Guard2::Face> polygon;
  for(int i = 0; i < 4 * k; ++i) {
    const int side = i / k, step = i % k;
    const Vector<2> corner[] = {Vector<2>(0, 0), Vector<2>(k, 0), Vector<2>(k, k), Vector<2>(0, k)};
    const Vector<2> along[] = {Vector<2>(1, 0), Vector<2>(0, 1), Vector<2>(-1, 0), Vector<2>(0, -1)};
    p.push_back(corner[side] + step * along[side]);
    polygon.push_back({Index(i), Index((i + 1) % (4 * k))});
  }
  Guard2 sink(polygon, p.size());
  sink.rebuild(p);
  const Index c = k / 2;   // the chunk is c - 2, ..., c + 2 at (c - 2, 0), ..., (c + 2, 0)
  for(int round = 0; round < 150; ++round)
    for(Index v = c - 2; v <= c + 2; ++v) {
      p[v] += Vector<2>(0, -0.1);
      ASSERT_TRUE(sink.accepts_move(v, p)) << round;
      sink.commit_move(v, p);
    }
  for(int step = 0; step < 10; ++step) {   // a bump at c + 1
    p[c + 1] += Vector<2>(0, 0.1);
    ASSERT_TRUE(sink.accepts_move(c + 1, p));
    sink.commit_move(c + 1, p);
  }
  const double y = p[c][1];
  ASSERT_NEAR(y, -15, 1e-9);
  ASSERT_NEAR(p[c + 1][1], -14, 1e-9);
  // Segment (c - 2, c - 1) crosses (c, c + 1), which shares no vertex with it; the own segments of
  // c - 1 stay apart, so only the tree can see this.
  p[c - 1] = Vector<2>(c + 1, y + 0.5);
  EXPECT_FALSE(sink.accepts_move(c - 1, p));
  EXPECT_FALSE(sink.is_injective(p));
  p[c - 1] = p[c + 2];   // onto a vertex of segments it shares no vertex with
  EXPECT_FALSE(sink.accepts_move(c - 1, p));
  p[c - 1] = Vector<2>(c - 1, y - 0.5);
  EXPECT_TRUE(sink.accepts_move(c - 1, p));
  EXPECT_TRUE(sink.is_injective(p));
}

TEST(BoundaryGuard, AgreesWithBruteForceOnRandomPlanarMoves)
{
  Map<2> m = grid_2(8);
  const auto faces = Guard2::boundary_faces(m.cells);
  Guard2 guard(faces, m.target.size());
  guard.rebuild(m.target);
  const std::vector<Index> boundary = boundary_vertices(m.target.size(), guard);
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::size_t> pick(0, boundary.size() - 1);
  std::uniform_real_distribution<double> small(-0.4, 0.4), large(-8, 8);
  std::uniform_int_distribution<int> kind(0, 3), lattice(-4, 18);
  int accepted, rejected;
  check_random_moves(m, guard, boundary, rng, 600, [&](Index v) {
    switch(kind(rng)) {
      case 0: m.target[v] += Vector<2>(small(rng), small(rng)); break;
      case 1: m.target[v] += Vector<2>(large(rng), large(rng)); break;
      case 2: m.target[v] = Vector<2>(lattice(rng), lattice(rng)) / 2; break;   // exact degeneracies
      default: {   // onto another boundary vertex or the midpoint of one of its segments
        const auto& f = faces[pick(rng) % faces.size()];
        m.target[v] = rng() % 2 ? m.target[f[0]] : Vector<2>((m.target[f[0]] + m.target[f[1]]) / 2);
      }
    }
  }, [&](Index) { return brute_force_injective(faces, m.target) && clear_of_each_other<2>(faces, m.target); }, accepted, rejected);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
}

TEST(BoundaryGuard, TetBoundaryPushedThroughTheOppositeFace)
{
  Map<3> m = grid_3(2);   // [0, 2]^3
  Guard3 guard(Guard3::boundary_faces(m.cells), m.target.size());
  guard.rebuild(m.target);
  EXPECT_TRUE(guard.is_injective(m.target));
  const Index face_centre = 0 + 3 * (1 + 3 * 1);   // (0, 1, 1)
  ASSERT_TRUE(guard.is_on_boundary(face_centre));
  EXPECT_FALSE(guard.is_on_boundary(1 + 3 * (1 + 3 * 1)));
  m.target[face_centre] = Vector<3>(3, 1, 1);
  EXPECT_FALSE(guard.accepts_move(face_centre, m.target));
  EXPECT_FALSE(guard.is_injective(m.target));
  m.target[face_centre] = Vector<3>(2, 1, 1);   // onto the opposite face's centre
  EXPECT_FALSE(guard.accepts_move(face_centre, m.target));
  m.target[face_centre] = Vector<3>(1.9, 1, 1);
  EXPECT_TRUE(guard.accepts_move(face_centre, m.target));
  m.target[face_centre] = Vector<3>(-0.1, 1.05, 0.95);
  EXPECT_TRUE(guard.accepts_move(face_centre, m.target));
  EXPECT_TRUE(guard.is_injective(m.target));
  EXPECT_TRUE(brute_force_injective(Guard3::boundary_faces(m.cells), m.target));
}

TEST(BoundaryGuard, TrianglesSharingAnEdgeOrAVertex)
{
  // One tet: its four boundary triangles pairwise share an edge.
  std::vector<Vector<3>> t = {Vector<3>(0, 0, 0), Vector<3>(4, 0, 0), Vector<3>(0, 4, 0), Vector<3>(0, 0, 4)};
  Guard3 tet(Guard3::boundary_faces({{0, 1, 2, 3}}), 4);
  tet.rebuild(t);
  t[3] = Vector<3>(1, 1, 0);   // coplanar fold into triangle 012
  EXPECT_FALSE(tet.accepts_move(3, t));
  EXPECT_FALSE(tet.is_injective(t));
  t[3] = Vector<3>(1, 1, 1e-300);
  EXPECT_TRUE(tet.accepts_move(3, t));
  t[3] = Vector<3>(2, 0, 0);   // onto edge 01: a degenerate face
  EXPECT_FALSE(tet.accepts_move(3, t));

  // A lone triangle made collinear is rejected.
  std::vector<Vector<3>> lone = {Vector<3>(0, 0, 0), Vector<3>(1, 0, 0), Vector<3>(0, 1, 0)};
  Guard3 one({{0, 1, 2}}, 3);
  one.rebuild(lone);
  EXPECT_TRUE(one.accepts_move(2, lone));
  lone[2] = Vector<3>(3, 0, 0);
  EXPECT_FALSE(one.accepts_move(2, lone));
  EXPECT_FALSE(one.is_injective(lone));

  // An open surface of two triangles on edge 01: only the moved vertex's own pair can fold.
  std::vector<Vector<3>> w = {Vector<3>(0, 0, 0), Vector<3>(4, 0, 0), Vector<3>(0, 4, 0), Vector<3>(0, -4, 0)};
  Guard3 hinge({{0, 1, 2}, {0, 1, 3}}, 4);
  hinge.rebuild(w);
  EXPECT_TRUE(hinge.accepts_move(3, w));   // flat but unfolded
  w[3] = Vector<3>(1, 1, 0);
  EXPECT_FALSE(hinge.accepts_move(3, w));
  EXPECT_FALSE(hinge.is_injective(w));
  w[3] = Vector<3>(1, 1, 1);
  EXPECT_TRUE(hinge.accepts_move(3, w));

  // Two triangles sharing vertex 0 where only edge 12 pierces triangle 034, not edge 34 triangle 012.
  const std::vector<Vector<3>> x = {Vector<3>(0, 0, 0), Vector<3>(2, 0, -1), Vector<3>(2, 0, 1),
                                    Vector<3>(3, -1, 0), Vector<3>(3, 1, 0)};
  Guard3 fan({{0, 1, 2}, {0, 3, 4}}, 5);
  fan.rebuild(x);
  for(Index v = 0; v < 5; ++v) EXPECT_FALSE(fan.accepts_move(v, x)) << v;
  EXPECT_FALSE(fan.is_injective(x));
  Guard3 fan_swapped({{0, 3, 4}, {0, 1, 2}}, 5);
  fan_swapped.rebuild(x);
  EXPECT_FALSE(fan_swapped.is_injective(x));
  EXPECT_FALSE(fan_swapped.accepts_move(3, x));

  // Coplanar triangles sharing vertex 0: overlapping, then apart, then on opposite rays from 0.
  std::vector<Vector<3>> y = {Vector<3>(0, 0, 0), Vector<3>(4, 0, 0), Vector<3>(0, 4, 0), Vector<3>(4, 1, 0),
                              Vector<3>(1, 4, 0)};
  Guard3 flat({{0, 1, 2}, {0, 3, 4}}, 5);
  flat.rebuild(y);
  EXPECT_FALSE(flat.accepts_move(3, y));
  EXPECT_FALSE(flat.is_injective(y));
  y[3] = Vector<3>(-4, -1, 0);
  y[4] = Vector<3>(-1, -4, 0);
  EXPECT_TRUE(flat.accepts_move(3, y));
  EXPECT_TRUE(flat.is_injective(y));
  y[3] = Vector<3>(-4, 0, 0);
  y[4] = Vector<3>(0, -4, 0);
  EXPECT_TRUE(flat.accepts_move(4, y));
  y[3] = Vector<3>(1, 0, 0);   // along edge 01
  EXPECT_FALSE(flat.accepts_move(3, y));

  // Two tets sharing vertex 0, mirror images: they touch only there.
  std::vector<Vector<3>> u = {Vector<3>(0, 0, 0),  Vector<3>(1, 0, 0),  Vector<3>(0, 1, 0), Vector<3>(0, 0, 1),
                              Vector<3>(-1, 0, 0), Vector<3>(0, -1, 0), Vector<3>(0, 0, -1)};
  const auto faces = Guard3::boundary_faces({{0, 1, 2, 3}, {0, 4, 5, 6}});
  ASSERT_EQ(faces.size(), 8u);
  Guard3 pair(faces, u.size());
  pair.rebuild(u);
  EXPECT_TRUE(pair.is_injective(u));
  u[4] = Vector<3>(0.2, 0.2, 0.2);   // edge 45 pierces face 013
  EXPECT_FALSE(pair.accepts_move(4, u));
  EXPECT_FALSE(brute_force_injective(faces, u));
  u[4] = Vector<3>(0.5, 0, 0);   // onto edge 01: the tets share a segment
  EXPECT_FALSE(pair.accepts_move(4, u));
  u[4] = Vector<3>(0.5, -1e-300, 0);   // just off it: only vertex 0 is shared again, but closer than the clearance
  EXPECT_FALSE(pair.accepts_move(4, u));
  EXPECT_TRUE(pair.is_injective(u));
  EXPECT_TRUE(brute_force_injective(faces, u));
  u[4] = Vector<3>(0.5, -1e-10, 0);   // clear of it
  EXPECT_TRUE(pair.accepts_move(4, u));
  EXPECT_TRUE(pair.is_injective(u, nullptr, 1.));
}

TEST(BoundaryGuard, AgreesWithBruteForceOnRandomTetBoundaryMoves)
{
  Map<3> m = grid_3(2);
  const auto faces = Guard3::boundary_faces(m.cells);
  Guard3 guard(faces, m.target.size());
  guard.rebuild(m.target);
  const std::vector<Index> boundary = boundary_vertices(m.target.size(), guard);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> small(-0.3, 0.3), large(-3, 3);
  std::uniform_int_distribution<int> kind(0, 2), lattice(-2, 6);
  int accepted, rejected;
  check_random_moves(m, guard, boundary, rng, 300, [&](Index v) {
    switch(kind(rng)) {
      case 0: m.target[v] += Vector<3>(small(rng), small(rng), small(rng)); break;
      case 1: m.target[v] += Vector<3>(large(rng), large(rng), large(rng)); break;
      default: m.target[v] = Vector<3>(lattice(rng), lattice(rng), lattice(rng)) / 2;   // exact degeneracies
    }
  }, [&](Index v) { return brute_force_injective(faces, m.target, &v) && clear_of_each_other<3>(faces, m.target); },
     accepted, rejected);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_TRUE(brute_force_injective(faces, m.target));
  EXPECT_GT(accepted, 50);
  EXPECT_GT(rejected, 50);
}

// A U of 3024 tetrahedra whose arms a rigid-type measure presses together, the faces between them
// free: the result keeps its clearance, and its coordinates rounded to 15 digits do not make the
// boundary cross itself (exact predicates). The guard's distance of two triangles once depended on
// their order (CGAL's Triangle_3-Triangle_3 distance in doubles): the arms ended 0.003 units in
// the last place apart, and the written map crossed itself.
TEST(BoundaryGuard, PressedArmsKeepTheirClearanceThroughRounding)
{
  const int nx = 18, ny = 12, nz = 3;
  const auto kept = [](int i, int j) { return i < 6 || i >= 12 || j < 4; };   // the cube at (i, j, .)
  DOI::Optimization_problem<3> p;
  std::map<std::array<int, 3>, Index> index;
  std::vector<unsigned char> fixed;
  const auto vertex = [&](std::array<int, 3> c) {
    const auto [it, added] = index.emplace(c, Index(p.map.target.size()));
    if(added) {
      p.map.target.emplace_back(0.5 * c[0], 0.5 * c[1], 0.5 * c[2]);
      fixed.push_back(c[1] == 0 || c[0] == 0 || c[0] == nx);   // the bottom and the arms' outer faces
    }
    return it->second;
  };
  for(int l = 0; l < nz; ++l)
    for(int j = 0; j < ny; ++j)
      for(int i = 0; i < nx; ++i) {
        if(!kept(i, j)) continue;
        std::array<int, 3> axes = {0, 1, 2};
        do {
          std::array<int, 3> c = {i, j, l};
          std::array<Index, 4> cell;
          cell[0] = vertex(c);
          for(int step = 0; step < 3; ++step) {
            ++c[axes[step]];
            cell[step + 1] = vertex(c);
          }
          DOI::Matrix<3> Dm;
          for(int k = 0; k < 3; ++k) Dm.col(k) = p.map.target[cell[k + 1]] - p.map.target[cell[0]];
          p.map.add_cell(cell, Dm, Dm.determinant() > 0 ? 1 : -1);
        } while(std::next_permutation(axes.begin(), axes.end()));
      }
  ASSERT_EQ(p.map.number_of_cells(), 3024u);
  for(auto& x : p.map.target) x[0] *= 0.6;   // the start: the arms 1.8 apart
  p.is_free.resize(fixed.size());
  for(std::size_t v = 0; v < fixed.size(); ++v) p.is_free[v] = !fixed[v];
  p.finalize(CGAL::Distortion_optimization::Cell_weighting::AVERAGE_VOLUME);
  DOI::Options options;
  options.global_injectivity = true;
  options.iterations = 200;
  const auto r = DOI::minimize(p, CGAL::Distortion_optimization::Isometric_dilatation(), CGAL::Epick(), options);
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_LT(r.final_energy, r.initial_energy);

  Guard3 guard(Guard3::boundary_faces(p.map.cells), p.map.target.size());
  guard.rebuild(p.map.target);
  EXPECT_TRUE(guard.keeps_clearance());
  std::vector<Vector<3>> rounded = p.map.target;
  for(auto& x : rounded)
    for(int k = 0; k < 3; ++k) {
      char text[32];
      std::snprintf(text, sizeof text, "%.15g", x[k]);
      x[k] = std::strtod(text, nullptr);
    }
  EXPECT_TRUE(guard.is_injective(rounded));
}

// The distance of two faces is the same in either order, to the last bit: a move's check and the
// whole boundary's meet a pair in different orders, and a pair a move kept beyond the clearance
// must not be within it for the other (CGAL 5.5's segment distances depend on the order: on these
// pairs, edges nearly crossing at 1e-13, one-way edge-edge distances made 6679 of the 20000 differ).
TEST(BoundaryGuard, FaceDistancesDoNotDependOnTheOrder)
{
  using K = Guard3::K;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto point = [&] { return K::Point_3(u(random), u(random), u(random)); };
  // A point of the segment (a, b) moved by about 1e-13.
  const auto near = [&](const K::Point_3& a, const K::Point_3& b) {
    const double s = 0.5 + 0.4 * u(random);
    return K::Point_3(a.x() + s * (b.x() - a.x()) + 1e-13 * u(random), a.y() + s * (b.y() - a.y()) + 1e-13 * u(random),
                      a.z() + s * (b.z() - a.z()) + 1e-13 * u(random));
  };
  int differ = 0;
  for(int i = 0; i < 20000; ++i) {
    // g's edge from c through a point nearly on e's edge (a, b), and beyond it by 1e-13 at most.
    const K::Point_3 a = point(), b = point(), c = point(), m = near(a, b);
    const K::Triangle_3 e(a, b, point()), g(c, m, K::Point_3(c.x() + 0.1 * u(random), c.y() + 0.1, c.z()));
    differ += Guard3::squared_distance(e, g) != Guard3::squared_distance(g, e);
    const K::Point_2 a2(a.x(), a.y()), b2(b.x(), b.y()), m2(m.x(), m.y());
    differ += Guard2::squared_distance(K::Segment_2(a2, b2), K::Segment_2(K::Point_2(c.x(), c.y()), m2)) !=
              Guard2::squared_distance(K::Segment_2(K::Point_2(c.x(), c.y()), m2), K::Segment_2(a2, b2));
  }
  EXPECT_EQ(differ, 0);
}

// The separating axes' shortcut (apart()) says that two triangles are more than d apart only where
// they are (exact distances, exact intersection test), and says it for the pairs it is there for:
// nearly coplanar faces side by side, a little apart, as a smooth boundary has them near a ring.
TEST(BoundaryGuard, SeparatingAxesAreCertain)
{
  using V = Vector<3>;
  using Triangle = std::array<V, 3>;
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto point = [&] { return V(u(random), u(random), u(random)); };
  const auto exact = [](const Triangle& t) {
    return EK::Triangle_3(EK::Point_3(t[0][0], t[0][1], t[0][2]), EK::Point_3(t[1][0], t[1][1], t[1][2]),
                          EK::Point_3(t[2][0], t[2][1], t[2][2]));
  };
  // Whether the exact distance of a and b exceeds d (vertices to triangles, edges to edges).
  const auto farther_than = [&](const Triangle& a, const Triangle& b, double d) {
    const EK::Triangle_3 e = exact(a), g = exact(b);
    if(CGAL::do_intersect(e, g)) return false;
    const EK::FT d2 = EK::FT(d) * EK::FT(d);
    for(int i = 0; i < 3; ++i) {
      if(CGAL::squared_distance(e.vertex(i), g) <= d2 || CGAL::squared_distance(g.vertex(i), e) <= d2) return false;
      for(int j = 0; j < 3; ++j)
        if(CGAL::squared_distance(EK::Segment_3(e.vertex(i), e.vertex((i + 1) % 3)),
                                  EK::Segment_3(g.vertex(j), g.vertex((j + 1) % 3))) <= d2)
          return false;
    }
    return true;
  };
  const double clearance = 64 * std::numeric_limits<double>::epsilon() * std::sqrt(3.);   // the guard's, near unit size
  // The least rounding margin apart() may be given: 64 units in the last place of the largest coordinate.
  const auto rounding = [](const Triangle& a, const Triangle& b) {
    double largest = 0;
    for(int i = 0; i < 3; ++i) largest = std::max({largest, a[i].cwiseAbs().maxCoeff(), b[i].cwiseAbs().maxCoeff()});
    return 64 * std::numeric_limits<double>::epsilon() * largest;
  };
  int wrong = 0, said_apart = 0, side_by_side = 0, found = 0;
  for(int i = 0; i < 1500; ++i) {
    const Triangle a = {point(), point(), point()};
    const V n = (a[1] - a[0]).cross(a[2] - a[0]).normalized();
    // Nearly touching: b from a point of a moved off it by 1e-16 to 1e-12, either way.
    const double w0 = std::abs(u(random)), w1 = std::abs(u(random)) * (1 - w0);
    const V on = a[0] + w0 * (a[1] - a[0]) + w1 * (a[2] - a[0]);
    const V off = on + std::pow(10., -14 + 2 * u(random)) * point().normalized();
    const Triangle touching = {off, off + 0.5 * point(), off + 0.5 * point()};
    // Side by side: across a's edge (a0, a1) in a's plane, 1e-3 beyond it, tilted by up to 1e-2.
    const V across = n.cross(a[1] - a[0]).normalized();
    const double side = across.dot(a[2] - a[0]) > 0 ? -1 : 1;
    const V shift = side * 1e-3 * across;
    const Triangle neighbour = {a[0] + shift, a[1] + shift, (a[0] + a[1]) / 2 + shift + side * across + 1e-2 * u(random) * n};
    for(const double d : {0., clearance, 0.25 * clearance}) {
      for(const Triangle& b : {touching, neighbour}) {
        if(!Guard3::apart(a, b, d, rounding(a, b))) continue;
        ++said_apart;
        wrong += !farther_than(a, b, d);
      }
      ++side_by_side;
      found += Guard3::apart(a, neighbour, d, rounding(a, neighbour));
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(said_apart, side_by_side);   // some nearly touching pairs too
  EXPECT_EQ(found, side_by_side);
}

// A piece inside another without any crossing: refused by the ray tests, also where the ray from
// the piece's vertices runs through the other's vertices and along its edges.
TEST(BoundaryGuard, PieceInsideAnotherPlanar)
{
  using V = Vector<2>;
  const auto injective = [](std::array<V, 3> corners) { return injective_with(annulus_2(), corners); };
  EXPECT_TRUE(injective({V(1.3, 1.4), V(1.7, 1.4), V(1.5, 1.6)}));    // in the hole
  EXPECT_FALSE(injective({V(0.3, 1.4), V(0.7, 1.4), V(0.5, 1.6)}));   // in the ring
  EXPECT_TRUE(injective({V(3.3, 1.4), V(3.7, 1.4), V(3.5, 1.6)}));    // outside
  EXPECT_FALSE(injective({V(-10, -10), V(20, -10), V(5, 20)}));       // around it all
  // Every corner on a row of the annulus' vertices: the rays pass through vertices and along the
  // hole's horizontal sides.
  EXPECT_TRUE(injective({V(-0.5, 1), V(-0.3, 1), V(-0.4, 2)}));
  EXPECT_FALSE(injective({V(0.2, 1), V(0.4, 1), V(0.3, 2)}));
  EXPECT_FALSE(injective({V(1.2, 1), V(1.8, 1), V(1.5, 2)}));   // on the hole's sides: crossing
  EXPECT_TRUE(injective({V(1.2, 1.2), V(1.8, 1.2), V(1.5, 1.8)}));

  // The crossing report holds both pieces' boundaries; without piece labels, one piece is assumed.
  Map<2> nested = annulus_2();
  add_simplex<2>(nested, {V(0.3, 1.4), V(0.7, 1.4), V(0.5, 1.6)});
  std::vector<Index> crossing;
  EXPECT_FALSE(guard_of_pieces(nested).is_injective(nested.target, &crossing));
  EXPECT_EQ(std::set<Index>(crossing.begin(), crossing.end()).size(), 16u + 3u);
  EXPECT_TRUE(Guard2(Guard2::boundary_faces(nested.cells), nested.target.size()).is_injective(nested.target));
  EXPECT_FALSE(Guard2(Guard2::boundary_faces(nested.cells), nested.target.size()).several_pieces());
}

TEST(BoundaryGuard, PieceInsideAnotherSpatial)
{
  using V = Vector<3>;
  const auto injective = [](std::array<V, 4> corners) { return injective_with(hollow_cube(), corners); };
  const auto small = [](V a) { return std::array<V, 4>{a, a + V(0.2, 0, 0), a + V(0, 0.2, 0), a + V(0, 0, 0.2)}; };
  EXPECT_TRUE(injective(small(V(1.3, 1.4, 1.5))));    // in the cavity
  EXPECT_FALSE(injective(small(V(0.3, 1.4, 1.5))));   // in the solid
  EXPECT_TRUE(injective(small(V(3.3, 1.4, 1.5))));    // outside
  EXPECT_FALSE(injective({V(-20, -20, -20), V(60, -20, -20), V(-20, 60, -20), V(-20, -20, 60)}));
  // Corners on the grid's lines: rays through vertices, along edges and faces of the cavity.
  EXPECT_TRUE(injective({V(-0.5, 1, 1), V(-0.3, 1, 1), V(-0.4, 2, 1), V(-0.4, 1, 2)}));
  EXPECT_FALSE(injective({V(0.2, 1, 1), V(0.4, 1, 1), V(0.3, 2, 1), V(0.3, 1, 2)}));
  EXPECT_TRUE(injective({V(-0.5, 2, 2), V(-0.3, 2, 2), V(-0.4, 1, 2), V(-0.4, 2, 1)}));
  EXPECT_FALSE(injective({V(0.2, 2, 2), V(0.4, 2, 2), V(0.3, 1, 2), V(0.3, 2, 1)}));
  EXPECT_TRUE(injective({V(1.2, 1.5, 1.5), V(1.8, 1.5, 1.5), V(1.5, 1.2, 1.5), V(1.5, 1.5, 1.2)}));
}

// A piece that grows over another in one move: the swept triangles (tetrahedra) hold it.
TEST(BoundaryGuard, MoveSweepingOverAnotherPiece)
{
  Map<2> m = grid_2(3);   // [0, 2]^2; vertex 5 = (2, 1) on the right side
  add_simplex<2>(m, {Vector<2>(2.5, 0.98), Vector<2>(2.52, 0.98), Vector<2>(2.51, 1.0)});
  Guard2 guard = guard_of_pieces(m);
  guard.rebuild(m.target);
  m.target[5] = Vector<2>(4, 1);   // a spike around the triangle: nothing crosses
  EXPECT_TRUE(brute_force_injective(Guard2::boundary_faces(m.cells), m.target));
  EXPECT_FALSE(guard.accepts_move(5, m.target));
  EXPECT_FALSE(guard.is_injective(m.target));
  m.target[5] = Vector<2>(2.4, 1);   // short of it
  EXPECT_TRUE(guard.accepts_move(5, m.target));
  guard.commit_move(5, m.target);
  m.target[5] = Vector<2>(4, 1);     // from there: still around it
  EXPECT_FALSE(guard.accepts_move(5, m.target));
  m.target[5] = Vector<2>(2.4, 1.5);
  EXPECT_TRUE(guard.accepts_move(5, m.target));

  Map<3> c = grid_3(1);   // the unit cube; vertex 7 = (1, 1, 1)
  add_simplex<3>(c, {Vector<3>(1.2, 1.2, 1.2), Vector<3>(1.21, 1.2, 1.2), Vector<3>(1.2, 1.21, 1.2), Vector<3>(1.2, 1.2, 1.21)});
  Guard3 guard3 = guard_of_pieces(c);
  guard3.rebuild(c.target);
  c.target[7] = Vector<3>(2, 2, 2);
  EXPECT_TRUE(brute_force_injective(Guard3::boundary_faces(c.cells), c.target));
  EXPECT_FALSE(pieces_apart(c));
  EXPECT_FALSE(guard3.accepts_move(7, c.target));
  EXPECT_FALSE(guard3.is_injective(c.target));
  c.target[7] = Vector<3>(1.1, 1.1, 1.1);
  EXPECT_TRUE(guard3.accepts_move(7, c.target));
}

TEST(BoundaryGuard, RandomMovesOfSeveralPiecesPlanar)
{
  // The annulus with small triangles near its sides, in its hole and outside.
  Map<2> m = annulus_2();
  using V = Vector<2>;
  for(V a : {V(1.45, 1.45), V(1.1, 1.8), V(3.05, 1.4), V(1.2, 3.05), V(-0.07, 0.5), V(0.6, -0.07), V(-0.07, 2.5)})
    add_simplex<2>(m, {a, a + V(0.02, 0), a + V(0.01, 0.02)});
  check_random_moves_of_pieces(m, 11, 3000, 0.25, 300, 10);
}

TEST(BoundaryGuard, RandomMovesOfSeveralPiecesSpatial)
{
  Map<3> m = grid_3(2);   // [0, 2]^3
  using V = Vector<3>;
  for(V a : {V(2.05, 0.8, 0.9), V(0.8, -0.08, 1.1), V(1.1, 0.9, 2.05), V(2.05, 2.05, 2.05), V(-0.08, 1.1, 0.4)})
    add_simplex<3>(m, {a, a + V(0.01, 0, 0), a + V(0, 0.01, 0), a + V(0, 0, 0.01)});
  check_random_moves_of_pieces(m, 5, 1500, 0.01, 100, 5);
}

// A grid at half its rest size grows back under the isometric measure, its border free, towards
// a small triangle beside it (a piece of its own, at its rest shape). The run keeps the triangle
// outside the grid; a start with the triangle inside is refused.
TEST(BoundaryGuard, MinimizeKeepsPiecesApart)
{
  using V = Vector<2>;
  const auto problem = [](V corner) {
    Map<2> source = grid_2(5);   // [0, 4]^2
    add_simplex<2>(source, {V(0, 0), V(0.04, 0), V(0.02, 0.04)});
    DOI::Optimization_problem<2> p;
    p.map.target = source.target;
    for(const auto& cell : source.cells) {
      DOI::Matrix<2> Dm;
      for(int k = 0; k < 2; ++k) Dm.col(k) = source.target[cell[k + 1]] - source.target[cell[0]];
      EXPECT_TRUE(p.map.add_cell(cell, Dm, 1));
    }
    for(std::size_t v = 0; v < 25; ++v) p.map.target[v] *= 0.5;
    for(std::size_t v = 25; v < 28; ++v) p.map.target[v] += corner;
    p.is_free.assign(28, 1);
    p.finalize(CGAL::Distortion_optimization::Cell_weighting::AVERAGE_VOLUME);
    return p;
  };
  const auto map_of = [](const DOI::Optimization_problem<2>& p) {
    Map<2> m;
    m.target = p.map.target;
    m.cells = p.map.cells;
    return m;
  };
  DOI::Options options;
  options.global_injectivity = true;
  options.iterations = 100;
  DOI::Optimization_problem<2> p = problem(V(2.05, 1.1));
  ASSERT_TRUE(pieces_apart(map_of(p)));
  const auto r = DOI::minimize(p, CGAL::Distortion_optimization::Isometric_dilatation(), CGAL::Epick(), options);
  EXPECT_EQ(r.inverted_cells, 0u);
  EXPECT_LT(r.final_energy, r.initial_energy);
  double right = 0;
  for(std::size_t v = 0; v < 25; ++v) right = std::max(right, p.map.target[v][0]);
  std::printf("grid's right side at x = %.3f; triangle at x >= %.3f\n", right, p.map.target[25][0]);
  EXPECT_TRUE(brute_force_injective(Guard2::boundary_faces(p.map.cells), p.map.target));
  EXPECT_TRUE(pieces_apart(map_of(p)));

  DOI::Optimization_problem<2> inside = problem(V(0.5, 0.5));
  try {
    DOI::minimize(inside, CGAL::Distortion_optimization::Isometric_dilatation(), CGAL::Epick(), options);
    ADD_FAILURE() << "a start with one piece inside another was taken";
  } catch(const CGAL::Distortion_optimization::Crossing_start_boundary& e) {
    EXPECT_NE(std::string(e.what()).find("one of its pieces lies inside another"), std::string::npos) << e.what();
  }
}
