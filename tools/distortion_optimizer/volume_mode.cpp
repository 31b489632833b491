// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The volume mode's Mesh_3 meshing of a closed surface, and the surface carried through a volume
// map (volume_mode.h).

#include "volume_mode.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/mesh_interior.h>
#include <CGAL/Distortion_optimization/volumetric_texture.h>
#include <CGAL/compute_distortion.h>

#include <chrono>
#include <iterator>
#include <utility>
#include <vector>

namespace distortion_optimizer {

DO::IO::Tetrahedron_soup read_or_mesh_source(const Command_line& c, double& mesh_seconds)
{
  if(tetrahedral_file(c.source)) return DO::IO::read_tetrahedron_soup(c.source);
  const auto begin = std::chrono::steady_clock::now();
  const Mesh surface = to_mesh(DO::IO::read_triangle_soup(c.source), c.source);
  DO::IO::Tetrahedron_soup soup;
  try {
    DO::tetrahedra_from_c3t3(c.cell_size > 0 ? DO::mesh_interior(surface, DO::parameters::cell_size(c.cell_size))
                                             : DO::mesh_interior(surface), soup.points, soup.cells);
    soup.labels.assign(soup.cells.size(), 1);
  } catch(const DO::Invalid_input& e) {
    // The library's remedies name its parameters; the tool's user has --cell-size (the facet size,
    // and ten times the facet distance).
    std::string what = e.what();
    for(const auto& [library, tool] : {std::pair<std::string, std::string>("; give larger sizes", "; give a larger --cell-size"),
                                       {"; give sizes below its thickness", "; give a --cell-size below 10 times its thickness"},
                                       {"; give sizes below their distance", "; give a --cell-size below 10 times their distance"},
                                       {"; try a larger sharp_edge_angle",   // (a smaller --cell-size would ask for more vertices)
                                        "; the tool has neither option: mesh it with the library's mesh_interior() and a larger "
                                        "sharp_edge_angle (180 protects no edge) or maximum_number_of_vertices, then give the .mesh"},
                                       {"; give smaller sizes", "; give a smaller --cell-size"}})
      if(const auto remedy = what.find(library); remedy != std::string::npos) what = what.substr(0, remedy) + tool;
    throw DO::Invalid_input(c.source + ": " + what);
  }
  mesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return soup;
}

struct Carried_surface::Embedded
{
  DO::IO::Triangle_soup soup;
  Mesh mesh;
  DO::Volume_embedding<C3t3> embedding;
};

namespace {

// The vertices outside the volume named in the tool's words (--snap, not the named parameter).
DO::Volume_embedding<C3t3> embed(const Command_line& c, const C3t3& c3t3, const Mesh& mesh)
{
  try {
    return DO::embed_surface_in_volume(c3t3, mesh, DO::parameters::snap_to_volume(c.snap));
  } catch(const DO::Points_outside_volume& e) {
    throw DO::Invalid_input(c.carry + ": " + e.listing() + " (--snap moves such points onto its boundary)");
  }
}

} // namespace

Carried_surface::Carried_surface(const Command_line& c, const C3t3& c3t3) : name_(c.carry)
{
  DO::IO::Triangle_soup soup = DO::IO::read_triangle_soup(c.carry);
  Mesh mesh = to_mesh(soup, c.carry);
  DO::Volume_embedding<C3t3> embedding = embed(c, c3t3, mesh);
  embedded_.reset(new Embedded{std::move(soup), std::move(mesh), std::move(embedding)});
}

Carried_surface::~Carried_surface() = default;

double Carried_surface::energy(const DO::Any_measure& measure, const Target_map& target)
{
  Mesh& mesh = embedded_->mesh;
  auto image = mesh.add_property_map<Vertex, K::Point_3>("v:carried").first;
  DO::carry_surface_vertices(mesh, embedded_->embedding, target, image);
  try {   // its errors name the carried surface, not the map's source
    return CGAL::compute_distortion(mesh, image, measure).mean_volume;
  } catch(const DO::Invalid_input& e) {
    throw DO::Invalid_input(name_ + " (the carried surface): " + e.what());
  }
}

void Carried_surface::write(const std::string& path, const Target_map& target) const
{
  std::vector<K::Point_3> images;
  DO::carry_points(embedded_->embedding, target, std::back_inserter(images));
  DO::IO::Triangle_soup out;
  out.cells = embedded_->soup.cells;
  for(const K::Point_3& p : images) out.points.push_back({p.x(), p.y(), p.z()});
  DO::IO::write_triangle_soup(path, out);
}

std::size_t Carried_surface::vertices() const { return embedded_->embedding.size(); }

std::size_t Carried_surface::vertices_outside() const { return embedded_->embedding.snapped_points.size(); }

} // namespace distortion_optimizer
