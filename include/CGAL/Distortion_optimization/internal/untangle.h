// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Untangling: from a start with inverted or flat cells to a map whose every cell has its source's
// orientation, by the method of Garanzha, Kaporin, Kudryavtseva, Protais, Ray and Sokolov,
// "Foldover-free maps in 50 lines of code" (SIGGRAPH 2021): minimize the barrier F_eps of
// measures.h (Untangling_barrier) for a decreasing eps. Their eps rule: after each round, with E
// and E_prev the energies after and before it and D- the smallest relative determinant,
// sigma = max(1 - E / E_prev, 0.1), mu = (1 - sigma) chi(D-, eps), and the new eps makes
// chi(D-, eps) = mu, i.e. eps = 2 sqrt(mu (mu - D-)) while D- < mu; so the worst cell's stand-in
// determinant shrinks by at least 10% a round, faster when the round gained much. Ours floors
// sigma at 0.5 rather than 0.1 and lets eps fall at most tenfold a round: this takes far fewer
// rounds, and a faster fall collapses folds into flat strips that no later round opens. eps starts
// at 1, or at 0.01 when the boundary slides (untangle_everywhere() says why).
//
// A cell is untangled when its orientation is its source's (exact predicate) and it is not
// numerically flat (simplicial_map.h): a cell valid by a hair would make a normalized measure
// infinite when the optimizer takes over.
//
// Each round minimizes the barrier for one eps by L-BFGS, as theirs, on the package's kernel (all
// cells' values and gradients at once, on the workers): constrained vertices never move, sliding
// ones stay on their surface, and with the boundary guard the boundary never starts crossing
// itself. The run stops as soon as every cell is valid; the regular measure takes over from there.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_UNTANGLE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_UNTANGLE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/minimize.h>
#include <CGAL/Distortion_optimization/internal/tutte_embedding.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The rounds untangle() and minimize_distortion(untangle_first) run at most by default.
constexpr std::size_t default_untangle_rounds = 1000;

// Whether cell c still needs untangling: inverted or flat (exact predicate), or numerically flat.
template <int n, class GeomTraits>
bool is_tangled(const Simplicial_map<n>& map, std::size_t c, const GeomTraits& traits)
{
  return is_inverted(map, c, traits) || is_numerically_flat(map, c);
}

// The number of cells still to untangle (is_tangled), in parallel.
template <int n, class GeomTraits>
std::size_t number_of_tangled_cells(const Simplicial_map<n>& map, const GeomTraits& traits, const Workers& workers)
{
  return workers.reduce(map.number_of_cells(), std::size_t(0), [&](std::size_t c) { return std::size_t(is_tangled(map, c, traits)); },
                        [](std::size_t a, std::size_t b) { return a + b; });
}

// The smallest det J_c of the map, in parallel.
template <int n>
double smallest_jacobian_determinant(const Simplicial_map<n>& map, const Workers& workers)
{
  return workers.reduce(map.number_of_cells(), infinity, [&](std::size_t c) { return map.jacobian_determinant(c); },
                        [](double a, double b) { return std::min(a, b); });
}

// The map's typical |det J|, to which the barrier relates determinants: the median over the cells.
// Neither the signed volume ratio (a free boundary that crosses itself may enclose almost no
// signed volume) nor the mean |det J| (a few cells stretched a hundredfold in a tangle) tells the
// scale of the untangled map as well; the mean only stands in when most cells are flat.
template <int n>
double typical_jacobian_determinant(const Simplicial_map<n>& map)
{
  std::vector<double> dets(map.number_of_cells());
  double mean = 0;
  for(std::size_t c = 0; c < dets.size(); ++c) {
    dets[c] = std::abs(map.jacobian_determinant(c));
    mean += dets[c] / dets.size();
  }
  if(dets.empty()) return 1.;
  std::nth_element(dets.begin(), dets.begin() + dets.size() / 2, dets.end());
  const double median = dets[dets.size() / 2];
  const double typical = median > 0 ? median : mean;
  return std::isfinite(typical) && typical > 0 ? typical : 1.;
}

// The barrier's energy sum_c w(c) F_eps(J_c) at the current targets and, if `gradient` is given,
// its gradient in the free vertices (n entries per vertex, 0 for constrained ones; for sliding
// vertices the part in their tangent plane), on the workers; the same whatever their number.
template <int n>
class Barrier_energy
{
public:
  Barrier_energy(const Optimization_problem<n>& problem, const Workers& workers)
    : p_(problem), workers_(workers), value_(problem.map.number_of_cells()), cell_gradient_(value_.size()) {}

