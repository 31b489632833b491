// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Start maps for the tetrahedra of a Mesh_complex_3_in_triangulation_3: a user function, the
// radial map x |x| of the paper's Table 1 and Fig. 5, a star-shaped domain onto the unit ball, and
// the harmonic map for fixed boundary targets. Targets are property maps keyed by Vertex_handle; only
// vertices of cells in the complex are written.

#ifndef CGAL_DISTORTION_OPTIMIZATION_VOLUME_MAPS_H
#define CGAL_DISTORTION_OPTIMIZATION_VOLUME_MAPS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/c3t3_adapter.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>
#include <CGAL/Distortion_optimization/internal/named_parameters.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel/global_functions_3.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Eigenvalues>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

namespace internal_np {
enum center_t { center };
} // namespace internal_np

namespace parameters {
/// `radial_map()` and `star_shaped_to_unit_ball()`: the centre of the map, a point of the
/// complex's kernel (`Point_3`, or `CGAL::ORIGIN`); default `volume_centroid()` of the complex.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(center_t, center)
} // namespace parameters

/// \ingroup PkgDistortionOptimizationRef
/// `put(target, v, f(p))` for every vertex `v` (position `p`, a `Point_3`) of the cells of the complex.
template <class C3T3, class TargetMap, class Function>
void map_vertices(const C3T3& c3t3, TargetMap target, const Function& f)
{
  const auto& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  std::unordered_set<typename C3T3::Triangulation::Vertex_handle> done;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(done.insert(c->vertex(i)).second) put(target, c->vertex(i), f(point(tr.point(c, i))));
}

namespace internal {

// The point type of a complex's vertices (without weight); the start maps take their centre as one,
// so that `CGAL::ORIGIN` converts to it.
template <class C3T3>
using C3t3_point = typename C3T3::Triangulation::Geom_traits::Point_3;

// The power of two that brings the largest extent of the cells' vertices into [1, 2). The start
// maps construct in coordinates scaled by it: their products of three or four lengths (volumes,
// normals dotted with directions) overflow beyond about 2^250 and underflow below 2^-250 otherwise,
// and an exact scaling changes no result in between.
template <class C3T3>
double complex_scale(const C3T3& c3t3)
{
  const auto& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  Bbox_3 box;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i) box += point(tr.point(c, i)).bbox();
  double half_extent = 0;   // an extent may overflow (from -2^1023 to 2^1023)
  for(int k = 0; k < 3; ++k) half_extent = (std::max)(half_extent, box.max_coord(k) / 2 - box.min_coord(k) / 2);
  return unit_scale(half_extent) / 2;
}

// `p` times `s`, a power of two.
template <class Point_3>
Point_3 scaled(const Point_3& p, double s)
{
  return Point_3(s * CGAL::to_double(p.x()), s * CGAL::to_double(p.y()), s * CGAL::to_double(p.z()));
}

// Whether p is in a cell of the complex (its facets included) and on no facet of the complex's
// boundary (exact predicates). Both are needed: a corner of the domain is in a cell whose facets
// through it are all inner ones.
template <class C3T3, class Point_3>
bool is_strictly_inside(const C3T3& c3t3, const Point_3& p)
{
  const auto& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  bool in_a_cell = false;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    bool inside = true;
    for(int i = 0; i < 4; ++i) {
      // p replaces vertex i: the facet opposite i sees p on the cell's side, or p is on it.
      std::array<Point_3, 4> q;
      for(int j = 0; j < 4; ++j) q[j] = j == i ? p : Point_3(point(tr.point(c, j)));
      const CGAL::Orientation o = CGAL::orientation(q[0], q[1], q[2], q[3]);
      inside = inside && o != CGAL::NEGATIVE;
      if(o == CGAL::ZERO && !c3t3.is_in_complex(c->neighbor(i))) {   // p on the plane of a boundary facet
        const auto a = point(tr.point(c, (i + 1) % 4)), b = point(tr.point(c, (i + 2) % 4)), d = point(tr.point(c, (i + 3) % 4));
        if(typename CGAL::Kernel_traits<Point_3>::Kernel::Triangle_3(Point_3(a), Point_3(b), Point_3(d)).has_on(p)) return false;
      }
    }
    in_a_cell = in_a_cell || inside;
  }
  return in_a_cell;
}

