// A gyroid carried from a cube onto a ball: a volumetric texture (the paper's section 4.4,
// Figs. 13 and 14).
//
// The gyroid sin x cos y + sin y cos z + sin z cos x = 0 has genus 3 per period cell: mapping it
// onto a sphere directly, as a surface, is hard. Instead, the cube that holds it is mapped onto a
// ball and the gyroid rides along:
//   1. the gyroid, two periods per side, meshed by CGAL's Mesh_3 from its implicit function and
//      kept to a box 5% smaller than the cube, so that every vertex is inside the volume;
//   2. the cube (12 triangles, of the unit ball's volume) meshed with tetrahedra (mesh_interior(),
//      slivers exuded);
//   3. the start map: the cube onto the unit ball by the star-shaped radial construction
//      (star_shaped_to_unit_ball(), the method of [NSZ16] in Fig. 14), which flattens
//      tetrahedra across the cube's edges;
//   4. the optimized map: the isometric dilatation C = max(s1, 1/s3) minimized from the start,
//      the flat tetrahedra untangled first, the boundary sliding on the unit sphere;
//   5. the gyroid embedded once in the cube's tetrahedra (barycentric coordinates, eq. 18) and
//      carried under both maps; the distortion of each carried gyroid against the original one.
// Writes gyroid.off (in the cube), gyroid_ball_map.off and gyroid_optimized.off (in the ball).
//
//   gyroid_texture [output_folder]     (default: the working directory)

#include "volume_examples.h"

#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/Distortion_optimization/volumetric_texture.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>

namespace DO = CGAL::Distortion_optimization;
namespace DOP = CGAL::Distortion_optimization::parameters;
using namespace volume_examples;

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? std::string(argv[1]) + "/" : std::string();
  const int periods = 2;
  // Of the unit ball's volume: the isometric dilatation is not scale invariant, so that a cube
  // of another size would pay for the change of size everywhere.
  const double h = std::cbrt(4 * CGAL_PI / 3) / 2;
  const DO::Isometric_dilatation isometric;
  const DO::Conformal_dilatation conformal;

  try {
    auto start = std::chrono::steady_clock::now();
    const Surface gyroid = mesh_gyroid(h, periods, 0.95 * h);
    std::printf("gyroid: %zu vertices, %zu triangles, meshed in %.2f s\n", std::size_t(gyroid.number_of_vertices()),
                std::size_t(gyroid.number_of_faces()), seconds_since(start));

    // The cube has sharp edges: mesh_interior() protects them, so the complex is exactly the
    // cube (its boundary vertices lie on its faces and edges). Sliver exudation removes the
    // flattest tetrahedra, so that fewer cells come out flat under the ball map and the
    // untangling has less to repair.
    start = std::chrono::steady_clock::now();
    const Volume volume = DO::mesh_interior(cube(h), DOP::exude_slivers(true));
    std::printf("cube: %zu tetrahedra, meshed in %.2f s\n", std::size_t(volume.number_of_cells_in_complex()),
                seconds_since(start));

    // The gyroid's vertices located once in the source tetrahedra (a walk in the triangulation,
    // checked with exact predicates); every map then carries them by their barycentric
    // coordinates, without locating them again.
    start = std::chrono::steady_clock::now();
    const auto embedding = DO::embed_surface_in_volume(volume, gyroid);
    std::printf("gyroid embedded in the tetrahedra in %.3f s\n\n", seconds_since(start));

    // One row per map: its time, its inverted tetrahedra, its isometric dilatation C (mean over
    // the volume), and the distortion of the gyroid it carries, C and the conformal dilatation K
    // (area-weighted mean, max). A carried surface is a copy of the gyroid (same vertex
    // descriptors) with moved points: its point map is a Point_3 target map of the gyroid, each
    // triangle measured in its own plane.
    std::printf("%-18s %8s %9s %10s %10s %10s %10s %10s %8s\n", "map", "seconds", "inverted", "volume C",
                "gyroid C", "C max", "gyroid K", "K max", "carry s");
    auto row = [&](const char* name, double seconds, std::size_t inverted, double volume_c, const Targets& map,
                   Surface& carried) {
      const auto carry_start = std::chrono::steady_clock::now();
      DO::carry_surface(gyroid, embedding, boost::const_associative_property_map<Targets>(map), carried);
      const double carry_seconds = seconds_since(carry_start);
      const auto c = CGAL::compute_distortion(gyroid, carried.points(), isometric);
      const auto k = CGAL::compute_distortion(gyroid, carried.points(), conformal);
      std::printf("%-18s %8.3f %9zu %10.5g %10.5g %10.5g %10.5g %10.5g %8.3f\n", name, seconds, inverted, volume_c,
                  c.mean_volume, c.max, k.mean_volume, k.max, carry_seconds);
      std::fflush(stdout);
    };

    // The start map. Its boundary lands on the unit sphere; tetrahedra with four vertices on the
    // boundary across an edge of the cube come out flat (their number is returned), and C is
    // +infinity on them.
    start = std::chrono::steady_clock::now();
    Targets ball_map;
    const std::size_t flat = DO::star_shaped_to_unit_ball(volume, Target_map(ball_map), CGAL::ORIGIN);
    const double ball_seconds = seconds_since(start);
    Surface carried_start;
    row("ball map (start)", ball_seconds, flat,
        CGAL::compute_distortion(volume, Target_map(ball_map), isometric).mean_volume, ball_map, carried_start);

    // The optimized map, from a copy of the start. With sliding_boundary no vertex is fixed: the
    // boundary moves on the unit sphere. untangle_first repairs the flat cells (with the same
    // sliding boundary) before C is minimized.
    Targets optimized = ball_map;
    const DO::Result r = CGAL::minimize_distortion(volume, Target_map(optimized), isometric,
      DOP::sliding_boundary(DO::Sphere_surface(), DOP::untangle_first(flat > 0)).number_of_iterations(200));
    Surface carried_optimized;
    row("optimized", r.seconds, r.inverted_cells, r.final_energy, optimized, carried_optimized);
    std::printf("(optimized: %zu iterations%s", r.iterations, r.converged ? ", converged" : "");
    if(r.untangle_iterations > 0)
      std::printf("; untangling %zu cells took %.3f s, then C = %.5g", r.inverted_start_cells, r.untangle_seconds,
                  r.initial_energy);
    std::printf(")\n");

    const std::pair<const char*, const Surface*> outputs[] = {
      {"gyroid.off", &gyroid}, {"gyroid_ball_map.off", &carried_start}, {"gyroid_optimized.off", &carried_optimized}};
    for(const auto& [name, mesh] : outputs)
      if(!CGAL::IO::write_polygon_mesh(folder + name, *mesh, CGAL::parameters::stream_precision(17))) {
        std::cerr << "Error: cannot write " << folder + name << std::endl;
        return 1;
      }
    std::cout << "wrote " << folder << "gyroid.off, gyroid_ball_map.off, gyroid_optimized.off" << std::endl;
  } catch(const DO::Invalid_input& e) {
    std::cerr << "Error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
