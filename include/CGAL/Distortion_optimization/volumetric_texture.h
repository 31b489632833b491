// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Volumetric textures (section 4.4 of the paper): a surface inside the source volume of a map of
// tetrahedra is stored as the barycentric coordinates (eq. 18) of its vertices in the tetrahedra
// that contain them, so that any map of the tetrahedra carries it along:
//   1. embed_in_volume(), embed_surface_in_volume(): find each point's cell of the complex (a walk
//      in the triangulation, verified with exact predicates; a grid of the cells' boxes where the
//      walk fails) and its coordinates; points outside are an error or, on request, snapped to
//      the closest point of the complex's boundary.
//   2. carry_points(), carry_surface(), carry_surface_vertices(): the images of the points under a
//      target map of the complex's vertices, as often as there are maps (no new location).
// CGAL::compute_distortion() measures the carried surface against the original one (Point_3
// targets).

#ifndef CGAL_DISTORTION_OPTIMIZATION_VOLUMETRIC_TEXTURE_H
#define CGAL_DISTORTION_OPTIMIZATION_VOLUMETRIC_TEXTURE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

namespace internal_np {
enum snap_to_volume_t { snap_to_volume };
} // namespace internal_np

namespace parameters {

/// \ingroup PkgDistortionOptimizationRef
/// `bool`, for `embed_in_volume()` and `embed_surface_in_volume()`: snap the points that lie outside the volume to its closest
/// point (on the boundary of the complex) instead of throwing `Points_outside_volume`; default
/// `false`.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(snap_to_volume_t, snap_to_volume)

} // namespace parameters

/// \ingroup PkgDistortionOptimizationRef
/// The `Invalid_input` thrown by `embed_in_volume()` when points lie in no cell of the complex
/// (and `snap_to_volume` is not set): `indices()` lists them all, in increasing order; the message
/// is `listing()` followed by the remedy.
class Points_outside_volume : public Invalid_input
{
public:
  explicit Points_outside_volume(std::vector<std::size_t> indices)
    : Invalid_input(listing(indices) + "; Distortion_optimization::parameters::snap_to_volume(true) snaps them to its boundary"),
      indices_(std::make_shared<const std::vector<std::size_t>>(std::move(indices)))
  {}

  /// The indices (in the input range) of the points outside the volume.
  const std::vector<std::size_t>& indices() const { return *indices_; }

  /// Their number and the first ten, as in the message, without its remedy (for a caller that
  /// words its own, such as a tool's option).
  std::string listing() const { return listing(*indices_); }

private:
  static std::string listing(const std::vector<std::size_t>& indices)
  {
    std::string m = std::to_string(indices.size()) + (indices.size() == 1 ? " point is" : " points are") +
                    " outside the volume (in no cell of the complex): ";
    const std::size_t shown = std::min<std::size_t>(indices.size(), 10);
    for(std::size_t k = 0; k < shown; ++k) m += (k ? ", " : "") + std::to_string(indices[k]);
    return shown < indices.size() ? m + ", ..." : m;
  }

  // Shared, so that copying the exception (as throwing may) cannot throw.
  std::shared_ptr<const std::vector<std::size_t>> indices_;
};

/// \ingroup PkgDistortionOptimizationRef
/// Points embedded in the volume of a `Mesh_complex_3_in_triangulation_3` (eq. 18 of the paper):
/// for each point, a cell of the complex that contains it and its barycentric coordinates there.
/// Made by `embed_in_volume()`; read by `carry_points()`, `carry_surface()` and
/// `carry_surface_vertices()` for any number of target maps. It refers to the complex's cells: it
/// is valid as long as the triangulation is not modified.
template <class C3T3>
struct Volume_embedding
{
  using Cell_handle = typename C3T3::Triangulation::Cell_handle;

