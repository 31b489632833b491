// Mesh quality at about 5.10^4 tetrahedra: improve_mesh_quality() (the paper's section 4.2 as a
// mesh optimizer, fixed connectivity) against CGAL Mesh_3's own optimizers, on the same meshes.
//
// mesh_interior() is deterministic (seeded, sequential): the same surface and sizes give the same
// refined complex, with or without Mesh_3's optimizers after it. So each row starts from the same
// mesh: "Mesh_3" is the refined mesh as it is; "Mesh_3 + ODT/perturb/exude" runs Mesh_3's
// optimizers on it (their time is the difference with the plain meshing); "ours, fixed" and
// "ours, sliding" run improve_mesh_quality() with the conformal dilatation K on the plain mesh,
// the boundary fixed, or sliding on the mesh's own boundary with its sharp edges fixed; the last
// row runs ours after Mesh_3's exudation. Each configuration runs `repeats` times, interleaved;
// median times are reported (the runs are deterministic, so all else is the same in each).
// "on bound." counts the slivers whose four vertices are all on the boundary surface: moving
// vertices, with the boundary fixed or sliding on that surface, cannot open them; only a change of
// connectivity (Mesh_3's exudation, which reweights the triangulation) can.
//
//   build/benchmark/Distortion_optimization/bench_quality [repeats, default 3 [closed_surface.off ...]]
//   (default surfaces: blobby.off of libcgal-demo, and the cube)

#include "bench_helpers.h"

#include <CGAL/Distortion_optimization/mesh_quality.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace DOP = CGAL::Distortion_optimization::parameters;
using namespace volume_examples;

