// Parameterize, then improve.
//
// Reads a surface mesh that is a topological disk, computes its Tutte parameterization (border on
// a circle, inner vertices at the barycenter of their neighbours: injective, but distorted), then
// improves it with CGAL::minimize_distortion(), the border staying fixed, for the product K * C of
// the conformal and isometric dilatations (the paper's Fig. 9), which trades angles against
// lengths. Writes the improved map as a flat mesh: the points (u, v, 0) with the faces of the mesh.
//
//   improve_parameterization [mesh.off [uv.off]]     (default output: improve_parameterization.off)

#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Vertex = Mesh::Vertex_index;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/mushroom.off";
  const std::string output = argc > 2 ? argv[2] : "improve_parameterization.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "Error: cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  auto uv = mesh.add_property_map<Vertex, K::Point_2>("v:uv").first;
  const DO::Product<DO::Conformal_dilatation, DO::Isometric_dilatation> measure;
  DO::Result r;
  try {
    // The start map; it throws if the mesh is not a disk.
    DO::initial_parameterization(mesh, uv);
    r = CGAL::minimize_distortion(mesh, uv, measure);
  } catch(const DO::Invalid_input& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << filename << ": " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " triangles; " << measure.name() << " (volume-weighted mean) of the Tutte map " << r.initial_energy
            << ", improved " << r.final_energy << " in " << r.iterations << " iterations" << std::endl;
  if(r.inverted_cells > 0 || !(r.final_energy < r.initial_energy)) {
    std::cerr << "Error: the improved map has inverted triangles or no lower energy" << std::endl;
    return EXIT_FAILURE;
  }

  for(Vertex v : mesh.vertices()) mesh.point(v) = K::Point_3(uv[v].x(), uv[v].y(), 0);
  if(!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << "Error: cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << std::endl;
  return EXIT_SUCCESS;
}
