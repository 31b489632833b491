// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangle maps: a planar deformation or a surface's parametrization (a target, the Tutte
// start of a disk, or the mesh's own ideal triangles with --reference ideal), optimized, then
// subdivided (--subdivide) and written.

#include "tool.h"

#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/IO/vertex_list.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>
#include <CGAL/Distortion_optimization/global_injectivity.h>
#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/mesh_quality.h>
#include <CGAL/Distortion_optimization/subdivide_map.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

namespace distortion_optimizer {

Mesh to_mesh(const DO::IO::Triangle_soup& soup, const std::string& name)
{
  Mesh mesh;
  for(const auto& p : soup.points) mesh.add_vertex(K::Point_3(p[0], p[1], p[2]));
  for(std::size_t f = 0; f < soup.cells.size(); ++f) {
    const auto& t = soup.cells[f];
    if(mesh.add_face(Vertex(t[0]), Vertex(t[1]), Vertex(t[2])) == Mesh::null_face())
      throw DO::Invalid_input(name + ": face " + std::to_string(f) +
                              " makes the mesh non-manifold or inconsistently oriented");
  }
  for(Vertex v : mesh.vertices())
    if(mesh.is_isolated(v)) throw DO::Invalid_input(name + ": vertex " + std::to_string(std::size_t(v)) + " is in no face");
  std::vector<Mesh::Halfedge_index> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(pinched));
  if(!pinched.empty())
    throw DO::Invalid_input(name + ": vertex " + std::to_string(std::size_t(mesh.target(pinched.front()))) + " is non-manifold");
  return mesh;
}

namespace {

// Whether the tool's Tutte start takes the source: every piece of genus 0 with a border (a disk,
// or a disk with holes; a disk beside a closed torus has the Euler characteristic of two disks,
// hence the borders counted per piece). Returns the number of borders (0 if it does not take it)
// and a halfedge of each piece's longest border in `longest`.
std::size_t borders_of_planar_domain(const Mesh& mesh, std::vector<Mesh::Halfedge_index>& longest)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::size_t> piece(mesh.number_of_faces());
  const std::size_t pieces = PMP::connected_components(mesh, boost::make_iterator_property_map(piece.begin(), get(CGAL::face_index, mesh)));
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  longest.assign(pieces, Mesh::null_halfedge());
  std::vector<double> length(pieces, -1);
  for(Mesh::Halfedge_index h : cycles) {
    const std::size_t k = piece[std::size_t(mesh.face(mesh.opposite(h)))];
    double l = 0;
    for(auto g : CGAL::halfedges_around_face(h, mesh)) l += PMP::edge_length(g, mesh);
    if(l > length[k]) length[k] = l, longest[k] = h;
  }
  const long long euler = static_cast<long long>(mesh.number_of_vertices()) - static_cast<long long>(mesh.number_of_edges()) +
                          static_cast<long long>(mesh.number_of_faces());
  const bool every_piece_has_a_border =
    std::find(longest.begin(), longest.end(), Mesh::null_halfedge()) == longest.end();
  return every_piece_has_a_border && euler == 2 * static_cast<long long>(pieces) - static_cast<long long>(cycles.size())
           ? cycles.size() : 0;
}

