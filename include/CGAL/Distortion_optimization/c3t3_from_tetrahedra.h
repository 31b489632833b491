// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H
#define CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/c3t3_from_tetrahedra/build_triangulation.h>
#include <CGAL/Distortion_optimization/internal/c3t3_from_tetrahedra/cell_checks.h>
#include <CGAL/Distortion_optimization/internal/c3t3_from_tetrahedra/manifold_tetrahedra.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <CGAL/Kernel/global_functions.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

namespace internal_np {
enum subdomain_index_t { subdomain_index };
} // namespace internal_np

namespace parameters {
/// `int`: the subdomain (> 0) of the tetrahedra that `c3t3_from_tetrahedra()` puts in the complex; default 1.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(subdomain_index_t, subdomain_index)
} // namespace parameters

/// \ingroup PkgDistortionOptimizationRef
/// Replaces the content of `c3t3` (a `CGAL::Mesh_complex_3_in_triangulation_3`) with the given
/// tetrahedra, all in one subdomain, vertex `i` at `points[i]`: the way to hand a mesh
/// from TetGen or a Medit file to `CGAL::minimize_distortion()`. Negatively oriented tetrahedra
/// are stored with two vertices swapped (a simplicial map does not depend on the vertex order).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{subdomain_index}
///     \cgalParamDescription{the subdomain of the tetrahedra (`Distortion_optimization::parameters::subdomain_index()`)}
///     \cgalParamType{`int`, positive}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads for the orientation, manifold and fold checks, beside which the
///                           complex is then built; `0` for all the hardware offers
///                           (`Distortion_optimization::parameters::number_of_threads()`)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`1`}
///     \cgalParamExtra{Used when the program links `CGAL::TBB_support`; the result and the messages
///                     are the same for any number.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the vertex handle of each point (`Vertex_handle()` for a point in no tetrahedron).
/// \throws Invalid_input for an index out of range, a non-finite point, a flat tetrahedron (exact
/// predicate, the message names it), a tetrahedron listed twice, or tetrahedra that do not form a
/// manifold complex: a facet in more than two, or two that meet only at an edge or a vertex (the
/// message names them), two on the same side of their common facet (a folded mesh: they
/// overlap; the message names them), a complex without boundary (its cells overlap), or parts
/// that overlap otherwise (one inside another, or a boundary that passes through itself: exact
/// tests); for a negative number of threads. `c3t3` is then unchanged.
template <class C3T3, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename C3T3::Triangulation::Vertex_handle>
c3t3_from_tetrahedra(C3T3& c3t3, const std::vector<std::array<double, 3>>& points,
                     const std::vector<std::array<std::size_t, 4>>& tetrahedra,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using Tr = typename C3T3::Triangulation;
  using Bare_point = typename Tr::Geom_traits::Point_3;
  const int label = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::subdomain_index), 1);
  if(points.empty() || tetrahedra.empty()) throw Invalid_input("no tetrahedron");
  if(label <= 0) throw Invalid_input("the subdomain label must be positive");
  const int threads = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 1);
  if(threads < 0) throw Invalid_input("the number of threads must be 0 (all) or positive");
  const internal::Workers workers(threads);
  std::vector<typename Tr::Point> tr_points;
  tr_points.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Invalid_input("point " + std::to_string(i) + " is not finite");
    tr_points.push_back(typename Tr::Point(Bare_point(p[0], p[1], p[2])));
  }
  std::vector<std::array<std::size_t, 4>> cells(tetrahedra);
  constexpr std::size_t block = 4096;
  std::vector<internal::First_failure> failures((cells.size() + block - 1) / block);
  workers.for_each_block(cells.size(), block, [&](std::size_t begin, std::size_t size) {
    for(std::size_t t = begin; t < begin + size; ++t) {
      auto& cell = cells[t];
      for(std::size_t v : cell)
        if(v >= points.size()) {
          failures[begin / block] = {t, "tetrahedron " + std::to_string(t) + " has a vertex index out of range"};
          return;
        }
      auto bare = [&](int j) { return Bare_point(points[cell[j]][0], points[cell[j]][1], points[cell[j]][2]); };
      const CGAL::Orientation o = CGAL::orientation(bare(0), bare(1), bare(2), bare(3));
      if(o == CGAL::COPLANAR) {
        failures[begin / block] = {t, "tetrahedron " + std::to_string(t) + " is flat (zero volume)"};
        return;
      }
      if(o == CGAL::NEGATIVE) std::swap(cell[2], cell[3]);
    }
  });
  internal::First_failure::throw_lowest(failures);
  // The fold check (on the workers) and the construction of the complex (sequential: CGAL's
  // containers) need only the adjacency: with threads they run beside the manifold checks' last
  // part, whose failures are still told first; the overlap shortens the call.
  std::vector<std::uint32_t> across;
  std::exception_ptr error;   // the fold check's, or else the construction's
  C3T3 built;
  std::vector<typename Tr::Vertex_handle> handles;
  internal::check_manifold_tetrahedra(cells, across, workers, [&] {
    try {
      internal::check_cells_do_not_fold(cells, across, workers);
      Tr tr;
      handles = internal::build_triangulation(tr, tr_points, cells, across, label);
      built.triangulation().swap(tr);
      built.rescan_after_load_of_triangulation();
    } catch(...) {
      error = std::current_exception();
    }
  });
  if(error) std::rethrow_exception(error);
  internal::check_cells_do_not_overlap(points, cells);
  // The complex's swap() exchanges the triangulations but not Mesh_3's cache of the facets around
  // each edge (face_status()): clear() drops that cache, which would otherwise still describe the
  // old complex, keyed by vertices that go with `built`.
  c3t3.clear();
  c3t3.swap(built);
  return handles;
}

