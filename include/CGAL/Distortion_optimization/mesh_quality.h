// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Mesh quality from distortion: a mesh is a map from ideal cells (the regular simplex), so that
// minimizing a measure of that map improves the mesh's element shapes with its connectivity kept
// and no cell inverted (Naitsat, Saucan and Zeevi, "Geometry-based distortion measures for space
// deformation", section 4.2). Also the classic quality statistics to judge the result.

#ifndef CGAL_DISTORTION_OPTIMIZATION_MESH_QUALITY_H
#define CGAL_DISTORTION_OPTIMIZATION_MESH_QUALITY_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/Result.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measures.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/c3t3_adapter.h>
#include <CGAL/Distortion_optimization/internal/run_on_adapter.h>
#include <CGAL/Distortion_optimization/internal/triangle_mesh_adapter.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// The shape quality of the cells of a mesh, as returned by `mesh_quality()`. Angles are the
/// dihedral angles of tetrahedra, or the angles of triangles, in degrees.
struct Mesh_quality
{
  std::size_t cells = 0;
  double min_angle = 0;            ///< the smallest angle of any cell
  double max_angle = 0;            ///< the largest angle of any cell
  double mean_min_angle = 0;       ///< the mean over the cells of each cell's smallest angle
  double min_radius_ratio = 0;     ///< the smallest n r / R (inradius over circumradius, 1 for the regular simplex)
  double mean_radius_ratio = 0;    ///< its mean over the cells
  std::size_t slivers = 0;         ///< cells with an angle below 10 degrees (3D: dihedral angles)
  std::size_t inverted_cells = 0;  ///< cells whose orientation is not the mesh's (exact predicate), flat ones included
};