// The bytes this process may still take: the smaller of the memory the system has available and
// what the address-space limit leaves (ulimit -v); the largest double if neither is known.
double memory_available()
{
  double available = std::numeric_limits<double>::max();
  std::ifstream meminfo("/proc/meminfo");
  for(std::string key; meminfo >> key;) {
    double kilobytes = 0;
    if(key == "MemAvailable:" && (meminfo >> kilobytes)) available = 1024 * kilobytes;
    meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  rlimit limit;
  if(::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    double used = 0;   // the address space taken so far (the first field of statm, in pages)
    std::ifstream("/proc/self/statm") >> used;
    available = std::min(available, double(limit.rlim_cur) - used * double(::sysconf(_SC_PAGESIZE)));
  }
  return available;
}

// A subdivision whose result cannot fit in memory is refused before the run rather than when
// the memory runs out: a run's peak is about 340 bytes per triangle of the result (the figure
// the manual gives under the tool's limits).
void check_subdivision_fits(const Command_line& c, std::size_t cells)
{
  const double triangles = double(cells) * std::pow(4., double(c.subdivide)), needed = 340 * triangles;
  const double available = memory_available();
  if(needed > available)
    throw DO::Invalid_input("--subdivide " + std::to_string(c.subdivide) + ": about " + shown_number(triangles) +
                            " triangles, about " + shown_number(needed / 1e9) + " GB, more than the " +
                            shown_number(std::max(available, 0.) / 1e9) +
                            " GB this run can still take: give fewer levels");
}

} // namespace

