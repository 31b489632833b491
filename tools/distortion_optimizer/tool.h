// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tool's modes share (triangle_maps.cpp, tetrahedral_maps.cpp, volume_mode.cpp): the
// surface mesh type, the options every run takes, the progress visitor, the boundary guard's
// fallback, and the report and pictures (outputs.cpp).

#ifndef DISTORTION_OPTIMIZER_TOOL_H
#define DISTORTION_OPTIMIZER_TOOL_H

#include "command_line.h"

#include <CGAL/Distortion_optimization/Any_measure.h>
#include <CGAL/Distortion_optimization/IO/simplex_soup.h>
#include <CGAL/Distortion_optimization/IO/svg.h>
#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace CGAL {
namespace Distortion_optimization {
struct Mesh_quality;
} // namespace Distortion_optimization
} // namespace CGAL

namespace distortion_optimizer {

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Vertex = Mesh::Vertex_index;

// The report's extra fields: name and JSON value.
using Fields = std::vector<std::pair<std::string, std::string>>;

// The two kinds of run (triangle_maps.cpp, tetrahedral_maps.cpp): each reads its inputs, runs,
// writes the outputs named in `c` and prints the report. Throw Invalid_input for bad input.
int run_triangles(const Command_line& c);
int run_tetrahedra(const Command_line& c);
// The first option given that only a map per vertex has (--fix FILE, --subdivide, ...), as the
// atlas's refusal names it; empty if none: run_triangles then gives an atlas to a surface with holes
// or in pieces.
std::string option_of_one_map(const Command_line& c);
// The atlas of a surface source that has no one map to the plane, or whose map per vertex is not
// asked for (atlas_maps.cpp), called by run_triangles.
int run_atlas(const Command_line& c, const DO::IO::Triangle_soup& source, Mesh& mesh);

// The source as a Surface_mesh, vertex i and face f in file order; rejects what a surface mesh
// cannot represent (non-manifold edges or vertices, inconsistent orientation, unused vertices).
Mesh to_mesh(const DO::IO::Triangle_soup& soup, const std::string& name);   // (triangle_maps.cpp)

// A target must list the source's vertices (as many) and cells (the same, in the same order).
template <class Points, class Cells>
void check_same_cells(const std::string& name, const Points& source_points, const Cells& source_cells,
                      const Points& target_points, const Cells& target_cells, const std::string& cell)
{
  if(target_points.size() != source_points.size() || target_cells.size() != source_cells.size())
    throw DO::Invalid_input(name + ": " + std::to_string(target_points.size()) + " vertices and " +
                            std::to_string(target_cells.size()) + " cells, the source has " +
                            std::to_string(source_points.size()) + " and " + std::to_string(source_cells.size()));
  for(std::size_t k = 0; k < source_cells.size(); ++k)
    if(target_cells[k] != source_cells[k])
      throw DO::Invalid_input(name + ": " + cell + " " + std::to_string(k) + " differs from the source's (same connectivity needed)");
}

// Free-boundary mode (some border vertex free), and boundary vertices sliding on a triangle surface
// (the source's own boundary, where a vertex projected onto the closest point of another part of
// it would cross it): the run keeps the boundary
// from crossing itself (global injectivity). A start whose boundary already crosses itself cannot
// be guarded: then the run goes on without the guard, with a warning. (Sliding on the unit sphere
// does not come here: a map of the sphere onto itself without folds is one-to-one.)
// `free_borders`: some border is free although --fix is boundary (the holes of a disk with holes).
template <class Run>
DO::Result with_boundary_guard(const Command_line& c, bool free_borders, const Run& run)
{
  if(c.fix == "boundary" && !c.slides() && !free_borders) return run(false);
  try {
    return run(true);
  } catch(const DO::Crossing_start_boundary& guarded) {
    DO::Result r = run(false);   // throws again if the input was bad for another reason
    std::cerr << "distortion_optimizer: warning: " << guarded.what() << "; optimized without the guard\n";
    return r;
  }
}

// The visitor of every optimization: a progress line per iteration on stderr (--verbose, or
// stderr a terminal without --quiet) and the stop at --time-limit. Copies share one clock, which
// starts with the first copy's run.
class Progress
{
public:
  explicit Progress(const Command_line& c)
    : show_(c.verbose || (!c.quiet && ::isatty(STDERR_FILENO))), limit_(c.time_limit), state_(std::make_shared<State>()) {}