namespace internal {

// The key of a cell's property maps: a face of a triangle mesh, a `Cell_handle` of a complex.
template <class Mesh, bool = Is_c3t3<Mesh>::value>
struct Cell_key
{
  using type = typename boost::graph_traits<Mesh>::face_descriptor;
};

template <class Mesh>
struct Cell_key<Mesh, true>
{
  using type = typename Mesh::Triangulation::Cell_handle;
};

// Calls f(cell, points) with each cell (a face of a triangle mesh, a `Cell_handle` of the complex:
// only its cells in the complex) and its vertex positions under `positions`.
template <class Mesh, class PositionMap, class F>
void for_each_cell_points(const Mesh& mesh, const PositionMap& positions, const F& f)
{
  using Point = typename boost::property_traits<PositionMap>::value_type;
  if constexpr(Is_c3t3<Mesh>::value) {
    for(auto c = mesh.cells_in_complex_begin(); c != mesh.cells_in_complex_end(); ++c)
      f(typename Mesh::Triangulation::Cell_handle(c),
        std::array<Point, 4>{get(positions, c->vertex(0)), get(positions, c->vertex(1)), get(positions, c->vertex(2)),
                             get(positions, c->vertex(3))});
  } else {
    for(auto face : faces(mesh)) {
      std::array<Point, 3> p;
      int i = 0;
      for(auto v : vertices_around_face(halfedge(face, mesh), mesh)) {
        if(i == 3) throw Invalid_input("face " + std::to_string(std::size_t(face)) + " is not a triangle");
        p[i++] = get(positions, v);
      }
      if(i != 3) throw Invalid_input("face " + std::to_string(std::size_t(face)) + " is not a triangle");
      f(face, p);
    }
  }
}

template <class Point>
Vector<3> as_vector(const Point& p)
{
  if constexpr(Target_dimension<Point>::value == 3)
    return Vector<3>(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  else
    return Vector<3>(CGAL::to_double(p.x()), CGAL::to_double(p.y()), 0.);
}

// The orientation of a planar mesh's triangles that are not inverted, from its total signed area
// (a planar mesh may be clockwise as a whole).
inline CGAL::Orientation planar_orientation(double signed_area)
{
  return signed_area >= 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
}

// The cell moved to the origin and scaled by a power of two (exactly) to edges of about unit
// length: angles and radius ratios do not change, and their products of up to five lengths
// neither overflow nor underflow whatever the mesh's units.
template <std::size_t N>
std::array<Vector<3>, N> unit_sized(const std::array<Vector<3>, N>& p)
{
  std::array<Vector<3>, N> q;
  double largest = 0;
  for(std::size_t i = 0; i < N; ++i) {
    q[i] = p[i] - p[0];
    largest = std::max(largest, q[i].cwiseAbs().maxCoeff());
  }
  const double scale = unit_scale(largest);
  for(Vector<3>& x : q) x *= scale;
  return q;
}

// The angles (degrees) and n r / R of a triangle or tetrahedron.
inline void cell_shape(const std::array<Vector<3>, 3>& cell, std::array<double, 6>& angles, int& count, double& ratio)
{
  const std::array<Vector<3>, 3> p = unit_sized(cell);
  count = 3;
  double perimeter = 0, product = 1;
  for(int i = 0; i < 3; ++i) {
    const Vector<3> a = p[(i + 1) % 3] - p[i], b = p[(i + 2) % 3] - p[i];
    angles[i] = std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / CGAL_PI;
    perimeter += a.norm();
    product *= a.norm();
  }
  const double area = (p[1] - p[0]).cross(p[2] - p[0]).norm() / 2;
  // r = 2A / perimeter, R = abc / 4A: 2 r / R = 16 A^2 / (perimeter abc).
  ratio = product > 0 ? 16 * area * area / (perimeter * product) : 0.;
}

inline void cell_shape(const std::array<Vector<3>, 4>& cell, std::array<double, 6>& angles, int& count, double& ratio)
{
  const std::array<Vector<3>, 4> p = unit_sized(cell);
  count = 6;
  static const int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for(int e = 0; e < 6; ++e) {
    const Vector<3> axis = p[edges[e][1]] - p[edges[e][0]];
    const Vector<3> n1 = axis.cross(p[edges[e][2]] - p[edges[e][0]]), n2 = axis.cross(p[edges[e][3]] - p[edges[e][0]]);
    angles[e] = std::atan2(n1.cross(n2).norm(), n1.dot(n2)) * 180 / CGAL_PI;
  }
  const Vector<3> a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double volume = std::abs(a.dot(b.cross(c))) / 6;
  double faces = 0;
  for(int i = 0; i < 4; ++i) faces += (p[(i + 2) % 4] - p[(i + 1) % 4]).cross(p[(i + 3) % 4] - p[(i + 1) % 4]).norm() / 2;
  // r = 3V / faces; R = |a^2 (b x c) + b^2 (c x a) + c^2 (a x b)| / 12V: 3 r / R = 108 V^2 / (faces |...|).
  const double circum = (a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b)).norm();
  ratio = faces > 0 && circum > 0 ? 108 * volume * volume / (faces * circum) : 0.;
}

// The edges of the regular simplex of the given volume (area in 2D) and orientation sign: the
// "source" of a cell measured against the ideal element.
template <int n>
Matrix<n> ideal_cell_edges(double volume, int sign)
{
  Matrix<n> E;
  if constexpr(n == 2) {
    E << 1., 0.5, 0., std::sqrt(3.) / 2;                       // area sqrt(3) / 4
    E *= std::sqrt(volume / (std::sqrt(3.) / 4));
  } else {
    E << 1., 0.5, 0.5, 0., std::sqrt(3.) / 2, std::sqrt(3.) / 6, 0., 0., std::sqrt(2. / 3);   // volume sqrt(2) / 12
    E *= cbrt_by_octaves(volume / (std::sqrt(2.) / 12));
  }
  if(sign < 0) E.row(n - 1) *= -1;   // the mirror image: the orientation of the cell
  return E;
}

// Each cell of the map measured against the regular simplex of its own source volume, all with
// the orientation of the mesh as a whole (the sign of its total signed volume): a cell that the
// start inverts is inverted for the optimizer too, not the image of a mirrored ideal.
template <int n>
void use_ideal_cells(Simplicial_map<n>& map)
{
  double signed_volume = 0;
  for(std::size_t c = 0; c < map.number_of_cells(); ++c) signed_volume += map.rest_sign[c] * map.rest_volume[c];
  const signed char sign = signed_volume >= 0 ? 1 : -1;
  for(std::size_t c = 0; c < map.number_of_cells(); ++c) {
    map.rest_sign[c] = sign;
    map.inverse_rest[c] = ideal_cell_edges<n>(map.rest_volume[c], sign).inverse();
  }
}

} // namespace internal

