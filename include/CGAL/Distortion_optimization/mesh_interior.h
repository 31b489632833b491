// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The first step of the volume workflow: a tetrahedral mesh of the inside of a closed triangle
// surface, made by CGAL's Mesh_3, ready for the start maps of volume_maps.h and for
// CGAL::minimize_distortion(). The steps, in order:
//   1. check the surface (never modified): not empty, triangles only, finite coordinates, closed,
//      2-manifold, no self-intersection; copy it, oriented to bound its volume, which must be
//      positive;
//   2. sizes: the user's, else defaults that scale with the enclosed volume (and the area), so
//      that any input, at any scale, gives about the same number of tetrahedra;
//   3. domain: Polyhedral_mesh_domain_with_features_3 on the copy, sharp edges detected and
//      protected (a smooth surface has none);
//   4. Delaunay refinement (make_mesh_3) with a seeded random generator; a component of the
//      surface that Mesh_3's initial points missed gets seeds of its own and the refinement goes on
//      (refine_mesh_3); then the optional optimizers (ODT, Lloyd, perturbation, exudation) without
//      time limits: the output depends only on the input and the parameters.
// Mesh_3 runs on a copy scaled by a power of two to unit size, and its complex is scaled back:
// Mesh_3 has absolute tolerances (it crashed on a surface 2^-60 in size and hung at 2^-40), and
// an exact scaling makes the mesh of a scaled surface the scaled mesh. A surface far from the
// origin for its size is moved near it first, exactly (its coordinates keep too few digits below
// its distance: a sphere of radius 0.5 at 10^12 hung Mesh_3), and the complex moved back.

#ifndef CGAL_DISTORTION_OPTIMIZATION_MESH_INTERIOR_H
#define CGAL_DISTORTION_OPTIMIZATION_MESH_INTERIOR_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/number_types.h>
#include <CGAL/Distortion_optimization/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/make_mesh_3.h>      // before the optimizers' headers, which miss some of its includes
#include <CGAL/refine_mesh_3.h>    // refine_mesh_3 and Mesh_3's optimizers

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

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
enum cell_radius_edge_ratio_t { cell_radius_edge_ratio };
enum facet_size_t { facet_size };
enum facet_distance_t { facet_distance };
enum facet_angle_t { facet_angle };
enum edge_size_t { edge_size };
enum sharp_edge_angle_t { sharp_edge_angle };
enum odt_iterations_t { odt_iterations };
enum lloyd_iterations_t { lloyd_iterations };
enum perturb_slivers_t { perturb_slivers };
enum exude_slivers_t { exude_slivers };
enum maximum_number_of_vertices_t { maximum_number_of_vertices };
} // namespace internal_np

namespace parameters {

/// `mesh_interior()`: upper bound on the circumradius of the tetrahedra (a length, > 0). Default:
/// the size that gives about 3.10^4 tetrahedra (see `mesh_interior()`).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cell_size_t, cell_size)
/// `mesh_interior()`: upper bound on circumradius / shortest edge of the tetrahedra (>= 2, where
/// Mesh_3 is proved to terminate). Default 3.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cell_radius_edge_ratio_t, cell_radius_edge_ratio)
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
/// `mesh_interior()`: an input edge is sharp, and kept as a polyline of the output, when the
/// normals of its two faces make an angle larger than this, in degrees, in (0, 180]; 180 keeps no
/// edge (better for noisy scanned surfaces, whose spurious sharp edges make small tetrahedra).
/// Default 60 (Mesh_3's).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(sharp_edge_angle_t, sharp_edge_angle)
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
/// refining, not while protecting the sharp edges: on mpi_triang.off the error comes after about
/// 60 s (a full run took 440 s and 7.10^5 tetrahedra).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(maximum_number_of_vertices_t, maximum_number_of_vertices)


} // namespace parameters

namespace internal {

// The defaults of mesh_interior(), measured on real surfaces (see mesh_interior()).
struct Interior_mesh_defaults
{
  static constexpr double cells = 3e4;              // the target number of tetrahedra
  static constexpr double volume_per_cell = 0.2;     // tetrahedron volume / cell_size^3 observed
  static constexpr double area_per_facet = 0.3;      // boundary facet area / facet_size^2 observed
  static constexpr double cells_per_vertex = 5.5;    // in a Delaunay tetrahedral mesh
  static constexpr double boundary_facets = 8e3;     // at most this many boundary facets by default
  static constexpr double distance_ratio = 0.1;      // facet_distance / facet_size
  static constexpr double facet_angle = 25;
  static constexpr double radius_edge_ratio = 3;
  static constexpr double sharp_edge_angle = 60;
  // Without exude_slivers, Mesh_3's exudation still runs on the cells with a dihedral angle below
  // this (degrees): a few milliseconds (see mesh_interior()).
  static constexpr double sliver_bound = 2;
};

// A checked copy of the input surface for the domain, oriented to bound its volume, moved by
// -offset (exactly, where the surface is far from the origin for its size; else 0) and scaled by
// `scale`, the power of two that brings its largest extent into [1, 2). The copy is
// rebuilt from a canonical soup (points and triangles in the input's order, each triangle starting
// at its smallest vertex), so that it, and the mesh, depend only on the geometry and that order:
// not on the input's orientation or on which halfedge each face stores.
template <class GeomTraits, class TriangleMesh>
struct Checked_surface
{
  using Surface = typename Interior_mesh<GeomTraits>::Surface;
  using Point_3 = typename GeomTraits::Point_3;
  using Triangle = std::array<std::size_t, 3>;

  Surface surface;   // the input moved by -offset, then scaled by `scale`
  std::vector<std::size_t> face_names;   // the input's index of each face of `surface`
  std::vector<std::size_t> vertex_names; // the input's index of each vertex of `surface`
  std::vector<std::size_t> component;    // the connected component of each face of `surface`
  std::vector<double> component_volume, component_area;   // unscaled; a cavity's volume is negative
  double scale = 1;
  std::array<double, 3> offset = {0, 0, 0};
  double volume = 0; // of the input, unscaled
  double area = 0;   // of the input, unscaled

