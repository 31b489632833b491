// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The functions of a measure in one dimension that a measure chosen at run time (Any_measure.h)
// calls through one virtual call each: the whole optimization is compiled once for such a
// measure, and only these functions once per measure. The cell kernel is called per batch of
// cells, so that its inner loop stays the measure's own.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MEASURE_KERNEL_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MEASURE_KERNEL_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <array>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n>
class Measure_kernel
{
public:
  virtual ~Measure_kernel() = default;
  virtual bool is_symmetric() const = 0;
  virtual bool has_hessian() const = 0;
  virtual bool has_laplacian_weight() const = 0;
  virtual double value(const Singular_values<n>& s) const = 0;
  virtual Singular_values<n> gradient(const Singular_values<n>& s) const = 0;
  // NaN where the measure has no Hessian.
  virtual Singular_values_hessian<n> hessian(const Singular_values<n>& s) const = 0;
  virtual double laplacian_weight(const Singular_values<n>& s) const = 0;
  // cell_distortions() on the cells cells[0 .. count).
  virtual void cell_distortions(const Simplicial_map<n>& map, std::size_t count, const std::uint32_t* cells, double* values,
                                std::array<Vector<n>, n + 1>* vertex_gradients, Vector<n>* sigma) const = 0;
  // jacobian_distortion() with dJ and sigma optional (null).
  virtual double jacobian_distortion(const Matrix<n>& J, Matrix<n>* dJ, Vector<n>* sigma) const = 0;
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MEASURE_KERNEL_H
