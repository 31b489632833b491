// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tetrahedral side of the tool: the complex type, the source volume (a .mesh, or a closed
// surface meshed by Mesh_3 in the volume mode) and the surface carried through a volume map
// (--carry, paper 4.4). Mesh_3 and the volumetric texture are compiled in volume_mode.cpp only.

#ifndef DISTORTION_OPTIMIZER_VOLUME_MODE_H
#define DISTORTION_OPTIMIZER_VOLUME_MODE_H

#include "tool.h"

#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <unordered_map>

namespace distortion_optimizer {

using Tr = CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<K>>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
// A tetrahedral map: the target of each vertex of the complex.
using Target_map = boost::associative_property_map<std::unordered_map<Tr::Vertex_handle, K::Point_3>>;

// The source tetrahedra: read from a .mesh, or the inside of a closed surface meshed by Mesh_3
// (its time in mesh_seconds).
DO::IO::Tetrahedron_soup read_or_mesh_source(const Command_line& c, double& mesh_seconds);

// The surface carried through the tetrahedral map (--carry): embedded in the source volume once,
// measured under the start map and the optimized one.
class Carried_surface
{
public:
  Carried_surface(const Command_line& c, const C3t3& c3t3);
  ~Carried_surface();
  // The mean distortion (volume-weighted, as the tool's energies) of the surface under `target`.
  double energy(const DO::Any_measure& measure, const Target_map& target);
  // The surface carried by `target`, written to `path`.
  void write(const std::string& path, const Target_map& target) const;
  std::size_t vertices() const;
  std::size_t vertices_outside() const;   // snapped onto the boundary (--snap)

  double start_energy = 0, final_energy = 0;

private:
  struct Embedded;
  const std::string name_;
  std::unique_ptr<Embedded> embedded_;
};

} // namespace distortion_optimizer

#endif // DISTORTION_OPTIMIZER_VOLUME_MODE_H