  template <class NamedParameters>
  Checked_surface(const TriangleMesh& tm, const NamedParameters& np)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, tm));
    // Elements are named by their indices (for a Surface_mesh, v.idx() and f.idx()).
    const auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np);
    const auto face_index = CGAL::get_initialized_face_index_map(tm, np);
    auto vertex_name = [&](auto v) { return "vertex " + std::to_string(std::size_t(get(vertex_index, v))); };
    auto face_name = [&](auto f) { return std::to_string(std::size_t(get(face_index, f))); };

    if(faces(tm).begin() == faces(tm).end())
      throw Invalid_input("mesh_interior: the surface is empty (it has no face)");
    for(auto f : faces(tm)) {
      const std::size_t degree = halfedges_around_face(halfedge(f, tm), tm).size();
      if(degree != 3)
        throw Invalid_input("mesh_interior: the surface is not a triangle mesh: face " + face_name(f) + " has " +
                            std::to_string(degree) + " vertices");
    }
    // The soup numbers vertices in iteration order: index maps may have gaps (a Surface_mesh with
    // removed elements), `compact` closes them.
    std::vector<Point_3> points;
    std::vector<std::size_t> compact;
    for(auto v : vertices(tm)) {
      const auto& p = get(vpm, v);
      const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
      if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        throw Invalid_input("mesh_interior: " + vertex_name(v) + " has a non-finite coordinate");
      const std::size_t i = get(vertex_index, v);
      if(compact.size() <= i) compact.resize(i + 1);
      compact[i] = points.size();
      points.emplace_back(x, y, z);
      vertex_names.push_back(i);
    }
    for(auto h : halfedges(tm))
      if(is_border(h, tm))
        throw Invalid_input("mesh_interior: the surface is not closed: the edge from " + vertex_name(source(h, tm)) +
                            " to " + vertex_name(target(h, tm)) + " is on a border");
    // One halfedge per umbrella of each non-manifold vertex.
    std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> umbrellas;
    PMP::non_manifold_vertices(tm, std::back_inserter(umbrellas));
    if(!umbrellas.empty())
      throw Invalid_input("mesh_interior: the surface is not 2-manifold: the faces around " +
                          vertex_name(target(umbrellas.front(), tm)) + " do not form a single disk");
    // The first pair found is enough to name (a degenerate face comes as the pair (f, f)).
    using Input_face = typename boost::graph_traits<TriangleMesh>::face_descriptor;
    std::vector<std::pair<Input_face, Input_face>> crossing;
    PMP::self_intersections(tm, std::back_inserter(crossing),
                            CGAL::parameters::vertex_point_map(vpm).maximum_number(1));
    if(!crossing.empty()) {
      const auto& [f, g] = crossing.front();
      if(f == g)
        throw Invalid_input("mesh_interior: face " + face_name(f) + " of the surface is degenerate (flat)");
      throw Invalid_input("mesh_interior: the surface intersects itself: faces " + face_name(f) + " and " +
                          face_name(g) + " cross");
    }

    std::vector<Triangle> triangles;
    for(auto f : faces(tm)) {
      Triangle t;
      std::size_t k = 0;
      for(auto h : halfedges_around_face(halfedge(f, tm), tm)) t[k++] = compact[get(vertex_index, target(h, tm))];
      triangles.push_back(t);
      face_names.push_back(get(face_index, f));
    }
    // Half extents: a surface from -2^1023 to 2^1023 has an extent of 2^1024, beyond doubles.
    const Bbox_3 box = bbox_3(points.begin(), points.end());
    double half_extent = 0;
    for(int k = 0; k < 3; ++k) half_extent = (std::max)(half_extent, box.max_coord(k) / 2 - box.min_coord(k) / 2);
    scale = unit_scale(half_extent) / 2;
    // Along an axis where the box lies within [m, 2 m] for its lower bound m > 0 (or [2 m, m] for
    // its upper bound m < 0), p - m is exact (Sterbenz): the copy starts there. Elsewhere the box
    // is at most its extent from the origin, near enough.
    for(int k = 0; k < 3; ++k) {
      const double low = box.min_coord(k), high = box.max_coord(k);
      if(low > 0 && high <= 2 * low) offset[k] = low;
      if(high < 0 && low >= 2 * high) offset[k] = high;
    }
    std::vector<Point_3> scaled;
    for(const Point_3& p : points)
      scaled.emplace_back(scale * (CGAL::to_double(p.x()) - offset[0]), scale * (CGAL::to_double(p.y()) - offset[1]),
                          scale * (CGAL::to_double(p.z()) - offset[2]));
    // Mesh_3 tells inside from outside by ray parity, so orientation does not change the volume
    // it meshes; orienting makes the volume below positive and the copy independent of the input's
    // orientation (orient a first build, then read its triangles back).
    Surface first = build(scaled, triangles);
    PMP::orient_to_bound_a_volume(first);
    for(auto f : faces(first)) {
      Triangle& t = triangles[std::size_t(f)];
      std::size_t k = 0;
      for(auto v : vertices_around_face(halfedge(f, first), first)) t[k++] = std::size_t(v);
    }
    surface = build(scaled, triangles);
    // The volume, as tetrahedra from the centre of the bounding box in units of its largest extent:
    // PMP::volume() sums them from the origin, where far from it rounding swamps the volume (a unit
    // sphere centred at (10^9, 10^9, 10^9) measured no volume at all).
    const auto unit = [&](std::size_t i) {
      std::array<double, 3> u;
      for(int k = 0; k < 3; ++k)
        u[k] = (CGAL::to_double(points[i][k]) / 2 - (box.min_coord(k) / 2 + box.max_coord(k) / 2) / 2) / half_extent;
      return u;
    };
    component.resize(triangles.size());
    const std::size_t components = PMP::connected_components(surface, CGAL::make_property_map(component));
    std::vector<double> unit_volumes(components, 0.);
    component_area.assign(components, 0.);
    double scaled_area = 0;   // PMP::area(surface), summed in its order
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      const Triangle& t = triangles[i];
      const auto a = unit(t[0]), b = unit(t[1]), c = unit(t[2]);
      unit_volumes[component[i]] += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
      const double face_area = CGAL::to_double(PMP::face_area(typename Surface::Face_index(i), surface));
      scaled_area += face_area;
      component_area[component[i]] += face_area;
    }
    for(double& a : component_area) a = a / scale / scale;
    double unit_volume = 0;
    for(double v : unit_volumes) {
      unit_volume += v;
      component_volume.push_back(v * (2 * half_extent) * (2 * half_extent) * (2 * half_extent));
    }
    if(!(unit_volume > 0) || !std::isfinite(unit_volume))
      throw Invalid_input("mesh_interior: the surface encloses no volume");
    volume = unit_volume * (2 * half_extent) * (2 * half_extent) * (2 * half_extent);
    area = scaled_area / scale / scale;
    if(!(volume > 0) || !std::isfinite(volume) || !(area > 0) || !std::isfinite(area))
    {
      char size[32];
      std::snprintf(size, sizeof size, "%g", 2 * half_extent);
      throw Invalid_input(std::string("mesh_interior: the surface's size (") + size +
                          ") is too large or too small for its volume in double precision: scale it");
    }
  }

  // The surface of the triangles, each rotated to start at its smallest index (vertex i of the
  // result is points[i]).
  static Surface build(const std::vector<Point_3>& points, std::vector<Triangle> triangles)
  {
    for(Triangle& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(triangles))
      throw Invalid_input("mesh_interior: the triangles of the surface do not form an oriented 2-manifold");
    Surface s;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, s);
    return s;
  }
};

inline void check_size(double value, const char* name)
{
  if(!(value > 0) || !std::isfinite(value))
    throw Invalid_input(std::string("mesh_interior: ") + name + " must be a positive finite number, not " +
                        std::to_string(value));
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
    throw Invalid_input("mesh_interior: the facet angle must be in (0, 30] degrees, not " + std::to_string(s.facet_angle));
  s.cell_radius_edge_ratio = choose_parameter(get_parameter(np, internal_np::cell_radius_edge_ratio), D::radius_edge_ratio);
  if(!(s.cell_radius_edge_ratio >= 2) || !std::isfinite(s.cell_radius_edge_ratio))
    throw Invalid_input("mesh_interior: the cell radius-edge ratio must be a finite number >= 2, not " +
                        std::to_string(s.cell_radius_edge_ratio));
  s.sharp_edge_angle = choose_parameter(get_parameter(np, internal_np::sharp_edge_angle), D::sharp_edge_angle);
  if(!(s.sharp_edge_angle > 0 && s.sharp_edge_angle <= 180))
    throw Invalid_input("mesh_interior: the sharp edge angle must be in (0, 180] degrees, not " +
                        std::to_string(s.sharp_edge_angle));
  return s;
}

// Maps the complex that Mesh_3 made by x -> factor x + offset (factor a power of two): the points
// and their weights (squared lengths), the facets' surface centres and the sizes Mesh_3's
// optimizers keep in the vertices; the cells' cached circumcentres are dropped, to be computed
// again when asked for. Exact without offset. With one, the points are rounded to the input's
// coordinates: throws if a cell of the complex is then no longer positively oriented.
template <class C3T3>
void map_complex_back(C3T3& c3t3, double factor, const std::array<double, 3>& offset)
{
  using Tr = typename C3T3::Triangulation;
  using Bare_point = typename Tr::Bare_point;
  using Weighted_point = typename Tr::Weighted_point;
  const bool moved = offset != std::array<double, 3>{0, 0, 0};
  if(factor == 1 && !moved) return;
  Tr& tr = c3t3.triangulation();
  const auto mapped = [&](const Bare_point& p) {
    return Bare_point(factor * CGAL::to_double(p.x()) + offset[0], factor * CGAL::to_double(p.y()) + offset[1],
                      factor * CGAL::to_double(p.z()) + offset[2]);
  };
  const auto point = tr.geom_traits().construct_point_3_object();
  for(auto v : tr.finite_vertex_handles()) {
    const Weighted_point& p = v->point();
    v->set_point(Weighted_point(mapped(point(p)), factor * factor * CGAL::to_double(p.weight())));
    v->set_meshing_info(factor * v->meshing_info());
  }
  for(auto c : tr.all_cell_handles()) {
    c->invalidate_weighted_circumcenter_cache();
    for(int i = 0; i < 4; ++i) c->set_facet_surface_center(i, mapped(c->get_facet_surface_center(i)));
  }
  if(!moved) return;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    if(CGAL::orientation(point(tr.point(c, 0)), point(tr.point(c, 1)), point(tr.point(c, 2)), point(tr.point(c, 3))) != CGAL::POSITIVE)
      throw Invalid_input("mesh_interior: the surface is too far from the origin for its size: its tetrahedra, rounded "
                          "to its coordinates' precision, are no longer all positively oriented; move it nearer to the origin");
}