// The symmetric matrix A = M^(-1/2), M the second moment of the complex's volume about `center`
// (points scaled by `scale`): A maps the domain to one whose inertia is the same about every axis.
// The second moment of a tetrahedron with vertices p_i about the origin is
// |V| / 20 (sum_i p_i p_i^T + (sum_i p_i)(sum_i p_i)^T).
template <class C3T3, class Point_3>
Eigen::Matrix3d whitening(const C3T3& c3t3, double scale, const Point_3& center)
{
  const auto& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Eigen::Matrix3d p;   // the edges from vertex 0, one per column: 6 V = det p
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), q[4];
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
    for(int i = 0; i < 4; ++i) {
      const auto u = scaled(Point_3(point(tr.point(c, i))), scale) - center;
      q[i] = Eigen::Vector3d(CGAL::to_double(u.x()), CGAL::to_double(u.y()), CGAL::to_double(u.z()));
      sum += q[i];
      outer += q[i] * q[i].transpose();
    }
    p << q[1] - q[0], q[2] - q[0], q[3] - q[0];
    moment += std::abs(p.determinant()) / 120 * (outer + sum * sum.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(moment);
  const Eigen::Vector3d values = eigen.eigenvalues();
  if(eigen.info() != Eigen::Success || !(values.minCoeff() > 0) || !std::isfinite(values.maxCoeff()))
    return Eigen::Matrix3d::Identity();
  return eigen.eigenvectors() * values.cwiseSqrt().cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationRef
/// The centre of mass of the cells of the complex (each cell weighted by its volume): the natural
/// centre of `star_shaped_to_unit_ball()` and `radial_map()`, and the tool's default `--center`.
/// The average of the vertices would follow the mesh's sampling instead of the volume.
/// \throws Invalid_input if the complex has no cell of positive volume
template <class C3T3>
typename C3T3::Triangulation::Geom_traits::Point_3 volume_centroid(const C3T3& c3t3)
{
  using Point_3 = internal::C3t3_point<C3T3>;
  const auto& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  const double s = internal::complex_scale(c3t3);
  double volume = 0, x = 0, y = 0, z = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Point_3 p[4];
    for(int i = 0; i < 4; ++i) p[i] = internal::scaled(Point_3(point(tr.point(c, i))), s);
    const double w = std::abs(CGAL::to_double(CGAL::volume(p[0], p[1], p[2], p[3])));
    const Point_3 g = CGAL::centroid(p[0], p[1], p[2], p[3]);
    volume += w;
    x += w * CGAL::to_double(g.x());
    y += w * CGAL::to_double(g.y());
    z += w * CGAL::to_double(g.z());
  }
  if(!(volume > 0)) throw Invalid_input("the complex has no cell of positive volume: it has no centroid");
  return Point_3(x / volume / s, y / volume / s, z / volume / s);
}

namespace internal {

// The `center` named parameter, or the complex's volume centroid.
template <class C3T3, class NamedParameters>
C3t3_point<C3T3> center_parameter(const C3T3& c3t3, const NamedParameters& np)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::center_t>::value)
    return volume_centroid(c3t3);
  else
    return C3t3_point<C3T3>(CGAL::parameters::get_parameter(np, internal_np::center));
}

} // namespace internal

