// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The package's own named parameters. CGAL 5.5 offers no hook to add chainable `.name()` members
// to CGAL::Named_function_parameters, so each new name is a free function that takes an optional
// existing pack and returns it extended:
//   namespace DOP = CGAL::Distortion_optimization::parameters;
//   auto np = DOP::vertex_weight_map(w, CGAL::parameters::vertex_point_map(vpm));
// The result is an ordinary CGAL pack: CGAL's members (.number_of_iterations(...)) chain after it.

#ifndef CGAL_DISTORTION_OPTIMIZATION_PARAMETERS_H
#define CGAL_DISTORTION_OPTIMIZATION_PARAMETERS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// The cell weights w(c, v) of eq. 23; the energy is sum_c w(c) D(J_c) with
/// w(c) = sum_{v in c} omega(v) w(c, v) (Algorithm 1, step 2).
enum class Cell_weighting
{
  UNIFORM,        ///< w(c, v) = 1
  VOLUME,         ///< w(c, v) = volume(c)
  AVERAGE_VOLUME  ///< w(c, v) = volume(c) / (number of vertices of c)
};

/// \ingroup PkgDistortionOptimizationRef
/// How one vertex's local problem (26) is solved at each visit.
enum class Local_solver
{
  GRADIENT_DESCENT, ///< one Armijo step along the ring gradient (Algorithm 2), the default
  BFGS              ///< a few quasi-Newton steps with an n x n inverse-Hessian estimate
};

/// \ingroup PkgDistortionOptimizationRef
/// The order in which a sweep visits the free vertices.
enum class Vertex_order
{
  GREEDY,          ///< the paper's Algorithm 2: always the most distorted remaining vertex (live priority queue); one thread only
  SORTED_PER_SWEEP ///< sorted once by distortion at the start of each sweep
};

/// \ingroup PkgDistortionOptimizationRef
/// What one iteration of the optimization does.
enum class Schedule
{
  LOCAL,       ///< the paper's Algorithms 1-2: one sweep of local vertex moves
  GLOBAL,      ///< one preconditioned step that moves all free vertices at once (the default with Newton's steps, except a smooth model's with sliding vertices)
  ALTERNATING  ///< a local sweep, then a global step (the default with the reweighted Laplacian's steps, and with a smooth model's Newton steps when vertices slide)
};

/// \ingroup PkgDistortionOptimizationRef
/// The linear system whose solution is the direction of a global step (schedules `GLOBAL` and
/// `ALTERNATING`).
enum class Global_solver
{
  REWEIGHTED_LAPLACIAN, ///< the source's Laplacian reweighted per cell, solved by a few conjugate gradient iterations
  PROJECTED_NEWTON      ///< the energy's Hessian with each cell's part made positive semi-definite, factored (measures with a `hessian()`, and on a tetrahedral complex with no vertex fixed, sliding ones allowed, K, the condition number and C through a smooth model, whose Hessian with sliding vertices is the metric of the measure's own gradient; the Laplacian otherwise); sliding vertices move in their tangent planes. Given explicitly, also the maxima K, the condition number, C and V take their own Newton steps where no model's apply, which they do not by default
};

/// \ingroup PkgDistortionOptimizationRef
/// How local sweeps are shared among threads (with `number_of_threads` > 1).
enum class Parallel_sweep
{
  INDEPENDENT_SETS, ///< the default: colour classes of vertices that share no cell, each optimized at once
  PARTITION         ///< the paper's Algorithm 3: k spatial parts in parallel after their interface
};

namespace internal_np {
enum schedule_t { schedule };
enum use_harmonic_start_t { use_harmonic_start };
enum vertex_weight_map_t { vertex_weight_map };
enum cell_distortion_map_t { cell_distortion_map };
enum inverted_cell_map_t { inverted_cell_map };
enum cell_radius_ratio_map_t { cell_radius_ratio_map };
enum sharp_edge_angle_t { sharp_edge_angle };
enum cell_radius_edge_ratio_t { cell_radius_edge_ratio };
enum cell_weighting_t { cell_weighting };
enum convergence_threshold_t { convergence_threshold };
enum local_solver_t { local_solver };
enum vertex_order_t { vertex_order };
enum number_of_threads_t { number_of_threads };
enum parallel_sweep_t { parallel_sweep };
enum global_solver_t { global_solver };
enum preserve_global_injectivity_t { preserve_global_injectivity };
enum untangle_first_t { untangle_first };
enum sliding_boundary_t { sliding_boundary };
} // namespace internal_np