// The three corners of face f of `surface` (a Surface_mesh of triangles).
template <class Surface>
std::array<typename Surface::Point, 3> corners(const Surface& surface, typename Surface::Face_index f)
{
  std::array<typename Surface::Point, 3> p;
  std::size_t k = 0;
  for(auto v : vertices_around_face(halfedge(f, surface), surface)) p[k++] = surface.point(v);
  return p;
}

// Mesh_3 finds the surface from its initial points, the hits of rays cast from the centre of the
// bounding box, or, where sharp edges are protected, only from the protecting balls; it then refines
// around the facets they make. A component of the surface that none of them reaches (a small sphere
// beside a large one or beside a cube, an island in a hollow ball) gets no facet and no tetrahedron.
// Returns, for each component of `surface` (the domain's; `component` numbers them per face) that
// bounds no tetrahedron of `c3t3` (no boundary facet of it has a cell of the complex on a side),
// points of it with their indices in `domain`: where short segments across its faces that lie
// outermost along +-x, +-y, +-z and +-(1, 1, 1) meet the surface; `missed` gets the index of one
// face of each such component.
template <class C3T3, class Domain, class Surface>
std::vector<std::pair<typename Domain::Point_3, typename Domain::Index>>
seeds_of_missed_components(const C3T3& c3t3, const Domain& domain, const Surface& surface,
                           const std::vector<std::size_t>& component, std::vector<std::size_t>& missed)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point_3 = typename Domain::Point_3;
  using K = typename Kernel_traits<Point_3>::Kernel;
  using Vector_3 = typename K::Vector_3;
  using Face = typename boost::graph_traits<Surface>::face_descriptor;
  std::vector<std::pair<Point_3, typename Domain::Index>> seeds;
  missed.clear();
  const std::size_t count = component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  if(count < 2) return seeds;

  // A facet of the complex lies on the component of the face nearest to its first vertex. A facet
  // with no cell of the complex on either side bounds nothing (the two sides of a flat component).
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Surface>>>;
  const Tree tree(faces(surface).first, faces(surface).second, surface);
  std::vector<bool> meshed(count, false);
  const auto point = c3t3.triangulation().geom_traits().construct_point_3_object();
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    if(c3t3.is_in_complex(f->first) || c3t3.is_in_complex(f->first->neighbor(f->second)))
      meshed[component[tree.closest_point_and_primitive(point(f->first->vertex((f->second + 1) % 4)->point())).second]] = true;

  const Vector_3 directions[8] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}, {-1, -1, -1}};
  std::vector<std::array<Face, 8>> outermost(count);
  std::vector<std::array<double, 8>> extent(count);
  for(auto& e : extent) e.fill(-std::numeric_limits<double>::infinity());
  const auto centroid = [&](Face f) {
    const auto p = corners(surface, f);
    return CGAL::centroid(p[0], p[1], p[2]);
  };
  for(Face f : faces(surface)) {
    const std::size_t c = component[f];
    if(meshed[c]) continue;
    if(extent[c][0] == -std::numeric_limits<double>::infinity()) missed.push_back(std::size_t(f));   // its first face
    const Vector_3 m = centroid(f) - CGAL::ORIGIN;
    for(int d = 0; d < 8; ++d) {
      const double along = CGAL::to_double(m * directions[d]);
      if(along > extent[c][d]) { extent[c][d] = along; outermost[c][d] = f; }
    }
  }
  const auto intersection = domain.construct_intersection_object();
  for(std::size_t c = 0; c < count; ++c) {
    if(meshed[c]) continue;
    for(int d = 0; d < 8; ++d) {
      const Face f = outermost[c][d];
      if(d > 0 && std::find(outermost[c].begin(), outermost[c].begin() + d, f) != outermost[c].begin() + d) continue;
      // Across the face at its centroid, a hundredth of its size to each side.
      const Vector_3 across = 0.01 * std::sqrt(CGAL::to_double(PMP::face_area(f, surface))) * PMP::compute_face_normal(f, surface);
      const Point_3 middle = centroid(f);
      const auto hit = intersection(typename K::Segment_3(middle - across, middle + across));
      if(std::get<2>(hit) != 0) seeds.emplace_back(std::get<0>(hit), std::get<1>(hit));
    }
  }
  return seeds;
}

// Whether facet i of cell c, in the complex, is on its boundary (the cell across is not).
template <class C3T3>
bool is_boundary_facet(const C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c, int i)
{
  return !c3t3.is_in_complex(c->neighbor(i));
}

// Takes cell c out of the complex (`in` false) or into it (`in` true, with the subdomain index
// `subdomain`), and makes its facets follow: a facet between a cell of the complex and another
// is a facet of the complex (a new one with the surface patch index `patch`), and no other.
template <class C3T3>
void set_in_complex(C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c, bool in,
                    const typename C3T3::Subdomain_index& subdomain, const typename C3T3::Surface_patch_index& patch)
{
  if(in) c3t3.add_to_complex(c, subdomain);
  else c3t3.remove_from_complex(c);
  for(int i = 0; i < 4; ++i) {
    const bool boundary = in != c3t3.is_in_complex(c->neighbor(i));
    if(c3t3.is_in_complex(c, i) && !boundary) c3t3.remove_from_complex(c, i);
    else if(!c3t3.is_in_complex(c, i) && boundary) c3t3.add_to_complex(c, i, patch);
  }
}

// Makes the facets of the complex the boundary of its cells: Mesh_3's facets are those whose dual
// Voronoi edge crosses the surface, and its cells those whose circumcentre is inside, which
// disagree in a few places (dino.off: 176 edges of its facets have four or more). A facet added
// takes the surface patch index of a facet of the complex that shares a cell with it, or else the
// first facet's. Returns the number of facets added or removed.
template <class C3T3>
std::size_t match_facets_to_cells(C3T3& c3t3)
{
  using Facet = typename C3T3::Triangulation::Facet;
  if(c3t3.number_of_facets_in_complex() == 0) return 0;
  const auto first = *c3t3.facets_in_complex_begin();
  const auto default_patch = c3t3.surface_patch_index(first.first, first.second);
  std::vector<Facet> extra, missing;
  for(auto f = c3t3.triangulation().finite_facets_begin(); f != c3t3.triangulation().finite_facets_end(); ++f) {
    const bool boundary = c3t3.is_in_complex(f->first) != c3t3.is_in_complex(f->first->neighbor(f->second));
    if(boundary != c3t3.is_in_complex(*f)) (boundary ? missing : extra).push_back(*f);
  }
  for(const Facet& f : extra) c3t3.remove_from_complex(f);
  for(const Facet& f : missing) {
    auto patch = default_patch;
    for(const auto c : {f.first, f.first->neighbor(f.second)})
      for(int i = 0; i < 4; ++i)
        if(c3t3.is_in_complex(c, i)) patch = c3t3.surface_patch_index(c, i);
    c3t3.add_to_complex(f, patch);
  }
  return extra.size() + missing.size();
}

// The vertices on the boundary of the complex, first seen first in the order of its cells.
template <class C3T3>
std::vector<typename C3T3::Triangulation::Vertex_handle> boundary_vertices_in_order(const C3T3& c3t3)
{
  std::vector<typename C3T3::Triangulation::Vertex_handle> order;
  std::unordered_set<typename C3T3::Triangulation::Vertex_handle> seen;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(is_boundary_facet(c3t3, c, i))
        for(int k = 1; k < 4; ++k)
          if(seen.insert(c->vertex((i + k) % 4)).second) order.push_back(c->vertex((i + k) % 4));
  return order;
}

// The signed volume of cell c of the triangulation of the complex (finite).
template <class C3T3>
double cell_volume(const C3T3& c3t3, typename C3T3::Triangulation::Cell_handle c)
{
  const auto& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  return CGAL::to_double(CGAL::volume(point(tr.point(c, 0)), point(tr.point(c, 1)), point(tr.point(c, 2)), point(tr.point(c, 3))));
}

