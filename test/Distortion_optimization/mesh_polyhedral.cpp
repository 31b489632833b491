// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tests' Mesh_3 meshes of polyhedral surfaces (test_mesh_3.h), compiled once, apart from the
// implicit ones (mesh_implicit.cpp): each instantiation of Mesh_3 is a long compilation.

#include "test_mesh_3.h"

#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/make_mesh_3.h>

Polyhedral_c3t3 mesh_polyhedral(const Surface_mesh_3& surface)
{
  namespace params = CGAL::parameters;
  const Polyhedral_domain domain(surface);
  const CGAL::Mesh_criteria_3<Polyhedral_tr> criteria(params::facet_distance = 0.05, params::cell_radius_edge_ratio = 3,
                                                      params::cell_size = 0.25);
  return CGAL::make_mesh_3<Polyhedral_c3t3>(domain, criteria, params::no_perturb(), params::no_exude());
}
