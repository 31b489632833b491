// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A strict reader and an atomic writer of tetrahedral meshes in the ASCII Medit format (.mesh),
// the format of CGAL::IO::output_to_medit(), TetGen, MMG and Gamma's libMeshb. Vertex and
// tetrahedron order is kept exactly as in the file (source/target pairs are matched by index).
// Anything the reader does not understand is an error naming the file and line.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_MEDIT_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_MEDIT_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>
#include <CGAL/Distortion_optimization/IO/simplex_soup.h>
#include <CGAL/Distortion_optimization/IO/tetgen.h>
#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cctype>
#include <cmath>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

namespace internal {

// The sections of a 3D Medit file, with the number of values of each entry (libMeshb's table,
// ASCII layout; "Pentahedra" is the old name of "Prisms"). Sections whose entries have a variable
// or unknown layout (solutions, Geometry file names, polygons, ...) are not listed: a file using
// them is rejected rather than misread.
struct Medit_section
{
  const char* name;
  int values_per_entry;
};

// The section named `keyword` (in any case), or null.
inline const Medit_section* medit_section(const std::string& keyword)
{
  static const Medit_section sections[] = {
    // cells, first and second order
    {"Vertices", 4}, {"Tetrahedra", 5}, {"Edges", 3}, {"Triangles", 4}, {"Quadrilaterals", 5}, {"Prisms", 7},
    {"Pentahedra", 7}, {"Pyramids", 6}, {"Hexahedra", 9}, {"EdgesP2", 4}, {"TrianglesP2", 7}, {"QuadrilateralsQ2", 10},
    // lists of vertices and cells, normals and tangents
    {"Corners", 1}, {"Ridges", 1}, {"RequiredVertices", 1}, {"RequiredEdges", 1}, {"RequiredTriangles", 1},
    {"RequiredQuadrilaterals", 1}, {"Normals", 3}, {"Tangents", 3}, {"NormalAtVertices", 2}, {"TangentAtVertices", 2},
    {"NormalAtTriangleVertices", 3}, {"NormalAtQuadrilateralVertices", 4}, {"TangentAtEdgeVertices", 3}};
  for(const Medit_section& s : sections) {
    std::size_t i = 0;
    while(s.name[i] != '\0' && i < keyword.size() &&
          std::tolower(static_cast<unsigned char>(s.name[i])) == std::tolower(static_cast<unsigned char>(keyword[i])))
      ++i;
    if(s.name[i] == '\0' && i == keyword.size()) return &s;
  }
  return nullptr;
}

// Whether a token is one of the keywords above or a header keyword: seen where a value is
// expected, it means the section before it is shorter than announced.
inline bool is_medit_keyword(std::string_view token)
{
  // Numbers, fast (an ASCII test: std::isalpha consults the locale).
  if(token.empty() || static_cast<unsigned char>((token[0] | 0x20) - 'a') >= 26) return false;
  const std::string k = to_lower(std::string(token));
  return medit_section(k) != nullptr || k == "meshversionformatted" || k == "dimension" || k == "end" ||
         k == "angleofcornerbound";
}

class Medit_reader
{
public:
  Medit_reader(std::istream& in, const std::string& name) : tokens_(in, name) {}