// Mesh_3 leaves a few flat caps on the surface: cells with two boundary facets and all four
// vertices on the surface, their two other facets nearly in the same place (the two diagonals of
// a nearly flat quadrilateral). They hold no volume, and a start map that bends the surface (the
// radial map, the ball map) can turn one over with all its vertices fixed, where no optimization
// can undo it (blobby, elephant, fandisk, eight and hand of libcgal-demo: one or two each, their
// smallest dihedral angles 0.08 to 1.5 degrees). A cap thinner than `thickness` (3 volume / the
// area A of its boundary facets; the facet distance: the surface stays as close) and than a tenth
// of its width (sqrt(A): a regular tetrahedron's is 0.44, and a small cell across a sharp edge
// stays) leaves the complex, its two inner facets becoming boundary facets, unless the edge they
// share is already on the boundary (the surface would no longer be a manifold there). Repeated
// while some cap goes: a peeled cap may uncover another. Returns the number of cells removed.
template <class C3T3>
std::size_t peel_flat_caps(C3T3& c3t3, double thickness)
{
  using Cell_handle = typename C3T3::Triangulation::Cell_handle;
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  const auto& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  const auto area = [&](Cell_handle c, int i) {
    return std::sqrt(CGAL::to_double(CGAL::squared_area(point(tr.point(c, (i + 1) % 4)), point(tr.point(c, (i + 2) % 4)),
                                                        point(tr.point(c, (i + 3) % 4)))));
  };
  // Whether the edge (c, a, b) has a boundary facet.
  const auto on_boundary = [&](Cell_handle c, int a, int b) {
    auto f = tr.incident_facets(typename C3T3::Triangulation::Edge(c, a, b)), end = f;
    do {
      if(c3t3.is_in_complex(f->first) != c3t3.is_in_complex(f->first->neighbor(f->second))) return true;
    } while(++f != end);
    return false;
  };
  // Peeling keeps these: a cap's new boundary facets have its four vertices, already on the surface.
  const auto boundary_vertices = boundary_vertices_in_order(c3t3);
  const std::unordered_set<Vertex_handle> surface_vertex(boundary_vertices.begin(), boundary_vertices.end());
  std::size_t peeled = 0;
  for(bool more = true; more;) {
    more = false;
    std::vector<Cell_handle> caps;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      int facets = 0;
      for(int i = 0; i < 4; ++i) facets += is_boundary_facet(c3t3, c, i) ? 1 : 0;
      if(facets != 2) continue;
      bool all_on_surface = true;
      for(int i = 0; i < 4 && all_on_surface; ++i) all_on_surface = surface_vertex.count(c->vertex(i)) > 0;
      if(!all_on_surface) continue;
      double boundary_area = 0;
      for(int i = 0; i < 4; ++i)
        if(is_boundary_facet(c3t3, c, i)) boundary_area += area(c, i);
      const double volume = std::abs(cell_volume(c3t3, c));
      if(3 * volume < (std::min)(thickness, 0.1 * std::sqrt(boundary_area)) * boundary_area) caps.push_back(c);
    }
    for(Cell_handle c : caps) {
      // The vertices opposite the boundary facets span the edge that the inner facets share.
      int opposite[2], k = 0;
      for(int i = 0; i < 4; ++i)
        if(is_boundary_facet(c3t3, c, i) && k < 2) opposite[k++] = i;
      if(k != 2 || !c3t3.is_in_complex(c) || on_boundary(c, opposite[0], opposite[1])) continue;   // (an earlier peel may have changed it)
      set_in_complex(c3t3, c, false, c3t3.subdomain_index(c), c3t3.surface_patch_index(c, opposite[0]));
      ++peeled;
      more = true;
    }
  }
  return peeled;
}

// Mesh_3 can leave cells flat to rounding inside the complex where four of its points are coplanar
// and cospherical (the square sections of a 40 x 0.1 x 0.1 bar: 15 of 15194 cells, all four
// vertices on the surface, which exudation does not move). No map of such a cell has a Jacobian.
// Each is flipped away among cells of the complex: an edge of it with three cells around goes by a
// 3-2 flip; one with four, by a 2-3 flip of a facet around it that is not the flat cell's, then the
// 3-2 flip. The triangulation stays valid, its cells positive (CGAL's flips test that), but is no
// longer the regular one. Boundary facets keep their surface patches. Returns the number of flat
// cells that remain (those whose edges all have more cells around).
template <class C3T3>
std::size_t flip_flat_cells(C3T3& c3t3)
{
  using Tr = typename C3T3::Triangulation;
  using Cell_handle = typename Tr::Cell_handle;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Triple = std::array<Vertex_handle, 3>;
  Tr& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  const auto is_flat = [&](Cell_handle c) {
    double longest = 0;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        longest = (std::max)(longest, CGAL::to_double(CGAL::squared_distance(point(tr.point(c, i)), point(tr.point(c, j)))));
    return std::abs(cell_volume(c3t3, c)) <= 1e-12 * longest * std::sqrt(longest);
  };
  const auto triple = [](Cell_handle c, int i) {
    Triple t{c->vertex((i + 1) % 4), c->vertex((i + 2) % 4), c->vertex((i + 3) % 4)};
    std::sort(t.begin(), t.end());
    return t;
  };
  const auto around = [&](Cell_handle c, int i, int j) {
    std::vector<Cell_handle> cells;
    auto cell = tr.incident_cells(typename Tr::Edge(c, i, j)), end = cell;
    do cells.push_back(cell); while(++cell != end);
    return cells;
  };
  // Takes `cells` out of the complex, remembering their boundary facets' patches; `flip` runs the
  // flip and returns the cells it made (none if it failed), which join the complex.
  const auto replace = [&](const std::vector<Cell_handle>& cells, const auto& flip) {
    const auto subdomain = c3t3.subdomain_index(cells.front());
    std::map<Triple, typename C3T3::Surface_patch_index> patch;
    for(Cell_handle c : cells) {
      if(tr.is_infinite(c) || !c3t3.is_in_complex(c) || c3t3.subdomain_index(c) != subdomain) return false;
      for(int i = 0; i < 4; ++i)
        if(c3t3.is_in_complex(c, i)) patch[triple(c, i)] = c3t3.surface_patch_index(c, i);
    }
    for(Cell_handle c : cells) {
      for(int i = 0; i < 4; ++i)
        if(c3t3.is_in_complex(c, i)) c3t3.remove_from_complex(c, i);
      c3t3.remove_from_complex(c);
    }
    std::vector<Cell_handle> made = flip();
    const bool flipped = !made.empty();
    if(!flipped) made = cells;
    for(Cell_handle c : made) c3t3.add_to_complex(c, subdomain);
    for(Cell_handle c : made)
      for(int i = 0; i < 4; ++i)
        if(const auto p = patch.find(triple(c, i)); p != patch.end()) c3t3.add_to_complex(c, i, p->second);
    return flipped;
  };
  // The 3-2 flip of the edge (c, i, j): the two new cells share the facet of its ring.
  const auto flip_edge = [&](Cell_handle c, int i, int j) {
    const std::vector<Cell_handle> cells = around(c, i, j);
    if(cells.size() != 3) return false;
    const Vertex_handle a = c->vertex(i), b = c->vertex(j);
    std::vector<Vertex_handle> ring;
    for(Cell_handle x : cells)
      for(int k = 0; k < 4; ++k)
        if(x->vertex(k) != a && x->vertex(k) != b && std::find(ring.begin(), ring.end(), x->vertex(k)) == ring.end())
          ring.push_back(x->vertex(k));
    return replace(cells, [&] {
      if(!tr.flip(c, i, j)) return std::vector<Cell_handle>();
      Cell_handle n;
      int u, v, w;
      tr.is_facet(ring[0], ring[1], ring[2], n, u, v, w);
      return std::vector<Cell_handle>{n, n->neighbor(6 - u - v - w)};
    });
  };
  // The 2-3 flip of facet k of cell x: the three new cells share the edge between the apexes.
  const auto flip_facet = [&](Cell_handle x, int k) {
    const Cell_handle y = x->neighbor(k);
    const Vertex_handle s = x->vertex(k), t = y->vertex(y->index(x));
    return replace({x, y}, [&] {
      if(!tr.flip(x, k)) return std::vector<Cell_handle>();
      Cell_handle n;
      int u, v;
      tr.is_edge(s, t, n, u, v);
      return around(n, u, v);
    });
  };

  // Flips c away; false where none of the flips above applies.
  const auto flip_away = [&](Cell_handle c) {
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(flip_edge(c, i, j)) return true;   // (false, untouched, unless three cells are around)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const Vertex_handle a = c->vertex(i), b = c->vertex(j);
        const std::vector<Cell_handle> cells = around(c, i, j);
        if(cells.size() != 4) continue;
        for(Cell_handle x : cells)
          for(int k = 0; k < 4; ++k)
            if(x != c && x->vertex(k) != a && x->vertex(k) != b && x->neighbor(k) != c &&
               std::count(cells.begin(), cells.end(), x->neighbor(k)) > 0 && flip_facet(x, k)) {
              Cell_handle e;
              int u, v;
              return tr.is_edge(a, b, e, u, v) && flip_edge(e, u, v);
            }
      }
    return false;
  };
  // A flip may take other flat cells with it: they are looked for again after each. (Each round
  // removes a flat cell or keeps one; the bound is for configurations where a flip would make one.)
  std::set<Cell_handle> kept;
  std::size_t limit = 0;
  for(std::size_t round = 0;; ++round) {
    Cell_handle next;
    std::size_t flat = 0;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
      if(is_flat(c)) {
        ++flat;
        if(next == Cell_handle() && kept.count(c) == 0) next = c;
      }
    if(round == 0) limit = 4 * flat;
    if(next == Cell_handle() || round > limit) return flat;
    if(!flip_away(next)) kept.insert(next);
  }
}

