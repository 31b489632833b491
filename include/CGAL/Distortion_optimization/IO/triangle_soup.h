// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Strict readers and atomic writers of triangle meshes in OFF and OBJ, keeping vertex and face
// order exactly as in the file (source/target pairs are matched by index). Anything a reader does
// not understand is an error naming the file and line, never a silent guess.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_TRIANGLE_SOUP_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_TRIANGLE_SOUP_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>
#include <CGAL/Distortion_optimization/IO/simplex_soup.h>
#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>

#include <array>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <istream>
#include <iterator>
#include <limits>
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

// The vertex index of an OBJ face reference "i", "i/t", "i//n" or "i/t/n" (texture and normal
// indices checked to be integers, not kept).
inline long long obj_vertex_reference(const Line_reader& reader, const std::string& ref)
{
  std::size_t begin = 0;
  long long vertex = 0;
  for(int part = 0; part < 3; ++part) {
    const std::size_t slash = ref.find('/', begin);
    const std::string value = ref.substr(begin, slash == std::string::npos ? std::string::npos : slash - begin);
    if(part == 0) vertex = reader.integer(value);
    else if(!value.empty() || slash == std::string::npos) reader.integer(value); // "i/" is malformed, "i//n" is not
    if(slash == std::string::npos) return vertex;
    begin = slash + 1;
  }
  reader.fail("face vertex '" + ref + "' has more than three parts");
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Reads an OFF file of triangles ("OFF" and the three counts "nv nf ne" on its line or the next,
/// vertex lines "x y z [...]", face lines "3 i j k [...]", the optional values being numbers such
/// as colors). A UTF-8 byte order mark is skipped. `name` is used in error messages.
/// \throws Invalid_input naming the line for a missing header or count, a count line without
/// exactly three counts, a line longer than 1 MiB, a truncated file, a token that is not a number
/// (a NUL byte or other garbage in it included), a non-finite coordinate, a face that is not a
/// triangle, an index out of range, or anything after the announced faces.
inline Triangle_soup read_OFF(std::istream& in, const std::string& name = "OFF input")
{
  internal::Line_reader reader(in, name);
  std::vector<std::string> t;
  if(!reader.next(t)) reader.fail("empty file");
  std::size_t first = 0;   // where the counts start: "OFF nv nf ne", or "OFF" then "nv nf ne"
  if(t[0] == "OFF") {
    if(t.size() > 1) first = 1;
    else if(!reader.next(t)) reader.fail("missing vertex and face counts");
  } else if(t[0].size() > 3 && t[0].compare(t[0].size() - 3, 3, "OFF") == 0) {
    reader.fail("only plain OFF is supported, not '" + t[0] + "'");
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
/// Reads the vertices ("v x y z [...]", the optional values being numbers such as w or a color)
/// and faces ("f a b c", with a/b/c possibly "i/t/n", 1-based or negative relative indices) of an
/// OBJ file; the other statements of the format are skipped. A UTF-8 byte order mark is skipped.
/// \throws Invalid_input naming the line, as `read_OFF()`, and for a line that is not an OBJ
/// statement.
inline Triangle_soup read_OBJ(std::istream& in, const std::string& name = "OBJ input")
{
  internal::Line_reader reader(in, name);
  std::vector<std::string> t;
  Triangle_soup soup;
  while(reader.next(t)) {
    if(t[0] == "v") {
      if(t.size() < 4) reader.fail("vertex with fewer than 3 coordinates");
      soup.points.push_back({reader.coordinate(t[1]), reader.coordinate(t[2]), reader.coordinate(t[3])});
      reader.check_numbers(t, 4);
    } else if(t[0] == "f") {
      const std::size_t f = soup.cells.size();
      if(t.size() != 4) reader.fail("face " + std::to_string(f) + " is not a triangle (" + std::to_string(t.size() - 1) + " vertices)");
      std::array<std::size_t, 3> tri;
      for(int i = 0; i < 3; ++i) {
        long long index = internal::obj_vertex_reference(reader, t[1 + i]);
        const long long count = static_cast<long long>(soup.points.size());
        index = index < 0 ? count + index : index - 1;
        if(index < 0 || index >= count) reader.fail("face " + std::to_string(f) + " has vertex index " + t[1 + i] + " out of range");
        tri[i] = static_cast<std::size_t>(index);
      }
      internal::check_triangle(reader, tri, f);
      soup.cells.push_back(tri);
    } else if(!internal::is_obj_statement(t[0])) {
      reader.fail("'" + t[0] + "' is not an OBJ statement");
    }
  }
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads an `.off` or `.obj` file (by its extension).
/// \throws Invalid_input if the file cannot be opened, has another extension, or is malformed.
inline Triangle_soup read_triangle_soup(const std::string& path)
{
  const std::string e = internal::extension(path);
  if(e != "off" && e != "obj") throw Invalid_input(internal::printable(path) + ": unsupported extension (use .off or .obj)");
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Invalid_input(internal::printable(path) + ": cannot open the file");
  Triangle_soup soup = e == "off" ? read_OFF(in, path) : read_OBJ(in, path);
  if(soup.cells.empty()) throw Invalid_input(internal::printable(path) + ": no triangle");
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// Writes a triangle soup as `.off` or `.obj` (by the extension of `path`), atomically.
inline void write_triangle_soup(const std::string& path, const Triangle_soup& soup)
{
  const std::string e = internal::extension(path);
  if(e != "off" && e != "obj") throw Invalid_input(path + ": unsupported extension (use .off or .obj)");
  write_file_atomically(path, [&](std::ostream& out) {
    if(e == "off") {
      out << "OFF\n" << soup.points.size() << ' ' << soup.cells.size() << " 0\n";
      for(const auto& p : soup.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      for(const auto& t : soup.cells) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    } else {
      for(const auto& p : soup.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      for(const auto& t : soup.cells) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
  });
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_TRIANGLE_SOUP_H