/*!
\ingroup PkgDistortionOptimizationRef

The radial map of the paper's Table 1 and Fig. 5 about a centre `c`: `p` goes to
`(p - c) |p - c|` (on the unit ball about the origin, f0(x) = x |x|, which keeps the unit sphere
and shrinks the inside). Injective on any domain, but with a conformal distortion that grows
without bound towards the centre: a hard start for the optimizer.

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
\tparam TargetMap a model of `WritablePropertyMap` from `C3T3::Triangulation::Vertex_handle` to `Point_3`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param c3t3 the complex (not modified); only the cells in the complex count
\param target receives the image of each vertex of the cells of the complex
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{center}
    \cgalParamDescription{the centre `c` of the map (`Distortion_optimization::parameters::center()`)}
    \cgalParamType{`C3T3::Triangulation::Geom_traits::Point_3`, or a type it is constructible from such as `CGAL::Origin`}
    \cgalParamDefault{`volume_centroid(c3t3)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Center_outside_domain (an `Invalid_input`) if the centre is not strictly inside the
domain (exact predicates), as for `star_shaped_to_unit_ball()`: about a point outside, the map is
no longer the one that shrinks the domain onto its centre; `Invalid_input` if the image, whose
size is the square of the domain's, is beyond double precision (a domain larger than
\f$ 2^{500} \f$ or smaller than \f$ 2^{-500} \f$ about the centre), and, without `center`, as
`volume_centroid()`. `target` is then unchanged.
*/
template <class C3T3, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void radial_map(const C3T3& c3t3, TargetMap target, const NamedParameters& np = CGAL::parameters::default_values())
{
  using Point_3 = internal::C3t3_point<C3T3>;
  const Point_3 center = internal::center_parameter(c3t3, np);
  if(!internal::is_strictly_inside(c3t3, center))
    throw Center_outside_domain("the centre of the radial map is not strictly inside the domain");
  const auto& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  double farthest = 0;   // the largest coordinate of p - center
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    for(int i = 0; i < 4; ++i) {
      const Point_3 p = point(tr.point(c, i));
      for(int k = 0; k < 3; ++k) farthest = (std::max)(farthest, std::abs(CGAL::to_double(p[k]) - CGAL::to_double(center[k])));
    }
  if(!(farthest < 0x1p500 && farthest > 0x1p-500))
    throw Invalid_input("radial_map: the domain's size about the centre (about 2^" + std::to_string(std::ilogb(farthest)) +
                        ") squared, the size of its image, is beyond double precision: scale the domain");
  map_vertices(c3t3, target, [&](const Point_3& p) {
    const auto u = p - center;
    const double r = std::sqrt(CGAL::to_double(u.squared_length()));
    return Point_3(r * CGAL::to_double(u.x()), r * CGAL::to_double(u.y()), r * CGAL::to_double(u.z()));
  });
}

