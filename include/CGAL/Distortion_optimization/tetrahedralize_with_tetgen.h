// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Tetrahedral meshes of closed triangle surfaces from TetGen 1.5 (Si, "TetGen, a Delaunay-based
// quality tetrahedral mesh generator", 2015), through its library: link with -ltet (the CMake
// target Distortion_optimization::TetGen) and define TETLIBRARY (the target does).

#ifndef CGAL_DISTORTION_OPTIMIZATION_TETRAHEDRALIZE_WITH_TETGEN_H
#define CGAL_DISTORTION_OPTIMIZATION_TETRAHEDRALIZE_WITH_TETGEN_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/IO/simplex_soup.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#ifndef TETLIBRARY
#define TETLIBRARY
#endif
#include <tetgen.h>

#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {

namespace internal_np {
enum maximum_cell_volume_t { maximum_cell_volume };
} // namespace internal_np

namespace parameters {
/// `tetrahedralize_with_tetgen()`: upper bound on the volume of the tetrahedra (> 0); default none.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(maximum_cell_volume_t, maximum_cell_volume)
} // namespace parameters

/*!
\ingroup PkgDistortionOptimizationRef

Tetrahedralizes the inside of a closed triangle surface with TetGen: a constrained Delaunay
quality mesh (TetGen switches `pzQq<ratio>a<volume>`: PLC, zero-based, quiet, quality, volume
bound). The output tetrahedra are positively oriented; the surface's vertices come first among the
points, in the order of their indices; `c3t3_from_tetrahedra()` makes a complex of them.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam NamedParameters a sequence of \ref secDistortionNamedParameters "Named Parameters"

\param surface a closed triangle surface without self-intersection (not modified)
\param np an optional sequence of \ref secDistortionNamedParameters "Named Parameters" among the
       ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the position of each vertex of `surface`, given to TetGen in `double`}
    \cgalParamType{a readable vertex property map to a 3D point type whose `x()`, `y()` and `z()` `CGAL::to_double()` converts}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, surface)`}
  \cgalParamNEnd

  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex of `surface` a unique index between `0` and
                          `num_vertices(surface) - 1`: its index among the output points}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd

  \cgalParamNBegin{maximum_cell_volume}
    \cgalParamDescription{upper bound on the volume of the tetrahedra (TetGen's `a`)
                          (`Distortion_optimization::parameters::maximum_cell_volume()`)}
    \cgalParamType{`double`, positive}
    \cgalParamDefault{no bound}
  \cgalParamNEnd

  \cgalParamNBegin{cell_radius_edge_ratio}
    \cgalParamDescription{upper bound on circumradius / shortest edge of the tetrahedra (TetGen's `q`)
                          (`Distortion_optimization::parameters::cell_radius_edge_ratio()`)}
    \cgalParamType{`double`}
    \cgalParamDefault{`1.414`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the tetrahedra, in `IO::Tetrahedron_soup::points` and `IO::Tetrahedron_soup::cells`
\throws Invalid_input if a face of `surface` is not a triangle, or if TetGen fails
        (self-intersecting or open input, ...).
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
IO::Tetrahedron_soup tetrahedralize_with_tetgen(const TriangleMesh& surface,
                                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, surface));
  const auto index = CGAL::get_initialized_vertex_index_map(surface, np);
  const double radius_edge_ratio = choose_parameter(get_parameter(np, internal_np::cell_radius_edge_ratio), 1.414);
  std::vector<std::array<double, 3>> surface_points(num_vertices(surface));
  for(auto v : vertices(surface)) {
    const auto& p = get(vpm, v);
    surface_points[get(index, v)] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }
  std::vector<std::array<std::size_t, 3>> surface_triangles;
  for(auto f : faces(surface)) {
    std::array<std::size_t, 3> t;
    int i = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, surface), surface)) {
      if(i == 3) throw Invalid_input("tetrahedralize_with_tetgen(): a face is not a triangle");
      t[i++] = get(index, v);
    }
    if(i != 3) throw Invalid_input("tetrahedralize_with_tetgen(): a face is not a triangle");
    surface_triangles.push_back(t);
  }
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surface_points.size());
  in.pointlist = new REAL[3 * surface_points.size()];
  for(std::size_t i = 0; i < surface_points.size(); ++i)
    for(int d = 0; d < 3; ++d) in.pointlist[3 * i + d] = surface_points[i][d];
  in.numberoffacets = static_cast<int>(surface_triangles.size());
  in.facetlist = new tetgenio::facet[surface_triangles.size()];
  for(std::size_t f = 0; f < surface_triangles.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for(int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = static_cast<int>(surface_triangles[f][k]);
  }
  std::ostringstream switches;
  switches << "pzQq" << radius_edge_ratio;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::maximum_cell_volume_t>::value)
    switches << "a" << double(get_parameter(np, internal_np::maximum_cell_volume));
  std::string s = switches.str();
  try {
    tetrahedralize(&s[0], &in, &out);
  } catch(int code) {
    throw Invalid_input("TetGen failed with code " + std::to_string(code) +
                        " (is the surface closed and free of self-intersections?)");
  }
  IO::Tetrahedron_soup result;
  result.points.resize(out.numberofpoints);
  for(int i = 0; i < out.numberofpoints; ++i)
    for(int d = 0; d < 3; ++d) result.points[i][d] = out.pointlist[3 * i + d];
  result.cells.resize(out.numberoftetrahedra);
  for(int t = 0; t < out.numberoftetrahedra; ++t)
    for(int k = 0; k < 4; ++k) result.cells[t][k] = static_cast<std::size_t>(out.tetrahedronlist[out.numberofcorners * t + k]);
  if(result.cells.empty()) throw Invalid_input("TetGen produced no tetrahedron");
  return result;
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_TETRAHEDRALIZE_WITH_TETGEN_H