  /// For each point, a cell of the complex that contains it (one of those that share the face,
  /// edge or vertex it lies on).
  std::vector<Cell_handle> cells;
  /// For each point, its barycentric coordinates in its cell: weight `j` goes with
  /// `cells[i]->vertex(j)`. They are non-negative and sum to 1 (to rounding); exactly 0 for the
  /// vertices opposite the faces the point lies on (by exact predicates).
  std::vector<std::array<double, 4>> coordinates;
  /// The points that were outside the volume and were snapped to it (`snap_to_volume`), increasing.
  std::vector<std::size_t> snapped_points;
  /// Their distances to the volume, in the order of `snapped_points`.
  std::vector<double> snap_distances;

  /// The number of points.
  std::size_t size() const { return cells.size(); }

  /// The image of point `i` under the map that sends each vertex `v` of the complex to
  /// `get(target, v)` (a `Point_3`): the same barycentric combination of its cell's images.
  /// \throws Invalid_input if the image is not finite (a target of the cell's vertices is not).
  template <class TargetMap>
  typename boost::property_traits<TargetMap>::value_type image(std::size_t i, const TargetMap& target) const
  {
    using Point = typename boost::property_traits<TargetMap>::value_type;
    double x[3] = {0, 0, 0};
    for(int j = 0; j < 4; ++j) {
      const Point& q = get(target, cells[i]->vertex(j));
      const double w = coordinates[i][j];
      x[0] += w * CGAL::to_double(q.x());
      x[1] += w * CGAL::to_double(q.y());
      x[2] += w * CGAL::to_double(q.z());
    }
    if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      throw Invalid_input("the image of point " + std::to_string(i) + " is not finite: a vertex of its cell has a non-finite target");
    return Point(x[0], x[1], x[2]);
  }
};

namespace internal {

// Finds the cell of a complex that contains a point: a walk first, verified, then a grid. Builds
// the grid and the boundary tree only when they are needed.
template <class C3T3>
class Volume_locator
{
  using Tr = typename C3T3::Triangulation;
  using Cell_handle = typename Tr::Cell_handle;
  using GT = typename Tr::Geom_traits;
  using Point = typename GT::Point_3;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Triangle = typename Kernel::Triangle_3;
  using Coordinates = std::array<double, 4>;
  using Boundary_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, typename std::vector<Triangle>::const_iterator>>>;

public:
  explicit Volume_locator(const C3T3& c3t3) : c3t3_(c3t3), tr_(c3t3.triangulation()) {}

  // A cell of the complex that contains p (closed), tried first where the walk from `hint` ends,
  // then among the grid's candidates; false if there is none. `hint` becomes the cell found.
  bool locate(const Point& p, Cell_handle& hint, Cell_handle& cell, Coordinates& w)
  {
    // The walk ends in the cell that contains p when the triangulation is Delaunay (Mesh_3) or
    // when it can reach p without leaving the complex; through a concave part of the boundary of
    // a complex built from tetrahedra (c3t3_from_tetrahedra) it may stop outside instead.
    typename Tr::Locate_type lt;
    int li, lj;
    const Cell_handle c = tr_.locate(typename Tr::Point(p), lt, li, lj, hint);
    if(c != Cell_handle() && contains(c, p, w)) {
      hint = cell = c;
      return true;
    }
    if(!grid_built_) build_grid();
    if(!inside_box(box_, p)) return false;
    const std::size_t b = bucket(index(CGAL::to_double(p.x()), 0), index(CGAL::to_double(p.y()), 1), index(CGAL::to_double(p.z()), 2));
    for(std::size_t k = first_[b]; k < first_[b + 1]; ++k) {
      const std::uint32_t i = items_[k];
      if(inside_box(boxes_[i], p) && contains(cells_[i], p, w)) {
        hint = cell = cells_[i];
        return true;
      }
    }
    return false;
  }

