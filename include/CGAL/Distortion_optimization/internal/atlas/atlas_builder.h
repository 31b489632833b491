// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The atlas of a triangle surface, on flat arrays: its pieces, each cut open along seams into a
// chart of genus 0, each chart flattened without overlap, then all packed into the unit square.
// Atlas_builder::run() lists the steps; compute_atlas() (atlas.h) translates a CGAL mesh to and
// from these arrays.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_ATLAS_BUILDER_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_ATLAS_BUILDER_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/global_injectivity.h>
#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/internal/atlas/cones.h>
#include <CGAL/Distortion_optimization/internal/atlas/cut_graph.h>
#include <CGAL/Distortion_optimization/internal/atlas/cut_mesh.h>
#include <CGAL/Distortion_optimization/internal/atlas/pack_charts.h>
#include <CGAL/Distortion_optimization/internal/atlas/scaffold.h>
#include <CGAL/Distortion_optimization/internal/atlas/split_charts.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

struct Atlas_options
{
  double max_log_scale = 1;           // the cones' bound on the conformal flattening's log scale
  double hole_turning = M_PI / 36;    // a hole whose loop turns further from -2 pi gets a seam (radians)
  double max_distortion = 0;          // a piece's mean distortion above it cuts it into charts (0: no bound)
  double gutter = 0.01;               // between charts, a fraction of the square's side
  double min_fill = 0.6;              // a chart filling less of its bounding rectangle is split
  std::vector<std::array<std::uint32_t, 2>> seams;   // the user's, as vertex pairs of edges
  // Each chart's optimization (flatten_with_scaffold()): minimize_distortion()'s options. Its
  // visitor is called after each iteration of every chart's (numbered across them); false stops
  // the optimizations, and the charts not yet flattened keep their Tutte start.
  Options optimizer;
  Cell_weighting weighting = Cell_weighting::AVERAGE_VOLUME;
};

// What the atlas has: each face's chart and its corners' UVs, the seams, and the figures.
struct Atlas_arrays
{
  std::vector<std::array<std::array<double, 2>, 3>> corner_uv;   // by face, in the corners' order
  std::vector<std::size_t> chart;                                // by face
  std::vector<double> face_distortion;                           // by face
  std::vector<std::array<std::uint32_t, 2>> seam_edges;          // the seams as vertex pairs
  std::size_t charts = 0, cones = 0;
  double seam_length = 0, edge_length = 0, packing_efficiency = 0;
  double mean_distortion = 0, max_distortion = 0;   // area-weighted mean over the surface; largest of a face
  std::size_t inverted_faces = 0, overlapping_charts = 0, iterations = 0;
  bool stopped_by_visitor = false;
};

template <class Measure>
class Atlas_builder
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  using Vertex = Mesh::Vertex_index;

public:
  Atlas_builder(const std::vector<std::array<double, 3>>& points, const std::vector<std::array<std::uint32_t, 3>>& faces,
                const Measure& measure, const Atlas_options& options)
    : points_(points), faces_(faces), measure_(measure), options_(options)
  {}

  Atlas_arrays run()
  {
    split_into_pieces();
    for(std::size_t k = 0; k < pieces_.size(); ++k) {
      Piece& piece = pieces_[k];
      piece.seam = handle_seams(piece.mesh);
      add_user_seams(piece);
      std::vector<double> weight, defect;   // cotangent weights by edge, angle defects by vertex (cones.h)
      cotangent_weights_and_defects(piece.mesh, weight, defect);
      add_hole_seams(piece.mesh, defect, options_.hole_turning, piece.seam);
      add_cone_seams(piece, weight, defect, options_.max_log_scale);
      cut_open(piece);
      flatten(piece);
      // Above the distortion bound: the piece in 2, 3, 4, 6, 9, ... regions (half again each time:
      // doubling overshoots the charts a bound needs), each a chart of 16 faces at least, until it holds.
      const std::vector<bool> seam = piece.seam;
      for(std::size_t regions = 2; options_.max_distortion > 0 && piece.mean > options_.max_distortion &&
                                   16 * regions <= piece.mesh.number_of_faces() && regions <= 512; regions = regions * 3 / 2) {
        piece.seam = seam;
        add_region_seams(piece, regions);
        cut_open(piece);
        flatten(piece);
      }
    }
    split_and_pack();
    return collect();
  }

