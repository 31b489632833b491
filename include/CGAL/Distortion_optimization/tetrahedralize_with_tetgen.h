// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Tetrahedral meshes of closed triangle surfaces from TetGen 1.5 (Si, "TetGen, a Delaunay-based
// quality tetrahedral mesh generator", 2015), through its library: link with -ltet (the CMake
// target Distortion_optimization::TetGen) and define TETLIBRARY (the target does).

#ifndef CGAL_DISTORTION_OPTIMIZATION_TETRAHEDRALIZE_WITH_TETGEN_H
#define CGAL_DISTORTION_OPTIMIZATION_TETRAHEDRALIZE_WITH_TETGEN_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>

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

/// \ingroup PkgDistortionOptimizationRef
/// Tetrahedralizes the inside of a closed triangle surface given as points and triangles: a
/// constrained Delaunay quality mesh (TetGen switches `pzQq<ratio>a<volume>`: PLC, zero-based, quiet, quality, volume bound) whose tetrahedra have
/// at most `max_volume`. Output tetrahedra are positively oriented; input points come first.
/// \throws Invalid_input if TetGen fails (self-intersecting or open input, ...).
inline void tetrahedralize_with_tetgen(const std::vector<std::array<double, 3>>& surface_points,
                                       const std::vector<std::array<std::size_t, 3>>& surface_triangles,
                                       double max_volume,
                                       std::vector<std::array<double, 3>>& points,
                                       std::vector<std::array<std::size_t, 4>>& tetrahedra,
                                       double radius_edge_ratio = 1.414)
{
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
  switches << "pzQq" << radius_edge_ratio << "a" << max_volume;
  std::string s = switches.str();
  try {
    tetrahedralize(&s[0], &in, &out);
  } catch(int code) {
    throw Invalid_input("TetGen failed with code " + std::to_string(code) +
                        " (is the surface closed and free of self-intersections?)");
  }
  points.resize(out.numberofpoints);
  for(int i = 0; i < out.numberofpoints; ++i)
    for(int d = 0; d < 3; ++d) points[i][d] = out.pointlist[3 * i + d];
  tetrahedra.resize(out.numberoftetrahedra);
  for(int t = 0; t < out.numberoftetrahedra; ++t)
    for(int k = 0; k < 4; ++k) tetrahedra[t][k] = static_cast<std::size_t>(out.tetrahedronlist[out.numberofcorners * t + k]);
  if(tetrahedra.empty()) throw Invalid_input("TetGen produced no tetrahedron");
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_TETRAHEDRALIZE_WITH_TETGEN_H
