// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// distortion_optimizer: the command-line tool of the package; `--help` and the manual's section
// "The Command-Line Tool" give its usage. This file stages the outputs (all written or none) and
// decides the exit status: 0 on success, 1 for bad input (one-line message), 2 for a bad command
// line. The command line is read in command_line.cpp, triangle maps run in triangle_maps.cpp,
// tetrahedral maps in tetrahedral_maps.cpp (with the volume mode's meshing and carried surface in
// volume_mode.cpp), and the report and pictures are written by outputs.cpp.

#include "solver_runtime.h"
#include "staged_output.h"
#include "tool.h"

#include <CGAL/exceptions.h>

#include <future>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace distortion_optimizer {

namespace {

// TBB starts its threads inside the run, where a failure cannot be caught (the program aborts):
// they are started once here, all alive at once, so that a process or memory limit that cannot
// give them is a message.
void check_threads(std::size_t n)
{
  std::promise<void> go;
  const std::shared_future<void> started = go.get_future().share();
  std::vector<std::thread> threads;
  bool failed = false;
  try {
    while(threads.size() + 1 < n) threads.emplace_back([started] { started.wait(); });
  } catch(const std::system_error&) {
    failed = true;
  }
  go.set_value();
  for(std::thread& t : threads) t.join();
  if(failed)
    throw DO::Invalid_input("--threads " + std::to_string(n) + ": cannot start that many threads here (only " +
                            std::to_string(threads.size() + 1) + " under this machine's limits): give fewer");
}

// All outputs or none: each output gets a temporary name beside it before any input is read (so a
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
  check_threads(c.threads);
  set_up_sparse_solvers();
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
  // Devices and pipes first: writing into them may fail (/dev/full), renaming a file hardly can;
  // the renames are the commit, which no signal interrupts.
  for(std::size_t i = 0; i < outputs.size(); ++i)
    if(files[i] && files[i]->is_streamed()) files[i]->rename_to(c.*outputs[i]);
  commit_uninterrupted([&] {
    for(std::size_t i = 0; i < outputs.size(); ++i)
      if(files[i] && !files[i]->is_streamed()) files[i]->rename_to(c.*outputs[i]);
  });
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
  } catch(const CGAL::Failure_exception& e) {
    // CGAL's own message spans lines (file, line, explanation): its first line and where.
    const std::string text = e.message().empty() ? e.expression() : e.message();
    std::cerr << "distortion_optimizer: CGAL failed a check of its own (" << text.substr(0, text.find('\n')) << ", "
              << e.filename().substr(e.filename().find_last_of('/') + 1) << ":" << e.line_number() << "); nothing written\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "distortion_optimizer: " << e.what() << "\n";
    return 1;
  }
}
