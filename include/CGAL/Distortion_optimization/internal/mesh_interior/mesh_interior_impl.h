// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The driver of mesh_interior(), after its named parameters were read: the steps below, each in a
// header of this folder, in order:
//   1. check the surface (checked_surface.h; done by the caller, which also reads the sizes);
//   2. domain: Polyhedral_mesh_domain_with_features_3 on the copy, sharp edges detected and
//      protected (a smooth surface has none);
//   3. refuse what Mesh_3 would not mesh in bounded time and memory: thin parts (thin_parts.h),
//      components closer than the facet distance (close_components.h), sharp edges as close
//      (close_sharp_edges.h), sizes that ask for too many vertices;
//   4. Delaunay refinement (make_mesh_3) with a seeded random generator; a component of the surface
//      that Mesh_3's initial points missed gets seeds of its own and the refinement goes on
//      (refine_mesh_3, missed_components.h); then the optional optimizers without time limits: the
//      output depends only on the input and the parameters;
//   5. repairs of the complex: facets made the boundary of the cells (match_facets_to_cells.h),
//      touching tetrahedra separated (separate_touching_tetrahedra.h), flat caps peeled
//      (peel_flat_caps.h), flat cells flipped away (flip_flat_cells.h);
//   6. the complex mapped back to the input's units and place (map_complex_back.h), and its boundary
//      checked: a 2-manifold (manifold_boundary.h) with the surface's genera (boundary_genera.h).
// Mesh_3 runs on a copy scaled by a power of two to unit size, and its complex is scaled back:
// Mesh_3 has absolute tolerances (it crashes or hangs on surfaces far from unit size), and an exact
// scaling makes the mesh of a scaled surface the scaled mesh. A surface far from the origin for its
// size is moved near it first, exactly (its coordinates keep too few digits below its distance, and
// Mesh_3 can hang there), and the complex moved back.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MESH_INTERIOR_IMPL_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MESH_INTERIOR_IMPL_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/boundary_genera.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/checked_surface.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/close_components.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/close_sharp_edges.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/flip_flat_cells.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/manifold_boundary.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/map_complex_back.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/match_facets_to_cells.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/mesh_size_estimate.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/missed_components.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/peel_flat_caps.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/separate_touching_tetrahedra.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/thin_parts.h>

#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/exceptions.h>
#include <CGAL/Mesh_error_code.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>      // before the optimizers' headers, which miss some of its includes
#include <CGAL/refine_mesh_3.h>    // refine_mesh_3 and Mesh_3's optimizers

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// What mesh_interior() read from its named parameters besides the sizes.
struct Mesh_3_settings
{
  int odt_iterations = 0;
  int lloyd_iterations = 0;
  bool perturb_slivers = false;
  bool exude_slivers = false;
  double asked_vertices = 0;          // about as many vertices as the sizes ask for
  std::size_t maximum_vertices = 0;   // where Mesh_3 stops; 0 for no limit
  bool maximum_given = false;         // whether the user gave maximum_vertices
  double time_limit = 0;              // seconds after which Mesh_3's refinement stops; 0 for none
};

// Raises Mesh_3's stop flag once `seconds` have passed (from a thread of its own, which the
// destructor ends at once); 0 for never.
class Mesh_3_deadline
{
public:
  explicit Mesh_3_deadline(double seconds) : seconds_(seconds)
  {
    if(seconds > 0)
      watchdog_ = std::thread([this, seconds] {
        std::unique_lock<std::mutex> lock(mutex_);
        if(!ended_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return done_; })) stop_ = true;
      });
  }
  Mesh_3_deadline(const Mesh_3_deadline&) = delete;
  Mesh_3_deadline& operator=(const Mesh_3_deadline&) = delete;
  ~Mesh_3_deadline()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    ended_.notify_all();
    if(watchdog_.joinable()) watchdog_.join();
  }
  std::atomic<bool>* flag() { return &stop_; }
  // Throws if the time ran out (Mesh_3 then returned an unfinished complex).
  void check() const
  {
    if(stop_)
      throw Invalid_input("mesh_interior: Mesh_3 did not finish within the time limit of " + shown_number(seconds_) +
                          " s (larger sizes ask for fewer tetrahedra)");
  }

private:
  double seconds_;
  std::atomic<bool> stop_{false};
  bool done_ = false;
  std::mutex mutex_;
  std::condition_variable ended_;
  std::thread watchdog_;
};