  Tetrahedron_soup read()
  {
    std::string t;
    if(!tokens_.next(t)) tokens_.fail("empty file");
    if(to_lower(t) != "meshversionformatted")
      tokens_.fail("not a Medit file: expected 'MeshVersionFormatted', found '" + t + "'");
    const long long version = tokens_.integer(header_value("MeshVersionFormatted"));
    if(version < 1 || version > 4) tokens_.fail("unsupported MeshVersionFormatted " + std::to_string(version) + " (expected 1 to 4)");

    bool has_dimension = false, has_vertices = false, has_tetrahedra = false, has_triangles = false;
    while(tokens_.next(t)) {
      const std::string key = to_lower(t);
      if(key == "end") {
        if(tokens_.next(t)) tokens_.fail("'" + t + "' after End");
        break;
      }
      if(key == "meshversionformatted") tokens_.fail("MeshVersionFormatted repeated");
      if(key == "dimension") {
        if(has_dimension) tokens_.fail("Dimension repeated");
        const std::string d = header_value("Dimension");
        if(tokens_.integer(d) != 3) tokens_.fail("Dimension " + d + ": only 3D meshes are supported");
        has_dimension = true;
        continue;
      }
      const Medit_section* section = medit_section(key);
      if(section == nullptr && key != "angleofcornerbound") {
        if(Token_reader::is_number(t))
          tokens_.fail("expected a section keyword, found '" + t + "' (does the section before announce too few entries?)");
        tokens_.fail("unsupported Medit section '" + t + "' (its layout is unknown)");
      }
      if(!has_dimension) tokens_.fail("section " + t + " before Dimension");
      if(section == nullptr) { // AngleOfCornerBound: one value, no count
        check_number("AngleOfCornerBound", value("AngleOfCornerBound", 1, 0));
        continue;
      }
      const std::string name = section->name;
      if(name == "Vertices") {
        if(has_vertices) tokens_.fail("second Vertices section");
        read_vertices();
        has_vertices = true;
      } else if(name == "Tetrahedra") {
        if(has_tetrahedra) tokens_.fail("second Tetrahedra section");
        // Sections come in any order (libMeshb finds them by keyword): before the vertices, the
        // tetrahedra's indices are checked once those are known, as the triangles' are.
        tetrahedra_first = !has_vertices;
        read_simplices("Tetrahedra", "tetrahedron", soup_.cells, soup_.labels);
        has_tetrahedra = true;
      } else if(name == "Triangles") {
        if(has_triangles) tokens_.fail("second Triangles section");
        read_simplices("Triangles", "triangle", soup_.triangles, soup_.triangle_labels);
        has_triangles = true;
      } else {
        skip(*section);
      }
    }
    if(!has_vertices) tokens_.fail("no Vertices section");
    if(!has_tetrahedra) tokens_.fail("no Tetrahedra section");
    for(std::size_t c = 0; tetrahedra_first && c < soup_.cells.size(); ++c)
      for(std::size_t v : soup_.cells[c])
        if(v >= soup_.points.size())
          tokens_.fail("tetrahedron " + std::to_string(c) + " has vertex index " + std::to_string(v + 1) + " out of range (1 to " +
                       std::to_string(soup_.points.size()) + ")");
    for(std::size_t f = 0; f < soup_.triangles.size(); ++f)
      for(std::size_t v : soup_.triangles[f])
        if(v >= soup_.points.size())
          tokens_.fail("triangle " + std::to_string(f) + " has vertex index " + std::to_string(v + 1) + " out of range (1 to " +
                       std::to_string(soup_.points.size()) + ")");
    return std::move(soup_);
  }

private:
  std::string header_value(const std::string& keyword)
  {
    std::string v;
    if(!tokens_.next(v)) tokens_.fail("missing value after " + keyword);
    return v;
  }

  // The entry count after a section keyword, checked against what the rest of the file can hold
  // (each value takes at least one character and one separator), so that a corrupt count fails
  // at once instead of allocating memory for it.
  long long count(const std::string& section, int values_per_entry)
  {
    std::string c;
    if(!tokens_.next(c)) tokens_.fail("missing " + section + " count");
    if(is_medit_keyword(c)) tokens_.fail("missing " + section + " count (found '" + c + "')");
    const long long n = tokens_.integer(c);
    if(n < 0) tokens_.fail("negative " + section + " count " + c);
    const long long rest = tokens_.remaining_bytes();
    if(rest >= 0 && n > (rest + 1) / (2 * values_per_entry))
      tokens_.fail(section + " count " + c + " is more than the rest of the file can hold");
    return n;
  }

  // The next value of entry `entry` of a section announcing `n` entries: a view into the line,
  // valid until the next call.
  std::string_view value(const std::string& section, long long n, long long entry)
  {
    std::string_view v;
    if(!tokens_.next(v) || is_medit_keyword(v))
      tokens_.fail("truncated " + section + " section: " + std::to_string(n) + " entries announced, " +
                   std::to_string(entry) + " found");
    return v;
  }

  void check_number(const std::string& section, std::string_view v) const
  {
    if(!Token_reader::is_number(v)) tokens_.fail("'" + std::string(v) + "' in " + section + " is not a number");
  }

  // Room for `n` entries of a section, no more than the rest of the stream can hold.
  std::size_t plausible(long long n, int values_per_entry) const
  {
    return plausible_reserve(n, tokens_.remaining_bytes(), 2 * values_per_entry);
  }

  void read_vertices()
  {
    const long long n = count("Vertices", 4);
    soup_.points.reserve(plausible(n, 4));
    for(long long v = 0; v < n; ++v) {
      std::array<double, 3> p;
      for(int i = 0; i < 3; ++i) p[i] = tokens_.coordinate(value("Vertices", n, v));
      soup_.point_labels.push_back(reference("vertex", v, value("Vertices", n, v)));
      soup_.points.push_back(p);
    }
  }

