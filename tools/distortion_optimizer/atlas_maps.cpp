// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The atlas path: a surface source with a closed piece or a handle (or with holes or in pieces,
// when no map per vertex is asked for; run_triangles decides), without --target, is cut into
// charts, flattened and packed by compute_atlas(), and written as an OBJ with one UV per corner.

#include "tool.h"

#include <CGAL/Distortion_optimization/IO/svg.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/IO/vertex_list.h>
#include <CGAL/Distortion_optimization/atlas.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace distortion_optimizer {

std::string option_of_one_map(const Command_line& c)
{
  if(c.fix != "boundary" && c.fix != "none") return "--fix FILE";
  if(c.fix_given && c.fix == "boundary") return "--fix boundary (an atlas's borders are free)";
  if(c.subdivide > 0) return "--subdivide";
  if(!c.vertex_weights.empty()) return "--vertex-weights";
  if(!c.flat_output.empty()) return "--flat-output";
  if(c.untangle) return "--untangle (the charts' starts are never tangled)";
  if(c.svg_both) return "--svg-both (the atlas is drawn alone)";
  return "";
}

int run_atlas(const Command_line& c, const DO::IO::Triangle_soup& source, Mesh& mesh)
{
  const std::string why = c.seams.empty() ? printable(c.source) + " has a closed piece or a handle, so its map to the plane is an atlas with seams"
                                          : "with --seams the map is an atlas";
  if(extension(c.output) != "obj")
    throw DO::Invalid_input(why + ", whose UVs are per corner: give an .obj output (--output X.obj)");
  if(const std::string option = option_of_one_map(c); !option.empty())
    throw DO::Invalid_input(why + ": " + option + " does not apply to it");

  auto seam = mesh.add_property_map<Mesh::Edge_index, bool>("e:atlas_seam", false).first;
  if(!c.seams.empty()) {
    std::ifstream in(c.seams, std::ios::binary);
    if(!in) throw DO::Invalid_input(printable(c.seams) + ": cannot open the file of seams");
    const auto is_edge = [&](std::size_t u, std::size_t w) { return mesh.halfedge(Vertex(u), Vertex(w)) != Mesh::null_halfedge(); };
    for(const auto& [u, w] : DO::IO::read_vertex_pairs(in, mesh.number_of_vertices(), is_edge, c.seams))
      seam[mesh.edge(mesh.halfedge(Vertex(u), Vertex(w)))] = true;
  }
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:atlas_uv").first;
  auto value = mesh.add_property_map<Mesh::Face_index, double>("f:atlas_distortion").first;
  const DO::Any_measure measure = measure_of(c);
  // The library's messages name faces and vertices by their index in the source: say which file.
  const auto in_source = [&](auto&& run) {
    try {
      return run();
    } catch(const DO::Invalid_input& e) {
      throw DO::Invalid_input(printable(c.source) + ": " + e.what());
    }
  };
  // The optimizer's options as for any map (--schedule, --threshold, --solver, ...); every vertex
  // weighs 1 (--vertex-weights is refused above).
  auto weights = mesh.add_property_map<Vertex, double>("v:atlas_weight", 1.).first;
  const DO::Atlas_result a = in_source([&] {
    return DO::compute_atlas(mesh, uv, measure,
                             DO::parameters::cell_distortion_map(value, DO::parameters::edge_is_seam_map(seam,
                               DO::parameters::max_distortion(c.max_distortion, common_parameters(c, weights)))));
  });

  // The surface as read, with one vt per distinct UV of a vertex (a vertex on a seam has several).
  DO::IO::Triangle_soup textured;
  textured.points = source.points;
  textured.cells = source.cells;
  std::map<std::tuple<std::size_t, double, double>, std::size_t> vt;
  for(auto f : mesh.faces()) {
    std::array<std::size_t, 3> t{};
    for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const std::size_t v = std::size_t(mesh.target(h));
      const auto key = std::make_tuple(v, uv[h].x(), uv[h].y());
      auto [at, added] = vt.emplace(key, textured.texture_coordinates.size());
      if(added) textured.texture_coordinates.push_back({uv[h].x(), uv[h].y()});
      for(int i = 0; i < 3; ++i)
        if(source.cells[std::size_t(f)][i] == v) t[i] = at->second;
    }
    textured.cell_texture_indices.push_back(t);
  }
  DO::IO::write_triangle_soup(c.output, textured);

  DO::Result r;
  r.initial_energy = r.harmonic_start_energy = std::numeric_limits<double>::quiet_NaN();
  r.final_energy = a.mean_distortion;
  r.iterations = a.iterations;
  r.seconds = a.seconds;
  r.inverted_cells = a.inverted_faces;
  r.stopped_by_visitor = a.stopped_by_visitor;
  // The pictures: each face's UV triangle (its corners apart, as the seams have them).
  DO::IO::Svg_panel map;
  if(!c.svg.empty()) {
    std::vector<std::array<double, 3>> corners;
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<double> values;
    for(auto f : mesh.faces()) {
      std::array<std::size_t, 3> t{};
      int i = 0;
      for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
        t[i++] = corners.size();
        corners.push_back({uv[h].x(), uv[h].y(), 0.});
      }
      triangles.push_back(t);
      values.push_back(value[f]);
    }
    map = DO::IO::triangle_panel("atlas", corners, triangles, values);
  }
  write_pictures(c, {}, std::move(map), measure.name(), measure.name(), r);
  report(c, mesh.number_of_faces(), mesh.number_of_vertices(), measure.name(), r,
         {{"charts", std::to_string(a.charts)},
          {"cones", std::to_string(a.cones)},
          {"seam_length_fraction", json_number(a.seam_length_fraction)},
          {"packing_efficiency", json_number(a.packing_efficiency)},
          {"overlapping_charts", std::to_string(a.overlapping_charts)},
          {"max_cell_distortion", json_number(a.max_distortion)}});
  return 0;
}

} // namespace distortion_optimizer
