// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Checks of mesh_interior() before Mesh_3 runs: a volume, or a component of it, too thin for the
// sizes, whose boundary Mesh_3 would not recover; a knife-edged rim or a needle tip, about which
// it would run for minutes.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/checked_surface.h>
#include <CGAL/Distortion_optimization/internal/mesh_interior/mesh_size_estimate.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// A domain thinner (mean thickness 2 V / A) than the facet distance passes Mesh_3's surface
// criteria with facets joining its two sides: the boundary is not recovered (the tetrahedra touch,
// or the refinement runs to the vertex limit), or only after a long refinement. So does a
// `slab` (see is_slab()) thinner than half the facet size: its sides are flat, and the facet
// distance, which bounds the facets of a curved surface, does not refine them. Throws if the part
// of volume `volume` and area `area`, named `what` in the message, is that thin; `lost` says what
// Mesh_3 would not recover and `remedy` ends the message. The facet size advised for a slab is
// its thickness, half the size refused (at twice its thickness a plate 1000 times thinner than
// wide still came out with touching tetrahedra), and asks for a mesh of its own size: the message
// says how large, and where that is more than `affordable` vertices, that no size both recovers
// the slab and fits.
inline void check_thickness(double volume, double area, bool slab, double cell_size, double facet_size,
                            double facet_distance, double affordable, const std::string& what,
                            const std::string& lost, const std::string& remedy)
{
  const double thickness = 2 * volume / area;
  if((!slab || thickness >= facet_size / 2) && thickness >= facet_distance) return;
  char text[320];
  bool meshable = true;   // at some size that fits
  if(slab && thickness < facet_size / 2) {
    const double advised = thickness;
    const double asked = asked_vertices(volume, area, (std::min)(cell_size, advised), advised);
    meshable = asked <= affordable;
    if(meshable)
      std::snprintf(text, sizeof text, " is thinner (2 volume / area = %.3g) than half the facet size (%.3g): Mesh_3 would not "
                    "recover %s; give a facet size below %.3g (about %.2g vertices)", thickness, facet_size / 2,
                    lost.c_str(), advised, asked);
    else
      std::snprintf(text, sizeof text, " is thinner (2 volume / area = %.3g) than half the facet size (%.3g): Mesh_3 would not "
                    "recover %s, and a facet size that would (below %.3g) asks for about %.2g vertices, more than the "
                    "maximum: the part is too thin to mesh", thickness, facet_size / 2, lost.c_str(), advised,
                    (std::min)(asked, 1e300));
  } else {
    std::snprintf(text, sizeof text, " is thinner (2 volume / area = %.3g) than the facet distance (%.3g): Mesh_3 would not "
                  "recover %s; give a facet distance below %.3g", thickness, facet_distance, lost.c_str(), thickness);
  }
  throw Invalid_input("mesh_interior: " + what + text + (meshable ? remedy : std::string()));
}

// Whether the surface spreads far less in one direction than in the others (a plate, a disc; not
// a needle): the smallest eigenvalue of the area-weighted second moments of its faces' centroids
// under a hundredth of the middle one. `moments` holds the area, the first moments and the second
// (xx, yy, zz, xy, xz, yz), summed over its faces.
inline bool is_slab(const std::array<double, 10>& moments)
{
  const double a = moments[0];
  Eigen::Matrix3d m;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      const int second = i == j ? 4 + i : 7 + i + j - 1;   // xy: 7, xz: 8, yz: 9
      m(i, j) = moments[second] / a - moments[1 + i] / a * moments[1 + j] / a;
    }
  const Eigen::Vector3d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues();
  return spread[0] < 1e-2 * spread[1];
}

// The sharpest fold of a part: the largest angle, in degrees, between the normals of two faces
// that share an edge. A slab whose rim folds by more than knife_fold (faces meeting at less than
// 30 degrees: a squashed sphere's rim) has its rim protected as a sharp edge by balls that Mesh_3
// places among nearly coplanar weighted points, for minutes at any size that passes the thickness
// check, and unprotected its two sides meet: it is refused at once, with no size to advise.
constexpr double knife_fold = 150;

inline void check_rim(double fold, bool slab, double sharp_edge_angle, const std::string& what)
{
  if(!slab || !(fold > knife_fold) || !(fold > sharp_edge_angle)) return;
  char text[200];
  std::snprintf(text, sizeof text, " is a slab whose rim is a knife edge (its faces meet there with normals %.0f degrees "
                "apart): Mesh_3 would not protect it in bounded time at any size; give it a thicker rim", fold);
  throw Invalid_input("mesh_interior: " + what + text);
}

