// The paper's mesh generation (section 4.2, Fig. 15): a regular mesh of the square or the cube,
// its boundary mapped by the radial map f0(x) = x |x| (Fig. 5), the inside optimized with the
// boundary fixed: the target is a mesh of the domain f0(square) or f0(cube). Compared, at nearly
// the same number of cells, with CGAL's Mesh_2 (+ Lloyd) in 2D and with Mesh_3 (with and without
// its optimizers) and TetGen (-q) in 3D, meshing the same domain (the polygon or the closed
// triangle surface of the target's boundary).
//
// Columns: cells; mean cell aspect R / (n r) (1 for the regular simplex); mean over the vertices
// of the longest over the shortest edge at the vertex; smallest angle (3D: dihedral); slivers
// (an angle under 10 degrees); seconds.
//
//   build/benchmark/Distortion_optimization/bench_mesh_generation [k, default 12: k x k squares, k^3 cubes]

#include "bench_helpers.h"

#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/Distortion_optimization/mesh_quality.h>
#include <CGAL/Distortion_optimization/tetrahedralize_with_tetgen.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace DOP = CGAL::Distortion_optimization::parameters;
using namespace volume_examples;
using Point_2 = K::Point_2;
using Mesh2 = CGAL::Surface_mesh<Point_2>;

namespace {

// Mean over the vertices of (longest / shortest edge at the vertex), from cells of n + 1 vertices.
template <std::size_t m, class P>
double edge_aspect(const std::vector<P>& points, const std::vector<std::array<std::size_t, m>>& cells)
{
  std::vector<double> shortest(points.size(), HUGE_VAL), longest(points.size(), 0);
  for(const auto& c : cells)
    for(std::size_t i = 0; i < m; ++i)
      for(std::size_t j = i + 1; j < m; ++j) {
        const double l = std::sqrt(CGAL::squared_distance(points[c[i]], points[c[j]]));
        for(std::size_t v : {c[i], c[j]}) {
          shortest[v] = std::min(shortest[v], l);
          longest[v] = std::max(longest[v], l);
        }
      }
  double sum = 0;
  std::size_t count = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(longest[v] > 0) {
      sum += longest[v] / shortest[v];
      ++count;
    }
  return sum / count;
}

void print(const char* name, std::size_t cells, double aspect, double edges, const DO::Mesh_quality& q, double seconds)
{
  std::printf("%-32s %8zu %10.4f %10.4f %9.3f %8zu %8.3f\n", name, cells, aspect, edges, q.min_angle, q.slivers, seconds);
  std::fflush(stdout);
}

void header(const char* title)
{
  std::printf("\n%s\n%-32s %8s %10s %10s %9s %8s %8s\n", title, "mesh", "cells", "R/(n r)", "edge asp.", "min angle",
              "slivers", "seconds");
}

// The mean of R / (n r) over the cells: the inverse radius ratios, from the statistics' per-cell
// values recomputed here (Mesh_quality keeps their mean of r/R).
template <class Mesh, class Positions>
double mean_aspect(const Mesh& mesh, const Positions& positions)
{
  double sum = 0;
  std::size_t count = 0;
  using Point = typename boost::property_traits<Positions>::value_type;
  constexpr int n = DO::internal::Is_c3t3<Mesh>::value ? 3 : 2;
  DO::internal::for_each_cell_points(mesh, positions, [&](const auto&, const std::array<Point, n + 1>& p) {
    std::array<DO::internal::Vector<3>, n + 1> x;
    for(int i = 0; i <= n; ++i) x[i] = DO::internal::as_vector(p[i]);
    std::array<double, 6> angles;
    int k = 0;
    double ratio = 0;
    DO::internal::cell_shape(x, angles, k, ratio);
    sum += 1 / ratio;
    ++count;
  });
  return sum / count;
}

// The complex's cells as indices into `points` (the positions of its vertices in order of first use).
struct Soup
{
  std::vector<Point> points;
  std::map<Vertex_handle, std::size_t> index;
  std::vector<std::array<std::size_t, 4>> cells;

  Soup(const Volume& volume, const Targets& positions)
  {
    std::vector<std::array<double, 3>> xyz;
    const auto handles = DO::tetrahedra_from_c3t3(
        volume, xyz, cells, CGAL::parameters::vertex_point_map(boost::const_associative_property_map<Targets>(positions)));
    for(std::size_t i = 0; i < xyz.size(); ++i) {
      points.emplace_back(xyz[i][0], xyz[i][1], xyz[i][2]);
      index.emplace(handles[i], i);
    }
  }
};

Point_2 radial(const Point_2& p) { const double r = std::sqrt(p.x() * p.x() + p.y() * p.y()); return Point_2(r * p.x(), r * p.y()); }
Point radial(const Point& p) { const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()); return Point(r * p.x(), r * p.y(), r * p.z()); }

