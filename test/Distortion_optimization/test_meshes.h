// Small meshes and maps shared by the triangle-mesh tests.
#ifndef DISTORTION_OPTIMIZATION_TEST_MESHES_H
#define DISTORTION_OPTIMIZATION_TEST_MESHES_H

#include <CGAL/Distortion_optimization/measures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace test_meshes {

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_2 = K::Point_2;
using Point_3 = K::Point_3;
using Mesh3 = CGAL::Surface_mesh<Point_3>;
using Mesh2 = CGAL::Surface_mesh<Point_2>;

// A (columns x rows)-square grid on [0,1]^2 split into 2 columns rows triangles, counter-clockwise
// in the (x, y) plane, each vertex placed at make_point(x, y).
template <class Mesh, class MakePoint>
Mesh grid(int columns, int rows, MakePoint make_point)
{
  Mesh m;
  std::vector<typename Mesh::Vertex_index> v;
  for(int j = 0; j <= rows; ++j)
    for(int i = 0; i <= columns; ++i) v.push_back(m.add_vertex(make_point(double(i) / columns, double(j) / rows)));
  auto at = [&](int i, int j) { return v[j * (columns + 1) + i]; };
  for(int j = 0; j < rows; ++j)
    for(int i = 0; i < columns; ++i) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

template <class Mesh, class MakePoint>
Mesh grid(int k, MakePoint make_point)
{
  return grid<Mesh>(k, k, make_point);
}

inline Mesh2 planar_grid(int k) { return grid<Mesh2>(k, [](double x, double y) { return Point_2(x, y); }); }
inline Mesh3 flat_grid(int k) { return grid<Mesh3>(k, [](double x, double y) { return Point_3(x, y, 0); }); }

template <class Mesh, class F>
typename Mesh::template Property_map<typename Mesh::Vertex_index, Point_2> make_target(Mesh& m, F f)
{
  auto uv = m.template add_property_map<typename Mesh::Vertex_index, Point_2>("v:target").first;
  for(auto v : m.vertices()) uv[v] = f(m.point(v));
  return uv;
}

// The target of every vertex, in vertex order.
template <class Mesh, class UV>
std::vector<Point_2> targets_of(const Mesh& mesh, const UV& uv)
{
  std::vector<Point_2> x;
  for(auto v : mesh.vertices()) x.push_back(uv[v]);
  return x;
}

using Map = std::function<Point_2(const Point_2&)>;

// A 16 x 16 grid (512 triangles): border mapped by f, interior by f plus noise.
struct Noisy_map
{
  Mesh2 mesh = planar_grid(16);
  Mesh2::Property_map<Mesh2::Vertex_index, Point_2> uv;
  Mesh2::Property_map<Mesh2::Vertex_index, Point_2> exact;

  Noisy_map(const Map& f, double noise, unsigned seed = 1)
  {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-noise, noise);
    uv = mesh.add_property_map<Mesh2::Vertex_index, Point_2>("v:uv").first;
    exact = mesh.add_property_map<Mesh2::Vertex_index, Point_2>("v:exact").first;
    for(auto v : mesh.vertices()) {
      const Point_2 p = mesh.point(v);
      exact[v] = f(p);
      uv[v] = mesh.is_border(v) ? f(p) : f(Point_2(p.x() + u(rng), p.y() + u(rng)));
    }
  }

  std::vector<Point_2> targets() const { return targets_of(mesh, uv); }
  double max_error() const
  {
    double e = 0;
    for(auto v : mesh.vertices()) e = std::max(e, std::sqrt(CGAL::squared_distance(uv[v], exact[v])));
    return e;
  }
  double diameter() const
  {
    double d = 0;
    for(auto a : mesh.vertices())
      for(auto b : mesh.vertices()) d = std::max(d, std::sqrt(CGAL::squared_distance(exact[a], exact[b])));
    return d;
  }
};