  // The closest point of the complex's boundary to p, as a cell and its coordinates (zero for the
  // vertex opposite the boundary facet); returns the distance from p.
  double snap(const Point& p, Cell_handle& cell, Coordinates& w)
  {
    if(!tree_) build_boundary_tree();
    const auto [q, id] = tree_->closest_point_and_primitive(p);
    const std::size_t f = static_cast<std::size_t>(id - boundary_.begin());
    const auto& [c, i] = boundary_facets_[f];
    // q's coordinates in the facet triangle (normal equations of q - a = s (b - a) + u (c - a)),
    // clamped so that the snapped point lies on the facet.
    const Triangle& t = boundary_[f];
    const auto e1 = t[1] - t[0], e2 = t[2] - t[0], d = q - t[0];
    const double a11 = CGAL::to_double(e1 * e1), a12 = CGAL::to_double(e1 * e2), a22 = CGAL::to_double(e2 * e2);
    const double b1 = CGAL::to_double(d * e1), b2 = CGAL::to_double(d * e2);
    const double det = a11 * a22 - a12 * a12;
    double s = (a22 * b1 - a12 * b2) / det, u = (a11 * b2 - a12 * b1) / det;
    double r = 1 - s - u;
    s = std::max(s, 0.), u = std::max(u, 0.), r = std::max(r, 0.);
    double sum = r + s + u;
    if(!(sum > 0) || !std::isfinite(sum)) {   // a facet too thin for the normal equations: its nearest corner
      const double d0 = CGAL::to_double(CGAL::squared_distance(q, t[0])), d1 = CGAL::to_double(CGAL::squared_distance(q, t[1])),
                   d2 = CGAL::to_double(CGAL::squared_distance(q, t[2]));
      const int nearest = d0 <= d1 && d0 <= d2 ? 0 : d1 <= d2 ? 1 : 2;
      r = nearest == 0, s = nearest == 1, u = nearest == 2;
      sum = 1;
    }
    w[i] = 0;
    w[(i + 1) % 4] = r / sum;
    w[(i + 2) % 4] = s / sum;
    w[(i + 3) % 4] = u / sum;
    cell = c;
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
  }

private:
  Point point(Cell_handle c, int j) const { return tr_.geom_traits().construct_point_3_object()(tr_.point(c, j)); }

  // Whether c is a cell of the complex that contains p (exact predicates), and then p's
  // barycentric coordinates in it.
  bool contains(Cell_handle c, const Point& p, Coordinates& w) const
  {
    if(tr_.is_infinite(c) || !c3t3_.is_in_complex(c)) return false;
    const auto orientation = tr_.geom_traits().orientation_3_object();
    std::array<Point, 4> v = {point(c, 0), point(c, 1), point(c, 2), point(c, 3)};
    // Complex cells are positive; the sign is read rather than assumed, and a flat cell (which
    // no barycentric coordinates describe) contains nothing.
    const CGAL::Orientation sign = orientation(v[0], v[1], v[2], v[3]);
    if(sign == CGAL::COPLANAR) return false;
    std::array<CGAL::Orientation, 4> o;
    for(int i = 0; i < 4; ++i) {
      std::array<Point, 4> q = v;
      q[i] = p;
      o[i] = orientation(q[0], q[1], q[2], q[3]);
      if(o[i] == -sign) return false;
    }
    // Coordinate i is the volume of the cell with vertex i moved to p, over the cell's. The
    // volumes are computed relative to p (small numbers when p is near the cell), set to 0
    // where the exact predicate says p is on the face, clamped at 0 otherwise (p is inside), and
    // normalized by their sum.
    std::array<std::array<double, 3>, 4> d;
    for(int j = 0; j < 4; ++j) {
      d[j] = {CGAL::to_double(v[j].x()) - CGAL::to_double(p.x()), CGAL::to_double(v[j].y()) - CGAL::to_double(p.y()),
              CGAL::to_double(v[j].z()) - CGAL::to_double(p.z())};
    }
    double sum = 0;
    for(int i = 0; i < 4; ++i) {
      if(o[i] == CGAL::COPLANAR) {
        w[i] = 0;
        continue;
      }
      std::array<std::array<double, 3>, 4> q = d;
      q[i] = {0, 0, 0};
      w[i] = std::max(0., (sign == CGAL::POSITIVE ? 1. : -1.) * volume(q));
      sum += w[i];
    }
    if(!(sum > 0) || !std::isfinite(sum)) {
      // A cell so thin that rounding swamps its volume (never seen): its vertex nearest to p.
      int nearest = 0;
      for(int j = 1; j < 4; ++j)
        if(CGAL::squared_distance(p, v[j]) < CGAL::squared_distance(p, v[nearest])) nearest = j;
      w = {0, 0, 0, 0};
      w[nearest] = sum = 1;
    }
    for(double& x : w) x /= sum;
    return true;
  }

