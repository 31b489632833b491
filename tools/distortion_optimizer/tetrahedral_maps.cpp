// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tetrahedral maps: a .mesh source with a target, the volume mode's start maps (the unit ball
// or x|x|, untangled), or the mesh's own ideal tetrahedra (--reference ideal), optimized with the
// boundary fixed, free or sliding, and written with the carried surface (--carry).

#include "volume_mode.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/vertex_list.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/mesh_quality.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Bbox_3.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <unordered_set>
#include <vector>

namespace distortion_optimizer {

namespace {

// The size of the tetrahedra's vertices (a point in none has no say): the exponent e for which
// their box's largest half extent is in [2^(e-1), 2^e), as the library scales complexes (1 for no
// extent; the exponent of a subnormal extent is taken as -1023's).
int size_exponent_of_cells(const DO::IO::Tetrahedron_soup& soup)
{
  CGAL::Bbox_3 box;
  for(const auto& t : soup.cells)
    for(std::size_t v : t) box += CGAL::Bbox_3(soup.points[v][0], soup.points[v][1], soup.points[v][2],
                                              soup.points[v][0], soup.points[v][1], soup.points[v][2]);
  double half_extent = 0;   // an extent may overflow (from -2^1023 to 2^1023)
  for(int k = 0; k < 3; ++k) half_extent = std::max(half_extent, box.max_coord(k) / 2 - box.min_coord(k) / 2);
  return half_extent > 0 && std::isfinite(half_extent) ? 1 + std::max(std::ilogb(half_extent), -1023) : 1;
}

} // namespace

int run_tetrahedra(const Command_line& c)
{
  double mesh_seconds = 0;
  // With threads, the target is read while the source is (a source's error is still the first told).
  std::future<DO::IO::Tetrahedron_soup> target_read;
  if(!c.target.empty())
    target_read = std::async(c.threads > 1 ? std::launch::async : std::launch::deferred,
                             [&] { return DO::IO::read_tetrahedron_soup(c.target); });
  const DO::IO::Tetrahedron_soup source = read_or_mesh_source(c, mesh_seconds);
  DO::IO::Tetrahedron_soup target = target_read.valid() ? target_read.get() : source;
  if(!c.target.empty()) check_same_cells(c.target, source.points, source.cells, target.points, target.cells, "tetrahedron");
  C3t3 c3t3;
  std::vector<Tr::Vertex_handle> handles;
  try {
    handles = DO::c3t3_from_tetrahedra(c3t3, source.points, source.cells, DO::parameters::number_of_threads(static_cast<int>(c.threads)));
  } catch(const DO::Invalid_input& e) {
    // The source's tetrahedra are the complex's: they must be valid, even where the map is
    // untangled (--untangle repairs the target; with --reference ideal the target is S itself).
    throw DO::Invalid_input((tetrahedral_file(c.source) ? c.source + ": " : std::string()) + e.what() +
                            (c.ideal() ? " (--reference ideal takes a valid mesh: --untangle repairs a map's target, not the "
                                         "source)" : ""));
  }
  std::unordered_map<Tr::Vertex_handle, K::Point_3> storage;
  std::unordered_map<Tr::Vertex_handle, std::size_t> index;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Tr::Vertex_handle()) {
      storage[handles[i]] = K::Point_3(target.points[i][0], target.points[i][1], target.points[i][2]);
      index[handles[i]] = i;
    }
  boost::associative_property_map<decltype(storage)> target_map(storage);
  std::unique_ptr<Carried_surface> carried;
  if(!c.carry.empty()) carried = std::make_unique<Carried_surface>(c, c3t3);

  // Volume mode: the start map, the tool's own, untangled if the map flattens cells (a ball map
  // does across the sharp edges of the domain).
  Command_line run = c;
  if(c.volume_mode()) {
    // The start is the tool's own, of about unit size (the radial map's, the square of a unit
    // source's): a source too far from unit size for the measures is refused as such, before
    // the radial map squares its size out of double precision.
    const int size = size_exponent_of_cells(source);
    if(std::abs(size - 1) > DO::largest_size_ratio_exponent<3>)
      throw DO::Invalid_input("the source's size (about 2^" + std::to_string(size) + ") and the unit size of the start (--start " +
                              c.start + ") differ by more than 2^" + std::to_string(DO::largest_size_ratio_exponent<3>) +
                              ": distortions cannot be evaluated in double precision; scale the source");
    const K::Point_3 center = c.center.empty() ? DO::volume_centroid(c3t3) : K::Point_3(c.center[0], c.center[1], c.center[2]);
    // The messages in the tool's words: its options rather than the library's functions.
    try {
      if(c.start == "ball") {
        DO::star_shaped_to_unit_ball(c3t3, target_map, DO::parameters::center(center));
      } else {
        DO::radial_map(c3t3, target_map, DO::parameters::center(center));
      }
    } catch(const DO::Center_outside_domain&) {
      throw DO::Invalid_input(c.center.empty() ? "the centroid of the volume is outside it (a volume in several parts, or one "
                                                 "curved around its centroid): give a --center inside"
                                               : "--center is not inside the volume");
    } catch(const DO::Domain_not_star_shaped&) {
      throw DO::Invalid_input("the volume is not star-shaped about the centre (a boundary facet faces it): give another "
                              "--center, or take --start radial with --boundary slide");
    }
    run.untangle = true;
  }
  const DO::Any_measure measure = measure_of(c);
  const std::string measure_name = measure.name();
  if(carried) carried->start_energy = carried->energy(measure, target_map);

