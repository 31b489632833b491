// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Start maps for surface parametrization, with the borders of CGAL's Surface_mesh_parameterization
// package (Tutte's map solved by the package's own sparse Cholesky solve, the discrete conformal
// map by CGAL's parameterizer), so that "parameterize, then improve" is two calls:
//   CGAL::Distortion_optimization::initial_parameterization(mesh, uv);
//   CGAL::minimize_distortion(mesh, uv, CGAL::Distortion_optimization::Symmetric_dirichlet());

#ifndef CGAL_DISTORTION_OPTIMIZATION_INITIAL_MAPS_H
#define CGAL_DISTORTION_OPTIMIZATION_INITIAL_MAPS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>
#include <CGAL/Distortion_optimization/internal/tutte_embedding.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

/// \ingroup PkgDistortionOptimizationRef
/// The convex shape the border of a disk is mapped to (with arc-length spacing).
enum class Border_shape { CIRCLE, SQUARE };

/// \ingroup PkgDistortionOptimizationRef
/// The kind of start map computed by `initial_parameterization()`.
enum class Initial_map
{
  TUTTE,            ///< barycentric (uniform weights) mapping: injective for a convex border (Tutte)
  DISCRETE_CONFORMAL ///< cotangent weights (discrete conformal map): smoother, may flip triangles
};

namespace internal_np {
enum initial_map_t { initial_map };
enum border_shape_t { border_shape };
} // namespace internal_np

namespace parameters {
/// An `Initial_map`: the kind of start map of `initial_parameterization()`; default `Initial_map::TUTTE`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(initial_map_t, initial_map)
/// A `Border_shape`: the shape the border is mapped to by `initial_parameterization()`; default
/// `Border_shape::CIRCLE`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(border_shape_t, border_shape)
} // namespace parameters

// (Declared for the pieces of a mesh, each parameterized alone: see below.)
template <class TriangleMesh, class UVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void initial_parameterization(const TriangleMesh& tm, UVMap uv, const NamedParameters& np = CGAL::parameters::default_values());

namespace internal {

// The longest border of tm, after checking that tm is one piece of genus 0 with a border: a disk,
// or a disk with holes, whose other borders `holes` receives (one halfedge of each, if given).
// (CGAL's parameterizers map the piece of the border only: the others would stay where uv had
// them; on a surface with handles no map to the plane is one-to-one.)
template <class TriangleMesh>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor longest_border_of_disk(
  const TriangleMesh& tm, std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>* holes = nullptr)
{
  if(num_faces(tm) == 0)
    throw Invalid_input("the mesh has no face");
  const std::size_t pieces =
    CGAL::Polygon_mesh_processing::connected_components(tm, get(CGAL::dynamic_face_property_t<std::size_t>(), tm));
  if(pieces != 1)
    throw Invalid_input("the mesh has " + std::to_string(pieces) + " connected components: a disk (one piece, genus 0, "
                        "one border) is needed to parameterize it");
  const auto border = CGAL::Polygon_mesh_processing::longest_border(tm).first;
  if(border == boost::graph_traits<TriangleMesh>::null_halfedge())
    throw Invalid_input("the mesh has no border: a disk (genus 0, one border) is needed to parameterize it");
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(tm, std::back_inserter(cycles));
  // V - E + F = 2 - 2 genus - borders on one piece (isolated vertices are not part of it).
  long long used_vertices = 0;
  for(auto v : vertices(tm)) used_vertices += halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge();
  const long long euler = used_vertices - static_cast<long long>(num_edges(tm)) + static_cast<long long>(num_faces(tm));
  const long long genus = (2 - euler - static_cast<long long>(cycles.size())) / 2;
  if(genus != 0)
    throw Invalid_input("the mesh has " + std::to_string(genus) + " handle" + (genus == 1 ? "" : "s") +
                        ": a disk, or a disk with holes (genus 0), is needed to parameterize it");
  if(holes) {
    holes->clear();
    for(auto h : cycles) {
      bool outer = false;
      for(auto g : CGAL::halfedges_around_face(h, tm)) outer = outer || g == border;
      if(!outer) holes->push_back(h);
    }
  }
  return border;
}

template <class TriangleMesh, class UVMap, class Parameterizer>
void run_parameterizer(const TriangleMesh& tm, UVMap uv, const Parameterizer& parameterizer)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> holes;
  const auto border = longest_border_of_disk(tm, &holes);
  if(!holes.empty())
    throw Invalid_input("the mesh has " + std::to_string(holes.size() + 1) + " borders: the discrete conformal start "
                        "needs a disk (one border); Tutte's start takes holes");
  // CGAL's parameterizers take a non-const mesh but do not modify it.
  const SMP::Error_code status = SMP::parameterize(const_cast<TriangleMesh&>(tm), parameterizer, border, uv);
  if(status != SMP::OK)
    throw Invalid_input(std::string("the parameterization failed: ") + SMP::get_error_message(status));
}

