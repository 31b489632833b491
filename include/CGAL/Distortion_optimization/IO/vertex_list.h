// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A strict reader of vertex lists (one 0-based index per line), the format of the command-line
// tool's --fix file: bounded lines, every line read, messages that name the file and line.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_VERTEX_LIST_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_VERTEX_LIST_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>

#include <array>
#include <cstddef>
#include <fstream>
#include <istream>
#include <limits>
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

/// \ingroup PkgDistortionOptimizationIO
/// Reads a list of edges of a mesh with `count` vertices, each as the 0-based indices of its two
/// vertices on one line (the seams of an atlas, `compute_atlas()`), `#` starting a comment, blank
/// lines skipped. `is_edge(i, j)` tells whether vertices i and j are joined by an edge. `name` is
/// used in error messages.
/// \throws Invalid_input naming the line for a token that is not an integer, a line without two
/// indices, an index out of range, or two vertices that no edge joins.
template <class IsEdge>
std::vector<std::array<std::size_t, 2>> read_vertex_pairs(std::istream& in, std::size_t count, const IsEdge& is_edge,
                                                          const std::string& name = "vertex pairs")
{
  internal::Line_reader reader(in, name);
  std::vector<std::array<std::size_t, 2>> pairs;
  std::vector<std::string> t;
  while(reader.next(t)) {
    if(t.size() != 2) reader.fail("two vertex indices per line (an edge)");
    std::array<std::size_t, 2> pair{};
    for(int k = 0; k < 2; ++k) {
      const long long index = reader.integer(t[k]);
      if(index < 0 || static_cast<unsigned long long>(index) >= count)
        reader.fail("vertex index " + std::to_string(index) + " out of range (the mesh has " + std::to_string(count) +
                    " vertices)");
      pair[k] = static_cast<std::size_t>(index);
    }
    if(!is_edge(pair[0], pair[1]))
      reader.fail("vertices " + std::to_string(pair[0]) + " and " + std::to_string(pair[1]) + " are not joined by an edge");
    pairs.push_back(pair);
  }
  return pairs;
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads one weight per vertex of a mesh with `count` vertices (the paper's omega(v) of eq. 23,
/// for the named parameter `vertex_weight_map`): one positive finite number per line, in vertex
/// order, `#` starting a comment, blank lines skipped. `name` is used in error messages.
/// \throws Invalid_input naming the line for a token that is not a number, two tokens on a line,
/// a weight that is not positive and finite, or a number of weights other than `count`.
inline std::vector<double> read_vertex_weights(std::istream& in, std::size_t count, const std::string& name = "vertex weights")
{
  internal::Line_reader reader(in, name);
  std::vector<double> weights;
  std::vector<std::string> t;
  while(reader.next(t)) {
    if(t.size() > 1) reader.fail("one weight per line");
    if(weights.size() == count) reader.fail("more weights than the " + std::to_string(count) + " vertices");
    const double w = reader.coordinate(t[0], "weight", std::numeric_limits<double>::max());
    if(!(w > 0)) reader.fail("weight " + t[0] + " is not positive");
    weights.push_back(w);
  }
  if(weights.size() != count)
    reader.fail(std::to_string(weights.size()) + " weights for " + std::to_string(count) + " vertices");
  return weights;
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads the vertex weights in the file `path` (see the stream overload).
/// \throws Invalid_input if the file cannot be opened, and as the stream overload.
inline std::vector<double> read_vertex_weights(const std::string& path, std::size_t count)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Invalid_input(internal::printable(path) + ": cannot open the file of vertex weights");
  return read_vertex_weights(in, count, path);
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_VERTEX_LIST_H
