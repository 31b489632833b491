// Parameterize, then improve.
//
// Reads a surface mesh that is a topological disk, computes its Tutte parameterization (border
// on a circle, inner vertices at the barycenter of their neighbours: injective, but distorted),
// then improves a copy of it with CGAL::minimize_distortion() for several measures, the border
// staying fixed: the conformal dilatation K, the isometric dilatation C, the symmetric Dirichlet
// energy, and the product K * C (the paper's Fig. 9), which trades angles against lengths.
// Finally the symmetric Dirichlet energy with a free border, kept from crossing itself
// (preserve_global_injectivity), on two threads when the program links TBB.
//
//   improve_parameterization [mesh.off [uv.obj]]
//
// With a second argument, the K * C map is written as an OBJ file of the points (u, v, 0) with
// the faces of the mesh.

#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using UV_map = Mesh::Property_map<vertex_descriptor, K::Point_2>;

// Writes (u, v, 0) and the faces of `mesh` to a temporary file, then renames it to `filename`,
// so that a reader never sees a half-written file.
bool write_uv_obj(const Mesh& mesh, const UV_map& uv, const std::string& filename)
{
  const std::string temporary = filename + ".tmp";
  {
    std::ofstream out(temporary);
    out.precision(17);
    // The mesh was just read, so it has no removed vertices: its indices are 0, 1, ..., n-1.
    for(vertex_descriptor v : mesh.vertices())
      out << "v " << uv[v].x() << ' ' << uv[v].y() << " 0\n";
    for(auto f : mesh.faces()) {
      out << 'f';
      for(vertex_descriptor v : vertices_around_face(mesh.halfedge(f), mesh))
        out << ' ' << std::size_t(v) + 1;   // OBJ indices start at 1
      out << '\n';
    }
    if(!out.flush())
      return false;
  }
  return std::rename(temporary.c_str(), filename.c_str()) == 0;
}

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/mushroom.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || num_faces(mesh) == 0) {
    std::cerr << "Error: cannot read a triangle mesh from " << filename << std::endl;
    return 1;
  }
  std::cout << filename << ": " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " triangles" << std::endl;

  // The start map: Tutte's barycentric map onto a circle (throws if the mesh is not a disk).
  UV_map tutte = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:tutte").first;
  UV_map uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  try {
    DO::initial_parameterization(mesh, tutte);
  } catch(const DO::Invalid_input& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return 1;
  }

  // Improve a copy of the Tutte map for each measure. Energies are volume-weighted means.
  // K is blind to scale; C and the symmetric Dirichlet energy are not: the Tutte map is scaled to
  // the surface's area, but with the border fixed on a circle its shape still costs isometry.
  std::printf("%-22s %12s %12s %7s %9s %9s\n", "measure", "Tutte", "improved", "sweeps", "seconds", "inverted");
  auto improve = [&](const auto& measure) {
    for(vertex_descriptor v : mesh.vertices())
      uv[v] = tutte[v];
    const DO::Result r = CGAL::minimize_distortion(mesh, uv, measure);
    std::printf("%-22s %12.6f %12.6f %7zu %9.3f %9zu\n", measure.name().c_str(), r.initial_energy, r.final_energy,
                r.iterations, r.seconds, r.inverted_cells);
  };
  improve(DO::Conformal_dilatation());
  improve(DO::Isometric_dilatation());
  improve(DO::Symmetric_dirichlet());
  improve(DO::Product<DO::Conformal_dilatation, DO::Isometric_dilatation>());   // uv holds K * C

  // A free border: no vertex constrained; the guard keeps the border from crossing itself.
  Mesh::Property_map<vertex_descriptor, bool> none = mesh.add_property_map<vertex_descriptor, bool>("v:free", false).first;
  UV_map free_uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:free_uv").first;
  for(vertex_descriptor v : mesh.vertices())
    free_uv[v] = tutte[v];
  namespace DOP = DO::parameters;
  const DO::Result r = CGAL::minimize_distortion(mesh, free_uv, DO::Symmetric_dirichlet(),
    DOP::preserve_global_injectivity(true, DOP::number_of_threads(2)).vertex_is_constrained_map(none));
  std::printf("%-22s %12.6f %12.6f %7zu %9.3f %9zu\n", "sym. Dirichlet, free", r.initial_energy, r.final_energy,
              r.iterations, r.seconds, r.inverted_cells);

  if(argc > 2) {
    if(!write_uv_obj(mesh, uv, argv[2])) {
      std::cerr << "Error: cannot write " << argv[2] << std::endl;
      return 1;
    }
    std::cout << "K * C map written to " << argv[2] << std::endl;
  }
  return 0;
}