  // det(b1 - b0, b2 - b0, b3 - b0): CGAL's orientation of (b0, b1, b2, b3) is its sign.
  static double volume(const std::array<std::array<double, 3>, 4>& b)
  {
    double e[3][3];
    for(int k = 0; k < 3; ++k)
      for(int a = 0; a < 3; ++a) e[k][a] = b[k + 1][a] - b[0][a];
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  }

  static bool inside_box(const CGAL::Bbox_3& b, const Point& p)
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    return b.xmin() <= x && x <= b.xmax() && b.ymin() <= y && y <= b.ymax() && b.zmin() <= z && z <= b.zmax();
  }

  // The grid: about one bucket per cell; each cell is listed in every bucket its box overlaps.
  // Bucket indices are monotone in the coordinate, so a box that contains p is listed in p's
  // bucket whatever the rounding.
  int index(double x, int axis) const
  {
    const double t = std::floor((x - low_[axis]) * inverse_step_[axis]);
    return static_cast<int>(std::min(std::max(t, 0.), static_cast<double>(size_[axis] - 1)));
  }
  std::size_t bucket(int i, int j, int k) const { return (static_cast<std::size_t>(k) * size_[1] + j) * size_[0] + i; }

  void build_grid()
  {
    grid_built_ = true;
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c) {
      cells_.push_back(c);
      boxes_.push_back(point(c, 0).bbox() + point(c, 1).bbox() + point(c, 2).bbox() + point(c, 3).bbox());
      box_ += boxes_.back();
    }
    const double extent[3] = {box_.xmax() - box_.xmin(), box_.ymax() - box_.ymin(), box_.zmax() - box_.zmin()};
    const double largest = std::max({extent[0], extent[1], extent[2]});
    const double step = std::max(std::cbrt(extent[0] * extent[1] * extent[2] / static_cast<double>(cells_.size())), 1e-3 * largest);
    for(int a = 0; a < 3; ++a) {
      low_[a] = a == 0 ? box_.xmin() : a == 1 ? box_.ymin() : box_.zmin();
      size_[a] = static_cast<int>(std::min(std::max(std::ceil(extent[a] / step), 1.), 1000.));
      inverse_step_[a] = extent[a] > 0 ? size_[a] / extent[a] : 0.;
    }
    // Counting sort of (bucket, cell) pairs into first_ / items_.
    first_.assign(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2] + 1, 0);
    for(int pass = 0; pass < 2; ++pass) {
      if(pass == 1) {
        std::partial_sum(first_.begin(), first_.end(), first_.begin());
        items_.resize(first_.back());
      }
      for(std::size_t c = 0; c < cells_.size(); ++c) {
        const CGAL::Bbox_3& b = boxes_[c];
        for(int k = index(b.zmin(), 2); k <= index(b.zmax(), 2); ++k)
          for(int j = index(b.ymin(), 1); j <= index(b.ymax(), 1); ++j)
            for(int i = index(b.xmin(), 0); i <= index(b.xmax(), 0); ++i) {
              if(pass == 0) ++first_[bucket(i, j, k) + 1];
              else items_[first_[bucket(i, j, k)]++] = static_cast<std::uint32_t>(c);
            }
      }
    }
    // The second pass advanced each bucket's start to the next one's: shift back.
    std::copy_backward(first_.begin(), first_.end() - 1, first_.end());
    first_[0] = 0;
  }

  void build_boundary_tree()
  {
    for(auto c = c3t3_.cells_in_complex_begin(); c != c3t3_.cells_in_complex_end(); ++c)
      for(int i = 0; i < 4; ++i)
        if(!c3t3_.is_in_complex(c->neighbor(i))) {
          boundary_.emplace_back(point(c, (i + 1) % 4), point(c, (i + 2) % 4), point(c, (i + 3) % 4));
          boundary_facets_.emplace_back(c, i);
        }
    tree_ = std::make_unique<Boundary_tree>(boundary_.begin(), boundary_.end());
    tree_->accelerate_distance_queries();
  }

  const C3T3& c3t3_;
  const Tr& tr_;
  bool grid_built_ = false;
  std::vector<Cell_handle> cells_;
  std::vector<CGAL::Bbox_3> boxes_;
  CGAL::Bbox_3 box_;
  double low_[3] = {0, 0, 0}, inverse_step_[3] = {0, 0, 0};
  int size_[3] = {1, 1, 1};
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> items_;
  std::vector<Triangle> boundary_;
  std::vector<std::pair<Cell_handle, int>> boundary_facets_;
  std::unique_ptr<Boundary_tree> tree_;
};

} // namespace internal

