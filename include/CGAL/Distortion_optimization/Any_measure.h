// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A distortion measure whose type does not say which: the measure chosen at run time.

#ifndef CGAL_DISTORTION_OPTIMIZATION_ANY_MEASURE_H
#define CGAL_DISTORTION_OPTIMIZATION_ANY_MEASURE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/measure_kernel.h>
#include <CGAL/Distortion_optimization/internal/newton_model.h>

#include <memory>
#include <optional>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Distortion_optimization {

namespace internal {

// What an Any_measure holds: the measure, its kernels in 2D and 3D, and its Newton model.
class Any_measure_model
{
public:
  virtual ~Any_measure_model() = default;
  virtual std::string name() const = 0;
  virtual bool is_normalized() const = 0;
  virtual const Measure_kernel<2>& kernel_2() const = 0;
  virtual const Measure_kernel<3>& kernel_3() const = 0;
  // The smooth measure whose Newton steps this one takes (newton_model.h); null: its own.
  std::shared_ptr<const Any_measure_model> newton_model;
  // Whether its own Newton steps are taken by default where no model's are (newton_model.h).
  bool own_newton_steps_lead = true;
};

// The kernel of `Measure` in dimension n: each function the measure's own.
template <int n, class Measure>
class Measure_kernel_of final : public Measure_kernel<n>
{
public:
  explicit Measure_kernel_of(const Measure& measure) : m_(measure) {}
  bool is_symmetric() const override { return m_.template is_symmetric<n>(); }
  bool has_hessian() const override { return measures_internal::has_hessian<n>(m_); }
  bool has_laplacian_weight() const override { return measures_internal::has_laplacian_weight<n>(m_); }
  double value(const Singular_values<n>& s) const override { return m_.template value<n>(s); }
  Singular_values<n> gradient(const Singular_values<n>& s) const override { return m_.template gradient<n>(s); }
  Singular_values_hessian<n> hessian(const Singular_values<n>& s) const override
  {
    if constexpr(measures_internal::Has_hessian<Measure, n>::value) return m_.template hessian<n>(s);
    else return Singular_values_hessian<n>::Constant(not_a_number);
  }
  double laplacian_weight(const Singular_values<n>& s) const override { return measures_internal::laplacian_weight<n>(m_, s); }
  void cell_distortions(const Simplicial_map<n>& map, std::size_t count, const std::uint32_t* cells, double* values,
                        std::array<Vector<n>, n + 1>* vertex_gradients, Vector<n>* sigma) const override
  {
    internal::cell_distortions<n>(m_, map, count, [cells](std::size_t k) { return cells[k]; }, values, vertex_gradients, sigma);
  }
  double jacobian_distortion(const Matrix<n>& J, Matrix<n>* dJ, Vector<n>* sigma) const override
  {
    return dJ ? internal::jacobian_distortion<n>(m_, J, *dJ, sigma) : internal::jacobian_distortion<n>(m_, J);
  }

private:
  const Measure& m_;
};

template <class Measure>
class Any_measure_model_of final : public Any_measure_model
{
public:
  explicit Any_measure_model_of(const Measure& measure) : measure_(measure), kernel_2_(measure_), kernel_3_(measure_)
  {
    own_newton_steps_lead = Newton_model<Measure>::own_steps_lead(measure_);
    if(const auto model = Newton_model<Measure>::of(measure_))
      newton_model = std::make_shared<const Any_measure_model_of<typename Newton_model<Measure>::type>>(*model);
  }
  Any_measure_model_of(const Any_measure_model_of&) = delete;
  Any_measure_model_of& operator=(const Any_measure_model_of&) = delete;

  std::string name() const override { return measure_.name(); }
  bool is_normalized() const override { return measure_.is_normalized(); }
  const Measure_kernel<2>& kernel_2() const override { return kernel_2_; }
  const Measure_kernel<3>& kernel_3() const override { return kernel_3_; }

private:
  const Measure measure_;
  const Measure_kernel_of<2, Measure> kernel_2_;
  const Measure_kernel_of<3, Measure> kernel_3_;
};

} // namespace internal

/// \ingroup PkgDistortionOptimizationMeasures
/// Any distortion measure, chosen at run time (`measure_from_name()`, a configuration): the
/// functions that take a measure are compiled once for `Any_measure` whatever the measure it
/// holds, while its evaluation per batch of cells, its derivatives and its Newton steps stay the
/// measure's own, with the same results to the last bit. Copies share the measure.
///
/// The measure held must be defined in 2D and 3D. Combine measures before holding them
/// (`Product`, `Weighted_sum` of `Any_measure`s do not see whether the measures held have a
/// Hessian).
/// \cgalModels `DistortionMeasure`
class Any_measure : public measures_internal::Erased_measure_tag
{
public:
  /// Holds a copy of `measure`, a model of `DistortionMeasure`.
  template <class Measure, class = std::enable_if_t<!std::is_base_of<Any_measure, Measure>::value>>
  Any_measure(const Measure& measure) : model_(std::make_shared<const internal::Any_measure_model_of<Measure>>(measure)) {}

  std::string name() const { return model_->name(); }
  bool is_normalized() const { return model_->is_normalized(); }
  template <int n> bool is_symmetric() const { return kernel<n>().is_symmetric(); }
  template <int n> double value(const Singular_values<n>& s) const { return kernel<n>().value(s); }
  template <int n> Singular_values<n> gradient(const Singular_values<n>& s) const { return kernel<n>().gradient(s); }
  /// NaN where the measure held has no `hessian()` (`has_hessian()`).
  template <int n> Singular_values_hessian<n> hessian(const Singular_values<n>& s) const { return kernel<n>().hessian(s); }
  /// The measure held's `laplacian_weight()`, or 1 where it has none (`has_laplacian_weight()`).
  template <int n> double laplacian_weight(const Singular_values<n>& s) const { return kernel<n>().laplacian_weight(s); }
  /// Whether the measure held has a `hessian()` in dimension `n`.
  template <int n> bool has_hessian() const { return kernel<n>().has_hessian(); }
  /// Whether the measure held has a `laplacian_weight()` in dimension `n`.
  template <int n> bool has_laplacian_weight() const { return kernel<n>().has_laplacian_weight(); }

  /// \cond SKIP_IN_MANUAL
  template <int n>
  const internal::Measure_kernel<n>& kernel() const
  {
    static_assert(n == 2 || n == 3, "a measure of triangles (2) or tetrahedra (3)");
    if constexpr(n == 2) return model_->kernel_2();
    else return model_->kernel_3();
  }
  // The smooth measure whose Newton steps this one takes (internal/newton_model.h); empty: its own.
  std::optional<Any_measure> newton_model() const
  {
    if(!model_->newton_model) return std::nullopt;
    return Any_measure(model_->newton_model);
  }
  bool own_newton_steps_lead() const { return model_->own_newton_steps_lead; }
  /// \endcond

private:
  explicit Any_measure(std::shared_ptr<const internal::Any_measure_model> model) : model_(std::move(model)) {}
  std::shared_ptr<const internal::Any_measure_model> model_;
};

namespace internal {

template <>
struct Newton_model<Any_measure>
{
  using type = Any_measure;
  static std::optional<type> of(const Any_measure& measure) { return measure.newton_model(); }
  static bool own_steps_lead(const Any_measure& measure) { return measure.own_newton_steps_lead(); }
};

} // namespace internal

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_ANY_MEASURE_H