  double operator()(const Untangling_barrier& barrier, Eigen::VectorXd* gradient)
  {
    const std::size_t nc = value_.size(), nv = p_.number_of_vertices();
    workers_.for_each_block(nc, 1024, [&](std::size_t first, std::size_t size) {
      cell_distortions<n>(barrier, p_.map, size, [&](std::size_t i) { return first + i; }, &value_[first],
                          gradient ? &cell_gradient_[first] : nullptr);
    });
    const double energy = workers_.sum(nc, [&](std::size_t c) { return p_.cell_weight[c] * value_[c]; });
    if(gradient) {
      gradient->resize(n * nv);
      workers_.for_each(nv, 1024, [&](std::size_t v) {
        Vector<n> g = Vector<n>::Zero();
        if(p_.is_free[v])
          for(std::uint32_t k = p_.ring_begin[v]; k < p_.ring_begin[v + 1]; ++k)
            g += p_.cell_weight[p_.ring[k].cell] * cell_gradient_[p_.ring[k].cell][p_.ring[k].local];
        if(p_.slides(v)) {
          Vector<n> normal;
          p_.slide(v, p_.map.target[v], normal);
          g -= g.dot(normal) * normal;
        }
        gradient->template segment<n>(n * v) = g;
      });
    }
    return energy;
  }

private:
  const Optimization_problem<n>& p_;
  const Workers& workers_;
  std::vector<double> value_;
  std::vector<std::array<Vector<n>, n + 1>> cell_gradient_;
};

// Minimizes the barrier for one eps by L-BFGS (Nocedal and Wright, "Numerical optimization",
// Algorithm 7.4, memory 8), as Garanzha et al. do, with a backtracking (Armijo) line search.
// Sliding vertices move in their tangent planes and are projected back onto their surface at every
// trial. With the boundary guard, a trial whose boundary would cross itself holds the vertices of
// the crossing faces where they are and is tried again, so that one part of the boundary meeting
// another does not stop the whole map. Stops when the gradient fell to 1e-3 of its start, when
// `done()` (checked after each accepted step) says so, when no step is found, when five in a row
// gain less than 1e-10 of the energy, or after `max_iterations`. `scale` carries the
// inverse-Hessian scale from round to round; when it is 0, the first step moves no vertex farther
// than `first_step`. Returns the number of steps taken.
template <int n, class Done>
std::size_t barrier_descent(Optimization_problem<n>& p, Barrier_energy<n>& energy, const Untangling_barrier& barrier,
                            Boundary_guard<n>* guard, std::size_t max_iterations, double first_step, double& scale,
                            const Done& done)
{
  constexpr int memory = 8;
  const std::size_t nv = p.number_of_vertices();
  Eigen::Map<Eigen::VectorXd> x(p.map.target.data()->data(), n * nv);
  Eigen::VectorXd g, g_new, d, x0;
  std::vector<Eigen::VectorXd> s, y;
  std::vector<double> rho;
  std::vector<std::uint32_t> crossing;
  double e = energy(barrier, &g);
  const double g_start = g.norm();
  if(!(scale > 0)) scale = first_step / std::max(g.lpNorm<Eigen::Infinity>(), 1e-300);
  constexpr double gtol = 1e-3;
  std::size_t steps = 0, stalled = 0;
  for(; steps < max_iterations && g.norm() > gtol * g_start; ++steps) {
    // The two-loop recursion: d = -H g.
    d = -g;
    std::vector<double> alpha(s.size());
    for(std::size_t i = s.size(); i-- > 0;) {
      alpha[i] = rho[i] * s[i].dot(d);
      d -= alpha[i] * y[i];
    }
    d *= scale;
    for(std::size_t i = 0; i < s.size(); ++i) d += (alpha[i] - rho[i] * y[i].dot(d)) * s[i];
    double slope = g.dot(d);
    if(!(slope < 0)) {   // a stale memory: start it again
      s.clear(), y.clear(), rho.clear();
      d = -scale * g;
      slope = g.dot(d);
    }
    x0 = x;
    bool accepted = false;
    std::size_t holds = 0;
    double e_new = e;
    for(double t = 1; !accepted && t > 1e-12; t *= 0.5) {
      x = x0 + t * d;
      if(!p.is_sliding.empty())
        for(std::size_t v = 0; v < nv; ++v)
          if(p.slides(v)) {
            Vector<n> normal;
            p.map.target[v] = p.slide(v, p.map.target[v], normal);
          }
      if(guard && !guard->is_injective(p.map.target, &crossing)) {
        // The boundary would cross itself: hold the vertices of the crossing faces where they are
        // and try the same step again (a shorter one after many holds).
        for(std::uint32_t v : crossing) d.template segment<n>(n * v).setZero();
        if(!((slope = g.dot(d)) < 0)) break;
        if(++holds <= 64) t *= 2;
        continue;
      }
      e_new = energy(barrier, &g_new);
      accepted = e_new <= e + 1e-4 * t * slope;
    }
    if(!accepted) {
      x = x0;
      break;
    }
    if(guard) guard->rebuild(p.map.target);
    Eigen::VectorXd sk = x - x0, yk = g_new - g;
    const double sy = sk.dot(yk);
    if(sy > 1e-12 * sk.norm() * yk.norm()) {
      if(s.size() == memory) s.erase(s.begin()), y.erase(y.begin()), rho.erase(rho.begin());
      scale = sy / yk.squaredNorm();
      s.push_back(std::move(sk)), y.push_back(std::move(yk)), rho.push_back(1 / sy);
    }
    stalled = e - e_new > 1e-10 * std::abs(e) ? 0 : stalled + 1;
    e = e_new;
    g.swap(g_new);
    if(stalled >= 5) break;
    if(done()) {
      ++steps;
      break;
    }
  }
  return steps;
}

