// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A texture atlas of any triangle surface: compute_atlas(). This header reads the named
// parameters and translates the mesh to flat arrays; the steps (cuts, cones, flattening, packing)
// are in internal/atlas/, listed by Atlas_builder::run().

#ifndef CGAL_DISTORTION_OPTIMIZATION_ATLAS_H
#define CGAL_DISTORTION_OPTIMIZATION_ATLAS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/atlas/atlas_builder.h>
#include <CGAL/Distortion_optimization/internal/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <set>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// What `compute_atlas()` returns.
struct Atlas_result
{
  std::size_t charts = 0;             ///< charts (a connected piece of the surface, or a part of one: a region cut under `max_distortion`, or split for packing)
  std::size_t cones = 0;              ///< cone vertices the seams were drawn to
  double seam_length_fraction = 0;    ///< the seams' length over the length of all edges
  double packing_efficiency = 0;      ///< the charts' UV area over that of the rectangle bounding them all
  double mean_distortion = 0;         ///< the measure's mean over the surface, weighted by the faces' areas
  double max_distortion = 0;          ///< its largest value on a face
  std::size_t inverted_faces = 0;     ///< faces whose UV triangle is inverted or flat (exact predicate): 0
  std::size_t overlapping_charts = 0; ///< charts whose border crosses itself or another's: 0
  std::size_t iterations = 0;         ///< iterations of the charts' optimizations, summed
  double seconds = 0;                 ///< wall-clock time
  bool stopped_by_visitor = false;    ///< the visitor returned false (the charts are valid, less optimized)
};

namespace internal_np {
enum face_chart_map_t { face_chart_map };
enum edge_is_seam_map_t { edge_is_seam_map };
enum atlas_gutter_t { atlas_gutter };
enum min_chart_fill_t { min_chart_fill };
enum cone_log_scale_t { cone_log_scale };
enum max_distortion_t { max_distortion };
} // namespace internal_np

namespace parameters {
/// A writable face property map to `std::size_t` that receives each face's chart (`compute_atlas()`).
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(face_chart_map_t, face_chart_map)
/// A read-write edge property map to `bool` (`compute_atlas()`): the edges it flags are seams (the
/// user's, as CGAL's `Seam_mesh` takes them), and on return it flags every seam.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(edge_is_seam_map_t, edge_is_seam_map)
/// The space between charts and about them, a fraction of the unit square's side (`compute_atlas()`); default 0.01.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(atlas_gutter_t, atlas_gutter)
/// A chart that fills less than this of its least bounding rectangle is split for packing, along
/// straight lines in its UV plane (its map unchanged; the cuts become seams) (`compute_atlas()`);
/// default 0.6, 0 never splits.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(min_chart_fill_t, min_chart_fill)
/// Cones are placed until the conformal flattening's log scale factor is at most this everywhere
/// (`compute_atlas()`); default 1: smaller values give more cones and longer seams.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(cone_log_scale_t, cone_log_scale)
/// A bound on each piece's mean distortion (`compute_atlas()`): a piece above it is cut into more
/// charts of nearly constant normal until it holds; default none.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(max_distortion_t, max_distortion)
} // namespace parameters

