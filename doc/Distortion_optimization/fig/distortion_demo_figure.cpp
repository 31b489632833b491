// Writes distortion_demo.svg, the package picture: the noisy map of the demo
// (examples/Distortion_optimization/distortion_demo.cpp, same grid, seed and noise), each triangle
// colored by its quasi-conformal dilatation K, as returned through the named parameter
// cell_distortion_map of CGAL::compute_distortion().
// Not part of the build. To regenerate, from the repository root:
//   g++ -std=c++17 -Iinclude -I/usr/include/eigen3 -o /tmp/figure
//       doc/Distortion_optimization/fig/distortion_demo_figure.cpp -lgmp -lmpfr
//   /tmp/figure > doc/Distortion_optimization/fig/distortion_demo.svg

#include <CGAL/compute_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_2>;

int main()
{
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

  auto per_face = mesh.add_property_map<Mesh::Face_index, double>("f:K", 0.).first;
  const DO::Distortion_statistics s = CGAL::compute_distortion(
    mesh, noisy, DO::Conformal_dilatation(), DO::parameters::cell_distortion_map(per_face));

  const double size = 360, margin = 10, legend = 40;
  std::printf("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" viewBox=\"0 0 %g %g\">\n",
              size + 2 * margin, size + 2 * margin + legend, size + 2 * margin, size + 2 * margin + legend);
  std::printf("<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
  auto color = [&](double d) {  // log scale: white at K = 1, dark red at the largest K of the map
    const double t = std::clamp(std::log(d) / std::log(s.max), 0., 1.);
    return std::array<int, 3>{int(255 - 75 * t), int(255 - 225 * t), int(255 - 225 * t)};
  };
  for(auto f : mesh.faces()) {
    std::printf("<polygon points=\"");
    for(auto vd : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      std::printf("%.2f,%.2f ", margin + size * noisy[vd].x(), margin + size * (1 - noisy[vd].y()));
    const auto c = color(per_face[f]);
    std::printf("\" fill=\"rgb(%d,%d,%d)\" stroke=\"#555\" stroke-width=\"0.4\"/>\n", c[0], c[1], c[2]);
  }
  const double y = size + 2 * margin + 8;
  std::printf("<defs><linearGradient id=\"k\"><stop offset=\"0\" stop-color=\"rgb(255,255,255)\"/>"
              "<stop offset=\"1\" stop-color=\"rgb(180,30,30)\"/></linearGradient></defs>\n");
  std::printf("<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"10\" fill=\"url(#k)\" stroke=\"#555\"/>\n",
              margin + 60, y, size - 120);
  std::printf("<text x=\"%g\" y=\"%g\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"end\">K = 1</text>\n",
              margin + 55, y + 10);
  std::printf("<text x=\"%g\" y=\"%g\" font-family=\"sans-serif\" font-size=\"12\">%.1f</text>\n",
              margin + size - 55, y + 10, s.max);
  std::printf("<text x=\"%g\" y=\"%g\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\">"
              "log scale; volume-weighted mean K %.3f</text>\n",
              margin + size / 2, y + 28, s.mean_volume);
  std::printf("</svg>\n");
  return 0;
}