/*!
\ingroup PkgDistortionOptimizationRef

The shape quality of the triangles of a planar triangle mesh, or of the tetrahedra of a
`CGAL::Mesh_complex_3_in_triangulation_3` (only the cells in the complex count), at `positions`:
smallest, largest and mean smallest angles (dihedral angles in 3D), radius ratios, slivers and
inverted cells. A triangle is inverted when its orientation differs from the sign of the mesh's
total signed area (a mesh may be clockwise as a whole); a tetrahedron when it is not positive, as
every cell of a complex is. The radius ratio and the inversion of each cell can also be written
to property maps, e.g. to draw a mesh's quality with `IO::write_SVG()`.

\tparam Mesh a triangle mesh (a model of `FaceListGraph`) or a `CGAL::Mesh_complex_3_in_triangulation_3`
\tparam PositionMap a model of `ReadablePropertyMap` from the vertex descriptors of a triangle mesh
        to `Point_2`, or from `Mesh::Triangulation::Vertex_handle` to `Point_3`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param mesh the mesh (not modified)
\param positions the position of each vertex
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below. The cell maps are keyed by `boost::graph_traits<Mesh>::%face_descriptor`
       for a triangle mesh, by `Mesh::Triangulation::Cell_handle` (the cells of the complex) for a
       complex.

\cgalNamedParamsBegin
  \cgalParamNBegin{cell_radius_ratio_map}
    \cgalParamDescription{a property map that receives the radius ratio \f$ n r / R \f$ of each cell (inradius over
                          circumradius, 1 for the regular simplex, 0 for a flat cell), the values whose smallest
                          and mean are `Mesh_quality::min_radius_ratio` and `Mesh_quality::mean_radius_ratio`
                          (`Distortion_optimization::parameters::cell_radius_ratio_map()`)}
    \cgalParamType{a class model of `WritablePropertyMap` with the cell key type and `double` as value type}
    \cgalParamDefault{unused}
    \cgalParamExtra{Written only when the function returns normally.}
  \cgalParamNEnd

  \cgalParamNBegin{inverted_cell_map}
    \cgalParamDescription{as `cell_radius_ratio_map`, `true` for each cell counted in `Mesh_quality::inverted_cells` (flat
                          ones included), `false` for the others (`Distortion_optimization::parameters::inverted_cell_map()`)}
    \cgalParamType{the same, with `bool` as value type}
    \cgalParamDefault{unused}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type of `positions`, using `CGAL::Kernel_traits`}
    \cgalParamExtra{Its `Compute_area_2` and `Orientation_2` (triangle mesh) or `Orientation_3` (complex) decide
                    which cells are inverted, exactly on the coordinates of `positions`.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the statistics of the cells' shapes
\throws Invalid_input if a face is not a triangle or the mesh has no cell
*/
template <class Mesh, class PositionMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_quality mesh_quality(const Mesh& mesh, const PositionMap& positions,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point = typename boost::property_traits<PositionMap>::value_type;
  using Default_traits = typename CGAL::Kernel_traits<Point>::Kernel;
  using GT = typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                                 Default_traits>::type;
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto ratio_map = get_parameter(np, internal_np::cell_radius_ratio_map);
  const auto inverted_map = get_parameter(np, internal_np::inverted_cell_map);
  constexpr bool wants_ratios = !std::is_same<std::decay_t<decltype(ratio_map)>, CGAL::internal_np::Param_not_found>::value;
  constexpr bool wants_inverted = !std::is_same<std::decay_t<decltype(inverted_map)>, CGAL::internal_np::Param_not_found>::value;
  constexpr int n = internal::Is_c3t3<Mesh>::value ? 3 : 2;
  using Cell = typename internal::Cell_key<Mesh>::type;
  Mesh_quality q;
  double signed_area = 0;
  if constexpr(n == 2)
    internal::for_each_cell_points(mesh, positions, [&](const Cell&, const std::array<Point, 3>& p) {
      signed_area += CGAL::to_double(gt.compute_area_2_object()(p[0], p[1], p[2]));
    });
  const CGAL::Orientation expected = n == 3 ? CGAL::POSITIVE : internal::planar_orientation(signed_area);
  // Each cell's values, put in the maps once every cell was measured.
  std::vector<std::pair<Cell, double>> ratios;
  std::vector<std::pair<Cell, bool>> inverted;
  q.min_angle = 180;
  q.min_radius_ratio = 1;
  internal::for_each_cell_points(mesh, positions, [&](const Cell& cell, const std::array<Point, n + 1>& p) {
    std::array<internal::Vector<3>, n + 1> x;
    for(int i = 0; i <= n; ++i) x[i] = internal::as_vector(p[i]);
    std::array<double, 6> angles;
    int count = 0;
    double ratio = 0;
    internal::cell_shape(x, angles, count, ratio);
    const double smallest = *std::min_element(angles.begin(), angles.begin() + count);
    q.min_angle = std::min(q.min_angle, smallest);
    q.max_angle = std::max(q.max_angle, *std::max_element(angles.begin(), angles.begin() + count));
    q.mean_min_angle += smallest;
    q.min_radius_ratio = std::min(q.min_radius_ratio, ratio);
    q.mean_radius_ratio += ratio;
    q.slivers += smallest < 10;
    bool is_inverted = false;
    if constexpr(n == 2) is_inverted = gt.orientation_2_object()(p[0], p[1], p[2]) != expected;
    else is_inverted = gt.orientation_3_object()(p[0], p[1], p[2], p[3]) != expected;
    q.inverted_cells += is_inverted;
    if constexpr(wants_ratios) ratios.emplace_back(cell, ratio);
    if constexpr(wants_inverted) inverted.emplace_back(cell, is_inverted);
    ++q.cells;
  });
  if(q.cells == 0) throw Invalid_input("the mesh has no cell");
  q.mean_min_angle /= q.cells;
  q.mean_radius_ratio /= q.cells;
  if constexpr(wants_ratios)
    for(const auto& [cell, ratio] : ratios) put(ratio_map, cell, ratio);
  if constexpr(wants_inverted)
    for(const auto& [cell, is_inverted] : inverted) put(inverted_map, cell, is_inverted);
  return q;
}