namespace parameters {

// Defines the named parameter NAME for the tag internal_np::TAG; the headers with their own
// parameters (mesh_interior.h, volumetric_texture.h) use it too, in this namespace.
#define CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(TAG, NAME)                           \
  template <class T, class NP = CGAL::parameters::Default_named_parameters>                  \
  CGAL::Named_function_parameters<T, internal_np::TAG, NP>                                   \
  NAME(const T& value, const NP& np = CGAL::parameters::default_values())                   \
  {                                                                                          \
    return CGAL::Named_function_parameters<T, internal_np::TAG, NP>(value, np);            \
  }

/// Vertex weights omega(v) > 0 (a readable vertex property map to a number); default 1.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(vertex_weight_map_t, vertex_weight_map)
/// A writable cell (face) property map that receives the distortion of each cell.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cell_distortion_map_t, cell_distortion_map)
/// A writable cell (face) property map that receives, for each cell, whether the map inverts or
/// flattens it (`true`) or keeps its orientation (`false`); for `mesh_quality()`, whether the cell
/// is inverted at the positions.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(inverted_cell_map_t, inverted_cell_map)
/// `mesh_quality()`: a writable cell (face) property map that receives the radius ratio of each
/// cell (n r / R, 1 for the regular simplex, 0 for a flat cell).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cell_radius_ratio_map_t, cell_radius_ratio_map)
/// An angle in degrees: an edge is sharp when the normals of its two faces make a larger angle.
/// `mesh_interior()`: an input edge that is sharp is kept as a polyline of the output; in (0, 180],
/// 180 keeps no edge (better for noisy scanned surfaces, whose spurious sharp edges make small
/// tetrahedra); default 60 (Mesh_3's). `sharp_boundary_vertices()`: the edges of the complex's
/// boundary whose vertices it returns; default 60.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(sharp_edge_angle_t, sharp_edge_angle)
/// Upper bound on circumradius / shortest edge of the tetrahedra. `mesh_interior()`: >= 2, where
/// Mesh_3 is proved to terminate; default 3. `tetrahedralize_with_tetgen()`: TetGen's `q`;
/// default 1.414.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cell_radius_edge_ratio_t, cell_radius_edge_ratio)
/// A `Cell_weighting`; default `Cell_weighting::AVERAGE_VOLUME`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cell_weighting_t, cell_weighting)

/// Stop when an iteration decreases the energy by less than this fraction of the energy above the
/// measure's minimum (of the energy itself for a measure that is not normalized); default 1e-4.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(convergence_threshold_t, convergence_threshold)
/// A `Local_solver`; default `Local_solver::GRADIENT_DESCENT`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(local_solver_t, local_solver)
/// A `Vertex_order`; default `Vertex_order::SORTED_PER_SWEEP` (same energies as the paper's
/// `GREEDY` order in less time). It applies to the one-thread sweep: with `number_of_threads` > 1
/// the parallel sweeps use the sorted order.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(vertex_order_t, vertex_order)

/// A `Schedule` (or a `std::optional` of one: empty for the default); default `Schedule::GLOBAL` with projected
/// Newton steps (a local sweep then follows a step that gains too little or is cut short), `Schedule::ALTERNATING`
/// otherwise, and with a smooth model's Newton steps when vertices slide.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(schedule_t, schedule)
/// `bool`: start from the harmonic map of the fixed vertices when it is valid and better (or from
/// the best safe point towards it); default `true`, except with `Schedule::LOCAL` (the paper's
/// schedule, which starts from the given map).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(use_harmonic_start_t, use_harmonic_start)

/// `int`: threads for the sweeps and the global steps; 0 takes all the hardware offers; default 1.
/// Used when the program links `CGAL::TBB_support` (CGAL_LINKED_WITH_TBB), sequential otherwise.
/// For a given number of threads the output is deterministic.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(number_of_threads_t, number_of_threads)
/// A `Parallel_sweep`; default `Parallel_sweep::INDEPENDENT_SETS`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(parallel_sweep_t, parallel_sweep)
/// A `Global_solver`; default `Global_solver::PROJECTED_NEWTON` (solved by a sparse factorization
/// for triangle meshes, by truncated conjugate gradients for tetrahedral meshes, whose systems
/// fill in too much to factor), except for the maxima `Conformal_dilatation`, `Condition_number`,
/// `Isometric_dilatation` and `Volume_distortion`, which by default take the reweighted
/// Laplacian's steps where no smooth model's apply (their kinks make their own Hessians poor models).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(global_solver_t, global_solver)

/// `bool`: keep the map globally injective when boundary vertices are free (paper section 3.2):
/// a move that would make the target boundary cross itself, or a piece of the mesh grow over
/// another, is shortened. The start map's boundary must not intersect itself, nor a piece lie
/// inside another. Default `false` (with a fixed boundary there is nothing to guard).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(preserve_global_injectivity_t, preserve_global_injectivity)

/// `bool`: when the start map has inverted or flat cells, untangle it first
/// (`Distortion_optimization::untangle()`), then minimize the measure from the untangled map.
/// Default `false`: such a start is an error under a normalized measure.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(untangle_first_t, untangle_first)

/// A model of `SlidingSurface` (`Sphere_surface`, `Triangle_surface`, see sliding_surfaces.h):
/// boundary vertices that are not constrained move on this surface instead of staying where the
/// start map put them (the paper's Fig. 13: a cube onto a ball, the boundary on the sphere). With
/// it, `CGAL::parameters::vertex_is_constrained_map` defaults to no vertex, so that the whole
/// boundary slides; the vertices it constrains stay fixed. A sliding vertex moves in the tangent
/// plane and is projected back onto the surface; the move is kept only if the energy decreases
/// and no valid cell of its ring inverts (exact predicates). The start's boundary vertices should
/// lie on the surface (e.g. `star_shaped_to_unit_ball()` puts them on the unit sphere): a vertex
/// off it is moved onto it by its first accepted move.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(sliding_boundary_t, sliding_boundary)

} // namespace parameters
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_PARAMETERS_H
