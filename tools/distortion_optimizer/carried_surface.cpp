// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The surface carried through a volume map (--carry, volume_mode.h): its embedding in the source
// tetrahedra, its distortion under a map, and its image.

#include "volume_mode.h"

#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/volumetric_texture.h>
#include <CGAL/compute_distortion.h>

#include <iterator>
#include <utility>
#include <vector>

namespace distortion_optimizer {

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
    DO::Volume_embedding<C3t3> e = DO::embed_surface_in_volume(c3t3, mesh, DO::parameters::snap_to_volume(c.snap));
    // Snapped, a surface wholly outside would be flattened onto the boundary (far away: onto one point).
    if(e.snapped_points.size() == num_vertices(mesh))
      throw DO::Invalid_input(c.carry + ": all its " + std::to_string(num_vertices(mesh)) +
                              " vertices are outside the volume, and --snap would flatten it onto the volume's boundary");
    return e;
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