/*!
\ingroup PkgDistortionOptimizationRef
Computes a texture atlas of the triangle surface `tm`, of any topology: each connected piece is
cut open along seams into one chart of genus 0 (a disk, or a disk with holes), each chart is
flattened with `measure` minimized, no triangle inverted and no chart's border crossing itself,
a chart that fills its bounding rectangle poorly is split (`min_chart_fill`), and the charts are packed into the unit square at one common scale (the same texel density
everywhere), turned but never mirrored, `atlas_gutter` apart.

The seams: the loops of a tree-cotree decomposition open the handles (Erickson and Whittlesey's
short loops), shortest paths join to the outer border each hole whose border turns on the
surface more than 5 degrees unlike a hole in the plane (by \f$ -2\pi \f$), and shortest paths
join the seams to cone vertices placed where a conformal flattening would stretch the piece most
(Ben-Chen, Gotsman and Bunin 2008); a piece of genus 0 with a border and a flat enough shape
needs none. `tm` is never modified: the seams only split
the UVs, which are written per corner, as CGAL's `Seam_mesh` has them: `uv[h]` is the UV of
`target(h)` in `face(h)`, for every halfedge `h` of a face.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam HalfedgeUVMap a writable property map with `halfedge_descriptor` as key type and a
        `Point_2` of a CGAL kernel as value type
\tparam Measure a distortion measure of this package (`Symmetric_dirichlet`, `Any_measure`, ...)

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map} \cgalParamDescription{the surface's points} \cgalParamDefault{`get(CGAL::vertex_point, tm)`} \cgalParamNEnd
  \cgalParamNBegin{face_chart_map} \cgalParamDescription{receives each face's chart number, from 0} \cgalParamDefault{unused} \cgalParamNEnd
  \cgalParamNBegin{cell_distortion_map} \cgalParamDescription{receives the measure's value on each face} \cgalParamDefault{unused} \cgalParamNEnd
  \cgalParamNBegin{edge_is_seam_map} \cgalParamDescription{the user's seams (edges flagged true; a border edge is no seam), then on return every seam} \cgalParamDefault{no seam given, none returned} \cgalParamNEnd
  \cgalParamNBegin{atlas_gutter} \cgalParamDescription{space between charts and about them, a fraction of the square's side, in [0, 0.25)} \cgalParamDefault{0.01} \cgalParamNEnd
  \cgalParamNBegin{min_chart_fill} \cgalParamDescription{a chart filling less of its least bounding rectangle is split for packing (by straight cuts, under a few rules, the densest packing kept; 0: never split), in [0, 1)} \cgalParamDefault{0.6} \cgalParamNEnd
  \cgalParamNBegin{cone_log_scale} \cgalParamDescription{the cones' bound on the conformal log scale factor, > 0} \cgalParamDefault{1} \cgalParamNEnd
  \cgalParamNBegin{max_distortion} \cgalParamDescription{a bound on each piece's mean distortion (area-weighted): a piece above it is cut into 2, 3, 4, 6, 9, ... charts of nearly constant normal (CGAL's variational shape approximation) and flattened again until it holds (or its charts would have fewer than 16 faces)} \cgalParamDefault{none} \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations} \cgalParamDescription{the most iterations of each chart's optimization} \cgalParamDefault{100} \cgalParamNEnd
  \cgalParamNBegin{convergence_threshold, schedule, local_solver, global_solver, cell_weighting, vertex_order, parallel_sweep} \cgalParamDescription{each chart's optimization's, as for `CGAL::minimize_distortion()` (the scaffold is remade every two iterations; the threshold is the relative gain under which the rounds stop)} \cgalParamDefault{theirs} \cgalParamNEnd
  \cgalParamNBegin{visitor} \cgalParamDescription{called as `visitor(iteration, energy)` or `visitor(iteration, energy, inverted)` after each iteration of the charts' optimizations, numbered across them; `false` stops them, and the charts not yet flattened keep their Tutte start} \cgalParamDefault{none} \cgalParamNEnd
  \cgalParamNBegin{number_of_threads} \cgalParamDescription{as for `CGAL::minimize_distortion()`} \cgalParamDefault{1} \cgalParamNEnd
\cgalNamedParamsEnd

\throws Invalid_input if `tm` has no face, a face that is not a triangle, a face of zero area, or
a parameter out of its range
*/
template <class TriangleMesh, class HalfedgeUVMap, class Measure,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Atlas_result compute_atlas(const TriangleMesh& tm, HalfedgeUVMap uv, const Measure& measure,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  const auto start = std::chrono::steady_clock::now();
  internal::Atlas_options options;
  options.gutter = choose_parameter(get_parameter(np, internal_np::atlas_gutter), 0.01);
  options.min_fill = choose_parameter(get_parameter(np, internal_np::min_chart_fill), 0.6);
  options.max_log_scale = choose_parameter(get_parameter(np, internal_np::cone_log_scale), 1.);
  options.max_distortion = choose_parameter(get_parameter(np, internal_np::max_distortion), 0.);
  options.optimizer = internal::read_options(np);
  options.weighting = choose_parameter(get_parameter(np, internal_np::cell_weighting), Cell_weighting::AVERAGE_VOLUME);
  if(!(options.gutter >= 0 && options.gutter < 0.25)) throw Invalid_input("compute_atlas(): the gutter must be in [0, 0.25)");
  if(!(options.min_fill >= 0 && options.min_fill < 1)) throw Invalid_input("compute_atlas(): the least chart fill must be in [0, 1)");
  if(!(options.max_log_scale > 0)) throw Invalid_input("compute_atlas(): the cones' log scale bound must be positive");
  if(!(options.max_distortion >= 0)) throw Invalid_input("compute_atlas(): the distortion bound must be positive");

  // The surface as flat arrays, each face's corners with the halfedge that has them.
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto index = CGAL::get_initialized_vertex_index_map(tm, np);
  std::vector<std::array<double, 3>> points(num_vertices(tm));
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    points[get(index, v)] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<halfedge_descriptor, 3>> corners;
  for(auto f : faces(tm)) {
    std::array<std::uint32_t, 3> t;
    std::array<halfedge_descriptor, 3> c;
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(i == 3) throw Invalid_input("compute_atlas(): face " + std::to_string(triangles.size()) + " is not a triangle");
      c[i] = h;
      t[i++] = static_cast<std::uint32_t>(get(index, target(h, tm)));
    }
    if(i != 3) throw Invalid_input("compute_atlas(): face " + std::to_string(triangles.size()) + " is not a triangle");
    triangles.push_back(t);
    corners.push_back(c);
  }

  const auto seam_map = get_parameter(np, internal_np::edge_is_seam_map);
  constexpr bool wants_seams = !std::is_same<std::decay_t<decltype(seam_map)>, CGAL::internal_np::Param_not_found>::value;
  if constexpr(wants_seams)
    for(auto e : edges(tm))
      if(get(seam_map, e) && !is_border(e, tm))
        options.seams.push_back({static_cast<std::uint32_t>(get(index, source(e, tm))), static_cast<std::uint32_t>(get(index, target(e, tm)))});

  const internal::Atlas_arrays a = internal::Atlas_builder<Measure>(points, triangles, measure, options).run();

  const auto chart_map = get_parameter(np, internal_np::face_chart_map);
  const auto value_map = get_parameter(np, internal_np::cell_distortion_map);
  constexpr bool wants_values = !std::is_same<std::decay_t<decltype(value_map)>, CGAL::internal_np::Param_not_found>::value;
  constexpr bool wants_charts = !std::is_same<std::decay_t<decltype(chart_map)>, CGAL::internal_np::Param_not_found>::value;
  std::set<std::pair<std::uint32_t, std::uint32_t>> seam;   // by its ends' indices, the smaller first
  for(const auto& [u, w] : a.seam_edges) seam.emplace((std::min)(u, w), (std::max)(u, w));
  if constexpr(wants_seams)
    for(auto e : edges(tm)) put(seam_map, e, false);
  std::size_t k = 0;
  for(auto f : faces(tm)) {
    for(int i = 0; i < 3; ++i) {
      put(uv, corners[k][i], Point_2(a.corner_uv[k][i][0], a.corner_uv[k][i][1]));
      if constexpr(wants_seams) {
        const std::uint32_t from = triangles[k][(i + 2) % 3], to = triangles[k][i];
        if(seam.count({(std::min)(from, to), (std::max)(from, to)}) > 0) put(seam_map, edge(corners[k][i], tm), true);
      }
    }
    if constexpr(wants_charts) put(chart_map, f, a.chart[k]);
    if constexpr(wants_values) put(value_map, f, a.face_distortion[k]);
    ++k;
  }

  Atlas_result r;
  r.charts = a.charts;
  r.cones = a.cones;
  r.seam_length_fraction = a.edge_length > 0 ? a.seam_length / a.edge_length : 0;
  r.packing_efficiency = a.packing_efficiency;
  r.mean_distortion = a.mean_distortion;
  r.max_distortion = a.max_distortion;
  r.inverted_faces = a.inverted_faces;
  r.overlapping_charts = a.overlapping_charts;
  r.iterations = a.iterations;
  r.stopped_by_visitor = a.stopped_by_visitor;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_ATLAS_H
