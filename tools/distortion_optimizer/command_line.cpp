// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of distortion_optimizer (command_line.h): usage, parser and checks.

#include "command_line.h"

#include <CGAL/Distortion_optimization/IO/file_names.h>
#include <CGAL/Distortion_optimization/IO/tetgen.h>
#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <sys/stat.h>

namespace distortion_optimizer {

namespace DO = CGAL::Distortion_optimization;

std::string default_measure_name() { return DO::measure_names()[0]; }

DO::Any_measure measure_of(const Command_line& c) { return DO::measure_from_name(c.measure); }

std::string extension(const std::string& path) { return DO::IO::file_extension(path); }

std::string printable(const std::string& text) { return DO::IO::printable(text); }

std::string shown_number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The usage text; the measures come from the package's registry of built-in measures.
std::string usage()
{
  const auto& known = DO::measure_names();
  std::vector<std::string> words(known.begin(), known.end());
  words.front() += " (default)";
  words.push_back("a product such as " + known[0] + "*" + known[3]);
  words.push_back("or a weighted sum such as 0.5*" + known[0] + "+" + known[3]);
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
  "         [--quiet|--verbose] [--time-limit SECONDS] [--flat-output F]\n"
  "         [--svg P.svg [--svg-both]] [--energy-plot E.svg] [--vertex-weights FILE]\n"
  "         [--cell-weighting average|volume|uniform] [--order sorted|greedy]\n"
  "         [--parallel-sweep sets|partition] [--harmonic-start on|off]\n"
  "         [--global-step newton|laplacian]\n"
  "       distortion_optimizer --source CLOSED --start ball|radial --output O.mesh\n"
  "         [--mesh-output M.mesh] [--cell-size H] [--center X,Y,Z] [--boundary slide|fixed]\n"
  "         [--carry INNER --carry-output C [--snap]] [options above]\n"
  "       distortion_optimizer --source S --reference ideal --output O [--boundary fixed|slide]\n"
  "         [options above]\n"
  "       distortion_optimizer --source SURFACE --output O.obj [--max-distortion D]\n"
  "         [--seams FILE] [options above]\n"
  "       distortion_optimizer --source S [--target T] --output O --subdivide N\n"
  "         --subdivided-source S2 [--scheme linear|loop] [options above]\n"
  "  S, T, O      triangle meshes (OFF, OBJ; S and T also PLY, STL or GOCAD .ts, read by CGAL)\n"
  "               or tetrahedral meshes (Medit .mesh; S and T also TetGen .ele with its .node),\n"
  "               with the same vertices and cells in the same order; a planar target has z = 0;\n"
  "               without --target a triangulated disk gets a Tutte start; a closed surface,\n"
  "               one with handles, and (with O .obj) one with holes or in pieces get an atlas:\n"
  "               cut along seams into charts of genus 0, flattened, packed into the unit\n"
  "               square (O .obj, one vt per UV corner; the report gives its charts, seams and\n"
  "               packing); a planar source with holes or in pieces, or a surface with them and\n"
  "               O not .obj, --flat-output or an option of one map (--fix boundary or FILE,\n"
  "               --subdivide, --vertex-weights, --untangle, --svg-both), gets one Tutte start\n"
  "               (its holes free, only its longest border fixed; pieces side by side); O may\n"
  "               be .vtu (the map with each cell's distortion and each vertex's displacement\n"
  "               from the source, for ParaView: warp by -1 shows a surface). A surface's map is\n"
  "               a parametrization: O.obj gets the surface with its UVs (vt, f v/vt), T.obj may\n"
  "               give them so\n"
  "  --flat-output  a triangle map's result as a flat mesh (u, v, 0) too (.off or .obj)\n"
  "  --svg        a picture of the result, each cell coloured by its distortion (viridis; red:\n"
  "               inverted): a triangle map's target, or the section of a tetrahedral map's\n"
  "               target by the plane z = middle; --svg-both draws the source beside it; with\n"
  "               --reference ideal each cell's radius ratio, after (and before)\n"
  "  --energy-plot  the energy of the start and after each iteration, as an SVG plot\n"
  "  --start      volume mode: the inside of CLOSED (a closed OFF/OBJ surface, meshed with\n"
  "               CGAL Mesh_3, or a .mesh) is mapped onto the unit ball (ball: star-shaped\n"
  "               about the centre) or by x |x| about the centre (radial), then optimized; a\n"
  "               start with flat cells is untangled first\n"
  "  --mesh-output  the tetrahedra of the meshed source (.mesh): with O, a source/target pair\n"
  "  --cell-size  largest tetrahedron circumradius for the meshing (default: from the volume)\n"
  "  --center     the centre of the start map (default: the centroid of the volume)\n"
  "  --boundary   slide (default with ball): boundary vertices move on the start's boundary\n"
  "               surface (the unit sphere for ball); fixed (default with radial); --fix none\n"
  "               or FILE frees the boundary instead (refused with an explicit --boundary fixed)\n"
  "  --reference  ideal: improve the shapes of S's own cells (a planar triangle mesh, z = 0,\n"
  "               or a .mesh), measured against regular triangles or tetrahedra; O (.off, .obj\n"
  "               or .mesh) gets S with the moved vertices; --boundary fixed (default) or slide\n"
  "               (tetrahedra: on S's boundary, sharp edges fixed); the report adds quality\n"
  "               before and after; NAME is a measure infinite on flat cells (not arap, dirichlet)\n"
  "  --subdivide  after optimizing a triangle map, subdivide its source and its result N times\n"
  "               (each triangle into four; --scheme linear, the default, keeps every energy,\n"
  "               loop smooths both): O gets the refined map, S2 (OFF/OBJ) the refined source\n"
  "  --carry      a triangle surface inside the source volume, carried through the map to\n"
  "               --carry-output (OFF/OBJ, same vertices and faces); --snap moves its vertices\n"
  "               outside the volume onto the boundary instead of refusing them\n"
  "  NAME         " + names + "\n"
  "  --fix        boundary (default): border vertices keep their target; none; or a file with\n"
  "               one 0-based vertex index per line. With free border vertices the boundary is\n"
  "               kept from crossing itself and the mesh's pieces from overlapping (global\n"
  "               injectivity), unless the start's already does: then a warning, and\n"
  "               cells are kept from inverting only\n"
  "  --iterations largest number of iterations, each a local sweep and a global step (default 100);\n"
  "               0: the start is only evaluated, not moved (untangled with --untangle)\n"
  "  --threshold  stop when an iteration lowers the energy by less than this fraction of the\n"
  "               energy above its value on rigid maps (above 0 with arap or dirichlet in the\n"
  "               measure, which are finite on flat cells) (default 1e-4); the first iteration's\n"
  "               from the energy after the harmonic start (the report's harmonic_start_energy)\n"
  "  --solver     gd (default, gradient descent) or bfgs, for each vertex's local problem\n"
  "  --vertex-weights  a file of one positive weight per line, per vertex in the source's order\n"
  "               (the paper's omega(v), eq. 23; default 1)\n"
  "  --cell-weighting  the cell weights w(c, v) of eq. 23: average (default, volume / vertices),\n"
  "               volume or uniform\n"
  "  --order      sorted (default: the vertices sorted by distortion once per sweep) or greedy\n"
  "               (the paper's Algorithm 2: the most distorted first, one thread)\n"
  "  --parallel-sweep  with threads: sets (default, independent sets of vertices) or partition\n"
  "               (the paper's Algorithm 3)\n"
  "  --global-step  newton (projected Newton steps; by default with symmetric_dirichlet,\n"
  "               mips, arap, dirichlet and products and sums of measures, and on tetrahedra\n"
  "               with no vertex fixed (--fix none, or --boundary slide) with conformal,\n"
  "               condition and isometric through mips or symmetric_dirichlet; given, also\n"
  "               conformal, condition, isometric and volume by their own Hessians) or\n"
  "               laplacian (the reweighted Laplacian: the default for the other cases)\n"
  "  --harmonic-start  on (default, except with --schedule local) or off: start from the\n"
  "               harmonic map of the fixed vertices where it is valid and better; with\n"
  "               --untangle, untangle from that of a fixed or sliding boundary where it\n"
  "               folds less than the start\n"
  "  --threads    number of threads (default 1; the sparse solver's BLAS keeps one); the\n"
  "               output is the same for every run with the same number (and no\n"
  "               --time-limit, which stops by the clock)\n"
  "  --report     also write the results as JSON\n"
  "  --untangle   when the start has inverted or flat cells, untangle it first (then optimize);\n"
  "               without it such a start is refused under a measure infinite there\n"
  "  --schedule   alternating (a local sweep then a global step per iteration, after a harmonic\n"
  "               start: the default with laplacian global steps, and with a smooth model's\n"
  "               newton ones when the boundary slides), global (a global step per iteration;\n"
  "               the default with the other newton ones, which adds a local sweep to an\n"
  "               iteration that gains too little or is cut short) or local (the paper's sweeps)\n"
  "  --verbose    a progress line per iteration on stderr (iteration, energy, relative decrease,\n"
  "               seconds; with --untangle the untangling's rounds first, their energy the\n"
  "               barrier's); the default when stderr is a terminal; --quiet: none\n"
  "  --seams      a file of edges to cut an atlas along, one per line as two 0-based vertex\n"
  "               indices: any source then gets an atlas; more seams are added where needed\n"
  "  --max-distortion  an atlas's bound on each piece's mean distortion: a piece above it is cut\n"
  "               into 2, 3, 4, 6, 9, ... charts of nearly constant normal until it holds\n"
  "  --time-limit stop after the first iteration that ends SECONDS or more after the optimization\n"
  "               started, and write that map (the report says stopped_by_time_limit); a limit\n"
  "               reached while untangling, cells still inverted, fails (status 1); in the volume\n"
  "               mode, Mesh_3 stops at SECONDS too (within a tenth more, 2 s at least), which\n"
  "               fails (status 1)\n"
  "exit status: 0 done; 1 bad input or a failed run, nothing written; 2 a usage error\n";
}

bool tetrahedral_file(const std::string& path)
{
  const std::string e = extension(path);
  return e == "mesh" || e == "ele" || e == "node";
}

namespace {

// The whole text as a number: no spaces around it; one that T cannot hold ("99999999999999999999",
// "1e309") is out of range rather than not a number.
template <class T>
T parse_number(const std::string& option, const std::string& text)
{
  std::istringstream in(text);
  T value;
  const bool spaced = text.find_first_of(" \t\n\r\f\v") != std::string::npos;
  if(spaced || !(in >> value) || !in.eof()) {
    errno = 0;
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    const bool whole = !spaced && !text.empty() && end == text.c_str() + text.size();
    const bool too_large = std::is_integral<T>::value ? whole && text.find_first_not_of("+0123456789") == std::string::npos
                                                      : whole && errno == ERANGE;
    if(too_large) throw Usage_error(option + " '" + text + "' is out of range");
    throw Usage_error(option + " expects a number, not '" + text + "'");
  }
  // An unsigned read of "-5" wraps around instead of failing; "1e-5" is positive.
  if(value < 0 || (std::is_unsigned<T>::value && text[0] == '-')) throw Usage_error(option + " must not be negative");
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

// "X,Y,Z": three finite numbers.
std::vector<double> parse_point(const std::string& option, const std::string& text)
{
  std::vector<double> x;
  std::string rest = text;
  for(int k = 0; k < 3; ++k) {
    const std::size_t comma = rest.find(',');
    if((k < 2) == (comma == std::string::npos)) throw Usage_error(option + " expects X,Y,Z, not '" + text + "'");
    std::istringstream in(rest.substr(0, comma));
    double value;
    if(!(in >> value) || !in.eof() || !std::isfinite(value)) throw Usage_error(option + " expects X,Y,Z, not '" + text + "'");
    x.push_back(value);
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
  }
  return x;
}

// Inputs must be regular files (a folder reads as an empty file, /dev/zero never ends), and no
// output may name an input or another output: writing over the start map in place is refused too
// (write elsewhere, then move).
void check_files(const Command_line& c)
{
  std::vector<std::pair<std::string, std::string>> inputs = {{"--source", c.source}}, outputs = {{"--output", c.output}};
  if(!c.target.empty()) inputs.emplace_back("--target", c.target);
  if(c.fix != "boundary" && c.fix != "none") inputs.emplace_back("--fix", c.fix);
  if(!c.vertex_weights.empty()) inputs.emplace_back("--vertex-weights", c.vertex_weights);
  if(!c.seams.empty()) inputs.emplace_back("--seams", c.seams);
  if(!c.carry.empty()) inputs.emplace_back("--carry", c.carry);
  if(!c.report.empty()) outputs.emplace_back("--report", c.report);
  if(!c.mesh_output.empty()) outputs.emplace_back("--mesh-output", c.mesh_output);
  if(!c.carry_output.empty()) outputs.emplace_back("--carry-output", c.carry_output);
  if(!c.subdivided_source.empty()) outputs.emplace_back("--subdivided-source", c.subdivided_source);
  if(!c.flat_output.empty()) outputs.emplace_back("--flat-output", c.flat_output);
  if(!c.svg.empty()) outputs.emplace_back("--svg", c.svg);
  if(!c.energy_plot.empty()) outputs.emplace_back("--energy-plot", c.energy_plot);
  // A TetGen mesh is read from both files of its pair, whichever was named.
  for(const std::string option : {"--source", "--target"}) {
    for(const std::string& file : DO::IO::TetGen_files(option == "--source" ? c.source : c.target))
      if(!file.empty()) inputs.emplace_back(option + " (its TetGen pair)", file);
  }
  const auto shown = [](const std::string& path) { return printable(path); };
  for(const auto& [option, path] : inputs) {
    struct stat s;
    if(::stat(path.c_str(), &s) != 0) continue;   // the reader names it
    if(S_ISDIR(s.st_mode)) throw Usage_error(option + " " + shown(path) + " is a folder, not a file");
    // A device or a pipe may never end (/dev/zero) or be read once only: the readers read files.
    if(!S_ISREG(s.st_mode))
      throw Usage_error(option + " " + shown(path) + " is not a regular file (a device, a pipe or a socket)");
  }
  for(std::size_t i = 0; i < outputs.size(); ++i) {
    const auto& [option, path] = outputs[i];
    struct stat s;
    if(::stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode)) throw Usage_error(option + " " + shown(path) + " is a folder, not a file");
    const File_identity id = identify(path);
    for(const auto& [other, other_path] : inputs)
      if(identify(other_path) == id) throw Usage_error(option + " " + shown(path) + " is the file given as " + other + ": it would be overwritten");
    for(std::size_t j = 0; j < i; ++j)
      if(identify(outputs[j].second) == id) throw Usage_error(option + " and " + outputs[j].first + " name the same file");
  }
}

// Sets the option that takes `value`; false if there is no such option.
bool set_option(Command_line& c, const std::string& option, const std::string& value)
{
  // The options whose value is kept as it is given (checked later, against each other).
  static const std::map<std::string, std::string Command_line::*> text = {
    {"--source", &Command_line::source}, {"--target", &Command_line::target}, {"--output", &Command_line::output},
    {"--measure", &Command_line::measure}, {"--start", &Command_line::start},
    {"--mesh-output", &Command_line::mesh_output}, {"--boundary", &Command_line::boundary},
    {"--reference", &Command_line::reference}, {"--scheme", &Command_line::scheme},
    {"--subdivided-source", &Command_line::subdivided_source}, {"--flat-output", &Command_line::flat_output},
    {"--svg", &Command_line::svg}, {"--vertex-weights", &Command_line::vertex_weights},
    {"--cell-weighting", &Command_line::cell_weighting}, {"--order", &Command_line::order},
    {"--parallel-sweep", &Command_line::parallel_sweep}, {"--global-step", &Command_line::global_step},
    {"--harmonic-start", &Command_line::harmonic_start}, {"--energy-plot", &Command_line::energy_plot},
    {"--carry", &Command_line::carry}, {"--carry-output", &Command_line::carry_output},
    {"--solver", &Command_line::solver}, {"--report", &Command_line::report}, {"--seams", &Command_line::seams}, {"--schedule", &Command_line::schedule}};
  if(const auto member = text.find(option); member != text.end()) c.*(member->second) = value;
  else if(option == "--fix") { c.fix = value; c.fix_given = true; }
  else if(option == "--subdivide") {
    c.subdivide = parse_number<std::size_t>(option, value);
    if(c.subdivide == 0) throw Usage_error("--subdivide expects 1 to 6 levels, not 0");
  }
  else if(option == "--center") c.center = parse_point(option, value);
  else if(option == "--cell-size") {
    c.cell_size = parse_number<double>(option, value);
    if(!(c.cell_size > 0) || !std::isfinite(c.cell_size)) throw Usage_error("--cell-size must be a positive number");
  }
  else if(option == "--iterations") c.iterations = parse_number<std::size_t>(option, value);
  else if(option == "--threads") c.threads = parse_number<std::size_t>(option, value);
  else if(option == "--threshold") c.threshold = parse_number<double>(option, value);
  else if(option == "--max-distortion") {
    c.max_distortion = parse_number<double>(option, value);
    if(!(c.max_distortion >= 1) || !std::isfinite(c.max_distortion)) throw Usage_error("--max-distortion must be a number >= 1");
  }
  else if(option == "--time-limit") {
    c.time_limit = parse_number<double>(option, value);
    if(!(c.time_limit > 0) || !std::isfinite(c.time_limit)) throw Usage_error("--time-limit must be a positive number of seconds");
  }
  else return false;
  return true;
}

// Whether `option` takes a value (whatever the value).
bool set_option_known(const std::string& option)
{
  Command_line probe;
  try {
    return set_option(probe, option, "1");
  } catch(const Usage_error&) {   // "1" is not a value of that option: it is one
    return true;
  }
}

} // namespace

Command_line parse(int argc, char** argv)
{
  Command_line c;
  std::map<std::string, std::string> seen;
  for(int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if(option == "--help" || option == "-h") throw Usage_error("");
    if(option == "--untangle" || option == "--snap" || option == "--quiet" || option == "--verbose" || option == "--svg-both") {
      bool& flag = option == "--untangle" ? c.untangle : option == "--snap" ? c.snap : option == "--quiet" ? c.quiet
                 : option == "--verbose" ? c.verbose : c.svg_both;   // options without a value
      if(flag) throw Usage_error(option + " is given twice");
      flag = true;
      continue;
    }
    if(i + 1 >= argc) {
      // A known option without its value, or an unknown one (a misspelt flag given last).
      throw Usage_error(set_option_known(option) ? option + " needs a value" : "unknown option " + option);
    }
    const std::string value = argv[++i];
    // An empty value (--target '') would silently mean "not given".
    if(value.empty() && set_option_known(option)) throw Usage_error(option + " needs a value, not an empty one");
    if(seen.count(option)) throw Usage_error(option + " is given twice");
    seen[option] = value;
    if(!set_option(c, option, value)) throw Usage_error("unknown option " + option);
  }
  if(c.source.empty()) throw Usage_error("--source is required");
  if(c.output.empty()) throw Usage_error("--output is required");
  if(c.solver != "gd" && c.solver != "bfgs") throw Usage_error("--solver is gd or bfgs, not '" + c.solver + "'");
  if(c.threads == 0) throw Usage_error("--threads must be at least 1");
  if(!c.schedule.empty() && c.schedule != "alternating" && c.schedule != "local" && c.schedule != "global")
    throw Usage_error("--schedule is alternating, local or global, not '" + c.schedule + "'");
  if(!(c.threshold >= 0)) throw Usage_error("--threshold must be a non-negative number");
  if(c.quiet && c.verbose) throw Usage_error("--quiet and --verbose contradict each other");
  const std::vector<std::pair<std::string, std::vector<std::string>>> choices = {
    {"--cell-weighting", {c.cell_weighting, "average", "volume", "uniform"}}, {"--order", {c.order, "sorted", "greedy"}},
    {"--parallel-sweep", {c.parallel_sweep, "sets", "partition"}},
    {"--global-step", {c.global_step.empty() ? "newton" : c.global_step, "newton", "laplacian"}}};
  for(const auto& [option, values] : choices)
    if(std::find(values.begin() + 1, values.end(), values[0]) == values.end()) {
      std::string allowed;
      for(std::size_t i = 1; i < values.size(); ++i) allowed += (i == 1 ? "" : i + 1 == values.size() ? " or " : ", ") + values[i];
      throw Usage_error(option + " is " + allowed + ", not '" + values[0] + "'");
    }
  if(!c.harmonic_start.empty() && c.harmonic_start != "on" && c.harmonic_start != "off")
    throw Usage_error("--harmonic-start is on or off, not '" + c.harmonic_start + "'");
  const std::string in = extension(c.source), out = extension(c.output);
  const bool tetrahedra = tetrahedral_file(c.source) || c.volume_mode();
  // The ideal mode writes the improved mesh itself, in the source's kind.
  if(c.ideal() && (tetrahedral_file(c.source) ? out != "mesh" : out != "off" && out != "obj"))
    throw Usage_error(std::string("--reference ideal writes the improved mesh: --output must end in ") +
                      (tetrahedral_file(c.source) ? ".mesh" : ".off or .obj"));
  if(tetrahedra ? (out != "mesh" && out != "vtu") : (out != "off" && out != "obj" && out != "vtu"))
    throw Usage_error(tetrahedra ? "--output must end in .mesh or .vtu for a tetrahedral map"
                                 : "--output must end in .off, .obj or .vtu");
  if(!c.start.empty() && c.start != "ball" && c.start != "radial")
    throw Usage_error("--start is ball or radial, not '" + c.start + "'");
  if(c.volume_mode() && !c.target.empty()) throw Usage_error("--start and --target both give the start map: give one");
  if(!c.reference.empty() && !c.ideal()) throw Usage_error("--reference is ideal, not '" + c.reference + "'");
  if(c.max_distortion > 0 && (!c.target.empty() || c.volume_mode() || c.ideal() || tetrahedral_file(c.source)))
    throw Usage_error("--max-distortion bounds an atlas's charts: it takes a triangle surface source without --target");
  if(!c.seams.empty() && (!c.target.empty() || c.volume_mode() || c.ideal() || tetrahedral_file(c.source)))
    throw Usage_error("--seams cuts an atlas: it takes a triangle surface source without --target");
  if(c.ideal() && (!c.target.empty() || c.volume_mode()))
    throw Usage_error("--reference ideal improves the source itself: no --target or --start");
  if(tetrahedral_file(c.source) && c.target.empty() && !c.volume_mode() && !c.ideal())
    throw Usage_error("a .mesh source needs --target (the start map) or --start");
  const std::vector<std::pair<std::string, bool>> volume_only = {
    {"--mesh-output", !c.mesh_output.empty()}, {"--cell-size", c.cell_size > 0}, {"--center", !c.center.empty()},
    {"--boundary", !c.boundary.empty()}};
  for(const auto& [option, given] : volume_only)
    if(given && !c.volume_mode() && !(option == "--boundary" && c.ideal()))
      throw Usage_error(option + " needs --start (the volume mode)");
  if(c.ideal() && c.boundary == "slide" && !tetrahedral_file(c.source))
    throw Usage_error("--boundary slide with --reference ideal needs a tetrahedral mesh (.mesh)");
  if(tetrahedral_file(c.source) && (c.cell_size > 0)) throw Usage_error("--cell-size is for a surface source (a .mesh source is already meshed)");
  if(!c.mesh_output.empty() && extension(c.mesh_output) != "mesh")
    throw Usage_error("--mesh-output must end in .mesh");
  if(!c.boundary.empty() && c.boundary != "slide" && c.boundary != "fixed")
    throw Usage_error("--boundary is slide or fixed, not '" + c.boundary + "'");
  if(c.slides() && c.fix_given && c.fix == "boundary")
    throw Usage_error("--fix boundary and --boundary slide contradict each other");
  if(c.order == "greedy" && c.threads > 1)
    throw Usage_error("--order greedy is the one-thread sweep (the paper's Algorithm 2): not with --threads " +
                      std::to_string(c.threads));
  if(c.boundary == "fixed" && c.fix != "boundary")
    throw Usage_error("--boundary fixed and --fix " + std::string(c.fix == "none" ? "none" : "FILE") +
                      " contradict each other (--fix FILE constrains only the listed vertices: list the boundary's "
                      "there, or drop --boundary fixed)");
  if(!c.scheme.empty() && c.scheme != "linear" && c.scheme != "loop")
    throw Usage_error("--scheme is linear or loop, not '" + c.scheme + "'");
  if((c.subdivide > 0) != !c.subdivided_source.empty())
    throw Usage_error("--subdivide and --subdivided-source go together");
  if(!c.scheme.empty() && c.subdivide == 0) throw Usage_error("--scheme needs --subdivide");
  if(c.subdivide > 0 && (tetrahedra || c.ideal()))
    throw Usage_error("--subdivide is for a triangle map (not tetrahedra, not --reference ideal)");
  if(c.subdivide > 6) throw Usage_error("--subdivide is at most 6 (each level multiplies the triangles by 4)");
  if(!c.subdivided_source.empty() && extension(c.subdivided_source) != "off" &&
     extension(c.subdivided_source) != "obj")
    throw Usage_error("--subdivided-source must end in .off or .obj");
  if(!c.flat_output.empty() && (tetrahedra || c.ideal()))
    throw Usage_error("--flat-output is for a triangle map (not tetrahedra, not --reference ideal)");
  if(!c.flat_output.empty() && extension(c.flat_output) != "off" &&
     extension(c.flat_output) != "obj")
    throw Usage_error("--flat-output must end in .off or .obj");
  for(const std::string* picture : {&c.svg, &c.energy_plot})
    if(!picture->empty() && extension(*picture) != "svg")
      throw Usage_error("--svg and --energy-plot must end in .svg");
  if(c.svg_both && c.svg.empty()) throw Usage_error("--svg-both needs --svg");
  if(c.carry.empty() != c.carry_output.empty()) throw Usage_error("--carry and --carry-output go together");
  if(!c.carry.empty() && !tetrahedra) throw Usage_error("--carry needs a tetrahedral map (--start, or a .mesh source)");
  if(c.snap && c.carry.empty()) throw Usage_error("--snap needs --carry");
  for(const std::string* carried : {&c.carry, &c.carry_output}) {
    const std::string e = extension(*carried);
    if(!carried->empty() && e != "off" && e != "obj") throw Usage_error("--carry and --carry-output must end in .off or .obj");
  }
  if(!c.target.empty() && tetrahedral_file(c.target) != tetrahedral_file(c.source))
    throw Usage_error("--source and --target must both be triangle meshes or both tetrahedral meshes");
  try {
    DO::with_measure(c.measure, [](const auto&) { return 0; });
  } catch(const DO::Invalid_input& e) {
    throw Usage_error(std::string("--measure: ") + e.what());
  }
  check_files(c);
  return c;
}

} // namespace distortion_optimizer