// A vertex whose faces' angles there sum to less than needle_angle degrees is the tip of a
// needle (a cone of under half a degree, over 100 times as long as wide). Mesh_3 spends minutes
// about such a tip, the sharper the longer, and its refinement sometimes fails a check of its own
// there: refused at once, with the face whose corner it is. `corner_angles` holds each vertex's
// sum, `face_of_vertex` a face of each.
constexpr double needle_angle = 3;
inline void check_needle_tips(const std::vector<double>& corner_angles, const std::vector<std::size_t>& face_of_vertex)
{
  const auto tip = std::min_element(corner_angles.begin(), corner_angles.end());
  if(tip == corner_angles.end() || !(*tip < needle_angle)) return;
  char text[300];
  std::snprintf(text, sizeof text, "mesh_interior: the surface has a needle tip at a corner of face %zu (its faces' angles "
                "there sum to %.2g degrees, under %g): Mesh_3 would take minutes about it at any size, or fail; blunt it",
                face_of_vertex[std::size_t(tip - corner_angles.begin())], *tip, needle_angle);
  throw Invalid_input(text);
}

// The whole volume, then each component (a cavity measured by the space it encloses): a thin
// component beside thick ones holds up Mesh_3's protection or refinement just as well, or gets no
// tetrahedron at all.
template <class CheckedSurface>
void check_thickness_of_parts(const CheckedSurface& checked, double cell_size, double facet_size, double facet_distance,
                              double affordable, double sharp_edge_angle)
{
  const std::size_t components = checked.component_volume.size();
  std::vector<std::array<double, 10>> moments(components + 1, std::array<double, 10>{});   // the last: all
  std::vector<Eigen::Vector3d> normal;
  std::vector<double> corner_angles(num_vertices(checked.surface), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> face_of_vertex(num_vertices(checked.surface), 0);
  std::size_t f = 0;
  for(auto face : faces(checked.surface)) {
    const auto p = corners(checked.surface, face);
    auto h = halfedge(face, checked.surface);
    for(int k = 0; k < 3; ++k, h = next(h, checked.surface)) {   // the corner at h's target
      const auto& m = checked.surface;
      const std::size_t v = std::size_t(target(h, m));
      double& sum = corner_angles[v];   // infinite until the vertex's first face
      sum = (std::isinf(sum) ? 0 : sum) + CGAL::approximate_angle(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
      face_of_vertex[v] = checked.face_names[f];
    }
    const double w = std::sqrt(CGAL::to_double(CGAL::squared_area(p[0], p[1], p[2])));
    const double x[3] = {CGAL::to_double(p[0].x() + p[1].x() + p[2].x()) / 3, CGAL::to_double(p[0].y() + p[1].y() + p[2].y()) / 3,
                         CGAL::to_double(p[0].z() + p[1].z() + p[2].z()) / 3};
    const auto n = CGAL::normal(p[0], p[1], p[2]);
    normal.push_back(Eigen::Vector3d(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())).normalized());
    for(const std::size_t c : {checked.component[f++], components}) {
      std::array<double, 10>& m = moments[c];
      const double terms[10] = {1, x[0], x[1], x[2], x[0] * x[0], x[1] * x[1], x[2] * x[2], x[0] * x[1], x[0] * x[2], x[1] * x[2]};
      for(int k = 0; k < 10; ++k) m[k] += w * terms[k];
    }
  }
  std::vector<double> fold(components + 1, 0.);
  for(auto e : edges(checked.surface)) {
    const auto h = halfedge(e, checked.surface), g = opposite(h, checked.surface);
    const std::size_t a = std::size_t(face(h, checked.surface)), b = std::size_t(face(g, checked.surface));
    const double angle = std::acos(std::clamp(normal[a].dot(normal[b]), -1., 1.)) * 180 / CGAL_PI;
    for(const std::size_t c : {checked.component[a], components}) fold[c] = (std::max)(fold[c], angle);
  }
  check_needle_tips(corner_angles, face_of_vertex);
  const bool slab = is_slab(moments[components]);
  check_rim(fold[components], slab, sharp_edge_angle, "the volume");
  check_thickness(checked.volume, checked.area, slab, cell_size, facet_size, facet_distance, affordable, "the volume",
                  "its boundary", "");
  std::vector<std::size_t> first_face(components, 0);   // of each component, to name it
  for(std::size_t g = checked.component.size(); g-- > 0;) first_face[checked.component[g]] = g;
  for(std::size_t c = 0; c < components && components > 1; ++c) {
    const std::string what = "the component of the surface with face " + std::to_string(checked.face_names[first_face[c]]);
    check_rim(fold[c], is_slab(moments[c]), sharp_edge_angle, what);
    check_thickness(std::abs(checked.component_volume[c]), checked.component_area[c], is_slab(moments[c]), cell_size,
                    facet_size, facet_distance, affordable, what, "it", ", or remove it");
  }
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_MESH_INTERIOR_THIN_PARTS_H
