// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tests' Mesh_3 meshes of implicit domains (test_mesh_3.h), compiled once; those of polyhedral
// surfaces are in mesh_polyhedral.cpp.

#include "test_mesh_3.h"

#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/make_mesh_3.h>

C3t3 mesh_implicit(double (*f)(const Point_3&), double radius, double size)
{
  namespace params = CGAL::parameters;
  const Implicit_domain domain =
    Implicit_domain::create_implicit_mesh_domain(f, K::Sphere_3(CGAL::ORIGIN, radius * radius));
  const CGAL::Mesh_criteria_3<Tr> criteria(params::facet_angle = 25, params::facet_size = size,
                                           params::facet_distance = size / 10, params::cell_radius_edge_ratio = 3,
                                           params::cell_size = size);
  return CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
}
