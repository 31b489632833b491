// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The state every step of the optimization works on, owned by minimize(): the target positions
// (in the problem's map), each cell's distortion D(J_c), whether each cell still has its source's
// orientation (exact predicate), the energy, and the one way to change them: a trial of moved
// targets, accepted and committed only if the energy decreases and no valid cell flips, and the
// boundary guard agrees. A step (local_step.h, global_step.h, ...) moves targets, asks for a
// trial, and restores its targets when the trial is refused; it never touches another step.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_OPTIMIZER_STATE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_OPTIMIZER_STATE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

template <int n, class Measure, class GeomTraits>
class Optimizer_state
{
public:
  static constexpr int dimension = n;
  using Vec = Vector<n>;
  // The sufficient-decrease constant of every line search (Armijo).
  static constexpr double armijo = 1e-4;
  // A trial must lower the energy by more than this many ulps of it, so that what is accepted
  // really decreases the energy and not only its rounding.
  static constexpr double rounding = 64 * std::numeric_limits<double>::epsilon();

  // The start's cell values and orientations are computed on the workers. Throws Invalid_input
  // where the measure cannot be evaluated on the start map (NaN, or +inf: an inverted or flat
  // cell under a normalized measure).
  // With keep_valid_cells false (untangling), a trial may flip valid cells too: only the energy
  // and the check decide.
  Optimizer_state(Optimization_problem<n>& problem, const Measure& measure, const GeomTraits& traits,
                  const Workers& workers, bool keep_valid_cells = true)
    : p_(problem), measure_(measure), traits_(traits), workers_(workers), keep_valid_(keep_valid_cells),
      keep_robust_(!measure.is_normalized()), value_(problem.map.number_of_cells()), valid_(problem.map.number_of_cells())
  {
    revalidate();
  }

  // The orientations and values, again after the targets were replaced; throws as the constructor.
  void revalidate()
  {
    workers_.for_each(valid_.size(), 1024, [&](std::size_t c) { valid_[c] = status(c); });
    refresh();
  }

  // The cell values, again after the measure changed (e.g. the untangling barrier's eps); throws
  // as the constructor.
  void refresh()
  {
    workers_.for_each_block(value_.size(), 1024, [&](std::size_t first, std::size_t size) {
      cell_distortions<n>(measure_, p_.map, size, [&](std::size_t i) { return first + i; }, &value_[first]);
    });
    for(std::size_t c = 0; c < value_.size(); ++c) {
      if(std::isnan(value_[c])) {
        const Matrix<n> J = p_.map.jacobian(c);
        throw Invalid_input("the distortion of cell " + std::to_string(c) + " is not a number " +
                            (J.allFinite() && signed_singular_values(J).allFinite()
                             ? "(the measure '" + measure_.name() + "' gives NaN for its singular values)"
                             : std::string("(its singular values overflow or underflow: is the target's size far from the source's?)")));
      }
      if(!std::isfinite(value_[c]) && valid_[c])   // (exact predicates) the value overflows
        throw Invalid_input("the distortion of cell " + std::to_string(c) + " of the start map under '" + measure_.name() +
                            "' exceeds the largest double, though the cell is not inverted: it is nearly flat, or "
                            "the measure's weights are too large");
      if(!std::isfinite(value_[c])) {
        std::string remedy = "untangle the map first";
        if constexpr(n == 2) {
          const std::int64_t closed = planar_obstruction(p_.map).closed;
          if(closed >= 0) remedy = closed_piece_message(closed);
        }
        throw Invalid_input("cell " + std::to_string(c) + " of the start map is inverted or degenerate, and the "
                            "measure '" + measure_.name() + "' is infinite there: " + remedy);
      }
    }
  }

  const Optimization_problem<n>& problem() const { return p_; }
  const Measure& measure() const { return measure_; }
  const Workers& workers() const { return workers_; }
  // The target positions: steps move them for a trial, and put them back if it is refused.
  std::vector<Vec>& targets() { return p_.map.target; }

  // D(J_c) of the current map, and whether cell c has the orientation of its source.
  double value(std::size_t c) const { return value_[c]; }
  bool is_valid(std::size_t c) const { return valid_[c] != 0; }
  // Whether trials keep every valid cell valid (the optimizer's guarantee); steps then bound their
  // moves by the first degeneracy of a valid cell.
  bool keeps_valid_cells() const { return keep_valid_; }
  void keep_valid_cells(bool keep) { keep_valid_ = keep; }
  std::size_t number_of_inverted_cells() const
  {
    std::size_t count = 0;
    for(unsigned char ok : valid_) count += !ok;
    return count;
  }

