// distortion_optimizer: the command-line tool of the package.
//
//   distortion_optimizer --source S --target T --output O [--measure NAME] [--fix boundary|none|FILE]
//                        [--iterations N] [--threshold EPS] [--solver gd|bfgs] [--threads N] [--report R.json]
//                        [--schedule alternating|local|global] [--untangle]
//
// S, T, O: OFF or OBJ triangle meshes, or Medit .mesh tetrahedral meshes, with the same vertices
// and cells in the same order; a planar target has z = 0. Without --target, a disk-topology
// triangle source gets a Tutte start (circle border). O may also be .vtu: the optimized map with
// each cell's distortion, for ParaView.
// Energies are volume-weighted means sum vol(c) D(J_c) / sum vol(c).
// Exit status: 0 on success, 1 for bad input (one-line message), 2 for a bad command line.

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>
#include <CGAL/Distortion_optimization/IO/vtu.h>
#include <CGAL/Distortion_optimization/IO/write_file_atomically.h>
#include <CGAL/Distortion_optimization/c3t3_from_tetrahedra.h>
#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <unordered_map>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>

namespace DO = CGAL::Distortion_optimization;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Vertex = Mesh::Vertex_index;
using Tr = CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<K>>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;

namespace {

// The usage text; the measures come from the package's registry of built-in measures.
std::string usage()
{
  const auto& known = DO::measure_names();
  std::vector<std::string> words(known.begin(), known.end());
  words.front() += " (default)";
  words.push_back("or a product such as " + known[0] + "*" + known[3]);
  std::string names;
  std::size_t column = 15;   // where the text of NAME starts
  for(const std::string& word : words) {
    if(!names.empty()) {
      const bool wrap = column + word.size() + 2 > 92;
      names += wrap ? ",\n               " : ", ";
      column = wrap ? 15 : column + 2;
    }
    names += word;
    column += word.size();
  }
  return
  "usage: distortion_optimizer --source S [--target T] --output O [--measure NAME]\n"
  "         [--fix boundary|none|FILE] [--iterations N] [--threshold EPS] [--solver gd|bfgs]\n"
  "         [--threads N] [--report R.json] [--schedule alternating|local|global] [--untangle]\n"
  "  S, T, O      OFF or OBJ triangle meshes, or Medit .mesh tetrahedral meshes, with the same\n"
  "               vertices and cells in the same order; a planar target has z = 0; without\n"
  "               --target a triangulated disk gets a Tutte start; O may be .vtu (the map with\n"
  "               each cell's distortion, for ParaView)\n"
  "  NAME         " + names + "\n"
  "  --fix        boundary (default): border vertices keep their target; none; or a file with\n"
  "               one 0-based vertex index per line. With free border vertices the boundary is\n"
  "               kept from crossing itself (global injectivity)\n"
  "  --iterations largest number of iterations, each a local sweep and a global step (default 100)\n"
  "  --threshold  stop when an iteration lowers the energy by less than this fraction of the\n"
  "               energy above the measure's minimum (default 1e-4)\n"
  "  --solver     gd (default, gradient descent) or bfgs, for each vertex's local problem\n"
  "  --threads    number of threads (default 1); the output is the same for every run with\n"
  "               the same number\n"
  "  --report     also write the results as JSON\n"
  "  --untangle   when the start has inverted or flat cells, untangle it first (then optimize);\n"
  "               without it such a start is refused under a measure infinite there\n"
  "  --schedule   alternating (default: a local sweep then a global step per iteration, after a\n"
  "               harmonic start), local (the paper's sweeps only) or global\n";
}

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Command_line
{
  std::string source, target, output, measure = DO::measure_names()[0], fix = "boundary", solver = "gd", report,
    schedule = "alternating";
  std::size_t iterations = 100, threads = 1;
  double threshold = 1e-4;
  bool untangle = false;
};

template <class T>
T parse_number(const std::string& option, const std::string& text)
{
  std::istringstream in(text);
  T value;
  if(!(in >> value) || !in.eof()) throw Usage_error(option + " expects a number, not '" + text + "'");
  // An unsigned read of "-5" wraps around instead of failing.
  if(text.find('-') != std::string::npos && !(value < 0)) throw Usage_error(option + " must not be negative");
  return value;
}

// What names one file: its device and inode when it exists, else its folder's and its own name,
// so that links and spellings such as ./o.off of one file compare equal.
struct File_identity
{
  dev_t device = 0;
  ino_t inode = 0;
  std::string name;
  bool operator==(const File_identity& o) const { return device == o.device && inode == o.inode && name == o.name; }
};

File_identity identify(const std::string& path)
{
  struct stat s;
  if(::stat(path.c_str(), &s) == 0) return {s.st_dev, s.st_ino, ""};
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  if(::stat(folder.c_str(), &s) != 0) return {0, 0, path};   // the write will fail with its message
  return {s.st_dev, s.st_ino, path.substr(slash == std::string::npos ? 0 : slash + 1)};
}

// Inputs must be files (a folder reads as an empty file), and no output may name an input or
// another output: writing over the start map in place is refused too (write elsewhere, then move).
void check_files(const Command_line& c)
{
  std::vector<std::pair<std::string, std::string>> inputs = {{"--source", c.source}}, outputs = {{"--output", c.output}};
  if(!c.target.empty()) inputs.emplace_back("--target", c.target);
  if(c.fix != "boundary" && c.fix != "none") inputs.emplace_back("--fix", c.fix);
  if(!c.report.empty()) outputs.emplace_back("--report", c.report);
  for(const auto& [option, path] : inputs) {
    struct stat s;
    if(::stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode)) throw Usage_error(option + " " + path + " is a folder, not a file");
  }
  for(std::size_t i = 0; i < outputs.size(); ++i) {
    const auto& [option, path] = outputs[i];
    struct stat s;
    if(::stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode)) throw Usage_error(option + " " + path + " is a folder, not a file");
    const File_identity id = identify(path);
    for(const auto& [other, other_path] : inputs)
      if(identify(other_path) == id) throw Usage_error(option + " " + path + " is the file given as " + other + ": it would be overwritten");
    for(std::size_t j = 0; j < i; ++j)
      if(identify(outputs[j].second) == id) throw Usage_error(option + " and " + outputs[j].first + " name the same file");
  }
}