// The boundary of the complex is made of the facets between its cells and the others (Mesh_3's
// facets in the complex, where the surface crosses their dual Voronoi edges, may differ in a few
// places). Whether that boundary is a 2-manifold at vertex v: the boundary facets at v, by their
// edges opposite v, must make one cycle. Returns (v, u) where an edge (v, u) has more than two
// boundary facets, (v, null) where every edge has two but the facets make several fans (two parts
// of the mesh touching at v), and (null, null) where the boundary is a 2-manifold at v.
template <class C3T3>
std::pair<typename C3T3::Triangulation::Vertex_handle, typename C3T3::Triangulation::Vertex_handle>
non_manifold_boundary_at(const C3T3& c3t3, typename C3T3::Triangulation::Vertex_handle v)
{
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  using Cell_handle = typename C3T3::Triangulation::Cell_handle;
  std::vector<Cell_handle> cells;
  c3t3.triangulation().incident_cells(v, std::back_inserter(cells));
  std::vector<std::pair<Vertex_handle, Vertex_handle>> link;
  for(Cell_handle c : cells) {
    if(!c3t3.is_in_complex(c)) continue;
    const int at = c->index(v);
    for(int i = 0; i < 4; ++i)
      if(i != at && is_boundary_facet(c3t3, c, i)) {
        Vertex_handle w[2];
        int k = 0;
        for(int j = 0; j < 4; ++j)
          if(j != i && j != at) w[k++] = c->vertex(j);
        link.emplace_back(w[0], w[1]);
      }
  }
  if(link.empty()) return {Vertex_handle(), Vertex_handle()};
  std::map<Vertex_handle, std::vector<Vertex_handle>> next;   // looked up only: the order does not matter
  for(const auto& [a, b] : link) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  // Around a boundary edge (v, u) the link has one edge per boundary facet at u.
  for(const auto& [a, b] : link)
    for(const Vertex_handle u : {a, b})
      if(next[u].size() != 2) return {v, u};
  std::size_t walked = 0;
  Vertex_handle previous = link.front().first, at = link.front().second;
  do {
    const auto& n = next[at];
    const Vertex_handle after = n[0] == previous ? n[1] : n[0];
    previous = at;
    at = after;
    ++walked;
  } while(previous != link.front().first && walked <= link.size());
  if(walked != link.size()) return {v, Vertex_handle()};
  return {Vertex_handle(), Vertex_handle()};
}

// The first place, in the order of the cells, where the boundary of the complex is not a
// 2-manifold (see non_manifold_boundary_at()); (null, null) if none.
template <class C3T3>
std::pair<typename C3T3::Triangulation::Vertex_handle, typename C3T3::Triangulation::Vertex_handle>
non_manifold_boundary_place(const C3T3& c3t3)
{
  for(const auto v : boundary_vertices_in_order(c3t3))
    if(const auto place = non_manifold_boundary_at(c3t3, v); place.first != decltype(v)()) return place;
  return {};
}

// The genera of the connected components of a closed, orientable 2-manifold surface given by its
// triangles (vertex numbers below n), sorted: a component's V - E + F = V - F / 2 is 2 - 2 genus.
inline std::vector<long> genera_of_components(std::size_t n, const std::vector<std::array<std::size_t, 3>>& triangles)
{
  std::vector<std::size_t> parent(n);
  for(std::size_t v = 0; v < n; ++v) parent[v] = v;
  const auto root = [&](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const auto& t : triangles)
    for(int k = 1; k < 3; ++k) parent[root(t[k])] = root(t[0]);
  std::vector<long> vertices(n, 0), faces(n, 0);
  std::vector<bool> used(n, false);
  for(const auto& t : triangles) {
    ++faces[root(t[0])];
    for(const std::size_t v : t) used[v] = true;
  }
  for(std::size_t v = 0; v < n; ++v)
    if(used[v]) ++vertices[root(v)];
  std::vector<long> genera;
  for(std::size_t r = 0; r < n; ++r)
    if(faces[r] > 0) genera.push_back(1 - (vertices[r] - faces[r] / 2) / 2);
  std::sort(genera.begin(), genera.end());
  return genera;
}

// The genera of the components of the boundary of the complex (a 2-manifold).
template <class C3T3>
std::vector<long> boundary_genera(const C3T3& c3t3)
{
  std::unordered_map<typename C3T3::Triangulation::Vertex_handle, std::size_t> number;
  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(is_boundary_facet(c3t3, c, i)) {
        std::array<std::size_t, 3> t;
        for(int k = 1; k < 4; ++k) t[k - 1] = number.emplace(c->vertex((i + k) % 4), number.size()).first->second;
        triangles.push_back(t);
      }
  return genera_of_components(number.size(), triangles);
}

// The genera of the components of a closed triangle surface.
template <class Surface>
std::vector<long> surface_genera(const Surface& surface)
{
  std::vector<std::array<std::size_t, 3>> triangles;
  std::size_t n = 0;
  for(const auto f : faces(surface)) {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(const auto v : vertices_around_face(halfedge(f, surface), surface)) n = (std::max)(n, (t[k++] = std::size_t(v)) + 1);
    triangles.push_back(t);
  }
  return genera_of_components(n, triangles);
}

// "2 components of genera 0, 1" (up to six listed).
inline std::string describe_genera(const std::vector<long>& genera)
{
  std::string text = std::to_string(genera.size()) + (genera.size() == 1 ? " component of genus " : " components of genera ");
  for(std::size_t i = 0; i < genera.size() && i < 6; ++i) text += (i > 0 ? ", " : "") + std::to_string(genera[i]);
  return text + (genera.size() > 6 ? ", ..." : "");
}

