// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The first step of the volume workflow: mesh_interior(), a tetrahedral mesh of the inside of a
// closed triangle surface, made by CGAL's Mesh_3, ready for the start maps of volume_maps.h and
// for CGAL::minimize_distortion(); its types, its named parameters and interior_mesh_sizes().
// This header reads the named parameters; the steps (checks of the surface, Mesh_3, the repairs
// of its complex) are in internal/mesh_interior/, listed by mesh_interior_impl().

#ifndef CGAL_DISTORTION_OPTIMIZATION_MESH_INTERIOR_H
#define CGAL_DISTORTION_OPTIMIZATION_MESH_INTERIOR_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/checked_surface.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/mesh_interior_impl.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// The types of the mesh that `mesh_interior()` builds, for a kernel `GeomTraits` with inexact
/// constructions (default `CGAL::Exact_predicates_inexact_constructions_kernel`). `C3T3` is the
/// return type of `mesh_interior()`; its triangulation stores weighted points (protecting balls of
/// the sharp edges), so read positions with
/// `tr.geom_traits().construct_point_3_object()(tr.point(c, i))`, as every function of the
/// package does.
template <class GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel>
struct Interior_mesh
{
  using Geom_traits = GeomTraits;
  using Point_3 = typename GeomTraits::Point_3;
  /// The copy of the input surface that the domain holds.
  using Surface = CGAL::Surface_mesh<Point_3>;
  using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<GeomTraits, Surface>;
  /// Sequential on purpose: the parallel Mesh_3 does not give the same mesh twice.
  using Triangulation = typename CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3T3 = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation, typename Domain::Corner_index,
                                                       typename Domain::Curve_index>;
  using Criteria = CGAL::Mesh_criteria_3<Triangulation>;
};

/// \ingroup PkgDistortionOptimizationRef
/// The Mesh_3 criteria that `mesh_interior()` uses, in the units of the input (angles in
/// degrees), after the defaults were filled in. `interior_mesh_sizes()` returns them.
struct Interior_mesh_sizes
{
  double cell_size = 0;              ///< upper bound on the circumradius of the tetrahedra
  double cell_radius_edge_ratio = 0; ///< upper bound on circumradius / shortest edge of the tetrahedra
  double facet_size = 0;             ///< upper bound on the radius of the surface Delaunay balls of boundary facets
  double facet_distance = 0;         ///< upper bound on the distance from a boundary facet's circumcentre to the surface
  double facet_angle = 0;            ///< lower bound on the angles of the boundary facets
  double edge_size = 0;              ///< upper bound on the size of the protecting balls along sharp edges
  double sharp_edge_angle = 0;       ///< an edge is sharp when the normals of its faces differ by more than this
  double volume = 0;                 ///< the volume enclosed by the surface (measured, not a criterion)
  double area = 0;                   ///< the area of the surface (measured, not a criterion)
};

namespace internal_np {
enum cell_size_t { cell_size };
enum facet_size_t { facet_size };
enum facet_distance_t { facet_distance };
enum facet_angle_t { facet_angle };
enum edge_size_t { edge_size };
enum odt_iterations_t { odt_iterations };
enum lloyd_iterations_t { lloyd_iterations };
enum perturb_slivers_t { perturb_slivers };
enum exude_slivers_t { exude_slivers };
enum maximum_number_of_vertices_t { maximum_number_of_vertices };
enum meshing_time_limit_t { meshing_time_limit };
} // namespace internal_np