  // Entries of k 1-based vertex indices and a reference: tetrahedra, checked against the vertices
  // and for a repeated vertex as they are read, or triangles (the Triangles section, kept for the
  // output), whose indices are checked once all vertices are known, and whose values are first
  // checked to be numbers (as those of the sections skipped).
  template <std::size_t k>
  void read_simplices(const char* section, const char* entry, std::vector<std::array<std::size_t, k>>& simplices,
                      std::vector<int>& labels)
  {
    constexpr bool tetrahedra = k == 4;
    constexpr int values = static_cast<int>(k) + 1;
    const long long n = count(section, values);
    const long long nv = tetrahedra && !tetrahedra_first ? static_cast<long long>(soup_.points.size()) : std::numeric_limits<long long>::max();
    simplices.reserve(plausible(n, values));
    labels.reserve(plausible(n, values));
    const auto next = [&](long long c) {
      const std::string_view s = value(section, n, c);
      if(!tetrahedra) check_number(section, s);
      return s;
    };
    for(long long c = 0; c < n; ++c) {
      std::array<std::size_t, k> simplex;
      for(std::size_t i = 0; i < k; ++i) {
        const std::string_view s = next(c);
        const long long index = tokens_.integer(s);
        if(index < 1 || index > nv)
          tokens_.fail(std::string(entry) + " " + std::to_string(c) + " has vertex index " + std::string(s) + " out of range" +
                       (nv < std::numeric_limits<long long>::max() ? " (1 to " + std::to_string(nv) + ")" : std::string()));
        simplex[i] = static_cast<std::size_t>(index - 1);
        for(std::size_t j = 0; tetrahedra && j < i; ++j)
          if(simplex[j] == simplex[i]) tokens_.fail(std::string(entry) + " " + std::to_string(c) + " repeats vertex " + std::string(s));
      }
      simplices.push_back(simplex);
      labels.push_back(reference(entry, c, next(c)));
    }
  }

  // A reference (label), as an int.
  int reference(const char* entry, long long index, std::string_view s)
  {
    const long long label = tokens_.integer(s);
    if(label < std::numeric_limits<int>::min() || label > std::numeric_limits<int>::max())
      tokens_.fail(std::string(entry) + " " + std::to_string(index) + " has reference " + std::string(s) + " out of range");
    return static_cast<int>(label);
  }

  void skip(const Medit_section& section)
  {
    const long long n = count(section.name, section.values_per_entry);
    // Other volume cells would be dropped, and the mesh read as a part of itself.
    const std::string volume_cells[] = {"Prisms", "Pentahedra", "Pyramids", "Hexahedra"};
    if(n > 0 && std::find(std::begin(volume_cells), std::end(volume_cells), section.name) != std::end(volume_cells))
      tokens_.fail(std::to_string(n) + " " + section.name + ": only tetrahedral meshes are supported");
    for(long long e = 0; e < n; ++e)
      for(int i = 0; i < section.values_per_entry; ++i) check_number(section.name, value(section.name, n, e));
  }