int run_triangles(const Command_line& c)
{
  const DO::IO::Triangle_soup source = DO::IO::read_triangle_soup(c.source);
  if(c.subdivide > 0) check_subdivision_fits(c, source.cells.size());
  Mesh mesh = to_mesh(source, c.source);
  bool planar = true;
  for(const auto& p : source.points) planar = planar && p[2] == 0;

  auto uv = mesh.add_property_map<Vertex, K::Point_2>("v:target").first;
  // Where the tool makes the start: the source's borders, and each piece's longest.
  std::size_t borders = 0;
  std::vector<Mesh::Halfedge_index> outer;
  auto source_2 = mesh.add_property_map<Vertex, K::Point_2>("v:source_2").first;
  for(Vertex v : mesh.vertices()) source_2[v] = K::Point_2(mesh.point(v).x(), mesh.point(v).y());
  if(c.ideal()) {
    if(!planar) throw DO::Invalid_input(c.source + ": --reference ideal needs a planar mesh (z = 0) or a .mesh");
    // As with a .mesh: the mesh improved is the source, which must be valid (not folded, no flat triangle).
    if(const auto count = DO::mesh_quality(mesh, source_2).inverted_cells; count > 0)
      throw DO::Invalid_input(c.source + ": " + std::to_string(count) + " of its triangles are inverted or flat (--reference "
                              "ideal takes a valid mesh: --untangle repairs a map's target, not the source)");
    for(Vertex v : mesh.vertices()) uv[v] = K::Point_2(mesh.point(v).x(), mesh.point(v).y());
  } else if(!c.target.empty()) {
    // The target's positions (z = 0), or its UVs: an OBJ whose faces refer to texture coordinates.
    const DO::IO::Triangle_soup target = DO::IO::read_triangle_soup(c.target);
    check_same_cells(c.target, source.points, source.cells, target.points, target.cells, "face");
    const std::vector<std::array<double, 2>> texture = DO::IO::per_vertex_texture_coordinates(target, c.target);
    // A planar source's target may be its map by its positions (z = 0) as well as by its UVs: the
    // UVs are the map only where the positions are the source's own (a surface with its UVs, as
    // the tool writes one); planar positions elsewhere make it ambiguous.
    if(!texture.empty() && planar && target.points != source.points &&
       std::all_of(target.points.begin(), target.points.end(), [](const std::array<double, 3>& p) { return p[2] == 0; }))
      throw DO::Invalid_input(printable(c.target) + ": both its positions (planar, not the source's) and its UVs "
                              "(f v/vt) could be the map of the planar source: write the map as positions without UVs, or as "
                              "UVs with the source's positions");
    for(std::size_t i = 0; i < target.points.size(); ++i) {
      if(!texture.empty()) {
        uv[Vertex(i)] = K::Point_2(texture[i][0], texture[i][1]);
        continue;
      }
      if(target.points[i][2] != 0)
        throw DO::Invalid_input(c.target + ": vertex " + std::to_string(i) + " has z != 0 (the target must be planar" +
                                (target.texture_coordinates.empty() ? ")"
                                 : "; its vt lines are not UVs of the map: no face refers to them, as in f v/vt)"));
      uv[Vertex(i)] = K::Point_2(target.points[i][0], target.points[i][1]);
    }
  } else {
    borders = borders_of_planar_domain(mesh, outer);
    // A closed piece or a handle, or seams given: no one map to the plane, but an atlas (cut,
    // flattened, packed). A surface with holes or in pieces has one, but gets the atlas too where
    // nothing asks for its one map (an OBJ output, none of the options only a map per vertex has):
    // its charts free of any fixed border and packed into the unit square.
    const bool one_map_asked = extension(c.output) != "obj" || !option_of_one_map(c).empty();
    const bool disk = borders == 1;
    if(borders == 0 || !c.seams.empty() || (!planar && !disk && !one_map_asked)) return run_atlas(c, source, mesh);
    if(c.max_distortion > 0)
      throw DO::Invalid_input(c.source + ": --max-distortion bounds the charts of an atlas, and this source gets none (" +
                              (planar ? "a planar source" : disk ? "a disk" : "its map per vertex is asked for") + ")");
    DO::initial_parameterization(mesh, uv);
    // The tool's own start has the source's orientation: the Tutte map is counter-clockwise, so a
    // planar source listed clockwise gets its mirror image. (A surface is compared in each face's
    // own frame, where any consistent orientation is positive.)
    std::size_t left = 0, right = 0;   // the triangles' orientations (exact: no area underflows far from unit size)
    for(const auto& t : source.cells) {
      const auto &a = source.points[t[0]], &b = source.points[t[1]], &d = source.points[t[2]];
      const CGAL::Orientation o = CGAL::orientation(K::Point_2(a[0], a[1]), K::Point_2(b[0], b[1]), K::Point_2(d[0], d[1]));
      left += o == CGAL::LEFT_TURN;
      right += o == CGAL::RIGHT_TURN;
    }
    // A planar source that folds (triangles of both orientations) inverts some cells of any start.
    if(planar && left > 0 && right > 0 && !c.untangle)
      throw DO::Invalid_input(c.source + ": the planar source folds over itself (" + std::to_string(std::min(left, right)) +
                              " of its triangles are oriented against the others), so the tool's Tutte start inverts "
                              "them: --untangle unfolds it");
    if(planar && right > left)
      for(Vertex v : mesh.vertices()) uv[v] = K::Point_2(uv[v].x(), -uv[v].y());
  }

  auto fixed = mesh.add_property_map<Vertex, bool>("v:fixed", false).first;
  // The Tutte start of a disk with holes maps the holes to star-shaped polygons: their borders are
  // left free to open up, kept from crossing (the guard), and only the outer border is fixed.
  const bool holes = borders > outer.size() && c.fix == "boundary";
  if(holes) {
    for(Mesh::Halfedge_index longest : outer)
      for(auto h : CGAL::halfedges_around_face(longest, mesh)) fixed[mesh.target(h)] = true;
  } else if(c.fix == "boundary") {
    for(Vertex v : mesh.vertices()) fixed[v] = mesh.is_border(v);
  } else if(c.fix != "none") {
    const auto list = DO::IO::read_vertex_list(c.fix, mesh.number_of_vertices());
    for(Vertex v : mesh.vertices()) fixed[v] = list[std::size_t(v)] != 0;
  }

  auto weights = mesh.add_property_map<Vertex, double>("v:weight", 1.).first;
  if(!c.vertex_weights.empty()) {
    const std::vector<double> w = DO::IO::read_vertex_weights(c.vertex_weights, mesh.number_of_vertices());
    for(Vertex v : mesh.vertices()) weights[v] = w[std::size_t(v)];
  }

  std::string measure_name;
  Fields fields;
  const DO::Mesh_quality before = c.ideal() ? DO::mesh_quality(mesh, uv) : DO::Mesh_quality();
  const DO::Any_measure measure = measure_of(c);
  measure_name = measure.name();
  const DO::Result r = with_boundary_guard(c, holes, [&](bool guard) {
    auto np = DO::parameters::preserve_global_injectivity(guard, common_parameters(c, weights)).vertex_is_constrained_map(fixed);
    if(c.ideal()) return DO::improve_mesh_quality(mesh, uv, measure, np);
    // A planar source is compared in its own plane (so its orientation counts), a surface in
    // each triangle's frame.
    return planar ? CGAL::minimize_distortion(mesh, uv, measure, np.vertex_point_map(source_2))
                  : CGAL::minimize_distortion(mesh, uv, measure, np);
  });
  check_untangled(r);
  if(c.ideal()) fields = quality_fields(before, DO::mesh_quality(mesh, uv));
  const std::size_t cells = mesh.number_of_faces(), vertices = mesh.number_of_vertices();

  // The map's distortion, each face's value into per_face, and which faces it inverts or flattens.
  auto per_face = mesh.add_property_map<Mesh::Face_index, double>("f:distortion").first;
  auto inverted_face = mesh.add_property_map<Mesh::Face_index, bool>("f:inverted").first;
  const auto distortion = [&] {
    const auto np = DO::parameters::cell_distortion_map(per_face, DO::parameters::inverted_cell_map(inverted_face));
    return planar ? CGAL::compute_distortion(mesh, uv, measure, np.vertex_point_map(source_2))
                  : CGAL::compute_distortion(mesh, uv, measure, np);
  };
  DO::IO::Triangle_soup output;
  output.cells = source.cells;
  if(c.subdivide > 0) {
    // The source and the optimized map refined together (paper 4.3); the source goes to its own file.
    const bool injective = r.inverted_cells == 0 && DO::is_boundary_embedded(mesh, uv);
    DO::subdivide_map(mesh, uv, DO::parameters::subdivision_scheme(c.scheme == "loop" ? DO::Subdivision_scheme::LOOP
                                                                                      : DO::Subdivision_scheme::LINEAR)
                                  .number_of_iterations(static_cast<unsigned>(c.subdivide)));
    DO::IO::Triangle_soup refined;
    for(Vertex v : mesh.vertices()) {
      source_2[v] = K::Point_2(mesh.point(v).x(), mesh.point(v).y());
      refined.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    }
    for(auto f : mesh.faces()) {
      std::array<std::size_t, 3> t;
      int i = 0;
      for(Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[i++] = std::size_t(v);
      refined.cells.push_back(t);
    }
    output.cells = refined.cells;
    // Loop's smoothing may invert cells of the refined map, and so may linear midpoints rounded on
    // a nearly flat cell (a measure finite on flat cells lets cells get that thin): no output then.
    // (A map inverted already, under such a measure without --untangle, is refined as it is.)
    const DO::Distortion_statistics refined_distortion = distortion();
    if(refined_distortion.inverted_cells > 0 && r.inverted_cells == 0)
      throw DO::Invalid_input("the subdivided map has " + std::to_string(refined_distortion.inverted_cells) +
                              " inverted or flat cells (" +
                              (c.scheme == "loop" ? std::string("Loop's smoothing folds it; --scheme linear keeps the optimized map's cells")
                                                  : "rounded midpoints of nearly flat cells of the optimized map; a measure infinite "
                                                    "on flat cells keeps them away") + "); nothing written");
    // Loop's border rule also moves the border: it may cross itself, or pieces overlap.
    if(injective && refined_distortion.inverted_cells == 0 && !DO::is_boundary_embedded(mesh, uv))
      throw DO::Invalid_input("the subdivided map's border crosses itself or one of its pieces overlaps another (" +
                              (c.scheme == "loop" ? std::string("Loop's smoothing moves the border; --scheme linear keeps the optimized map")
                                                  : "rounded midpoints of borders closer than their rounding") + "); nothing written");
    DO::IO::write_triangle_soup(c.subdivided_source, refined);
    // The refined map's energy under --cell-weighting; its new vertices have no weights of their
    // own, so every vertex weighs 1 here.
    const double refined_energy = c.cell_weighting == "uniform" ? refined_distortion.mean_uniform : refined_distortion.mean_volume;
    fields.insert(fields.end(), {{"subdivided_cells", std::to_string(mesh.number_of_faces())},
                                 {"subdivided_vertices", std::to_string(mesh.number_of_vertices())},
                                 {"subdivided_energy", json_number(refined_energy)},
                                 {"subdivided_inverted_cells", std::to_string(refined_distortion.inverted_cells)}});
  }
  for(Vertex v : mesh.vertices()) output.points.push_back({uv[v].x(), uv[v].y(), 0.});
  std::vector<double> values;   // each face's distortion, evaluated once for the outputs that show it
  std::vector<bool> inverted;   // whether the map inverts or flattens each face
  if(extension(c.output) == "vtu" || (!c.svg.empty() && !c.ideal())) {
    if(c.subdivide == 0) distortion();   // (a subdivided map's values are in per_face already)
    for(auto f : mesh.faces()) {
      values.push_back(per_face[f]);
      inverted.push_back(inverted_face[f]);
    }
  }
  if(!c.flat_output.empty()) DO::IO::write_triangle_soup(c.flat_output, output);
  if(!planar && extension(c.output) == "obj") {
    // A parametrization as texture tools read it: the surface, with one UV per vertex.
    DO::IO::Triangle_soup textured;
    for(Vertex v : mesh.vertices()) {
      textured.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
      textured.texture_coordinates.push_back({uv[v].x(), uv[v].y()});
    }
    textured.cells = textured.cell_texture_indices = output.cells;
    DO::IO::write_triangle_soup(c.output, textured);
  } else if(extension(c.output) == "vtu") {
    std::vector<std::array<double, 3>> displacement;
    for(Vertex v : mesh.vertices())
      displacement.push_back({uv[v].x() - mesh.point(v).x(), uv[v].y() - mesh.point(v).y(), -mesh.point(v).z()});
    DO::IO::write_VTU(c.output, output.points, output.cells, {{measure_name, values}}, {{"displacement", displacement}});
  } else {
    DO::IO::write_triangle_soup(c.output, output);
  }
  if(!c.svg.empty()) {
    // A map's distortion, or with --reference ideal the quality of the mesh before and after.
    std::vector<std::array<double, 3>> points;
    for(Vertex v : mesh.vertices()) points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    if(c.ideal()) {
      // Each face's radius ratio at `positions`, red where the face is inverted.
      auto ratio = mesh.add_property_map<Mesh::Face_index, double>("f:radius_ratio").first;
      auto inverted_at = mesh.add_property_map<Mesh::Face_index, bool>("f:inverted_at").first;
      const auto quality = [&](const auto& positions) {
        DO::mesh_quality(mesh, positions, DO::parameters::cell_radius_ratio_map(ratio, DO::parameters::inverted_cell_map(inverted_at)));
        std::vector<double> shown;
        for(auto f : mesh.faces()) shown.push_back(inverted_at[f] ? std::numeric_limits<double>::infinity() : ratio[f]);
        return shown;
      };
      write_pictures(c, DO::IO::triangle_panel("before", points, output.cells, quality(source_2)),
                     DO::IO::triangle_panel("after", output.points, output.cells, quality(uv)), "radius ratio", measure_name, r);
    } else {
      const std::vector<double> shown = red_where_inverted(values, inverted);
      write_pictures(c, DO::IO::triangle_panel("source", points, output.cells, shown),
                     DO::IO::triangle_panel("map", output.points, output.cells, shown), measure_name, measure_name, r);
    }
  } else {
    write_pictures(c, {}, {}, measure_name, measure_name, r);
  }
  report(c, cells, vertices, measure_name, r, fields);
  return 0;
}

} // namespace distortion_optimizer
