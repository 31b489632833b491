// The demo: a planar disk-like grid whose interior is mapped with noise (boundary fixed);
// prints the distortion of that map and of the identity for every measure of the package.

#include <CGAL/compute_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <random>

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
  auto identity = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:identity").first;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> noise(-0.3 / k, 0.3 / k);
  for(auto vd : mesh.vertices()) {
    const K::Point_2 p = mesh.point(vd);
    identity[vd] = p;
    noisy[vd] = mesh.is_border(vd) ? p : K::Point_2(p.x() + noise(rng), p.y() + noise(rng));
  }

  std::printf("%zu vertices, %zu triangles; volume-weighted mean distortion:\n",
              std::size_t(mesh.number_of_vertices()), std::size_t(mesh.number_of_faces()));
  std::printf("%-22s %14s %14s %10s\n", "measure", "noisy map", "identity", "inverted");
  auto row = [&](const auto& measure) {
    const auto before = CGAL::compute_distortion(mesh, noisy, measure);
    const auto after = CGAL::compute_distortion(mesh, identity, measure);
    std::printf("%-22s %14.6f %14.6f %10zu\n", measure.name().c_str(), before.mean_volume, after.mean_volume,
                before.inverted_cells);
  };
  row(DO::Conformal_dilatation());
  row(DO::Condition_number());
  row(DO::MIPS());
  row(DO::Isometric_dilatation());
  row(DO::ARAP());
  row(DO::Symmetric_dirichlet());
  row(DO::Volume_distortion());
  row(DO::Dirichlet());
  row(DO::Product<DO::Conformal_dilatation, DO::Isometric_dilatation>());
  return 0;
}
