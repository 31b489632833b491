// Fixed-boundary planar deformation.
//
// A planar triangle mesh (a jittered grid of a 2 x 0.5 rectangle, or the planar OFF file given
// as argv[1]) is bent into an arc: the border vertices follow the smooth bend exactly, the inner
// vertices follow it up to some noise that keeps every triangle positively oriented. From that
// noisy start, CGAL::minimize_distortion() moves the inner vertices (the border is fixed by
// default) to minimize two measures: the conformal dilatation K and the symmetric Dirichlet
// energy. Both runs start from the same map.
//
//   planar_deformation [planar_mesh.off]

#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_2 = K::Point_2;
using Mesh = CGAL::Surface_mesh<Point_2>;
using vertex_descriptor = Mesh::Vertex_index;
using Target_map = Mesh::Property_map<vertex_descriptor, Point_2>;

// A k x (k/4) grid of the rectangle [-1, 1] x [-0.25, 0.25], with jittered inner vertices.
Mesh jittered_rectangle(int k)
{
  Mesh mesh;
  const int m = k / 4;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  const double h = 2. / k;
  std::vector<vertex_descriptor> v;
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= k; ++i) {
      const bool inner = i > 0 && i < k && j > 0 && j < m;
      const double x = -1 + h * (i + (inner ? jitter(rng) : 0.)), y = -0.25 + h * (j + (inner ? jitter(rng) : 0.));
      v.push_back(mesh.add_vertex(Point_2(x, y)));
    }
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < k; ++i) {
      const auto a = v[j * (k + 1) + i], b = v[j * (k + 1) + i + 1], c = v[(j + 1) * (k + 1) + i],
                 d = v[(j + 1) * (k + 1) + i + 1];
      mesh.add_face(a, b, d);
      mesh.add_face(a, d, c);
    }
  return mesh;
}

// Reads a planar mesh from an OFF file (z is ignored).
bool read_planar_mesh(const char* filename, Mesh& mesh)
{
  CGAL::Surface_mesh<K::Point_3> mesh_3;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh_3) || num_faces(mesh_3) == 0)
    return false;
  std::vector<vertex_descriptor> v(mesh_3.number_of_vertices());
  for(auto w : mesh_3.vertices())
    v[w.idx()] = mesh.add_vertex(Point_2(mesh_3.point(w).x(), mesh_3.point(w).y()));
  for(auto f : mesh_3.faces()) {
    std::vector<vertex_descriptor> face;
    for(auto w : vertices_around_face(mesh_3.halfedge(f), mesh_3))
      face.push_back(v[w.idx()]);
    if(mesh.add_face(face) == Mesh::null_face())
      return false;
  }
  return true;
}

// True when every face around v has the same orientation in the target as in the source.
bool ring_is_positive(const Mesh& mesh, vertex_descriptor v, const Target_map& target)
{
  for(auto f : faces_around_target(mesh.halfedge(v), mesh)) {
    if(f == Mesh::null_face())
      continue;
    std::vector<vertex_descriptor> t;
    for(auto w : vertices_around_face(mesh.halfedge(f), mesh))
      t.push_back(w);
    if(CGAL::orientation(target[t[0]], target[t[1]], target[t[2]]) !=
       CGAL::orientation(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2])))
      return false;
  }
  return true;
}

int main(int argc, char* argv[])
{
  Mesh mesh;
  if(argc > 1) {
    if(!read_planar_mesh(argv[1], mesh)) {
      std::cerr << "Error: cannot read a planar triangle mesh from " << argv[1] << std::endl;
      return 1;
    }
  } else {
    mesh = jittered_rectangle(64);
  }

  // The bend: the bounding box's long side is rolled onto a 120-degree arc of radius R, and a
  // point at height y above the box's mid-line goes to radius R - y. It stretches the bottom
  // and compresses the top: a smooth, orientation-preserving, non-rigid map.
  const CGAL::Bbox_2 box = CGAL::bbox_2(mesh.points().begin(), mesh.points().end());
  const double width = box.xmax() - box.xmin(), height = box.ymax() - box.ymin();
  const double cx = 0.5 * (box.xmin() + box.xmax()), cy = 0.5 * (box.ymin() + box.ymax());
  const double R = std::max(width / (2 * CGAL_PI / 3), height);
  auto bend = [&](const Point_2& p) {
    const double angle = (p.x() - cx) / R, r = R - (p.y() - cy);
    return Point_2(r * std::sin(angle), R - r * std::cos(angle));
  };

  // The start map: the bend, plus noise on the inner vertices. A noisy position is kept only if
  // the triangles around the vertex keep their orientation; otherwise the noise is halved.
  Target_map smooth = mesh.add_property_map<vertex_descriptor, Point_2>("v:smooth").first;
  Target_map start = mesh.add_property_map<vertex_descriptor, Point_2>("v:start").first;
  for(vertex_descriptor v : mesh.vertices())
    smooth[v] = start[v] = bend(mesh.point(v));
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> noise(-0.6, 0.6);   // times the shortest edge at v
  for(vertex_descriptor v : mesh.vertices()) {
    if(mesh.is_border(v))
      continue;
    double edge = std::numeric_limits<double>::infinity();
    for(vertex_descriptor w : vertices_around_target(mesh.halfedge(v), mesh))
      edge = std::min(edge, std::sqrt(CGAL::squared_distance(smooth[v], smooth[w])));
    const double dx = edge * noise(rng), dy = edge * noise(rng);
    for(double scale = 1; scale > 1e-3; scale /= 2) {
      start[v] = Point_2(smooth[v].x() + scale * dx, smooth[v].y() + scale * dy);
      if(ring_is_positive(mesh, v, start))
        break;
      start[v] = smooth[v];
    }
  }

  const auto inverted = CGAL::compute_distortion(mesh, start, DO::ARAP()).inverted_cells;
  std::printf("%zu vertices, %zu triangles, %zu inverted triangles in the start map\n",
              std::size_t(mesh.number_of_vertices()), std::size_t(mesh.number_of_faces()), std::size_t(inverted));
  if(inverted > 0) {
    std::cerr << "Error: the bend inverts triangles of this mesh" << std::endl;
    return 1;
  }

  // Optimize each measure from a copy of the same start map. Energies are volume-weighted means;
  // "bend" is the energy of the noise-free map, for reference.
  Target_map result = mesh.add_property_map<vertex_descriptor, Point_2>("v:result").first;
  std::printf("%-20s %12s %12s %12s %7s %9s %9s\n", "measure", "bend", "before", "after", "sweeps", "seconds",
              "inverted");
  auto optimize = [&](const auto& measure) {
    for(vertex_descriptor v : mesh.vertices())
      result[v] = start[v];
    const DO::Result r = CGAL::minimize_distortion(mesh, result, measure);
    std::printf("%-20s %12.6f %12.6f %12.6f %7zu %9.3f %9zu\n", measure.name().c_str(),
                CGAL::compute_distortion(mesh, smooth, measure).mean_volume, r.initial_energy, r.final_energy,
                r.iterations, r.seconds, r.inverted_cells);
  };
  optimize(DO::Conformal_dilatation());
  optimize(DO::Symmetric_dirichlet());
  return 0;
}
