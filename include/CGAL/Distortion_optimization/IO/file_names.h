// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// File names as the readers and writers of the package see them: the extension that chooses a
// format, and the quoting of a name in a message.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_FILE_NAMES_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_FILE_NAMES_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/IO/internal/line_reader.h>

#include <string>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// The extension of the file name `path`, in lower case and without its dot (empty if the last
/// component of `path` has no dot): what the readers and writers of this package choose a format
/// by.
inline std::string file_extension(const std::string& path) { return internal::extension(path); }

/// \ingroup PkgDistortionOptimizationIO
/// `text` with its control bytes (C0, DEL, C1) and the bytes that are not UTF-8 written as
/// `\xNN`: how the messages of this package (those of `Invalid_input`) quote file names and file
/// contents, so that printing a message cannot send escape sequences to a terminal.
inline std::string printable(const std::string& text) { return internal::printable(text); }

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_FILE_NAMES_H