/*!
\ingroup PkgDistortionOptimizationRef

Maps a domain star-shaped about a centre `c` onto the unit ball centred at the origin: the point
`c + r u` (|u| = 1) goes to `(r / R(u)) Au / |Au|`, where `R(u)` is the distance from `c` to the
complex boundary along `u` (found by ray casting in an AABB tree of the boundary facets); boundary
vertices land on the unit sphere. This is the radial construction of Naitsat, Saucan and Zeevi,
"Geometry-based distortion measures ...", section 4.4, applied to the domain transformed by the
symmetric matrix `A` that makes its inertia about `c` the same about every axis (the inverse
square root of its second moment; a ratio `r / R(u)` along a ray is kept by any linear map). On a
domain as wide in every direction, such as a cube or a ball about its centre, `A` is a multiple of
the identity up to the mesh's own asymmetry, and the map is theirs. An elongated domain is no
longer squeezed across its length onto narrow cones about its axis, a start that even the
untangling with the boundary sliding may fail to repair. The domain must be star-shaped about
`c`: `c` on the inner side of the plane of every boundary facet (exact predicates), checked before
anything is written.

Even then the map is not always valid: near a sharp edge of the domain, a tetrahedron whose four
vertices are on the boundary, on both sides of the edge, can come out flat or inverted (the edge
is rounded onto the sphere). Their number is returned; `CGAL::minimize_distortion()` with
`Distortion_optimization::parameters::untangle_first(true)` repairs them.

The template parameters, the parameters and the named parameter `center` (the centre `c`,
default `volume_centroid(c3t3)`) are those of `radial_map()`, see there.

\returns the number of cells of the complex the map inverts or flattens (exact predicate)
\throws Center_outside_domain (an `Invalid_input`) if the centre is not strictly inside the
domain, or Domain_not_star_shaped (an `Invalid_input`) if the domain is not star-shaped about it
(the message names the first boundary facet that faces the centre; another centre, or untangling
a map built otherwise, e.g. the radial map, are the remedies); without `center`, as
`volume_centroid()`. `target` is then unchanged.
*/
template <class C3T3, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t star_shaped_to_unit_ball(const C3T3& c3t3, TargetMap target,
                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using Point_3 = internal::C3t3_point<C3T3>;
  using K = typename Kernel_traits<Point_3>::Kernel;
  using Triangle = typename K::Triangle_3;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, typename std::vector<Triangle>::const_iterator>>>;
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  const auto& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  const Point_3 center = internal::center_parameter(c3t3, np);
  if(!internal::is_strictly_inside(c3t3, center))
    throw Center_outside_domain("the centre of the ball map is not strictly inside the domain");
  // The rays are cast in coordinates scaled by `scale` (see complex_scale()); the image does not change.
  const double scale = internal::complex_scale(c3t3);
  const Point_3 scaled_center = internal::scaled(center, scale);
  std::vector<Triangle> boundary;
  std::size_t index = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c, ++index)
    for(int i = 0; i < 4; ++i)
      if(!c3t3.is_in_complex(c->neighbor(i))) {
        const Point_3 a = point(tr.point(c, (i + 1) % 4)), b = point(tr.point(c, (i + 2) % 4)), d = point(tr.point(c, (i + 3) % 4));
        // Star-shaped about the centre: it sees every boundary facet from the cell's side.
        if(CGAL::orientation(a, b, d, center) != CGAL::orientation(a, b, d, Point_3(point(tr.point(c, i)))))
          throw Domain_not_star_shaped("the domain is not star-shaped about the centre: the boundary facet of cell " +
                              std::to_string(index) + " of the complex faces it; choose another centre, or start "
                              "from another map (e.g. radial_map()) and untangle it (untangle())");
        boundary.emplace_back(internal::scaled(a, scale), internal::scaled(b, scale), internal::scaled(d, scale));
      }
  if(boundary.empty()) throw Invalid_input("the complex has no boundary facet");
  Tree tree(boundary.begin(), boundary.end());
  const Eigen::Matrix3d whitening = internal::whitening(c3t3, scale, scaled_center);
  std::unordered_map<Vertex_handle, Point_3> image;
  map_vertices(c3t3, boost::associative_property_map<std::unordered_map<Vertex_handle, Point_3>>(image), [&](const Point_3& p) {
    const auto u = internal::scaled(p, scale) - scaled_center;
    const double r = std::sqrt(CGAL::to_double(u.squared_length()));
    if(r == 0) return Point_3(0, 0, 0);
    // Where the ray leaves the domain: a star-shaped domain has one exit point (a ray through an
    // edge or a vertex meets it in several facets). The facets the ray meets come from the exact
    // predicate; the exit is where the ray meets their planes. Constructing the intersections
    // instead missed them all, in double arithmetic, where the ray passes through a vertex of the
    // boundary, as it does for every boundary vertex.
    std::vector<typename Tree::Primitive_id> facets;
    tree.all_intersected_primitives(typename K::Ray_3(scaled_center, u), std::back_inserter(facets));
    double R = 0;
    for(const auto& facet : facets) {
      const Triangle& t = *facet;
      const auto normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
      const double along = CGAL::to_double(normal * u);   // 0: the ray is in the facet's plane
      if(along != 0) R = std::max(R, r * CGAL::to_double(normal * (t[0] - scaled_center)) / along);
    }
    if(!(R > 0)) throw Invalid_input("a ray from the centre misses the boundary: is the centre inside the domain?");
    const Eigen::Vector3d w = whitening * Eigen::Vector3d(CGAL::to_double(u.x()), CGAL::to_double(u.y()), CGAL::to_double(u.z()));
    const double s = r / R / w.norm();
    return Point_3(s * w.x(), s * w.y(), s * w.z());
  });
  std::size_t inverted = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    inverted += CGAL::orientation(image.at(c->vertex(0)), image.at(c->vertex(1)), image.at(c->vertex(2)),
                                  image.at(c->vertex(3))) != CGAL::POSITIVE;
  for(const auto& [v, p] : image) put(target, v, p);
  return inverted;
}

