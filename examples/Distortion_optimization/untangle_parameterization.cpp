// Repair, then improve, CGAL's own parameterization.
//
// CGAL's ARAP_parameterizer_3 can return OK with flipped triangles on real disks (the manual shows
// lion-head's). This example counts them, then calls CGAL::minimize_distortion() with
// untangle_first: the map is first made injective (Distortion_optimization::untangle(), no
// triangle inverted, the free border kept from crossing itself), then its symmetric Dirichlet
// energy is minimized. It writes the surface with both parameterizations as UVs (OBJ: v, vt,
// f v/vt) and pictures of both maps, each triangle coloured by its distortion (the flipped ones in
// red).
//
//   untangle_parameterization [mesh.off [output_prefix]]
//
// writes output_prefix_arap.obj, _arap.svg, _optimized.obj, _optimized.svg (default prefix: the
// mesh's name in the current folder).

#include <CGAL/Distortion_optimization/IO/svg.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace SMP = CGAL::Surface_mesh_parameterization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Vertex = Mesh::Vertex_index;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/lion-head.off";
  std::string prefix = argc > 2 ? argv[2] : path.substr(path.find_last_of('/') + 1);
  if(argc <= 2) prefix = prefix.substr(0, prefix.find_last_of('.'));
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << path << ": not a triangle mesh\n";
    return EXIT_FAILURE;
  }
  auto uv = mesh.add_property_map<Vertex, K::Point_2>("v:uv").first;
  const SMP::Error_code status =
    SMP::parameterize(mesh, SMP::ARAP_parameterizer_3<Mesh>(), CGAL::Polygon_mesh_processing::longest_border(mesh).first, uv);
  if(status != SMP::OK) {
    std::cerr << path << ": ARAP failed: " << SMP::get_error_message(status) << "\n";
    return EXIT_FAILURE;
  }

  // The surface with its UVs (OBJ), and a picture of the map, each triangle coloured by its distortion.
  auto per_face = mesh.add_property_map<Mesh::Face_index, double>("f:distortion").first;
  const DO::Symmetric_dirichlet measure;
  const auto write = [&](const std::string& name) {
    const DO::Distortion_statistics s = CGAL::compute_distortion(mesh, uv, measure, DO::parameters::cell_distortion_map(per_face));
    DO::IO::Triangle_soup soup;
    std::vector<std::array<double, 3>> flat;   // the map in the plane, for the picture
    for(Vertex v : mesh.vertices()) {
      soup.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
      soup.texture_coordinates.push_back({uv[v].x(), uv[v].y()});
      flat.push_back({uv[v].x(), uv[v].y(), 0});
    }
    for(auto f : mesh.faces()) {
      const auto h = mesh.halfedge(f);
      soup.cells.push_back({mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))});
    }
    soup.cell_texture_indices = soup.cells;
    DO::IO::write_triangle_soup(prefix + "_" + name + ".obj", soup);
    const std::vector<double> values(per_face.begin(), per_face.end());
    DO::IO::write_SVG(prefix + "_" + name + ".svg", {DO::IO::triangle_panel(name, flat, soup.cells, values)}, measure.name());
    return s;
  };
  const DO::Distortion_statistics arap = write("arap");
  std::printf("%s: %zu vertices, %zu triangles; CGAL's ARAP parameterization: %zu triangles flipped\n", path.c_str(),
              std::size_t(mesh.number_of_vertices()), std::size_t(mesh.number_of_faces()), arap.inverted_cells);

  // Untangle, then minimize, the border free (kept from crossing itself).
  auto free = mesh.add_property_map<Vertex, bool>("v:free", false).first;
  const DO::Result r = CGAL::minimize_distortion(
    mesh, uv, measure,
    DO::parameters::untangle_first(true, DO::parameters::preserve_global_injectivity(true)).vertex_is_constrained_map(free));
  const DO::Distortion_statistics optimized = write("optimized");
  std::printf("untangled: %zu -> %zu inverted in %.3f s (%zu iterations); %s %.6f after %zu iterations, %.3f s in all\n",
              r.inverted_start_cells, r.inverted_cells, r.untangle_seconds, r.untangle_iterations, measure.name().c_str(),
              optimized.mean_volume, r.iterations, r.seconds);
  std::printf("wrote %s_arap.obj, %s_arap.svg, %s_optimized.obj, %s_optimized.svg\n", prefix.c_str(), prefix.c_str(),
              prefix.c_str(), prefix.c_str());
  if(r.inverted_cells > 0 || !(r.final_energy < r.initial_energy)) {
    std::cerr << "Error: inverted triangles left, or no lower energy after the untangling" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