/*!
\ingroup PkgDistortionOptimizationRef

The vertices of the complex's boundary on a sharp edge at `positions`: an edge whose two boundary
facets have normals more than `sharp_edge_angle` degrees apart (as `mesh_interior()`'s), corners
included, and the edges of more than two boundary facets. With the boundary sliding in
`improve_mesh_quality()`, constraining them keeps the features: a vertex on an edge would
otherwise round it off.

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
\tparam PositionMap a model of `ReadablePropertyMap` from `C3T3::Triangulation::Vertex_handle` to `Point_3`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param c3t3 the complex (not modified); only the cells in the complex count
\param positions the position of each vertex of the cells of the complex
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{sharp_edge_angle}
    \cgalParamDescription{an edge is sharp when the normals of its two boundary facets make a larger angle, in degrees
                          (`Distortion_optimization::parameters::sharp_edge_angle()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`60`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the vertices on the sharp edges
*/
template <class C3T3, class PositionMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::unordered_set<typename C3T3::Triangulation::Vertex_handle>
sharp_boundary_vertices(const C3T3& c3t3, const PositionMap& positions,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  const double angle = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::sharp_edge_angle), 60.);
  std::map<std::pair<Vertex_handle, Vertex_handle>, std::vector<internal::Vector<3>>> normals;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i) {
      if(c3t3.is_in_complex(c->neighbor(i))) continue;
      Vertex_handle v[3] = {c->vertex((i + 1) % 4), c->vertex((i + 2) % 4), c->vertex((i + 3) % 4)};
      const auto x = internal::unit_sized(std::array<internal::Vector<3>, 4>{
        internal::as_vector(get(positions, v[0])), internal::as_vector(get(positions, v[1])),
        internal::as_vector(get(positions, v[2])), internal::as_vector(get(positions, c->vertex(i)))});
      internal::Vector<3> normal = x[1].cross(x[2]);   // x[0] is the origin
      if(normal.dot(x[3]) > 0) normal = -normal;   // outward
      normal.normalize();
      for(int k = 0; k < 3; ++k) normals[std::minmax(v[k], v[(k + 1) % 3])].push_back(normal);
    }
  const double cosine = std::cos(angle * CGAL_PI / 180);
  std::unordered_set<Vertex_handle> sharp;
  for(const auto& [edge, n] : normals)
    if(n.size() != 2 || n[0].dot(n[1]) < cosine) {   // more than two facets: a non-manifold edge, kept too
      sharp.insert(edge.first);
      sharp.insert(edge.second);
    }
  return sharp;
}