namespace parameters {

/// `mesh_interior()`: upper bound on the circumradius of the tetrahedra (a length, > 0). Default:
/// the size that gives about 3.10^4 tetrahedra (see `mesh_interior()`).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cell_size_t, cell_size)
/// `mesh_interior()`: upper bound on the radius of the surface Delaunay ball of a boundary facet
/// (a length, > 0). Default: the cell size.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(facet_size_t, facet_size)
/// `mesh_interior()`: upper bound on the distance from the circumcentre of a boundary facet to the
/// input surface: how closely the boundary follows curved parts (a length, > 0). Default: the
/// facet size / 10.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(facet_distance_t, facet_distance)
/// `mesh_interior()`: lower bound on the angles of the boundary facets, in degrees, in (0, 30]
/// (Mesh_3 is proved to terminate up to 30). Default 25.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(facet_angle_t, facet_angle)
/// `mesh_interior()`: upper bound on the protecting balls (hence the edges) along the sharp edges
/// (a length, > 0). Default: the facet size.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(edge_size_t, edge_size)
// (`cell_radius_edge_ratio` and `sharp_edge_angle` are in parameters.h: `tetrahedralize_with_tetgen()` and
// `sharp_boundary_vertices()` read them too.)
/// `mesh_interior()`: an `int`, the number of iterations of Mesh_3's ODT smoothing (moves vertices
/// to lower the optimal-Delaunay-triangulation energy, `CGAL::odt_optimize_mesh_3()`), run after
/// the refinement; 0 (the default) skips it. It stops earlier when it converges.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(odt_iterations_t, odt_iterations)
/// `mesh_interior()`: an `int`, the number of iterations of Mesh_3's Lloyd smoothing (moves vertices
/// to the centroids of their Voronoi cells, `CGAL::lloyd_optimize_mesh_3()`), after ODT; 0 (the
/// default) skips it.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(lloyd_iterations_t, lloyd_iterations)
/// `mesh_interior()`: a `bool`, run Mesh_3's sliver perturbation (`CGAL::perturb_mesh_3()`: moves
/// vertices of the flattest tetrahedra) after the smoothers. Default `false`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(perturb_slivers_t, perturb_slivers)
/// `mesh_interior()`: a `bool`, run Mesh_3's sliver exudation last (`CGAL::exude_mesh_3()`:
/// changes vertex weights, hence the connectivity, to remove flat tetrahedra; it moves no vertex).
/// Default `false`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(exude_slivers_t, exude_slivers)

/// `mesh_interior()`: a `std::size_t`, the number of vertices at which Mesh_3 stops and
/// `mesh_interior()` throws; 0 for no limit. Default: 10 times the number of vertices the sizes
/// ask for (volume / (0.2 cell_size^3) / 5.5 + area / (0.3 facet_size^2) / 2, see
/// `mesh_interior()`), which stops the runs where details of the surface far below the sizes (e.g.
/// a sharp edge shorter than 10^-4 of the model) would force a huge mesh. Mesh_3 checks it while
/// refining, not while protecting the sharp edges, so the error may come only after a long
/// protection phase.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(maximum_number_of_vertices_t, maximum_number_of_vertices)
/// `mesh_interior()`: the seconds after which Mesh_3's refinement is stopped and the function
/// throws; 0 (the default) for no limit.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(meshing_time_limit_t, meshing_time_limit)


} // namespace parameters

