// A texture atlas of a surface that is not a disk.
//
// CGAL's parameterizers take one topological disk at a time, along seams the user gives
// (Seam_mesh). CGAL::Distortion_optimization::compute_atlas() takes any triangle surface (closed,
// with holes or handles, in pieces): it cuts it into charts, flattens each with the measure
// minimized (no triangle inverted, no chart overlapping itself) and packs them into the unit
// square. The surface is not modified: the UVs are written per halfedge, as through a Seam_mesh.
//
//   texture_atlas [surface.off [atlas.obj [max_distortion]]]
//
// writes the surface with its atlas (OBJ: v in the surface's order, one vt per UV corner, f v/vt;
// default: elephant.off, a closed surface, to elephant_atlas.obj). With max_distortion, a piece
// whose mean symmetric Dirichlet energy stays above it is cut into more charts.

#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/atlas.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : DISTORTION_OPTIMIZATION_DATA_DIR "/elephant.off";
  const std::string output = argc > 2 ? argv[2] : "elephant_atlas.obj";
  const double bound = argc > 3 ? std::atof(argv[3]) : 0.;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << path << ": not a triangle mesh\n";
    return EXIT_FAILURE;
  }
  // The UV of target(h) in face(h), for every halfedge h of a face; each face's chart.
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  auto chart = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:chart").first;
  DO::Atlas_result atlas;
  try {
    atlas = DO::compute_atlas(mesh, uv, DO::Symmetric_dirichlet(),
                              DO::parameters::face_chart_map(chart, DO::parameters::max_distortion(bound)));
  } catch(const DO::Invalid_input& e) {   // not manifold, a degenerate face, a bad parameter
    std::cerr << path << ": " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  // The OBJ: the surface's vertices, then each face's three UV corners.
  DO::IO::Triangle_soup soup;
  for(auto v : mesh.vertices()) soup.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
  for(auto f : mesh.faces()) {
    std::array<std::size_t, 3> cell, corner;
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      cell[i] = std::size_t(mesh.target(h));
      corner[i++] = soup.texture_coordinates.size();
      soup.texture_coordinates.push_back({uv[h].x(), uv[h].y()});
    }
    soup.cells.push_back(cell);
    soup.cell_texture_indices.push_back(corner);
  }
  DO::IO::write_triangle_soup(output, soup);

  std::printf("%s: %zu faces in %zu charts (%zu cones), seams %.2f%% of the edge length, packing %.3f; "
              "symmetric Dirichlet mean %.4f, max %.3f; %zu inverted, %zu overlapping; %.2f s; wrote %s\n",
              path.c_str(), std::size_t(mesh.number_of_faces()), atlas.charts, atlas.cones, 100 * atlas.seam_length_fraction,
              atlas.packing_efficiency, atlas.mean_distortion, atlas.max_distortion, atlas.inverted_faces,
              atlas.overlapping_charts, atlas.seconds, output.c_str());
  std::size_t last_chart = 0;
  for(auto f : mesh.faces()) last_chart = std::max(last_chart, chart[f]);
  if(atlas.inverted_faces > 0 || atlas.overlapping_charts > 0 || last_chart + 1 != atlas.charts) {
    std::cerr << "Error: an inverted face, an overlapping chart, or charts miscounted\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
