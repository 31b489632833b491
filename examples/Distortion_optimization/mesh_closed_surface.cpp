// The inside of a closed surface meshed with tetrahedra (the start of the paper's section 4.4).
//
// Reads a closed, 2-manifold triangle surface that does not intersect itself (default: blobby.off),
// meshes its inside with CGAL's Mesh_3 through mesh_interior() at the default sizes (about 3.10^4
// tetrahedra), with sliver exudation, and writes the tetrahedra as a MEDIT .mesh file, the input of
// volume_to_ball and of the command-line tool.
//
//   mesh_closed_surface [closed_surface.off [output.mesh]]     (default output: closed_surface.mesh)

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/mesh_interior.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace DO = CGAL::Distortion_optimization;

int main(int argc, char* argv[])
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::string filename = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/blobby.off";
  const std::string output = argc > 2 ? argv[2] : "closed_surface.mesh";
  CGAL::Surface_mesh<K::Point_3> surface;
  if(!CGAL::IO::read_polygon_mesh(filename, surface)) {
    std::cerr << "Error: cannot read a polygon mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  try {
    // Sliver exudation removes the flattest tetrahedra: fewer come out flat under later maps.
    const auto volume = DO::mesh_interior(surface, DO::parameters::exude_slivers(true));
    DO::IO::Tetrahedron_soup soup;
    DO::tetrahedra_from_c3t3(volume, soup.points, soup.cells);
    DO::IO::write_MEDIT_soup(output, soup);
    std::cout << filename << ": " << soup.cells.size() << " tetrahedra, " << soup.points.size()
              << " vertices; wrote " << output << std::endl;
  } catch(const DO::Invalid_input& e) {
    // Not closed, not manifold, self-intersecting, sizes that ask for too many vertices, ...
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