// Tutte's map as CGAL's Barycentric_mapping_parameterizer_3 defines it (the longest border placed
// by `border_parameterizer`, every other vertex at the mean of its neighbours), solved as the
// symmetric positive definite system of the inner vertices alone by the package's one Tutte solve
// (barycentric_positions()) rather than CGAL's unsymmetric system of all vertices and its
// iterative solver.
template <class TriangleMesh, class UVMap, class BorderParameterizer>
void tutte_parameterization(const TriangleMesh& tm, UVMap uv, BorderParameterizer border_parameterizer)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  using Point_2 = typename boost::property_traits<UVMap>::value_type;
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> holes;
  const auto border = longest_border_of_disk(tm, &holes);
  const auto index = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  const auto placed = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertex;
  for(auto v : vertices(tm)) {
    put(index, v, static_cast<int>(vertex.size()));
    put(placed, v, false);
    vertex.push_back(v);
  }
  const SMP::Error_code status = border_parameterizer.parameterize(tm, border, uv, index, placed);
  if(status != SMP::OK)
    throw Invalid_input(std::string("the parameterization failed: ") + SMP::get_error_message(status));
  std::vector<std::vector<std::uint32_t>> neighbours(vertex.size());
  std::vector<int> column(vertex.size(), -1);
  std::vector<Vector<2>> x(vertex.size(), Vector<2>::Zero());
  int size = 0;
  for(std::size_t i = 0; i < vertex.size(); ++i) {
    if(halfedge(vertex[i], tm) == boost::graph_traits<TriangleMesh>::null_halfedge()) continue;   // isolated: left alone
    if(get(placed, vertex[i])) {
      const Point_2 p = get(uv, vertex[i]);
      x[i] = Vector<2>(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    } else {
      column[i] = size++;
    }
    for(auto w : CGAL::vertices_around_target(halfedge(vertex[i], tm), tm))
      neighbours[i].push_back(static_cast<std::uint32_t>(get(index, w)));
  }
  // A disk with holes: each hole filled, for the solve only, by a vertex of its own joined to the
  // hole's border, so that the system is Tutte's of a triangulated disk, whose map is one-to-one
  // (Floater, "One-to-one piecewise linear mappings over triangulations", 2003); without the
  // fill, a hole's border vertices would lack the neighbours that hold them apart. The holes' map
  // is then a star-shaped polygon about each fill vertex, dropped after the solve.
  for(auto h : holes) {
    const auto fill = static_cast<std::uint32_t>(neighbours.size());
    neighbours.emplace_back();
    column.push_back(size++);
    x.push_back(Vector<2>::Zero());
    for(auto g : CGAL::halfedges_around_face(h, tm)) {
      const auto i = static_cast<std::uint32_t>(get(index, target(g, tm)));
      neighbours[i].push_back(fill);
      neighbours[fill].push_back(i);
    }
  }
  if(!barycentric_positions(neighbours, column, size, x))
    throw Invalid_input(std::string("the parameterization failed: ") + SMP::get_error_message(SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM));
  for(std::size_t i = 0; i < vertex.size(); ++i)
    if(column[i] >= 0) put(uv, vertex[i], Point_2(x[i][0], x[i][1]));
}