// Singular values of the 2x2 Jacobian of face f, computed from scratch: the face is put in its
// own frame with plain arithmetic and s1, s2 follow from |J|^2 = s1^2 + s2^2 and det J = s1 s2.
template <class Mesh, class UV>
std::pair<double, double> brute_force_singular_values(const Mesh& m, const UV& uv, typename Mesh::Face_index f,
                                                      double* area = nullptr)
{
  std::vector<typename Mesh::Vertex_index> vs;
  for(auto v : m.vertices_around_face(m.halfedge(f))) vs.push_back(v);
  double P[3][3] = {};
  for(int i = 0; i < 3; ++i) {
    const auto& p = m.point(vs[i]);
    for(int d = 0; d < p.dimension(); ++d) P[i][d] = CGAL::to_double(p[d]);
  }
  double e1[3], e2[3];
  for(int d = 0; d < 3; ++d) { e1[d] = P[1][d] - P[0][d]; e2[d] = P[2][d] - P[0][d]; }
  const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  const double a = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1;
  const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2], cz = e1[0] * e2[1] - e1[1] * e2[0];
  double b = std::sqrt(cx * cx + cy * cy + cz * cz) / l1;
  // A planar (Point_2) source keeps its own orientation; a surface face is positive in its frame.
  if(m.point(vs[0]).dimension() == 2 && cz < 0) b = -b;
  const double S[4] = {l1, a, 0, b};   // source edges, columns (l1, 0) and (a, b)
  const double T[4] = {uv[vs[1]].x() - uv[vs[0]].x(), uv[vs[2]].x() - uv[vs[0]].x(),
                       uv[vs[1]].y() - uv[vs[0]].y(), uv[vs[2]].y() - uv[vs[0]].y()};
  const double dS = S[0] * S[3] - S[1] * S[2];
  const double Si[4] = {S[3] / dS, -S[1] / dS, -S[2] / dS, S[0] / dS};
  const double J[4] = {T[0] * Si[0] + T[1] * Si[2], T[0] * Si[1] + T[1] * Si[3],
                       T[2] * Si[0] + T[3] * Si[2], T[2] * Si[1] + T[3] * Si[3]};
  const double fro2 = J[0] * J[0] + J[1] * J[1] + J[2] * J[2] + J[3] * J[3];
  const double det = J[0] * J[3] - J[1] * J[2];
  const double s1 = std::sqrt(0.5 * (fro2 + std::sqrt(std::max(0., fro2 * fro2 - 4 * det * det))));
  if(area) *area = std::abs(dS) / 2;
  return {s1, det / s1};
}

// The paper's equations 8-16 in 2D, written out again.
inline double brute_force_measure(const std::string& name, double s1, double s2)
{
  const double inf = std::numeric_limits<double>::infinity();
  const bool ok = s2 > 0;
  if(name == "conformal" || name == "condition") return ok ? s1 / s2 : inf;
  if(name == "mips") return ok ? s1 / s2 + s2 / s1 : inf;
  if(name == "isometric") return ok ? std::max(s1, 1 / s2) : inf;
  if(name == "arap") return (s1 - 1) * (s1 - 1) + (s2 - 1) * (s2 - 1);
  if(name == "symmetric_dirichlet") return ok ? (s1 * s1 + s2 * s2 + 1 / (s1 * s1) + 1 / (s2 * s2)) / 4 : inf;
  if(name == "volume") return ok ? std::max(s1 * s2, 1 / (s1 * s2)) : inf;
  if(name == "dirichlet") return (s1 * s1 + s2 * s2) / 2;
  if(name == "conformal*isometric") return brute_force_measure("conformal", s1, s2) * brute_force_measure("isometric", s1, s2);
  return std::numeric_limits<double>::quiet_NaN();
}

// The area-weighted mean of a measure over all faces.
template <class Mesh, class UV>
double brute_force_energy(const Mesh& m, const UV& uv, const std::string& name)
{
  double e = 0, total = 0;
  for(auto f : m.faces()) {
    double area;
    const auto s = brute_force_singular_values(m, uv, f, &area);
    e += area * brute_force_measure(name, s.first, s.second);
    total += area;
  }
  return e / total;
}

// Faces whose image is not counter-clockwise (exact predicate).
template <class Mesh, class UV>
std::size_t count_flipped(const Mesh& m, const UV& uv)
{
  std::size_t flipped = 0;
  for(auto f : m.faces()) {
    std::vector<Point_2> q;
    for(auto v : m.vertices_around_face(m.halfedge(f))) q.push_back(uv[v]);
    if(CGAL::orientation(q[0], q[1], q[2]) != CGAL::LEFT_TURN) ++flipped;
  }
  return flipped;
}

// Pairs of border edges of the target that intersect improperly, by brute force with exact
// predicates: edges sharing no vertex must be disjoint; edges sharing a vertex must not overlap.
template <class Mesh, class UV>
std::size_t border_self_intersections(const Mesh& mesh, const UV& uv)
{
  std::vector<std::pair<typename Mesh::Vertex_index, typename Mesh::Vertex_index>> edges;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h)) edges.emplace_back(mesh.source(h), mesh.target(h));
  std::size_t count = 0;
  for(std::size_t i = 0; i < edges.size(); ++i)
    for(std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto [a, b] = edges[i];
      const auto [c, d] = edges[j];
      const K::Segment_2 s(uv[a], uv[b]), t(uv[c], uv[d]);
      const bool shared = a == c || a == d || b == c || b == d;
      if(!shared) { count += CGAL::do_intersect(s, t); continue; }
      // Sharing vertex p: improper iff the other ends are collinear with p on the same side.
      const auto p = (a == c || a == d) ? a : b;
      const Point_2& q = uv[p == a ? b : a];
      const Point_2& r = uv[p == c ? d : c];
      count += CGAL::collinear(uv[p], q, r) && CGAL::angle(q, uv[p], r) == CGAL::ACUTE;
    }
  return count;
}

} // namespace test_meshes

#endif
