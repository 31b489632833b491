// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Cell_lanes: the number type of the kernel that evaluates several cells at once, one per SIMD
// lane. With GCC it is a vector of two doubles (one SSE2 register, which every x86-64 has; wider
// vectors measured no faster, the kernel being bound by gathering vertices into lanes); elsewhere
// a plain double, one cell at a time. The same formulas serve both: arithmetic, comparisons and
// ?: act lane by lane, and the few helpers below make up the rest.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LANES_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LANES_H

#include <cmath>
#include <type_traits>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

#if defined(__GNUC__) && !defined(__clang__) && !defined(__INTEL_COMPILER)
typedef double Cell_lanes __attribute__((vector_size(16)));
#else
typedef double Cell_lanes;
#endif

template <class T>
constexpr int number_of_lanes = static_cast<int>(sizeof(T) / sizeof(double));

template <class T>
double lane(const T& x, int i)
{
  if constexpr(std::is_same_v<T, double>) return (void)i, x;
  else return x[i];
}

template <class T>
void set_lane(T& x, int i, double value)
{
  if constexpr(std::is_same_v<T, double>) (void)i, x = value;
  else x[i] = value;
}

// x in every lane.
template <class T>
T broadcast(double x)
{
  if constexpr(std::is_same_v<T, double>) return x;
  else return T{} + x;
}

template <class T>
bool any_nonzero(const T& x)
{
  for(int i = 0; i < number_of_lanes<T>; ++i)
    if(lane(x, i) != 0) return true;
  return false;
}

// cbrt has no SIMD instruction: lane by lane.
template <class T>
T lanewise_cbrt(const T& x)
{
  T r = x;
  for(int i = 0; i < number_of_lanes<T>; ++i) set_lane(r, i, std::cbrt(lane(x, i)));
  return r;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_LANES_H