  std::vector<unsigned char> listed;
  if(c.fix != "boundary" && c.fix != "none") listed = DO::IO::read_vertex_list(c.fix, source.points.size());
  auto fixed = boost::make_function_property_map<Tr::Vertex_handle>([&](Tr::Vertex_handle v) {
    return listed.empty() ? false : listed[index.at(v)] != 0;
  });
  const std::vector<double> weight_values = c.vertex_weights.empty() ? std::vector<double>(source.points.size(), 1.)
                                                                     : DO::IO::read_vertex_weights(c.vertex_weights, source.points.size());
  auto weights = boost::make_function_property_map<Tr::Vertex_handle>([&](Tr::Vertex_handle v) { return weight_values[index.at(v)]; });

  const DO::Mesh_quality before = c.ideal() ? DO::mesh_quality(c3t3, target_map) : DO::Mesh_quality();
  const DO::Result r = [&] {
    // optimize(np) under the command line's boundary: fixed, free, or sliding on the complex's own
    // boundary (the last two guarded), with the vertices `held` constrained.
    const auto constrained = [&](const auto& optimize, const auto& held) {
      if(c.slides()) {
        const auto surface = DO::Triangle_surface::from_complex_boundary(c3t3, target_map);
        return with_boundary_guard(c, false, [&](bool guard) {
          return optimize(DO::parameters::sliding_boundary(
            surface, DO::parameters::preserve_global_injectivity(guard, common_parameters(run, weights)).vertex_is_constrained_map(held)));
        });
      }
      return with_boundary_guard(c, false, [&](bool guard) {
        return c.fix == "boundary"
          ? optimize(common_parameters(run, weights))
          : optimize(DO::parameters::preserve_global_injectivity(guard, common_parameters(run, weights)).vertex_is_constrained_map(held));
      });
    };
    if(c.ideal()) {
      const auto improve = [&](const auto& np) { return DO::improve_mesh_quality(c3t3, target_map, measure, np); };
      if(!c.slides()) return constrained(improve, fixed);
      // Sliding on the mesh's own boundary, the vertices on its sharp edges fixed.
      const auto sharp = DO::sharp_boundary_vertices(c3t3, target_map);
      return constrained(improve, boost::make_function_property_map<Tr::Vertex_handle>(
                                    [&](Tr::Vertex_handle v) { return sharp.count(v) > 0 || get(fixed, v); }));
    }
    const auto minimize = [&](const auto& np) { return CGAL::minimize_distortion(c3t3, target_map, measure, np); };
    if(c.slides() && c.start == "ball")
      return minimize(
        DO::parameters::sliding_boundary(DO::Sphere_surface(), common_parameters(run, weights).vertex_is_constrained_map(fixed)));
    try {
      return constrained(minimize, fixed);
    } catch(const DO::Unmovable_inverted_cell& e) {
      // The tool's own start inverts cells that its fixed boundary keeps inverted (a radial map
      // of a non-convex volume): the remedy is the sliding boundary.
      if(!c.volume_mode() || c.slides()) throw;
      throw DO::Invalid_input(std::string(e.what()) + " (--boundary slide lets the boundary vertices move)");
    }
  }();
  check_untangled(r);
  DO::IO::Tetrahedron_soup output = source;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Tr::Vertex_handle()) {
      const K::Point_3& p = storage.at(handles[i]);
      output.points[i] = {p.x(), p.y(), p.z()};
    } else {
      output.points[i] = target.points[i];
    }
  // The cell of the complex of each source cell, and a per-cell value of the complex in the
  // source's order.
  std::vector<Tr::Cell_handle> cell_of;
  if(extension(c.output) == "vtu" || !c.svg.empty())
    for(const auto& t : source.cells) {
      Tr::Cell_handle cell;
      int i0, i1, i2, i3;
      c3t3.triangulation().is_cell(handles[t[0]], handles[t[1]], handles[t[2]], handles[t[3]], cell, i0, i1, i2, i3);
      cell_of.push_back(cell);
    }
  const auto in_source_order = [&](const auto& per_cell) {
    std::vector<std::decay_t<decltype(per_cell.begin()->second)>> ordered;
    for(Tr::Cell_handle cell : cell_of) ordered.push_back(per_cell.at(cell));
    return ordered;
  };
  std::vector<double> values;   // each source cell's distortion, for pictures
  std::vector<bool> inverted;   // whether the map inverts or flattens each cell
  if(extension(c.output) == "vtu" || (!c.svg.empty() && !c.ideal())) {
    std::unordered_map<Tr::Cell_handle, double> per_cell;
    std::unordered_map<Tr::Cell_handle, bool> inverted_cell;
    CGAL::compute_distortion(c3t3, target_map, measure,
                             DO::parameters::cell_distortion_map(boost::make_assoc_property_map(per_cell),
                               DO::parameters::inverted_cell_map(boost::make_assoc_property_map(inverted_cell))));
    values = in_source_order(per_cell);
    inverted = in_source_order(inverted_cell);
  }
  // With --reference ideal, the pictures show each cell's radius ratio at `positions`.
  const auto radius_ratios = [&](const auto& positions) {
    std::unordered_map<Tr::Cell_handle, double> ratio;
    DO::mesh_quality(c3t3, positions, DO::parameters::cell_radius_ratio_map(boost::make_assoc_property_map(ratio)));
    return in_source_order(ratio);
  };
  if(extension(c.output) == "vtu") {
    std::vector<std::array<double, 3>> displacement;
    for(std::size_t i = 0; i < output.points.size(); ++i)
      displacement.push_back({output.points[i][0] - source.points[i][0], output.points[i][1] - source.points[i][1],
                              output.points[i][2] - source.points[i][2]});
    DO::IO::write_VTU(c.output, output.points, output.cells, {{measure_name, values}}, {{"displacement", displacement}});
  } else {
    DO::IO::write_MEDIT_soup(c.output, output);
  }
  if(!c.mesh_output.empty()) DO::IO::write_MEDIT_soup(c.mesh_output, source);
  if(c.svg.empty())
    write_pictures(c, {}, {}, measure_name, measure_name, r);
  else if(c.ideal())   // the quality of the mesh before and after
    write_pictures(c, DO::IO::cross_section_panel("before, section z = middle", source.points, source.cells,
                                                  radius_ratios(boost::make_function_property_map<Tr::Vertex_handle>(
                                                    [&](Tr::Vertex_handle v) {
                                                      const auto& p = source.points[index.at(v)];
                                                      return K::Point_3(p[0], p[1], p[2]);
                                                    }))),
                   DO::IO::cross_section_panel("after, section z = middle", output.points, output.cells,
                                               radius_ratios(target_map)), "radius ratio", measure_name, r);
  else {
    const std::vector<double> shown = red_where_inverted(values, inverted);
    write_pictures(c, DO::IO::cross_section_panel("source, section z = middle", source.points, source.cells, shown),
                   DO::IO::cross_section_panel("map, section z = middle", output.points, output.cells, shown),
                   measure_name, measure_name, r);
  }
  Fields fields;
  if(c.ideal()) fields = quality_fields(before, DO::mesh_quality(c3t3, target_map));
  if(c.volume_mode() || carried) {
    std::unordered_set<Tr::Vertex_handle> boundary;
    for(auto t = c3t3.cells_in_complex_begin(); t != c3t3.cells_in_complex_end(); ++t)
      for(int i = 0; i < 4; ++i)
        if(!c3t3.is_in_complex(t->neighbor(i)))
          for(int j = 1; j < 4; ++j) boundary.insert(t->vertex((i + j) % 4));
    fields = {{"tets", std::to_string(source.cells.size())}, {"boundary_vertices", std::to_string(boundary.size())},
              {"mesh_seconds", json_number(mesh_seconds)}};
  }
  if(carried) {
    carried->final_energy = carried->energy(measure, target_map);
    carried->write(c.carry_output, target_map);
    fields.insert(fields.end(), {{"carried_vertices", std::to_string(carried->vertices())},
                                 {"carried_outside", std::to_string(carried->vertices_outside())},
                                 {"start_energy_carried", json_number(carried->start_energy)},
                                 {"final_energy_carried", json_number(carried->final_energy)}});
  }
  report(c, source.cells.size(), source.points.size(), measure_name, r, fields);
  return 0;
}

} // namespace distortion_optimizer