namespace internal {

inline void check_size(double value, const char* name)
{
  if(!(value > 0) || !std::isfinite(value))
    throw Invalid_input(std::string("mesh_interior: ") + name + " must be a positive finite number, not " + shown_number(value));
}

// The user's sizes where given, else the defaults (each one following the one it derives from).
// The defaults are computed on the surface scaled by `scale` (a power of two), then scaled back:
// libm's cube root is not correctly rounded, and would make the default sizes of a surface scaled
// by 2 differ from twice its sizes in the last place.
template <class NamedParameters>
Interior_mesh_sizes read_interior_mesh_sizes(double volume, double area, double scale, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using D = Interior_mesh_defaults;
  Interior_mesh_sizes s;
  s.volume = volume;
  s.area = area;
  // Tetrahedra for the volume, boundary facets for the area: the larger size wins, so that thin
  // shapes (a lot of area for little volume) do not get far more tetrahedra than the target.
  const double by_volume = std::cbrt(volume * scale * scale * scale / (D::cells * D::volume_per_cell)) / scale;
  const double by_area = std::sqrt(area * scale * scale / (D::boundary_facets * D::area_per_facet)) / scale;
  s.cell_size = choose_parameter(get_parameter(np, internal_np::cell_size), (std::max)(by_volume, by_area));
  check_size(s.cell_size, "the cell size");
  s.facet_size = choose_parameter(get_parameter(np, internal_np::facet_size), s.cell_size);
  check_size(s.facet_size, "the facet size");
  s.facet_distance = choose_parameter(get_parameter(np, internal_np::facet_distance), D::distance_ratio * s.facet_size);
  check_size(s.facet_distance, "the facet distance");
  s.edge_size = choose_parameter(get_parameter(np, internal_np::edge_size), s.facet_size);
  check_size(s.edge_size, "the edge size");
  s.facet_angle = choose_parameter(get_parameter(np, internal_np::facet_angle), D::facet_angle);
  if(!(s.facet_angle > 0 && s.facet_angle <= 30))
    throw Invalid_input("mesh_interior: the facet angle must be in (0, 30] degrees, not " + shown_number(s.facet_angle));
  s.cell_radius_edge_ratio = choose_parameter(get_parameter(np, internal_np::cell_radius_edge_ratio), D::radius_edge_ratio);
  if(!(s.cell_radius_edge_ratio >= 2) || !std::isfinite(s.cell_radius_edge_ratio))
    throw Invalid_input("mesh_interior: the cell radius-edge ratio must be a finite number >= 2, not " +
                        shown_number(s.cell_radius_edge_ratio));
  s.sharp_edge_angle = choose_parameter(get_parameter(np, internal_np::sharp_edge_angle), D::sharp_edge_angle);
  if(!(s.sharp_edge_angle > 0 && s.sharp_edge_angle <= 180))
    throw Invalid_input("mesh_interior: the sharp edge angle must be in (0, 180] degrees, not " +
                        shown_number(s.sharp_edge_angle));
  return s;
}

// The kernel of the output: the `geom_traits` parameter's type, else Epick.
template <class NamedParameters>
using Interior_mesh_traits_of = typename CGAL::internal_np::Lookup_named_param_def<
  CGAL::internal_np::geom_traits_t, NamedParameters, CGAL::Exact_predicates_inexact_constructions_kernel>::type;

} // namespace internal