namespace {

const double cells_wanted = 50000;

struct Row
{
  std::string name;
  std::vector<double> seconds;
  DO::Mesh_quality quality;
  std::size_t boundary_slivers = 0;
};

// The quality of `volume` at `positions` into `row`, with the slivers (smallest dihedral angle
// below 10 degrees, as mesh_quality() counts them) whose vertices are all on the boundary.
void score(const Volume& volume, const Targets& positions, Row& row)
{
  row.quality = DO::mesh_quality(volume, boost::const_associative_property_map<Targets>(positions));
  row.boundary_slivers = 0;
  for(auto c = volume.cells_in_complex_begin(); c != volume.cells_in_complex_end(); ++c) {
    bool on_boundary = true;
    std::array<DO::internal::Vector<3>, 4> x;
    for(int i = 0; i < 4; ++i) {
      on_boundary = on_boundary && volume.in_dimension(c->vertex(i)) < 3;
      x[i] = DO::internal::as_vector(positions.at(c->vertex(i)));
    }
    if(!on_boundary) continue;
    std::array<double, 6> angles;
    int count = 0;
    double ratio = 0;
    DO::internal::cell_shape(x, angles, count, ratio);
    row.boundary_slivers += *std::min_element(angles.begin(), angles.begin() + count) < 10;
  }
}

void print(const Row& row)
{
  const DO::Mesh_quality& q = row.quality;
  std::printf("%-30s %8.3f %8zu %9.3f %9.3f %9.4f %9.4f %8zu %9zu %8zu\n", row.name.c_str(), median(row.seconds), q.cells,
              q.min_angle, q.max_angle, q.min_radius_ratio, q.mean_radius_ratio, q.slivers, row.boundary_slivers,
              q.inverted_cells);
}

Targets identity(const Volume& volume)
{
  Targets positions;
  DO::map_vertices(volume, Target_map(positions), [](const Point& p) { return p; });
  return positions;
}

// improve_mesh_quality() on `volume` (K), boundary fixed or sliding with sharp edges fixed, into
// `row` (its time after `earlier_seconds`).
void ours(const Volume& volume, bool sliding, double earlier_seconds, Row& row)
{
  Targets positions = identity(volume);
  const auto start = std::chrono::steady_clock::now();
  if(sliding) {
    const auto sharp = DO::sharp_boundary_vertices(volume, Target_map(positions));
    DO::improve_mesh_quality(volume, Target_map(positions), DO::Conformal_dilatation(),
      DOP::sliding_boundary(DO::Triangle_surface::from_complex_boundary(volume, Target_map(positions)),
        CGAL::parameters::vertex_is_constrained_map(
          boost::make_function_property_map<Vertex_handle>([&](Vertex_handle v) { return sharp.count(v) > 0; }))));
  } else {
    DO::improve_mesh_quality(volume, Target_map(positions));
  }
  row.seconds.push_back(earlier_seconds + seconds_since(start));
  score(volume, positions, row);
}

void bench_surface(const std::string& name, const Surface& surface, int repeats)
{
  // The cell size for about `cells_wanted` tetrahedra: the count goes as cell_size^-3.
  double h = DO::interior_mesh_sizes(surface).cell_size;
  h *= std::cbrt(DO::mesh_interior(surface, DOP::cell_size(h)).number_of_cells_in_complex() / cells_wanted);

  Row plain{"Mesh_3 (refined only)", {}, {}}, odt{"Mesh_3 + ODT + perturb + exude", {}, {}},
      exude{"Mesh_3 + exude", {}, {}}, fixed{"ours (K), boundary fixed", {}, {}},
      sliding{"ours (K), boundary sliding", {}, {}}, after_exude{"Mesh_3 + exude, then ours", {}, {}};
  for(int r = 0; r < repeats; ++r) {
    auto start = std::chrono::steady_clock::now();
    const Volume refined = DO::mesh_interior(surface, DOP::cell_size(h));
    const double mesh_seconds = seconds_since(start);
    plain.seconds.push_back(0);
    const Targets refined_positions = identity(refined);
    score(refined, refined_positions, plain);

    start = std::chrono::steady_clock::now();
    const Volume optimized = DO::mesh_interior(surface, DOP::cell_size(h, DOP::odt_iterations(25, DOP::perturb_slivers(true,
                                                                          DOP::exude_slivers(true)))));
    odt.seconds.push_back(seconds_since(start) - mesh_seconds);
    const Targets odt_positions = identity(optimized);
    score(optimized, odt_positions, odt);

    start = std::chrono::steady_clock::now();
    const Volume exuded = DO::mesh_interior(surface, DOP::cell_size(h, DOP::exude_slivers(true)));
    exude.seconds.push_back(seconds_since(start) - mesh_seconds);
    const Targets exuded_positions = identity(exuded);
    score(exuded, exuded_positions, exude);

    ours(refined, false, 0, fixed);
    ours(refined, true, 0, sliding);
    ours(exuded, true, exude.seconds.back(), after_exude);
  }
  std::printf("\n%s (cell size %.4g), median of %d runs; times exclude the refinement\n", name.c_str(), h, repeats);
  std::printf("%-30s %8s %8s %9s %9s %9s %9s %8s %9s %8s\n", "mesh", "seconds", "tets", "min dih", "max dih", "min r/R",
              "mean r/R", "slivers", "on bound.", "inverted");
  for(const Row* row : {&plain, &exude, &odt, &fixed, &sliding, &after_exude}) print(*row);
}

} // namespace

int main(int argc, char** argv)
{
  const int repeats = argc > 1 ? std::max(1, std::stoi(argv[1])) : 3;
  std::vector<std::string> files;
  for(int i = 2; i < argc; ++i) files.push_back(argv[i]);
  if(files.empty()) files.push_back(DISTORTION_OPTIMIZATION_DATA_DIR "/blobby.off");
  try {
    for(const std::string& file : files) {
      Surface surface;
      if(!CGAL::IO::read_polygon_mesh(file, surface) || num_faces(surface) == 0) {
        std::fprintf(stderr, "Error: cannot read a triangle mesh from %s\n", file.c_str());
        return 1;
      }
      bench_surface(file, surface, repeats);
    }
    if(argc <= 2) bench_surface("cube", cube(1), repeats);
  } catch(const DO::Invalid_input& e) {
    std::fprintf(stderr, "Error: %s\n", e.what());
    return 1;
  }
  return 0;
}
