// The paper's Fig. 11 (section 4.3): an optimized parametrization of a coarse disk, subdivided,
// against optimizing the fine mesh directly.
//
// For each disk: the Tutte parametrization optimized for the symmetric Dirichlet energy with the
// border fixed (threshold 1e-5); then, for 1 to `levels` levels, the source and the optimized map
// subdivided together by Loop's scheme (subdivide_map(), LOOP) and, on the same refined source,
// a Tutte start optimized directly with the same settings. Printed: triangles, the energy of the
// Loop-refined map and its time (optimizing the coarse map plus subdividing), the energy reached
// directly and its time. Linear subdivision would keep the coarse energy exactly (Appendix D).
//
//   build/benchmark/Distortion_optimization/bench_subdivision [levels, default 2 [disk.off ...]]
//   (default disks: lion-head.off and mannequin-devil.off of libcgal-demo)

#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/subdivide_map.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace DOP = CGAL::Distortion_optimization::parameters;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using UV = Mesh::Property_map<Mesh::Vertex_index, K::Point_2>;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Tutte, then the symmetric Dirichlet energy minimized with the border fixed; returns the seconds.
double parametrize(Mesh& mesh, UV uv)
{
  const auto start = std::chrono::steady_clock::now();
  DO::initial_parameterization(mesh, uv);
  CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
                            DOP::convergence_threshold(1e-5, CGAL::parameters::number_of_iterations(500)));
  return seconds_since(start);
}

double energy(const Mesh& mesh, UV uv) { return CGAL::compute_distortion(mesh, uv, DO::Symmetric_dirichlet()).mean_volume; }

} // namespace

int main(int argc, char** argv)
{
  const unsigned levels = argc > 1 ? static_cast<unsigned>(std::stoi(argv[1])) : 2;
  std::vector<std::string> files;
  for(int i = 2; i < argc; ++i) files.push_back(argv[i]);
  if(files.empty())
    files = {DISTORTION_OPTIMIZATION_DATA_DIR "/lion-head.off", DISTORTION_OPTIMIZATION_DATA_DIR "/mannequin-devil.off"};
  try {
    for(const std::string& file : files) {
      Mesh coarse;
      if(!CGAL::IO::read_polygon_mesh(file, coarse) || num_faces(coarse) == 0) {
        std::fprintf(stderr, "Error: cannot read a triangle mesh from %s\n", file.c_str());
        return 1;
      }
      UV uv = coarse.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
      const double coarse_seconds = parametrize(coarse, uv);
      std::printf("\n%s: symmetric Dirichlet, border fixed; Loop = coarse optimization + subdivision\n", file.c_str());
      std::printf("%6s %10s %12s %10s %12s %10s\n", "level", "triangles", "E Loop", "s Loop", "E direct", "s direct");
      std::printf("%6d %10zu %12.6f %10.3f %12s %10s\n", 0, std::size_t(coarse.number_of_faces()), energy(coarse, uv),
                  coarse_seconds, "-", "-");
      for(unsigned level = 1; level <= levels; ++level) {
        Mesh refined = coarse;
        UV refined_uv = refined.property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
        const auto start = std::chrono::steady_clock::now();
        DO::subdivide_map(refined, refined_uv,
                          DO::parameters::subdivision_scheme(DO::Subdivision_scheme::LOOP).number_of_iterations(level));
        const double loop_seconds = coarse_seconds + seconds_since(start);
        const double loop_energy = energy(refined, refined_uv);
        // The same refined source, optimized from its own Tutte start.
        const double direct_seconds = parametrize(refined, refined_uv);
        std::printf("%6u %10zu %12.6f %10.3f %12.6f %10.3f\n", level, std::size_t(refined.number_of_faces()), loop_energy,
                    loop_seconds, energy(refined, refined_uv), direct_seconds);
        std::fflush(stdout);
      }
    }
  } catch(const DO::Invalid_input& e) {
    std::fprintf(stderr, "Error: %s\n", e.what());
    return 1;
  }
  return 0;
}
