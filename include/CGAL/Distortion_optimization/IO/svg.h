// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Pictures where people look rather than read: a map's cells coloured by their distortion (a
// planar or parametrized triangle mesh, or a planar cross-section of a tetrahedral mesh, as in the
// paper's Figs. 5 and 10), side by side with the source if wanted, and an energy-per-iteration
// plot. Plain SVG 1.1, written atomically.

#ifndef CGAL_DISTORTION_OPTIMIZATION_IO_SVG_H
#define CGAL_DISTORTION_OPTIMIZATION_IO_SVG_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>
#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace IO {

/// \ingroup PkgDistortionOptimizationIO
/// One drawing of an SVG figure: polygons in the plane, each with a value (e.g. its cell's
/// distortion; +infinity for an inverted or flat cell), and a title written above it.
struct Svg_panel
{
  std::string title;
  std::vector<std::vector<std::array<double, 2>>> polygons;
  std::vector<double> values;   ///< one per polygon
};

namespace internal {

// The perceptually uniform colour map viridis (van der Walt and Smith, matplotlib 2015), by its
// values at t = 0, 1/8, ..., 1, interpolated linearly in sRGB.
inline std::array<int, 3> viridis(double t)
{
  static const int stops[9][3] = {{68, 1, 84},    {71, 45, 123},  {59, 82, 139},   {44, 114, 142}, {33, 145, 140},
                                  {40, 174, 128}, {94, 201, 98},  {173, 220, 48},  {253, 231, 37}};
  t = std::clamp(t, 0., 1.) * 8;
  const int i = std::min(7, static_cast<int>(t));
  const double s = t - i;
  std::array<int, 3> c;
  for(int k = 0; k < 3; ++k) c[k] = static_cast<int>(std::lround(stops[i][k] + s * (stops[i + 1][k] - stops[i][k])));
  return c;
}

inline std::string rgb(const std::array<int, 3>& c)
{
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", c[0], c[1], c[2]);
  return buffer;
}

// A number as a short label: 4 significant digits.
inline std::string label(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", x);
  return buffer;
}

constexpr const char* inverted_colour = "#d62728";   // red, apart from every viridis colour

} // namespace internal

/// \ingroup PkgDistortionOptimizationIO
/// The triangles of a planar map or of a parametrization as a panel: `points` projected onto the
/// plane of their two largest bounding-box extents (the xy plane for a planar mesh), one polygon
/// and one value per triangle.
/// \throws Invalid_input if `values` does not have one entry per triangle or an index is out of range.
inline Svg_panel triangle_panel(const std::string& title, const std::vector<std::array<double, 3>>& points,
                                const std::vector<std::array<std::size_t, 3>>& triangles,
                                const std::vector<double>& values)
{
  if(values.size() != triangles.size())
    throw Invalid_input(title + ": " + std::to_string(values.size()) + " values for " + std::to_string(triangles.size()) + " triangles");
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for(const auto& p : points)
    for(int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  int drop = 2;   // the axis of smallest extent
  for(int k = 0; k < 2; ++k)
    if(hi[k] - lo[k] < hi[drop] - lo[drop]) drop = k;
  const int a = drop == 0 ? 1 : 0, b = drop == 2 ? 1 : 2;
  Svg_panel panel{title, {}, values};
  for(const auto& t : triangles) {
    std::vector<std::array<double, 2>> polygon;
    for(std::size_t i : t) {
      if(i >= points.size()) throw Invalid_input(title + ": a triangle has vertex index " + std::to_string(i) + " out of range");
      polygon.push_back({points[i][a], points[i][b]});
    }
    panel.polygons.push_back(polygon);
  }
  return panel;
}

/// \ingroup PkgDistortionOptimizationIO
/// The cross-section of a tetrahedral mesh by the plane z = (min z + max z) / 2 as a panel (the
/// paper's Figs. 5 and 10): each tetrahedron that the plane cuts gives a triangle or a
/// quadrilateral in the xy plane, with the tetrahedron's value. A vertex on the plane counts as
/// above it, so that a layer of faces lying in the plane is drawn once; a tetrahedron that only
/// touches the plane gives nothing.
/// \throws Invalid_input if `values` does not have one entry per tetrahedron or an index is out of range.
inline Svg_panel cross_section_panel(const std::string& title, const std::vector<std::array<double, 3>>& points,
                                     const std::vector<std::array<std::size_t, 4>>& tetrahedra,
                                     const std::vector<double>& values)
{
  if(values.size() != tetrahedra.size())
    throw Invalid_input(title + ": " + std::to_string(values.size()) + " values for " + std::to_string(tetrahedra.size()) + " tetrahedra");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for(const auto& p : points) lo = std::min(lo, p[2]), hi = std::max(hi, p[2]);
  const double z = (lo + hi) / 2;
  Svg_panel panel{title, {}, {}};
  for(std::size_t c = 0; c < tetrahedra.size(); ++c) {
    const auto& t = tetrahedra[c];
    for(std::size_t i : t)
      if(i >= points.size()) throw Invalid_input(title + ": tetrahedron " + std::to_string(c) + " has vertex index " + std::to_string(i) + " out of range");
    std::vector<std::array<double, 2>> polygon;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        const auto &p = points[t[i]], &q = points[t[j]];
        if((p[2] >= z) == (q[2] >= z)) continue;
        const double s = (z - p[2]) / (q[2] - p[2]);
        polygon.push_back({p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])});
      }
    if(polygon.size() < 3) continue;
    // Three or four points of a convex polygon: ordered by angle about their centroid.
    double cx = 0, cy = 0;
    for(const auto& p : polygon) cx += p[0] / polygon.size(), cy += p[1] / polygon.size();
    std::sort(polygon.begin(), polygon.end(), [&](const auto& p, const auto& q) {
      return std::atan2(p[1] - cy, p[0] - cx) < std::atan2(q[1] - cy, q[0] - cx);
    });
    double area = 0;   // zero where the tetrahedron only touches the plane (a vertex or an edge on it)
    for(std::size_t i = 0; i < polygon.size(); ++i) {
      const auto &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
      area += p[0] * q[1] - p[1] * q[0];
    }
    if(!(area > 0)) continue;
    panel.polygons.push_back(polygon);
    panel.values.push_back(values[c]);
  }
  return panel;
}