// Sizes that ask for more vertices than memory holds are refused before Mesh_3 starts rather than
// after it has filled the memory: beyond the maximum when one is given, else beyond
// Interior_mesh_defaults::affordable_vertices.
inline void check_vertex_budget(const Mesh_3_settings& settings, double cell_size, double facet_size)
{
  const double asked = settings.asked_vertices;
  const bool maximum_given = settings.maximum_given;
  if(!(asked <= affordable_vertices(maximum_given, settings.maximum_vertices))) {
    char text[160];
    std::snprintf(text, sizeof text, "about %.2g vertices, more than %s (cell size %.3g, facet size %.3g)",
                  (std::min)(asked, 1e300),
                  maximum_given ? "maximum_number_of_vertices" : "2 million", cell_size, facet_size);
    throw Invalid_input(std::string("mesh_interior: the sizes ask for ") + text + "; give larger sizes" +
                        (maximum_given ? "" : ", or a larger maximum_number_of_vertices"));
  }
}

// Throws where Mesh_3 stopped at the maximum number of vertices (its error code `error`).
inline void check_mesh_3_error(CGAL::Mesh_error_code error, std::size_t maximum_vertices)
{
  if(error == CGAL::CGAL_MESH_3_MAXIMAL_NUMBER_OF_VERTICES_REACHED)
    throw Invalid_input("mesh_interior: Mesh_3 stopped at " + std::to_string(maximum_vertices) +
                        " vertices (maximum_number_of_vertices): the surface has details far smaller than the "
                        "sizes (thin parts, short sharp edges?); try a larger sharp_edge_angle (180 protects no "
                        "edge) or a larger maximum");
}

// Runs `step` (a Mesh_3 call); a check of CGAL's own that fails inside it, as some needle-like
// features make Mesh_3's refinement do, becomes the package's one-line error.
template <class Step>
decltype(auto) mesh_3_or_invalid_input(Step&& step)
{
  try {
    return step();
  } catch(const CGAL::Failure_exception& e) {
    const std::string text = e.message().empty() ? e.expression() : e.message();
    const std::string file = e.filename().substr(e.filename().find_last_of('/') + 1);
    throw Invalid_input("mesh_interior: Mesh_3 failed a check of its own (" + text.substr(0, text.find('\n')) + ", " + file + ":" +
                        std::to_string(e.line_number()) + "): the surface may have a spike or a feature too sharp for "
                        "Mesh_3 at these sizes; try another cell size or blunt the feature");
  }
}

// The optimizers as make_mesh_3 runs them, in its order. ODT, Lloyd and the perturbation have
// no time limit: one would make the output depend on the machine's speed (Mesh_3's default limit
// for perturbation and exudation is the refinement time). The exudation, which has no other
// bound, gets twice the refinement's `refinement_seconds`, 10 s at least: on surfaces with
// several long spikes it ran for minutes after a refinement of seconds; only there does the
// output depend on the machine.
template <class C3T3, class Domain>
void run_mesh_3_optimizers(C3T3& c3t3, const Domain& domain, const Mesh_3_settings& settings, double refinement_seconds)
{
  using D = Interior_mesh_defaults;
  namespace mp = CGAL::parameters;   // Mesh_3's Boost.Parameter keywords live there
  if(settings.odt_iterations > 0)
    CGAL::odt_optimize_mesh_3(c3t3, domain, mp::time_limit = 0, mp::max_iteration_number = settings.odt_iterations);
  if(settings.lloyd_iterations > 0)
    CGAL::lloyd_optimize_mesh_3(c3t3, domain, mp::time_limit = 0, mp::max_iteration_number = settings.lloyd_iterations);
  if(settings.perturb_slivers) CGAL::perturb_mesh_3(c3t3, domain, mp::time_limit = 0);
  const double exudation_limit = (std::max)(10., 2 * refinement_seconds);
  if(settings.exude_slivers) CGAL::exude_mesh_3(c3t3, mp::time_limit = exudation_limit);
  else CGAL::exude_mesh_3(c3t3, mp::sliver_bound = D::sliver_bound, mp::time_limit = exudation_limit);
}