void planar(int k)
{
  header(("2D: the square [-1, 1]^2 in " + std::to_string(2 * k * k) + " triangles, boundary mapped by x |x|").c_str());
  // The regular source: k x k squares, each cut along a diagonal.
  Mesh2 source;
  std::vector<Mesh2::Vertex_index> v;
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) v.push_back(source.add_vertex(Point_2(-1 + 2. * i / k, -1 + 2. * j / k)));
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      const auto a = v[j * (k + 1) + i], b = v[j * (k + 1) + i + 1], c = v[(j + 1) * (k + 1) + i], d = v[(j + 1) * (k + 1) + i + 1];
      source.add_face(a, b, d);
      source.add_face(a, d, c);
    }
  std::vector<Point_2> boundary;   // the target polygon, counterclockwise
  for(int i = 0; i < k; ++i) boundary.push_back(radial(source.point(v[i])));
  for(int j = 0; j < k; ++j) boundary.push_back(radial(source.point(v[j * (k + 1) + k])));
  for(int i = k; i > 0; --i) boundary.push_back(radial(source.point(v[k * (k + 1) + i])));
  for(int j = k; j > 0; --j) boundary.push_back(radial(source.point(v[j * (k + 1)])));

  for(const auto& [name, measure] : std::vector<std::pair<const char*, std::string>>{{"ours, isometric", "isometric"},
                                                                                     {"ours, conformal", "conformal"}}) {
    auto uv = source.add_property_map<Mesh2::Vertex_index, Point_2>("v:uv").first;
    // The inside at the identity: the optimizer's harmonic start takes it from there.
    for(auto u : source.vertices()) uv[u] = source.is_border(u) ? radial(source.point(u)) : source.point(u);
    const auto start = std::chrono::steady_clock::now();
    CGAL::minimize_distortion(source, uv, DO::measure_from_name(measure),
                              DOP::convergence_threshold(1e-6, CGAL::parameters::number_of_iterations(300)));
    const double seconds = seconds_since(start);
    std::vector<Point_2> points;
    std::vector<std::array<std::size_t, 3>> cells;
    for(auto u : source.vertices()) points.push_back(uv[u]);
    for(auto f : source.faces()) {
      std::array<std::size_t, 3> t;
      int i = 0;
      for(auto u : CGAL::vertices_around_face(source.halfedge(f), source)) t[i++] = std::size_t(u);
      cells.push_back(t);
    }
    print(name, cells.size(), mean_aspect(source, uv), edge_aspect(points, cells), DO::mesh_quality(source, uv), seconds);
    source.remove_property_map(uv);
  }

  // Mesh_2 of the polygon, its size bound tuned to about as many triangles, with and without Lloyd.
  using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
  using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb, Fb>>;
  const auto mesh2 = [&](double size, bool lloyd, Mesh2& out) {
    CDT cdt;
    for(std::size_t i = 0; i < boundary.size(); ++i) cdt.insert_constraint(boundary[i], boundary[(i + 1) % boundary.size()]);
    CGAL::refine_Delaunay_mesh_2(cdt, CGAL::Delaunay_mesh_size_criteria_2<CDT>(0.125, size));
    if(lloyd) CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = 50);
    out.clear();
    std::map<CDT::Vertex_handle, Mesh2::Vertex_index> index;
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      std::array<Mesh2::Vertex_index, 3> t;
      for(int i = 0; i < 3; ++i) {
        auto it = index.find(f->vertex(i));
        if(it == index.end()) it = index.emplace(f->vertex(i), out.add_vertex(f->vertex(i)->point())).first;
        t[i] = it->second;
      }
      out.add_face(t[0], t[1], t[2]);
    }
  };
  double size = 2.5 * 2 / k;
  Mesh2 m;
  for(int round = 0; round < 4; ++round) {   // the size bound for about 2 k^2 triangles
    mesh2(size, false, m);
    size *= std::sqrt(double(m.number_of_faces()) / (2. * k * k));
  }
  for(bool lloyd : {false, true}) {
    const auto start = std::chrono::steady_clock::now();
    mesh2(size, lloyd, m);
    const double seconds = seconds_since(start);
    std::vector<Point_2> points(m.points().begin(), m.points().end());
    std::vector<std::array<std::size_t, 3>> cells;
    for(auto f : m.faces()) {
      std::array<std::size_t, 3> t;
      int i = 0;
      for(auto u : CGAL::vertices_around_face(m.halfedge(f), m)) t[i++] = std::size_t(u);
      cells.push_back(t);
    }
    print(lloyd ? "Mesh_2 + Lloyd (50)" : "Mesh_2", cells.size(), mean_aspect(m, m.points()), edge_aspect(points, cells),
          DO::mesh_quality(m, m.points()), seconds);
  }
}