/*!
\ingroup PkgDistortionOptimizationRef

Replaces the targets of the free vertices by the harmonic map: the minimizer of the Dirichlet
energy sum_c w(c) |J_c|^2 for the targets of the fixed ones, with the cell weights w(c) of
`CGAL::minimize_distortion()` (by default proportional to the volumes: the volume-weighted
cotangent Laplacian), solved by conjugate gradients with Jacobi's preconditioner to a relative
residual of 1e-10 (on the threads of `number_of_threads`). The optimizer's harmonic start is the
same solve. The result may invert cells where the boundary is not convex;
`CGAL::compute_distortion()` tells.

\tparam C3T3 a `CGAL::Mesh_complex_3_in_triangulation_3`
\tparam TargetMap a model of `ReadWritePropertyMap` from `C3T3::Triangulation::Vertex_handle` to a `Point_3`
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param c3t3 the complex (not modified); only the cells in the complex count
\param target the targets: read for the fixed vertices, written for the free ones
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below (those of `CGAL::minimize_distortion()` that define the problem)

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{a property map containing the constrained-or-not status of each vertex of the cells
                          of `c3t3`: the constrained (fixed) vertices keep their target, the others are solved for}
    \cgalParamType{a class model of `ReadablePropertyMap` with `C3T3::Triangulation::Vertex_handle`
                   as key type and `bool` as value type}
    \cgalParamDefault{the vertices on the boundary of the complex (on a facet between a cell of the complex and a
                      cell outside it) are constrained}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_weight_map}
    \cgalParamDescription{a property map associating a weight omega(v) to each vertex of the cells of `c3t3`,
                          which enters the cell weights w(c) (`Distortion_optimization::parameters::vertex_weight_map()`)}
    \cgalParamType{a class model of `ReadablePropertyMap` with `C3T3::Triangulation::Vertex_handle`
                   as key type and a number type convertible to `double` as value type}
    \cgalParamDefault{omega(v) = 1 for every vertex}
    \cgalParamExtra{Every weight must be finite and positive.}
  \cgalParamNEnd

  \cgalParamNBegin{cell_weighting}
    \cgalParamDescription{the cell weights w(c, v) (`Distortion_optimization::parameters::cell_weighting()`)}
    \cgalParamType{`Distortion_optimization::Cell_weighting`}
    \cgalParamDefault{`Distortion_optimization::Cell_weighting::AVERAGE_VOLUME`}
  \cgalParamNEnd

  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the number of threads of the solve; `0` for all the hardware offers
                          (`Distortion_optimization::parameters::number_of_threads()`)}
    \cgalParamType{`int`}
    \cgalParamDefault{`1`}
    \cgalParamExtra{Used when the program links `CGAL::TBB_support` (`CGAL_LINKED_WITH_TBB`); sequential otherwise.
                    A negative value is an error.}
  \cgalParamNEnd

  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{`CGAL::Kernel_traits<C3T3::Triangulation::Geom_traits::Point_3>::Kernel`, the kernel of the
                      triangulation's points}
    \cgalParamExtra{Its `Orientation_3` checks, on `double` coordinates, that each source tetrahedron is positive.}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Invalid_input if the harmonic map is not defined: some free vertex is connected to no
fixed one (e.g. no vertex is fixed); and for a complex with no cell, a source tetrahedron that is
not positively oriented, a non-finite target coordinate, or a weight that is not finite and
positive. `target` is then unchanged.
*/
template <class C3T3, class TargetMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void harmonic_map(const C3T3& c3t3, TargetMap target, const NamedParameters& np = CGAL::parameters::default_values())
{
  auto adapter = internal::make_c3t3_adapter(c3t3, target, np);
  const internal::Optimization_problem<3> problem = internal::make_problem(adapter, np);
  const internal::Workers workers(internal::read_options(np).threads);
  internal::Laplacian_system<3> system(problem, workers);
  std::vector<internal::Vector<3>> x;
  if(!system.harmonic_targets(problem.map.target, x))
    throw Invalid_input("the harmonic map is not defined: some free vertex is not connected to a fixed one");
  adapter.write_targets(target, x, problem.is_free);
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_VOLUME_MAPS_H
