// A closed surface's volume onto the unit ball (the paper's section 4.4 and Fig. 14).
//
// Reads a closed triangle surface that is star-shaped about the centre of its volume (default:
// blobby.off of libcgal-demo, a smooth, non-convex blob), scales it so that it encloses the
// volume of the unit ball, meshes its inside with tetrahedra (mesh_interior(), CGAL's Mesh_3),
// maps the tetrahedra onto the unit ball by the star-shaped radial construction
// (star_shaped_to_unit_ball()), then lowers the symmetric Dirichlet energy of that map with
// CGAL::minimize_distortion(), the boundary vertices sliding on the unit sphere instead of staying
// where the radial construction put them. The ball map may flatten a few tetrahedra (those whose
// four vertices are on the boundary, where the surface bends more than the mesh): they are
// untangled first. Prints one row per stage and writes the optimized map, with the distortion of
// each tetrahedron before and after, as a VTK file for ParaView.
//
//   volume_to_ball [closed_surface.off [output.vtu]]     (default output: volume_to_ball.vtu)

#include "volume_examples.h"

#include <CGAL/Distortion_optimization/IO/vtu.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace DOP = CGAL::Distortion_optimization::parameters;
using namespace volume_examples;
using C3t3 = Volume;
using Tr = C3t3::Triangulation;

namespace {

// Per-tetrahedron values of the measure under `target`, in the complex's cell order.
template <class Measure>
std::vector<double> distortion_per_cell(const C3t3& c3t3, const Targets& target, const Measure& measure)
{
  std::unordered_map<Tr::Cell_handle, double> per_cell;
  CGAL::compute_distortion(c3t3, boost::const_associative_property_map<Targets>(target), measure,
                           DOP::cell_distortion_map(boost::associative_property_map<decltype(per_cell)>(per_cell)));
  std::vector<double> values;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) values.push_back(per_cell.at(c));
  return values;
}

// The image of the tetrahedra as a VTU file with one array of values per cell.
void write_map(const std::string& path, const C3t3& c3t3, const Targets& target,
               const std::vector<std::pair<std::string, std::vector<double>>>& cell_data)
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> cells;
  DO::tetrahedra_from_c3t3(c3t3, points, cells,
                           CGAL::parameters::vertex_point_map(boost::const_associative_property_map<Targets>(target)));
  DO::IO::write_VTU(path, points, cells, cell_data);
}

void print_row(const char* stage, double seconds, std::size_t tets, const std::string& inverted, double before,
               double after, double distance)
{
  auto number = [](double x, const char* format) {
    if(std::isnan(x)) return std::string("-");
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, format, x);
    return std::string(buffer);
  };
  std::printf("%-16s %8.3f %8s %9s %14s %14s %12s\n", stage, seconds, tets ? std::to_string(tets).c_str() : "-",
              inverted.c_str(), number(before, "%.6g").c_str(), number(after, "%.6g").c_str(),
              number(distance, "%.2e").c_str());
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/blobby.off";
  const std::string output = argc > 2 ? argv[2] : "volume_to_ball.vtu";
  const double none = std::nan("");
  const DO::Symmetric_dirichlet measure;

  auto start = std::chrono::steady_clock::now();
  Surface surface;
  if(!CGAL::IO::read_polygon_mesh(filename, surface) || num_faces(surface) == 0) {
    std::cerr << "Error: cannot read a triangle mesh from " << filename << std::endl;
    return 1;
  }
  try {
    // The symmetric Dirichlet energy is not scale invariant: a map between volumes of different
    // sizes pays for the change of size everywhere. Scaling the input to the ball's volume leaves
    // only the change of shape to pay. interior_mesh_sizes() checks the surface as mesh_interior()
    // will (closed, manifold, no self-intersection) and measures the volume it encloses.
    const double volume = DO::interior_mesh_sizes(surface).volume;
    const double scale = std::cbrt(4 * CGAL_PI / 3 / volume);
    for(auto v : surface.vertices()) surface.point(v) = CGAL::ORIGIN + scale * (surface.point(v) - CGAL::ORIGIN);
    std::cout << filename << ": " << surface.number_of_vertices() << " vertices, " << surface.number_of_faces()
              << " triangles, scaled by " << scale << " to the volume of the unit ball" << std::endl;
    std::printf("%-16s %8s %8s %9s %14s %14s %12s\n", "stage", "seconds", "tets", "inverted", "energy before",
                "energy after", "max |r - 1|");
    print_row("read and check", seconds_since(start), 0, "-", none, none, none);

    // Mesh_3 with the default sizes (about 3.10^4 tetrahedra); every cell is positive. Sliver
    // exudation removes the flattest tetrahedra, so that fewer cells come out flat under the ball
    // map and the untangling has less to repair.
    start = std::chrono::steady_clock::now();
    const C3t3 c3t3 = DO::mesh_interior(surface, DOP::exude_slivers(true));
    const std::size_t tets = c3t3.number_of_cells_in_complex();
    print_row("mesh_interior", seconds_since(start), tets, "0", none, none, none);

    // The ball map throws if the mesh is not star-shaped about the centre (every boundary facet
    // must face away from it), and returns how many tetrahedra it inverts or flattens.
    start = std::chrono::steady_clock::now();
    Targets ball;
    const std::size_t flat = DO::star_shaped_to_unit_ball(c3t3, Target_map(ball), DO::volume_centroid(c3t3));
    const double ball_seconds = seconds_since(start);
    const auto boundary = boundary_vertices(c3t3);
    // A normalized measure is +infinity on a flat cell, and so is then the mean.
    const std::vector<double> start_values = distortion_per_cell(c3t3, ball, measure);
    const double start_energy = CGAL::compute_distortion(c3t3, Target_map(ball), measure).mean_volume;
    print_row("ball map", ball_seconds, tets, std::to_string(flat), none, start_energy,
              largest_distance_to_unit_sphere(boundary, ball));

    // With sliding_boundary no vertex is fixed: the boundary moves on the unit sphere (each move
    // projected back onto it exactly) and the inside follows. untangle_first repairs the flat
    // cells of the start, with the same sliding boundary, before the energy is minimized (the
    // energy is infinite until then). The returned energies are volume-weighted means, as
    // compute_distortion()'s mean_volume.
    const DO::Result r = CGAL::minimize_distortion(c3t3, Target_map(ball), measure,
      DOP::sliding_boundary(DO::Sphere_surface(), DOP::untangle_first(flat > 0)).number_of_iterations(200));
    if(flat > 0)
      print_row("untangle", r.untangle_seconds, tets, std::to_string(r.inverted_start_cells) + "->0", start_energy,
                r.initial_energy, none);
    print_row("optimize", r.seconds - r.untangle_seconds, tets, std::to_string(r.inverted_cells), r.initial_energy,
              r.final_energy, largest_distance_to_unit_sphere(boundary, ball));

    start = std::chrono::steady_clock::now();
    write_map(output, c3t3, ball, {{measure.name(), distortion_per_cell(c3t3, ball, measure)},
                                   {measure.name() + "_ball_map", start_values}});
    print_row("write VTU", seconds_since(start), tets, "-", none, none, none);
    std::cout << r.iterations << " iterations" << (r.converged ? " (converged)" : "") << "; the optimized map is in "
              << output << " (cell arrays: " << measure.name() << ", " << measure.name() << "_ball_map)" << std::endl;
  } catch(const DO::Invalid_input& e) {
    // Not closed, not manifold, self-intersecting, not star-shaped about its centre, ...
    std::cerr << "Error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
