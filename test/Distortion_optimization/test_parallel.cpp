// Parallel sweeps (independent sets, and the paper's Algorithm 3) and parallel global steps on a
// real parametrization: same energy as one thread, no flips, deterministic output.

#include "test_meshes.h"

#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace test_meshes;

namespace {

struct Disk
{
  Mesh3 mesh;
  Mesh3::Property_map<Mesh3::Vertex_index, Point_2> uv;
  std::vector<Point_2> tutte;

  explicit Disk(const std::string& name)
  {
    const std::string path = std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/" + name;
    if(!CGAL::IO::read_polygon_mesh(path, mesh)) throw std::runtime_error("missing " + path);
    uv = mesh.add_property_map<Mesh3::Vertex_index, Point_2>("v:uv").first;
    DO::initial_parameterization(mesh, uv);
    for(auto v : mesh.vertices()) tutte.push_back(uv[v]);
  }

  // Runs from the Tutte start; returns the result and leaves the map in uv.
  template <class NamedParameters>
  DO::Result run(const NamedParameters& np)
  {
    for(auto v : mesh.vertices()) uv[v] = tutte[v.idx()];
    return CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(), np);
  }

  std::vector<Point_2> map() const { return targets_of(mesh, uv); }
};

} // namespace

TEST(Parallel, SweepsReachTheSequentialEnergyWithoutFlips)
{
  // Converged runs (local sweeps alone need thousands on a Tutte start: the small disk).
  Disk disk("nefertiti.off");
  for(auto schedule : {DO::Schedule::LOCAL, DO::Schedule::ALTERNATING}) {
    auto np = [&](int threads, DO::Parallel_sweep method) {
      return DO::parameters::number_of_threads(threads, DO::parameters::parallel_sweep(method,
             DO::parameters::schedule(schedule, DO::parameters::convergence_threshold(1e-6)))).number_of_iterations(20000);
    };
    const auto sequential = disk.run(np(1, DO::Parallel_sweep::INDEPENDENT_SETS));
    ASSERT_TRUE(sequential.converged);
    ASSERT_EQ(count_flipped(disk.mesh, disk.uv), 0u);
    for(auto method : {DO::Parallel_sweep::INDEPENDENT_SETS, DO::Parallel_sweep::PARTITION})
      for(int threads : {0, 2, 3}) {   // 0: all the hardware offers
        const auto r = disk.run(np(threads, method));
        const std::string label = "threads " + std::to_string(threads) + " method " + std::to_string(int(method)) +
                                  " schedule " + std::to_string(int(schedule));
        EXPECT_TRUE(r.converged) << label;
        EXPECT_NEAR(r.final_energy, sequential.final_energy, 1e-3 * sequential.final_energy) << label;
        EXPECT_EQ(r.inverted_cells, 0u) << label;
        EXPECT_EQ(count_flipped(disk.mesh, disk.uv), 0u) << label;
        EXPECT_NEAR(r.final_energy, brute_force_energy(disk.mesh, disk.uv, "symmetric_dirichlet"), 1e-9 * r.final_energy)
          << label;
      }
  }
}

TEST(Parallel, OutputIsDeterministic)
{
  Disk disk("mushroom.off");
  auto np = [](int threads, DO::Parallel_sweep method) {
    return DO::parameters::number_of_threads(threads, DO::parameters::parallel_sweep(method)).number_of_iterations(15);
  };
  for(auto method : {DO::Parallel_sweep::INDEPENDENT_SETS, DO::Parallel_sweep::PARTITION}) {
    const auto first = disk.run(np(2, method));
    const auto x = disk.map();
    const auto second = disk.run(np(2, method));
    EXPECT_EQ(first.final_energy, second.final_energy);
    EXPECT_EQ(first.energy_per_iteration, second.energy_per_iteration);
    EXPECT_TRUE(x == disk.map()) << "two runs with 2 threads differ";
  }
  // Independent sets: the output does not even depend on the number of threads.
  const auto two = disk.run(np(2, DO::Parallel_sweep::INDEPENDENT_SETS));
  const auto x = disk.map();
  const auto four = disk.run(np(4, DO::Parallel_sweep::INDEPENDENT_SETS));
  EXPECT_EQ(two.energy_per_iteration, four.energy_per_iteration);
  EXPECT_TRUE(x == disk.map()) << "2 and 4 threads differ";
}

TEST(Parallel, NegativeThreadCountIsRejected)
{
  Disk disk("nefertiti.off");
  EXPECT_THROW(disk.run(DO::parameters::number_of_threads(-1)), DO::Invalid_input);
}
