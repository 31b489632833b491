// Fixed-boundary planar deformation.
//
// Reads a triangle mesh and takes its projection on the xy plane as a planar mesh (default:
// nefertiti.off, a face in relief, seen from the front). The map bends it into an arc: the border
// vertices follow the smooth bend exactly, the inner vertices follow it up to some noise that keeps
// every triangle positively oriented. From that noisy start, CGAL::minimize_distortion() moves the
// inner vertices (the border is fixed by default) to minimize the symmetric Dirichlet energy; any
// other measure of the package, e.g. the conformal dilatation K, is used the same way.
//
//   planar_deformation [mesh.off [output.off]]     (default output: planar_deformation.off)

#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_2 = K::Point_2;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Vertex = Mesh::Vertex_index;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/nefertiti.off";
  const std::string output = argc > 2 ? argv[2] : "planar_deformation.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "Error: cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  // The source of the map: the mesh seen along z (its triangles must not overlap there).
  auto source = mesh.add_property_map<Vertex, Point_2>("v:source").first;
  for(Vertex v : mesh.vertices()) source[v] = Point_2(mesh.point(v).x(), mesh.point(v).y());

  // The bend: the long side of the bounding box is rolled onto a 120-degree arc of radius R, and a
  // point at height y above the box's mid-line goes to radius R - y: a smooth, orientation
  // preserving map that stretches the bottom and compresses the top.
  const CGAL::Bbox_2 box = CGAL::bbox_2(source.begin(), source.end());
  const double cx = (box.xmin() + box.xmax()) / 2, cy = (box.ymin() + box.ymax()) / 2;
  const double R = std::max((box.xmax() - box.xmin()) / (2 * CGAL_PI / 3), box.ymax() - box.ymin());
  auto bend = [&](const Point_2& p) {
    const double angle = (p.x() - cx) / R, r = R - (p.y() - cy);
    return Point_2(r * std::sin(angle), R - r * std::cos(angle));
  };

  // The start map: the bend plus noise on the inner vertices, a fraction of the shortest edge at
  // each, halved until no triangle is inverted (minimize_distortion() needs a valid start).
  auto target = mesh.add_property_map<Vertex, Point_2>("v:target").first;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> noise(-0.6, 0.6);
  const DO::Symmetric_dirichlet measure;
  DO::Result r;
  try {   // minimize_distortion() and compute_distortion() throw on a flat source triangle
    std::size_t inverted = 1;
    for(double scale = 1; inverted > 0 && scale > 1e-3; scale /= 2) {
      for(Vertex v : mesh.vertices()) {
        double edge = mesh.is_border(v) ? 0 : HUGE_VAL;   // no noise on the border
        for(Vertex w : vertices_around_target(mesh.halfedge(v), mesh))
          edge = std::min(edge, std::sqrt(CGAL::squared_distance(source[v], source[w])));
        const double dx = scale * edge * noise(rng), dy = scale * edge * noise(rng);
        target[v] = bend(Point_2(source[v].x() + dx, source[v].y() + dy));
      }
      inverted = CGAL::compute_distortion(mesh, target, measure, CGAL::parameters::vertex_point_map(source)).inverted_cells;
    }
    if(inverted > 0) throw DO::Invalid_input("the bend inverts triangles of this mesh");
    r = CGAL::minimize_distortion(mesh, target, measure, CGAL::parameters::vertex_point_map(source));
  } catch(const DO::Invalid_input& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << filename << ": " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " triangles; "
            << measure.name() << " " << r.initial_energy << " -> " << r.final_energy << " in " << r.iterations
            << " iterations, " << r.inverted_cells << " inverted" << std::endl;
  if(r.inverted_cells > 0 || !(r.final_energy < r.initial_energy)) {
    std::cerr << "Error: the optimized map is not better than the start" << std::endl;
    return EXIT_FAILURE;
  }

  // The deformed mesh, in the plane z = 0.
  for(Vertex v : mesh.vertices()) mesh.point(v) = K::Point_3(target[v].x(), target[v].y(), 0);
  if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << "Error: cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << std::endl;
  return EXIT_SUCCESS;
}
