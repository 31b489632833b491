// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The measure whose projected Newton steps a measure takes (global_step/newton_direction.h).

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_NEWTON_MODEL_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_NEWTON_MODEL_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/measures.h>

#include <optional>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// Every built-in measure has a Hessian, but the maxima among them (the dilatations K and C, the
// condition number, the volume distortion) are not smooth where the terms they compare cross, at
// their minimum above all: there their projected Hessian is a poor model (flip modes grow without
// bound, V's is singular along every move that keeps areas), and by default their global steps
// are the reweighted Laplacian's, as measured (benchmark/Distortion_optimization/NOTES.md, "Newton
// models"); Global_solver::PROJECTED_NEWTON asks for their own steps all the same.
//
// On a tetrahedral mesh where no vertex is fixed, K, the condition number and C take the steps of
// a smooth model, in the spirit of the proxies of SLIM (Rabinovich et al. 2017): MIPS for K and
// the condition number, symmetric Dirichlet for C; the line search decides on the measure itself.
// With nothing fixed the model has the same minimizers (the source's similarities, its rigid
// motions). With a boundary sliding on a surface they differ: the model's Hessian is then only the
// metric of the measure's own gradient, a proxy as SLIM's reweighted Laplacian is, so that each
// step descends on the measure, and the steps alternate with sweeps (minimize.h). A proxy's steps
// are held short by the measure's kinks, not by its metric: its Hessian, two thirds of a step's
// cost, is assembled every third step only, and each step starts from twice the last accepted
// length, as the Laplacian's. With fixed vertices the model's steps do not lead, and on a
// surface's parametrization no map has K = 1.
//
// `type` is the model's type and `of(measure)` the model, empty where the measure is its own;
// `own_steps_lead(measure)`: whether the measure's own Newton steps are taken by default where
// no model's are.
template <class Measure, bool lead>
struct Own_newton_steps
{
  using type = Measure;
  static std::optional<type> of(const Measure&) { return std::nullopt; }
  static bool own_steps_lead(const Measure&) { return lead; }
};

template <class Measure> struct Newton_model : Own_newton_steps<Measure, true> {};

template <class Measure, class Model>
struct Smooth_newton_model
{
  using type = Model;
  static std::optional<type> of(const Measure&) { return Model(); }
  static bool own_steps_lead(const Measure&) { return false; }
};

template <> struct Newton_model<Conformal_dilatation> : Smooth_newton_model<Conformal_dilatation, MIPS> {};
template <> struct Newton_model<Condition_number> : Smooth_newton_model<Condition_number, MIPS> {};
template <> struct Newton_model<Isometric_dilatation> : Smooth_newton_model<Isometric_dilatation, Symmetric_dirichlet> {};
template <> struct Newton_model<Volume_distortion> : Own_newton_steps<Volume_distortion, false> {};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_NEWTON_MODEL_H