/// \ingroup PkgDistortionOptimizationRef
/// Embeds points in the volume of the complex `c3t3` (a `CGAL::Mesh_complex_3_in_triangulation_3`;
/// only its cells count): for each point, a cell that contains it and its barycentric coordinates
/// (eq. 18 of the paper), so that `carry_points()` can map it with any map of the complex.
///
/// Each point is first located by the triangulation's walk, from the cell of the previous point
/// (the points are visited in a spatial order); the answer is accepted when exact orientation
/// predicates confirm that it is a cell of the complex containing the point. Otherwise (the walk
/// of a complex made of non-convex tetrahedra, `c3t3_from_tetrahedra()`, may stop outside it; a
/// point on the complex's boundary may be located in a cell outside) the cells whose bounding
/// boxes contain the point, found in a grid, are tested the same way. A point on a face, an edge
/// or a vertex gets one of the cells that share it.
///
/// \tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
/// \tparam PointRange a model of `ConstRange` whose value type is a 3D point type (with `x()`, `y()`,
///         `z()` convertible by `CGAL::to_double()`), e.g. `Point_3`
/// \tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"
///
/// \param c3t3 the complex (not modified; the embedding refers to its cells)
/// \param points a range of `Point_3`
/// \param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
///        ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{snap_to_volume}
///     \cgalParamDescription{if `true`, a point in no cell is snapped to the closest point of the complex's boundary
///                           facets (found in an AABB tree), and listed in `Volume_embedding::snapped_points` with its
///                           distance in `Volume_embedding::snap_distances`
///                           (`Distortion_optimization::parameters::snap_to_volume()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`: a point in no cell is an error}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Points_outside_volume (an `Invalid_input`) for points in no cell of the complex,
///   without `snap_to_volume`; the message gives their number and the first indices
/// \throws Invalid_input for a point with a non-finite coordinate or one beyond 1e100 in magnitude,
/// or a complex with no cell
template <class C3T3, class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
Volume_embedding<C3T3> embed_in_volume(const C3T3& c3t3, const PointRange& points,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using Tr = typename C3T3::Triangulation;
  using Point = typename Tr::Geom_traits::Point_3;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  const bool snap = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::snap_to_volume), false);
  if(c3t3.number_of_cells_in_complex() == 0) throw Invalid_input("the complex has no cell");
  std::vector<Point> p;
  for(const auto& q : points) {
    const double x = CGAL::to_double(q.x()), y = CGAL::to_double(q.y()), z = CGAL::to_double(q.z());
    if(const std::string problem = internal::coordinate_problem(x, y, z); !problem.empty())
      throw Invalid_input("point " + std::to_string(p.size()) + " has " + problem);
    p.emplace_back(x, y, z);
  }
  Volume_embedding<C3T3> e;
  e.cells.resize(p.size());
  e.coordinates.resize(p.size());
  // Nearby points one after the other: each walk is short.
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  CGAL::spatial_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, decltype(CGAL::make_property_map(p))>(CGAL::make_property_map(p)));
  internal::Volume_locator<C3T3> locator(c3t3);
  typename Tr::Cell_handle hint;
  std::vector<std::size_t> outside;
  for(std::size_t i : order)
    if(!locator.locate(p[i], hint, e.cells[i], e.coordinates[i])) outside.push_back(i);
  std::sort(outside.begin(), outside.end());
  if(!outside.empty() && !snap) throw Points_outside_volume(std::move(outside));
  for(std::size_t i : outside) {
    e.snap_distances.push_back(locator.snap(p[i], e.cells[i], e.coordinates[i]));
    e.snapped_points.push_back(i);
  }
  return e;
}