/// \ingroup PkgDistortionOptimizationIO
/// Writes `panels` side by side, each fitted in a 400-pixel square (same scale within a panel,
/// y upwards), every polygon filled with the colour of its value on one scale shared by all
/// panels: viridis (perceptually uniform) from the smallest finite value to the 99th percentile
/// (larger values take the top colour, and the legend gives the maximum), on a log scale when the
/// smallest is positive and the end of the scale at least ten times it; infinite values (inverted
/// or flat cells) in red. A legend below names `value_name`, the range and the scale, and counts
/// the red cells. Outlines are drawn up to 5000 polygons per panel.
/// \throws Invalid_input (before anything is written) if there is no panel, a panel's values and
/// polygons differ in number, or a coordinate or value is NaN or a coordinate infinite; or if the
/// file cannot be written.
inline void write_SVG(const std::string& path, const std::vector<Svg_panel>& panels, const std::string& value_name)
{
  if(panels.empty()) throw Invalid_input(internal::printable(path) + ": no panel to draw");
  std::vector<double> finite;
  std::size_t infinite = 0;
  for(std::size_t k = 0; k < panels.size(); ++k) {
    const Svg_panel& panel = panels[k];
    if(panel.values.size() != panel.polygons.size())
      throw Invalid_input(internal::printable(path) + ": panel '" + panel.title + "' has " + std::to_string(panel.values.size()) + " values for " +
                          std::to_string(panel.polygons.size()) + " polygons");
    for(const auto& polygon : panel.polygons)
      for(const auto& p : polygon)
        if(!std::isfinite(p[0]) || !std::isfinite(p[1]))
          throw Invalid_input(internal::printable(path) + ": panel '" + panel.title + "' has a non-finite coordinate");
    for(double v : panel.values)
      if(std::isnan(v)) throw Invalid_input(internal::printable(path) + ": panel '" + panel.title + "' has a NaN value");
    // A panel showing the values of an earlier one (a map's cells drawn on its source and on its
    // target) counts once: the scale and the red count are the cells', whatever is drawn.
    if(std::any_of(panels.begin(), panels.begin() + k, [&](const Svg_panel& other) { return other.values == panel.values; })) continue;
    for(double v : panel.values) {
      if(std::isinf(v)) ++infinite;
      else finite.push_back(v);
    }
  }
  // The scale ends at the 99th percentile, so that a few extreme cells do not flatten the rest
  // into one colour; the cells above it take the top colour, and the legend says so.
  const bool any = !finite.empty();
  double lo = 0, hi = 0, top = 0;
  if(any) {
    const std::size_t k = (finite.size() - 1) * 99 / 100;
    std::nth_element(finite.begin(), finite.begin() + k, finite.end());
    hi = finite[k];
    lo = *std::min_element(finite.begin(), finite.end());
    top = *std::max_element(finite.begin(), finite.end());
  }
  const bool log_scale = any && lo > 0 && hi >= 10 * lo;
  const auto position = [&](double v) {   // on the colour scale, in [0, 1]
    if(!any || hi == lo) return 0.5;
    return log_scale ? std::log(v / lo) / std::log(hi / lo) : (v - lo) / (hi - lo);
  };

  const double box = 400, margin = 20, title_height = 24, legend_height = 80;
  const double width = std::max(panels.size() * (box + margin) + margin, 640.), height = title_height + box + legend_height + 2 * margin;
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
        << width << ' ' << height << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for(std::size_t k = 0; k < panels.size(); ++k) {
      const Svg_panel& panel = panels[k];
      double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
      for(const auto& polygon : panel.polygons)
        for(const auto& p : polygon) x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]), x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
      const double extent = std::max(x1 - x0, y1 - y0), scale = extent > 0 ? box / extent : 1;
      const double left = margin + k * (box + margin) + (box - scale * (x1 - x0)) / 2,
                   top = margin + title_height + (box - scale * (y1 - y0)) / 2;
      out << "<text x=\"" << margin + k * (box + margin) + box / 2 << "\" y=\"" << margin + 14
          << "\" text-anchor=\"middle\">" << internal::xml_escaped(panel.title) << "</text>\n";
      // Outlines where they can be seen: beyond a few thousand cells they would only darken.
      const bool outlines = panel.polygons.size() <= 5000;
      // Without outlines, crisp edges keep the background from showing between the cells.
      out << "<g stroke=\"" << (outlines ? "#333" : "none") << "\" stroke-width=\""
          << (panel.polygons.size() > 1000 ? 0.15 : 0.3) << "\" stroke-linejoin=\"round\""
          << (outlines ? "" : " shape-rendering=\"crispEdges\"") << ">\n";
      for(std::size_t i = 0; i < panel.polygons.size(); ++i) {
        out << "<polygon points=\"";
        char buffer[64];
        for(const auto& p : panel.polygons[i]) {
          std::snprintf(buffer, sizeof buffer, "%.1f,%.1f ", left + scale * (p[0] - x0), top + scale * (y1 - p[1]));
          out << buffer;
        }
        const double v = panel.values[i];
        out << "\" fill=\"" << (std::isinf(v) ? internal::inverted_colour : internal::rgb(internal::viridis(position(v)))) << "\"/>\n";
      }
      out << "</g>\n";
    }
    // The legend: the colour bar with its ends, the measure and the scale, and the red cells.
    const double y = margin + title_height + box + 16, bar = std::min(300., width - 2 * margin - 160);
    out << "<defs><linearGradient id=\"scale\">";
    for(int i = 0; i <= 8; ++i)
      out << "<stop offset=\"" << i / 8. << "\" stop-color=\"" << internal::rgb(internal::viridis(i / 8.)) << "\"/>";
    out << "</linearGradient></defs>\n"
        << "<rect x=\"" << margin + 80 << "\" y=\"" << y << "\" width=\"" << bar << "\" height=\"12\" fill=\"url(#scale)\" stroke=\"#333\" stroke-width=\"0.5\"/>\n"
        << "<text x=\"" << margin + 74 << "\" y=\"" << y + 11 << "\" text-anchor=\"end\">" << (any ? internal::label(lo) : "-") << "</text>\n"
        << "<text x=\"" << margin + 86 + bar << "\" y=\"" << y + 11 << "\">" << (any ? internal::label(hi) : "-")
        << (top > hi ? " (max " + internal::label(top) + ")" : "") << "</text>\n"
        << "<text x=\"" << margin + 80 << "\" y=\"" << y + 32 << "\">" << internal::xml_escaped(value_name) << " per cell, "
        << (log_scale ? "log" : "linear") << " scale" << (top > hi ? " to the 99th percentile" : "") << "</text>\n";
    if(infinite > 0)
      out << "<text x=\"" << margin + 80 << "\" y=\"" << y + 52 << "\"><tspan fill=\"" << internal::inverted_colour
          << "\">&#9632;</tspan> " << infinite << " inverted or flat</text>\n";
    out << "</svg>\n";
  });
}