Command_line parse(int argc, char** argv)
{
  Command_line c;
  std::map<std::string, std::string> seen;
  for(int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if(option == "--help" || option == "-h") throw Usage_error("");
    if(option == "--untangle") {   // the one option without a value
      if(c.untangle) throw Usage_error(option + " is given twice");
      c.untangle = true;
      continue;
    }
    if(i + 1 >= argc) throw Usage_error(option + " needs a value");
    const std::string value = argv[++i];
    if(seen.count(option)) throw Usage_error(option + " is given twice");
    seen[option] = value;
    if(option == "--source") c.source = value;
    else if(option == "--target") c.target = value;
    else if(option == "--output") c.output = value;
    else if(option == "--measure") c.measure = value;
    else if(option == "--fix") c.fix = value;
    else if(option == "--solver") c.solver = value;
    else if(option == "--report") c.report = value;
    else if(option == "--schedule") c.schedule = value;
    else if(option == "--iterations") c.iterations = parse_number<std::size_t>(option, value);
    else if(option == "--threads") c.threads = parse_number<std::size_t>(option, value);
    else if(option == "--threshold") c.threshold = parse_number<double>(option, value);
    else throw Usage_error("unknown option " + option);
  }
  if(c.source.empty()) throw Usage_error("--source is required");
  if(c.output.empty()) throw Usage_error("--output is required");
  if(c.solver != "gd" && c.solver != "bfgs") throw Usage_error("--solver is gd or bfgs, not '" + c.solver + "'");
  if(c.threads == 0) throw Usage_error("--threads must be at least 1");
  if(c.schedule != "alternating" && c.schedule != "local" && c.schedule != "global")
    throw Usage_error("--schedule is alternating, local or global, not '" + c.schedule + "'");
  if(!(c.threshold >= 0)) throw Usage_error("--threshold must be a non-negative number");
  const std::string in = DO::IO::internal::extension(c.source), out = DO::IO::internal::extension(c.output);
  if(in == "mesh" ? (out != "mesh" && out != "vtu") : (out != "off" && out != "obj" && out != "vtu"))
    throw Usage_error(in == "mesh" ? "--output must end in .mesh or .vtu for a tetrahedral source"
                                   : "--output must end in .off, .obj or .vtu");
  if(in == "mesh" && c.target.empty())
    throw Usage_error("a .mesh source needs --target (the start map)");
  if(!c.target.empty() && (DO::IO::internal::extension(c.target) == "mesh") != (in == "mesh"))
    throw Usage_error("--source and --target must both be triangle meshes or both .mesh files");
  try {
    DO::with_measure(c.measure, [](const auto&) { return 0; });
  } catch(const DO::Invalid_input& e) {
    throw Usage_error(std::string("--measure: ") + e.what());
  }
  check_files(c);
  return c;
}

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