// Throws Unmovable_inverted_cell if an inverted or flat cell has only constrained vertices: no untangling
// moves it. Checked on the whole map, so that the message names the cell by its index there.
template <int n, class GeomTraits>
void check_tangled_cells_can_move(const Optimization_problem<n>& problem, const GeomTraits& traits)
{
  for(std::size_t c = 0; c < problem.map.number_of_cells(); ++c) {
    bool moves = false;
    for(auto v : problem.map.cells[c]) moves = moves || problem.is_free[v];
    if(!moves && is_tangled(problem.map, c, traits))
      throw Unmovable_inverted_cell("cell " + std::to_string(c) + " is inverted or flat and all its vertices are "
                                    "constrained: no map with these constraints is injective", c);
  }
}

// Untangles problem.map in place (the whole map; untangle() below first tries the tangle's
// surroundings). options.iterations bounds the rounds (values of eps); a round minimizes the
// barrier for its eps (barrier_descent, at most 1000 steps, 200 in a part); the visitor is called after each
// round with the round, the mean barrier energy and the number of cells still inverted, and may
// stop the run there. With throw_on_failure (a whole map, not a part), throws Invalid_input, with
// the map unchanged, when some inverted cell has only constrained vertices, or when the rounds end
// with inverted cells (no injective map may exist with these constraints).
template <int n, class GeomTraits>
Untangle_result untangle_everywhere(Optimization_problem<n>& problem, const GeomTraits& traits, Options options,
                                    bool throw_on_failure = true)
{
  const auto start = std::chrono::steady_clock::now();
  const Workers workers(options.threads);
  const std::size_t nc = problem.map.number_of_cells();
  const auto count = [&](const auto& is_counted) {
    return workers.reduce(nc, std::size_t(0), [&](std::size_t c) { return std::size_t(is_counted(c)); },
                          [](std::size_t a, std::size_t b) { return a + b; });
  };
  const auto tangled = [&] { return number_of_tangled_cells(problem.map, traits, workers); };
  Untangle_result report;
  report.inverted_before = report.inverted_after = tangled();
  if(report.inverted_before == 0) return report;
  if(throw_on_failure) check_tangled_cells_can_move(problem, traits);
  const bool constrained = std::find(problem.is_free.begin(), problem.is_free.end(), 0) != problem.is_free.end();
  const bool slides = std::any_of(problem.is_sliding.begin(), problem.is_sliding.end(), [](unsigned char s) { return s != 0; });
  // A mirror image: nothing holds the map (no vertex constrained, none sliding) and its cells'
  // signed volumes sum below zero, so that the descent would have to turn it inside out (over a
  // thousand rounds from some sizes). Its reflection is the same map the right way round.
  if(!constrained && !slides) {
    double signed_volume = 0;
    for(std::size_t c = 0; c < nc; ++c) signed_volume += problem.map.jacobian_determinant(c) * problem.map.rest_volume[c];
    if(signed_volume < 0) {
      for(Vector<n>& t : problem.map.target) t[n - 1] = -t[n - 1];
      if((report.inverted_after = tangled()) == 0) {
        report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return report;
      }
    }
  }
  std::unique_ptr<Boundary_guard<n>> guard = make_boundary_guard(problem, options);
  Untangling_barrier barrier;
  barrier.reference_det = typical_jacobian_determinant(problem.map);
  // A boundary that slides can shrink along its surface, and at eps = 1 the barrier prefers a
  // collapsed cell (F = 2 theta / eps = 1 in 3D) to an undistorted one (about 2.15): the first
  // round then flattens much of the map, and no later round reopens it. From eps = 0.01 such maps
  // untangle in fewer rounds. A fixed or free boundary keeps eps = 1, which takes fewer rounds
  // there.
  if(slides) barrier.epsilon = 0.01;
  Barrier_energy<n> energy(problem, workers);
  // The first step moves a vertex by a tenth of a typical edge.
  double volume = 0;
  for(double v : problem.map.rest_volume) volume += v;
  // (Roots that give the same digits for a map scaled by a power of two, scaled: libm's pow and cbrt
  // do not, and a map's untangling then depended on its size in the last places.)
  const double size = volume / nc * barrier.reference_det, edge = n == 2 ? std::sqrt(size) : cbrt_by_octaves(size);
  const double floor = n == 2 ? 1e-9 : 1e-10;
  double scale = 0;
  const std::vector<Vector<n>> start_targets = problem.map.target;
  std::vector<Vector<n>> best_targets = start_targets;
  std::size_t fewest = report.inverted_before, rounds_without_progress = 0;
  std::size_t lowest = std::numeric_limits<std::size_t>::max(), rounds_since_low = 0;
  const double start_epsilon = barrier.epsilon;
  std::size_t rounds_since_fewest = 0, restarts = 0;
  // Checked after every step: the exact count only once no cell is numerically flat any more.
  const auto untangled = [&] { return count([&](std::size_t c) { return is_numerically_flat(problem.map, c); }) == 0 && tangled() == 0; };
  // A part (throw_on_failure false) gains more from lowering eps often than from converging each
  // round, hence 200 steps a round. The whole map keeps 1000: with 200, large tangles stay
  // inverted.
  const std::size_t steps_per_round = throw_on_failure ? 1000 : 200;
  while(report.iterations < options.iterations) {
    ++report.iterations;
    const double before = energy(barrier, nullptr);
    barrier_descent(problem, energy, barrier, guard.get(), steps_per_round, 0.1 * edge, scale, untangled);
    const double after = energy(barrier, nullptr);
    const std::size_t inverted_before = report.inverted_after;
    report.inverted_after = tangled();
    const double weight = problem.total_weight > 0 ? problem.total_weight : 1.;
    if(options.visitor && !options.visitor(report.iterations, after / weight, report.inverted_after)) {
      report.stopped_by_visitor = true;
      break;
    }
    if(report.inverted_after == 0) break;
    // Rounds since this run's count last fell a tenth below its low (the first rounds may tangle
    // more cells than the start had, on their way to fewer): a part that only creeps gives way.
    if(report.inverted_after < 0.9 * lowest) {
      lowest = report.inverted_after;
      rounds_since_low = 0;
    } else {
      ++rounds_since_low;
    }
    if(report.inverted_after < fewest) {
      fewest = report.inverted_after;
      best_targets = problem.map.target;
      rounds_since_fewest = 0;
    } else {
      ++rounds_since_fewest;
    }
    // Garanzha et al.'s rule, on determinants relative to the typical one.
    const double worst = smallest_jacobian_determinant(problem.map, workers) / barrier.reference_det;
    const double e = barrier.epsilon, root = std::sqrt(e * e + worst * worst);
    const double chi = Untangling_barrier::regularized_determinant(worst, e * e, root);
    const double sigma = std::max(before > 0 ? 1 - after / before : 0., 0.5), mu = (1 - sigma) * chi;
    barrier.epsilon = std::max({floor, 0.1 * e, worst < mu ? 2 * std::sqrt(mu * (mu - worst)) : floor});
    // A tight barrier can lock a tangle in: its cells' rings are valid and the barrier walls them
    // in, so that a cell whose vertices are all free can stay inverted while eps falls to its
    // floor. Loosened back to its start value, from the map as it is, the barrier lets the ring
    // give way: up to 3 times, once the count has made no new low for 5 rounds and eps is below a
    // thousandth of its start.
    if(rounds_since_fewest >= 5 && barrier.epsilon < 1e-3 * start_epsilon && restarts < 3) {
      barrier.epsilon = start_epsilon;
      rounds_since_fewest = 0;
      ++restarts;
    }
    // Stuck: eps at its floor and no cell untangled for a while.
    rounds_without_progress = barrier.epsilon <= floor && report.inverted_after >= inverted_before ? rounds_without_progress + 1 : 0;
    if(rounds_without_progress >= 20) break;
    // A part (throw_on_failure false) may have no injective map within its fixed surroundings: it
    // gives way to a wider one once three rounds brought no new low.
    if(!throw_on_failure && rounds_since_low >= 3) break;
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(report.inverted_after > 0 && !report.stopped_by_visitor && !throw_on_failure) {
    // The map with the fewest inverted cells: a start for a wider attempt.
    problem.map.target = best_targets;
    report.inverted_after = fewest;
  } else if(report.inverted_after > 0 && !report.stopped_by_visitor) {
    const std::size_t still = report.inverted_after;
    problem.map.target = start_targets;
    // (The count may exceed the start's: a round may flip valid cells on its way.)
    const std::string why = constrained ? "the descent found no injective map within the constraints, which may admit none "
                                          "(e.g. a fixed boundary that crosses itself)"
                          : slides ? "the boundary slides on its surface, and the descent found no injective map with it there"
                          : 2 * report.inverted_before > problem.map.number_of_cells()
                            ? "no vertex is constrained, and the start inverts most cells: it may be a mirror image (reflect it)"
                            : "no vertex is constrained, yet the descent found no injective map";
    throw Invalid_input("untangling failed: " + std::to_string(still) + " inverted or flat cells remain after " +
                        std::to_string(report.iterations) + " rounds (" + std::to_string(report.inverted_before) +
                        " at the start); " + why);
  }
  return report;
}

// The options with a visitor that numbers its rounds after the `done` ones already reported.
inline Options continuing(const Options& options, std::size_t done)
{
  Options o = options;
  if(o.visitor)
    o.visitor = [visitor = options.visitor, done](std::size_t round, double energy, std::size_t inverted) {
      return visitor(done + round, energy, inverted);
    };
  return o;
}

// The options with a visitor that also records the last round it was called with in `rounds`.
inline Options recording_rounds(const Options& options, std::size_t& rounds)
{
  Options o = options;
  o.visitor = [&rounds, visitor = options.visitor](std::size_t round, double energy, std::size_t inverted) {
    rounds = round;
    return !visitor || visitor(round, energy, inverted);
  };
  return o;
}

// Untangles problem.map in place without the boundary guard, as untangle_everywhere(). The
// inverted cells, however many (the tangles of a deformation or of a parameterizer, the flat cells
// a ball map leaves along the sharp edges of a domain), are first untangled in a part of the map
// the size of the tangles: their own vertices free (ring 0), then within 1, 2, 4, ..., 32 rings of
// those still inverted (a part gives up after three rounds without its count falling a tenth below
// its low; none is tried that holds half the map's cells); the whole map only if cells remain
// inverted. Ring 0 suits scattered cells, such as the flat cells along the edges of a ball map,
// whose one ring can be half the map. A tangle that needs room around it stalls there against the
// fixed vertices, squeezing its neighbours: ring 1 then starts again from the start map, which
// takes fewer rounds than from ring 0's best; wider rings start from the best map of the last. A
// part's untangled map is less even than the whole's, so the optimization after it can take more
// iterations.
template <int n, class GeomTraits>
Untangle_result untangle_in_parts(Optimization_problem<n>& problem, const GeomTraits& traits, const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  const auto inverted_vertices = [&](std::vector<unsigned char>& region) {
    std::size_t inverted = 0;
    region.assign(problem.number_of_vertices(), 0);
    for(std::size_t c = 0; c < problem.map.number_of_cells(); ++c)
      if(is_tangled(problem.map, c, traits)) {
        ++inverted;
        for(auto v : problem.map.cells[c]) region[v] = 1;
      }
    return inverted;
  };
  std::vector<unsigned char> region;
  Untangle_result report;
  report.inverted_before = report.inverted_after = inverted_vertices(region);
  if(report.inverted_before == 0)
    return untangle_everywhere(problem, traits, options);
  check_tangled_cells_can_move(problem, traits);   // before the parts, which number cells their own way
  const std::vector<Vector<n>> start_targets = problem.map.target;
  for(int rings = 0; rings <= 32 && report.inverted_after > 0; rings = rings == 0 ? 1 : 2 * rings) {
    if(rings > 0) inverted_vertices(region);
    for(int k = 0; k < rings; ++k) {
      // One more ring: every vertex of a cell that touches the region.
      std::vector<unsigned char> grown = region;
      for(const auto& cell : problem.map.cells) {
        bool touches = false;
        for(auto v : cell) touches = touches || region[v];
        if(touches)
          for(auto v : cell) grown[v] = 1;
      }
      region.swap(grown);
    }
    std::vector<std::uint32_t> global;
    Optimization_problem<n> part = part_of(problem, region, global);
    if(2 * part.map.number_of_cells() > problem.map.number_of_cells()) break;   // hardly smaller than the map
    const Untangle_result r = untangle_everywhere(part, traits, continuing(options, report.iterations), false);
    const bool kept = rings > 0 || r.inverted_after == 0 || r.stopped_by_visitor;
    if(kept)
      for(std::size_t i = 0; i < global.size(); ++i) problem.map.target[global[i]] = part.map.target[i];
    report.iterations += r.iterations;
    report.inverted_after = kept ? r.inverted_after : report.inverted_before;
    report.stopped_by_visitor = r.stopped_by_visitor;
    if(r.stopped_by_visitor) break;
  }
  if(report.inverted_after > 0 && !report.stopped_by_visitor) {
    try {
      const Untangle_result r = untangle_everywhere(problem, traits, continuing(options, report.iterations));
      report.iterations += r.iterations;
      report.inverted_after = r.inverted_after;
      report.stopped_by_visitor = r.stopped_by_visitor;
    } catch(const Invalid_input&) {
      problem.map.target = start_targets;
      throw;
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

// Untangles problem.map in place: untangle_in_parts(), and with the boundary guard (options'
// global_injectivity, some free boundary vertex) first without it, keeping that result if its
// boundary does not cross itself (exact test). Holding the guard from the start costs the barrier
// its freedom where a fold presses against the boundary: cells squeezed there can stay inverted
// with the guard and open without it, the boundary uncrossed. Only when the boundary then crosses
// does the guarded run start again from the start map.
template <int n, class GeomTraits>
Untangle_result untangle_from_start(Optimization_problem<n>& problem, const GeomTraits& traits, const Options& options)
{
  std::unique_ptr<Boundary_guard<n>> guard = make_boundary_guard(problem, options);   // throws if the start crosses
  if(!guard) return untangle_in_parts(problem, traits, options);
  if constexpr(n == 2) {
    const Planar_obstruction o = planar_obstruction(problem.map, &problem.is_free);
    if(o.handles >= 0)
      throw Invalid_input("untangling with global injectivity cannot succeed: " + handles_message(o.handles, o.genus));
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Vector<n>> start_targets = problem.map.target;
  Options unguarded = options;
  unguarded.global_injectivity = false;
  // The rounds reported so far, also when the attempt throws: the guarded run numbers after them.
  std::size_t rounds = 0;
  unguarded = recording_rounds(unguarded, rounds);
  Untangle_result report;
  try {
    report = untangle_in_parts(problem, traits, unguarded);
    if((report.inverted_after == 0 || report.stopped_by_visitor) && guard->is_injective(problem.map.target)) return report;
  } catch(const Invalid_input&) {
  }
  problem.map.target = start_targets;
  if(report.stopped_by_visitor) {
    report.inverted_after = report.inverted_before;
    return report;
  }
  const std::size_t unguarded_rounds = std::max(report.iterations, rounds);
  report = untangle_everywhere(problem, traits, continuing(options, unguarded_rounds));
  report.iterations += unguarded_rounds;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

// The volume the map's inverted cells cover: what its folds overlap.
template <int n>
double folded_volume(const Simplicial_map<n>& map)
{
  double folded = 0;
  for(std::size_t c = 0; c < map.number_of_cells(); ++c) folded += map.rest_volume[c] * std::max(0., -map.jacobian_determinant(c));
  return folded;
}

// Where the whole boundary is held (fixed, or sliding on its surface): the harmonic map of the
// held vertices (where they are) over the others, into x; false where the boundary is not held
// or the map not defined (Laplacian_system::harmonic_targets). A few held vertices elsewhere (a
// deformation's anchors) would not do: between them the harmonic map crushes whole parts (a
// twisted bar held by its ends).
template <int n>
bool harmonic_inside(const Optimization_problem<n>& problem, const Workers& workers, std::vector<Vector<n>>& x)
{
  std::vector<unsigned char> inside(problem.number_of_vertices());
  for(std::size_t v = 0; v < inside.size(); ++v) inside[v] = problem.is_free[v] && !problem.slides(v);
  for(const auto& face : Boundary_guard<n>::boundary_faces(problem.map.cells))
    for(std::uint32_t v : face)
      if(inside[v]) return false;
  if(std::find(inside.begin(), inside.end(), 0) == inside.end()) return false;
  Laplacian_system<n> system(problem, workers, &inside);
  return system.harmonic_targets(problem.map.target, x);
}

// Untangles problem.map in place (untangle_from_start()), or when that fails on a planar disk
// with at most three constrained vertices or its boundary fixed on a convex polygon, from its Tutte
// embedding (tutte_embedding.h): an injective map that is untangled already unless rounding left
// cells flat. Where the boundary is fixed or slides, the untangling first starts (unless
// options.harmonic_start is off) from the harmonic map of it over the inside (harmonic_inside())
// if that tangles fewer cells than the start or folds less volume (folded_volume()), and from the
// start if no injective map is found from there. Its folds depend on the boundary alone: it folds
// only about reflex corners (never on a convex boundary with positive weights: Floater, "One-to-one
// piecewise linear mappings over triangulations", 2003), where a start's folds (an inside
// mirrored, or pushed across the boundary) can take the barrier many rounds to undo, and a ball
// map's rays crush the inside of a spike; it is the optimization's harmonic start too. Throws as
// untangle_everywhere() when neither applies or succeeds, the map unchanged, and at once for a
// tangled triangle map with a closed piece, or with the boundary guard a piece with handles and a
// free border (planar_obstruction()).
template <int n, class GeomTraits>
Untangle_result untangle(Optimization_problem<n>& problem, const GeomTraits& traits, const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  const Workers workers(options.threads);
  const std::size_t tangled = number_of_tangled_cells(problem.map, traits, workers);
  if constexpr(n == 2) {
    const Planar_obstruction o = planar_obstruction(problem.map);
    if(o.closed >= 0 && tangled > 0)
      throw Invalid_input("untangling cannot succeed: " + closed_piece_message(o.closed));
  }
  std::size_t done = 0;   // the rounds of the attempts before, which a later one numbers after
  const auto finish = [&](Untangle_result report) {   // the report of an attempt that succeeded, over all
    report.inverted_before = tangled;
    report.iterations += done;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  };
  std::vector<Vector<n>> harmonic;
  if(options.harmonic_start && tangled > 0 && harmonic_inside(problem, workers, harmonic)) {
    const std::vector<Vector<n>> start_targets = problem.map.target;
    const double folded = folded_volume(problem.map);
    problem.map.target.swap(harmonic);
    if(number_of_tangled_cells(problem.map, traits, workers) < tangled || folded_volume(problem.map) < folded) {
      std::size_t rounds = 0;
      try {
        return finish(untangle_from_start(problem, traits, recording_rounds(options, rounds)));
      } catch(const Invalid_input&) {   // no injective map found from it: the start's own attempt follows
        done = rounds;
      }
    }
    problem.map.target = start_targets;
  }
  std::size_t rounds = 0;
  try {
    return finish(untangle_from_start(problem, traits, recording_rounds(continuing(options, done), rounds)));
  } catch(const Crossing_start_boundary&) {
    throw;
  } catch(const Invalid_input&) {
    std::vector<Vector<n>> tutte;
    if constexpr(n == 2) {
      if(!tutte_embedding(problem, typical_jacobian_determinant(problem.map), tutte)) throw;
    } else {
      throw;
    }
    done += rounds;
    const std::vector<Vector<n>> start_targets = problem.map.target;   // the start, which the failed attempt restored
    problem.map.target = tutte;
    try {
      return finish(untangle_everywhere(problem, traits, continuing(options, done)));
    } catch(const Invalid_input&) {
      problem.map.target = start_targets;
      throw;
    }
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_UNTANGLE_H

