// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The step bound of the global steps and the harmonic start: the exact largest fraction of a
// direction that every valid cell takes without degenerating (det(Ds + t dDs) is a quadratic in
// t in 2D, a cubic in 3D: its smallest positive root).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_STEP_BOUND_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_STEP_BOUND_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The smallest root in (0, bound] of c0 + c1 t + c2 t^2 + c3 t^3 when c0 > 0 (bound if none): the
// first t at which a cell's signed volume reaches 0. Most cells are cleared at once by a lower
// bound of the polynomial on [0, bound]; roots are bracketed between the critical points and
// refined by bisection, which is robust to the cancellations of closed formulas.
inline double first_positive_root(double c0, double c1, double c2, double c3, double bound)
{
  if(c0 + std::min(c1, 0.) * bound + std::min(c2, 0.) * bound * bound + std::min(c3, 0.) * bound * bound * bound > 0)
    return bound;
  auto p = [&](double t) { return c0 + t * (c1 + t * (c2 + t * c3)); };
  // Critical points (roots of c1 + 2 c2 t + 3 c3 t^2), then the bound.
  std::array<double, 3> stops;
  std::size_t count = 0;
  const double a = 3 * c3, b = 2 * c2, c = c1;
  if(a != 0) {
    const double disc = b * b - 4 * a * c;
    if(disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if(q != 0) stops[count++] = c / q;
      stops[count++] = q / a;
    }
  } else if(b != 0) {
    stops[count++] = -c / b;
  }
  std::sort(stops.begin(), stops.begin() + count);
  stops[count++] = bound;
  double left = 0;
  for(std::size_t i = 0; i < count; ++i) {
    const double s = std::min(stops[i], bound);
    if(!(s > left)) continue;
    if(p(s) <= 0) {
      // Bisection to 1e-12 relative: callers take a fraction of the root anyway.
      double lo = left, hi = s;
      for(int k = 0; k < 100 && hi - lo > 1e-12 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (p(mid) > 0 ? lo : hi) = mid;
      }
      return lo;   // the side where the volume is still positive
    }
    left = s;
  }
  return bound;
}

// The exact largest t <= bound such that no valid cell of `moving` degenerates at X + t D, on
// the state's workers (bound where the state may flip valid cells: untangling).
template <class State>
double largest_safe_step(const State& state, const std::vector<std::uint32_t>& moving,
                         const std::vector<Vector<State::dimension>>& direction, double bound)
{
  constexpr int n = State::dimension;
  if(!state.keeps_valid_cells()) return bound;
  const auto& map = state.problem().map;
  const auto cell_bound = [&](std::size_t i) {
    const std::uint32_t c = moving[i];
    if(!state.is_valid(c)) return bound;
    const auto& cell = map.cells[c];
    Matrix<n> A = map.target_edges(c), B;
    for(int k = 0; k < n; ++k) B.col(k) = direction[cell[k + 1]] - direction[cell[0]];
    const double sign = map.rest_sign[c];
    const Cofactor_and_determinant<n> a(A), b(B);
    const double c0 = sign * a.det, c1 = sign * (a.cofactor.array() * B.array()).sum();
    double c2, c3 = 0;
    if constexpr(n == 2) c2 = sign * b.det;
    else { c2 = sign * (b.cofactor.array() * A.array()).sum(); c3 = sign * b.det; }
    return c0 > 0 ? first_positive_root(c0, c1, c2, c3, bound) : bound;
  };
  return state.workers().reduce(moving.size(), bound, cell_bound, [](double a, double b) { return std::min(a, b); });
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_STEP_BOUND_H
