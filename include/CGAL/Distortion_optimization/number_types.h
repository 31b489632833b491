// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The numbers a measure computes with: the package's NaN and infinity, and the lanes through
// which the kernel evaluates several cells at once. A measure's invariant form (measures.h) is
// written once for a `double` (one cell) and for `lanes::Cell_lanes` (one cell per lane): with
// GCC a vector of two doubles (one SSE2 register, which every x86-64 has; wider vectors measured
// no faster, the kernel being bound by gathering vertices into lanes), elsewhere a plain double.
// Arithmetic, comparisons and ?: act lane by lane on both; the helpers below make up the rest.
//
// The 3D singular-value kernel (internal/svd.h) batches eight cells in an Eigen array instead:
// it needs square roots and clamps, which Eigen vectorizes on its arrays and GCC's vector
// extension does not, and a chain of dependent roots needs eight independent lanes to fill the
// pipeline, where the invariant forms are bound by the gather and two lanes suffice.

#ifndef CGAL_DISTORTION_OPTIMIZATION_NUMBER_TYPES_H
#define CGAL_DISTORTION_OPTIMIZATION_NUMBER_TYPES_H

#include <CGAL/license/Distortion_optimization.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationMeasures
/// The value of a normalized measure on an inverted or degenerate cell.
constexpr double infinity = std::numeric_limits<double>::infinity();
/// \ingroup PkgDistortionOptimizationMeasures
/// The value of every measure on a cell whose Jacobian has a non-finite entry.
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

/// \ingroup PkgDistortionOptimizationMeasures
/// Lane-by-lane helpers for the number types `T` of a measure's `value_of_invariants`: `double`
/// or `Cell_lanes`.
namespace lanes {

#if defined(__GNUC__) && !defined(__clang__) && !defined(__INTEL_COMPILER)
typedef double Cell_lanes __attribute__((vector_size(16)));
#else
typedef double Cell_lanes;
#endif

template <class T>
constexpr int count = static_cast<int>(sizeof(T) / sizeof(double));

template <class T>
double get(const T& x, int i)
{
  if constexpr(std::is_same_v<T, double>) return (void)i, x;
  else return x[i];
}

template <class T>
void set(T& x, int i, double value)
{
  if constexpr(std::is_same_v<T, double>) (void)i, x = value;
  else x[i] = value;
}

/// x in every lane.
template <class T>
T broadcast(double x)
{
  if constexpr(std::is_same_v<T, double>) return x;
  else return T{} + x;
}

template <class T>
bool any_nonzero(const T& x)
{
  for(int i = 0; i < count<T>; ++i)
    if(get(x, i) != 0) return true;
  return false;
}

/// The square root of each lane.
template <class T>
T sqrt(const T& x)
{
  T r = x;
  for(int i = 0; i < count<T>; ++i) set(r, i, std::sqrt(get(x, i)));
  return r;
}

/// The cube root of each lane, to within about 3 units in the last place, as libm's. No SIMD
/// instruction computes one, and libm's is a noticeable share of a MIPS run: here Halley's iteration
/// y <- y (y^3 + 2x) / (2y^3 + x), whose relative error cubes at each step, runs from an
/// estimate read off the exponent bits (a third of them, within 4%: three steps reach full
/// precision), three times faster. Lanes that are zero, subnormal, negative, above a quarter of
/// the largest double (where 2x would overflow), infinite or NaN go to std::cbrt, all of them.
template <class T>
T cbrt(const T& x)
{
  bool usual = true;
  for(int i = 0; i < count<T>; ++i)
    usual = usual && get(x, i) >= std::numeric_limits<double>::min() && get(x, i) <= std::numeric_limits<double>::max() / 4;
  T y = x;
  if(!usual) {
    for(int i = 0; i < count<T>; ++i) set(y, i, std::cbrt(get(x, i)));
    return y;
  }
  for(int i = 0; i < count<T>; ++i) {
    const double xi = get(x, i);
    std::uint64_t bits;
    std::memcpy(&bits, &xi, sizeof bits);
    bits = bits / 3 + 0x2A9F7893782DA1CEull; // the bias, a third of it off, corrected for the mantissa
    double yi;
    std::memcpy(&yi, &bits, sizeof yi);
    set(y, i, yi);
  }
  for(int k = 0; k < 3; ++k) {
    const T y3 = y * y * y;
    y = y * ((y3 + 2. * x) / (2. * y3 + x)); // the quotient first: y (y^3 + 2x) overflows for large x
  }
  return y;
}

} // namespace lanes

/// \ingroup PkgDistortionOptimizationMeasures
/// The largest `k` for which a map in dimension `n` whose target is `2^k` times larger or smaller
/// than its source can be optimized in double precision: the measures' second derivatives reach
/// products of 3n singular values of the Jacobian (the volume measure's 1 / det^3), each about that
/// ratio, which must stay within \f$ 2^{\pm 900} \f$ (a margin for the sums that hold them; the
/// volume measure in 3D lost progress at 2^111). 150 for triangles, 100 for tetrahedra; the
/// functions that evaluate a map throw `Invalid_input` beyond.
template <int n>
constexpr int largest_size_ratio_exponent = 900 / (3 * n);

namespace internal {

// The power of two that scales `largest` into [1, 2) (exactly, as any power of two); 1 where
// `largest` is 0 or not finite. For whatever multiplies several lengths at any size: maps,
// sliding surfaces, the shapes of cells, the meshing of a surface. At most 2^1023, the largest
// power of two a double holds: a subnormal `largest` (below 2^-1022) is scaled to below 1.
inline double unit_scale(double largest)
{
  return largest > 0 && std::isfinite(largest) ? std::ldexp(1., (std::min)(-std::ilogb(largest), 1023)) : 1.;
}

// The cube root of x > 0 taken on x scaled by a power of 8 into [1, 8): libm's cbrt is not
// correctly rounded, and cbrt(8 x) may differ from 2 cbrt(x) in the last place; this one gives
// the same digits for x and 8^k x, so that a mesh scaled by a power of two has the same ideal
// cells and the same untangling barrier, scaled, and the same optimization (with the boundary
// sliding, the last places of the start decided the result's fifth digit).
inline double cbrt_by_octaves(double x)
{
  if(!(x > 0) || !std::isfinite(x)) return std::cbrt(x);
  const int e = std::ilogb(x), k = (e >= 0 ? e : e - 2) / 3;   // floor(e / 3)
  return std::ldexp(std::cbrt(std::ldexp(x, -3 * k)), k);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_NUMBER_TYPES_H