/// \ingroup PkgDistortionOptimizationRef
/// `embed_in_volume()` of the vertices of the triangle mesh `tm`, in the order of `vertices(tm)`:
/// the embedding that `carry_surface()` and `carry_surface_vertices()` read.
///
/// \tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"
///
/// \param c3t3 the complex (not modified; the embedding refers to its cells)
/// \param tm the triangle mesh whose vertices are embedded (not modified)
/// \param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
///        ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and a 3D point type (with `x()`, `y()`, `z()` convertible by `CGAL::to_double()`)
///                    as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
///                     must be available in `TriangleMesh`.}
///   \cgalParamNEnd
///
///   \cgalParamNBegin{snap_to_volume}
///     \cgalParamDescription{if `true`, a vertex in no cell is snapped to the closest point of the complex's boundary
///                           facets, as in `embed_in_volume()` (`Distortion_optimization::parameters::snap_to_volume()`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`: a vertex in no cell is an error}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Points_outside_volume (an `Invalid_input`), indices in the order of `vertices(tm)`, and
///   Invalid_input as `embed_in_volume()`
template <class C3T3, class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Volume_embedding<C3T3> embed_surface_in_volume(const C3T3& c3t3, const TriangleMesh& tm,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  std::vector<typename boost::property_traits<decltype(vpm)>::value_type> points;
  for(auto v : vertices(tm)) points.push_back(get(vpm, v));
  return embed_in_volume(c3t3, points, np);
}

/// \ingroup PkgDistortionOptimizationRef
/// Writes the image of each embedded point under the map that sends each vertex `v` of the complex
/// to `get(target, v)` to `out`, in the order of the points: `Volume_embedding::image()`. Under an
/// affine map of the complex the points move by the same affine map.
/// \tparam TargetMap a `ReadablePropertyMap` from `Vertex_handle` to `Point_3` (as for
///         `CGAL::minimize_distortion()` on a complex)
/// \throws Invalid_input for a non-finite image; `out` may then have received the images before it
template <class C3T3, class TargetMap, class OutputIterator>
OutputIterator carry_points(const Volume_embedding<C3T3>& embedding, const TargetMap& target, OutputIterator out)
{
  for(std::size_t i = 0; i < embedding.size(); ++i) *out++ = embedding.image(i, target);
  return out;
}

