// distortion_optimizer: the command-line tool of the package.
//
//   distortion_optimizer --source S --target T --output O [--measure NAME] [--fix boundary|none|FILE]
//                        [--iterations N] [--threshold EPS] [--solver gd|bfgs] [--threads N] [--report R.json]
//                        [--schedule alternating|local|global] [--untangle] [--quiet|--verbose]
//                        [--time-limit SECONDS]
//   distortion_optimizer --source CLOSED --start ball|radial --output O.mesh [--mesh-output M.mesh]
//                        [--cell-size H] [--center X,Y,Z] [--boundary slide|fixed]
//                        [--carry INNER --carry-output C [--snap]] [options above]
//
// S, T, O: OFF or OBJ triangle meshes, or Medit .mesh tetrahedral meshes, with the same vertices
// and cells in the same order; a planar target has z = 0. Without --target, a disk-topology
// triangle source gets a Tutte start (circle border). O may also be .vtu: the optimized map with
// each cell's distortion, for ParaView.
// Volume mode (--start): the inside of a closed surface is meshed with Mesh_3 (or a .mesh source
// is taken as it is), mapped onto the unit ball or by x |x|, untangled where that start flattens
// cells, and optimized with the boundary sliding on the start's boundary surface or fixed; a
// surface inside the volume may be carried through the map (paper 4.4).
// Energies are volume-weighted means sum vol(c) D(J_c) / sum vol(c).
// Exit status: 0 on success, 1 for bad input (one-line message), 2 for a bad command line.

#include "command_line.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/IO/vertex_list.h>
#include <CGAL/Distortion_optimization/IO/svg.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>
#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/Distortion_optimization/mesh_interior.h>
#include <CGAL/Distortion_optimization/mesh_quality.h>
#include <CGAL/Distortion_optimization/sliding_surfaces.h>
#include <CGAL/Distortion_optimization/subdivide_map.h>
#include <CGAL/Distortion_optimization/volume_maps.h>
#include <CGAL/Distortion_optimization/volumetric_texture.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <future>
#include <unordered_map>
#include <unordered_set>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Vertex = Mesh::Vertex_index;
using Tr = CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<K>>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;

namespace {

using distortion_optimizer::Command_line;
using distortion_optimizer::Usage_error;
using distortion_optimizer::parse;
using distortion_optimizer::usage;
using distortion_optimizer::tetrahedral_file;

// The source as a Surface_mesh, vertex i and face f in file order; rejects what a surface mesh
// cannot represent (non-manifold edges or vertices, inconsistent orientation, unused vertices).
Mesh to_mesh(const DO::IO::Triangle_soup& soup, const std::string& name)
{
  Mesh mesh;
  for(const auto& p : soup.points) mesh.add_vertex(K::Point_3(p[0], p[1], p[2]));
  for(std::size_t f = 0; f < soup.cells.size(); ++f) {
    const auto& t = soup.cells[f];
    if(mesh.add_face(Vertex(t[0]), Vertex(t[1]), Vertex(t[2])) == Mesh::null_face())
      throw DO::Invalid_input(name + ": face " + std::to_string(f) +
                              " makes the mesh non-manifold or inconsistently oriented");
  }
  for(Vertex v : mesh.vertices())
    if(mesh.is_isolated(v)) throw DO::Invalid_input(name + ": vertex " + std::to_string(std::size_t(v)) + " is in no face");
  std::vector<Mesh::Halfedge_index> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(pinched));
  if(!pinched.empty())
    throw DO::Invalid_input(name + ": vertex " + std::to_string(std::size_t(mesh.target(pinched.front()))) + " is non-manifold");
  return mesh;
}

// One piece (a disk beside a closed torus has one border and Euler characteristic 1 too), one
// border, Euler characteristic 1.
bool is_disk(const Mesh& mesh)
{
  std::vector<std::size_t> component(mesh.number_of_faces());
  if(CGAL::Polygon_mesh_processing::connected_components(
       mesh, boost::make_iterator_property_map(component.begin(), get(CGAL::face_index, mesh))) != 1)
    return false;
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  const long long euler = static_cast<long long>(mesh.number_of_vertices()) - static_cast<long long>(mesh.number_of_edges()) +
                          static_cast<long long>(mesh.number_of_faces());
  return cycles.size() == 1 && euler == 1;
}

// A target must list the source's vertices (as many) and cells (the same, in the same order).
template <class Points, class Cells>
void check_same_cells(const std::string& name, const Points& source_points, const Cells& source_cells,
                      const Points& target_points, const Cells& target_cells, const std::string& cell)
{
  if(target_points.size() != source_points.size() || target_cells.size() != source_cells.size())
    throw DO::Invalid_input(name + ": " + std::to_string(target_points.size()) + " vertices and " +
                            std::to_string(target_cells.size()) + " cells, the source has " +
                            std::to_string(source_points.size()) + " and " + std::to_string(source_cells.size()));
  for(std::size_t k = 0; k < source_cells.size(); ++k)
    if(target_cells[k] != source_cells[k])
      throw DO::Invalid_input(name + ": " + cell + " " + std::to_string(k) + " differs from the source's (same connectivity needed)");
}

