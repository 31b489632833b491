// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_DISTORTION_OPTIMIZATION_ERRORS_H
#define CGAL_DISTORTION_OPTIMIZATION_ERRORS_H

#include <CGAL/license/Distortion_optimization.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
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
/// boundary already crosses itself, or with a piece of the mesh inside another: the guard cannot
/// keep what the start does not have (a caller may then run without it).
class Crossing_start_boundary : public Invalid_input
{
public:
  explicit Crossing_start_boundary(const std::string& what) : Invalid_input(what) {}
};

/// \ingroup PkgDistortionOptimizationRef
/// The `Invalid_input` thrown by `radial_map()` and `star_shaped_to_unit_ball()` when their centre
/// is not strictly inside the domain (exact predicates).
class Center_outside_domain : public Invalid_input
{
public:
  explicit Center_outside_domain(const std::string& what) : Invalid_input(what) {}
};

/// \ingroup PkgDistortionOptimizationRef
/// The `Invalid_input` thrown by `star_shaped_to_unit_ball()` when a boundary facet of the domain
/// faces its centre: the domain is not star-shaped about it.
class Domain_not_star_shaped : public Invalid_input
{
public:
  explicit Domain_not_star_shaped(const std::string& what) : Invalid_input(what) {}
};

/// \ingroup PkgDistortionOptimizationRef
/// The `Invalid_input` thrown by untangling (`untangle()`, or `minimize_distortion()` with
/// `untangle_first`) when an inverted or flat cell has only constrained vertices: no map with
/// these constraints is injective. `cell()` is its index among the cells of the input.
class Unmovable_inverted_cell : public Invalid_input
{
public:
  Unmovable_inverted_cell(const std::string& what, std::size_t cell) : Invalid_input(what), cell_(cell) {}

  /// The index of the cell (in the order of the mesh's cells, as in the message).
  std::size_t cell() const { return cell_; }

private:
  std::size_t cell_;
};

namespace internal {

// A number in a message, as printf's %g writes it (std::to_string writes 4.9e-324 as 0.000000).
inline std::string shown_number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The largest magnitude of a coordinate that the package takes: products of three coordinates
// (volumes, orientation determinants, squared areas of scaled cells) must stay finite in double
// precision, which a coordinate near 1e103 already breaks.
constexpr double largest_coordinate = 1e100;

// Why `x` is not a coordinate the package takes ("a non-finite coordinate", "a coordinate of
// magnitude beyond 1e100 (...)"), or empty if it is one.
inline std::string coordinate_problem(double x)
{
  if(!std::isfinite(x)) return "a non-finite coordinate";
  if(std::abs(x) <= largest_coordinate) return {};
  return "a coordinate of magnitude beyond 1e100 (" + shown_number(x) + ")";
}

// The problem of the first of a point's coordinates that has one, or empty.
inline std::string coordinate_problem(double x, double y, double z)
{
  std::string problem = coordinate_problem(x);
  if(problem.empty()) problem = coordinate_problem(y);
  if(problem.empty()) problem = coordinate_problem(z);
  return problem;
}

} // namespace internal

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_ERRORS_H