namespace internal {

template <class C3T3, class TargetMap, class TriangleMesh>
std::vector<typename boost::property_traits<TargetMap>::value_type>
carried_vertices(const TriangleMesh& tm, const Volume_embedding<C3T3>& embedding, const TargetMap& target)
{
  if(static_cast<std::size_t>(vertices(tm).size()) != embedding.size())
    throw Invalid_input("the embedding has " + std::to_string(embedding.size()) + " points and the mesh " +
                        std::to_string(vertices(tm).size()) + " vertices: embed the mesh with embed_surface_in_volume()");
  std::vector<typename boost::property_traits<TargetMap>::value_type> images;
  images.reserve(embedding.size());
  carry_points(embedding, target, std::back_inserter(images));
  return images;
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationRef
/// `put(image, v, p)` for each vertex `v` of `tm`, `p` its image under the map `target` of the
/// complex, for the embedding of `tm`'s vertices (`embed_surface_in_volume()`). With `image` a
/// vertex map to `Point_3`, `CGAL::compute_distortion(tm, image, measure)` measures how the
/// volume map distorts the surface. Nothing is written if an exception is thrown.
/// \throws Invalid_input if the embedding does not have one point per vertex, or for a
///   non-finite image
template <class TriangleMesh, class C3T3, class TargetMap, class VertexImageMap>
void carry_surface_vertices(const TriangleMesh& tm, const Volume_embedding<C3T3>& embedding, const TargetMap& target,
                            VertexImageMap image)
{
  using Point = typename boost::property_traits<VertexImageMap>::value_type;
  const auto images = internal::carried_vertices(tm, embedding, target);
  std::size_t i = 0;
  for(auto v : vertices(tm)) {
    const auto& q = images[i++];
    put(image, v, Point(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())));
  }
}

/// \ingroup PkgDistortionOptimizationRef
/// Makes `out` (not `tm` itself) a copy of the triangle mesh `tm` whose vertex points
/// (`get(CGAL::vertex_point, out)`) are the images of `tm`'s vertices under the map `target` of
/// the complex, for the embedding of `tm`'s vertices (`embed_surface_in_volume()`). The copy has
/// the same vertices and faces in the same order; when `OutputMesh` is `TriangleMesh` it is a copy
/// of `tm` (same descriptors, so that the copy's point map is a target map of `tm` for
/// `CGAL::compute_distortion()`), otherwise it is built vertex by vertex, then face by face.
/// \tparam OutputMesh a `MutableFaceGraph` with an internal vertex point property, default
///         constructible and assignable (e.g. `CGAL::Surface_mesh<Point_3>`)
/// \throws Invalid_input if the embedding does not have one point per vertex, for a non-finite
///   image, or if `OutputMesh` cannot hold a face of `tm`; `out` is then unchanged
template <class TriangleMesh, class C3T3, class TargetMap, class OutputMesh>
void carry_surface(const TriangleMesh& tm, const Volume_embedding<C3T3>& embedding, const TargetMap& target, OutputMesh& out)
{
  const auto images = internal::carried_vertices(tm, embedding, target);
  if constexpr(std::is_same<OutputMesh, TriangleMesh>::value) {
    out = tm;
  } else {
    OutputMesh copy;
    std::vector<typename boost::graph_traits<OutputMesh>::vertex_descriptor> vertex_of;
    auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    for(auto v : vertices(tm)) {
      put(index, v, vertex_of.size());
      vertex_of.push_back(add_vertex(copy));
    }
    std::vector<typename boost::graph_traits<OutputMesh>::vertex_descriptor> corners;
    std::size_t f_index = 0;
    for(auto f : faces(tm)) {
      corners.clear();
      for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) corners.push_back(vertex_of[get(index, v)]);
      if(CGAL::Euler::add_face(corners, copy) == boost::graph_traits<OutputMesh>::null_face())
        throw Invalid_input("face " + std::to_string(f_index) + " cannot be added to the output mesh");
      ++f_index;
    }
    out = std::move(copy);
  }
  auto out_vpm = get(CGAL::vertex_point, out);
  using Out_point = typename boost::property_traits<decltype(out_vpm)>::value_type;
  std::size_t i = 0;
  for(auto v : vertices(out)) {
    const auto& q = images[i++];
    put(out_vpm, v, Out_point(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())));
  }
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_VOLUMETRIC_TEXTURE_H
