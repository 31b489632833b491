// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// distortion_optimizer: the command-line tool of the package (README.md, the manual's "Command-Line
// Tool"). This file: the outputs staged all or none, and the exit status; the modes are in
// triangle_maps.cpp and tetrahedral_maps.cpp, the command line in command_line.cpp.
//
//   distortion_optimizer --source S --target T --output O [--measure NAME] [--fix boundary|none|FILE]
//                        [--iterations N] [--threshold EPS] [--solver gd|bfgs] [--threads N] [--report R.json]
//                        [--schedule alternating|local|global] [--untangle] [--quiet|--verbose]
//                        [--time-limit SECONDS]
//   distortion_optimizer --source CLOSED --start ball|radial --output O.mesh [--mesh-output M.mesh]
//                        [--cell-size H] [--center X,Y,Z] [--boundary slide|fixed]
//                        [--carry INNER --carry-output C [--snap]] [options above]
//
// S, T, O: OFF or OBJ triangle meshes, or Medit .mesh tetrahedral meshes, with the same vertices
// and cells in the same order; a planar target has z = 0. Without --target, a disk-topology
// triangle source gets a Tutte start (circle border). O may also be .vtu: the optimized map with
// each cell's distortion, for ParaView.
// Volume mode (--start): the inside of a closed surface is meshed with Mesh_3 (or a .mesh source
// is taken as it is), mapped onto the unit ball or by x |x|, untangled where that start flattens
// cells, and optimized with the boundary sliding on the start's boundary surface or fixed; a
// surface inside the volume may be carried through the map (paper 4.4).
// Energies are volume-weighted means sum vol(c) D(J_c) / sum vol(c).
// Exit status: 0 on success, 1 for bad input (one-line message), 2 for a bad command line.

#include "staged_output.h"
#include "tool.h"

#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace distortion_optimizer {

namespace {

// All outputs or none: each output gets a temporary file beside it before any input is read (so a
// folder that cannot be written fails first), the run writes there, and the files are renamed
// only when every one was written (after the outputs into devices, whose writes may still fail).
int run(const Command_line& c)
{
  const auto suffix = [](const std::string& path) {
    const std::string e = extension(path);
    return e.empty() ? e : "." + e;
  };
  // The report last: it is renamed only once the map's files are.
  const std::vector<std::string Command_line::*> outputs = {&Command_line::output, &Command_line::mesh_output,
    &Command_line::carry_output, &Command_line::subdivided_source, &Command_line::flat_output, &Command_line::svg, &Command_line::energy_plot,
    &Command_line::report};
  std::vector<std::unique_ptr<Temporary_file>> files(outputs.size());
  Command_line staged = c;
  for(std::size_t i = 0; i < outputs.size(); ++i)
    if(!(c.*outputs[i]).empty()) {
      files[i] = std::make_unique<Temporary_file>(c.*outputs[i], suffix(c.*outputs[i]));
      staged.*outputs[i] = files[i]->path();
    }
  const bool tetrahedra = tetrahedral_file(c.source) || c.volume_mode();
  int status = 0;
  try {
    status = tetrahedra ? run_tetrahedra(staged) : run_triangles(staged);
  } catch(const DO::Invalid_input& e) {
    // A writer names the file it writes: the user's name, not the hidden temporary one.
    std::string message = e.what();
    for(std::size_t i = 0; i < outputs.size(); ++i)
      for(std::size_t at; files[i] && (at = message.find(files[i]->path())) != std::string::npos;)
        message.replace(at, files[i]->path().size(), c.*outputs[i]);
    // The library's word on a source cell: the source file's cell, when the file lists them.
    if((message.rfind("source face ", 0) == 0 || message.rfind("source cell ", 0) == 0) && !c.volume_mode())
      message = printable(c.source) + ": " + message;
    throw DO::Invalid_input(message);
  }
  // Devices and pipes first: writing into them may fail (/dev/full), renaming a file hardly can.
  for(const bool streamed : {true, false})
    for(std::size_t i = 0; i < outputs.size(); ++i)
      if(files[i] && files[i]->is_streamed() == streamed) files[i]->rename_to(c.*outputs[i]);
  return status;
}

} // namespace

} // namespace distortion_optimizer

int main(int argc, char** argv)
{
  using namespace distortion_optimizer;
  remove_temporary_files_on_signals();
  try {
    return run(parse(argc, argv));
  } catch(const Usage_error& e) {
    if(!*e.what()) {   // --help
      std::cout << usage();
      return 0;
    }
    std::cerr << "distortion_optimizer: " << e.what() << " (run with --help for the usage)\n";
    return 2;
  } catch(const std::bad_alloc&) {
    std::cerr << "distortion_optimizer: out of memory (a mesh too large for this machine, or --subdivide with too many "
                 "levels: each multiplies the cells by 4); nothing written\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "distortion_optimizer: " << e.what() << "\n";
    return 1;
  }
}
