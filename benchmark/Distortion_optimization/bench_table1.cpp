// The paper's Table 1: conformal optimization of the radial map f0(x) = x|x| of the cube [-1,1]^3
// (boundary fixed, K, threshold 1e-4) at about 0.8K, 6K, 50K, 400K and 1M tetrahedra (TetGen),
// with the default schedule (local sweeps alternated with global steps, harmonic start) and the
// paper's local-only schedule (Algorithms 1-2), on one thread and on two (the paper's Algorithm 3
// with k = 2 parts, and the parallel sweep over independent sets). Then a map with large volume
// changes, the exponential stretch (x, y, z) -> (exp(2x), y, z) of the ~50K cube (det J from 0.27
// to 15), for K, MIPS and symmetric Dirichlet under the three schedules, one thread. Last, the
// radial map of the ~6K and ~50K cubes with nothing fixed, K and C, Laplacian against Newton steps.
//
//   build/benchmark/Distortion_optimization/bench_table1 [largest number of tets, default 1000000]

#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/tetrahedralize_with_tetgen.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <type_traits>
#include <unordered_map>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tr = CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<K>>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Storage = std::unordered_map<Tr::Vertex_handle, K::Point_3>;
using Target = boost::associative_property_map<Storage>;

namespace {

// Resident memory of the process (field "VmRSS:") or its peak since the last reset ("VmHWM:"),
// in bytes (Linux); writing 5 to /proc/self/clear_refs resets the peak to the current size.
double memory(const char* field)
{
  std::ifstream status("/proc/self/status");
  for(std::string line; std::getline(status, line);)
    if(line.rfind(field, 0) == 0) return std::stod(line.substr(std::string(field).size())) * 1024;
  return 0;
}
void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }

void cube(double max_volume, std::vector<std::array<double, 3>>& points, std::vector<std::array<std::size_t, 4>>& tets)
{
  using Surface = CGAL::Surface_mesh<K::Point_3>;
  Surface cube;
  for(int i = 0; i < 8; ++i) cube.add_vertex(K::Point_3(i & 1 ? 1. : -1., i & 2 ? 1. : -1., i & 4 ? 1. : -1.));
  const std::vector<std::array<std::size_t, 3>> faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                         {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for(const auto& f : faces) cube.add_face(Surface::Vertex_index(f[0]), Surface::Vertex_index(f[1]), Surface::Vertex_index(f[2]));
  DO::IO::Tetrahedron_soup soup = DO::tetrahedralize_with_tetgen(cube, DO::parameters::maximum_cell_volume(max_volume));
  points = std::move(soup.points);
  tets = std::move(soup.cells);
}

// A cube of about `count` tetrahedra: TetGen's count for a volume bound is roughly proportional to
// 1/bound, so one correction.
void cube_of_about(double count, std::vector<std::array<double, 3>>& points, std::vector<std::array<std::size_t, 4>>& tets)
{
  const double bound = 8. / count * 1.5;
  cube(bound, points, tets);
  cube(bound * tets.size() / count, points, tets);
}

K::Point_3 stretch(const K::Point_3& p) { return K::Point_3(std::exp(2 * p.x()), p.y(), p.z()); }

K::Point_3 radial(const K::Point_3& p)
{
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
  return K::Point_3(r * p.x(), r * p.y(), r * p.z());
}

} // namespace

