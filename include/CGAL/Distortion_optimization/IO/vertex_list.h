// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A strict reader of vertex lists (one 0-based index per line), the format of the command-line
// tool's --fix file: bounded lines, every line read, messages that name the file and line.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_VERTEX_LIST_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_VERTEX_LIST_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>

#include <fstream>
#include <istream>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// Reads a list of vertex indices of a mesh with `count` vertices: one 0-based index per line,
/// `#` starting a comment, blank lines skipped, a UTF-8 byte order mark skipped. Returns one flag
/// per vertex, 1 for the listed ones. `name` is used in error messages.
/// \throws Invalid_input naming the line for a line longer than 1 MiB, a token that is not an
/// integer, two tokens on a line, or an index out of range.
inline std::vector<unsigned char> read_vertex_list(std::istream& in, std::size_t count, const std::string& name = "vertex list")
{
  internal::Line_reader reader(in, name);
  std::vector<unsigned char> listed(count, 0);
  std::vector<std::string> t;
  while(reader.next(t)) {
    const long long index = reader.integer(t[0]);
    if(t.size() > 1) reader.fail("one vertex index per line");
    if(index < 0 || static_cast<unsigned long long>(index) >= count)
      reader.fail("vertex index " + std::to_string(index) + " out of range (the mesh has " + std::to_string(count) +
                  " vertices)");
    listed[static_cast<std::size_t>(index)] = 1;
  }
  return listed;
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads the vertex list in the file `path` (see the stream overload).
/// \throws Invalid_input if the file cannot be opened, and as the stream overload.
inline std::vector<unsigned char> read_vertex_list(const std::string& path, std::size_t count)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Invalid_input(internal::printable(path) + ": cannot open the file of vertex indices");
  return read_vertex_list(in, count, path);
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_VERTEX_LIST_H