// mesh_interior() on the checked copy of its surface, with the sizes (an `Interior_mesh_sizes`,
// in the units of the input) and settings read from its named parameters. `Types` is
// `Interior_mesh<GeomTraits>`.
template <class Types, class CheckedSurface, class Sizes>
typename Types::C3T3 mesh_interior_impl(const CheckedSurface& checked, const Sizes& sizes, const Mesh_3_settings& settings)
{
  namespace mp = CGAL::parameters;   // Mesh_3's Boost.Parameter keywords live there

  // The domain keeps a pointer to the generator; without one it would draw from a generator of
  // its own, seeded alike, but the explicit seed states the intent.
  CGAL::Random random(0);
  typename Types::Domain domain(checked.surface, &random);
  if(sizes.sharp_edge_angle < 180) domain.detect_features(sizes.sharp_edge_angle);

  // What Mesh_3 would not mesh, or not in bounded time and memory, is refused before it starts.
  check_thickness_of_parts(checked, sizes.cell_size, sizes.facet_size, sizes.facet_distance,
                           affordable_vertices(settings.maximum_given, settings.maximum_vertices), sizes.sharp_edge_angle);
  check_components_apart(checked, sizes.facet_distance);
  check_sharp_edges_apart(checked, sizes.sharp_edge_angle, sizes.facet_distance, sizes.edge_size);
  check_vertex_budget(settings, sizes.cell_size, sizes.facet_size);

  const double s = checked.scale;   // the sizes in the units of the scaled copy
  const typename Types::Criteria criteria(mp::edge_size = s * sizes.edge_size, mp::facet_angle = sizes.facet_angle,
                                          mp::facet_size = s * sizes.facet_size,
                                          mp::facet_distance = s * sizes.facet_distance,
                                          mp::cell_radius_edge_ratio = sizes.cell_radius_edge_ratio,
                                          mp::cell_size = s * sizes.cell_size);
  CGAL::Mesh_error_code error = CGAL::CGAL_MESH_3_NO_ERROR;
  Mesh_3_deadline deadline(settings.time_limit);
  const auto refinement_start = std::chrono::steady_clock::now();
  const auto options = mp::mesh_3_options(mp::maximal_number_of_vertices = settings.maximum_vertices,
                                          mp::pointer_to_error_code = &error,
                                          mp::pointer_to_stop_atomic_boolean = deadline.flag());
  typename Types::C3T3 c3t3 = mesh_3_or_invalid_input([&] {
    return CGAL::make_mesh_3<typename Types::C3T3>(domain, criteria, mp::features(domain), mp::no_odt(), mp::no_lloyd(),
                                                   mp::no_perturb(), mp::no_exude(), options);
  });
  deadline.check();
  check_mesh_3_error(error, settings.maximum_vertices);

  // Components that Mesh_3's initial points missed get seeds, and the refinement goes on from the
  // whole triangulation.
  std::vector<std::size_t> missed;
  const auto seeds = seeds_of_missed_components(c3t3, domain, checked.surface, checked.component, missed);
  if(!seeds.empty()) {
    insert_seeds(c3t3, seeds);
    mesh_3_or_invalid_input([&] {
      CGAL::refine_mesh_3(c3t3, domain, criteria, mp::no_odt(), mp::no_lloyd(), mp::no_perturb(), mp::no_exude(),
                          mp::no_reset_c3t3(), options);
    });
    deadline.check();
    check_mesh_3_error(error, settings.maximum_vertices);
    seeds_of_missed_components(c3t3, domain, checked.surface, checked.component, missed);
  }
  check_no_missed_component(missed, checked.face_names);

  const double refinement_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - refinement_start).count();
  mesh_3_or_invalid_input([&] { run_mesh_3_optimizers(c3t3, domain, settings, refinement_seconds); });

  // The repairs that make the complex a mesh the maps of the package take.
  match_facets_to_cells(c3t3);
  separate_touching_tetrahedra(c3t3, c3t3.number_of_cells_in_complex() / 100);
  peel_flat_caps(c3t3, s * sizes.facet_distance);
  flip_flat_cells(c3t3);
  if(c3t3.number_of_cells_in_complex() == 0)
    throw Invalid_input("mesh_interior: Mesh_3 produced no tetrahedron inside the surface (sizes too large "
                        "for the volume?)");

  map_complex_back(c3t3, 1 / s, checked.offset);
  check_boundary_is_manifold(c3t3);
  check_boundary_genera(c3t3, checked.surface);
  return c3t3;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_MESH_INTERIOR_IMPL_H