/*!
\ingroup PkgDistortionOptimizationRef

Improves the shapes of the cells of a mesh with its connectivity kept: the mesh at `positions` is
taken as the image of a map whose source cells are regular simplices, and the distortion of that
map is minimized with `CGAL::minimize_distortion()`. For a triangle mesh each ideal triangle has
the area of the triangle at `positions`; for a complex each ideal tetrahedron has the volume of the
cell in the triangulation (its points, which are also where the source tetrahedra are checked to be
positive), so that `positions` may start away from the triangulation's points. All ideal cells
have the orientation of the mesh as a whole (the sign of its total signed area for a triangle
mesh, positive for a complex). With the default `Conformal_dilatation` (scale invariant) each cell
is pulled towards the regular shape whatever its size; a measure that is not scale invariant
(`Isometric_dilatation`, `Symmetric_dirichlet`) also keeps each cell near the size of its ideal
cell. No cell that is valid at the start is ever inverted or flattened (exact predicates), so
`mesh_quality()`'s `inverted_cells` never grows.

\tparam Mesh a triangle mesh (`FaceListGraph`, planar: `positions` gives `Point_2`) or a
        `CGAL::Mesh_complex_3_in_triangulation_3` (`positions` gives `Point_3`, keyed by
        `Vertex_handle`; only cells in the complex count)
\tparam PositionMap a model of `ReadWritePropertyMap` from the vertex descriptors of a triangle mesh
        to `Point_2`, or from `Mesh::Triangulation::Vertex_handle` to `Point_3`
\tparam Measure a model of `DistortionMeasure`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param mesh the mesh (its connectivity; not modified)
\param positions the vertex positions: read as the start, written with the improved ones (free
       vertices only). For a `Surface_mesh<Point_2>`, `mesh.points()` improves it in place.
\param measure the distortion measure of the map from the ideal cells, normalized (infinite on flat cells)
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below: those of `CGAL::minimize_distortion()` except `vertex_point_map`, which is
       ignored (the source is the ideal cells). Vertex maps are keyed as `positions` is.

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{a property map containing the constrained-or-not status of each vertex: a constrained
                          vertex keeps its position}
    \cgalParamType{a class model of `ReadablePropertyMap` with the key type of `positions` and `bool` as value type}
    \cgalParamDefault{the border vertices of a triangle mesh, the vertices on the boundary of a complex, are
                      constrained; with `sliding_boundary`, no vertex is}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_weight_map}
    \cgalParamDescription{a property map associating a weight omega(v) to each vertex
                          (`Distortion_optimization::parameters::vertex_weight_map()`)}
    \cgalParamType{a class model of `ReadablePropertyMap` with the key type of `positions` and a number type
                   convertible to `double` as value type}
    \cgalParamDefault{omega(v) = 1 for every vertex}
    \cgalParamExtra{Every weight must be finite and positive.}
  \cgalParamNEnd

  \cgalParamNBegin{cell_weighting}
    \cgalParamDescription{the cell weights w(c, v) of the energy, with the ideal cells' volumes
                          (`Distortion_optimization::parameters::cell_weighting()`)}
    \cgalParamType{`Distortion_optimization::Cell_weighting`}
    \cgalParamDefault{`Distortion_optimization::Cell_weighting::AVERAGE_VOLUME`}
  \cgalParamNEnd

  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of iterations}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`100`}
  \cgalParamNEnd

  \cgalParamNBegin{convergence_threshold}
    \cgalParamDescription{as for `CGAL::minimize_distortion()`
                          (`Distortion_optimization::parameters::convergence_threshold()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`1e-4`}
    \cgalParamExtra{It must be non-negative.}
  \cgalParamNEnd

  \cgalParamNBegin{local_solver}
    \cgalParamDescription{how one vertex's local problem is solved (`Distortion_optimization::parameters::local_solver()`)}
    \cgalParamType{`Distortion_optimization::Local_solver`}
    \cgalParamDefault{`Distortion_optimization::Local_solver::GRADIENT_DESCENT`}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_order}
    \cgalParamDescription{the order in which a one-thread sweep visits the free vertices
                          (`Distortion_optimization::parameters::vertex_order()`)}
    \cgalParamType{`Distortion_optimization::Vertex_order`}
    \cgalParamDefault{`Distortion_optimization::Vertex_order::SORTED_PER_SWEEP`}
  \cgalParamNEnd

  \cgalParamNBegin{schedule}
    \cgalParamDescription{what an iteration does (`Distortion_optimization::parameters::schedule()`)}
    \cgalParamType{`Distortion_optimization::Schedule`}
    \cgalParamDefault{`GLOBAL` where the global steps are projected Newton steps (a measure that has a `hessian()`, other than the maxima `Conformal_dilatation`, `Condition_number`, `Isometric_dilatation` and `Volume_distortion` unless `PROJECTED_NEWTON` is given; tetrahedral complexes with no vertex constrained or sliding under `Conformal_dilatation`, `Condition_number` or `Isometric_dilatation`, whose steps are a smooth model's), with a local sweep added to an iteration whose step gains too little to go on or is cut short of its full length; `ALTERNATING` otherwise (the reweighted Laplacian's steps, and on tetrahedral complexes with the boundary sliding under `Conformal_dilatation`, `Condition_number` or `Isometric_dilatation` a smooth model's Newton steps, whose minimizers are not the measure's)}
  \cgalParamNEnd

  \cgalParamNBegin{global_solver}
    \cgalParamDescription{the system that gives the direction of a global step
                          (`Distortion_optimization::parameters::global_solver()`)}
    \cgalParamType{`Distortion_optimization::Global_solver`}
    \cgalParamDefault{`Distortion_optimization::Global_solver::PROJECTED_NEWTON`}
    \cgalParamExtra{Newton steps apply to measures with a `hessian()`; by default `Conformal_dilatation` takes the
                    Laplacian's steps, except on a complex with no vertex constrained (then MIPS's Newton steps; with vertices sliding, MIPS's Hessian as the metric of K's gradient);
                    with `PROJECTED_NEWTON` given, its own Newton steps where vertices are constrained.}
  \cgalParamNEnd

  \cgalParamNBegin{use_harmonic_start}
    \cgalParamDescription{if `true`, the run starts from the harmonic map of the fixed vertices (from the ideal cells)
                          when it is valid and better, or from the best safe point towards it
                          (`Distortion_optimization::parameters::use_harmonic_start()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`, except with `Distortion_optimization::Schedule::LOCAL`: then `false`}
  \cgalParamNEnd

  \cgalParamNBegin{untangle_first}
    \cgalParamDescription{if `true`, inverted start cells are first untangled as by `Distortion_optimization::untangle()`
                          (`Distortion_optimization::parameters::untangle_first()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`: under a normalized measure an inverted or flat start cell is an error}
    \cgalParamExtra{At most 1000 rounds, reported to the visitor first. A flat triangle of a triangle mesh at `positions` is a
                    degenerate source cell, an error even with this parameter.}
  \cgalParamNEnd

  \cgalParamNBegin{preserve_global_injectivity}
    \cgalParamDescription{if `true`, with free boundary vertices, the boundary is kept from crossing itself
                          (`Distortion_optimization::parameters::preserve_global_injectivity()`)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd

  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the number of threads; `0` for all the hardware offers
                          (`Distortion_optimization::parameters::number_of_threads()`)}
    \cgalParamType{`int`}
    \cgalParamDefault{`1`}
    \cgalParamExtra{Used when the program links `CGAL::TBB_support` (`CGAL_LINKED_WITH_TBB`); sequential otherwise.}
  \cgalParamNEnd

  \cgalParamNBegin{parallel_sweep}
    \cgalParamDescription{how local sweeps are shared among threads (`Distortion_optimization::parameters::parallel_sweep()`)}
    \cgalParamType{`Distortion_optimization::Parallel_sweep`}
    \cgalParamDefault{`Distortion_optimization::Parallel_sweep::INDEPENDENT_SETS`}
  \cgalParamNEnd

  \cgalParamNBegin{sliding_boundary}
    \cgalParamDescription{a surface on which the boundary vertices that are not constrained slide
                          (`Distortion_optimization::parameters::sliding_boundary()`), e.g.
                          `Triangle_surface::from_complex_boundary(c3t3, positions)` with the vertices of
                          `sharp_boundary_vertices()` constrained}
    \cgalParamType{a model of `SlidingSurface` of the dimension of the mesh (2 for a triangle mesh, 3 for a complex)}
    \cgalParamDefault{unused}
    \cgalParamExtra{With it, `vertex_is_constrained_map` defaults to no vertex.}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{for a triangle mesh, a \cgal Kernel deduced from the point type of `positions`, using
                      `CGAL::Kernel_traits`; for a complex,
                      `CGAL::Kernel_traits<Mesh::Triangulation::Geom_traits::Point_3>::Kernel`}
    \cgalParamExtra{Its orientation predicates decide, on `double` coordinates, which cells are inverted.}
  \cgalParamNEnd

  \cgalParamNBegin{visitor}
    \cgalParamDescription{a callable called after each iteration with the mean energy (and, if it takes a third
                          argument, the number of inverted or flat cells); returning `false` stops the run}
    \cgalParamType{a class with `bool operator()(std::size_t iteration, double energy) const` or
                   `bool operator()(std::size_t iteration, double energy, std::size_t inverted_cells) const`}
    \cgalParamDefault{unused}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the `Result` of the minimization: its energies are those of the map from the ideal cells
\throws Invalid_input for a measure that is not normalized (finite on flat cells: its minimum may flatten
        cells), and as `CGAL::minimize_distortion()`, e.g. for an inverted or flat start cell
        under a normalized measure (`untangle_first(true)` repairs inverted ones first, and flat
        tetrahedra of a complex), and for a flat triangle of a triangle mesh at `positions`
        (a degenerate source triangle, whatever the named parameters)
*/
template <class Mesh, class PositionMap, class Measure = Conformal_dilatation,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Result improve_mesh_quality(const Mesh& mesh, PositionMap positions, const Measure& measure = Measure(),
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  // A measure finite on flat cells (ARAP, Dirichlet) may trade some cells' shapes for the others'
  // down to numerically flat ones, valid to the exact predicates and useless as elements.
  if(!measure.is_normalized())
    throw Invalid_input("improve_mesh_quality: the measure " + measure.name() + " is finite on flat cells, so its "
                        "minimum may flatten some; take one infinite there (normalized), such as conformal or mips");
  if constexpr(internal::Is_c3t3<Mesh>::value) {
    auto adapter = internal::make_c3t3_adapter(mesh, positions, np);
    internal::use_ideal_cells(adapter.map);
    return internal::minimize_adapted(adapter, positions, measure, np);
  } else {
    // The start positions are the source: they give each cell its orientation and its size.
    auto adapter = internal::make_triangle_mesh_adapter(mesh, positions, np.vertex_point_map(positions));
    internal::use_ideal_cells(adapter.map);
    return internal::minimize_adapted(adapter, positions, measure, np);
  }
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_MESH_QUALITY_H
