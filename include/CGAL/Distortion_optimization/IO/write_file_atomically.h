// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The atomic writer every IO header uses, and which programs may use for their own files: a new
// file with a unique hidden name beside the target, renamed over it only when everything was
// written, and removed on every failure. Portable: C++17's std::filesystem and stdio only.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <locale>
#include <ostream>
#include <random>
#include <string>
#include <system_error>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// Where `write_file_atomically()` puts the bytes for `path`: the file a symbolic link names (else
/// `path` itself), with `special` set when that is a device or a pipe, which is written into
/// rather than replaced. A program that stages its outputs itself (to remove them on signals, say)
/// makes its temporary files beside it, as `write_file_atomically()` does.
/// \throws Invalid_input if `path` is a folder, a symbolic link to nothing, or a link that cannot
/// be resolved.
inline std::filesystem::path write_destination(const std::string& path, bool& special)
{
  namespace fs = std::filesystem;
  std::error_code error;
  special = false;
  const fs::file_status link = fs::symlink_status(path, error);
  if(error || !fs::exists(link)) return path;   // a new file
  const fs::file_status status = fs::status(path, error);
  if(fs::is_symlink(link) && (error || !fs::exists(status)))
    throw Invalid_input(internal::printable(path) + ": a symbolic link to nothing");
  if(fs::is_directory(status)) throw Invalid_input(internal::printable(path) + ": a folder, not a file name");
  special = !fs::is_regular_file(status);
  if(!fs::is_symlink(link) || special) return path;   // a device is written through its name
  const fs::path place = fs::canonical(path, error);
  if(error) throw Invalid_input(internal::printable(path) + ": cannot resolve the symbolic link");
  return place;
}

namespace internal {

// A new file beside `place` with a unique hidden name, created exclusively ("x": C11, C++17):
// its name, or empty if none could be made.
inline std::string unique_file_beside(const std::filesystem::path& place)
{
  static std::atomic<unsigned long long> counter(0);
  const std::string stem = (place.parent_path() / ("." + place.filename().string() + ".")).string();
  std::random_device device;
  for(int attempt = 0; attempt < 64; ++attempt) {
    const unsigned long long key = (static_cast<unsigned long long>(device()) << 20) ^ counter++;
    const std::string name = stem + std::to_string(key) + ".tmp";
    if(std::FILE* file = std::fopen(name.c_str(), "wbx")) {
      std::fclose(file);
      return name;
    }
    if(errno != EEXIST) break;
  }
  return "";
}

// Formats each double inserted into a stream as the shortest decimal that reads back to the
// same value (std::to_chars): several times faster than the 17 significant digits of printf-style
// formatting, and shorter. Stream precision and flags do not apply.
class Shortest_double_put : public std::num_put<char>
{
protected:
  iter_type do_put(iter_type out, std::ios_base&, char, double x) const override
  {
    char buffer[32];
    const char* end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
    return std::copy(static_cast<const char*>(buffer), end, out);
  }
};

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// Writes a file whole or not at all: `write(stream)` fills a new file with a unique hidden name
/// beside `path`, which is renamed to `path` only when everything was written, and removed on
/// any failure. No other file is touched. Where `path` is a symbolic link, the file it names is
/// replaced and the link kept; a device or a pipe (`/dev/null`, `/dev/stdout`) is written into,
/// never replaced. The stream writes each `double` as the shortest decimal that reads back to the
/// same value. Portable (std::filesystem); a program that wants temporary files removed on signals
/// as well stages its outputs itself (the command-line tool does).
/// \throws Invalid_input if the file cannot be written (the temporary file is removed), if `path`
/// is a folder, or a symbolic link to nothing.
inline void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  bool special = false;
  const std::filesystem::path place = write_destination(path, special);
  if(place.filename().empty()) throw Invalid_input(internal::printable(path) + ": not a file name");
  const auto fill = [&](const std::string& name) {
    std::ofstream out(name, std::ios::binary | std::ios::trunc);
    if(!out) throw Invalid_input(internal::printable(path) + ": cannot write (is the folder writable?)");
    out.imbue(std::locale(std::locale::classic(), new internal::Shortest_double_put));
    write(out);
    out.flush();
    if(!out) throw Invalid_input(internal::printable(path) + ": write error");
  };
  if(special) {   // written into at once: a device has no file to replace
    fill(place.string());
    return;
  }
  const std::string temporary = internal::unique_file_beside(place);
  if(temporary.empty()) throw Invalid_input(internal::printable(path) + ": cannot write (does the folder exist, and is it writable?)");
  try {
    fill(temporary);
  } catch(...) {
    std::remove(temporary.c_str());
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, place, error);
  if(error) {
    std::remove(temporary.c_str());
    throw Invalid_input(internal::printable(path) + ": cannot replace the file");
  }
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H
