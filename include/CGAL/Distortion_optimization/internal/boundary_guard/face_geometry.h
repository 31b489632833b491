// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What the boundary guard's parts share about a boundary face (a segment in 2D, a triangle in 3D):
// its vertices, their points in the kernel whose exact predicates the tests rest on, and its box,
// in Eigen's form for the box tree and in CGAL's for box_intersection_d.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_FACE_GEOMETRY_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_FACE_GEOMETRY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {
namespace boundary_guard {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

template <int n>
struct Face_geometry
{
  static_assert(n == 2 || n == 3, "segments of a planar triangle map or triangles of a tet map");

  using Face = std::array<std::uint32_t, n>;
  using Box = Eigen::AlignedBox<double, n>;
  using Box_d = CGAL::Box_intersection_d::Box_with_info_d<double, n, std::uint32_t>;   // box_intersection_d's

  static auto point(const Vector<n>& x) { return to_point<K>(x); }
  static auto point(std::uint32_t v, const std::vector<Vector<n>>& t) { return point(t[v]); }

  static Box face_box(const Face& f, const std::vector<Vector<n>>& target)
  {
    Box b(target[f[0]]);
    for(int i = 1; i < n; ++i) b.extend(target[f[i]]);
    return b;
  }

  static Box_d box_d(const Box& b, std::uint32_t info)
  {
    double lo[n], hi[n];
    for(int i = 0; i < n; ++i) lo[i] = b.min()[i], hi[i] = b.max()[i];
    return Box_d(lo, hi, info);
  }
};

} // namespace boundary_guard
} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_FACE_GEOMETRY_H