  // The untangling's rounds (with --untangle) come first, their energy the barrier's; the
  // optimization's iterations then start again from 1, under a line that says so.
  bool operator()(std::size_t iteration, double energy, std::size_t inverted) const;

private:
  struct State
  {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::size_t iteration = 0;
    double energy = 0;
  };
  bool show_;
  double limit_;
  std::shared_ptr<State> state_;
};

// The options both kinds of mesh share, with the vertex weights (a map of the mesh's vertices).
template <class Weights>
auto common_parameters(const Command_line& c, const Weights& weights)
{
  namespace P = DO::parameters;
  const auto solver = c.solver == "bfgs" ? DO::Local_solver::BFGS : DO::Local_solver::GRADIENT_DESCENT;
  // Without --schedule, the library's default (minimize_distortion()'s schedule parameter).
  const std::optional<DO::Schedule> schedule =
    c.schedule.empty() ? std::nullopt
    : std::optional<DO::Schedule>(c.schedule == "local" ? DO::Schedule::LOCAL
                                  : c.schedule == "global" ? DO::Schedule::GLOBAL : DO::Schedule::ALTERNATING);
  const auto weighting = c.cell_weighting == "volume" ? DO::Cell_weighting::VOLUME
                       : c.cell_weighting == "uniform" ? DO::Cell_weighting::UNIFORM : DO::Cell_weighting::AVERAGE_VOLUME;
  const auto order = c.order == "greedy" ? DO::Vertex_order::GREEDY : DO::Vertex_order::SORTED_PER_SWEEP;
  const auto sweep = c.parallel_sweep == "partition" ? DO::Parallel_sweep::PARTITION : DO::Parallel_sweep::INDEPENDENT_SETS;
  const bool harmonic = c.harmonic_start.empty() ? schedule != DO::Schedule::LOCAL : c.harmonic_start == "on";
  // Without --global-step, the library's default for the mesh's dimension.
  const std::optional<DO::Global_solver> solver_of_global_step =
    c.global_step.empty() ? std::nullopt
    : std::optional<DO::Global_solver>(c.global_step == "newton" ? DO::Global_solver::PROJECTED_NEWTON
                                                                 : DO::Global_solver::REWEIGHTED_LAPLACIAN);
  return P::number_of_threads(static_cast<int>(std::min<std::size_t>(c.threads, 256)),
    P::schedule(schedule, P::local_solver(solver, P::untangle_first(c.untangle, P::convergence_threshold(c.threshold,
      P::cell_weighting(weighting, P::vertex_order(order, P::parallel_sweep(sweep, P::use_harmonic_start(harmonic,
        P::global_solver(solver_of_global_step, P::vertex_weight_map(weights)))))))))))
    .number_of_iterations(c.iterations).visitor(Progress(c));
}

// The report's number: 17 significant digits, or null where not finite.
std::string json_number(double x);

// Prints the results and writes them to --report as JSON.
void report(const Command_line& c, std::size_t cells, std::size_t vertices, const std::string& measure_name,
            const DO::Result& r, const Fields& fields = {});

// A run that --time-limit stopped during the untangling has no valid map to write.
void check_untangled(const DO::Result& r);

// Each cell's value for a picture: an infinite one (drawn red) where the map inverts or flattens
// the cell, also under a measure finite there (ARAP, Dirichlet).
std::vector<double> red_where_inverted(std::vector<double> values, const std::vector<bool>& inverted);

// --svg (the map's cells coloured by `value_name`, beside the source's with --svg-both) and
// --energy-plot (the start's energy, then each iteration's).
void write_pictures(const Command_line& c, DO::IO::Svg_panel source, DO::IO::Svg_panel map, const std::string& value_name,
                    const std::string& measure_name, const DO::Result& r);

// --reference ideal: the report's quality fields (angles are dihedral angles for tetrahedra).
Fields quality_fields(const DO::Mesh_quality& before, const DO::Mesh_quality& after);

} // namespace distortion_optimizer

#endif // DISTORTION_OPTIMIZER_TOOL_H
