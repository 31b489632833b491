// A closed surface's volume onto the unit ball (the paper's section 4.4 and Fig. 14).
//
// Reads a tetrahedral mesh (MEDIT .mesh) of a volume that is star-shaped about its centroid (e.g.
// the inside of blobby.off, a smooth, non-convex blob, meshed by the example mesh_closed_surface),
// scales it to the volume of the unit ball, maps it onto the unit ball by the star-shaped radial
// construction (star_shaped_to_unit_ball()), then lowers the symmetric Dirichlet energy of that
// map with CGAL::minimize_distortion(), the boundary vertices sliding on the unit sphere. The few
// tetrahedra that the ball map flattens are untangled first. Writes the optimized map, with the
// distortion of each tetrahedron, as a VTK file for ParaView.
//
//   volume_to_ball volume.mesh [output.vtu]     (default output: volume_to_ball.vtu)

#include "volume_examples.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <unordered_map>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace DOP = CGAL::Distortion_optimization::parameters;
using namespace volume_examples;

int main(int argc, char* argv[])
{
  if(argc < 2) {
    std::cerr << "usage: volume_to_ball volume.mesh [output.vtu]" << std::endl;
    return 2;
  }
  const std::string filename = argv[1];
  const std::string output = argc > 2 ? argv[2] : "volume_to_ball.vtu";
  try {
    DO::IO::Tetrahedron_soup soup = DO::IO::read_tetrahedron_soup(filename);
    // The symmetric Dirichlet energy is not scale invariant: at the ball's volume, the map pays
    // only for the change of shape.
    double enclosed = 0;
    for(const auto& t : soup.cells) {
      const auto& [a, b, c, d] = t;
      const auto p = [&](std::size_t i) { return Point(soup.points[i][0], soup.points[i][1], soup.points[i][2]); };
      enclosed += std::abs(CGAL::volume(p(a), p(b), p(c), p(d)));
    }
    const double scale = std::cbrt(4 * CGAL_PI / 3 / enclosed);
    for(auto& point : soup.points)
      for(double& x : point) x *= scale;
    Volume volume;
    DO::c3t3_from_tetrahedra(volume, soup.points, soup.cells);

    // Throws if the volume is not star-shaped about its centroid; returns how many cells it flattens.
    Targets ball;
    const std::size_t flat = DO::star_shaped_to_unit_ball(volume, Target_map(ball));

    // No vertex is fixed: the boundary slides on the unit sphere and the inside follows.
    const DO::Symmetric_dirichlet measure;
    const DO::Result r = CGAL::minimize_distortion(volume, Target_map(ball), measure,
      DOP::sliding_boundary(DO::Sphere_surface(), DOP::untangle_first(flat > 0)).number_of_iterations(200));
    std::cout << filename << ": " << volume.number_of_cells_in_complex() << " tetrahedra, " << flat
              << " flat in the ball map; " << measure.name() << " after untangling " << r.initial_energy
              << ", optimized " << r.final_energy << " in " << r.iterations << " iterations" << std::endl;
    if(r.inverted_cells > 0 || !(r.final_energy < r.initial_energy)) {
      std::cerr << "Error: " << r.inverted_cells << " inverted tetrahedra, or no lower energy" << std::endl;
      return EXIT_FAILURE;
    }

    // The image of the tetrahedra, with the distortion of each (in the complex's cell order).
    std::unordered_map<Volume::Triangulation::Cell_handle, double> per_cell;
    CGAL::compute_distortion(volume, Target_map(ball), measure,
                             DOP::cell_distortion_map(boost::associative_property_map<decltype(per_cell)>(per_cell)));
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::size_t, 4>> tetrahedra;
    DO::tetrahedra_from_c3t3(volume, points, tetrahedra, CGAL::parameters::vertex_point_map(Target_map(ball)));
    std::vector<double> values;
    for(auto c = volume.cells_in_complex_begin(); c != volume.cells_in_complex_end(); ++c) values.push_back(per_cell[c]);
    DO::IO::write_VTU(output, points, tetrahedra, {{measure.name(), values}});
    std::cout << "wrote " << output << std::endl;
  } catch(const DO::Invalid_input& e) {
    // A file that is not a tetrahedral mesh, a volume not star-shaped about its centroid, ...
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
