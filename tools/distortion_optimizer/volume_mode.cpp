// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The volume mode's Mesh_3 meshing of a closed surface (volume_mode.h).

#include "volume_mode.h"

#include "staged_output.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/mesh_interior.h>

#include <algorithm>
#include <chrono>
#include <utility>

namespace distortion_optimizer {

DO::IO::Tetrahedron_soup read_or_mesh_source(const Command_line& c, double& mesh_seconds)
{
  if(tetrahedral_file(c.source)) return DO::IO::read_tetrahedron_soup(c.source);
  const auto begin = std::chrono::steady_clock::now();
  const Mesh surface = to_mesh(DO::IO::read_triangle_soup(c.source), c.source);
  DO::IO::Tetrahedron_soup soup;
  try {
    namespace P = DO::parameters;
    const auto limit = P::meshing_time_limit(c.time_limit);   // 0: none
    // Mesh_3 stops at the limit where it checks it; past that, a moment later, the tool does.
    const Hard_deadline deadline(c.time_limit > 0 ? c.time_limit + (std::max)(2., 0.1 * c.time_limit) : 0.,
                                 c.source + ": mesh_interior: Mesh_3 did not finish within the time limit of " +
                                   shown_number(c.time_limit) + " s (larger sizes ask for fewer tetrahedra)");
    DO::tetrahedra_from_c3t3(c.cell_size > 0 ? DO::mesh_interior(surface, P::cell_size(c.cell_size, limit))
                                             : DO::mesh_interior(surface, limit), soup.points, soup.cells);
    soup.labels.assign(soup.cells.size(), 1);
  } catch(const DO::Invalid_input& e) {
    // The library's remedies name its parameters; the tool's user has --cell-size (the facet size,
    // and ten times the facet distance).
    std::string what = e.what();
    const std::string facet_size = "; give a facet size below ";
    if(const auto at = what.find(facet_size); at != std::string::npos)   // the number stays
      what.replace(at, facet_size.size(), "; give a --cell-size below ");
    for(const auto& [library, tool] : {std::pair<std::string, std::string>("; give larger sizes", "; give a larger --cell-size"),
                                       {"; give sizes below their distance", "; give a --cell-size below 10 times their distance"},
                                       {"; try a larger sharp_edge_angle",   // (a smaller --cell-size would ask for more vertices)
                                        "; the tool has neither option: mesh it with the library's mesh_interior() and a larger "
                                        "sharp_edge_angle (180 protects no edge) or maximum_number_of_vertices, then give the .mesh"},
                                       {"; give smaller sizes", "; give a smaller --cell-size"}})
      if(const auto remedy = what.find(library); remedy != std::string::npos) what = what.substr(0, remedy) + tool;
    throw DO::Invalid_input(c.source + ": " + what);
  }
  mesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return soup;
}

} // namespace distortion_optimizer
