// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's outputs beside the maps: the report (stdout and --report), the pictures (--svg,
// --energy-plot) and the progress lines (--verbose).

#include "tool.h"

#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>
#include <CGAL/Distortion_optimization/mesh_quality.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

#include <unistd.h>

namespace distortion_optimizer {

bool Progress::operator()(std::size_t iteration, double energy, std::size_t inverted) const
{
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - state_->start).count();
  if(show_) {
    char decrease[32] = "-";   // the visitor is not told the start's energy
    if(state_->iteration == 0)
      std::fprintf(stderr, "%9s %18s %11s %9s %9s\n", "iteration", "energy", "decrease", "seconds", "inverted");
    else if(iteration <= state_->iteration)
      std::fprintf(stderr, "(above: untangling rounds, the energy the untangling barrier's; below: the optimization)\n");
    if(iteration > state_->iteration && state_->iteration > 0)
      std::snprintf(decrease, sizeof decrease, "%.3e", (state_->energy - energy) / std::abs(state_->energy));
    std::fprintf(stderr, "%9zu %18.10g %11s %9.3f %9zu\n", iteration, energy, decrease, seconds, inverted);
  }
  state_->iteration = iteration;
  state_->energy = energy;
  return !(limit_ > 0 && seconds >= limit_);
}


std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

void report(const Command_line& c, std::size_t cells, std::size_t vertices, const std::string& measure_name,
            const DO::Result& r, const Fields& fields)
{
  std::ostringstream json;
  json << "{\n  \"cells\": " << cells << ",\n  \"vertices\": " << vertices
       << ",\n  \"measure\": \"" << measure_name << "\",\n  \"initial_energy\": " << json_number(r.initial_energy)
       << ",\n  \"harmonic_start_energy\": " << json_number(r.harmonic_start_energy)
       << ",\n  \"final_energy\": " << json_number(r.final_energy) << ",\n  \"sweeps\": " << r.iterations
       << ",\n  \"seconds\": " << json_number(r.seconds) << ",\n  \"inverted_cells\": " << r.inverted_cells
       << ",\n  \"converged\": " << (r.converged ? "true" : "false")
       << ",\n  \"stopped_by_time_limit\": " << (r.stopped_by_visitor ? "true" : "false")
       << ",\n  \"inverted_start_cells\": " << r.inverted_start_cells << ",\n  \"untangle_iterations\": "
       << r.untangle_iterations << ",\n  \"untangle_seconds\": " << json_number(r.untangle_seconds)
       ;
  for(const auto& [name, value] : fields) json << ",\n  \"" << name << "\": " << value;
  json << ",\n  \"energy_per_sweep\": [";
  for(std::size_t i = 0; i < r.energy_per_iteration.size(); ++i)
    json << (i ? ", " : "") << json_number(r.energy_per_iteration[i]);
  json << "]\n}\n";
  if(!c.report.empty())
    DO::IO::write_file_atomically(c.report, [&](std::ostream& out) { out << json.str(); });
  std::printf("cells           %zu\nvertices        %zu\nmeasure         %s\ninitial_energy  %.12g\n"
              "final_energy    %.12g\nsweeps          %zu\nseconds         %.3f\ninverted_cells  %zu\n",
              cells, vertices, measure_name.c_str(), r.initial_energy, r.final_energy, r.iterations, r.seconds,
              r.inverted_cells);
  if(r.stopped_by_visitor) std::printf("stopped_by_time_limit true\n");
  if(c.untangle || c.volume_mode())
    std::printf("inverted_start_cells  %zu\nuntangle_iterations   %zu\nuntangle_seconds      %.3f\n", r.inverted_start_cells,
                r.untangle_iterations, r.untangle_seconds);
  // The fields' reals as the table's own (seconds to the millisecond, energies to 12 digits); the
  // report keeps them whole.
  for(const auto& [name, value] : fields) {
    char* end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    const bool real = !value.empty() && *end == '\0' && value.find_first_of(".eE") != std::string::npos;
    const bool seconds = name.size() >= 7 && name.compare(name.size() - 7, 7, "seconds") == 0;
    if(real) std::printf(seconds ? "%-21s %.3f\n" : "%-21s %.12g\n", name.c_str(), x);
    else std::printf("%-21s %s\n", name.c_str(), value.c_str());
  }
}

void check_untangled(const DO::Result& r)
{
  if(r.stopped_by_visitor && r.inverted_cells > 0)
    throw DO::Invalid_input("the time limit stopped the untangling with " + std::to_string(r.inverted_cells) +
                            " inverted or flat cells left (" + std::to_string(r.inverted_start_cells) +
                            " at the start) after " + std::to_string(r.untangle_iterations) +
                            " rounds; nothing written (a longer --time-limit lets it finish)");
}

std::vector<double> red_where_inverted(std::vector<double> values, const std::vector<bool>& inverted)
{
  for(std::size_t i = 0; i < values.size(); ++i)
    if(inverted[i]) values[i] = std::numeric_limits<double>::infinity();
  return values;
}

void write_pictures(const Command_line& c, DO::IO::Svg_panel source, DO::IO::Svg_panel map, const std::string& value_name,
                    const std::string& measure_name, const DO::Result& r)
{
  if(!c.svg.empty()) {
    std::vector<DO::IO::Svg_panel> panels;
    if(c.svg_both) panels.push_back(std::move(source));
    panels.push_back(std::move(map));
    DO::IO::write_SVG(c.svg, panels, value_name);
  }
  if(!c.energy_plot.empty()) {
    std::vector<double> energies = {r.initial_energy};
    energies.insert(energies.end(), r.energy_per_iteration.begin(), r.energy_per_iteration.end());
    DO::IO::write_energy_plot_SVG(c.energy_plot, energies, measure_name + " energy per iteration");
  }
}

Fields quality_fields(const DO::Mesh_quality& before, const DO::Mesh_quality& after)
{
  return {{"min_dihedral_before", json_number(before.min_angle)}, {"min_dihedral_after", json_number(after.min_angle)},
          {"mean_radius_ratio_before", json_number(before.mean_radius_ratio)},
          {"mean_radius_ratio_after", json_number(after.mean_radius_ratio)},
          {"min_radius_ratio_before", json_number(before.min_radius_ratio)},
          {"min_radius_ratio_after", json_number(after.min_radius_ratio)},
          {"slivers_before", std::to_string(before.slivers)}, {"slivers_after", std::to_string(after.slivers)}};
}

} // namespace distortion_optimizer
