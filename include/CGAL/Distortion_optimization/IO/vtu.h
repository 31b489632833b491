// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// An atomic writer of simplicial meshes with per-cell values (e.g. the distortion of each cell) as
// ASCII VTK XML unstructured grids (.vtu), for ParaView and VisIt.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_VTU_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_VTU_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// The value written in place of +infinity (and its opposite for -infinity) by `write_VTU()`:
/// the VTK readers parse ASCII numbers with C++ streams, which do not accept "inf".
constexpr double vtu_infinity = 1e308;

namespace internal {

inline std::string xml_escaped(const std::string& s)
{
  std::string e;
  for(char c : s) {
    switch(c) {
      case '&': e += "&amp;"; break;
      case '<': e += "&lt;"; break;
      case '>': e += "&gt;"; break;
      case '"': e += "&quot;"; break;
      case '\'': e += "&apos;"; break;
      default: e += c;
    }
  }
  return e;
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Writes points and cells (triangles, `N = 3`, VTK_TRIANGLE, e.g. a planar or surface map; or
/// tetrahedra, `N = 4`, VTK_TETRA) as an ASCII VTK XML UnstructuredGrid, atomically, with one
/// Float64 cell array per entry of `cell_data` (name, one value per cell); the first one is the
/// active scalar. Values are written with 17 significant digits; +infinity (the distortion of an
/// inverted cell) is written as `vtu_infinity` = 1e308 and -infinity as -1e308, so thresholds and
/// colour maps in ParaView still work ("inf" is not readable there). Each entry of `point_data` is
/// a Float64 point array of 3-vectors (name, one per point), e.g. the displacement from the source
/// to the target: ParaView's "Warp By Vector" with scale factor -1 then shows the cells where they
/// come from (a parametrization on its 3D surface) with their distortion.
/// \throws Invalid_input (before anything is written) if a coordinate is not finite, a cell has an
/// index out of range, an array has an empty, repeated or control-character name, a size other
/// than the number of cells (points), or a NaN value (a non-finite point value); or if the file
/// cannot be written.
template <std::size_t N>
void write_VTU(const std::string& path,
               const std::vector<std::array<double, 3>>& points,
               const std::vector<std::array<std::size_t, N>>& cells,
               const std::vector<std::pair<std::string, std::vector<double>>>& cell_data = {},
               const std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>>& point_data = {})
{
  static_assert(N == 3 || N == 4, "write_VTU writes triangles (N = 3) or tetrahedra (N = 4)");
  const int vtk_type = N == 3 ? 5 : 10; // VTK_TRIANGLE, VTK_TETRA
  const char* const cell_name = N == 3 ? "triangle " : "tetrahedron ";

  for(std::size_t v = 0; v < points.size(); ++v)
    for(double x : points[v])
      if(!std::isfinite(x)) throw Invalid_input(path + ": vertex " + std::to_string(v) + " has a non-finite coordinate");
  for(std::size_t c = 0; c < cells.size(); ++c)
    for(std::size_t i : cells[c])
      if(i >= points.size())
        throw Invalid_input(path + ": " + cell_name + std::to_string(c) + " has vertex index " + std::to_string(i) +
                            " out of range");
  const auto check_name = [&path](std::set<std::string>& names, const std::string& kind, const std::string& name,
                                  std::size_t size, std::size_t expected) {
    if(name.empty()) throw Invalid_input(path + ": a " + kind + " array has an empty name");
    for(char ch : name)
      if(static_cast<unsigned char>(ch) < 0x20)
        throw Invalid_input(path + ": " + kind + " array name '" + name + "' has a control character");
    if(!names.insert(name).second) throw Invalid_input(path + ": " + kind + " array '" + name + "' given twice");
    if(size != expected)
      throw Invalid_input(path + ": " + kind + " array '" + name + "' has " + std::to_string(size) + " values for " +
                          std::to_string(expected) + " " + kind + "s");
  };
  std::set<std::string> names, point_names;
  for(const auto& array : cell_data) {
    check_name(names, "cell", array.first, array.second.size(), cells.size());
    for(std::size_t c = 0; c < array.second.size(); ++c)
      if(std::isnan(array.second[c]))
        throw Invalid_input(path + ": cell array '" + array.first + "' is NaN at cell " + std::to_string(c));
  }
  for(const auto& array : point_data) {
    check_name(point_names, "point", array.first, array.second.size(), points.size());
    for(std::size_t v = 0; v < array.second.size(); ++v)
      for(double x : array.second[v])
        if(!std::isfinite(x))
          throw Invalid_input(path + ": point array '" + array.first + "' is not finite at point " + std::to_string(v));
  }

  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << cells.size() << "\">\n"
        << "      <Points>\n"
        << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for(const auto& p : points) out << "          " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    out << "        </DataArray>\n"
        << "      </Points>\n"
        << "      <Cells>\n"
        << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for(const auto& c : cells) {
      out << "         ";
      for(std::size_t i : c) out << ' ' << i;
      out << '\n';
    }
    out << "        </DataArray>\n"
        << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for(std::size_t c = 0; c < cells.size(); ++c) out << "          " << (c + 1) * N << '\n';
    out << "        </DataArray>\n"
        << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for(std::size_t c = 0; c < cells.size(); ++c) out << "          " << vtk_type << '\n';
    out << "        </DataArray>\n"
        << "      </Cells>\n";
    if(!point_data.empty()) {
      out << "      <PointData Vectors=\"" << internal::xml_escaped(point_data.front().first) << "\">\n";
      for(const auto& array : point_data) {
        out << "        <DataArray type=\"Float64\" Name=\"" << internal::xml_escaped(array.first)
            << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for(const auto& x : array.second) out << "          " << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
        out << "        </DataArray>\n";
      }
      out << "      </PointData>\n";
    }
    if(cell_data.empty()) {
      out << "      <CellData>\n";
    } else {
      out << "      <CellData Scalars=\"" << internal::xml_escaped(cell_data.front().first) << "\">\n";
    }
    for(const auto& array : cell_data) {
      out << "        <DataArray type=\"Float64\" Name=\"" << internal::xml_escaped(array.first) << "\" format=\"ascii\">\n";
      for(double x : array.second)
        out << "          " << (std::isinf(x) ? (x > 0 ? vtu_infinity : -vtu_infinity) : x) << '\n';
      out << "        </DataArray>\n";
    }
    out << "      </CellData>\n"
        << "    </Piece>\n"
        << "  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
  });
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_VTU_H