/// \ingroup PkgDistortionOptimizationRef
/// The converse of `c3t3_from_tetrahedra()`: the cells of the complex of `c3t3` (in the order of
/// `cells_in_complex_begin()`, each with its cell's vertex order) as `points` and `tetrahedra`,
/// indices into `points`, which are numbered in the order the cells first reach their vertices.
/// What the writers take (`IO::write_MEDIT_soup()`, `IO::write_VTU()`); `points` and `tetrahedra`
/// are cleared first.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the point written for each vertex: a target map writes the image of
///                           the tetrahedra}
///     \cgalParamType{a readable property map from `Triangulation::Vertex_handle` to a point with
///                    `x()`, `y()`, `z()`}
///     \cgalParamDefault{the triangulation's points, without their weights}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the vertex handle of each point.
template <class C3T3, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename C3T3::Triangulation::Vertex_handle>
tetrahedra_from_c3t3(const C3T3& c3t3, std::vector<std::array<double, 3>>& points,
                     std::vector<std::array<std::size_t, 4>>& tetrahedra,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  const auto& tr = c3t3.triangulation();
  const auto bare = tr.geom_traits().construct_point_3_object();
  std::vector<Vertex_handle> handles;
  std::unordered_map<Vertex_handle, std::size_t> index;
  index.reserve(tr.number_of_vertices());
  points.clear();
  tetrahedra.clear();
  tetrahedra.reserve(c3t3.number_of_cells_in_complex());
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<std::size_t, 4> cell;
    for(int i = 0; i < 4; ++i) {
      const auto [at, added] = index.emplace(c->vertex(i), points.size());
      if(added) {
        handles.push_back(c->vertex(i));
        if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value) {
          const auto p = bare(tr.point(c, i));
          points.push_back({p.x(), p.y(), p.z()});
        } else {
          const auto& p = get(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point), c->vertex(i));
          points.push_back({double(p.x()), double(p.y()), double(p.z())});
        }
      }
      cell[i] = at->second;
    }
    tetrahedra.push_back(cell);
  }
  return handles;
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H
