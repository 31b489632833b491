// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_DISTORTION_OPTIMIZATION_ERRORS_H
#define CGAL_DISTORTION_OPTIMIZATION_ERRORS_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// Thrown by every function of the package for input it cannot accept: empty or non-triangular
/// meshes, sizes that differ, non-finite coordinates, degenerate source cells, inverted cells in a
/// start map under a normalized measure, unreadable files, ... The message names the offending
/// element (vertex or cell index, file and line). compute_distortion() and minimize_distortion() leave their inputs (and the target map) unmodified
/// when they throw.
class Invalid_input : public std::invalid_argument
{
public:
  explicit Invalid_input(const std::string& what) : std::invalid_argument(what) {}
};

/// \ingroup PkgDistortionOptimizationRef
/// The `Invalid_input` thrown when `preserve_global_injectivity` is asked for a start map whose
/// boundary already crosses itself: the guard cannot keep what the start does not have (a caller
/// may then run without it).
class Crossing_start_boundary : public Invalid_input
{
public:
  explicit Crossing_start_boundary(const std::string& what) : Invalid_input(what) {}
};

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_ERRORS_H
