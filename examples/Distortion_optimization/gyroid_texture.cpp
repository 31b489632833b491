// A gyroid carried from a cube onto a ball: a volumetric texture (the paper's section 4.4,
// Figs. 13 and 14).
//
// The gyroid sin x cos y + sin y cos z + sin z cos x = 0 has genus 3 per period cell: mapping it
// onto a sphere directly, as a surface, is hard. Instead, the cube that holds it is cut into
// tetrahedra (a regular grid, each small cube into six) and mapped onto the unit ball, and the gyroid rides along, embedded
// once in the cube's tetrahedra by barycentric coordinates (eq. 18). The start map, the radial
// construction star_shaped_to_unit_ball() (the method of [NSZ16] in Fig. 14), flattens tetrahedra
// across the cube's edges; CGAL::minimize_distortion() untangles them, then minimizes the isometric
// dilatation C = max(s1, 1/s3), the boundary sliding on the unit sphere. Prints the distortion of
// the gyroid carried by each map, and writes both carried gyroids. The gyroid (data/gyroid.off,
// one period, meshed by CGAL's Mesh_3) is placed 5% inside the cube, whatever its size in the file.
//
//   gyroid_texture [gyroid.off [output_folder]]     (default output folder: the working directory)

#include "volume_examples.h"

#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/Distortion_optimization/volumetric_texture.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>

namespace DO = CGAL::Distortion_optimization;
namespace DOP = CGAL::Distortion_optimization::parameters;
using namespace volume_examples;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/gyroid.off";
  const std::string folder = argc > 2 ? std::string(argv[2]) + "/" : std::string();
  Surface gyroid;
  if(!CGAL::IO::read_polygon_mesh(filename, gyroid) || !CGAL::is_triangle_mesh(gyroid) || gyroid.is_empty()) {
    std::cerr << "Error: cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  // The cube has the unit ball's volume: C is not scale invariant, and a cube of another size
  // would pay for the change of size everywhere.
  const double h = std::cbrt(4 * CGAL_PI / 3) / 2;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(gyroid);
  double extent = 0;
  for(int k = 0; k < 3; ++k) extent = std::max(extent, (box.max(k) - box.min(k)) / 2);
  const Point centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  for(auto v : gyroid.vertices())
    gyroid.point(v) = CGAL::ORIGIN + 0.95 * h / extent * (gyroid.point(v) - centre);
  const DO::Isometric_dilatation measure;
  try {
    const Volume volume = cube_volume(h, 16);   // 24,576 tetrahedra
    const auto embedding = DO::embed_surface_in_volume(volume, gyroid);

    Targets ball;
    const std::size_t flat = DO::star_shaped_to_unit_ball(volume, Target_map(ball), DO::parameters::center(CGAL::ORIGIN));
    Surface start;
    DO::carry_surface(gyroid, embedding, Target_map(ball), start);

    const DO::Result r = CGAL::minimize_distortion(volume, Target_map(ball), measure,
      DOP::sliding_boundary(DO::Sphere_surface(), DOP::untangle_first(flat > 0)).number_of_iterations(200));
    Surface optimized;
    DO::carry_surface(gyroid, embedding, Target_map(ball), optimized);

    // A carried gyroid has the gyroid's vertex descriptors: its points are a target map of it.
    const double start_c = CGAL::compute_distortion(gyroid, start.points(), measure).mean_volume;
    const double optimized_c = CGAL::compute_distortion(gyroid, optimized.points(), measure).mean_volume;
    std::cout << "gyroid: " << gyroid.number_of_faces() << " triangles in " << volume.number_of_cells_in_complex()
              << " tetrahedra (" << flat << " flat in the ball map); " << measure.name() << " of the volume map "
              << r.initial_energy << " after untangling, " << r.final_energy << " optimized; of the gyroid "
              << start_c << " carried by the ball map, " << optimized_c << " by the optimized map" << std::endl;
    if(r.inverted_cells > 0 || !(r.final_energy < r.initial_energy) || !(optimized_c < start_c)) {
      std::cerr << "Error: inverted tetrahedra, or the optimized map distorts as much as the ball map" << std::endl;
      return EXIT_FAILURE;
    }

    const std::pair<const char*, const Surface*> outputs[] = {{"gyroid_ball_map.off", &start},
                                                              {"gyroid_optimized.off", &optimized}};
    for(const auto& [name, mesh] : outputs)
      if(!CGAL::IO::write_polygon_mesh(folder + name, *mesh, CGAL::parameters::stream_precision(17))) {
        std::cerr << "Error: cannot write " << folder + name << std::endl;
        return EXIT_FAILURE;
      }
    std::cout << "wrote " << folder << "gyroid_ball_map.off and " << folder << "gyroid_optimized.off" << std::endl;
  } catch(const DO::Invalid_input& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
