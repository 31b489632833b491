// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A strict reader of TetGen's .node/.ele pair (the files `tetgen` writes, and tetgenio's
// save_nodes/save_elements), keeping the order of points and tetrahedra as in the files.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_TETGEN_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_TETGEN_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>
#include <CGAL/Distortion_optimization/IO/simplex_soup.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <istream>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// Reads a tetrahedral mesh from TetGen's two files: the points (`node`: "count 3 attributes
/// markers", then "index x y z [attributes] [marker]") and the tetrahedra (`ele`: "count 4|10
/// regions", then "index n1 n2 n3 n4 [6 more nodes] [region]"). Indices are 0- or 1-based as the
/// first point's index says, and must then be consecutive; a quadratic (10-node) tetrahedron gives
/// its 4 corners; an integer region attribute becomes the tetrahedron's label. `node_name` and
/// `ele_name` are used in error messages. TetGen writes its tetrahedra positively oriented, as the
/// package expects; the reader does not reorient them.
/// \throws Invalid_input naming the file and line for: a bad header (dimension other than 3, 0
/// points, i.e. points kept in a .poly file, nodes per tetrahedron other than 4 or 10), a
/// truncated file or extra lines, an index out of sequence, a token that is not a number, a
/// non-finite coordinate or one beyond 1e100 in magnitude, a node index out of range, a tetrahedron repeating a vertex, or a region
/// attribute that is not an integer.
inline Tetrahedron_soup read_TetGen(std::istream& node, std::istream& ele, const std::string& node_name = "TetGen .node input",
                                    const std::string& ele_name = "TetGen .ele input")
{
  Tetrahedron_soup soup;
  std::vector<std::string> t;
  internal::Line_reader nodes(node, node_name);
  if(!nodes.next(t)) nodes.fail("empty file");
  if(t.size() != 4) nodes.fail("expected 4 header values (points, dimension, attributes, markers), found " + std::to_string(t.size()));
  const long long n = nodes.integer(t[0]), dimension = nodes.integer(t[1]), attributes = nodes.integer(t[2]),
                  markers = nodes.integer(t[3]);
  if(n == 0) nodes.fail("no point (points kept in a .poly file are not supported)");
  if(n < 0 || attributes < 0 || (markers != 0 && markers != 1)) nodes.fail("bad header counts");
  if(dimension != 3) nodes.fail("dimension " + t[1] + ": only 3D meshes are supported");
  long long base = 0;
  soup.points.reserve(internal::plausible_reserve(n, nodes.remaining_bytes(), 8));
  for(long long i = 0; i < n; ++i) {
    if(!nodes.next(t)) nodes.fail("truncated: " + std::to_string(n) + " points announced, " + std::to_string(i) + " found");
    if(static_cast<long long>(t.size()) != 4 + attributes + markers)
      nodes.fail("point line with " + std::to_string(t.size()) + " values, the header announces " +
                 std::to_string(4 + attributes + markers));
    const long long index = nodes.integer(t[0]);
    if(i == 0 && index != 0 && index != 1) nodes.fail("the first point's index is " + t[0] + " (0 or 1 expected)");
    if(i == 0) base = index;
    if(index != base + i) nodes.fail("point index " + t[0] + " out of sequence (" + std::to_string(base + i) + " expected)");
    soup.points.push_back({nodes.coordinate(t[1]), nodes.coordinate(t[2]), nodes.coordinate(t[3])});
    nodes.check_numbers(t, 4);
  }
  if(nodes.next(t)) nodes.fail("'" + t[0] + "' after the " + std::to_string(n) + " points the header announces");

  internal::Line_reader cells(ele, ele_name);
  if(!cells.next(t)) cells.fail("empty file");
  if(t.size() != 3) cells.fail("expected 3 header values (tetrahedra, nodes per tetrahedron, regions), found " + std::to_string(t.size()));
  const long long m = cells.integer(t[0]), corners = cells.integer(t[1]), regions = cells.integer(t[2]);
  if(m < 0 || (regions != 0 && regions != 1)) cells.fail("bad header counts");
  if(corners != 4 && corners != 10) cells.fail(t[1] + " nodes per tetrahedron (4 or 10 expected)");
  soup.cells.reserve(internal::plausible_reserve(m, cells.remaining_bytes(), 10));
  for(long long c = 0; c < m; ++c) {
    if(!cells.next(t)) cells.fail("truncated: " + std::to_string(m) + " tetrahedra announced, " + std::to_string(c) + " found");
    if(static_cast<long long>(t.size()) != 1 + corners + regions)
      cells.fail("tetrahedron line with " + std::to_string(t.size()) + " values, the header announces " +
                 std::to_string(1 + corners + regions));
    if(cells.integer(t[0]) != base + c)
      cells.fail("tetrahedron index " + t[0] + " out of sequence (" + std::to_string(base + c) + " expected)");
    std::array<std::size_t, 4> tet;
    for(int k = 0; k < corners; ++k) {
      const long long v = cells.integer(t[1 + k]) - base;
      if(v < 0 || v >= n) cells.fail("tetrahedron " + std::to_string(c) + " has node index " + t[1 + k] + " out of range");
      if(k < 4) tet[k] = static_cast<std::size_t>(v);
    }
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b)
        if(tet[a] == tet[b]) cells.fail("tetrahedron " + std::to_string(c) + " repeats a vertex");
    soup.cells.push_back(tet);
    if(regions == 1) {
      const double region = cells.coordinate(t[1 + corners], "region attribute");
      if(region != std::floor(region) || std::abs(region) > 2147483647.)
        cells.fail("region attribute " + t[1 + corners] + " is not an integer label");
      soup.labels.push_back(static_cast<int>(region));
    }
  }
  if(cells.next(t)) cells.fail("'" + t[0] + "' after the " + std::to_string(m) + " tetrahedra the header announces");
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// The `.node` and `.ele` files of the TetGen mesh that `path` names (either one), both of which
/// `read_TetGen()` opens: a program that reads such a mesh must not write over either. Two empty
/// strings if `path` names neither (its extension is not `node` or `ele`).
inline std::array<std::string, 2> TetGen_files(const std::string& path)
{
  const std::string e = internal::extension(path);
  if(e != "ele" && e != "node") return {};
  const std::string stem = path.substr(0, path.size() - e.size() - 1);
  return {stem + ".node", stem + ".ele"};
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads `stem.node` and `stem.ele` with `read_TetGen()`, given the path of either one (or of
/// `stem.ele` only: the other is found beside it).
/// \throws Invalid_input if a file cannot be opened, is malformed, or there is no tetrahedron.
inline Tetrahedron_soup read_TetGen(const std::string& path)
{
  const auto [node_path, ele_path] = TetGen_files(path);
  if(node_path.empty()) throw Invalid_input(internal::printable(path) + ": a TetGen mesh is a .node/.ele pair");
  std::ifstream node(node_path, std::ios::binary), ele(ele_path, std::ios::binary);
  if(!node) throw Invalid_input(internal::printable(node_path) + ": cannot open the file");
  if(!ele) throw Invalid_input(internal::printable(ele_path) + ": cannot open the file");
  Tetrahedron_soup soup = read_TetGen(node, ele, node_path, ele_path);
  if(soup.cells.empty()) throw Invalid_input(internal::printable(ele_path) + ": no tetrahedron");
  return soup;
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_TETGEN_H