/*!
\ingroup PkgDistortionOptimizationRef

The criteria `mesh_interior()` would use for `surface` and `np`: the given ones and the
defaults, with the enclosed volume and the area. Checks the surface as `mesh_interior()` does.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` (e.g. `CGAL::Surface_mesh`)
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param surface a closed, 2-manifold triangle surface without self-intersections
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters": those of
       `mesh_interior()` that read the surface and set the criteria (`vertex_point_map`,
       `vertex_index_map`, `face_index_map`, `geom_traits`, `cell_size`, `cell_radius_edge_ratio`,
       `facet_size`, `facet_distance`, `facet_angle`, `edge_size`, `sharp_edge_angle`), with the
       meanings, defaults and ranges listed there; the others of `mesh_interior()` (its optimizers
       and `maximum_number_of_vertices`) are ignored

\throws Invalid_input as `mesh_interior()` (except for an output with no cell or
`maximum_number_of_vertices`).
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Interior_mesh_sizes interior_mesh_sizes(const TriangleMesh& surface,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using GT = internal::Interior_mesh_traits_of<NamedParameters>;
  const internal::Checked_surface<typename Interior_mesh<GT>::Surface, TriangleMesh> checked(surface, np);
  return internal::read_interior_mesh_sizes(checked.volume, checked.area, checked.scale, np);
}

/*!
\ingroup PkgDistortionOptimizationRef

Meshes the inside of the closed triangle surface `surface` with tetrahedra (CGAL's Mesh_3 on a
`Polyhedral_mesh_domain_with_features_3`, sharp edges protected) and returns the complex: its
cells are positively oriented, its boundary vertices lie on `surface` (up to rounding) and,
where `surface` has sharp edges, its boundary keeps them (a cube keeps its 8 corners and 12
edges). The result is what `map_vertices()`, `star_shaped_to_unit_ball()`, `harmonic_map()`,
`CGAL::compute_distortion()` and `CGAL::minimize_distortion()` take. `surface` is not modified;
its orientation does not matter; several components (disjoint or nested, e.g. a hollow ball)
are meshed as the volume they bound, every one of them: Mesh_3 finds the surface from rays cast
from the centre of the bounding box and from the sharp edges, and a component that these miss (a
small sphere beside a large one, an island in a hollow ball) is seeded with points of its own
before the refinement resumes (`CGAL::refine_mesh_3()`). Mesh_3 leaves a few flat caps on the
surface: cells with two boundary facets and all four vertices on the surface, thinner than the facet distance
and than a tenth of their width (smallest dihedral angles of 0.1 to 1.5 degrees), which hold no
volume and which a start map that bends the surface (the radial map, the unit ball map) can turn
over with every vertex on the boundary, where no optimization with a fixed boundary can undo it.
They are removed from the complex, their two inner facets becoming boundary facets, less than the
facet distance deeper. Inside, Mesh_3 leaves a few cells as flat with all four vertices on the
surface across thin parts, which the radial map can turn over: without `exude_slivers`, Mesh_3's
sliver exudation still runs on the cells with a dihedral angle below 2 degrees. Where four of
Mesh_3's points are coplanar and cospherical, a cell can be flat to rounding (the square sections
of a long thin bar), which no map can measure: it is flipped away (a 3-2 flip of an edge, after a
2-3 flip where the edge has four cells around it), among cells of the complex: the triangulation
stays valid with positive cells but is no longer the regular one. Two runs with the same input
give the same complex (the random generator of Mesh_3 is seeded, the optimizers have no time
limit, but for the exudation's, twice the refinement's time and 10 s at least, which only
surfaces with several long spikes reached, after minutes without it).

Defaults. Without sizes, the criteria scale with the enclosed volume V and the area A of the
surface: cell_size = facet_size = edge_size = max(cbrt(V / 6000), sqrt(A / 2400)),
facet_distance = facet_size / 10, facet_angle = 25, cell_radius_edge_ratio = 3, and
sharp_edge_angle = 60. This aims at about 3.10^4 tetrahedra (the volume term) with at most
about 8.10^3 boundary facets (the area term, for thin shapes). On the 66 closed, 2-manifold,
self-intersection-free surfaces of libcgal-demo's data it gave 1.4.10^4 to 1.03.10^5
tetrahedra (median 2.7.10^4); the largest counts come
from spurious sharp edges of scanned surfaces (femur.off, which `sharp_edge_angle(180)` brings
near the median), and one CAD model with sharp edges 10^-4 of its size
(mpi_triang.off) stops at `maximum_number_of_vertices`. Where parts of the surface are closer
than the sizes, Mesh_3's tetrahedra may touch only along an edge or at a vertex (nine of those
surfaces at the default sizes: armadillo, cheese, dino, femur, hand, homer, rotor, rotor_small,
triceratops, at the same places with half the sizes): there, the smaller side changes sides (the
tetrahedra of the smaller group at that vertex leave the complex, or the space of a hole closing
there is filled), at up to 100 places and 1% of the cells; six of the nine are meshed so, and
cheese (thin walls), rotor and rotor_small are refused. The facets of the returned complex are
exactly the boundary of its cells (Mesh_3's facets, those whose dual Voronoi edge crosses the
surface, differ from it in a few places). Sizes are in the units of the input, and
Mesh_3 runs on a copy scaled by a power of two to unit size: a surface of any size whose volume a
`double` holds is meshed alike, and a surface scaled by a power of two gives exactly the scaled complex
(points and weights). A surface far from the origin for its size (within \f$ [m, 2m] \f$ along an
axis) is moved near it for Mesh_3 (exactly), and the complex moved back (rounded). A size that is given also sets the defaults of the sizes
derived from it: `cell_size(h)` alone makes facet_size = edge_size = h and facet_distance =
h / 10.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` (e.g. `CGAL::Surface_mesh`)
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param surface a closed, 2-manifold triangle surface without self-intersections
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below. Mesh_3's optimizers are off by default: the optimizers of this package
       start from the refined mesh, and they cost far more than it (each of them several times
       the refinement's time).

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `surface`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and a 3D point type (with `x()`, `y()`, `z()` convertible by `CGAL::to_double()`)
                   as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, surface)`}
    \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
                    must be available in `TriangleMesh`.}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex of `surface` a unique index, which orders the
                          vertices of the copy of the surface and names them in error messages}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
    \cgalParamExtra{The indices need not be contiguous (e.g. a `Surface_mesh` with removed elements).}
  \cgalParamNEnd

  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of `surface` a unique index, which names the faces
                          in error messages}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
                   as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{the kernel of the output: only its type is used}
    \cgalParamType{a class model of `Kernel` with inexact constructions, as Mesh_3 requires}
    \cgalParamDefault{`CGAL::Exact_predicates_inexact_constructions_kernel`}
  \cgalParamNEnd

  \cgalParamNBegin{cell_size}
    \cgalParamDescription{an upper bound on the circumradius of the tetrahedra (a length)
                          (`Distortion_optimization::parameters::cell_size()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`max(cbrt(V / 6000), sqrt(A / 2400))`, V the volume enclosed by `surface` and A its area}
    \cgalParamExtra{It must be positive and finite.}
  \cgalParamNEnd

  \cgalParamNBegin{cell_radius_edge_ratio}
    \cgalParamDescription{an upper bound on circumradius / shortest edge of the tetrahedra
                          (`Distortion_optimization::parameters::cell_radius_edge_ratio()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`3`}
    \cgalParamExtra{It must be finite and at least 2 (where Mesh_3 is proved to terminate).}
  \cgalParamNEnd

  \cgalParamNBegin{facet_size}
    \cgalParamDescription{an upper bound on the radius of the surface Delaunay ball of a boundary facet (a length)
                          (`Distortion_optimization::parameters::facet_size()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{the cell size}
    \cgalParamExtra{It must be positive and finite.}
  \cgalParamNEnd

  \cgalParamNBegin{facet_distance}
    \cgalParamDescription{an upper bound on the distance from the circumcentre of a boundary facet to `surface`
                          (a length) (`Distortion_optimization::parameters::facet_distance()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{the facet size / 10}
    \cgalParamExtra{It must be positive and finite.}
  \cgalParamNEnd

  \cgalParamNBegin{facet_angle}
    \cgalParamDescription{a lower bound on the angles of the boundary facets, in degrees
                          (`Distortion_optimization::parameters::facet_angle()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`25`}
    \cgalParamExtra{It must be in (0, 30] (Mesh_3 is proved to terminate up to 30).}
  \cgalParamNEnd

  \cgalParamNBegin{edge_size}
    \cgalParamDescription{an upper bound on the size of the protecting balls (hence the edges) along the sharp edges
                          (a length) (`Distortion_optimization::parameters::edge_size()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{the facet size}
    \cgalParamExtra{It must be positive and finite.}
  \cgalParamNEnd

  \cgalParamNBegin{sharp_edge_angle}
    \cgalParamDescription{an edge of `surface` is sharp, and kept as a polyline of the output, when the normals of its
                          two faces make an angle larger than this, in degrees
                          (`Distortion_optimization::parameters::sharp_edge_angle()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`60`}
    \cgalParamExtra{It must be in (0, 180]; `180` keeps no edge.}
  \cgalParamNEnd

  \cgalParamNBegin{odt_iterations}
    \cgalParamDescription{the number of iterations of Mesh_3's ODT smoothing (`CGAL::odt_optimize_mesh_3()`), run
                          after the refinement; `0` skips it (`Distortion_optimization::parameters::odt_iterations()`)}
    \cgalParamType{`int`}
    \cgalParamDefault{`0`}
    \cgalParamExtra{It must be non-negative. The smoothing stops earlier when it converges; it has no time limit.}
  \cgalParamNEnd

  \cgalParamNBegin{lloyd_iterations}
    \cgalParamDescription{the number of iterations of Mesh_3's Lloyd smoothing (`CGAL::lloyd_optimize_mesh_3()`), run
                          after ODT; `0` skips it (`Distortion_optimization::parameters::lloyd_iterations()`)}
    \cgalParamType{`int`}
    \cgalParamDefault{`0`}
    \cgalParamExtra{It must be non-negative. It has no time limit.}
  \cgalParamNEnd

  \cgalParamNBegin{perturb_slivers}
    \cgalParamDescription{if `true`, Mesh_3's sliver perturbation (`CGAL::perturb_mesh_3()`) runs after the smoothers
                          (`Distortion_optimization::parameters::perturb_slivers()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd

  \cgalParamNBegin{exude_slivers}
    \cgalParamDescription{if `true`, Mesh_3's sliver exudation (`CGAL::exude_mesh_3()`) runs last, on every cell
                          (`Distortion_optimization::parameters::exude_slivers()`); if `false`, only on the cells
                          with a dihedral angle below 2 degrees}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd

  \cgalParamNBegin{maximum_number_of_vertices}
    \cgalParamDescription{the number of vertices at which Mesh_3 stops and this function throws; `0` for no limit
                          (`Distortion_optimization::parameters::maximum_number_of_vertices()`)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{10 times the number of vertices the sizes ask for,
                      `V / (0.2 cell_size^3) / 5.5 + A / (0.3 facet_size^2) / 2` (at least 10^4, at most 10^15)}
    \cgalParamExtra{Mesh_3 checks it while refining, not while protecting the sharp edges. Sizes that ask for more
                    vertices than this maximum (when it is given and not 0), or than 2 million (when it is not
                    given: Mesh_3 and a map of the package take a few kilobytes a vertex), are refused before
                    Mesh_3 starts.}
  \cgalParamNEnd

  \cgalParamNBegin{meshing_time_limit}
    \cgalParamDescription{the seconds after which Mesh_3's refinement (with the protection of the sharp edges) is
                          stopped and this function throws; `0` for no limit
                          (`Distortion_optimization::parameters::meshing_time_limit()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
    \cgalParamExtra{A complex that Mesh_3 finishes within the limit is the same as without it; the repairs after
                    the refinement are not timed.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the complex, of type `Interior_mesh<GeomTraits>::C3T3`.
\throws Invalid_input, naming the offending input element, if `surface` is empty, has a face
that is not a triangle, a non-finite coordinate or one beyond 1e100 in magnitude, a border edge, a non-manifold vertex, a
degenerate face or two faces that cross, encloses no volume, is thinner than the facet distance
(its mean thickness, 2 volume / area, is smaller) or, as a slab (a surface whose faces spread ten
times less in one direction than in the others), than half the facet size (a plate 0.02 thick
meshed at a facet size of 0.058 came out with touching tetrahedra, at 0.035 it came out right), or
is a slab whose rim is a knife edge (a sharp edge, per `sharp_edge_angle`, whose faces' normals
differ by more than 150 degrees: Mesh_3 would protect it for minutes at any size), or has a
needle's tip (a vertex whose faces' angles there sum to less than 3 degrees: Mesh_3 would take
minutes about it, or fail; the error names a face with that corner), or
has a component that is (2 |volume| / area of that component; the error names one of its faces),
has two components closer than the facet
distance (the error names a face of each) or two sharp edges (those protected, see
`sharp_edge_angle`) closer than it along more than the edge size that meet only farther away,
such as the two sides of a slit (Mesh_3 would protect them with balls no larger than the gap,
for minutes or without end; the error names their vertices), if a size is not a positive finite
number (or an angle or ratio is out of its range), if the sizes ask for more vertices than
`maximum_number_of_vertices` allows (2 million by default), if Mesh_3 reaches
`maximum_number_of_vertices` or runs longer than `meshing_time_limit`, if a check of CGAL's own
fails inside Mesh_3 (the error gives its first line and place), if the complex has no cell or a component of the surface gets no
tetrahedron even when seeded (the error names one of its faces), if the boundary of the complex
is not a 2-manifold after the changes of sides above (tetrahedra that touch only along an edge
or at a vertex, where parts of the surface are closer than the sizes: the error gives the place;
smaller sizes may be the remedy), if that boundary's components and their genera are not the
surface's (a neck or gap finer than the sizes was cut or bridged: a sphere pinched to a waist of
radius 0.005 came out as a torus at the default sizes; smaller sizes are the remedy), or
if the surface is so far from the origin for its size that a cell of the complex, its points
rounded to the input's precision, is not positively oriented.
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Interior_mesh<GeomTraits>::C3T3
#else
typename Interior_mesh<internal::Interior_mesh_traits_of<NamedParameters>>::C3T3
#endif
mesh_interior(const TriangleMesh& surface, const NamedParameters& np = CGAL::parameters::default_values())
{
  using GT = internal::Interior_mesh_traits_of<NamedParameters>;
  using Types = Interior_mesh<GT>;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const internal::Checked_surface<typename Types::Surface, TriangleMesh> checked(surface, np);
  const Interior_mesh_sizes sizes = internal::read_interior_mesh_sizes(checked.volume, checked.area, checked.scale, np);
  internal::Mesh_3_settings settings;
  settings.odt_iterations = choose_parameter(get_parameter(np, internal_np::odt_iterations), 0);
  settings.lloyd_iterations = choose_parameter(get_parameter(np, internal_np::lloyd_iterations), 0);
  settings.perturb_slivers = choose_parameter(get_parameter(np, internal_np::perturb_slivers), false);
  settings.exude_slivers = choose_parameter(get_parameter(np, internal_np::exude_slivers), false);
  settings.time_limit = choose_parameter(get_parameter(np, internal_np::meshing_time_limit), 0.);
  if(!(settings.time_limit >= 0) || !std::isfinite(settings.time_limit))
    throw Invalid_input("mesh_interior: the meshing time limit must be a number of seconds >= 0, not " +
                        internal::shown_number(settings.time_limit));
  if(settings.odt_iterations < 0 || settings.lloyd_iterations < 0)
    throw Invalid_input("mesh_interior: the numbers of ODT and Lloyd iterations must be >= 0");
  const double asked = internal::asked_vertices(checked.volume, checked.area, sizes.cell_size, sizes.facet_size);
  const auto given_maximum = get_parameter(np, internal_np::maximum_number_of_vertices);
  constexpr bool maximum_given = !std::is_same<std::decay_t<decltype(given_maximum)>, CGAL::internal_np::Param_not_found>::value;
  // (At least 10^4: Mesh_3 needs some vertices to follow any surface, however large the sizes.)
  const std::size_t maximum_vertices =
    choose_parameter(given_maximum, static_cast<std::size_t>((std::min)((std::max)(10 * asked, 1e4), 1e15)));
  settings.asked_vertices = asked;
  settings.maximum_vertices = maximum_vertices;
  settings.maximum_given = maximum_given;
  return internal::mesh_interior_impl<Types>(checked, sizes, settings);
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_MESH_INTERIOR_H
