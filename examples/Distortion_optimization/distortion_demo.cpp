// All the measures on one map: a planar grid whose interior is mapped with noise (the border is fixed); for every
// measure of the package, minimizes the distortion from that start and prints before / after.

#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_2>;

int main()
{
  // A 20 x 20 grid of the unit square, two triangles per square.
  const int k = 20;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) v.push_back(mesh.add_vertex(K::Point_2(double(i) / k, double(j) / k)));
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      const auto a = v[j * (k + 1) + i], b = v[j * (k + 1) + i + 1], c = v[(j + 1) * (k + 1) + i],
                 d = v[(j + 1) * (k + 1) + i + 1];
      mesh.add_face(a, b, d);
      mesh.add_face(a, d, c);
    }

  auto noisy = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:noisy").first;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> noise(-0.3 / k, 0.3 / k);
  for(auto vd : mesh.vertices()) {
    const K::Point_2 p = mesh.point(vd);
    noisy[vd] = mesh.is_border(vd) ? p : K::Point_2(p.x() + noise(rng), p.y() + noise(rng));
  }

  std::printf("%zu vertices, %zu triangles, border fixed; volume-weighted mean distortion:\n",
              std::size_t(mesh.number_of_vertices()), std::size_t(mesh.number_of_faces()));
  std::printf("%-22s %12s %12s %8s %9s %9s\n", "measure", "before", "after", "sweeps", "seconds", "inverted");
  auto target = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:target").first;
  bool ok = true;
  auto row = [&](const auto& measure) {
    for(auto vd : mesh.vertices()) target[vd] = noisy[vd];
    const DO::Result r = CGAL::minimize_distortion(mesh, target, measure);
    // An independent check of what the optimizer reports: evaluate the returned map again.
    const auto after = CGAL::compute_distortion(mesh, target, measure);
    std::printf("%-22s %12.6f %12.6f %8zu %9.4f %9zu\n", measure.name().c_str(), r.initial_energy,
                after.mean_volume, r.iterations, r.seconds, after.inverted_cells);
    ok = ok && after.inverted_cells == 0 && after.mean_volume < r.initial_energy;
  };
  // Each measure by its name, held by an Any_measure: the optimizer is compiled once for all.
  std::vector<std::string> names = DO::measure_names();
  names.push_back("conformal*isometric");
  for(const std::string& name : names) row(DO::measure_from_name(name));
  if(!ok) {
    std::cerr << "Error: a map has inverted triangles, or a measure did not decrease" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