private:
  struct Piece
  {
    Mesh mesh;                                      // the piece alone, its faces in input order
    std::vector<std::size_t> face;                  // the input face of each
    std::vector<std::uint32_t> vertex;              // the input vertex of each
    std::vector<bool> seam;                         // by edge of `mesh`
    std::size_t cones = 0;
    Mesh chart;                                     // the piece cut open
    std::vector<std::array<std::uint32_t, 3>> corner;   // the chart's vertex at each corner of each face
    std::vector<Vector<2>> uv;                      // by chart vertex
    std::vector<double> value;                      // the measure's value on each face
    std::vector<std::uint32_t> part;                // the chart each face is packed with (split_charts.h)
    std::uint32_t parts = 1;
    std::vector<std::array<Vector<2>, 3>> corner_uv;   // packed, by face
    double area = 0, uv_area = 0, mean = 0, max = 0;
    std::size_t inverted = 0, iterations = 0;
    bool embedded = true;
  };

  // The input's connected pieces, each its own Surface_mesh; bad input refused with the face.
  void split_into_pieces()
  {
    Mesh all;
    for(const auto& p : points_) all.add_vertex(K::Point_3(p[0], p[1], p[2]));
    for(std::size_t f = 0; f < faces_.size(); ++f) {
      const Vertex a(faces_[f][0]), b(faces_[f][1]), c(faces_[f][2]);
      // A face without area has no frame to measure the map in.
      if(CGAL::collinear(all.point(a), all.point(b), all.point(c)))
        throw Invalid_input("face " + std::to_string(f) + " is degenerate (its corners are collinear)");
      if(all.add_face(a, b, c) == Mesh::null_face())
        throw Invalid_input("face " + std::to_string(f) + " makes the surface non-manifold or inconsistently oriented");
    }
    auto piece_of = all.add_property_map<Mesh::Face_index, std::size_t>("f:piece").first;
    const std::size_t n = faces_.empty() ? 0 : CGAL::Polygon_mesh_processing::connected_components(all, piece_of);
    if(n == 0) throw Invalid_input("the surface has no face");
    pieces_.resize(n);
    std::vector<std::uint32_t> local(points_.size(), std::uint32_t(-1));
    std::vector<std::size_t> owner(points_.size(), n);
    for(std::size_t f = 0; f < faces_.size(); ++f) {
      Piece& piece = pieces_[piece_of[Mesh::Face_index(std::uint32_t(f))]];
      std::array<Vertex, 3> t;
      for(int i = 0; i < 3; ++i) {
        const std::uint32_t v = faces_[f][i];
        if(owner[v] != std::size_t(&piece - pieces_.data())) {
          owner[v] = std::size_t(&piece - pieces_.data());
          local[v] = std::uint32_t(piece.mesh.add_vertex(all.point(Vertex(v))));
          piece.vertex.push_back(v);
        }
        t[i] = Vertex(local[v]);
      }
      piece.mesh.add_face(t[0], t[1], t[2]);
      piece.face.push_back(f);
    }
  }

  // The user's seams on this piece: its edges whose ends the options pair.
  void add_user_seams(Piece& piece)
  {
    if(options_.seams.empty()) return;
    std::vector<std::uint32_t> local(points_.size(), std::uint32_t(-1));
    for(std::size_t i = 0; i < piece.vertex.size(); ++i) local[piece.vertex[i]] = std::uint32_t(i);
    for(const auto& [u, w] : options_.seams) {
      if(local[u] == std::uint32_t(-1) || local[w] == std::uint32_t(-1)) continue;
      const auto h = piece.mesh.halfedge(Vertex(local[u]), Vertex(local[w]));
      if(h == Mesh::null_halfedge()) throw Invalid_input("seam " + std::to_string(u) + " " + std::to_string(w) + " is not an edge");
      piece.seam[std::size_t(piece.mesh.edge(h))] = true;
    }
  }

  // Seams from the cones to the seams there are (Atlas_options::max_log_scale).
  void add_cone_seams(Piece& piece, const std::vector<double>& weight, const std::vector<double>& defect, double bound)
  {
    const std::vector<Vertex> cones = place_cones(piece.mesh, weight, defect, piece.seam, bound, 64);
    for(std::size_t i = 0; i < cones.size(); ++i)
      add_seam_to(piece.mesh, cones[i], cones[i == 0 ? (cones.size() > 1 ? 1 : 0) : 0], piece.seam);
    piece.cones += cones.size();
  }

  // Seams between `regions` regions of nearly constant normal (at most; CGAL's variational shape
  // approximation under the L^{2,1} metric: Cohen-Steiner, Alliez and Desbrun, "Variational shape
  // approximation", 2004): where a piece flattens with too much distortion, its charts become
  // such regions, each nearly flat, which flatten with little.
  void add_region_seams(Piece& piece, std::size_t regions)
  {
    Mesh& m = piece.mesh;
    auto region = m.add_property_map<Mesh::Face_index, std::size_t>("f:region", 0).first;
    CGAL::Surface_mesh_approximation::approximate_triangle_mesh(m, CGAL::parameters::max_number_of_proxies(regions).face_proxy_map(region));
    add_seams_between(m, [&](Mesh::Face_index f) { return region[f]; }, piece.seam);
    m.remove_property_map(region);
  }

  // Marks as seams the edges between faces of different labels (regions, parts).
  template <class Label>
  static void add_seams_between(const Mesh& m, const Label& label, std::vector<bool>& seam)
  {
    for(auto e : m.edges())
      if(!m.is_border(e) && label(m.face(m.halfedge(e))) != label(m.face(m.opposite(m.halfedge(e))))) seam[std::size_t(e)] = true;
  }

  void cut_open(Piece& piece) { piece.chart = cut_along(piece.mesh, piece.seam, piece.corner); }

  // The chart's Tutte start (its longest border on a circle, its holes filled for the solve), then
  // the measure minimized with every vertex free, the border kept from crossing itself by a
  // scaffold (scaffold.h; the boundary guard of minimize_distortion() holds the border's vertices
  // where they would cross, and the border then opens by short steps).
  void flatten(Piece& piece)
  {
    Mesh& chart = piece.chart;
    auto uv = chart.add_property_map<Vertex, K::Point_2>("v:uv").first;
    auto value = chart.add_property_map<Mesh::Face_index, double>("f:distortion").first;
    initial_parameterization(chart, uv);
    const auto visit = [this](std::size_t, double energy, std::size_t inverted) {
      stopped_ = options_.optimizer.visitor && !options_.optimizer.visitor(++visited_, energy, inverted);
      return !stopped_;
    };
    Options optimizer = options_.optimizer;
    optimizer.iterations = stopped_ ? 0 : optimizer.iterations;
    optimizer.visitor = visit;
    const Result r = flatten_with_scaffold(chart, uv, measure_, optimizer, options_.weighting);
    piece.embedded = is_boundary_embedded(chart, uv);
    const Distortion_statistics s = CGAL::compute_distortion(chart, uv, measure_, parameters::cell_distortion_map(value));
    piece.mean = s.mean_volume, piece.max = s.max, piece.inverted = s.inverted_cells, piece.iterations = r.iterations;
    piece.value.clear();
    for(auto f : chart.faces()) piece.value.push_back(value[f]);
    piece.uv.clear();
    for(auto v : chart.vertices()) piece.uv.emplace_back(uv[v].x(), uv[v].y());
    piece.area = piece.uv_area = 0;
    for(auto f : chart.faces()) {
      const auto h = chart.halfedge(f);
      const Vertex a = chart.source(h), b = chart.target(h), c = chart.target(chart.next(h));
      piece.area += std::sqrt(CGAL::to_double(CGAL::squared_area(chart.point(a), chart.point(b), chart.point(c))));
      piece.uv_area += CGAL::to_double(CGAL::area(uv[a], uv[b], uv[c]));
    }
  }

  // The flattened pieces split into charts for packing (split_charts.h) by each of a few rules (none;
  // lines across the longer side; lines in four directions), each split packed, and the densest
  // packing kept: the rules' figure of merit, how the parts fill their rectangles, only guesses at
  // how densely they pack, and packing is cheap beside flattening. The edges between parts become seams.
  void split_and_pack()
  {
    std::vector<Split_rule> rules{{0, 0}};
    if(options_.min_fill > 0) rules.insert(rules.end(), {{1, 5}, {4, 7}});
    struct Packed { std::vector<std::uint32_t> part; std::uint32_t parts; std::vector<std::array<Vector<2>, 3>> corner_uv; };
    std::vector<Packed> best(pieces_.size());
    std::vector<std::vector<std::uint32_t>> tried;   // the last rule's parts: a rule that splits alike is not packed again
    for(const Split_rule& rule : rules) {
      bool alike = !tried.empty();
      for(std::size_t k = 0; k < pieces_.size(); ++k) {
        Piece& piece = pieces_[k];
        piece.part = split_for_packing(piece.corner, piece.uv, options_.min_fill, rule);
        piece.parts = piece.part.empty() ? 0 : *std::max_element(piece.part.begin(), piece.part.end()) + 1;
        alike = alike && piece.part == tried[k];
      }
      if(alike) continue;
      tried.clear();
      for(const Piece& piece : pieces_) tried.push_back(piece.part);
      const double efficiency = pack();
      if(efficiency > efficiency_ || &rule == &rules.front()) {
        efficiency_ = efficiency;
        for(std::size_t k = 0; k < pieces_.size(); ++k) best[k] = {pieces_[k].part, pieces_[k].parts, pieces_[k].corner_uv};
      }
    }
    for(std::size_t k = 0; k < pieces_.size(); ++k) {
      Piece& piece = pieces_[k];
      piece.part = std::move(best[k].part), piece.parts = best[k].parts, piece.corner_uv = std::move(best[k].corner_uv);
      add_seams_between(piece.mesh, [&](Mesh::Face_index f) { return piece.part[std::size_t(f)]; }, piece.seam);
    }
  }

  // Every chart at one scale (the same texel density), then packed; each face's corners get their
  // chart's packed UVs. Returns the packing's efficiency.
  double pack()
  {
    double area = 0, uv_area = 0;
    for(const Piece& piece : pieces_) area += piece.area, uv_area += piece.uv_area;
    const double s = uv_area > 0 ? std::sqrt(area / uv_area) : 1;
    std::vector<Chart_to_pack> charts;
    std::vector<std::vector<std::int64_t>> local;   // by piece: each corner's index in its chart's UVs
    for(Piece& piece : pieces_) {
      const std::size_t first = charts.size();
      charts.resize(first + piece.parts);
      local.emplace_back(piece.corner.size() * 3, -1);
      std::vector<std::int64_t> at(piece.uv.size(), -1);
      std::vector<std::uint32_t> stamp(piece.uv.size(), std::uint32_t(-1));
      for(std::size_t f = 0; f < piece.corner.size(); ++f) {
        const std::uint32_t k = piece.part[f];
        Chart_to_pack& chart = charts[first + k];
        std::array<std::size_t, 3> triangle;
        for(int i = 0; i < 3; ++i) {
          const std::uint32_t v = piece.corner[f][i];
          if(stamp[v] != k) stamp[v] = k, at[v] = std::int64_t(chart.uv.size()), chart.uv.push_back(s * piece.uv[v]);
          local.back()[3 * f + i] = at[v];
          triangle[i] = std::size_t(at[v]);
        }
        chart.triangles.push_back(triangle);
        const Vector<2> a = piece.uv[piece.corner[f][1]] - piece.uv[piece.corner[f][0]];
        const Vector<2> b = piece.uv[piece.corner[f][2]] - piece.uv[piece.corner[f][0]];
        chart.area += 0.5 * s * s * (a[0] * b[1] - a[1] * b[0]);
      }
    }
    const double efficiency = pack_charts(charts, options_.gutter);
    std::size_t first = 0;
    for(std::size_t n = 0; n < pieces_.size(); ++n) {
      Piece& piece = pieces_[n];
      piece.corner_uv.resize(piece.corner.size());
      for(std::size_t f = 0; f < piece.corner.size(); ++f)
        for(int i = 0; i < 3; ++i) piece.corner_uv[f][i] = charts[first + piece.part[f]].uv[std::size_t(local[n][3 * f + i])];
      first += piece.parts;
    }
    return efficiency;
  }

  Atlas_arrays collect() const
  {
    Atlas_arrays a;
    a.corner_uv.resize(faces_.size());
    a.chart.resize(faces_.size());
    a.face_distortion.resize(faces_.size());
    a.charts = 0;
    a.packing_efficiency = efficiency_;
    a.stopped_by_visitor = stopped_;
    double area = 0;
    for(std::size_t k = 0; k < pieces_.size(); ++k) {
      const Piece& piece = pieces_[k];
      for(std::size_t f = 0; f < piece.face.size(); ++f) {
        a.chart[piece.face[f]] = a.charts + piece.part[f];
        a.face_distortion[piece.face[f]] = piece.value[f];
        for(int i = 0; i < 3; ++i) a.corner_uv[piece.face[f]][i] = {piece.corner_uv[f][i][0], piece.corner_uv[f][i][1]};
      }
      a.charts += piece.parts;
      for(auto e : piece.mesh.edges()) {
        const double l = edge_length(piece.mesh, e);
        a.edge_length += l;
        if(piece.seam[std::size_t(e)] && !piece.mesh.is_border(e)) {
          a.seam_length += l;
          a.seam_edges.push_back({piece.vertex[std::size_t(piece.mesh.vertex(e, 0))], piece.vertex[std::size_t(piece.mesh.vertex(e, 1))]});
        }
      }
      a.cones += piece.cones;
      a.mean_distortion += piece.mean * piece.area;
      area += piece.area;
      a.max_distortion = (std::max)(a.max_distortion, piece.max);
      a.inverted_faces += piece.inverted;
      a.overlapping_charts += !piece.embedded;
      a.iterations += piece.iterations;
    }
    a.mean_distortion /= area;
    return a;
  }

  const std::vector<std::array<double, 3>>& points_;
  const std::vector<std::array<std::uint32_t, 3>>& faces_;
  const Measure& measure_;
  Atlas_options options_;
  std::vector<Piece> pieces_;
  double efficiency_ = 0;
  bool stopped_ = false;       // the visitor stopped the optimizations
  std::size_t visited_ = 0;    // iterations reported to it
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_ATLAS_ATLAS_BUILDER_H