  Token_reader tokens_;
  bool tetrahedra_first = false;   // the Tetrahedra section came before the Vertices one
  Tetrahedron_soup soup_;
};

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Reads a 3D ASCII Medit mesh: "MeshVersionFormatted v" (1 to 4), "Dimension 3", "Vertices" n
/// then n entries "x y z ref", "Tetrahedra" n then n entries "a b c d ref" (1-based), and an
/// optional "End". Keywords are case-insensitive, '#' starts a comment, values may be spread
/// over lines in any way, and a UTF-8 byte order mark at the start is skipped. The vertices'
/// references and a "Triangles" section (entries "a b c ref") are kept in the soup. The other
/// sections of the format with a fixed layout (Edges, Quadrilaterals, Corners, Ridges,
/// Required*, Normals, Tangents, NormalAt*, TangentAt*, EdgesP2, TrianglesP2, QuadrilateralsQ2,
/// AngleOfCornerBound, and empty Prisms, Pyramids or Hexahedra) are checked and skipped. `name`
/// is used in error messages.
/// \throws Invalid_input naming the line for: a missing header, a dimension other than 3, a missing
/// Vertices or Tetrahedra section, volume cells other than tetrahedra, a section the reader does not know, a negative count, a count
/// larger than the rest of the file can hold, a line longer than 1 MiB, a truncated section, a
/// token that is not a number (a NUL byte or other garbage in it included), a non-finite
/// coordinate or one beyond 1e100 in magnitude, a vertex index out of range, a tetrahedron repeating a vertex, or anything after
/// End.
inline Tetrahedron_soup read_MEDIT_soup(std::istream& in, const std::string& name = "MEDIT input")
{
  return internal::Medit_reader(in, name).read();
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads a `.mesh` file with `read_MEDIT_soup()`, or a TetGen pair (`.ele` or `.node`, the other one
/// beside it) with `read_TetGen()`.
/// \throws Invalid_input if the file cannot be opened, has another extension, is malformed or has
/// no tetrahedron.
inline Tetrahedron_soup read_tetrahedron_soup(const std::string& path)
{
  const std::string shown = internal::printable(path);
  if(internal::extension(path) == "ele" || internal::extension(path) == "node") return read_TetGen(path);
  if(internal::extension(path) != "mesh") throw Invalid_input(shown + ": unsupported extension (use .mesh, or TetGen's .ele/.node)");
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Invalid_input(shown + ": cannot open the file");
  Tetrahedron_soup soup = read_MEDIT_soup(in, path);
  if(soup.cells.empty()) throw Invalid_input(shown + ": no tetrahedron");
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// Writes `soup` as an ASCII Medit file (MeshVersionFormatted 1, Dimension 3, Vertices with
/// `soup.point_labels` as references, or 0 for all when it is empty, Triangles with
/// `soup.triangle_labels` when `soup.triangles` is not empty, Tetrahedra with `soup.labels` as
/// references, or 1 for all when `labels` is empty, End), atomically, with the shortest decimals
/// that `read_MEDIT_soup()` reads back as the same doubles.
/// \throws Invalid_input (before anything is written) if `labels`, `point_labels` or
/// `triangle_labels` is neither empty nor one per tetrahedron, vertex or triangle, a coordinate is
/// not finite, or a triangle or a tetrahedron has an index out of range or repeats a vertex, i.e.
/// whenever `read_MEDIT_soup()` would reject the file; or if the file cannot be written.
inline void write_MEDIT_soup(const std::string& path, const Tetrahedron_soup& soup)
{
  const auto check_labels = [&](std::size_t labels, std::size_t entries, const char* what) {
    if(labels != 0 && labels != entries)
      throw Invalid_input(internal::printable(path) + ": " + std::to_string(labels) + " labels for " + std::to_string(entries) + " " + what);
  };
  check_labels(soup.labels.size(), soup.cells.size(), "tetrahedra");
  check_labels(soup.point_labels.size(), soup.points.size(), "vertices");
  check_labels(soup.triangle_labels.size(), soup.triangles.size(), "triangles");
  const auto check_simplices = [&](const auto& simplices, const std::string& entry) {
    for(std::size_t c = 0; c < simplices.size(); ++c) {
      const auto& s = simplices[c];
      for(std::size_t i = 0; i < s.size(); ++i) {
        if(s[i] >= soup.points.size())
          throw Invalid_input(internal::printable(path) + ": " + entry + " " + std::to_string(c) + " has vertex index " + std::to_string(s[i]) + " out of range");
        for(std::size_t j = 0; j < i; ++j)
          if(s[j] == s[i]) throw Invalid_input(internal::printable(path) + ": " + entry + " " + std::to_string(c) + " repeats vertex " + std::to_string(s[i]));
      }
    }
  };
  check_simplices(soup.triangles, "triangle");
  for(std::size_t v = 0; v < soup.points.size(); ++v)
    for(double x : soup.points[v])
      if(!std::isfinite(x)) throw Invalid_input(internal::printable(path) + ": vertex " + std::to_string(v) + " has a non-finite coordinate");
  check_simplices(soup.cells, "tetrahedron");
  // Formatted into memory with std::to_chars (the shortest decimals that read back the same
  // doubles), then written at once: through the stream's locale, each number took a virtual call.
  std::string text;
  text.reserve(80 * soup.points.size() + 40 * soup.cells.size() + 32 * soup.triangles.size() + 64);
  char number[32];
  const auto put = [&](auto x, char after) {
    text.append(number, std::to_chars(number, number + sizeof number, x).ptr);
    text += after;
  };
  text += "MeshVersionFormatted 1\nDimension 3\nVertices\n";
  put(soup.points.size(), '\n');
  for(std::size_t v = 0; v < soup.points.size(); ++v) {
    for(double x : soup.points[v]) put(x, ' ');
    put(soup.point_labels.empty() ? 0 : soup.point_labels[v], '\n');
  }
  if(!soup.triangles.empty()) {
    text += "Triangles\n";
    put(soup.triangles.size(), '\n');
    for(std::size_t f = 0; f < soup.triangles.size(); ++f) {
      for(std::size_t v : soup.triangles[f]) put(v + 1, ' ');
      put(soup.triangle_labels.empty() ? 0 : soup.triangle_labels[f], '\n');
    }
  }
  text += "Tetrahedra\n";
  put(soup.cells.size(), '\n');
  for(std::size_t c = 0; c < soup.cells.size(); ++c) {
    for(std::size_t v : soup.cells[c]) put(v + 1, ' ');
    put(soup.labels.empty() ? 1 : soup.labels[c], '\n');
  }
  text += "End\n";
  write_file_atomically(path, [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_MEDIT_H
