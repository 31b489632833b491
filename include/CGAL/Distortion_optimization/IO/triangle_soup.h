// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Strict readers and atomic writers of triangle meshes in OFF and OBJ (and PLY, STL and GOCAD
// read through CGAL's readers, then checked as strictly), keeping vertex and face order exactly as
// in the file (source/target pairs are matched by index). Anything a reader does
// not understand is an error naming the file and line, never a silent guess.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_TRIANGLE_SOUP_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_TRIANGLE_SOUP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>
#include <CGAL/Distortion_optimization/IO/simplex_soup.h>
#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>

#include <CGAL/IO/GOCAD.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <istream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

namespace internal {

inline void check_triangle(const Line_reader& reader, const std::array<std::size_t, 3>& t, std::size_t face)
{
  if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    reader.fail("face " + std::to_string(face) + " repeats a vertex");
}

// The statements of the OBJ format (Wavefront's specification, with the old maplib and usemap).
// Those other than v and f do not concern a triangle soup and are skipped; a line starting with
// anything else is not OBJ and is refused rather than dropped.
inline bool is_obj_statement(const std::string& keyword)
{
  static const char* const statements[] = {
    "v", "vt", "vn", "vp", "f", "p", "l", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm",
    "trim", "hole", "scrv", "sp", "end", "con", "g", "s", "mg", "o", "bevel", "c_interp", "d_interp", "lod",
    "usemtl", "mtllib", "shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap"};
  return std::find(std::begin(statements), std::end(statements), keyword) != std::end(statements);
}

// The vertex, texture and normal indices of an OBJ face reference "i", "i/t", "i//n" or "i/t/n"
// (as written, 0 for none).
inline std::array<long long, 3> obj_vertex_reference(const Line_reader& reader, const std::string& ref)
{
  std::size_t begin = 0;
  std::array<long long, 3> indices = {0, 0, 0};
  for(int part = 0; part < 3; ++part) {
    const std::size_t slash = ref.find('/', begin);
    const std::string value = ref.substr(begin, slash == std::string::npos ? std::string::npos : slash - begin);
    if(part == 0) indices[0] = reader.integer(value);
    else if(!value.empty() || slash == std::string::npos) {   // "i/" is malformed, "i//n" is not
      const long long index = reader.integer(value);
      if(index == 0)
        reader.fail("face vertex '" + ref + "' has " + (part == 1 ? "texture" : "normal") + " index 0 (OBJ counts from 1)");
      indices[part] = index;
    }
    if(slash == std::string::npos) return indices;
    begin = slash + 1;
  }
  reader.fail("face vertex '" + ref + "' has more than three parts");
}

// An OBJ index (1-based, or negative relative to the `count` items so far) made 0-based;
// -1 when out of range.
inline long long obj_index(long long index, std::size_t count)
{
  const long long n = static_cast<long long>(count);
  index = index < 0 ? n + index : index - 1;
  return index >= 0 && index < n ? index : -1;
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Reads an OFF file of triangles ("OFF", or "off", and the three counts "nv nf ne" on its line
/// or the next, vertex lines "x y z [...]", face lines "3 i j k [...]", the optional values being
/// numbers such as colors). The header may also be that of a variant with texture coordinates,
/// colours or normals on the vertex lines (STOFF, COFF, NOFF, CNOFF, ...), whose values are
/// skipped. A UTF-8 byte order mark is skipped. `name` is used in error messages.
/// \throws Invalid_input naming the line for a missing header or count, a count line without
/// exactly three counts, a line longer than 1 MiB, a truncated file, a token that is not a number
/// (a NUL byte or other garbage in it included), a non-finite coordinate or one beyond 1e100 in
/// magnitude (products of three coordinates must stay finite), a face that is not a triangle, an
/// index out of range, or anything after the announced faces.
inline Triangle_soup read_OFF(std::istream& in, const std::string& name = "OFF input")
{
  internal::Line_reader reader(in, name);
  std::vector<std::string> t;
  if(!reader.next(t)) reader.fail("empty file");
  std::size_t first = 0;   // where the counts start: "OFF nv nf ne", or "OFF" then "nv nf ne"
  // "OFF" in any case ("off" is written by some tools); the variants' prefixes are case sensitive.
  std::string off = t[0].size() >= 3 ? t[0].substr(t[0].size() - 3) : std::string();
  for(char& c : off) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if(off == "OFF") {
    // The variants whose vertex lines add values after x y z: texture (ST), colour (C), normal
    // (N), in that order (COFF, NOFF, STCNOFF, ...); the optional values are skipped anyway.
    // Homogeneous (4OFF) and n-dimensional (nOFF) coordinates would be misread.
    const std::string prefix = t[0].substr(0, t[0].size() - 3);
    std::size_t known = prefix.compare(0, 2, "ST") == 0 ? 2 : 0;
    if(known < prefix.size() && prefix[known] == 'C') ++known;
    if(known < prefix.size() && prefix[known] == 'N') ++known;
    if(known != prefix.size())
      reader.fail("'" + t[0] + "' is not supported: only OFF and its variants with texture, colour or normal values "
                  "(STOFF, COFF, NOFF, ...)");
    if(t.size() > 1) first = 1;
    else if(!reader.next(t)) reader.fail("missing vertex and face counts");
  }
  if(t.size() < first + 2) reader.fail("missing vertex and face counts");
  if(t.size() != first + 3)
    reader.fail("expected 3 counts (vertices, faces, edges), found " + std::to_string(t.size() - first));
  const long long nv = reader.integer(t[first]), nf = reader.integer(t[first + 1]), ne = reader.integer(t[first + 2]);
  if(nv < 0 || nf < 0 || ne < 0) reader.fail("negative counts");

  // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 8 ("3 0 1 2\n").
  Triangle_soup soup;
  soup.points.reserve(internal::plausible_reserve(nv, reader.remaining_bytes(), 6));
  for(long long v = 0; v < nv; ++v) {
    if(!reader.next(t)) reader.fail("truncated: " + std::to_string(nv) + " vertices announced, " + std::to_string(v) + " found");
    if(t.size() < 3) reader.fail("vertex " + std::to_string(v) + " has fewer than 3 coordinates");
    soup.points.push_back({reader.coordinate(t[0]), reader.coordinate(t[1]), reader.coordinate(t[2])});
    reader.check_numbers(t, 3);
  }
  soup.cells.reserve(internal::plausible_reserve(nf, reader.remaining_bytes(), 8));
  for(long long f = 0; f < nf; ++f) {
    if(!reader.next(t)) reader.fail("truncated: " + std::to_string(nf) + " faces announced, " + std::to_string(f) + " found");
    const long long k = reader.integer(t[0]);
    if(k != 3) reader.fail("face " + std::to_string(f) + " is not a triangle (" + t[0] + " vertices)");
    if(t.size() < 4) reader.fail("face " + std::to_string(f) + " lists fewer than 3 vertices");
    std::array<std::size_t, 3> tri;
    for(int i = 0; i < 3; ++i) {
      const long long index = reader.integer(t[1 + i]);
      if(index < 0 || index >= nv) reader.fail("face " + std::to_string(f) + " has vertex index " + t[1 + i] + " out of range");
      tri[i] = static_cast<std::size_t>(index);
    }
    reader.check_numbers(t, 4);
    internal::check_triangle(reader, tri, static_cast<std::size_t>(f));
    soup.cells.push_back(tri);
  }
  if(reader.next(t))
    reader.fail("'" + t[0] + "' after the " + std::to_string(nf) + " faces the header announces");
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads the vertices ("v x y z [...]", the optional values being numbers such as w or a color),
/// texture coordinates ("vt u v [w]") and faces ("f a b c", with a/b/c possibly "i/t/n", 1-based or
/// negative relative indices) of an OBJ file; the other statements of the format are skipped. A
/// backslash ending a line continues its statement on the next line. A UTF-8 byte order mark is
/// skipped.
/// \throws Invalid_input naming the line, as `read_OFF()`, and for a line that is not an OBJ
/// statement.
inline Triangle_soup read_OBJ(std::istream& in, const std::string& name = "OBJ input")
{
  internal::Line_reader reader(in, name);
  std::vector<std::string> t;
  Triangle_soup soup;
  std::size_t normals = 0;   // checked in faces' references, not kept
  std::vector<std::string> more;
  while(reader.next(t)) {
    // A backslash at the end of a line continues the statement on the next one.
    while(t.back().back() == '\\') {
      t.back().pop_back();
      if(t.back().empty()) t.pop_back();
      if(!reader.next(more)) reader.fail("a line continued ('\\' at its end) by no other line");
      t.insert(t.end(), more.begin(), more.end());
    }
    if(t[0] == "vn") {
      ++normals;
    } else if(t[0] == "v") {
      if(t.size() < 4) reader.fail("vertex with fewer than 3 coordinates");
      soup.points.push_back({reader.coordinate(t[1]), reader.coordinate(t[2]), reader.coordinate(t[3])});
      reader.check_numbers(t, 4);
    } else if(t[0] == "vt") {
      if(t.size() < 3) reader.fail("texture coordinate with fewer than 2 values");
      soup.texture_coordinates.push_back({reader.coordinate(t[1]), reader.coordinate(t[2])});
      reader.check_numbers(t, 3);
    } else if(t[0] == "f") {
      const std::size_t f = soup.cells.size();
      if(t.size() != 4) reader.fail("face " + std::to_string(f) + " is not a triangle (" + std::to_string(t.size() - 1) + " vertices)");
      constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
      std::array<std::size_t, 3> tri, tex = {none, none, none};
      bool textured = false;
      for(int i = 0; i < 3; ++i) {
        const std::array<long long, 3> ref = internal::obj_vertex_reference(reader, t[1 + i]);
        const long long index = internal::obj_index(ref[0], soup.points.size());
        if(index < 0) reader.fail("face " + std::to_string(f) + " has vertex index " + t[1 + i] + " out of range");
        tri[i] = static_cast<std::size_t>(index);
        if(ref[1] != 0) {
          const long long texture = internal::obj_index(ref[1], soup.texture_coordinates.size());
          if(texture < 0) reader.fail("face " + std::to_string(f) + " has texture index " + t[1 + i] + " out of range");
          tex[i] = static_cast<std::size_t>(texture);
          textured = true;
        }
        if(ref[2] != 0 && internal::obj_index(ref[2], normals) < 0)
          reader.fail("face " + std::to_string(f) + " has normal index " + t[1 + i] + " out of range");
      }
      internal::check_triangle(reader, tri, f);
      soup.cells.push_back(tri);
      // Texture indices for every face once one has some (none where a face has none).
      if(textured && soup.cell_texture_indices.size() < f) soup.cell_texture_indices.assign(f, {none, none, none});
      if(textured || !soup.cell_texture_indices.empty()) soup.cell_texture_indices.push_back(tex);
    } else if(!internal::is_obj_statement(t[0])) {
      reader.fail("'" + t[0] + "' is not an OBJ statement");
    }
  }
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// One (u, v) per vertex from the texture coordinates of an OBJ soup: a parametrization stored as
/// UVs. Empty if the faces refer to no texture coordinates. `name` is used in error messages.
/// \throws Invalid_input if some face vertices have no texture index while others have, if a
/// vertex has two different texture coordinates (a seam: the map needs one per vertex, so the
/// mesh must be cut there) or if a vertex is in no face.
inline std::vector<std::array<double, 2>> per_vertex_texture_coordinates(const Triangle_soup& soup, const std::string& name)
{
  if(soup.cell_texture_indices.empty()) return {};
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> index(soup.points.size(), none);
  for(std::size_t f = 0; f < soup.cells.size(); ++f)
    for(int i = 0; i < 3; ++i) {
      std::size_t& mine = index[soup.cells[f][i]];
      const std::size_t t = soup.cell_texture_indices[f][i];
      if(t == none)
        throw Invalid_input(internal::printable(name) + ": face " + std::to_string(f) +
                            ": some face vertices have texture indices and others not");
      if(mine != none && soup.texture_coordinates[mine] != soup.texture_coordinates[t])
        throw Invalid_input(internal::printable(name) + ": vertex " + std::to_string(soup.cells[f][i]) +
                            " has two texture coordinates (a seam); one (u, v) per vertex is needed");
      mine = t;
    }
  std::vector<std::array<double, 2>> uv(index.size());
  for(std::size_t v = 0; v < index.size(); ++v) {
    if(index[v] == none) throw Invalid_input(internal::printable(name) + ": vertex " + std::to_string(v) + " is in no face");
    uv[v] = soup.texture_coordinates[index[v]];
  }
  return uv;
}

namespace internal {

// The size in bytes of a scalar type of the PLY format (by its old or its sized name); 0 for a
// name that is no PLY type.
inline std::size_t PLY_type_size(const std::string& type)
{
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32") return 4;
  if(type == "double" || type == "float64") return 8;
  return 0;
}

// A value of the PLY scalar type `type` read from `in` by CGAL's PLY reader's own code (ASCII or
// binary as its `mode` says: 0, 1 little-endian, 2 big-endian), or none where that read fails.
inline std::optional<long double> read_PLY_value(std::istream& in, const std::string& type, std::size_t mode)
{
  const auto read = [&](auto zero) -> std::optional<long double> {
    CGAL::IO::internal::PLY_read_typed_number<decltype(zero)> reader("", mode);
    reader.get(in);
    if(in.fail()) return std::nullopt;
    return static_cast<long double>(reader.buffer());
  };
  if(type == "char" || type == "int8") return read(std::int8_t());
  if(type == "uchar" || type == "uint8") return read(std::uint8_t());
  if(type == "short" || type == "int16") return read(std::int16_t());
  if(type == "ushort" || type == "uint16") return read(std::uint16_t());
  if(type == "int" || type == "int32") return read(std::int32_t());
  if(type == "uint" || type == "uint32") return read(std::uint32_t());
  if(type == "float" || type == "float32") return read(float());
  return read(double());
}

// What CGAL's PLY reader does not check, or checks only after taking memory without bound, checked
// on the bytes before it reads them. The header, parsed as that reader parses it (the format on
// line 2, then keywords up to the end_header line): every property after its element and of a PLY
// type (the reader crashes on the first, skips and misreads the second), element counts that are
// numbers the file can hold, vertices with scalar x, y and z, faces with 32-bit vertex_indices
// (the only ones it takes, saying so on std::cerr alone). Then the body, read value by value as it
// reads it: list counts that it can read (it makes room for a count before reading the entries, an
// uninitialized one where the read fails), not negative and no larger than the rest of the file can
// hold (a count near 2^32 in a small file would take gigabytes), and nothing after the elements
// the header announces (it stops after them, silently dropping the rest), every value a number it
// reads.
inline void check_PLY(const std::string& bytes, const std::string& shown)
{
  struct Property { std::string name, type, count_type; };   // a list has a count type
  struct Element { std::string name; unsigned long long count = 0; std::vector<Property> properties; };
  std::vector<Element> elements;
  std::string format, index_type, coordinates;   // coordinates: the vertices' scalar x, y and z seen
  std::size_t at = 0, line_number = 0;
  const auto where = [&] { return shown + ":" + std::to_string(line_number) + ": "; };
  for(bool ended = false; !ended;) {
    // (CGAL's reader would take the whole file for the header, then read its elements from nothing.)
    if(at >= bytes.size()) {
      if(line_number == 0) return;   // an empty file: CGAL's reader tells
      throw Invalid_input(shown + ": the header has no end_header line");
    }
    const std::size_t end = (std::min)(bytes.find('\n', at), bytes.size());
    std::istringstream words(bytes.substr(at, end - at));
    at = end + 1;
    ++line_number;
    std::string word, name, type, count_type, version;
    words >> word;
    if(line_number == 1) {
      if(word != "ply") return;   // CGAL's reader tells
    } else if(line_number == 2) {
      if(word != "format" || !(words >> format >> version) ||
         (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian"))
        throw Invalid_input(where() + "not the format line (format ascii, binary_little_endian or binary_big_endian, "
                                      "then a version)");
    } else if(word == "end_header") {
      ended = true;
    } else if(word == "element" && (words >> name >> type)) {
      // A count that is no count (-5 read as 2^64 - 5) or larger than the file could hold (an
      // instance takes a byte at least): CGAL's reader would make room for it first.
      if(type.find_first_not_of("0123456789") != std::string::npos)
        throw Invalid_input(where() + "element " + name + " has the count '" + type + "', not a number of elements");
      if(type.size() > 18 || std::stoull(type) > bytes.size())
        throw Invalid_input(where() + "element " + name + " announces " + type + " instances, more than the file holds");
      elements.push_back({name, std::stoull(type), {}});
    } else if(word == "property") {
      if(elements.empty()) throw Invalid_input(where() + "a property declared before any element");
      const bool list = (words >> type) && type == "list";
      if(!(list ? (words >> count_type >> type >> name) : (words >> name))) return;   // CGAL's reader tells
      for(const std::string& t : list ? std::vector<std::string>{count_type, type} : std::vector<std::string>{type})
        if(PLY_type_size(t) == 0) throw Invalid_input(where() + "a property of type " + printable(t) + ", which is no PLY type");
      if(list && (count_type.find("float") != std::string::npos || count_type == "double"))
        throw Invalid_input(where() + "a list counted by a " + count_type + " (a count is an integer)");
      Element& element = elements.back();
      element.properties.push_back({name, type, list ? count_type : std::string()});
      if(element.name == "vertex" && (name == "x" || name == "y" || name == "z")) {
        if(list) throw Invalid_input(where() + "the vertex coordinate " + name + " is declared as a list");
        coordinates += name;
      }
      if((element.name == "face" || element.name == "faces") && list && (name == "vertex_indices" || name == "vertex_index"))
        index_type = type;
    }
  }
  const auto declared = [&](const char* name) {
    return std::any_of(elements.begin(), elements.end(), [&](const Element& e) { return e.name == name; });
  };
  for(const char axis : {'x', 'y', 'z'})
    if(declared("vertex") && coordinates.find(axis) == std::string::npos)
      throw Invalid_input(shown + ": the vertices have no property " + std::string(1, axis));
  if((declared("face") || declared("faces")) && index_type.empty())
    throw Invalid_input(shown + ": the faces have no list property vertex_indices (or vertex_index)");
  if((declared("face") || declared("faces")) && index_type != "int" && index_type != "uint" && index_type != "int32" &&
     index_type != "uint32")
    throw Invalid_input(shown + ": face vertex indices of type " + printable(index_type) + " (CGAL's PLY reader takes int or uint)");

  unsigned long long announced = 0;
  for(const Element& element : elements) announced += element.count;
  // The body read as CGAL's reader reads it, by its own code, but for the lists' entries: it takes
  // a count it could not read (the file ended, or no number) from an uninitialized variable, and
  // makes room for that many entries.
  std::istringstream in(bytes.substr(at));
  CGAL::IO::set_mode(in, CGAL::IO::BINARY);
  const std::size_t mode = format == "ascii" ? 0 : format == "binary_little_endian" ? 1 : 2;
  const auto bad_count = [&](const Element& element, unsigned long long i, const std::string& count, const std::string& why) {
    throw Invalid_input(shown + ": " + element.name + " " + std::to_string(i) + " has a list of " + count + " entries" + why);
  };
  const char* const space = " \t\r\n\v\f";
  // The token of an ASCII file at `position` (after blanks), as written; `position` is where the
  // last value read below began.
  std::size_t position = 0;
  const auto token_at = [&](std::size_t from) {
    const std::size_t begin = (std::min)(bytes.find_first_not_of(space, from), bytes.size());
    return bytes.substr(begin, bytes.find_first_of(space, begin) - begin);
  };
  // Reads a value of `type` for `role` (empty, "the count of ", "an entry of ") property `name` of
  // instance i of `element`; where CGAL's reader would fail (and, in a face element, go on reading
  // the next elements from a failed stream, into uninitialized counts), says why.
  const auto value = [&](const Element& element, unsigned long long i, const char* role, const std::string& name,
                         const std::string& type) {
    position = in.eof() ? bytes.size() : at + static_cast<std::size_t>(in.tellg());
    const std::optional<long double> v = read_PLY_value(in, type, mode);
    if(v) return *v;
    const std::string text = mode == 0 ? token_at(position) : std::string();
    if(mode == 0 ? text.empty() : bytes.size() - position < PLY_type_size(type))
      throw Invalid_input(shown + ": the file ends before the " + std::to_string(announced) + " elements the header announces");
    throw Invalid_input(shown + ": " + element.name + " " + std::to_string(i) + " has '" + printable(text) + "' for " + role +
                        name + ", not a number of type " + type);
  };
  for(const Element& element : elements)
    for(unsigned long long i = 0; i < element.count && !element.properties.empty(); ++i)
      for(const Property& p : element.properties) {
        if(p.count_type.empty()) {
          value(element, i, "", p.name, p.type);
          continue;
        }
        const long double n = value(element, i, "the count of ", p.name, p.count_type);
        // (In an ASCII file, the number as written: CGAL converts it to the count's type.)
        const std::string text = mode == 0 ? token_at(position) : std::string();
        const std::string count = mode == 0 ? printable(text) : std::to_string(static_cast<long long>(n));
        if(n < 0 || (mode == 0 && text[0] == '-' && text.find_first_not_of("-0") != std::string::npos)) bad_count(element, i, count, "");
        // Each entry takes a character and a separator at least, or its size in binary.
        const std::size_t left = in.eof() ? 0 : bytes.size() - at - static_cast<std::size_t>(in.tellg());
        if(n > (mode == 0 ? (left + 1) / 2 : left / PLY_type_size(p.type))) bad_count(element, i, count, ", more than the file holds");
        for(long double k = 0; k < n; ++k) value(element, i, "an entry of ", p.name, p.type);
      }
  if(in.eof()) return;
  const std::size_t end = at + static_cast<std::size_t>(in.tellg()), extra = bytes.find_first_not_of(space, end);
  if(extra == std::string::npos) return;
  const std::string after = "content after the " + std::to_string(announced) + " elements the header announces";
  if(mode == 0)
    throw Invalid_input(shown + ":" + std::to_string(1 + std::count(bytes.begin(), bytes.begin() + std::ptrdiff_t(extra), '\n')) + ": " + after);
  throw Invalid_input(shown + ": " + after + " (byte " + std::to_string(end) + " of " + std::to_string(bytes.size()) + ")");
}

// The checks on a file's bytes that CGAL's PLY, STL and GOCAD readers do not make: PLY's in
// check_PLY(); content after a binary STL's facets or an ASCII STL's first endsolid, or after a
// GOCAD file's last END (ignored by them); GOCAD vertex ids out of order, ATOM vertices
// (misnumbered by them) and triangles of more than three indices; and non-finite STL coordinates (CGAL merges equal corners through comparisons, and a NaN
// compares equal to every point). Two repairs of the bytes: a GOCAD file's carriage returns are
// dropped (its reader takes "END\r" for an unknown keyword), and an ASCII STL written in capitals
// is read in lower case.
inline void check_bytes_for_CGAL(std::string& bytes, const std::string& shown, const std::string& e)
{
  const auto split = [](const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for(std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  };
  const auto blank = [](const std::string& line) {
    return std::all_of(line.begin(), line.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
  };
  const auto after = [&](std::size_t line, const std::string& what) {
    throw Invalid_input(shown + ":" + std::to_string(line + 1) + ": content after " + what);
  };
  if(e == "ts") {
    bytes.erase(std::remove(bytes.begin(), bytes.end(), '\r'), bytes.end());
    const std::vector<std::string> lines = split(bytes);
    std::size_t last_end = lines.size();   // the line of the last surface's END (CGAL reads every surface)
    for(std::size_t i = 0; i < lines.size(); ++i) {
      std::string word;
      if((std::istringstream(lines[i]) >> word) && word == "END") last_end = i;
    }
    for(std::size_t j = last_end + 1; j < lines.size(); ++j)
      if(!blank(lines[j])) after(j, "the last surface's END");
    // CGAL's reader numbers the vertices in the order they come, from the first one's id: ids
    // out of that order would join triangles to the wrong vertices, silently.
    long long expected = 0;
    bool first = true;
    for(std::size_t i = 0; i < lines.size(); ++i) {
      std::istringstream words(lines[i]);
      std::string word;
      long long id = 0;
      if(!(words >> word)) continue;
      if(word == "ATOM" || word == "PATOM")
        throw Invalid_input(shown + ":" + std::to_string(i + 1) + ": " + word + " (a vertex repeated by id) is not supported");
      if(word == "TRGL") {   // CGAL's reader takes the first three indices and drops the others
        std::size_t indices = 0;
        for(std::string index; words >> index;) ++indices;
        if(indices != 3)
          throw Invalid_input(shown + ":" + std::to_string(i + 1) + ": TRGL with " + std::to_string(indices) +
                              " indices (a triangle has 3)");
        continue;
      }
      if((word != "VRTX" && word != "PVRTX") || !(words >> id)) continue;
      if(!first && id != expected)
        throw Invalid_input(shown + ":" + std::to_string(i + 1) + ": vertex id " + std::to_string(id) + " where " +
                            std::to_string(expected) + " was expected (the ids must follow each other, as they are numbered in order)");
      first = false;
      expected = id + 1;
    }
  } else if(e == "ply") {
    check_PLY(bytes, shown);
  } else if(e == "stl") {
    const auto word = [&](std::size_t at) {   // little-endian, as STL stores it
      std::uint32_t w = 0;
      for(std::size_t k = 4; k-- > 0;) w = (w << 8) | static_cast<unsigned char>(bytes[at + k]);
      return w;
    };
    if(bytes.size() >= 84 && bytes.size() == 84 + 50 * std::size_t(word(80))) {   // binary
      for(std::size_t f = 0; 84 + 50 * f < bytes.size(); ++f)
        for(std::size_t k = 0; k < 9; ++k) {   // after the normal's three floats
          const std::uint32_t w = word(84 + 50 * f + 12 + 4 * k);
          float x;
          std::memcpy(&x, &w, sizeof x);
          if(!std::isfinite(x)) throw Invalid_input(shown + ": facet " + std::to_string(f) + " has a non-finite coordinate");
        }
      return;
    }
    // Not a binary STL of the facets its header announces: ASCII, whose reader stops at the first
    // endsolid (CGAL's binary one, tried first, would take the announced facets of a longer file).
    const std::size_t start = bytes.find_first_not_of(" \t\r\n");
    const bool text = std::none_of(bytes.begin(), bytes.end(), [](char c) { return c == '\0'; });
    // Keywords in capitals (SOLID, FACET NORMAL, ...; some exporters write them), which CGAL's
    // reader does not know: the whole text in lower case (numbers and the ignored names included).
    if(text && start != std::string::npos && bytes.size() >= start + 5) {
      std::string keyword = bytes.substr(start, 5);
      for(char& c : keyword) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if(keyword == "solid")
        for(char& c : bytes) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if(!text || start == std::string::npos || bytes.compare(start, 5, "solid") != 0) {
      if(bytes.size() >= 84)
        throw Invalid_input(shown + ": neither ASCII STL nor binary STL: the header announces " + std::to_string(word(80)) +
                            " facets (" + std::to_string(84 + 50 * std::size_t(word(80))) + " bytes), the file has " +
                            std::to_string(bytes.size()) + " bytes");
      return;   // CGAL's reader tells
    }
    std::istringstream words(bytes);
    std::size_t facet = 0;
    for(std::string w; words >> w;) {
      if(w == "endfacet") ++facet;
      if(w == "endsolid") {
        std::string rest;
        if(std::getline(words, rest) && (words >> w)) {   // (the solid's name, then more)
          const std::size_t first = bytes.size() - static_cast<std::size_t>(words.rdbuf()->in_avail()) - w.size();
          after(static_cast<std::size_t>(std::count(bytes.begin(), bytes.begin() + std::ptrdiff_t(first), '\n')), "endsolid");
        }
        break;
      }
      if(w != "vertex") continue;
      for(int k = 0; k < 3 && (words >> w); ++k) {
        // CGAL's reader takes the number that begins a token ("1.0.0" as 1.0, then fails on ".0").
        double x = 0;
        if(!parse_number(w, x))
          throw Invalid_input(shown + ": facet " + std::to_string(facet) + " has the coordinate '" + w + "', not a number");
        if(!std::isfinite(x))
          throw Invalid_input(shown + ": facet " + std::to_string(facet) + " has a non-finite coordinate '" + w + "'");
      }
    }
  }
}

// PLY, STL and GOCAD through CGAL's polygon soup readers, which keep the file's vertex and face
// order (read_polygon_mesh may repair and reorder, and source/target pairs are matched by index),
// then the checks the package's own readers make as they parse.
// `bytes` are the file's, `e` its extension (ply, stl or ts), `shown` its name in messages.
inline Triangle_soup read_with_CGAL(std::string bytes, const std::string& shown, const std::string& e)
{
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  bool ok = false;
  try {
    check_bytes_for_CGAL(bytes, shown, e);
    // CGAL's stream readers on the bytes read above (no newline translation: either mode reads them).
    const auto read = [&](CGAL::IO::Mode mode, auto reader) {
      std::istringstream in(bytes);
      CGAL::IO::set_mode(in, mode);
      return reader(in);
    };
    if(e == "ts") {
      ok = read(CGAL::IO::ASCII, [&](std::istream& in) { return CGAL::IO::read_GOCAD(in, points, faces, CGAL::parameters::verbose(false)); });
    } else if(e == "ply") {
      ok = read(CGAL::IO::BINARY, [&](std::istream& in) { return CGAL::IO::read_PLY(in, points, faces, CGAL::parameters::verbose(false)); });
    } else {
      // As CGAL's read_STL(file name): binary first, then ASCII.
      ok = read(CGAL::IO::BINARY, [&](std::istream& in) { return CGAL::IO::read_STL(in, points, faces, CGAL::parameters::verbose(false)); });
      if(!ok) {
        points.clear();
        faces.clear();
        ok = read(CGAL::IO::ASCII, [&](std::istream& in) {
          return CGAL::IO::read_STL(in, points, faces, CGAL::parameters::use_binary_mode(false).verbose(false));
        });
      }
    }
  } catch(const Invalid_input&) {
    throw;
  } catch(const std::exception& x) {
    throw Invalid_input(shown + ": " + x.what());
  }
  std::string format = e;
  for(char& c : format) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if(!ok) throw Invalid_input(shown + ": CGAL's " + format + " reader could not read the file");
  Triangle_soup soup;
  for(std::size_t v = 0; v < points.size(); ++v) {
    const Point& p = points[v];
    if(const std::string problem = Distortion_optimization::internal::coordinate_problem(p.x(), p.y(), p.z()); !problem.empty())
      throw Invalid_input(shown + ": vertex " + std::to_string(v) + " has " + problem);
    soup.points.push_back({p.x(), p.y(), p.z()});
  }
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const std::vector<std::size_t>& face = faces[f];
    if(face.size() != 3)
      throw Invalid_input(shown + ": face " + std::to_string(f) + " is not a triangle (" + std::to_string(face.size()) + " vertices)");
    for(std::size_t i : face)
      if(i >= points.size())   // (a negative index in the file comes as a huge unsigned one)
        throw Invalid_input(shown + ": face " + std::to_string(f) + " has vertex index " +
                            std::to_string(static_cast<long long>(i)) + " out of range");
    if(face[0] == face[1] || face[1] == face[2] || face[0] == face[2])
      throw Invalid_input(shown + ": face " + std::to_string(f) + " repeats a vertex");
    soup.cells.push_back({face[0], face[1], face[2]});
  }
  return soup;
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Reads a triangle mesh by the extension of `path`: `.off` and `.obj` with the package's own
/// strict readers `read_OFF()` and `read_OBJ()`; `.ply`, `.stl` and `.ts` (GOCAD) with CGAL's
/// `CGAL::IO::read_PLY()`, `read_STL()` and `read_GOCAD()` (ASCII or binary), which keep the order
/// of vertices and faces, followed by the same checks: finite coordinates at most 1e100 in
/// magnitude, triangles only, indices in range, no face repeating a vertex. Where CGAL's readers
/// would crash, misread or take memory without bound, the bytes are checked first: a PLY header
/// (every property after its element, element counts that are numbers the file can hold,
/// vertices with scalar x, y and z, faces with 32-bit vertex_indices) and body (list counts the
/// file can hold, nothing after the announced elements), an ASCII STL's coordinates (numbers),
/// a GOCAD file's triangles (three indices each). (An STL file lists each triangle's corners:
/// CGAL's reader merges equal points into one vertex.)
/// \throws Invalid_input if the file cannot be opened, has another extension, is malformed or has
/// no triangle.
inline Triangle_soup read_triangle_soup(const std::string& path)
{
  const std::string e = internal::extension(path);
  if(e != "off" && e != "obj" && e != "ply" && e != "stl" && e != "ts")
    throw Invalid_input(internal::printable(path) + ": unsupported extension (use .off, .obj, .ply, .stl or .ts)");
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Invalid_input(internal::printable(path) + ": cannot open the file");
  Triangle_soup soup;
  if(e == "off" || e == "obj") {
    soup = e == "off" ? read_OFF(in, path) : read_OBJ(in, path);
  } else {
    std::string bytes(std::istreambuf_iterator<char>(in), {});
    if(in.bad()) throw Invalid_input(internal::printable(path) + ": cannot read the file");
    soup = internal::read_with_CGAL(std::move(bytes), internal::printable(path), e);
  }
  if(soup.cells.empty()) throw Invalid_input(internal::printable(path) + ": no triangle");
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// Writes a triangle soup as `.off` or `.obj` (by the extension of `path`), atomically; in an OBJ
/// file, with its texture coordinates and faces "f a/ta b/tb c/tc" when it has cell texture indices.
/// \throws Invalid_input for another extension, or texture coordinates to write as OFF.
inline void write_triangle_soup(const std::string& path, const Triangle_soup& soup)
{
  const std::string e = internal::extension(path);
  if(e != "off" && e != "obj") throw Invalid_input(internal::printable(path) + ": unsupported extension (use .off or .obj)");
  const bool textured = !soup.cell_texture_indices.empty();
  if(textured && e == "off") throw Invalid_input(internal::printable(path) + ": OFF has no texture coordinates (use .obj)");
  write_file_atomically(path, [&](std::ostream& out) {
    if(e == "off") {
      out << "OFF\n" << soup.points.size() << ' ' << soup.cells.size() << " 0\n";
      for(const auto& p : soup.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      for(const auto& t : soup.cells) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    } else {
      for(const auto& p : soup.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      if(textured)
        for(const auto& uv : soup.texture_coordinates) out << "vt " << uv[0] << ' ' << uv[1] << '\n';
      for(std::size_t f = 0; f < soup.cells.size(); ++f) {
        out << 'f';
        for(int i = 0; i < 3; ++i) {
          out << ' ' << soup.cells[f][i] + 1;
          if(textured) out << '/' << soup.cell_texture_indices[f][i] + 1;
        }
        out << '\n';
      }
    }
  });
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_TRIANGLE_SOUP_H