bool is_disk(const Mesh& mesh)
{
  std::vector<Mesh::Halfedge_index> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  const long long euler = static_cast<long long>(mesh.number_of_vertices()) - static_cast<long long>(mesh.number_of_edges()) +
                          static_cast<long long>(mesh.number_of_faces());
  return cycles.size() == 1 && euler == 1;
}

std::vector<unsigned char> read_fixed_vertices(const std::string& path, std::size_t count)
{
  std::ifstream in(path);
  if(!in) throw DO::Invalid_input(path + ": cannot open the file of fixed vertices");
  std::vector<unsigned char> fixed(count, 0);
  std::string line;
  // Lines are bounded, so that an endless one (a link to /dev/zero) costs no memory.
  namespace IOI = DO::IO::internal;
  const auto next_line = [&](std::size_t number) {
    const IOI::Line_status status = IOI::read_bounded_line(in, line);
    if(status == IOI::Line_status::too_long)
      throw DO::Invalid_input(path + ":" + std::to_string(number) + ": line longer than " +
                              std::to_string(IOI::max_line_bytes) + " bytes");
    return status == IOI::Line_status::line;
  };
  for(std::size_t number = 1; next_line(number); ++number) {
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    long long index;
    if(!(words >> index)) {
      if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
      throw DO::Invalid_input(path + ":" + std::to_string(number) + ": not a vertex index");
    }
    std::string rest;
    if(words >> rest) throw DO::Invalid_input(path + ":" + std::to_string(number) + ": one vertex index per line");
    if(index < 0 || static_cast<std::size_t>(index) >= count)
      throw DO::Invalid_input(path + ":" + std::to_string(number) + ": vertex index " + std::to_string(index) +
                              " out of range (the mesh has " + std::to_string(count) + " vertices)");
    fixed[static_cast<std::size_t>(index)] = 1;
  }
  return fixed;
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

// Free-boundary mode (some border vertex free): the run keeps the boundary from crossing itself
// (global injectivity). A start whose boundary already crosses itself cannot be guarded: then the
// run goes on without the guard, with a warning.
template <class Run>
DO::Result with_boundary_guard(const Command_line& c, const Run& run)
{
  if(c.fix == "boundary") return run(false);
  try {
    return run(true);
  } catch(const DO::Crossing_start_boundary& guarded) {
    DO::Result r = run(false);   // throws again if the input was bad for another reason
    std::cerr << "distortion_optimizer: warning: " << guarded.what() << "; optimized without the guard\n";
    return r;
  }
}

// The options both kinds of mesh share.
auto common_parameters(const Command_line& c)
{
  const auto solver = c.solver == "bfgs" ? DO::Local_solver::BFGS : DO::Local_solver::GRADIENT_DESCENT;
  const auto schedule = c.schedule == "local" ? DO::Schedule::LOCAL
                      : c.schedule == "global" ? DO::Schedule::GLOBAL : DO::Schedule::ALTERNATING;
  return DO::parameters::number_of_threads(static_cast<int>(std::min<std::size_t>(c.threads, 256)),
    DO::parameters::schedule(schedule, DO::parameters::local_solver(solver, DO::parameters::untangle_first(c.untangle,
      DO::parameters::convergence_threshold(c.threshold)))))
    .number_of_iterations(c.iterations);
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
            const DO::Result& r)
{
  std::ostringstream json;
  json << "{\n  \"cells\": " << cells << ",\n  \"vertices\": " << vertices
       << ",\n  \"measure\": \"" << measure_name << "\",\n  \"initial_energy\": " << json_number(r.initial_energy)
       << ",\n  \"final_energy\": " << json_number(r.final_energy) << ",\n  \"sweeps\": " << r.iterations
       << ",\n  \"seconds\": " << json_number(r.seconds) << ",\n  \"inverted_cells\": " << r.inverted_cells
       << ",\n  \"converged\": " << (r.converged ? "true" : "false")
       << ",\n  \"inverted_start_cells\": " << r.inverted_start_cells << ",\n  \"untangle_iterations\": "
       << r.untangle_iterations << ",\n  \"untangle_seconds\": " << json_number(r.untangle_seconds)
       << ",\n  \"energy_per_sweep\": [";
  for(std::size_t i = 0; i < r.energy_per_iteration.size(); ++i)
    json << (i ? ", " : "") << json_number(r.energy_per_iteration[i]);
  json << "]\n}\n";
  if(!c.report.empty())
    DO::IO::write_file_atomically(c.report, [&](std::ostream& out) { out << json.str(); });
  std::printf("cells           %zu\nvertices        %zu\nmeasure         %s\ninitial_energy  %.12g\n"
              "final_energy    %.12g\nsweeps          %zu\nseconds         %.3f\ninverted_cells  %zu\n",
              cells, vertices, measure_name.c_str(), r.initial_energy, r.final_energy, r.iterations, r.seconds,
              r.inverted_cells);
  if(c.untangle)
    std::printf("inverted_start_cells  %zu\nuntangle_iterations   %zu\nuntangle_seconds      %.3f\n", r.inverted_start_cells,
                r.untangle_iterations, r.untangle_seconds);
}

int run_triangles(const Command_line& c)
{
  const DO::IO::Triangle_soup source = DO::IO::read_triangle_soup(c.source);
  Mesh mesh = to_mesh(source, c.source);
  bool planar = true;
  for(const auto& p : source.points) planar = planar && p[2] == 0;

  auto uv = mesh.add_property_map<Vertex, K::Point_2>("v:target").first;
  if(!c.target.empty()) {
    const DO::IO::Triangle_soup target = DO::IO::read_triangle_soup(c.target);
    check_same_cells(c.target, source.points, source.cells, target.points, target.cells, "face");
    for(std::size_t i = 0; i < target.points.size(); ++i) {
      if(target.points[i][2] != 0)
        throw DO::Invalid_input(c.target + ": vertex " + std::to_string(i) + " has z != 0 (the target must be planar)");
      uv[Vertex(i)] = K::Point_2(target.points[i][0], target.points[i][1]);
    }
  } else {
    if(!is_disk(mesh))
      throw DO::Invalid_input(c.source + ": without --target the source must be a topological disk (one border, no handle)");
    DO::initial_parameterization(mesh, uv);
    // The tool's own start has the source's orientation: the Tutte map is counter-clockwise, so a
    // planar source listed clockwise gets its mirror image. (A surface is compared in each face's
    // own frame, where any consistent orientation is positive.)
    double signed_area = 0;
    for(const auto& t : source.cells) {
      const auto &a = source.points[t[0]], &b = source.points[t[1]], &d = source.points[t[2]];
      signed_area += (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    }
    if(planar && signed_area < 0)
      for(Vertex v : mesh.vertices()) uv[v] = K::Point_2(uv[v].x(), -uv[v].y());
  }

  auto fixed = mesh.add_property_map<Vertex, bool>("v:fixed", false).first;
  if(c.fix == "boundary") {
    for(Vertex v : mesh.vertices()) fixed[v] = mesh.is_border(v);
  } else if(c.fix != "none") {
    const auto list = read_fixed_vertices(c.fix, mesh.number_of_vertices());
    for(Vertex v : mesh.vertices()) fixed[v] = list[std::size_t(v)] != 0;
  }

  auto source_2 = mesh.add_property_map<Vertex, K::Point_2>("v:source_2").first;
  for(Vertex v : mesh.vertices()) source_2[v] = K::Point_2(mesh.point(v).x(), mesh.point(v).y());

  std::string measure_name;
  const DO::Result r = DO::with_measure(c.measure, [&](const auto& measure) {
    measure_name = measure.name();
    return with_boundary_guard(c, [&](bool guard) {
      auto np = DO::parameters::preserve_global_injectivity(guard, common_parameters(c)).vertex_is_constrained_map(fixed);
      // A planar source is compared in its own plane (so its orientation counts), a surface in
      // each triangle's frame.
      return planar ? CGAL::minimize_distortion(mesh, uv, measure, np.vertex_point_map(source_2))
                    : CGAL::minimize_distortion(mesh, uv, measure, np);
    });
  });

  DO::IO::Triangle_soup output;
  output.cells = source.cells;
  for(Vertex v : mesh.vertices()) output.points.push_back({uv[v].x(), uv[v].y(), 0.});
  if(DO::IO::internal::extension(c.output) == "vtu") {
    auto per_face = mesh.add_property_map<Mesh::Face_index, double>("f:distortion").first;
    DO::with_measure(c.measure, [&](const auto& measure) {
      return planar ? CGAL::compute_distortion(mesh, uv, measure,
                        DO::parameters::cell_distortion_map(per_face, CGAL::parameters::vertex_point_map(source_2)))
                    : CGAL::compute_distortion(mesh, uv, measure, DO::parameters::cell_distortion_map(per_face));
    });
    std::vector<double> values;
    for(auto f : mesh.faces()) values.push_back(per_face[f]);
    DO::IO::write_VTU(c.output, output.points, output.cells, {{measure_name, values}});
  } else {
    DO::IO::write_triangle_soup(c.output, output);
  }
  report(c, mesh.number_of_faces(), mesh.number_of_vertices(), measure_name, r);
  return 0;
}

int run_tetrahedra(const Command_line& c)
{
  const DO::IO::Tetrahedron_soup source = DO::IO::read_tetrahedron_soup(c.source);
  DO::IO::Tetrahedron_soup target = source;
  if(!c.target.empty()) {
    target = DO::IO::read_tetrahedron_soup(c.target);
    check_same_cells(c.target, source.points, source.cells, target.points, target.cells, "tetrahedron");
  }
  C3t3 c3t3;
  const auto handles = DO::c3t3_from_tetrahedra(source.points, source.cells, c3t3);
  std::unordered_map<Tr::Vertex_handle, K::Point_3> storage;
  std::unordered_map<Tr::Vertex_handle, std::size_t> index;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Tr::Vertex_handle()) {
      storage[handles[i]] = K::Point_3(target.points[i][0], target.points[i][1], target.points[i][2]);
      index[handles[i]] = i;
    }
  boost::associative_property_map<decltype(storage)> target_map(storage);

  std::vector<unsigned char> listed;
  if(c.fix != "boundary" && c.fix != "none") listed = read_fixed_vertices(c.fix, source.points.size());
  auto fixed = boost::make_function_property_map<Tr::Vertex_handle>([&](Tr::Vertex_handle v) {
    return c.fix == "none" ? false : listed[index.at(v)] != 0;
  });

  std::string measure_name;
  const DO::Result r = DO::with_measure(c.measure, [&](const auto& measure) {
    measure_name = measure.name();
    return with_boundary_guard(c, [&](bool guard) {
      return c.fix == "boundary"
        ? CGAL::minimize_distortion(c3t3, target_map, measure, common_parameters(c))
        : CGAL::minimize_distortion(c3t3, target_map, measure,
            DO::parameters::preserve_global_injectivity(guard, common_parameters(c)).vertex_is_constrained_map(fixed));
    });
  });

  DO::IO::Tetrahedron_soup output = source;
  for(std::size_t i = 0; i < handles.size(); ++i)
    if(handles[i] != Tr::Vertex_handle()) {
      const K::Point_3& p = storage.at(handles[i]);
      output.points[i] = {p.x(), p.y(), p.z()};
    } else {
      output.points[i] = target.points[i];
    }
  if(DO::IO::internal::extension(c.output) == "vtu") {
    std::unordered_map<Tr::Cell_handle, double> per_cell;
    DO::with_measure(c.measure, [&](const auto& measure) {
      return CGAL::compute_distortion(c3t3, target_map, measure,
                                      DO::parameters::cell_distortion_map(boost::associative_property_map<decltype(per_cell)>(per_cell)));
    });
    std::vector<double> values;
    for(const auto& t : source.cells) {
      Tr::Cell_handle cell;
      int i0, i1, i2, i3;
      c3t3.triangulation().is_cell(handles[t[0]], handles[t[1]], handles[t[2]], handles[t[3]], cell, i0, i1, i2, i3);
      values.push_back(per_cell.at(cell));
    }
    DO::IO::write_VTU(c.output, output.points, output.cells, {{measure_name, values}});
  } else {
    DO::IO::write_MEDIT(c.output, output);
  }
  report(c, source.cells.size(), source.points.size(), measure_name, r);
  return 0;
}

// All outputs or none: each output gets a temporary file beside it before any input is read (so a
// folder that cannot be written fails first), the run writes there, and the files are renamed
// only when every one was written.
int run(const Command_line& c)
{
  const auto suffix = [](const std::string& path) {
    const std::string e = DO::IO::internal::extension(path);
    return e.empty() ? e : "." + e;
  };
  DO::IO::Temporary_file output(c.output, suffix(c.output));
  std::unique_ptr<DO::IO::Temporary_file> report;
  if(!c.report.empty()) report = std::make_unique<DO::IO::Temporary_file>(c.report, suffix(c.report));
  Command_line staged = c;
  staged.output = output.path();
  if(report) staged.report = report->path();
  const int status = DO::IO::internal::extension(c.source) == "mesh" ? run_tetrahedra(staged) : run_triangles(staged);
  output.rename_to(c.output);
  if(report) report->rename_to(c.report);
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
  } catch(const std::exception& e) {
    std::cerr << "distortion_optimizer: " << e.what() << "\n";
    return 1;
  }
}
