// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The atomic writer every IO header uses, and which programs may use for their own files (the
// command-line tool writes its JSON report with it).

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H

#include <CGAL/Distortion_optimization/errors.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <ostream>
#include <string>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// Writes a file whole or not at all: `write(stream)` fills a temporary file beside `path`, which
/// is renamed to `path` only when everything was written.
/// \throws Invalid_input if the file cannot be written (the temporary file is removed).
inline void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if(!out) throw Invalid_input(path + ": cannot write (is the folder writable?)");
    out.precision(17);
    write(out);
    out.flush();
    if(!out) {
      out.close();
      std::remove(temporary.c_str());
      throw Invalid_input(path + ": write error");
    }
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw Invalid_input(path + ": cannot replace the file");
  }
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_WRITE_FILE_ATOMICALLY_H