void volume(int k)
{
  header(("3D: the cube [-1, 1]^3 in " + std::to_string(6 * k * k * k) + " tetrahedra, boundary mapped by x |x|").c_str());
  // The regular source: k^3 cubes of side 2 / k, 6 Kuhn tetrahedra each.
  const Cube_tetrahedra block = cube_tetrahedra(k, [k](int i) { return -1 + 2. * i / k; });
  Volume source;
  DO::c3t3_from_tetrahedra(source, block.points, block.cells);
  const auto boundary = boundary_vertices(source);

  Surface target_boundary;   // the image of the cube's boundary: the domain the other meshers get
  for(const std::string measure : {"isometric", "conformal"}) {
    Targets map;
    DO::map_vertices(source, Target_map(map), [](const Point& p) { return p; });
    for(Vertex_handle u : boundary) map[u] = radial(map[u]);   // the inside at the identity, as in 2D
    const auto start = std::chrono::steady_clock::now();
    CGAL::minimize_distortion(source, Target_map(map), DO::measure_from_name(measure),
                              DOP::convergence_threshold(1e-6, CGAL::parameters::number_of_iterations(300)));
    const double seconds = seconds_since(start);
    const Soup image(source, map);
    print(("ours, " + measure).c_str(), image.cells.size(), mean_aspect(source, Target_map(map)),
          edge_aspect(image.points, image.cells), DO::mesh_quality(source, Target_map(map)), seconds);
    if(target_boundary.is_empty()) {   // the boundary facets under the map, outward
      std::map<std::size_t, Surface::Vertex_index> vertex;
      for(auto c = source.cells_in_complex_begin(); c != source.cells_in_complex_end(); ++c)
        for(int i = 0; i < 4; ++i) {
          if(source.is_in_complex(c->neighbor(i))) continue;
          std::array<Surface::Vertex_index, 3> f;
          for(int j = 0; j < 3; ++j) {
            const std::size_t w = image.index.at(c->vertex((i + 1 + j) % 4));
            auto it = vertex.find(w);
            if(it == vertex.end()) it = vertex.emplace(w, target_boundary.add_vertex(image.points[w])).first;
            f[j] = it->second;
          }
          // Facet (i+1, i+2, i+3) is outward for even i in a positive cell.
          if(i % 2 == 0) target_boundary.add_face(f[0], f[1], f[2]);
          else target_boundary.add_face(f[0], f[2], f[1]);
        }
    }
  }

  const double wanted = 6. * k * k * k;
  double h = DO::interior_mesh_sizes(target_boundary).cell_size;
  for(int round = 0; round < 2; ++round)
    h *= std::cbrt(DO::mesh_interior(target_boundary, DOP::cell_size(h)).number_of_cells_in_complex() / wanted);
  for(bool optimizers : {false, true}) {
    const auto start = std::chrono::steady_clock::now();
    const Volume meshed = optimizers ? DO::mesh_interior(target_boundary, DOP::cell_size(h, DOP::odt_iterations(25,
                                         DOP::perturb_slivers(true, DOP::exude_slivers(true)))))
                                     : DO::mesh_interior(target_boundary, DOP::cell_size(h));
    const double seconds = seconds_since(start);
    Targets positions;
    DO::map_vertices(meshed, Target_map(positions), [](const Point& p) { return p; });
    const Soup soup(meshed, positions);
    print(optimizers ? "Mesh_3 + ODT + perturb + exude" : "Mesh_3", soup.cells.size(), mean_aspect(meshed, Target_map(positions)),
          edge_aspect(soup.points, soup.cells), DO::mesh_quality(meshed, Target_map(positions)), seconds);
  }
  const double enclosed = DO::interior_mesh_sizes(target_boundary).volume;
  double max_volume = enclosed / wanted;
  for(int round = 0; round < 3; ++round)
    max_volume *= DO::tetrahedralize_with_tetgen(target_boundary, DOP::maximum_cell_volume(max_volume)).cells.size() / wanted;
  const auto start = std::chrono::steady_clock::now();
  const DO::IO::Tetrahedron_soup tetrahedralized = DO::tetrahedralize_with_tetgen(target_boundary, DOP::maximum_cell_volume(max_volume));
  const double seconds = seconds_since(start);
  const std::vector<std::array<double, 3>>& tet_points = tetrahedralized.points;
  const std::vector<std::array<std::size_t, 4>>& tet_cells = tetrahedralized.cells;
  Volume tetgen;
  DO::c3t3_from_tetrahedra(tetgen, tet_points, tet_cells);
  Targets positions;
  DO::map_vertices(tetgen, Target_map(positions), [](const Point& p) { return p; });
  std::vector<Point> pts;
  for(const auto& p : tet_points) pts.emplace_back(p[0], p[1], p[2]);
  print("TetGen -q (1.414)", tet_cells.size(), mean_aspect(tetgen, Target_map(positions)), edge_aspect(pts, tet_cells),
        DO::mesh_quality(tetgen, Target_map(positions)), seconds);
}

} // namespace

int main(int argc, char** argv)
{
  const int k = argc > 1 ? std::max(2, std::stoi(argv[1])) : 12;
  try {
    planar(3 * k);
    volume(k);
  } catch(const DO::Invalid_input& e) {
    std::fprintf(stderr, "Error: %s\n", e.what());
    return 1;
  }
  return 0;
}