// Where parts of the surface are closer than the sizes, Mesh_3's tetrahedra may touch only at a
// vertex or along an edge (9 of the 66 closed surfaces of libcgal-demo at the default sizes, at
// the same places with half the sizes), or the space outside them may (a thin hole or slot
// closing at a vertex). There, the tetrahedra on that side at the vertex are grouped (joined
// through their facets at it; at an edge with more than two boundary facets, the fans of
// tetrahedra of the complex around it), and all but the group of largest volume change sides:
// touching parts are separated, a closing hole is filled at the vertex. Repeated while the
// boundary is not a 2-manifold, up to `limit` cells changed at 100 places (hand.off and dino.off:
// a few cells; cheese.off, a thin-walled box with holes, and rotor.off stay refused). Returns the
// number of cells changed.
template <class C3T3>
std::size_t separate_touching_tetrahedra(C3T3& c3t3, std::size_t limit)
{
  using Tr = typename C3T3::Triangulation;
  using Cell_handle = typename Tr::Cell_handle;
  using Vertex_handle = typename Tr::Vertex_handle;
  const Tr& tr = c3t3.triangulation();
  const auto volume = [&](Cell_handle c) {
    return tr.is_infinite(c) ? std::numeric_limits<double>::infinity()   // the outside stays outside
                             : cell_volume(c3t3, c);
  };
  // The cells at v on one side (in the complex or not), joined through their facets at v.
  const auto groups_at = [&](Vertex_handle v, bool in) {
    std::vector<Cell_handle> cells;
    tr.incident_cells(v, std::back_inserter(cells));
    std::vector<std::vector<Cell_handle>> groups;
    std::unordered_set<Cell_handle> seen;
    for(Cell_handle c : cells) {
      if(c3t3.is_in_complex(c) != in || !seen.insert(c).second) continue;
      groups.push_back({c});
      for(std::size_t k = 0; k < groups.back().size(); ++k) {
        const Cell_handle a = groups.back()[k];
        for(int i = 0; i < 4; ++i) {
          const Cell_handle b = a->neighbor(i);
          if(i != a->index(v) && c3t3.is_in_complex(b) == in && seen.insert(b).second) groups.back().push_back(b);
        }
      }
    }
    return groups;
  };
  // The fans of cells of the complex around the edge (v, u), in the order of a circulation.
  const auto fans_around = [&](Vertex_handle v, Vertex_handle u) {
    std::vector<std::vector<Cell_handle>> fans;
    Cell_handle c;
    int i, j;
    if(!tr.is_edge(v, u, c, i, j)) return fans;
    auto around = tr.incident_cells(typename Tr::Edge(c, i, j)), end = around;
    // Start after a cell outside the complex, so that no fan is cut in two.
    while(c3t3.is_in_complex(around) && ++around != end) {}
    end = around;
    bool in_fan = false;
    do {
      const bool in = c3t3.is_in_complex(around);
      if(in && !in_fan) fans.emplace_back();
      if(in) fans.back().push_back(around);
      in_fan = in;
    } while(++around != end);
    return fans;
  };
  const auto first = *c3t3.facets_in_complex_begin();
  const auto patch = c3t3.surface_patch_index(first.first, first.second);
  const auto subdomain = c3t3.subdomain_index(c3t3.cells_in_complex_begin());
  std::size_t changed = 0;
  int places = 0;
  // Passes over the boundary's vertices, each place repaired where it is found; a repair can make
  // a neighbouring vertex a boundary vertex, which the next pass sees.
  for(bool repaired = true; repaired && changed <= limit && places < 100;) {
    repaired = false;
    for(const Vertex_handle w : boundary_vertices_in_order(c3t3)) {
      if(changed > limit || places >= 100) break;
      const auto [v, u] = non_manifold_boundary_at(c3t3, w);
      if(v == Vertex_handle()) continue;
      ++places;
      bool in = true;
      auto groups = u != Vertex_handle() ? fans_around(v, u) : groups_at(v, true);
      if(groups.size() < 2 && u == Vertex_handle()) {
        in = false;
        groups = groups_at(v, false);
      }
      if(groups.size() < 2) continue;   // not a touching: left to the final check
      std::size_t largest = 0;
      std::vector<double> size(groups.size(), 0.);
      for(std::size_t g = 0; g < groups.size(); ++g) {
        for(Cell_handle c : groups[g]) size[g] += volume(c);
        if(size[g] > size[largest]) largest = g;
      }
      for(std::size_t g = 0; g < groups.size(); ++g) {
        // (Two sides of the outside at a vertex of the triangulation's hull: neither is filled.)
        if(g == largest || (!in && std::isinf(size[g]))) continue;
        for(Cell_handle c : groups[g]) {
          set_in_complex(c3t3, c, !in, subdomain, patch);
          ++changed;
        }
      }
      repaired = true;
    }
  }
  return changed;
}

// Two faces of different components of `surface` (numbered per face by `component`) closer than
// `distance` (the lowest pair of the closest), and how close they are; `distance` as the distance
// when there are none. Candidates
// are the pairs whose boxes, grown by `distance`, overlap (CGAL::box_self_intersection_d); two
// triangles that do not cross are as close as the closest of their vertex-triangle and edge-edge
// pairs.
template <class Surface>
std::tuple<std::size_t, std::size_t, double>
closest_components(const Surface& surface, const std::vector<std::size_t>& component, double distance)
{
  using K = typename Kernel_traits<typename Surface::Point>::Kernel;
  using Face = typename Surface::Face_index;
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<Box> boxes;
  for(Face f : faces(surface)) {
    const auto p = corners(surface, f);
    const Bbox_3 b = p[0].bbox() + p[1].bbox() + p[2].bbox();
    boxes.emplace_back(Bbox_3(b.xmin() - distance, b.ymin() - distance, b.zmin() - distance, b.xmax() + distance,
                              b.ymax() + distance, b.zmax() + distance), std::size_t(f));
  }
  std::tuple<std::size_t, std::size_t, double> closest(0, 0, distance);
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    if(component[a.info()] == component[b.info()]) return;
    const auto p = corners(surface, Face(a.info())), q = corners(surface, Face(b.info()));
    const typename K::Triangle_3 tp(p[0], p[1], p[2]), tq(q[0], q[1], q[2]);
    double d2 = std::numeric_limits<double>::infinity();
    for(int i = 0; i < 3; ++i) {
      d2 = (std::min)({d2, CGAL::to_double(CGAL::squared_distance(p[i], tq)), CGAL::to_double(CGAL::squared_distance(q[i], tp))});
      for(int j = 0; j < 3; ++j)
        d2 = (std::min)(d2, CGAL::to_double(CGAL::squared_distance(typename K::Segment_3(p[i], p[(i + 1) % 3]),
                                                                    typename K::Segment_3(q[j], q[(j + 1) % 3]))));
    }
    // The lowest pair among equally close ones: the error does not depend on the order of the calls.
    const std::tuple<std::size_t, std::size_t, double> pair((std::min)(a.info(), b.info()), (std::max)(a.info(), b.info()), std::sqrt(d2));
    if(std::get<2>(pair) < std::get<2>(closest) ||
       (std::get<2>(pair) == std::get<2>(closest) && std::get<2>(pair) < distance && pair < closest))
      closest = pair;
  });
  return closest;
}

// Mesh_3 protects the sharp edges with balls that must not overlap unless they are neighbours on a
// curve: where two parts of the sharp edges come closer than the sizes without meeting nearby (the
// two sides of a thin slit, a hairpin), the balls shrink to the gap and their number grows without
// bound (a split ring with a slit of 0.001: no end in five minutes). Short close stretches are
// harmless (femur.off and dino.off have sharp edges 10^-4 apart over a fifth of the edge size).
// Returns the lowest pair of sharp edges (by `surface`'s edge indices) closer than `distance` along
// more than `length` of each, neither joined through sharp edges that come within 3 `distance` of
// the one's point nearest the other, and their distance; (0, 0, distance) if none. The sharp edges
// are those the domain protects (PMP::detect_sharp_edges(), `angle`).
template <class Surface>
std::tuple<std::size_t, std::size_t, double> close_sharp_edges(const Surface& surface, double angle, double distance,
                                                               double length)
{
  using K = typename Kernel_traits<typename Surface::Point>::Kernel;
  using Edge = typename Surface::Edge_index;
  using Vertex = typename Surface::Vertex_index;
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::tuple<std::size_t, std::size_t, double> closest(0, 0, distance);
  std::unordered_map<Edge, bool> sharp_of;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(surface, angle, boost::make_assoc_property_map(sharp_of));
  std::vector<Edge> sharp;
  std::unordered_map<Vertex, std::vector<Edge>> at;   // the sharp edges at each vertex
  for(Edge e : edges(surface))
    if(sharp_of[e]) {
      sharp.push_back(e);
      for(int k = 0; k < 2; ++k) at[surface.vertex(e, k)].push_back(e);
    }
  const auto segment = [&](Edge e) { return typename K::Segment_3(surface.point(surface.vertex(e, 0)), surface.point(surface.vertex(e, 1))); };
  std::vector<Box> boxes;
  for(Edge e : sharp) {
    const Bbox_3 b = segment(e).bbox();
    boxes.emplace_back(Bbox_3(b.xmin() - distance, b.ymin() - distance, b.zmin() - distance, b.xmax() + distance,
                              b.ymax() + distance, b.zmax() + distance), std::size_t(e));
  }
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    const Edge e(a.info()), f(b.info());
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j)
        if(surface.vertex(e, i) == surface.vertex(f, j)) return;
    const auto se = segment(e), sf = segment(f);
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(se, sf)));
    const std::tuple<std::size_t, std::size_t, double> pair((std::min)(a.info(), b.info()), (std::max)(a.info(), b.info()), d);
    if(!(d < std::get<2>(closest) || (d == std::get<2>(closest) && d < distance && pair < closest))) return;
    // The length of each within `distance` of the other and the point of e nearest to f, sampled
    // (a sample suffices: the walk's ball is 3 times the gap).
    typename K::Point_3 near = se.source();
    double best = std::numeric_limits<double>::infinity();
    std::size_t close_e = 0, close_f = 0;
    constexpr int samples = 64;
    const auto sample = [&](const typename K::Segment_3& g, int n) {
      return g.source() + (g.target() - g.source()) * (double(n) / samples);
    };
    for(int n = 0; n <= samples; ++n) {
      const auto p = sample(se, n);
      const double d2 = CGAL::to_double(CGAL::squared_distance(p, sf));
      if(d2 < best) { best = d2; near = p; }
      close_e += d2 < distance * distance ? 1 : 0;
      close_f += CGAL::to_double(CGAL::squared_distance(sample(sf, n), se)) < distance * distance ? 1 : 0;
    }
    const auto run = [&](const typename K::Segment_3& g, std::size_t close) {
      return std::sqrt(CGAL::to_double(g.squared_length())) * close / (samples + 1);
    };
    if(run(se, close_e) <= length || run(sf, close_f) <= length) return;
    const double reach = 3 * distance;
    std::vector<Edge> stack{e};
    std::unordered_set<Edge> seen{e};
    while(!stack.empty()) {
      const Edge g = stack.back();
      stack.pop_back();
      if(g == f) return;
      for(int k = 0; k < 2; ++k)
        for(Edge h : at[surface.vertex(g, k)])
          if(seen.insert(h).second && CGAL::to_double(CGAL::squared_distance(near, segment(h))) < reach * reach) stack.push_back(h);
    }
    closest = pair;
  });
  return closest;
}

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
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below; the others of `mesh_interior()` (its optimizers and
       `maximum_number_of_vertices`) are ignored

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
\cgalNamedParamsEnd