/// \ingroup PkgDistortionOptimizationIO
/// Writes an energy-per-iteration plot (e.g. `Result::energy_per_iteration`, with the start's
/// energy first) as an SVG line chart: iterations on x, energy on y from the smallest value to the
/// largest (on a log scale when they are positive and span a factor of ten or more), five
/// labelled ticks on each axis. Values that are not finite (a start with inverted cells under a
/// measure infinite there, a run stopped before its energy was evaluated) are left out of the line
/// and counted in a note under it.
/// \throws Invalid_input (before anything is written) if `energies` is empty; or if the file
/// cannot be written.
inline void write_energy_plot_SVG(const std::string& path, const std::vector<double>& energies, const std::string& name)
{
  if(energies.empty()) throw Invalid_input(internal::printable(path) + ": no energy to plot");
  std::vector<double> finite;
  for(double e : energies)
    if(std::isfinite(e)) finite.push_back(e);
  const std::size_t left_out = energies.size() - finite.size();
  const double lo = finite.empty() ? 0 : *std::min_element(finite.begin(), finite.end()),
               hi = finite.empty() ? 1 : *std::max_element(finite.begin(), finite.end());
  const bool log_scale = lo > 0 && hi >= 10 * lo;
  const auto f = [&](double e) { return log_scale ? std::log(e) : e; };
  const double n = std::max<double>(1, energies.size() - 1), range = hi > lo ? f(hi) - f(lo) : 1;
  const double left = 80, top = 30, w = 480, h = 300;
  const auto x = [&](double i) { return left + w * i / n; };
  const auto y = [&](double e) { return top + h * (1 - (f(e) - f(lo)) / range); };
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << left + w + 30 << "\" height=\"" << top + h + 80
        << "\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << left + w / 2 << "\" y=\"18\" text-anchor=\"middle\">" << internal::xml_escaped(name) << "</text>\n"
        << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << w << "\" height=\"" << h << "\" fill=\"none\" stroke=\"#333\"/>\n";
    // Five ticks on each axis: energies only where they differ (one label for a constant energy),
    // iterations at whole numbers, each once.
    double last_tick = -1;
    for(int k = 0; k <= 4; ++k) {
      const double e = log_scale ? lo * std::exp(range * k / 4) : lo + range * k / 4, i = std::round(n * k / 4);
      if(hi > lo || k == 0)   // (at k = 0, e is lo)
        out << "<text x=\"" << left - 6 << "\" y=\"" << y(e) + 4 << "\" text-anchor=\"end\">" << internal::label(e) << "</text>\n";
      if(i > last_tick && i <= double(energies.size() - 1))
        out << "<text x=\"" << x(i) << "\" y=\"" << top + h + 18 << "\" text-anchor=\"middle\">" << internal::label(i) << "</text>\n";
      last_tick = i;
    }
    out << "<text x=\"" << left + w / 2 << "\" y=\"" << top + h + 42 << "\" text-anchor=\"middle\">iteration"
        << (log_scale ? " (energy on a log scale)" : "") << "</text>\n";
    if(left_out > 0)
      out << "<text x=\"" << left + w / 2 << "\" y=\"" << top + h + 62 << "\" text-anchor=\"middle\">" << left_out << " of "
          << energies.size() << " energies not finite, not drawn</text>\n";
    // One polyline per run of finite values: a gap where an energy is not finite.
    char buffer[64];
    for(std::size_t i = 0; i < energies.size();) {
      if(!std::isfinite(energies[i])) {
        ++i;
        continue;
      }
      out << "<polyline fill=\"none\" stroke=\"" << internal::rgb(internal::viridis(0.25)) << "\" stroke-width=\"2\" points=\"";
      for(; i < energies.size() && std::isfinite(energies[i]); ++i) {
        std::snprintf(buffer, sizeof buffer, "%.2f,%.2f ", x(double(i)), y(energies[i]));
        out << buffer;
      }
      out << "\"/>\n";
    }
    out << "</svg>\n";
  });
}

} // namespace IO
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_IO_SVG_H