// Whether a planar map (the mesh's vertices, uv; its faces, cells) with no inverted cell is globally
// injective: its border crosses itself nowhere and no piece lies inside another (the boundary
// guard's exact test).
template <class UV>
bool is_globally_injective(const Mesh& mesh, const UV& uv, const std::vector<std::array<std::size_t, 3>>& cells)
{
  using Guard = DO::internal::Boundary_guard<2>;
  std::vector<std::array<std::uint32_t, 3>> faces;
  for(const auto& t : cells) faces.push_back({std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
  std::vector<DO::internal::Vector<2>> x;
  for(Vertex v : mesh.vertices()) x.emplace_back(uv[v].x(), uv[v].y());
  return Guard(Guard::boundary_faces(faces), x.size(), DO::internal::connected_pieces(faces, x.size())).is_injective(x);
}

// Free-boundary mode (some border vertex free), and boundary vertices sliding on a triangle surface
// (the source's own boundary, where a vertex projected onto the closest point of another part of it
// would cross it; hostile round 9: two blocks 1/4096 apart overlapped): the run keeps the boundary
// from crossing itself (global injectivity). A start whose boundary already crosses itself cannot
// be guarded: then the run goes on without the guard, with a warning. (Sliding on the unit sphere
// does not come here: a map of the sphere onto itself without folds is one-to-one.)
template <class Run>
DO::Result with_boundary_guard(const Command_line& c, const Run& run)
{
  if(c.fix == "boundary" && !c.slides()) return run(false);
  try {
    return run(true);
  } catch(const DO::Crossing_start_boundary& guarded) {
    DO::Result r = run(false);   // throws again if the input was bad for another reason
    std::cerr << "distortion_optimizer: warning: " << guarded.what() << "; optimized without the guard\n";
    return r;
  }
}

// The visitor of every optimization: a progress line per iteration on stderr (--verbose, or
// stderr a terminal without --quiet) and the stop at --time-limit. Copies share one clock, which
// starts with the first copy's run.
class Progress
{
public:
  explicit Progress(const Command_line& c)
    : show_(c.verbose || (!c.quiet && ::isatty(STDERR_FILENO))), limit_(c.time_limit), state_(std::make_shared<State>()) {}

  // The untangling's rounds (with --untangle) come first, their energy the barrier's; the
  // optimization's iterations then start again from 1, under a line that says so.
  bool operator()(std::size_t iteration, double energy, std::size_t inverted) const
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

private:
  struct State
  {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::size_t iteration = 0;
    double energy = 0;
  };
  bool show_;
  double limit_;
  std::shared_ptr<State> state_;
};

// The options both kinds of mesh share, with the vertex weights (a map of the mesh's vertices).
template <class Weights>
auto common_parameters(const Command_line& c, const Weights& weights)
{
  namespace P = DO::parameters;
  const auto solver = c.solver == "bfgs" ? DO::Local_solver::BFGS : DO::Local_solver::GRADIENT_DESCENT;
  // Without --schedule, the library's default (minimize_distortion()'s schedule parameter).
  const std::optional<DO::Schedule> schedule =
    c.schedule.empty() ? std::nullopt
    : std::optional<DO::Schedule>(c.schedule == "local" ? DO::Schedule::LOCAL
                                  : c.schedule == "global" ? DO::Schedule::GLOBAL : DO::Schedule::ALTERNATING);
  const auto weighting = c.cell_weighting == "volume" ? DO::Cell_weighting::VOLUME
                       : c.cell_weighting == "uniform" ? DO::Cell_weighting::UNIFORM : DO::Cell_weighting::AVERAGE_VOLUME;
  const auto order = c.order == "greedy" ? DO::Vertex_order::GREEDY : DO::Vertex_order::SORTED_PER_SWEEP;
  const auto sweep = c.parallel_sweep == "partition" ? DO::Parallel_sweep::PARTITION : DO::Parallel_sweep::INDEPENDENT_SETS;
  const bool harmonic = c.harmonic_start.empty() ? schedule != DO::Schedule::LOCAL : c.harmonic_start == "on";
  // Without --global-step, the library's default for the mesh's dimension.
  const std::optional<DO::Global_solver> solver_of_global_step =
    c.global_step.empty() ? std::nullopt
    : std::optional<DO::Global_solver>(c.global_step == "newton" ? DO::Global_solver::PROJECTED_NEWTON
                                                                 : DO::Global_solver::REWEIGHTED_LAPLACIAN);
  return P::number_of_threads(static_cast<int>(std::min<std::size_t>(c.threads, 256)),
    P::schedule(schedule, P::local_solver(solver, P::untangle_first(c.untangle, P::convergence_threshold(c.threshold,
      P::cell_weighting(weighting, P::vertex_order(order, P::parallel_sweep(sweep, P::use_harmonic_start(harmonic,
        P::global_solver(solver_of_global_step, P::vertex_weight_map(weights)))))))))))
    .number_of_iterations(c.iterations).visitor(Progress(c));
}

std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// Prints the results and writes them to --report as JSON.
void report(const Command_line& c, std::size_t cells, std::size_t vertices, const std::string& measure_name,
            const DO::Result& r, const std::vector<std::pair<std::string, std::string>>& fields = {})
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

// A run that --time-limit stopped during the untangling has no valid map to write.
void check_untangled(const DO::Result& r)
{
  if(r.stopped_by_visitor && r.inverted_cells > 0)
    throw DO::Invalid_input("the time limit stopped the untangling with " + std::to_string(r.inverted_cells) +
                            " inverted or flat cells left (" + std::to_string(r.inverted_start_cells) +
                            " at the start) after " + std::to_string(r.untangle_iterations) +
                            " rounds; nothing written (a longer --time-limit lets it finish)");
}

// Each cell's value for a picture: an infinite one (drawn red) where the map inverts or flattens
// the cell, also under a measure finite there (ARAP, Dirichlet).
std::vector<double> red_where_inverted(std::vector<double> values, const std::vector<bool>& inverted)
{
  for(std::size_t i = 0; i < values.size(); ++i)
    if(inverted[i]) values[i] = std::numeric_limits<double>::infinity();
  return values;
}

// --svg (the map's cells coloured by `value_name`, beside the source's with --svg-both) and
// --energy-plot (the start's energy, then each iteration's).
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

// --reference ideal: the report's quality fields (angles are dihedral angles for tetrahedra).
std::vector<std::pair<std::string, std::string>> quality_fields(const DO::Mesh_quality& before, const DO::Mesh_quality& after)
{
  return {{"min_dihedral_before", json_number(before.min_angle)}, {"min_dihedral_after", json_number(after.min_angle)},
          {"mean_radius_ratio_before", json_number(before.mean_radius_ratio)},
          {"mean_radius_ratio_after", json_number(after.mean_radius_ratio)},
          {"min_radius_ratio_before", json_number(before.min_radius_ratio)},
          {"min_radius_ratio_after", json_number(after.min_radius_ratio)},
          {"slivers_before", std::to_string(before.slivers)}, {"slivers_after", std::to_string(after.slivers)}};
}

int run_triangles(const Command_line& c)
{
  const DO::IO::Triangle_soup source = DO::IO::read_triangle_soup(c.source);
  Mesh mesh = to_mesh(source, c.source);
  bool planar = true;
  for(const auto& p : source.points) planar = planar && p[2] == 0;

  auto uv = mesh.add_property_map<Vertex, K::Point_2>("v:target").first;
  if(c.ideal()) {
    if(!planar) throw DO::Invalid_input(c.source + ": --reference ideal needs a planar mesh (z = 0) or a .mesh");
    for(Vertex v : mesh.vertices()) uv[v] = K::Point_2(mesh.point(v).x(), mesh.point(v).y());
  } else if(!c.target.empty()) {
    // The target's positions (z = 0), or its UVs: an OBJ whose faces refer to texture coordinates.
    const DO::IO::Triangle_soup target = DO::IO::read_triangle_soup(c.target);
    check_same_cells(c.target, source.points, source.cells, target.points, target.cells, "face");
    const std::vector<std::array<double, 2>> texture = DO::IO::per_vertex_texture_coordinates(target, c.target);
    // A planar source's target may be its map by its positions (z = 0) as well as by its UVs: the
    // UVs are the map only where the positions are the source's own (a surface with its UVs, as
    // the tool writes one); planar positions elsewhere make it ambiguous.
    if(!texture.empty() && planar && target.points != source.points &&
       std::all_of(target.points.begin(), target.points.end(), [](const std::array<double, 3>& p) { return p[2] == 0; }))
      throw DO::Invalid_input(DO::IO::internal::printable(c.target) + ": both its positions (planar, not the source's) and its UVs "
                              "(f v/vt) could be the map of the planar source: write the map as positions without UVs, or as "
                              "UVs with the source's positions");
    for(std::size_t i = 0; i < target.points.size(); ++i) {
      if(!texture.empty()) {
        uv[Vertex(i)] = K::Point_2(texture[i][0], texture[i][1]);
        continue;
      }
      if(target.points[i][2] != 0)
        throw DO::Invalid_input(c.target + ": vertex " + std::to_string(i) + " has z != 0 (the target must be planar" +
                                (target.texture_coordinates.empty() ? ")"
                                 : "; its vt lines are not UVs of the map: no face refers to them, as in f v/vt)"));
      uv[Vertex(i)] = K::Point_2(target.points[i][0], target.points[i][1]);
    }
  } else {
    if(!is_disk(mesh))
      throw DO::Invalid_input(c.source + ": without --target the source must be a topological disk (one piece, one border, no handle)");
    DO::initial_parameterization(mesh, uv);
    // The tool's own start has the source's orientation: the Tutte map is counter-clockwise, so a
    // planar source listed clockwise gets its mirror image. (A surface is compared in each face's
    // own frame, where any consistent orientation is positive.)
    std::size_t left = 0, right = 0;   // the triangles' orientations (exact: no area underflows far from unit size)
    for(const auto& t : source.cells) {
      const auto &a = source.points[t[0]], &b = source.points[t[1]], &d = source.points[t[2]];
      const CGAL::Orientation o = CGAL::orientation(K::Point_2(a[0], a[1]), K::Point_2(b[0], b[1]), K::Point_2(d[0], d[1]));
      left += o == CGAL::LEFT_TURN;
      right += o == CGAL::RIGHT_TURN;
    }
    // A planar source that folds (triangles of both orientations) inverts some cells of any start.
    if(planar && left > 0 && right > 0 && !c.untangle)
      throw DO::Invalid_input(c.source + ": the planar source folds over itself (" + std::to_string(std::min(left, right)) +
                              " of its triangles are oriented against the others), so the tool's Tutte start inverts "
                              "them: --untangle unfolds it");
    if(planar && right > left)
      for(Vertex v : mesh.vertices()) uv[v] = K::Point_2(uv[v].x(), -uv[v].y());
  }

  auto fixed = mesh.add_property_map<Vertex, bool>("v:fixed", false).first;
  if(c.fix == "boundary") {
    for(Vertex v : mesh.vertices()) fixed[v] = mesh.is_border(v);
  } else if(c.fix != "none") {
    const auto list = DO::IO::read_vertex_list(c.fix, mesh.number_of_vertices());
    for(Vertex v : mesh.vertices()) fixed[v] = list[std::size_t(v)] != 0;
  }

  auto weights = mesh.add_property_map<Vertex, double>("v:weight", 1.).first;
  if(!c.vertex_weights.empty()) {
    const std::vector<double> w = DO::IO::read_vertex_weights(c.vertex_weights, mesh.number_of_vertices());
    for(Vertex v : mesh.vertices()) weights[v] = w[std::size_t(v)];
  }

  auto source_2 = mesh.add_property_map<Vertex, K::Point_2>("v:source_2").first;
  for(Vertex v : mesh.vertices()) source_2[v] = K::Point_2(mesh.point(v).x(), mesh.point(v).y());

  std::string measure_name;
  std::vector<std::pair<std::string, std::string>> fields;
  const DO::Mesh_quality before = c.ideal() ? DO::mesh_quality(mesh, uv) : DO::Mesh_quality();
  const DO::Result r = DO::with_measure(c.measure, [&](const auto& measure) {
    measure_name = measure.name();
    return with_boundary_guard(c, [&](bool guard) {
      auto np = DO::parameters::preserve_global_injectivity(guard, common_parameters(c, weights)).vertex_is_constrained_map(fixed);
      if(c.ideal()) return DO::improve_mesh_quality(mesh, uv, measure, np);
      // A planar source is compared in its own plane (so its orientation counts), a surface in
      // each triangle's frame.
      return planar ? CGAL::minimize_distortion(mesh, uv, measure, np.vertex_point_map(source_2))
                    : CGAL::minimize_distortion(mesh, uv, measure, np);
    });
  });
  check_untangled(r);
  if(c.ideal()) fields = quality_fields(before, DO::mesh_quality(mesh, uv));
  const std::size_t cells = mesh.number_of_faces(), vertices = mesh.number_of_vertices();

  // The map's distortion, each face's value into per_face, and which faces it inverts or flattens.
  auto per_face = mesh.add_property_map<Mesh::Face_index, double>("f:distortion").first;
  auto inverted_face = mesh.add_property_map<Mesh::Face_index, bool>("f:inverted").first;
  const auto distortion = [&] {
    return DO::with_measure(c.measure, [&](const auto& measure) {
      const auto np = DO::parameters::cell_distortion_map(per_face, DO::parameters::inverted_cell_map(inverted_face));
      return planar ? CGAL::compute_distortion(mesh, uv, measure, np.vertex_point_map(source_2))
                    : CGAL::compute_distortion(mesh, uv, measure, np);
    });
  };
  DO::IO::Triangle_soup output;
  output.cells = source.cells;
  if(c.subdivide > 0) {
    // The source and the optimized map refined together (paper 4.3); the source goes to its own file.
    const bool injective = r.inverted_cells == 0 && is_globally_injective(mesh, uv, source.cells);
    DO::subdivide_map(mesh, uv, static_cast<unsigned>(c.subdivide),
                      c.scheme == "loop" ? DO::Subdivision_scheme::LOOP : DO::Subdivision_scheme::LINEAR);
    DO::IO::Triangle_soup refined;
    for(Vertex v : mesh.vertices()) {
      source_2[v] = K::Point_2(mesh.point(v).x(), mesh.point(v).y());
      refined.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    }
    for(auto f : mesh.faces()) {
      std::array<std::size_t, 3> t;
      int i = 0;
      for(Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[i++] = std::size_t(v);
      refined.cells.push_back(t);
    }
    output.cells = refined.cells;
    // Loop's smoothing may invert cells of the refined map, and so may linear midpoints rounded on
    // a nearly flat cell (a measure finite on flat cells lets cells get that thin): no output then.
    // (A map inverted already, under such a measure without --untangle, is refined as it is.)
    const DO::Distortion_statistics refined_distortion = distortion();
    if(refined_distortion.inverted_cells > 0 && r.inverted_cells == 0)
      throw DO::Invalid_input("the subdivided map has " + std::to_string(refined_distortion.inverted_cells) +
                              " inverted or flat cells (" +
                              (c.scheme == "loop" ? std::string("Loop's smoothing folds it; --scheme linear keeps the optimized map's cells")
                                                  : "rounded midpoints of nearly flat cells of the optimized map; a measure infinite "
                                                    "on flat cells keeps them away") + "); nothing written");
    // Loop's border rule also moves the border: it may cross itself, or pieces overlap.
    if(injective && refined_distortion.inverted_cells == 0 && !is_globally_injective(mesh, uv, refined.cells))
      throw DO::Invalid_input("the subdivided map's border crosses itself or one of its pieces overlaps another (" +
                              (c.scheme == "loop" ? std::string("Loop's smoothing moves the border; --scheme linear keeps the optimized map")
                                                  : "rounded midpoints of borders closer than their rounding") + "); nothing written");
    DO::IO::write_triangle_soup(c.subdivided_source, refined);
    // The refined map's energy under --cell-weighting; its new vertices have no weights of their
    // own, so every vertex weighs 1 here.
    const double refined_energy = c.cell_weighting == "uniform" ? refined_distortion.mean_uniform
                                : c.cell_weighting == "volume" ? refined_distortion.mean_volume
                                                               : refined_distortion.mean_average_volume;
    fields.insert(fields.end(), {{"subdivided_cells", std::to_string(mesh.number_of_faces())},
                                 {"subdivided_vertices", std::to_string(mesh.number_of_vertices())},
                                 {"subdivided_energy", json_number(refined_energy)},
                                 {"subdivided_inverted_cells", std::to_string(refined_distortion.inverted_cells)}});
  }
  for(Vertex v : mesh.vertices()) output.points.push_back({uv[v].x(), uv[v].y(), 0.});
  std::vector<double> values;   // each face's distortion, evaluated once for the outputs that show it
  std::vector<bool> inverted;   // whether the map inverts or flattens each face
  if(DO::IO::internal::extension(c.output) == "vtu" || (!c.svg.empty() && !c.ideal())) {
    if(c.subdivide == 0) distortion();   // (a subdivided map's values are in per_face already)
    for(auto f : mesh.faces()) {
      values.push_back(per_face[f]);
      inverted.push_back(inverted_face[f]);
    }
  }
  if(!c.flat_output.empty()) DO::IO::write_triangle_soup(c.flat_output, output);
  if(!planar && DO::IO::internal::extension(c.output) == "obj") {
    // A parametrization as texture tools read it: the surface, with one UV per vertex.
    DO::IO::Triangle_soup textured;
    for(Vertex v : mesh.vertices()) {
      textured.points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
      textured.texture_coordinates.push_back({uv[v].x(), uv[v].y()});
    }
    textured.cells = textured.cell_texture_indices = output.cells;
    DO::IO::write_triangle_soup(c.output, textured);
  } else if(DO::IO::internal::extension(c.output) == "vtu") {
    std::vector<std::array<double, 3>> displacement;
    for(Vertex v : mesh.vertices())
      displacement.push_back({uv[v].x() - mesh.point(v).x(), uv[v].y() - mesh.point(v).y(), -mesh.point(v).z()});
    DO::IO::write_VTU(c.output, output.points, output.cells, {{measure_name, values}}, {{"displacement", displacement}});
  } else {
    DO::IO::write_triangle_soup(c.output, output);
  }
  if(!c.svg.empty()) {
    // A map's distortion, or with --reference ideal the quality of the mesh before and after.
    std::vector<std::array<double, 3>> points;
    for(Vertex v : mesh.vertices()) points.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    if(c.ideal())
      write_pictures(c, DO::IO::triangle_panel("before", points, output.cells,
                                               red_where_inverted(DO::radius_ratios(points, output.cells),
                                                                  DO::inverted_triangles(points, output.cells))),
                     DO::IO::triangle_panel("after", output.points, output.cells,
                                            red_where_inverted(DO::radius_ratios(output.points, output.cells),
                                                               DO::inverted_triangles(output.points, output.cells))),
                     "radius ratio", measure_name, r);
    else {
      const std::vector<double> shown = red_where_inverted(values, inverted);
      write_pictures(c, DO::IO::triangle_panel("source", points, output.cells, shown),
                     DO::IO::triangle_panel("map", output.points, output.cells, shown), measure_name, measure_name, r);
    }
  } else {
    write_pictures(c, {}, {}, measure_name, measure_name, r);
  }
  report(c, cells, vertices, measure_name, r, fields);
  return 0;
}

// The source tetrahedra: read from a .mesh, or the inside of a closed surface meshed by Mesh_3.
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

// The surface carried through the tetrahedral map (--carry): embedded in the source volume once,
// measured under the start map and the optimized one.
struct Carried_surface
{
  DO::IO::Triangle_soup soup;
  Mesh mesh;
  DO::Volume_embedding<C3t3> embedding;
  double start_energy = 0, final_energy = 0;

  Carried_surface(const Command_line& c, const C3t3& c3t3)
    : soup(DO::IO::read_triangle_soup(c.carry)), mesh(to_mesh(soup, c.carry)), embedding(embed(c, c3t3, mesh))
  {}

  // The vertices outside the volume named in the tool's words (--snap, not the named parameter).
  static DO::Volume_embedding<C3t3> embed(const Command_line& c, const C3t3& c3t3, const Mesh& mesh)
  {
    try {
      return DO::embed_surface_in_volume(c3t3, mesh, DO::parameters::snap_to_volume(c.snap));
    } catch(const DO::Points_outside_volume& e) {
      throw DO::Invalid_input(c.carry + ": " + e.listing() + " (--snap moves such points onto its boundary)");
    }
  }

  // The mean distortion (volume-weighted, as the tool's energies) of the surface under `target`.
  template <class Target>
  double energy(const Command_line& c, const Target& target)
  {
    auto image = mesh.add_property_map<Vertex, K::Point_3>("v:carried").first;
    DO::carry_surface_vertices(mesh, embedding, target, image);
    try {   // its errors name the carried surface, not the map's source
      const auto stats = DO::with_measure(c.measure, [&](const auto& measure) { return CGAL::compute_distortion(mesh, image, measure); });
      return stats.mean_volume;
    } catch(const DO::Invalid_input& e) {
      throw DO::Invalid_input(c.carry + " (the carried surface): " + e.what());
    }
  }

  template <class Target>
  void write(const std::string& path, const Target& target)
  {
    std::vector<K::Point_3> images;
    DO::carry_points(embedding, target, std::back_inserter(images));
    DO::IO::Triangle_soup out;
    out.cells = soup.cells;
    for(const K::Point_3& p : images) out.points.push_back({p.x(), p.y(), p.z()});
    DO::IO::write_triangle_soup(path, out);
  }
};

int run_tetrahedra(const Command_line& c)
{
  std::vector<std::pair<std::string, std::string>> extra;   // the volume mode's report fields
  double mesh_seconds = 0;
  // With threads, the target is read while the source is (a source's error is still the first told).
  std::future<DO::IO::Tetrahedron_soup> target_read;
  if(!c.target.empty())
    target_read = std::async(c.threads > 1 ? std::launch::async : std::launch::deferred,
                             [&] { return DO::IO::read_tetrahedron_soup(c.target); });
  const DO::IO::Tetrahedron_soup source = read_or_mesh_source(c, mesh_seconds);
  DO::IO::Tetrahedron_soup target = target_read.valid() ? target_read.get() : source;
  if(!c.target.empty()) check_same_cells(c.target, source.points, source.cells, target.points, target.cells, "tetrahedron");
  C3t3 c3t3;
  std::vector<Tr::Vertex_handle> handles;
  try {
    handles = DO::c3t3_from_tetrahedra(source.points, source.cells, c3t3, 1, DO::parameters::number_of_threads(static_cast<int>(c.threads)));
  } catch(const DO::Invalid_input& e) {
    // The source's tetrahedra are the complex's: they must be valid, even where the map is
    // untangled (--untangle repairs the target; with --reference ideal the target is S itself).
    throw DO::Invalid_input((tetrahedral_file(c.source) ? c.source + ": " : std::string()) + e.what() +
                            (c.ideal() ? " (--reference ideal takes a valid mesh: --untangle repairs a map's target, not the "
                                         "source)" : ""));
  }
  std::unordered_map<Tr::Vertex_handle, K::Point_3> storage;
  std::unordered_map<Tr::Vertex_handle, std::size_t> index;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Tr::Vertex_handle()) {
      storage[handles[i]] = K::Point_3(target.points[i][0], target.points[i][1], target.points[i][2]);
      index[handles[i]] = i;
    }
  boost::associative_property_map<decltype(storage)> target_map(storage);
  std::unique_ptr<Carried_surface> carried;
  if(!c.carry.empty()) carried = std::make_unique<Carried_surface>(c, c3t3);

  // Volume mode: the start map, the tool's own, untangled if the map flattens cells (a ball map
  // does across the sharp edges of the domain).
  Command_line run = c;
  if(c.volume_mode()) {
    // The start is the tool's own, of about unit size (the radial map's, the square of a unit
    // source's): a source too far from unit size for the measures is refused as such, before
    // the radial map squares its size out of double precision. The size of the tetrahedra's
    // vertices (a point in none keeps its target): 2^size, the inverse of their scale.
    const int size = -std::ilogb(DO::internal::complex_scale(c3t3));
    if(std::abs(size - 1) > DO::largest_size_ratio_exponent<3>)
      throw DO::Invalid_input("the source's size (about 2^" + std::to_string(size) + ") and the unit size of the start (--start " +
                              c.start + ") differ by more than 2^" + std::to_string(DO::largest_size_ratio_exponent<3>) +
                              ": distortions cannot be evaluated in double precision; scale the source");
    const K::Point_3 center = c.center.empty() ? DO::volume_centroid(c3t3) : K::Point_3(c.center[0], c.center[1], c.center[2]);
    // The messages in the tool's words: its options rather than the library's functions.
    try {
      if(c.start == "ball") DO::star_shaped_to_unit_ball(c3t3, target_map, center);
      else DO::radial_map(c3t3, target_map, center);
    } catch(const DO::Center_outside_domain&) {
      throw DO::Invalid_input(c.center.empty() ? "the centroid of the volume is outside it (a volume in several parts, or one "
                                                 "curved around its centroid): give a --center inside"
                                               : "--center is not inside the volume");
    } catch(const DO::Domain_not_star_shaped&) {
      throw DO::Invalid_input("the volume is not star-shaped about the centre (a boundary facet faces it): give another "
                              "--center, or take --start radial with --boundary slide");
    }
    run.untangle = true;
  }
  if(carried) carried->start_energy = carried->energy(c, target_map);

  std::vector<unsigned char> listed;
  if(c.fix != "boundary" && c.fix != "none") listed = DO::IO::read_vertex_list(c.fix, source.points.size());
  auto fixed = boost::make_function_property_map<Tr::Vertex_handle>([&](Tr::Vertex_handle v) {
    return listed.empty() ? false : listed[index.at(v)] != 0;
  });
  const std::vector<double> weight_values = c.vertex_weights.empty() ? std::vector<double>(source.points.size(), 1.)
                                                                     : DO::IO::read_vertex_weights(c.vertex_weights, source.points.size());
  auto weights = boost::make_function_property_map<Tr::Vertex_handle>([&](Tr::Vertex_handle v) { return weight_values[index.at(v)]; });

  std::string measure_name;
  const DO::Mesh_quality before = c.ideal() ? DO::mesh_quality(c3t3, target_map) : DO::Mesh_quality();
  const DO::Result r = DO::with_measure(c.measure, [&](const auto& measure) {
    measure_name = measure.name();
    // optimize(np) under the command line's boundary: fixed, free, or sliding on the complex's own
    // boundary (the last two guarded), with the vertices `held` constrained.
    const auto constrained = [&](const auto& optimize, const auto& held) {
      if(c.slides()) {
        const auto surface = DO::Triangle_surface::from_complex_boundary(c3t3, target_map);
        return with_boundary_guard(c, [&](bool guard) {
          return optimize(DO::parameters::sliding_boundary(
            surface, DO::parameters::preserve_global_injectivity(guard, common_parameters(run, weights)).vertex_is_constrained_map(held)));
        });
      }
      return with_boundary_guard(c, [&](bool guard) {
        return c.fix == "boundary"
          ? optimize(common_parameters(run, weights))
          : optimize(DO::parameters::preserve_global_injectivity(guard, common_parameters(run, weights)).vertex_is_constrained_map(held));
      });
    };
    if(c.ideal()) {
      const auto improve = [&](const auto& np) { return DO::improve_mesh_quality(c3t3, target_map, measure, np); };
      if(!c.slides()) return constrained(improve, fixed);
      // Sliding on the mesh's own boundary, the vertices on its sharp edges fixed.
      const auto sharp = DO::sharp_boundary_vertices(c3t3, target_map);
      return constrained(improve, boost::make_function_property_map<Tr::Vertex_handle>(
                                    [&](Tr::Vertex_handle v) { return sharp.count(v) > 0 || get(fixed, v); }));
    }
    const auto minimize = [&](const auto& np) { return CGAL::minimize_distortion(c3t3, target_map, measure, np); };
    if(c.slides() && c.start == "ball")
      return minimize(
        DO::parameters::sliding_boundary(DO::Sphere_surface(), common_parameters(run, weights).vertex_is_constrained_map(fixed)));
    try {
      return constrained(minimize, fixed);
    } catch(const DO::Unmovable_inverted_cell& e) {
      // The tool's own start inverts cells that its fixed boundary keeps inverted (a radial map
      // of a non-convex volume): the remedy is the sliding boundary.
      if(!c.volume_mode() || c.slides()) throw;
      throw DO::Invalid_input(std::string(e.what()) + " (--boundary slide lets the boundary vertices move)");
    }
  });
  check_untangled(r);
  DO::IO::Tetrahedron_soup output = source;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Tr::Vertex_handle()) {
      const K::Point_3& p = storage.at(handles[i]);
      output.points[i] = {p.x(), p.y(), p.z()};
    } else {
      output.points[i] = target.points[i];
    }
  std::vector<double> values;   // each source cell's distortion, for pictures
  std::vector<bool> inverted;   // whether the map inverts or flattens each cell
  if(DO::IO::internal::extension(c.output) == "vtu" || (!c.svg.empty() && !c.ideal())) {
    std::unordered_map<Tr::Cell_handle, double> per_cell;
    std::unordered_map<Tr::Cell_handle, bool> inverted_cell;
    DO::with_measure(c.measure, [&](const auto& measure) {
      return CGAL::compute_distortion(c3t3, target_map, measure,
                                      DO::parameters::cell_distortion_map(boost::make_assoc_property_map(per_cell),
                                        DO::parameters::inverted_cell_map(boost::make_assoc_property_map(inverted_cell))));
    });
    for(const auto& t : source.cells) {
      Tr::Cell_handle cell;
      int i0, i1, i2, i3;
      c3t3.triangulation().is_cell(handles[t[0]], handles[t[1]], handles[t[2]], handles[t[3]], cell, i0, i1, i2, i3);
      values.push_back(per_cell.at(cell));
      inverted.push_back(inverted_cell.at(cell));
    }
  }
  if(DO::IO::internal::extension(c.output) == "vtu") {
    std::vector<std::array<double, 3>> displacement;
    for(std::size_t i = 0; i < output.points.size(); ++i)
      displacement.push_back({output.points[i][0] - source.points[i][0], output.points[i][1] - source.points[i][1],
                              output.points[i][2] - source.points[i][2]});
    DO::IO::write_VTU(c.output, output.points, output.cells, {{measure_name, values}}, {{"displacement", displacement}});
  } else {
    DO::IO::write_MEDIT_soup(c.output, output);
  }
  if(!c.mesh_output.empty()) DO::IO::write_MEDIT_soup(c.mesh_output, source);
  if(c.svg.empty())
    write_pictures(c, {}, {}, measure_name, measure_name, r);
  else if(c.ideal())   // the quality of the mesh before and after
    write_pictures(c, DO::IO::cross_section_panel("before, section z = middle", source.points, source.cells,
                                                  DO::radius_ratios(source.points, source.cells)),
                   DO::IO::cross_section_panel("after, section z = middle", output.points, output.cells,
                                               DO::radius_ratios(output.points, output.cells)), "radius ratio", measure_name, r);
  else {
    const std::vector<double> shown = red_where_inverted(values, inverted);
    write_pictures(c, DO::IO::cross_section_panel("source, section z = middle", source.points, source.cells, shown),
                   DO::IO::cross_section_panel("map, section z = middle", output.points, output.cells, shown),
                   measure_name, measure_name, r);
  }
  std::vector<std::pair<std::string, std::string>> fields;
  if(c.ideal()) fields = quality_fields(before, DO::mesh_quality(c3t3, target_map));
  if(c.volume_mode() || carried) {
    std::unordered_set<Tr::Vertex_handle> boundary;
    for(auto t = c3t3.cells_in_complex_begin(); t != c3t3.cells_in_complex_end(); ++t)
      for(int i = 0; i < 4; ++i)
        if(!c3t3.is_in_complex(t->neighbor(i)))
          for(int j = 1; j < 4; ++j) boundary.insert(t->vertex((i + j) % 4));
    fields = {{"tets", std::to_string(source.cells.size())}, {"boundary_vertices", std::to_string(boundary.size())},
              {"mesh_seconds", json_number(mesh_seconds)}};
  }
  if(carried) {
    carried->final_energy = carried->energy(c, target_map);
    carried->write(c.carry_output, target_map);
    fields.insert(fields.end(), {{"carried_vertices", std::to_string(carried->embedding.size())},
                                 {"carried_outside", std::to_string(carried->embedding.snapped_points.size())},
                                 {"start_energy_carried", json_number(carried->start_energy)},
                                 {"final_energy_carried", json_number(carried->final_energy)}});
  }
  report(c, source.cells.size(), source.points.size(), measure_name, r, fields);
  return 0;
}

// All outputs or none: each output gets a temporary file beside it before any input is read (so a
// folder that cannot be written fails first), the run writes there, and the files are renamed
// only when every one was written (after the outputs into devices, whose writes may still fail).
int run(const Command_line& c)
{
  const auto suffix = [](const std::string& path) {
    const std::string e = DO::IO::internal::extension(path);
    return e.empty() ? e : "." + e;
  };
  // The report last: it is renamed only once the map's files are.
  const std::vector<std::string Command_line::*> outputs = {&Command_line::output, &Command_line::mesh_output,
    &Command_line::carry_output, &Command_line::subdivided_source, &Command_line::flat_output, &Command_line::svg, &Command_line::energy_plot,
    &Command_line::report};
  std::vector<std::unique_ptr<DO::IO::Temporary_file>> files(outputs.size());
  Command_line staged = c;
  for(std::size_t i = 0; i < outputs.size(); ++i)
    if(!(c.*outputs[i]).empty()) {
      files[i] = std::make_unique<DO::IO::Temporary_file>(c.*outputs[i], suffix(c.*outputs[i]));
      staged.*outputs[i] = files[i]->path();
    }
  const bool tetrahedra = tetrahedral_file(c.source) || c.volume_mode();
  int status = 0;
  try {
    status = tetrahedra ? run_tetrahedra(staged) : run_triangles(staged);
  } catch(const DO::Invalid_input& e) {
    // A writer names the file it writes: the user's name, not the hidden temporary one.
    std::string message = e.what();
    for(std::size_t i = 0; i < outputs.size(); ++i)
      for(std::size_t at; files[i] && (at = message.find(files[i]->path())) != std::string::npos;)
        message.replace(at, files[i]->path().size(), c.*outputs[i]);
    // The library's word on a source cell: the source file's cell, when the file lists them.
    if((message.rfind("source face ", 0) == 0 || message.rfind("source cell ", 0) == 0) && !c.volume_mode())
      message = DO::IO::internal::printable(c.source) + ": " + message;
    throw DO::Invalid_input(message);
  }
  // Devices and pipes first: writing into them may fail (/dev/full), renaming a file hardly can.
  for(const bool streamed : {true, false})
    for(std::size_t i = 0; i < outputs.size(); ++i)
      if(files[i] && files[i]->is_streamed() == streamed) files[i]->rename_to(c.*outputs[i]);
  return status;
}

} // namespace

int main(int argc, char** argv)
{
  DO::IO::remove_temporary_files_on_signals();
  try {
    return run(parse(argc, argv));
  } catch(const Usage_error& e) {
    if(!*e.what()) {   // --help
      std::cout << usage();
      return 0;
    }
    std::cerr << "distortion_optimizer: " << e.what() << " (run with --help for the usage)\n";
    return 2;
  } catch(const std::bad_alloc&) {
    std::cerr << "distortion_optimizer: out of memory (a mesh too large for this machine, or --subdivide with too many "
                 "levels: each multiplies the cells by 4); nothing written\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "distortion_optimizer: " << e.what() << "\n";
    return 1;
  }
}