\throws Invalid_input as `mesh_interior()` (except for an output with no cell or
`maximum_number_of_vertices`).
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Interior_mesh_sizes interior_mesh_sizes(const TriangleMesh& surface,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using GT = internal::Interior_mesh_traits_of<NamedParameters>;
  const internal::Checked_surface<GT, TriangleMesh> checked(surface, np);
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
facet distance deeper (blobby.off: 35 of 2.7.10^4 cells). Inside, Mesh_3 leaves a few cells as
flat with all four vertices on the surface across thin parts (spool.off: one, with a dihedral
angle of 0.04 degrees, which the radial map turned over): without `exude_slivers`, Mesh_3's
sliver exudation still runs on the cells with a dihedral angle below 2 degrees (a few
milliseconds: 3 to 30 on spool.off and blobby.off). Where four of Mesh_3's points are coplanar
and cospherical, a cell can be flat to rounding (the square sections of a 40 x 0.1 x 0.1 bar: 15
of 1.5.10^4 cells), which no map can measure: it is flipped away (a 3-2 flip of an edge, after a
2-3 flip where the edge has four cells around it), among cells of the complex: the triangulation
stays valid with positive cells but is no longer the regular one. Two runs with the same input
give the same complex (the random generator of Mesh_3 is seeded, the optimizers have no time
limit).

Defaults. Without sizes, the criteria scale with the enclosed volume V and the area A of the
surface: cell_size = facet_size = edge_size = max(cbrt(V / 6000), sqrt(A / 2400)),
facet_distance = facet_size / 10, facet_angle = 25, cell_radius_edge_ratio = 3, and
sharp_edge_angle = 60. This aims at about 3.10^4 tetrahedra (the volume term) with at most
about 8.10^3 boundary facets (the area term, for thin shapes). On the 66 closed, 2-manifold,
self-intersection-free surfaces of libcgal-demo's data it gave 1.4.10^4 to 1.03.10^5
tetrahedra (median 2.7.10^4) in 0.1 to 6 s (median 0.4 s) on one core; the largest counts come
from spurious sharp edges of scanned surfaces (femur.off: 1135 corners; 2.8.10^4 tetrahedra
with `sharp_edge_angle(180)`), and one CAD model with sharp edges 10^-4 of its size
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
       start from the refined mesh, and they cost far more than it (sphere.off, 2.6.10^4
       tetrahedra: refinement 0.13 s; ODT 10 iterations 2.4 s, Lloyd 10 iterations 3.7 s,
       perturbation 0.6 s, exudation 2.4 s).

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
                    vertices than this maximum (when it is given and not 0), or than 10^7 (when it is not
                    given), are refused before Mesh_3 starts.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the complex, of type `Interior_mesh<GeomTraits>::C3T3`.
\throws Invalid_input, naming the offending input element, if `surface` is empty, has a face
that is not a triangle, a non-finite coordinate, a border edge, a non-manifold vertex, a
degenerate face or two faces that cross, encloses no volume, is thinner than the facet distance
(its mean thickness, 2 volume / area, is smaller) or has a component that is (2 |volume| / area
of that component; the error names one of its faces), has two components closer than the facet
distance (the error names a face of each) or two sharp edges (those protected, see
`sharp_edge_angle`) closer than it along more than the edge size that meet only farther away,
such as the two sides of a slit (Mesh_3 would protect them with balls no larger than the gap,
for minutes or without end; the error names their vertices), if a size is not a positive finite
number (or an angle or ratio is out of its range), if the sizes ask for more vertices than
`maximum_number_of_vertices` allows (10^7 by default), if Mesh_3 reaches
`maximum_number_of_vertices`, if the complex has no cell or a component of the surface gets no
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
typename Interior_mesh<internal::Interior_mesh_traits_of<NamedParameters>>::C3T3
mesh_interior(const TriangleMesh& surface, const NamedParameters& np = CGAL::parameters::default_values())
{
  using GT = internal::Interior_mesh_traits_of<NamedParameters>;
  using Types = Interior_mesh<GT>;
  using D = internal::Interior_mesh_defaults;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace mp = CGAL::parameters;   // Mesh_3's Boost.Parameter keywords live there

  internal::Checked_surface<GT, TriangleMesh> checked(surface, np);
  const Interior_mesh_sizes sizes = internal::read_interior_mesh_sizes(checked.volume, checked.area, checked.scale, np);
  const int odt = choose_parameter(get_parameter(np, internal_np::odt_iterations), 0);
  const int lloyd = choose_parameter(get_parameter(np, internal_np::lloyd_iterations), 0);
  const bool perturb = choose_parameter(get_parameter(np, internal_np::perturb_slivers), false);
  const bool exude = choose_parameter(get_parameter(np, internal_np::exude_slivers), false);
  if(odt < 0 || lloyd < 0)
    throw Invalid_input("mesh_interior: the numbers of ODT and Lloyd iterations must be >= 0");

  // The domain keeps a pointer to the generator; without one it would draw from a generator of
  // its own, seeded alike, but the explicit seed states the intent.
  CGAL::Random random(0);
  typename Types::Domain domain(checked.surface, &random);
  if(sizes.sharp_edge_angle < 180) domain.detect_features(sizes.sharp_edge_angle);

  // A domain thinner than the facet distance (its mean thickness 2 V / A, the thickness of a slab)
  // passes Mesh_3's surface criteria with facets joining its two sides: the boundary is not
  // recovered, and the protection of its rim's edges does not end (a sphere squashed to 1e-9).
  const auto check_thickness = [&](double volume, double area, const std::string& what, const std::string& lost,
                                   const std::string& remedy) {
    const double thickness = 2 * volume / area;
    if(thickness >= sizes.facet_distance) return;
    char text[200];
    std::snprintf(text, sizeof text, " is thinner (2 volume / area = %.3g) than the facet distance (%.3g)", thickness,
                  sizes.facet_distance);
    throw Invalid_input("mesh_interior: " + what + text + ": Mesh_3 would not recover " + lost +
                        "; give sizes below its thickness (facet distance, facet size, cell size)" + remedy);
  };
  check_thickness(checked.volume, checked.area, "the volume", "its boundary", "");
  // So is each component (a cavity measured by the space it encloses): a thin plate beside a ball
  // kept Mesh_3's protection of its rim going, a sphere of radius 1e-12 beside a unit one its
  // refinement, and a flat tetrahedron got no tetrahedron at all.
  const std::size_t components = checked.component_volume.size();
  std::vector<std::size_t> first_face(components, 0);   // of each component, to name it
  for(std::size_t f = checked.component.size(); f-- > 0;) first_face[checked.component[f]] = f;
  for(std::size_t c = 0; c < components && components > 1; ++c)
    check_thickness(std::abs(checked.component_volume[c]), checked.component_area[c],
                    "the component of the surface with face " + std::to_string(checked.face_names[first_face[c]]), "it",
                    ", or remove it");
  // Components closer than the facet distance: Mesh_3's boundary, within that distance of the
  // surface, need not keep them apart. Two cubes 10^-3 apart (facet distance 0.014) grew its edge
  // protection's memory without end; 10^-2 apart gave a complex that is not a manifold.
  if(components > 1) {
    const double scaled = checked.scale * sizes.facet_distance;   // in the units of the copy
    const auto [f, g, d] = internal::closest_components(checked.surface, checked.component, scaled);
    if(d < scaled) {
      char text[200];
      std::snprintf(text, sizeof text, " are %.3g apart, less than the facet distance (%.3g)", d / checked.scale, sizes.facet_distance);
      throw Invalid_input("mesh_interior: faces " + std::to_string(checked.face_names[f]) + " and " +
                          std::to_string(checked.face_names[g]) + " of two components of the surface" + text +
                          ": Mesh_3 would not keep them apart; give sizes below their distance (facet distance, "
                          "facet size, cell size), or move them apart");
    }
  }
  if(sizes.sharp_edge_angle < 180) {
    const double scaled = checked.scale * sizes.facet_distance;
    const auto [e, f, d] = internal::close_sharp_edges(checked.surface, sizes.sharp_edge_angle, scaled, checked.scale * sizes.edge_size);
    if(d < scaled) {
      const auto name = [&](std::size_t edge) {
        const auto h = checked.surface.halfedge(typename Types::Surface::Edge_index(edge));
        return "vertices " + std::to_string(checked.vertex_names[std::size_t(source(h, checked.surface))]) + ", " +
               std::to_string(checked.vertex_names[std::size_t(target(h, checked.surface))]);
      };
      char text[200];
      std::snprintf(text, sizeof text, " are %.3g apart, less than the facet distance (%.3g), along more than the edge size (%.3g), and meet only farther away",
                    d / checked.scale, sizes.facet_distance, sizes.edge_size);
      throw Invalid_input("mesh_interior: the sharp edges of the surface at " + name(e) + " and at " + name(f) + text +
                          " (the sides of a slit?): Mesh_3 would protect them with balls no larger than the gap, for "
                          "minutes or without end; give sizes below their distance (facet distance, facet size, cell "
                          "size), or a larger sharp_edge_angle (180 protects no edge)");
    }
  }
  const double asked = checked.volume / (D::volume_per_cell * std::pow(sizes.cell_size, 3)) / D::cells_per_vertex +
                       checked.area / (D::area_per_facet * sizes.facet_size * sizes.facet_size) / 2;
  const auto given_maximum = get_parameter(np, internal_np::maximum_number_of_vertices);
  constexpr bool maximum_given = !std::is_same<std::decay_t<decltype(given_maximum)>, CGAL::internal_np::Param_not_found>::value;
  // (At least 10^4: Mesh_3 needs some vertices to follow any surface, however large the sizes.)
  const std::size_t maximum_vertices =
    choose_parameter(given_maximum, static_cast<std::size_t>((std::min)((std::max)(10 * asked, 1e4), 1e15)));
  // Sizes that ask for more vertices than memory holds are refused before Mesh_3 starts rather than
  // after it has filled the memory: beyond the maximum when one is given, else beyond 10^7.
  const double affordable = maximum_given && maximum_vertices > 0 ? double(maximum_vertices) : maximum_given ? 1e300 : 1e7;
  if(!(asked <= affordable)) {
    char text[160];
    std::snprintf(text, sizeof text, "about %.2g vertices, more than %s (cell size %.3g, facet size %.3g)",
                  (std::min)(asked, 1e300),
                  maximum_given ? "maximum_number_of_vertices" : "10^7", sizes.cell_size, sizes.facet_size);
    throw Invalid_input(std::string("mesh_interior: the sizes ask for ") + text + "; give larger sizes" +
                        (maximum_given ? "" : ", or a larger maximum_number_of_vertices"));
  }

  const double s = checked.scale;   // the sizes in the units of the scaled copy
  const typename Types::Criteria criteria(mp::edge_size = s * sizes.edge_size, mp::facet_angle = sizes.facet_angle,
                                          mp::facet_size = s * sizes.facet_size,
                                          mp::facet_distance = s * sizes.facet_distance,
                                          mp::cell_radius_edge_ratio = sizes.cell_radius_edge_ratio,
                                          mp::cell_size = s * sizes.cell_size);
  CGAL::Mesh_error_code error = CGAL::CGAL_MESH_3_NO_ERROR;
  const auto options = mp::mesh_3_options(mp::maximal_number_of_vertices = maximum_vertices, mp::pointer_to_error_code = &error);
  const auto check_error = [&] {
    if(error == CGAL::CGAL_MESH_3_MAXIMAL_NUMBER_OF_VERTICES_REACHED)
      throw Invalid_input("mesh_interior: Mesh_3 stopped at " + std::to_string(maximum_vertices) +
                          " vertices (maximum_number_of_vertices): the surface has details far smaller than the "
                          "sizes (thin parts, short sharp edges?); try a larger sharp_edge_angle (180 protects no "
                          "edge) or a larger maximum");
  };
  typename Types::C3T3 c3t3 = CGAL::make_mesh_3<typename Types::C3T3>(
    domain, criteria, mp::features(domain), mp::no_odt(), mp::no_lloyd(), mp::no_perturb(), mp::no_exude(), options);
  check_error();
  // Components that Mesh_3's initial points missed get seeds, and the refinement goes on from the
  // whole triangulation: its facets and cells are classified again, as after a load.
  std::vector<std::size_t> missed;
  const auto seeds = internal::seeds_of_missed_components(c3t3, domain, checked.surface, checked.component, missed);
  if(!seeds.empty()) {
    c3t3.clear_cells_and_facets_from_c3t3();
    auto& tr = c3t3.triangulation();
    const auto weighted = tr.geom_traits().construct_weighted_point_3_object();
    for(const auto& [p, index] : seeds) {
      const auto v = tr.insert(weighted(p));
      if(v != typename Types::Triangulation::Vertex_handle()) {   // null when a protecting ball hides p
        c3t3.set_dimension(v, 2);
        c3t3.set_index(v, index);
      }
    }
    CGAL::refine_mesh_3(c3t3, domain, criteria, mp::no_odt(), mp::no_lloyd(), mp::no_perturb(), mp::no_exude(),
                        mp::no_reset_c3t3(), options);
    check_error();
    internal::seeds_of_missed_components(c3t3, domain, checked.surface, checked.component, missed);
  }
  if(!missed.empty())
    throw Invalid_input("mesh_interior: Mesh_3 left the component of the surface with face " +
                        std::to_string(checked.face_names[missed.front()]) +
                        " without tetrahedra (is it much smaller than the sizes?); give smaller sizes");
  // The optimizers as make_mesh_3 runs them, in its order. time_limit = 0 means none: a time limit
  // would make the output depend on the machine's speed (Mesh_3's default limit for perturbation
  // and exudation is the refinement time).
  if(odt > 0) CGAL::odt_optimize_mesh_3(c3t3, domain, mp::time_limit = 0, mp::max_iteration_number = odt);
  if(lloyd > 0) CGAL::lloyd_optimize_mesh_3(c3t3, domain, mp::time_limit = 0, mp::max_iteration_number = lloyd);
  if(perturb) CGAL::perturb_mesh_3(c3t3, domain, mp::time_limit = 0);
  if(exude) CGAL::exude_mesh_3(c3t3, mp::time_limit = 0);
  else CGAL::exude_mesh_3(c3t3, mp::sliver_bound = D::sliver_bound, mp::time_limit = 0);
  internal::match_facets_to_cells(c3t3);
  internal::separate_touching_tetrahedra(c3t3, c3t3.number_of_cells_in_complex() / 100);
  internal::peel_flat_caps(c3t3, s * sizes.facet_distance);
  internal::flip_flat_cells(c3t3);
  if(c3t3.number_of_cells_in_complex() == 0)
    throw Invalid_input("mesh_interior: Mesh_3 produced no tetrahedron inside the surface (sizes too large "
                        "for the volume?)");
  internal::map_complex_back(c3t3, 1 / s, checked.offset);
  if(const auto v = internal::non_manifold_boundary_place(c3t3).first; v != typename Types::Triangulation::Vertex_handle()) {
    const auto p = c3t3.triangulation().geom_traits().construct_point_3_object()(v->point());
    char text[160];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    throw Invalid_input(std::string("mesh_interior: Mesh_3's tetrahedra touch at the vertex ") + text +
                        " without sharing a facet: their boundary is not a 2-manifold there (parts of the surface closer "
                        "than the sizes, or details finer than them); give smaller sizes");
  }
  // Details finer than the sizes can change the topology with a valid complex: a sphere pinched to
  // a waist of radius 0.005 came out as a torus (7 tetrahedra bridged the waist), a dumbbell's thin
  // neck was dropped (two balls).
  if(const auto meshed = internal::boundary_genera(c3t3), input = internal::surface_genera(checked.surface); meshed != input)
    throw Invalid_input("mesh_interior: the boundary of Mesh_3's tetrahedra has " + internal::describe_genera(meshed) +
                        ", the surface " + internal::describe_genera(input) +
                        ": a neck or gap of the surface finer than the sizes was cut or bridged; give smaller sizes");
  return c3t3;
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_MESH_INTERIOR_H