int main(int argc, char** argv)
{
  const double largest = argc > 1 ? std::stod(argv[1]) : 1000000;
  const double sizes[] = {800, 6000, 50000, 400000, 1000000};
  const double paper[] = {0.2, 11.2, 107, -1, -1};
  // "seconds": the median of five runs up to 50K tets, one run above.
  // "B/tet": the optimizer's peak memory beyond what the mesh and the maps already use.
  // "peak MB": the whole process's peak resident memory during the run (mesh, C3T3, maps, optimizer).
  // "sweep": the parallel sweep with 2 threads, "parts" (Algorithm 3) or "sets" (independent sets).
  std::printf("%8s %-12s %7s %5s %9s %6s %10s %10s %10s %10s %9s %9s %8s %8s\n", "tets", "schedule", "threads", "sweep",
              "seconds", "iters", "K before", "K after", "cond bef.", "cond aft.", "inverted", "paper s", "B/tet", "peak MB");
  struct Run { DO::Schedule schedule; int threads; DO::Parallel_sweep sweep; };
  const auto sets = DO::Parallel_sweep::INDEPENDENT_SETS, parts = DO::Parallel_sweep::PARTITION;
  const Run runs[] = {{DO::Schedule::ALTERNATING, 1, sets}, {DO::Schedule::ALTERNATING, 2, sets},
                      {DO::Schedule::ALTERNATING, 2, parts}, {DO::Schedule::GLOBAL, 1, sets},
                      {DO::Schedule::GLOBAL, 2, sets}, {DO::Schedule::LOCAL, 1, sets},
                      {DO::Schedule::LOCAL, 2, sets}, {DO::Schedule::LOCAL, 2, parts}};
  for(int s = 0; s < 5 && sizes[s] <= largest; ++s) {
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::size_t, 4>> tets;
    cube_of_about(sizes[s], points, tets);

    // This machine's speed drifts by tens of percent from one second to the next: up to 50K
    // tets every configuration runs five times, interleaved, and the median time is reported
    // (the runs are deterministic, so everything else is the same in each).
    const int repeats = sizes[s] <= 60000 ? 5 : 1;
    struct Row { DO::Result r; CGAL::Distortion_optimization::Distortion_statistics k, condition_before, condition; double bytes = 0, peak = 0; std::vector<double> seconds; };
    std::vector<Row> rows(std::size(runs));
    for(int repeat = 0; repeat < repeats; ++repeat)
      for(std::size_t i = 0; i < std::size(runs); ++i) {
        const Run& run = runs[i];
        if(run.schedule != DO::Schedule::ALTERNATING && sizes[s] > 60000) continue;   // minutes: see the 50K rows
        if(sizes[s] > 500000 && run.sweep == parts) continue;
        C3t3 c3t3;
        DO::c3t3_from_tetrahedra(c3t3, points, tets);
        Storage storage;
        DO::map_vertices(c3t3, Target(storage), radial);
        Row& row = rows[i];
        row.condition_before = CGAL::compute_distortion(c3t3, Target(storage), DO::Condition_number());
        reset_peak_memory();
        const double before = memory("VmRSS:");
        row.r = CGAL::minimize_distortion(c3t3, Target(storage), DO::Conformal_dilatation(),
          DO::parameters::number_of_threads(run.threads, DO::parameters::parallel_sweep(run.sweep, DO::parameters::schedule(run.schedule)))
            .number_of_iterations(1000));
        row.bytes = std::max(row.bytes, memory("VmHWM:") - before);
        row.peak = std::max(row.peak, memory("VmHWM:"));
        row.seconds.push_back(row.r.seconds);
        row.k = CGAL::compute_distortion(c3t3, Target(storage), DO::Conformal_dilatation());
        row.condition = CGAL::compute_distortion(c3t3, Target(storage), DO::Condition_number());
      }
    for(std::size_t i = 0; i < std::size(runs); ++i) {
      const Run& run = runs[i];
      Row& row = rows[i];
      if(row.seconds.empty()) continue;
      std::sort(row.seconds.begin(), row.seconds.end());
      std::printf("%8zu %-12s %7d %5s %9.3f %6zu %10.5f %10.5f %10.5f %10.5f %9zu %9s %8.0f %8.0f\n", tets.size(),
                  run.schedule == DO::Schedule::LOCAL ? "local" : run.schedule == DO::Schedule::GLOBAL ? "global" : "alternating",
                  run.threads, run.threads == 1 ? "-" : run.sweep == parts ? "parts" : "sets", row.seconds[row.seconds.size() / 2],
                  row.r.iterations, row.r.initial_energy, row.k.mean_volume, row.condition_before.mean_volume,
                  row.condition.mean_volume, row.k.inverted_cells,
                  paper[s] > 0 ? std::to_string(paper[s]).substr(0, 5).c_str() : "-", row.bytes / tets.size(), row.peak / 1e6);
      std::fflush(stdout);
    }
  }
  // A long run on the ~50K mesh: the reference the threshold-1e-4 runs are compared with.
  if(largest >= 50000) {
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::size_t, 4>> tets;
    cube_of_about(50000, points, tets);
    C3t3 c3t3;
    DO::c3t3_from_tetrahedra(c3t3, points, tets);
    Storage storage;
    DO::map_vertices(c3t3, Target(storage), radial);
    const DO::Result r = CGAL::minimize_distortion(c3t3, Target(storage), DO::Conformal_dilatation(),
                                                   DO::parameters::convergence_threshold(1e-7).number_of_iterations(300));
    std::printf("reference: %zu tets, threshold 1e-7: K %.6f after %zu iterations, %.1f s\n", tets.size(),
                r.final_energy, r.iterations, r.seconds);

    std::printf("\nexponential stretch, %zu tets, boundary fixed, threshold 1e-4\n%-20s %-12s %-10s %9s %6s %12s %12s %9s\n",
                tets.size(), "measure", "schedule", "global", "seconds", "iters", "before", "after", "inverted");
    auto run = [&](const auto& measure) {
      // The global solvers differ only for a measure with a Hessian (the others use the Laplacian).
      const bool has_hessian = DO::measures_internal::Has_hessian<std::decay_t<decltype(measure)>, 3>::value;
      for(auto schedule : {DO::Schedule::ALTERNATING, DO::Schedule::GLOBAL, DO::Schedule::LOCAL})
        for(auto solver : {DO::Global_solver::REWEIGHTED_LAPLACIAN, DO::Global_solver::PROJECTED_NEWTON}) {
          if(solver == DO::Global_solver::PROJECTED_NEWTON && (!has_hessian || schedule == DO::Schedule::LOCAL)) continue;
          Storage start;
          DO::map_vertices(c3t3, Target(start), stretch);
          const DO::Result q = CGAL::minimize_distortion(c3t3, Target(start), measure,
            DO::parameters::schedule(schedule, DO::parameters::global_solver(solver)).number_of_iterations(1000));
          std::printf("%-20s %-12s %-10s %9.3f %6zu %12.6f %12.6f %9zu\n", measure.name().c_str(),
                      schedule == DO::Schedule::LOCAL ? "local" : schedule == DO::Schedule::GLOBAL ? "global" : "alternating",
                      schedule == DO::Schedule::LOCAL ? "-" : solver == DO::Global_solver::PROJECTED_NEWTON ? "Newton" : "Laplacian",
                      q.seconds, q.iterations, q.initial_energy, q.final_energy, q.inverted_cells);
          std::fflush(stdout);
        }
    };
    run(DO::Conformal_dilatation());
    run(DO::MIPS());
    run(DO::Symmetric_dirichlet());
  }
  // Nothing fixed: K and C are minimal (1) at the similarities and rigid motions, where their kinks
  // make the Laplacian's steps crawl; Newton steps take those of a smooth model (MIPS, symmetric
  // Dirichlet). Default schedule and threshold, one thread, median of three interleaved runs.
  std::printf("\nradial map, nothing fixed, threshold 1e-4, one thread\n%8s %-12s %-10s %9s %6s %12s %14s %9s\n", "tets",
              "measure", "global", "seconds", "iters", "before", "after", "inverted");
  for(double count : {6000., 50000.}) {
    if(count > largest) break;
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::size_t, 4>> tets;
    cube_of_about(count, points, tets);
    C3t3 c3t3;
    DO::c3t3_from_tetrahedra(c3t3, points, tets);
    const auto nothing_fixed = boost::make_function_property_map<Tr::Vertex_handle>([](Tr::Vertex_handle) { return false; });
    auto run = [&](const auto& measure) {
      const DO::Global_solver solvers[] = {DO::Global_solver::REWEIGHTED_LAPLACIAN, DO::Global_solver::PROJECTED_NEWTON};
      DO::Result results[2];
      std::vector<double> seconds[2];
      for(int repeat = 0; repeat < 3; ++repeat)
        for(int k = 0; k < 2; ++k) {
          Storage start;
          DO::map_vertices(c3t3, Target(start), radial);
          results[k] = CGAL::minimize_distortion(c3t3, Target(start), measure,
                                                 DO::parameters::global_solver(solvers[k]).vertex_is_constrained_map(nothing_fixed));
          seconds[k].push_back(results[k].seconds);
        }
      for(int k = 0; k < 2; ++k) {
        std::sort(seconds[k].begin(), seconds[k].end());
        std::printf("%8zu %-12s %-10s %9.3f %6zu %12.6f %14.10f %9zu\n", tets.size(), measure.name().c_str(),
                    k == 0 ? "Laplacian" : "Newton", seconds[k][1], results[k].iterations, results[k].initial_energy,
                    results[k].final_energy, results[k].inverted_cells);
        std::fflush(stdout);
      }
    };
    run(DO::Conformal_dilatation());
    run(DO::Isometric_dilatation());
  }
  return 0;
}