  // E = sum_c w(c) D(J_c) (eq. 25), summed with Neumaier's compensation so that its rounding error
  // stays near one ulp whatever the number of cells (sweep-to-sweep decreases can be that small).
  double energy() const
  {
    double sum = 0, compensation = 0;
    for(std::size_t c = 0; c < value_.size(); ++c) {
      const double term = p_.cell_weight[c] * value_[c], t = sum + term;
      compensation += std::abs(sum) >= std::abs(term) ? (sum - t) + term : (term - t) + sum;
      sum = t;
    }
    return sum + compensation;
  }

  // omega(v) dist_w(f, v) (eq. 22): the greedy order's key.
  double vertex_distortion(std::size_t v) const
  {
    double d = 0;
    for(std::uint32_t k = p_.ring_begin[v]; k < p_.ring_begin[v + 1]; ++k) {
      const std::uint32_t c = p_.ring[k].cell;
      d += p_.incidence_weight[c] * value_[c];
    }
    return p_.omega[v] * d;
  }

  // Global injectivity with free boundary vertices (none by default). The guard must have been
  // built for the current map; vertices on its boundary must then be optimized one at a time.
  void set_boundary_guard(Boundary_guard<n>* guard) { guard_ = guard; }
  Boundary_guard<n>* boundary_guard() const { return guard_; }

  // The trial of every line search, local or global: the targets of cells cell_at(0), ...,
  // cell_at(count - 1) have just moved, the energy was e0. Accepts, and commits their values, if
  // the energy becomes at most e0 + bound (Armijo) by a decrease above the rounding error of e0
  // and no valid cell flipped or flattened (exact predicate) nor a robust one became fragile, and
  // then `check` (e.g. the boundary guard's) agrees. A local trial (on_workers false) may run
  // concurrently with others on disjoint rings; a global one spreads its cells over the workers.
  template <class CellAt, class Check = bool (*)()>
  bool accept_trial(std::size_t count, const CellAt& cell_at, double e0, double bound, bool on_workers = false,
                    const Check& check = [] { return true; })
  {
    static thread_local std::vector<double> ring_trial;
    std::vector<double>& trial = on_workers ? global_trial_ : ring_trial;
    trial.resize(count);
    if(on_workers)
      workers_.for_each_block(count, 512, [&](std::size_t first, std::size_t size) {
        cell_distortions<n>(measure_, p_.map, size, [&](std::size_t i) { return cell_at(first + i); }, &trial[first]);
      });
    else
      cell_distortions<n>(measure_, p_.map, count, cell_at, trial.data());
    const auto change = [&](std::size_t i) {
      const std::uint32_t c = cell_at(i);
      return p_.cell_weight[c] * (trial[i] - value_[c]);
    };
    const auto flipped = [&](std::size_t i) {
      const std::uint32_t c = cell_at(i);
      return valid_[c] && (is_inverted(p_.map, c, traits_) || (valid_[c] == robust && is_fragile(p_.map, c)));
    };
    const auto commit = [&](std::size_t i) {
      const std::uint32_t c = cell_at(i);
      value_[c] = trial[i];
      if(!valid_[c] || !keep_valid_) valid_[c] = status(c);
      else if(keep_robust_ && valid_[c] != robust && !is_fragile(p_.map, c)) valid_[c] = robust;
    };
    double e = e0;
    if(on_workers) e += workers_.sum(count, change);
    else for(std::size_t i = 0; i < count; ++i) e += change(i);
    if(!(e <= e0 + bound) || !(e0 - e > rounding * std::abs(e0))) return false;
    bool any_flipped = false;
    if(keep_valid_ && on_workers) any_flipped = workers_.reduce(count, false, flipped, [](bool a, bool b) { return a || b; });
    else if(keep_valid_) for(std::size_t i = 0; i < count && !any_flipped; ++i) any_flipped = flipped(i);
    if(any_flipped || !check()) return false;
    if(on_workers) workers_.for_each(count, 1024, commit);
    else for(std::size_t i = 0; i < count; ++i) commit(i);
    return true;
  }

private:
  // valid_[c]: 0 inverted or flat (exact predicate); 1 valid; `robust` valid and, under a measure
  // finite on flat cells, not fragile (is_fragile()): such a cell must stay so. A measure finite
  // there would otherwise squeeze cells to tiny areas, valid in doubles but inverted by the
  // rounding of the decimal output another program reads; under a normalized measure they cost
  // too much to get there.
  static constexpr unsigned char robust = 2;
  unsigned char status(std::size_t c) const
  {
    if(is_inverted(p_.map, c, traits_)) return 0;
    return keep_robust_ && !is_fragile(p_.map, c) ? robust : 1;
  }

  Optimization_problem<n>& p_;
  const Measure& measure_;
  GeomTraits traits_;
  const Workers& workers_;
  bool keep_valid_;
  bool keep_robust_;
  std::vector<double> value_;
  std::vector<unsigned char> valid_;
  Boundary_guard<n>* guard_ = nullptr;
  std::vector<double> global_trial_;   // cell values at a trial position of a global step
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_OPTIMIZER_STATE_H
