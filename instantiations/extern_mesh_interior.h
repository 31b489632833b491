// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Mesh_3 front end of mesh_interior() compiled once for the files of the build that mesh a
// Surface_mesh (mesh_interior.cpp defines it): the same as extern_templates.h, for the body that
// runs Mesh_3 and its repairs. Each call of mesh_interior() still reads its named parameters.

#ifndef DISTORTION_OPTIMIZATION_EXTERN_MESH_INTERIOR_H
#define DISTORTION_OPTIMIZATION_EXTERN_MESH_INTERIOR_H

#include <CGAL/Distortion_optimization/mesh_interior.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#define DISTORTION_MESH_INTERIOR(extern_or_not)                                                                           \
  extern_or_not template Interior_mesh<Epick>::C3T3                                                                      \
  mesh_interior_impl<Interior_mesh<Epick>,                                                                                \
                     Checked_surface<Interior_mesh<Epick>::Surface, CGAL::Surface_mesh<Epick::Point_3>>,                  \
                     Interior_mesh_sizes>(                                                                                \
    const Checked_surface<Interior_mesh<Epick>::Surface, CGAL::Surface_mesh<Epick::Point_3>>&,                            \
    const Interior_mesh_sizes&, const Mesh_3_settings&);

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

#ifndef DISTORTION_INSTANTIATE_MESH_INTERIOR
DISTORTION_MESH_INTERIOR(extern)
#else
DISTORTION_MESH_INTERIOR()
#endif

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // DISTORTION_OPTIMIZATION_EXTERN_MESH_INTERIOR_H