// For a mesh in several pieces: each piece's start map on a copy of it (one piece, so that the
// caller's checks and start apply to it alone), the maps placed left to right in a row, apart by a
// tenth of the widest, so that no two pieces overlap; true if tm has several pieces (done).
template <class TriangleMesh, class UVMap>
bool parameterize_pieces(const TriangleMesh& tm, UVMap uv, Initial_map kind, Border_shape border)
{
  using Point_3 = typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Point_2 = typename boost::property_traits<UVMap>::value_type;
  using Piece = CGAL::Surface_mesh<Point_3>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto piece_of = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const std::size_t pieces = num_faces(tm) == 0 ? 0 : CGAL::Polygon_mesh_processing::connected_components(tm, piece_of);
  if(pieces < 2) return false;
  std::vector<Piece> copy(pieces);
  std::vector<std::vector<vertex_descriptor>> original(pieces);
  const auto in_piece = get(CGAL::dynamic_vertex_property_t<typename Piece::Vertex_index>(), tm);
  const auto vpm = get(CGAL::vertex_point, tm);
  for(auto v : vertices(tm)) put(in_piece, v, Piece::null_vertex());
  for(auto f : faces(tm)) {
    const std::size_t k = get(piece_of, f);
    std::vector<typename Piece::Vertex_index> corners;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if(get(in_piece, v) == Piece::null_vertex()) {
        put(in_piece, v, copy[k].add_vertex(get(vpm, v)));
        original[k].push_back(v);
      }
      corners.push_back(get(in_piece, v));
    }
    copy[k].add_face(corners);
  }
  std::vector<std::vector<Vector<2>>> map(pieces);
  std::vector<CGAL::Bbox_2> box(pieces);
  double widest = 0;
  for(std::size_t k = 0; k < pieces; ++k) {
    auto piece_uv = copy[k].template add_property_map<typename Piece::Vertex_index, Point_2>("v:uv").first;
    try {
      initial_parameterization(copy[k], piece_uv, parameters::initial_map(kind, parameters::border_shape(border)));
    } catch(const Invalid_input& e) {
      throw Invalid_input("piece " + std::to_string(k + 1) + " of " + std::to_string(pieces) + ": " + e.what());
    }
    for(auto v : copy[k].vertices()) {
      map[k].emplace_back(CGAL::to_double(piece_uv[v].x()), CGAL::to_double(piece_uv[v].y()));
      box[k] += CGAL::Bbox_2(map[k].back()[0], map[k].back()[1], map[k].back()[0], map[k].back()[1]);
    }
    widest = (std::max)(widest, box[k].x_span());
  }
  double left = 0;
  for(std::size_t k = 0; k < pieces; ++k) {
    const Vector<2> shift(left - box[k].xmin(), -0.5 * (box[k].ymin() + box[k].ymax()));
    for(std::size_t i = 0; i < original[k].size(); ++i) {
      const Vector<2> p = map[k][i] + shift;
      put(uv, original[k][i], Point_2(p[0], p[1]));
    }
    left += box[k].x_span() + 0.1 * widest;
  }
  return true;
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationRef
/// Writes into `uv` (a vertex property map to `Point_2`) a fixed-border parameterization of the
/// disk `tm` (a `FaceListGraph` of triangles with one border), or of a disk with holes (one piece
/// of genus 0 with several borders): the longest border is mapped to a
/// circle or a square by arc length (named parameter `Distortion_optimization::parameters::border_shape()`,
/// default a circle), the inner vertices by the `Initial_map` given as
/// `Distortion_optimization::parameters::initial_map()` (default Tutte's); then the map is scaled about
/// the origin so that its area is the surface's (isometric measures compare lengths, and CGAL's
/// parameterizers map to the unit square whatever the surface's size), and mirrored (v to -v)
/// where it reverses the faces' orientation as a whole, as CGAL's square border does: the
/// triangles of a Tutte map are then all positively oriented, a valid start for
/// `CGAL::minimize_distortion()`. Coordinates of any magnitude
/// are accepted: a mesh far from unit size is parameterized scaled by a power of two.
/// With holes, Tutte's map is that of the disk whose every hole is filled by a fan about one added
/// vertex (for the solve only; `tm` is not modified): the holes' borders are mapped to star-shaped
/// polygons and the map is one-to-one. Free their vertices, with
/// `preserve_global_injectivity`, for `CGAL::minimize_distortion()` to open the holes up.
/// A mesh in several pieces gets each piece's map (each a disk or a disk with holes, parameterized
/// alone), the maps placed left to right in a row, apart by a tenth of the widest: no two overlap.
/// \throws Invalid_input if `tm` is empty, if a piece has no border or a handle, if a piece has
/// holes and the start is not Tutte's, or if CGAL's parameterizer fails.
template <class TriangleMesh, class UVMap, class NamedParameters>
void initial_parameterization(const TriangleMesh& tm, UVMap uv, const NamedParameters& np)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Initial_map kind = choose_parameter(get_parameter(np, internal_np::initial_map), Initial_map::TUTTE);
  const Border_shape border = choose_parameter(get_parameter(np, internal_np::border_shape), Border_shape::CIRCLE);
  using Point_3 = typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Point_2 = typename boost::property_traits<UVMap>::value_type;
  if(internal::parameterize_pieces(tm, uv, kind, border)) return;
  // CGAL's parameterizers square lengths, and the area below squares areas: far from unit size they
  // overflow or underflow. Such a mesh is parameterized as a copy scaled by the adapters' power of
  // two (exact), and the map scaled back.
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm);
  const double scale = internal::coordinate_scale((std::max)({box.x_span(), box.y_span(), box.z_span()}));
  if(scale != 1) {
    CGAL::Surface_mesh<Point_3> copy;
    std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                          typename CGAL::Surface_mesh<Point_3>::Vertex_index>> copied;
    CGAL::copy_face_graph(tm, copy, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(copied)));
    for(auto v : copy.vertices()) {
      const Point_3& p = copy.point(v);
      copy.point(v) = Point_3(scale * CGAL::to_double(p.x()), scale * CGAL::to_double(p.y()), scale * CGAL::to_double(p.z()));
    }
    auto copy_uv = copy.template add_property_map<typename CGAL::Surface_mesh<Point_3>::Vertex_index, Point_2>("v:uv").first;
    initial_parameterization(copy, copy_uv, parameters::initial_map(kind, parameters::border_shape(border)));
    for(const auto& [v, w] : copied)
      put(uv, v, Point_2(CGAL::to_double(copy_uv[w].x()) / scale, CGAL::to_double(copy_uv[w].y()) / scale));
    return;
  }
  using Circle = SMP::Circular_border_arc_length_parameterizer_3<TriangleMesh>;
  using Square = SMP::Square_border_arc_length_parameterizer_3<TriangleMesh>;
  auto run = [&](auto border_parameterizer) {
    using Border = decltype(border_parameterizer);
    if(kind == Initial_map::TUTTE)
      internal::tutte_parameterization(tm, uv, border_parameterizer);
    else
      internal::run_parameterizer(tm, uv, SMP::Discrete_conformal_map_parameterizer_3<TriangleMesh, Border>());
  };
  if(border == Border_shape::CIRCLE) run(Circle());
  else run(Square());

  // The areas, and the map's orientation: CGAL's square border runs clockwise where its circle runs
  // counterclockwise, and a map that mirrors every face would be inverted everywhere.
  double surface_area = 0, uv_area = 0, signed_uv_area = 0;
  const auto vpm = get(CGAL::vertex_point, tm);
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const auto a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
    surface_area += std::sqrt(CGAL::to_double(CGAL::squared_area(get(vpm, a), get(vpm, b), get(vpm, c))));
    const double area = CGAL::to_double(CGAL::area(get(uv, a), get(uv, b), get(uv, c)));
    uv_area += std::abs(area);
    signed_uv_area += area;
  }
  if(!(uv_area > 0) || !(surface_area > 0)) throw Invalid_input("the parameterization has no area");
  const double s = std::sqrt(surface_area / uv_area), mirror = signed_uv_area < 0 ? -1. : 1.;
  for(auto v : vertices(tm)) {
    const Point_2 p = get(uv, v);
    put(uv, v, Point_2(s * CGAL::to_double(p.x()), mirror * s * CGAL::to_double(p.y())));
  }
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INITIAL_MAPS_H
