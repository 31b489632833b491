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

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Reads an OFF file of triangles ("OFF", counts, vertex lines "x y z [...]", face lines
/// "3 i j k [...]"). `name` is used in error messages.
/// \throws Invalid_input naming the line for a missing header or count, a truncated file, a token
/// that is not a number, a non-finite coordinate, a face that is not a triangle, or an index out
/// of range.
inline Triangle_soup read_OFF(std::istream& in, const std::string& name = "OFF input")
{
  internal::Line_reader reader(in, name);
  std::vector<std::string> t;
  if(!reader.next(t)) reader.fail("empty file");
  std::size_t first = 0;   // where the counts start: "OFF nv nf ne", or "OFF" then "nv nf ne"
  if(t[0] == "OFF") {
    if(t.size() >= 3) first = 1;
    else if(!reader.next(t)) reader.fail("missing vertex and face counts");
  } else if(t[0].size() > 3 && t[0].compare(t[0].size() - 3, 3, "OFF") == 0) {
    reader.fail("only plain OFF is supported, not '" + t[0] + "'");
  }
  if(t.size() < first + 2) reader.fail("missing vertex and face counts");
  const long long nv = reader.integer(t[first]), nf = reader.integer(t[first + 1]);
  if(nv < 0 || nf < 0) reader.fail("negative counts");

  Triangle_soup soup;
  soup.points.reserve(static_cast<std::size_t>(std::min<long long>(nv, 1 << 24)));
  for(long long v = 0; v < nv; ++v) {
    if(!reader.next(t)) reader.fail("truncated: " + std::to_string(nv) + " vertices announced, " + std::to_string(v) + " found");
    if(t.size() < 3) reader.fail("vertex " + std::to_string(v) + " has fewer than 3 coordinates");
    soup.points.push_back({reader.coordinate(t[0]), reader.coordinate(t[1]), reader.coordinate(t[2])});
  }
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
    internal::check_triangle(reader, tri, static_cast<std::size_t>(f));
    soup.cells.push_back(tri);
  }
  return soup;
}

/// \ingroup PkgDistortionOptimizationIO
/// Reads the vertices ("v x y z") and faces ("f a b c", with a/b/c possibly "i/t/n", 1-based or
/// negative relative indices) of an OBJ file; other statements are ignored.
/// \throws Invalid_input naming the line, as `read_OFF()`.
inline Triangle_soup read_OBJ(std::istream& in, const std::string& name = "OBJ input")
{
  internal::Line_reader reader(in, name);
  std::vector<std::string> t;
  Triangle_soup soup;
  while(reader.next(t)) {
    if(t[0] == "v") {
      if(t.size() < 4) reader.fail("vertex with fewer than 3 coordinates");
      soup.points.push_back({reader.coordinate(t[1]), reader.coordinate(t[2]), reader.coordinate(t[3])});
    } else if(t[0] == "f") {
      const std::size_t f = soup.cells.size();
      if(t.size() != 4) reader.fail("face " + std::to_string(f) + " is not a triangle (" + std::to_string(t.size() - 1) + " vertices)");
      std::array<std::size_t, 3> tri;
      for(int i = 0; i < 3; ++i) {
        const std::string ref = t[1 + i].substr(0, t[1 + i].find('/'));
        long long index = reader.integer(ref);
        const long long count = static_cast<long long>(soup.points.size());
        index = index < 0 ? count + index : index - 1;
        if(index < 0 || index >= count) reader.fail("face " + std::to_string(f) + " has vertex index " + ref + " out of range");
        tri[i] = static_cast<std::size_t>(index);
      }
      internal::check_triangle(reader, tri, f);
      soup.cells.push_back(tri);
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
  if(e != "off" && e != "obj") throw Invalid_input(path + ": unsupported extension (use .off or .obj)");
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Invalid_input(path + ": cannot open the file");
  Triangle_soup soup = e == "off" ? read_OFF(in, path) : read_OBJ(in, path);
  if(soup.cells.empty()) throw Invalid_input(path + ": no triangle");
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
