// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of distortion_optimizer: its options, and a parser that checks everything that
// can be checked before any file is read (options, numbers, the measure's name, which files are
// inputs and outputs). Apart from the rest of the tool so that a fuzz target can drive the parser.

#ifndef DISTORTION_OPTIMIZER_COMMAND_LINE_H
#define DISTORTION_OPTIMIZER_COMMAND_LINE_H

#include <CGAL/Distortion_optimization/Any_measure.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace distortion_optimizer {

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// The first of the registry's measures (measure_by_name.h).
std::string default_measure_name();

struct Command_line
{
  std::string source, target, output, measure = default_measure_name(), fix = "boundary", solver = "gd", report,
    schedule;   // empty: the library's default
  std::size_t iterations = 100, threads = 1;
  double threshold = 1e-4;
  bool untangle = false;
  bool quiet = false, verbose = false;       // progress lines: neither given = when stderr is a terminal
  double time_limit = 0;                     // 0: none
  double max_distortion = 0;                 // an atlas's bound (0: none)
  std::string seams;                         // an atlas's seams (vertex pairs), if given
  // Volume mode (--start): the start map, where the meshed source and the carried surface go.
  std::string start, mesh_output, boundary, carry, carry_output;
  double cell_size = 0;                      // 0: mesh_interior's default
  std::vector<double> center;                // empty: the centroid of the volume
  bool snap = false;
  bool fix_given = false;
  std::string reference;                     // "ideal": improve the source mesh itself
  std::size_t subdivide = 0;                 // levels of subdivision of the result (triangle maps)
  std::string scheme, subdivided_source;
  std::string flat_output;                   // a triangle map's result as (u, v, 0), beside --output
  std::string svg, energy_plot;              // pictures
  std::string vertex_weights;                // a file of one weight per vertex
  std::string cell_weighting = "average", order = "sorted", parallel_sweep = "sets", harmonic_start;
  std::string global_step;                   // empty: the library's default for the dimension
  bool svg_both = false;                     // the source beside the map in --svg
  bool volume_mode() const { return !start.empty(); }
  bool ideal() const { return reference == "ideal"; }
  // The ball start slides by default, unless --fix none or FILE frees the boundary.
  bool slides() const
  {
    return boundary == "slide" || (boundary.empty() && start == "ball" && !(fix_given && fix != "boundary"));
  }
};

// The usage text (--help).
std::string usage();

// The command line, checked; throws Usage_error (exit status 2), whose empty message asks for
// the usage (--help).
Command_line parse(int argc, char** argv);

// A tetrahedral mesh: Medit (.mesh) or TetGen (.ele and .node beside it).
bool tetrahedral_file(const std::string& path);

// The lower-case extension of a file name, as the library's readers and writers take it.
std::string extension(const std::string& path);

// A file name as messages show it (control bytes and invalid UTF-8 escaped), as the library's do.
std::string printable(const std::string& text);

// A number in a message, as printf's %g writes it (as the library's messages show numbers).
std::string shown_number(double value);

// The measure the command line names (checked by parse()).
CGAL::Distortion_optimization::Any_measure measure_of(const Command_line& c);

} // namespace distortion_optimizer

#endif // DISTORTION_OPTIMIZER_COMMAND_LINE_H
