// The command-line tool, run as a user would: its documented options, outputs and errors.

#include "kuhn_block.h"
#include "test_files.h"

#include <CGAL/Distortion_optimization/IO/medit.h>
#include <CGAL/Distortion_optimization/IO/triangle_soup.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <numeric>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace IO = CGAL::Distortion_optimization::IO;

namespace {

struct Tool_run
{
  int status;
  std::string output;
};

// A shell command's exit status and output (standard output and error).
Tool_run run_in_shell(const std::string& command_line)
{
  const std::string command = "{ " + command_line + "; } 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buffer[4096];
  while(std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

Tool_run run(const std::string& arguments) { return run_in_shell(std::string(DISTORTION_OPTIMIZER) + " " + arguments); }

// A run that failed on its input (status 1) with `fragment` in its message, leaving `output`
// unwritten and no temporary file beside it.
void expect_failed_cleanly(const Tool_run& result, const std::string& fragment, const std::string& output)
{
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find(fragment), std::string::npos) << result.output;
  EXPECT_FALSE(test_files::exists(output)) << output;
  EXPECT_EQ(test_files::leftovers(output), 0u) << output;
}

std::string temp(const std::string& name)
{
  return ::testing::TempDir() + "distortion_cli_" + name;
}

using test_files::exists;
using test_files::leftovers;

double json_value(const std::string& json, const std::string& key)
{
  std::smatch m;
  if(!std::regex_search(json, m, std::regex("\"" + key + "\": ([-0-9.eE+]+)"))) return NAN;
  return std::stod(m[1]);
}

std::string slurp(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A planar 12 x 12 grid (source) and the same grid with a noisy interior (target).
// The unit square cut into k x k squares, each into two counterclockwise triangles.
IO::Triangle_soup unit_grid(int k)
{
  IO::Triangle_soup s;
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) s.points.push_back({double(i) / k, double(j) / k, 0});
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      const std::size_t a = j * (k + 1) + i, b = a + 1, c = a + k + 1, d = c + 1;
      s.cells.push_back({a, b, d});
      s.cells.push_back({a, d, c});
    }
  return s;
}

void write_planar_pair(const std::string& source, const std::string& target, double noise = 0.02)
{
  const IO::Triangle_soup s = unit_grid(12);
  IO::Triangle_soup t = s;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-noise, noise);
  for(auto& p : t.points) {
    const bool border = p[0] == 0 || p[1] == 0 || p[0] == 1 || p[1] == 1;
    p = {2 * p[0] + (border ? 0 : u(rng)), p[1] + (border ? 0 : u(rng)), 0};
  }
  IO::write_triangle_soup(source, s);
  IO::write_triangle_soup(target, t);
}

std::string data(const std::string& name) { return std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/" + name; }

// A helical ramp of 1.2 turns: a disk whose free-boundary flattening wants to overlap its ends.
IO::Triangle_soup helical_ramp()
{
  const int nr = 6, nt = 120;
  IO::Triangle_soup ramp;
  for(int j = 0; j <= nt; ++j)
    for(int i = 0; i <= nr; ++i) {
      const double r = 1 + double(i) / nr, t = 2 * 3.141592653589793 * 1.2 * j / nt;
      ramp.points.push_back({r * std::cos(t), r * std::sin(t), 0.3 * t});
    }
  for(int j = 0; j < nt; ++j)
    for(int i = 0; i < nr; ++i) {
      const std::size_t a = j * (nr + 1) + i, b = a + 1, c = a + nr + 1, d = c + 1;
      ramp.cells.push_back({a, b, d});
      ramp.cells.push_back({a, d, c});
    }
  return ramp;
}

// Pairs of border edges of a planar output that share no vertex and intersect (exact predicates).
std::size_t border_crossings(const IO::Triangle_soup& soup)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for(const auto& t : soup.cells)
    for(int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::vector<std::pair<std::size_t, std::size_t>> border;
  for(const auto& [edge, count] : uses)
    if(count == 1) border.push_back(edge);
  auto p = [&](std::size_t i) { return K::Point_2(soup.points[i][0], soup.points[i][1]); };
  std::size_t crossings = 0;
  for(std::size_t i = 0; i < border.size(); ++i)
    for(std::size_t j = i + 1; j < border.size(); ++j) {
      const auto [a, b] = border[i];
      const auto [c, d] = border[j];
      if(a != c && a != d && b != c && b != d)
        crossings += CGAL::do_intersect(K::Segment_2(p(a), p(b)), K::Segment_2(p(c), p(d)));
    }
  return crossings;
}

} // namespace

TEST(CommandLine, FreeBoundaryModeKeepsTheMapGloballyInjectiveAndThreadsAreDeterministic)
{
  const std::string s = temp("ramp.off"), o1 = temp("ramp_uv1.off"), o2 = temp("ramp_uv2.off");
  IO::write_triangle_soup(s, helical_ramp());
  for(const std::string& o : {o1, o2}) {
    const Tool_run result = run("--source " + s + " --output " + o +
                                " --fix none --measure symmetric_dirichlet --iterations 300 --threads 2");
    ASSERT_EQ(result.status, 0) << result.output;
    EXPECT_NE(result.output.find("inverted_cells  0"), std::string::npos) << result.output;
  }
  const IO::Triangle_soup out = IO::read_triangle_soup(o1);
  EXPECT_EQ(border_crossings(out), 0u);
  EXPECT_EQ(slurp(o1), slurp(o2));   // same thread count, same output
}

TEST(CommandLine, OptimizesAPlanarPairAndReportsJson)
{
  const std::string s = temp("s.off"), t = temp("t.obj"), o = temp("o.obj"), r = temp("r.json");
  write_planar_pair(s, t);
  std::remove(o.c_str());
  const Tool_run result = run("--source " + s + " --target " + t + " --output " + o +
                         " --measure symmetric_dirichlet --iterations 50 --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string json = slurp(r);
  for(const char* key : {"cells", "vertices", "initial_energy", "final_energy", "sweeps", "seconds", "inverted_cells"})
    EXPECT_FALSE(std::isnan(json_value(json, key))) << key << " missing in\n" << json;
  EXPECT_NE(json.find("\"measure\": \"symmetric_dirichlet\""), std::string::npos);
  EXPECT_EQ(json_value(json, "cells"), 288);
  EXPECT_EQ(json_value(json, "vertices"), 169);
  EXPECT_LT(json_value(json, "final_energy"), json_value(json, "initial_energy"));
  EXPECT_EQ(json_value(json, "inverted_cells"), 0);
  EXPECT_NE(result.output.find("final_energy"), std::string::npos);

  // The output has the source's connectivity, z = 0, and the border where the target had it.
  const IO::Triangle_soup out = IO::read_triangle_soup(o), in = IO::read_triangle_soup(t);
  ASSERT_EQ(out.points.size(), in.points.size());
  EXPECT_EQ(out.cells, in.cells);
  for(std::size_t i = 0; i < out.points.size(); ++i) {
    EXPECT_EQ(out.points[i][2], 0.);
    const double x = IO::read_triangle_soup(s).points[i][0], y = IO::read_triangle_soup(s).points[i][1];
    if(x == 0 || y == 0 || x == 1 || y == 1) {
      EXPECT_EQ(out.points[i][0], in.points[i][0]);
      EXPECT_EQ(out.points[i][1], in.points[i][1]);
    }
  }

  // The first iteration is measured from the energy after the harmonic start, reported as such;
  // no iteration is no move (the harmonic start moved the whole interior before).
  EXPECT_LT(json_value(json, "harmonic_start_energy"), json_value(json, "initial_energy"));
  EXPECT_GE(json_value(json, "harmonic_start_energy"), json_value(json, "final_energy"));
  ASSERT_EQ(run("--source " + s + " --target " + t + " --output " + o + " --measure symmetric_dirichlet --iterations 0 --report " + r).status, 0);
  EXPECT_EQ(IO::read_triangle_soup(o).points, in.points);
  const std::string evaluated = slurp(r);
  EXPECT_EQ(json_value(evaluated, "final_energy"), json_value(json, "initial_energy"));
  EXPECT_EQ(json_value(evaluated, "harmonic_start_energy"), json_value(json, "initial_energy"));
}

// A grid at half its size that grows back, border free, towards a small triangle beside it (a
// piece of its own): the tool keeps the triangle outside, not inside a grid face. A start with
// the triangle already inside is optimized without the guard, with a warning.
TEST(CommandLine, FreeBoundaryModeKeepsPiecesApart)
{
  const auto write_pair = [](const std::string& source, const std::string& target, double x, double y) {
    IO::Triangle_soup s, t;
    for(int j = 0; j <= 4; ++j)
      for(int i = 0; i <= 4; ++i) {
        s.points.push_back({double(i), double(j), 0});
        t.points.push_back({0.5 * i, 0.5 * j, 0});
      }
    for(std::size_t j = 0; j < 4; ++j)
      for(std::size_t i = 0; i < 4; ++i) {
        const std::size_t a = j * 5 + i, b = a + 1, c = a + 5, d = c + 1;
        s.cells.push_back({a, b, d});
        s.cells.push_back({a, d, c});
      }
    for(const auto& p : {std::array<double, 2>{0, 0}, {0.04, 0}, {0.02, 0.04}}) {
      s.points.push_back({p[0], p[1], 0});
      t.points.push_back({x + p[0], y + p[1], 0});
    }
    s.cells.push_back({25, 26, 27});
    t.cells = s.cells;
    IO::write_triangle_soup(source, s);
    IO::write_triangle_soup(target, t);
  };
  const std::string s = temp("pieces_s.off"), t = temp("pieces_t.off"), o = temp("pieces_o.off");
  write_pair(s, t, 2.05, 1.1);
  Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --fix none --measure isometric");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const IO::Triangle_soup out = IO::read_triangle_soup(o);
  const auto triangle = [&](const std::array<std::size_t, 3>& c) {
    const auto p = [&](std::size_t v) { return K::Point_2(out.points[v][0], out.points[v][1]); };
    return K::Triangle_2(p(c[0]), p(c[1]), p(c[2]));
  };
  double right = 0;
  for(std::size_t v = 0; v < 25; ++v) right = std::max(right, out.points[v][0]);
  EXPECT_GT(right, out.points[25][0]);   // the grid reached beyond the triangle somewhere
  for(std::size_t c = 0; c < 32; ++c) EXPECT_FALSE(CGAL::do_intersect(triangle(out.cells[c]), triangle(out.cells[32]))) << c;

  write_pair(s, t, 0.6, 0.6);
  result = run("--source " + s + " --target " + t + " --output " + o + " --fix none --measure isometric --iterations 3");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("warning: the boundary of the start map intersects itself, or one of its pieces lies inside "
                               "another: global injectivity cannot be preserved; optimized without the guard"),
            std::string::npos) << result.output;
}

TEST(CommandLine, FixFileAndFreeBoundary)
{
  const std::string s = temp("s2.off"), t = temp("t2.off"), o = temp("o2.off"), f = temp("fix.txt");
  write_planar_pair(s, t);
  std::ofstream(f) << "# pinned vertices\n0\n12\n\n168\n84\n";
  Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --fix " + f + " --measure arap");
  ASSERT_EQ(result.status, 0) << result.output;
  const IO::Triangle_soup out = IO::read_triangle_soup(o), in = IO::read_triangle_soup(t);
  for(std::size_t i : {0, 12, 168, 84}) EXPECT_EQ(out.points[i], in.points[i]) << i;
  // Free border: ARAP relaxes the stretch x -> 2x towards a rigid map, so border vertices move.
  EXPECT_NE(out.points[6], in.points[6]);

  result = run("--source " + s + " --target " + t + " --output " + o + " --fix none --measure mips --solver bfgs");
  EXPECT_EQ(result.status, 0) << result.output;
}

TEST(CommandLine, TutteStartForADiskWithoutTarget)
{
  const std::string o = temp("nefertiti_uv.off");
  const Tool_run result = run("--source " + data("nefertiti.off") + " --output " + o + " --measure conformal*isometric");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("inverted_cells  0"), std::string::npos) << result.output;
  EXPECT_EQ(IO::read_triangle_soup(o).cells, IO::read_triangle_soup(data("nefertiti.off")).cells);
}

// A disk with holes (CGAL's holes.off, 7 borders) gets the Tutte start of the disk with its holes
// filled, its holes freed under the guard with the default --fix, or all its borders with --fix
// none: no triangle inverted, no border crossing another, the outer border where the start put it.
TEST(CommandLine, TutteStartForADiskWithHoles)
{
  const IO::Triangle_soup source = IO::read_triangle_soup(data("holes.off"));
  for(const std::string fix : {"boundary", "none"}) {
    const std::string o = temp("holes_uv_" + fix + ".off"), r = temp("holes_" + fix + ".json");
    const Tool_run result = run("--source " + data("holes.off") + " --output " + o + " --flat-output " + temp("holes_flat.off") +
                                " --measure symmetric_dirichlet --fix " + fix + " --report " + r);
    ASSERT_EQ(result.status, 0) << result.output;
    EXPECT_EQ(json_value(slurp(r), "inverted_cells"), 0) << fix;
    EXPECT_LT(json_value(slurp(r), "final_energy"), 0.75 * json_value(slurp(r), "initial_energy")) << fix;
    const IO::Triangle_soup flat = IO::read_triangle_soup(temp("holes_flat.off"));
    EXPECT_EQ(flat.cells, source.cells);
    EXPECT_EQ(border_crossings(flat), 0u) << fix;
  }
}

// A source in pieces (a disk with holes and a disk, in one file) gets each piece's Tutte start,
// side by side: with the holes free (default --fix) or every border free (--fix none), no triangle
// inverted and no border crossing another, within a piece or between them.
TEST(CommandLine, TutteStartForSeveralPieces)
{
  IO::Triangle_soup two = IO::read_triangle_soup(data("holes.off"));
  const IO::Triangle_soup disk = IO::read_triangle_soup(data("nefertiti.off"));
  const std::size_t offset = two.points.size();
  for(auto p : disk.points) two.points.push_back({p[0] + 1000, p[1], p[2]});
  for(const auto& t : disk.cells) two.cells.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const std::string s = temp("two_pieces.off");
  IO::write_triangle_soup(s, two);
  for(const std::string fix : {"boundary", "none"}) {
    const std::string flat = temp("two_pieces_flat_" + fix + ".off");
    const Tool_run result = run("--source " + s + " --output " + temp("two_pieces_uv.obj") + " --flat-output " + flat +
                                " --measure symmetric_dirichlet --fix " + fix);
    ASSERT_EQ(result.status, 0) << result.output;
    EXPECT_NE(result.output.find("inverted_cells  0"), std::string::npos) << result.output;
    const IO::Triangle_soup out = IO::read_triangle_soup(flat);
    EXPECT_EQ(out.cells, two.cells);
    EXPECT_EQ(border_crossings(out), 0u) << fix;
  }
}

namespace {

// An atlas as the tool writes it: the source's vertices and faces in order, a UV per corner, each
// in the unit square and each UV triangle counterclockwise (exact), as many charts (faces joined by
// their UVs) as its report (at `report`) says, no face inverted and no chart overlapping.
void expect_atlas_obj(const std::string& o, const IO::Triangle_soup& source, const std::string& report)
{
  EXPECT_EQ(json_value(slurp(report), "inverted_cells"), 0);
  EXPECT_EQ(json_value(slurp(report), "overlapping_charts"), 0);
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const IO::Triangle_soup atlas = IO::read_triangle_soup(o);
  EXPECT_EQ(atlas.points, source.points);
  EXPECT_EQ(atlas.cells, source.cells);
  ASSERT_EQ(atlas.cell_texture_indices.size(), source.cells.size());
  for(const auto& t : atlas.cell_texture_indices) {
    std::array<K::Point_2, 3> p;
    for(int i = 0; i < 3; ++i) {
      const auto& uv = atlas.texture_coordinates.at(t[i]);
      p[i] = K::Point_2(uv[0], uv[1]);
      EXPECT_TRUE(uv[0] >= 0 && uv[0] <= 1 && uv[1] >= 0 && uv[1] <= 1);
    }
    EXPECT_EQ(CGAL::orientation(p[0], p[1], p[2]), CGAL::LEFT_TURN);
  }
  std::vector<std::size_t> root(atlas.texture_coordinates.size());
  std::iota(root.begin(), root.end(), std::size_t(0));
  const auto find = [&](std::size_t i) {
    while(root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for(const auto& t : atlas.cell_texture_indices) root[find(t[1])] = find(t[0]), root[find(t[2])] = find(t[0]);
  std::set<std::size_t> charts;
  for(const auto& t : atlas.cell_texture_indices) charts.insert(find(t[0]));
  EXPECT_EQ(double(charts.size()), json_value(slurp(report), "charts"));
}

} // namespace

// A surface with holes (CGAL's holes.off, 7 borders) written as OBJ gets an atlas (its charts
// free of any fixed border, packed into the unit square); written as OFF, or with --flat-output,
// the map per vertex of the previous tests (no atlas fields in the report).
TEST(CommandLine, ASurfaceWithHolesWrittenAsOBJGetsAnAtlas)
{
  const IO::Triangle_soup source = IO::read_triangle_soup(data("holes.off"));
  const std::string o = temp("holes_atlas.obj"), r = temp("holes_atlas.json");
  const Tool_run result = run("--source " + data("holes.off") + " --output " + o + " --measure symmetric_dirichlet --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  expect_atlas_obj(o, source, r);
  const std::string report = slurp(r);
  EXPECT_GE(json_value(report, "charts"), 1);
  EXPECT_GT(json_value(report, "packing_efficiency"), 0.5);
  EXPECT_LT(json_value(report, "final_energy"), 1.05);
  for(const std::string& other : {" --output " + temp("holes_map.off"), " --output " + o + " --flat-output " + temp("holes_flat2.off")}) {
    ASSERT_EQ(run("--source " + data("holes.off") + other + " --measure symmetric_dirichlet --report " + r).status, 0) << other;
    EXPECT_EQ(slurp(r).find("\"charts\""), std::string::npos) << other;
  }
}

// A closed surface of genus 2 (CGAL's eight.off) without --target: an atlas, written as OBJ with
// the source's vertices in order, one vt per UV corner and the source's faces; every UV triangle
// counterclockwise (exact) and in the unit square; the report's atlas fields.
TEST(CommandLine, AnAtlasForAClosedSurface)
{
  const IO::Triangle_soup source = IO::read_triangle_soup(data("eight.off"));
  const std::string o = temp("eight_atlas.obj"), r = temp("eight_atlas.json");
  const Tool_run result = run("--source " + data("eight.off") + " --output " + o + " --measure symmetric_dirichlet --report " + r +
                              " --svg " + temp("eight_atlas.svg"));
  ASSERT_EQ(result.status, 0) << result.output;
  expect_atlas_obj(o, source, r);
  EXPECT_GT(IO::read_triangle_soup(o).texture_coordinates.size(), source.points.size());   // the seams' vertices have two UVs or more
  const std::string report = slurp(r);
  EXPECT_GT(json_value(report, "seam_length_fraction"), 0);
  EXPECT_GT(json_value(report, "packing_efficiency"), 0.5);   // 0.46 as one chart: split for packing
  EXPECT_LE(json_value(report, "packing_efficiency"), 1);
  EXPECT_LT(json_value(report, "final_energy"), 1.1);
  EXPECT_TRUE(test_files::exists(temp("eight_atlas.svg")));
  // A bound below what the first cut reaches: more seams, the charts still valid.
  const std::string bounded = temp("eight_bounded.json");
  ASSERT_EQ(run("--source " + data("eight.off") + " --output " + o + " --measure symmetric_dirichlet --max-distortion 1.01 --report " +
                bounded).status, 0);
  EXPECT_GT(json_value(slurp(bounded), "seam_length_fraction"), json_value(report, "seam_length_fraction"));
  EXPECT_EQ(json_value(slurp(bounded), "inverted_cells"), 0);
  EXPECT_EQ(json_value(slurp(bounded), "overlapping_charts"), 0);
  // The optimizer's options apply to the charts: a loose threshold stops sooner; local sweeps
  // with BFGS keep the charts valid.
  const std::string loose = temp("eight_loose.json"), local = temp("eight_local.json");
  ASSERT_EQ(run("--source " + data("eight.off") + " --output " + o + " --measure symmetric_dirichlet --threshold 0.5 --report " +
                loose).status, 0);
  EXPECT_LT(json_value(slurp(loose), "sweeps"), json_value(report, "sweeps"));
  ASSERT_EQ(run("--source " + data("eight.off") + " --output " + o + " --measure symmetric_dirichlet --schedule local --solver bfgs "
                "--iterations 20 --report " + local).status, 0);
  EXPECT_EQ(json_value(slurp(local), "inverted_cells"), 0);
  EXPECT_EQ(json_value(slurp(local), "overlapping_charts"), 0);
  // --time-limit stops the charts' optimizations too: the atlas is written, valid, less optimized.
  const std::string limited = temp("eight_limited.json");
  ASSERT_EQ(run("--source " + data("eight.off") + " --output " + o + " --measure symmetric_dirichlet --time-limit 1e-9 --report " +
                limited).status, 0);
  EXPECT_NE(slurp(limited).find("\"stopped_by_time_limit\": true"), std::string::npos);
  EXPECT_EQ(json_value(slurp(limited), "inverted_cells"), 0);
  EXPECT_EQ(json_value(slurp(limited), "overlapping_charts"), 0);
  EXPECT_GT(json_value(slurp(limited), "final_energy"), json_value(report, "final_energy"));
  const std::string none = temp("not_written.obj");
  std::ofstream(temp("flat_tetrahedron.off")) << "OFF\n4 4 0\n0 0 0\n1 0 0\n2 0 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  expect_failed_cleanly(run("--source " + temp("flat_tetrahedron.off") + " --output " + none),
                        "flat_tetrahedron.off: face 0 is degenerate (its corners are collinear)", none);
  expect_failed_cleanly(run("--source " + data("nefertiti.off") + " --output " + none + " --max-distortion 1.1"), "gets none (a disk)", none);
  const Tool_run usage = run("--source " + data("eight.off") + " --output " + none + " --max-distortion 0.5");
  EXPECT_EQ(usage.status, 2);
  EXPECT_NE(usage.output.find("--max-distortion must be a number >= 1"), std::string::npos) << usage.output;
}

// --seams: a strip of squares bent into an open cylinder (it needs no seam) cut along the user's
// seam unrolls without distortion; a seam that is not an edge is refused, nothing written.
TEST(CommandLine, SeamsFromAFile)
{
  IO::Triangle_soup tube;
  const int n = 24, m = 6;
  const double radius = 0.5 / std::sin(M_PI / n);
  for(int k = 0; k <= m; ++k)
    for(int i = 0; i < n; ++i) tube.points.push_back({radius * std::cos(2 * M_PI * i / n), radius * std::sin(2 * M_PI * i / n), double(k)});
  const auto v = [&](int i, int k) { return std::size_t(k * n + (i % n)); };
  for(int k = 0; k < m; ++k)
    for(int i = 0; i < n; ++i) {
      tube.cells.push_back({v(i, k), v(i + 1, k), v(i + 1, k + 1)});
      tube.cells.push_back({v(i, k), v(i + 1, k + 1), v(i, k + 1)});
    }
  const std::string s = temp("tube.off"), seams = temp("tube_seams.txt"), o = temp("tube_atlas.obj"), r = temp("tube.json");
  IO::write_triangle_soup(s, tube);
  {
    std::ofstream out(seams);
    out << "# rim to rim\n";
    for(int k = 0; k < m; ++k) out << v(0, k) << " " << v(0, k + 1) << "\n";
  }
  const Tool_run result = run("--source " + s + " --seams " + seams + " --output " + o + " --measure symmetric_dirichlet --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_GT(json_value(slurp(r), "seam_length_fraction"), 0);
  EXPECT_LT(json_value(slurp(r), "final_energy"), 1.001);
  EXPECT_EQ(json_value(slurp(r), "overlapping_charts"), 0);
  EXPECT_EQ(IO::read_triangle_soup(o).texture_coordinates.size(), tube.points.size() + m + 1);   // the seam's vertices twice
  std::ofstream(temp("bad_seams.txt")) << "0 1\n0 30\n";
  const std::string none = temp("tube_not_written.obj");
  expect_failed_cleanly(run("--source " + s + " --seams " + temp("bad_seams.txt") + " --output " + none), "bad_seams.txt:2: vertices 0 and 30 are not joined by an edge", none);
}

// The triangles of a planar soup that are not counterclockwise (exact predicate).
static std::size_t inverted(const IO::Triangle_soup& soup)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::size_t count = 0;
  auto p = [&](std::size_t i) { return K::Point_2(soup.points[i][0], soup.points[i][1]); };
  for(const auto& c : soup.cells) count += CGAL::orientation(p(c[0]), p(c[1]), p(c[2])) != CGAL::LEFT_TURN;
  return count;
}

TEST(CommandLine, UntangleThenOptimize)
{
  // Interior noise of 0.2 on a grid of spacing 1/12: a tangled start.
  const std::string s = temp("s_tangled.off"), t = temp("t_tangled.off"), o = temp("o_tangled.off"),
                    r = temp("r_tangled.json");
  write_planar_pair(s, t, 0.2);
  const std::size_t tangled = inverted(IO::read_triangle_soup(t));
  ASSERT_GT(tangled, 10u);
  // Without --untangle: today's clear error, nothing written.
  std::remove(o.c_str());
  Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --measure symmetric_dirichlet");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("untangle"), std::string::npos) << result.output;
  EXPECT_FALSE(exists(o));

  // (Without the harmonic start: the harmonic map of this square's border is the identity, which
  // the untangling would start from, valid at once.)
  result = run("--source " + s + " --target " + t + " --output " + o +
               " --measure symmetric_dirichlet --untangle --harmonic-start off --verbose --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string json = slurp(r);
  // --verbose: the untangling's rounds (the last with no inverted cell), then the optimization's
  // iterations from 1 again, none with an inverted cell.
  std::vector<std::pair<std::size_t, std::size_t>> rows;   // (iteration, inverted)
  std::istringstream lines(result.output);
  for(std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    std::size_t iteration, cells;
    double energy, seconds;
    std::string decrease;
    if(fields >> iteration >> energy >> decrease >> seconds >> cells) rows.emplace_back(iteration, cells);
  }
  const std::size_t rounds = static_cast<std::size_t>(json_value(json, "untangle_iterations"));
  ASSERT_EQ(rows.size(), rounds + static_cast<std::size_t>(json_value(json, "sweeps"))) << result.output;
  // Between the two, a line that tells them apart (the barrier's energy may rise from round to round).
  const std::size_t between = result.output.find("(above: untangling rounds");
  ASSERT_NE(between, std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("(above: untangling rounds", between + 1), std::string::npos) << result.output;
  EXPECT_GT(rounds, 0u) << result.output;
  for(std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].first, i < rounds ? i + 1 : i - rounds + 1) << result.output;
    EXPECT_LE(rows[i].second, tangled) << result.output;
    if(i + 1 >= rounds) { EXPECT_EQ(rows[i].second, 0u) << result.output; }
  }
  EXPECT_EQ(json_value(json, "inverted_start_cells"), tangled) << json;
  EXPECT_EQ(json_value(json, "inverted_cells"), 0) << json;
  EXPECT_GT(json_value(json, "untangle_iterations"), 0) << json;
  EXPECT_GE(json_value(json, "untangle_seconds"), 0) << json;
  const IO::Triangle_soup out = IO::read_triangle_soup(o), in = IO::read_triangle_soup(t);
  EXPECT_EQ(inverted(out), 0u);
  for(std::size_t i = 0; i < out.points.size(); ++i) {
    const double x = IO::read_triangle_soup(s).points[i][0], y = IO::read_triangle_soup(s).points[i][1];
    if(x == 0 || y == 0 || x == 1 || y == 1) { EXPECT_EQ(out.points[i], in.points[i]); }
  }
}

// A mirror image with nothing fixed is reflected at once rather than untangled round by round
// (every one of this 30 x 30 grid's 1,800 triangles is inverted); the result keeps no cell
// inverted.
TEST(CommandLine, AMirrorImageWithAFreeBorderIsReflectedAtOnce)
{
  const std::string s = temp("grid30.off"), t = temp("grid30_mirror.off"), o = temp("grid30_out.off"), r = temp("grid30.json");
  const IO::Triangle_soup grid = unit_grid(30);
  IO::Triangle_soup mirror = grid;
  for(auto& p : mirror.points) p[0] = -p[0];
  IO::write_triangle_soup(s, grid);
  IO::write_triangle_soup(t, mirror);
  const Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --untangle --fix none --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string json = slurp(r);
  EXPECT_EQ(json_value(json, "inverted_start_cells"), 1800) << json;
  EXPECT_EQ(json_value(json, "untangle_iterations"), 0) << json;
  EXPECT_EQ(json_value(json, "inverted_cells"), 0) << json;
  EXPECT_EQ(inverted(IO::read_triangle_soup(o)), 0u);
}

TEST(CommandLine, ProgressLinesAndTimeLimit)
{
  const std::string o = temp("lion_progress.off"), r = temp("lion_progress.json");
  const std::string common = "--source " + data("lion-head.off") + " --output " + o + " --measure symmetric_dirichlet --report " + r;
  // --verbose: a header, then one line per iteration whose energies are the report's.
  Tool_run result = run(common + " --verbose");
  ASSERT_EQ(result.status, 0) << result.output;
  std::string json = slurp(r);
  const std::size_t sweeps = static_cast<std::size_t>(json_value(json, "sweeps"));
  std::istringstream lines(result.output);
  std::string line;
  std::size_t rows = 0;
  double last = 0;
  while(std::getline(lines, line)) {
    std::istringstream fields(line);
    std::size_t iteration;
    double energy, seconds;
    std::size_t inverted;
    std::string decrease;   // "-" on the first line
    if(fields >> iteration >> energy >> decrease >> seconds >> inverted) {
      EXPECT_EQ(iteration, ++rows) << line;
      EXPECT_EQ(inverted, 0u) << line;
      last = energy;
    }
  }
  EXPECT_NE(result.output.find("iteration"), std::string::npos) << result.output;
  EXPECT_EQ(rows, sweeps) << result.output;
  EXPECT_NEAR(last, json_value(json, "final_energy"), 1e-9 * last) << result.output;
  EXPECT_EQ(json.find("\"stopped_by_time_limit\": true"), std::string::npos) << json;
  // Not a terminal and no --verbose, or --quiet: no progress.
  EXPECT_EQ(run(common).output.find("iteration"), std::string::npos);
  EXPECT_EQ(run(common + " --quiet").output.find("iteration"), std::string::npos);
  EXPECT_EQ(run(common + " --quiet --verbose").status, 2);
  EXPECT_EQ(run(common + " --time-limit 0").status, 2);
  EXPECT_EQ(run(common + " --time-limit nan").status, 2);

  // A limit that the first iteration already passes (an exponent with a minus is a positive
  // number): one iteration, its map written whole.
  result = run(common + " --time-limit 1e-9");
  ASSERT_EQ(result.status, 0) << result.output;
  json = slurp(r);
  EXPECT_EQ(json_value(json, "sweeps"), 1) << json;
  EXPECT_NE(json.find("\"stopped_by_time_limit\": true"), std::string::npos) << json;
  EXPECT_EQ(json_value(json, "inverted_cells"), 0) << json;
  EXPECT_LT(json_value(json, "final_energy"), json_value(json, "initial_energy")) << json;
  EXPECT_EQ(IO::read_triangle_soup(o).cells, IO::read_triangle_soup(data("lion-head.off")).cells);
}

// A surface's map is a parametrization: --output X.obj has the surface with one UV per vertex,
// --flat-output the same map as (u, v, 0), and an OBJ with UVs is read back as a start.
TEST(CommandLine, ASurfaceMapIsWrittenAsUVsAndReadBack)
{
  const std::string s = data("nefertiti.off"), o = temp("nefertiti_uv.obj"), f = temp("nefertiti_flat.off"),
                    r = temp("nefertiti_uv.json"), o2 = temp("nefertiti_uv2.obj"), r2 = temp("nefertiti_uv2.json");
  Tool_run result = run("--source " + s + " --output " + o + " --flat-output " + f + " --measure conformal --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const IO::Triangle_soup in = IO::read_triangle_soup(s), out = IO::read_triangle_soup(o), flat = IO::read_triangle_soup(f);
  EXPECT_EQ(out.points, in.points);   // the surface itself, to the bit
  EXPECT_EQ(out.cells, in.cells);
  EXPECT_EQ(out.cell_texture_indices, in.cells);
  const std::vector<std::array<double, 2>> uv = IO::per_vertex_texture_coordinates(out, o);
  ASSERT_EQ(uv.size(), in.points.size());
  EXPECT_EQ(flat.cells, in.cells);
  for(std::size_t v = 0; v < uv.size(); ++v) {
    const std::array<double, 3> expected = {uv[v][0], uv[v][1], 0.};
    EXPECT_EQ(flat.points[v], expected) << v;
  }
  EXPECT_NE(slurp(o).find("\nvt "), std::string::npos);

  // The UVs as the start of another run: its start energy is the first run's final one.
  result = run("--source " + s + " --target " + o + " --output " + o2 + " --measure conformal --report " + r2);
  ASSERT_EQ(result.status, 0) << result.output;
  const double final_energy = json_value(slurp(r), "final_energy");
  EXPECT_NEAR(json_value(slurp(r2), "initial_energy"), final_energy, 1e-12 * final_energy);

  // One vertex with two UVs (a seam), and faces of which only some have UVs: clear errors.
  const std::string seam = temp("seam.obj"), mixed = temp("mixed.obj"), square = temp("square.off");
  std::ofstream(square) << "OFF\n4 2 0\n0 0 1\n1 0 0\n1 1 1\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  std::ofstream(seam) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                         "f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n";
  std::ofstream(mixed) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 1 3 4\n";
  result = run("--source " + square + " --target " + seam + " --output " + o2);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("vertex 0 has two texture coordinates"), std::string::npos) << result.output;
  result = run("--source " + square + " --target " + mixed + " --output " + o2);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("texture indices and others not"), std::string::npos) << result.output;
  // UVs that no face refers to are not the map: the target is then its (non-planar) vertices.
  const std::string loose = temp("loose_uv.obj");
  std::ofstream(loose) << "v 0 0 1\nv 1 0 0\nv 1 1 1\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1 2 3\nf 1 3 4\n";
  result = run("--source " + square + " --target " + loose + " --output " + o2);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("vertex 0 has z != 0 (the target must be planar; its vt lines are not UVs of the map"),
            std::string::npos) << result.output;
  EXPECT_EQ(run("--source " + temp("none.mesh") + " --target " + temp("none2.mesh") + " --output " + temp("x.mesh") +
                " --flat-output " + f).status, 2);   // tetrahedra have no flat output

  // A planar source: an OBJ target with the source's positions gives the map by its UVs, as a
  // surface's does; one whose planar positions are another map as well is ambiguous (its UVs
  // silently replaced the positions).
  const std::string ps = temp("uv_s.off"), pt = temp("uv_t.off"), uvs = temp("uv_t.obj"), both = temp("uv_both.obj");
  write_planar_pair(ps, pt);
  const IO::Triangle_soup planar_source = IO::read_triangle_soup(ps), planar_target = IO::read_triangle_soup(pt);
  IO::Triangle_soup with_uvs = planar_source;
  for(const auto& p : planar_target.points) with_uvs.texture_coordinates.push_back({p[0], p[1]});
  with_uvs.cell_texture_indices = with_uvs.cells;
  IO::write_triangle_soup(uvs, with_uvs);
  with_uvs.points = planar_target.points;
  with_uvs.texture_coordinates.assign(with_uvs.points.size(), {0.5, 0.5});
  IO::write_triangle_soup(both, with_uvs);
  const std::string common = " --output " + o2 + " --iterations 0 --harmonic-start off --report " + r2;
  ASSERT_EQ(run("--source " + ps + " --target " + pt + common).status, 0);
  const double by_positions = json_value(slurp(r2), "initial_energy");
  result = run("--source " + ps + " --target " + uvs + common);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(json_value(slurp(r2), "initial_energy"), by_positions);
  result = run("--source " + ps + " --target " + both + common);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("could be the map of the planar source"), std::string::npos) << result.output;
}

// The Float64 values of the VTU array named `name` (or of the Points array for "Points").
std::vector<double> vtu_array(const std::string& vtu, const std::string& name)
{
  const std::size_t at = name == "Points" ? vtu.find("<Points>") : vtu.find("Name=\"" + name + "\"");
  std::vector<double> values;
  if(at == std::string::npos) return values;
  // The array's own tag holds the name; the Points array is the first one after <Points>.
  const std::size_t begin = vtu.find('>', name == "Points" ? vtu.find("<DataArray", at) : at) + 1,
                    end = vtu.find("</DataArray>", begin);
  std::istringstream in(vtu.substr(begin, end - begin));
  for(double x; in >> x;) values.push_back(x);
  return values;
}

std::size_t occurrences(const std::string& text, const std::string& word)
{
  std::size_t n = 0;
  for(std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

TEST(CommandLine, PicturesAndDisplacements)
{
  const std::string s = temp("pic_s.off"), t = temp("pic_t.off"), o = temp("pic.vtu"), p = temp("pic.svg"),
                    e = temp("pic_energy.svg"), r = temp("pic.json");
  write_planar_pair(s, t);
  Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --svg " + p + " --svg-both --energy-plot " +
                        e + " --report " + r + " --measure conformal --iterations 7 --threshold 0 --harmonic-start off");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string svg = slurp(p), plot = slurp(e), vtu = slurp(o);
  EXPECT_EQ(occurrences(svg, "<polygon"), 2 * 288u);   // the source and the map, side by side
  EXPECT_NE(svg.find(">conformal per cell, "), std::string::npos);
  EXPECT_EQ(occurrences(svg, "inverted or flat"), 0u);
  // The plot: the start and each of the 7 iterations.
  const std::size_t points = plot.find("points=\""), end = plot.find('"', points + 8);
  EXPECT_EQ(occurrences(plot.substr(points, end - points), ","), 8u);
  // The VTU: the map's positions, and the displacement from the source (z = 0 there).
  const IO::Triangle_soup source = IO::read_triangle_soup(s);
  const std::vector<double> positions = vtu_array(vtu, "Points"), displacement = vtu_array(vtu, "displacement");
  ASSERT_EQ(positions.size(), 3 * source.points.size());
  ASSERT_EQ(displacement.size(), positions.size());
  for(std::size_t i = 0; i < positions.size(); ++i)
    EXPECT_NEAR(positions[i] - displacement[i], source.points[i / 3][i % 3], 1e-14) << i;
  EXPECT_EQ(vtu_array(vtu, "conformal").size(), 288u);

  // The map's colours are the same with the source drawn beside it (the scale's percentile counted
  // every cell twice, and moved), and the plot's iterations are labelled at whole numbers, once.
  const std::string single = temp("pic_single.svg"), plot2 = temp("pic_plot2.svg");
  result = run("--source " + s + " --target " + t + " --output " + temp("pic2.off") + " --svg " + single +
               " --measure conformal --iterations 7 --threshold 0 --harmonic-start off");
  ASSERT_EQ(result.status, 0) << result.output;
  result = run("--source " + s + " --target " + t + " --output " + temp("pic3.off") + " --energy-plot " + plot2 +
               " --measure conformal --iterations 2 --threshold 0 --harmonic-start off");
  ASSERT_EQ(result.status, 0) << result.output;
  const auto fills = [](const std::string& picture) {
    std::vector<std::string> all;
    const std::regex fill("<polygon [^>]*fill=\"(#[0-9a-f]{6})\"");
    for(auto i = std::sregex_iterator(picture.begin(), picture.end(), fill); i != std::sregex_iterator(); ++i) all.push_back((*i)[1]);
    std::sort(all.begin(), all.end());
    return all;
  };
  const std::vector<std::string> alone = fills(slurp(single)), beside = fills(svg);
  ASSERT_EQ(beside.size(), 2 * alone.size());
  std::vector<std::string> twice;
  for(const std::string& f : alone) twice.insert(twice.end(), {f, f});
  EXPECT_EQ(beside, twice);
  EXPECT_GT(std::set<std::string>(alone.begin(), alone.end()).size(), 10u);
  std::vector<std::pair<std::string, std::string>> ticks;   // (x, label) under the axis
  const std::string two = slurp(plot2);
  const std::regex tick("<text x=\"([0-9.]+)\" y=\"348\" text-anchor=\"middle\">([^<]*)</text>");
  for(auto i = std::sregex_iterator(two.begin(), two.end(), tick); i != std::sregex_iterator(); ++i) ticks.emplace_back((*i)[1], (*i)[2]);
  EXPECT_EQ(ticks, (std::vector<std::pair<std::string, std::string>>{{"80", "0"}, {"320", "1"}, {"560", "2"}}));

  // A tetrahedral map: the sections of the source and of the map by their middle planes.
  const std::string m = temp("pic_cube.mesh"), ts = temp("pic_tets.svg");
  const IO::Tetrahedron_soup cube = kuhn_block(4);
  IO::Tetrahedron_soup map;
  map = cube;
  for(auto& q : map.points) q[0] = 2 * q[0] + 0.1 * q[1] * q[1];   // a stretch and a bend
  IO::write_MEDIT_soup(m, cube);
  {   // the map as TetGen writes it: 1-based, a boundary marker per point
    std::ofstream node(temp("pic_cube_map.node")), ele(temp("pic_cube_map.ele"));
    node.precision(17);
    node << map.points.size() << " 3 0 1\n";
    for(std::size_t v = 0; v < map.points.size(); ++v)
      node << v + 1 << ' ' << map.points[v][0] << ' ' << map.points[v][1] << ' ' << map.points[v][2] << " 0\n";
    ele << map.cells.size() << " 4 0\n";
    for(std::size_t c = 0; c < map.cells.size(); ++c)
      ele << c + 1 << ' ' << map.cells[c][0] + 1 << ' ' << map.cells[c][1] + 1 << ' ' << map.cells[c][2] + 1 << ' '
          << map.cells[c][3] + 1 << '\n';
  }
  result = run("--source " + m + " --target " + temp("pic_cube_map.ele") + " --output " + temp("pic_cube_out.vtu") + " --svg " + ts +
               " --svg-both --iterations 3");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string sections = slurp(ts);
  // In the source, the plane z = 2 holds a layer of faces: 2 triangles per unit square, 16 squares.
  const std::size_t first_panel = sections.find("</g>");
  ASSERT_NE(first_panel, std::string::npos);
  EXPECT_EQ(occurrences(sections.substr(0, first_panel), "<polygon"), 32u);
  EXPECT_GE(occurrences(sections.substr(first_panel), "<polygon"), 32u);   // the map's own middle plane
  const std::vector<double> moved = vtu_array(slurp(temp("pic_cube_out.vtu")), "displacement");
  ASSERT_EQ(moved.size(), 3 * cube.points.size());
  for(std::size_t v = 0; v < cube.points.size(); ++v) {
    if(cube.points[v][2] == 0) {
      EXPECT_EQ(moved[3 * v], map.points[v][0] - cube.points[v][0]);   // fixed boundary
    }
  }

  // A PLY source (read by CGAL's reader) with the same target: the same map.
  {
    std::ofstream ply(temp("pic_s.ply"));
    ply.precision(17);
    ply << "ply\nformat ascii 1.0\nelement vertex " << source.points.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << source.cells.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for(const auto& q : source.points) ply << q[0] << ' ' << q[1] << ' ' << q[2] << '\n';
    for(const auto& f : source.cells) ply << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
  }
  result = run("--source " + temp("pic_s.ply") + " --target " + t + " --output " + temp("pic_ply.vtu") +
               " --measure conformal --iterations 7 --threshold 0 --harmonic-start off");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(vtu_array(slurp(temp("pic_ply.vtu")), "Points"), positions);

  // Under a measure finite on inverted cells (ARAP), the picture still shows them in red; the plot
  // of a run whose start has an infinite energy leaves that point out.
  {
    IO::Triangle_soup folded = IO::read_triangle_soup(t);
    folded.points[6 * 13 + 6][0] += 0.5;   // the middle vertex, three columns over
    IO::write_triangle_soup(temp("pic_folded.off"), folded);
  }
  result = run("--source " + s + " --target " + temp("pic_folded.off") + " --output " + temp("x.off") + " --svg " + p +
               " --measure arap --iterations 0 --harmonic-start off --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const double inverted = json_value(slurp(r), "inverted_cells");
  EXPECT_GT(inverted, 0);
  EXPECT_EQ(double(occurrences(slurp(p), "fill=\"#d62728\"/>")), inverted);
  EXPECT_NE(slurp(p).find("</tspan> " + std::to_string(int(inverted)) + " inverted or flat"), std::string::npos);
  // The sphere with its inner vertices shuffled (each at another's place): so tangled that the
  // first round of untangling, after which the limit stops the run, leaves inverted cells. No
  // valid map: status 1, and neither the map nor the plot is written.
  const IO::Tetrahedron_soup sphere = IO::read_tetrahedron_soup(data("sphere.mesh"));
  IO::Tetrahedron_soup shuffled = sphere;
  std::vector<std::size_t> inner;
  double radius = 0;
  for(const auto& q : sphere.points) radius = std::max(radius, std::hypot(q[0], q[1], q[2]));
  for(std::size_t v = 0; v < sphere.points.size(); ++v)
    if(std::hypot(sphere.points[v][0], sphere.points[v][1], sphere.points[v][2]) < 0.98 * radius) inner.push_back(v);
  std::vector<std::size_t> places = inner;
  std::shuffle(places.begin(), places.end(), std::mt19937(1));
  for(std::size_t k = 0; k < inner.size(); ++k) shuffled.points[inner[k]] = sphere.points[places[k]];
  IO::write_MEDIT_soup(temp("pic_shuffled.mesh"), shuffled);
  std::remove(e.c_str());
  const std::string stopped = temp("pic_stopped.mesh");
  std::remove(stopped.c_str());
  result = run("--source " + data("sphere.mesh") + " --target " + temp("pic_shuffled.mesh") + " --output " + stopped +
               " --energy-plot " + e + " --untangle --time-limit 1e-9 --harmonic-start off");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("the time limit stopped the untangling with "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("nothing written"), std::string::npos) << result.output;
  EXPECT_FALSE(std::ifstream(stopped).good());
  EXPECT_FALSE(std::ifstream(e).good());

  EXPECT_EQ(run("--source " + s + " --target " + t + " --output " + temp("x.off") + " --svg-both").status, 2);
  EXPECT_EQ(run("--source " + s + " --target " + t + " --output " + temp("x.off") + " --svg " + temp("x.png")).status, 2);
}

// The options that choose the API's named parameters: weights, order, sweeps, harmonic start, sums.
TEST(CommandLine, WeightsOrdersSweepsAndWeightedSums)
{
  const std::string s = temp("opt_s.off"), t = temp("opt_t.off"), r = temp("opt.json"), o = temp("opt_o.off");
  write_planar_pair(s, t, 0.02);
  {   // cells of different areas, so that the weightings differ
    IO::Triangle_soup graded = IO::read_triangle_soup(s);
    for(auto& p : graded.points) p[0] = p[0] * (0.5 + p[0]) / 1.5;
    IO::write_triangle_soup(s, graded);
  }
  const auto energies = [&](const std::string& options) {
    const Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --report " + r + " " + options);
    EXPECT_EQ(result.status, 0) << options << "\n" << result.output;
    const std::string json = slurp(r);
    EXPECT_EQ(json_value(json, "inverted_cells"), 0.) << options;
    return std::make_pair(json_value(json, "initial_energy"), json_value(json, "final_energy"));
  };
  // The start's K per triangle, computed here: uniform weights average it, the default weights
  // (average volume) weight it by the source's area.
  const IO::Triangle_soup source = IO::read_triangle_soup(s), target = IO::read_triangle_soup(t);
  double plain = 0, weighted = 0, area = 0;
  for(const auto& c : source.cells) {
    const auto& a = source.points[c[0]]; const auto& b = source.points[c[1]]; const auto& d = source.points[c[2]];
    const auto& p = target.points[c[0]]; const auto& q = target.points[c[1]]; const auto& u = target.points[c[2]];
    const double s00 = b[0] - a[0], s01 = d[0] - a[0], s10 = b[1] - a[1], s11 = d[1] - a[1];
    const double t00 = q[0] - p[0], t01 = u[0] - p[0], t10 = q[1] - p[1], t11 = u[1] - p[1];
    const double sdet = s00 * s11 - s01 * s10;   // J = T S^-1
    const double j00 = (t00 * s11 - t01 * s10) / sdet, j01 = (t01 * s00 - t00 * s01) / sdet,
                 j10 = (t10 * s11 - t11 * s10) / sdet, j11 = (t11 * s00 - t10 * s01) / sdet;
    const double f = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11, det = j00 * j11 - j01 * j10;
    const double K = (f + std::sqrt(f * f - 4 * det * det)) / (2 * det);
    plain += K / source.cells.size();
    weighted += K * sdet / 2;
    area += sdet / 2;
  }
  ASSERT_GT(std::abs(plain - weighted / area), 1e-3);
  EXPECT_NEAR(energies("--measure conformal --iterations 1 --cell-weighting uniform").first, plain, 1e-12 * plain);
  EXPECT_NEAR(energies("--measure conformal --iterations 1").first, weighted / area, 1e-12 * plain);
  EXPECT_NEAR(energies("--measure conformal --iterations 1 --cell-weighting volume").first, weighted / area, 1e-12 * plain);

  // A weighted sum is the sum of its terms' energies.
  const double k = energies("--measure conformal --iterations 1").first, c = energies("--measure isometric --iterations 1").first;
  const auto sum = energies("--measure 0.5*conformal+isometric --iterations 20");
  EXPECT_NEAR(sum.first, 0.5 * k + c, 1e-12 * sum.first);
  EXPECT_LT(sum.second, sum.first);
  EXPECT_NE(slurp(r).find("\"measure\": \"0.5*conformal+isometric\""), std::string::npos);

  // Vertex weights: all 3 leave the normalized energies as they are; others change the optimum.
  const std::string w = temp("opt_weights.txt"), bad = temp("opt_bad_weights.txt");
  {
    std::ofstream equal(w);
    for(std::size_t v = 0; v < source.points.size(); ++v) equal << "3\n";
  }
  const auto unweighted = energies("--measure symmetric_dirichlet --iterations 30");
  const std::string unweighted_map = slurp(o);
  const auto equal = energies("--measure symmetric_dirichlet --iterations 30 --vertex-weights " + w);
  EXPECT_NEAR(equal.first, unweighted.first, 1e-12 * unweighted.first);
  {
    std::ofstream varied(w);
    for(std::size_t v = 0; v < source.points.size(); ++v) varied << (v % 7 == 0 ? 10 : 1) << "\n";
  }
  const auto varied = energies("--measure symmetric_dirichlet --iterations 30 --vertex-weights " + w);
  const std::string varied_map = slurp(o);
  EXPECT_NE(varied_map, unweighted_map);
  // The same weights times 2^1020, near the largest double: the same map and energies, not
  // sums that overflow to NaN.
  {
    std::ofstream huge(w);
    huge.precision(17);
    for(std::size_t v = 0; v < source.points.size(); ++v) huge << std::ldexp(v % 7 == 0 ? 10. : 1., 1020) << "\n";
  }
  EXPECT_EQ(energies("--measure symmetric_dirichlet --iterations 30 --vertex-weights " + w), varied);
  EXPECT_EQ(slurp(o), varied_map);
  std::ofstream(bad) << "1\n-2\n";
  Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --vertex-weights " + bad);
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.output.find(bad + ":2: weight -2 is not positive"), std::string::npos) << result.output;

  // The paper's greedy order and Algorithm 3's partition reach the same energy as the defaults.
  const auto sorted = energies("--measure symmetric_dirichlet --schedule local --iterations 200 --threshold 1e-7");
  const auto greedy = energies("--measure symmetric_dirichlet --schedule local --iterations 200 --threshold 1e-7 --order greedy");
  const auto partition = energies("--measure symmetric_dirichlet --schedule local --iterations 200 --threshold 1e-7 "
                                  "--threads 2 --parallel-sweep partition");
  EXPECT_NEAR(greedy.second, sorted.second, 5e-3 * (sorted.second - 1));
  EXPECT_NEAR(partition.second, sorted.second, 5e-3 * (sorted.second - 1));
  // Without the harmonic start the alternating schedule takes another path.
  energies("--measure symmetric_dirichlet --iterations 1");
  const std::string harmonic = slurp(o);
  energies("--measure symmetric_dirichlet --iterations 1 --harmonic-start off");
  EXPECT_NE(slurp(o), harmonic);
  EXPECT_EQ(run("--source " + s + " --target " + t + " --output " + o + " --order random").status, 2);
  const Tool_run greedy_threads = run("--source " + s + " --target " + t + " --output " + o + " --order greedy --threads 2");
  EXPECT_EQ(greedy_threads.status, 2);   // greedy is the one-thread sweep: not silently the sorted one
  EXPECT_NE(greedy_threads.output.find("--order greedy is the one-thread sweep"), std::string::npos) << greedy_threads.output;
  EXPECT_EQ(run("--source " + s + " --target " + t + " --output " + o + " --harmonic-start yes").status, 2);
  // Newton steps are the default for a triangle map: --global-step newton writes the same map;
  // the Laplacian's steps reach the same energy by another path.
  const auto by_default = energies("--measure symmetric_dirichlet --threshold 1e-8 --iterations 500");
  const std::string default_map = slurp(o);
  const auto newton = energies("--measure symmetric_dirichlet --threshold 1e-8 --iterations 500 --global-step newton");
  EXPECT_EQ(slurp(o), default_map);
  const auto laplacian = energies("--measure symmetric_dirichlet --threshold 1e-8 --iterations 500 --global-step laplacian");
  EXPECT_NE(slurp(o), default_map);
  EXPECT_EQ(newton.second, by_default.second);
  EXPECT_NEAR(laplacian.second, newton.second, 1e-5 * (newton.second - 1));
  EXPECT_EQ(run("--source " + s + " --target " + t + " --output " + o + " --global-step cholesky").status, 2);
}

// The usage the manual shows is the tool's --help, to the character.
TEST(CommandLine, TheManualShowsTheToolsUsage)
{
  const Tool_run help = run("--help");
  ASSERT_EQ(help.status, 0) << help.output;
  const std::string manual = slurp(DISTORTION_OPTIMIZATION_MANUAL);
  const std::size_t begin = manual.find("\\verbatim\nusage: distortion_optimizer");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t start = begin + std::string("\\verbatim\n").size();
  const std::size_t end = manual.find("\\endverbatim", start);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(manual.substr(start, end - start), help.output);
}

TEST(CommandLine, BadInputGivesAOneLineErrorAndWritesNothing)
{
  const std::string s = temp("s3.off"), t = temp("t3.off"), o = temp("o3.off");
  write_planar_pair(s, t);
  auto expect_failure = [&](const std::string& arguments, int status, const std::string& fragment) {
    std::remove(o.c_str());
    const Tool_run result = run(arguments);
    EXPECT_EQ(result.status, status) << arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(fragment), std::string::npos) << arguments << "\n" << result.output;
    EXPECT_FALSE(exists(o)) << arguments;
    EXPECT_EQ(leftovers(o), 0u) << arguments;
  };
  const std::string base = "--source " + s + " --output " + o;
  expect_failure(base + " --target " + temp("missing.off"), 1, "cannot open");
  expect_failure(base + " --target " + t + " --measure nonsense", 2, "unknown measure 'nonsense'");
  expect_failure(base + " --target " + t + " --solver newton", 2, "--solver");
  expect_failure(base + " --target " + t + " --iterations many", 2, "--iterations expects a number");
  expect_failure(base + " --target " + t + " --iterations 99999999999999999999", 2, "--iterations '99999999999999999999' is out of range");
  expect_failure(base + " --target " + t + " --time-limit 1e309", 2, "--time-limit '1e309' is out of range");
  expect_failure(base + " --target " + t + " --iterations ' 2'", 2, "--iterations expects a number, not ' 2'");
  expect_failure(base + " --target " + t + " --iterations '2 '", 2, "--iterations expects a number, not '2 '");
  expect_failure(base + " --target " + t + " --measure dirichlet --fix none", 1,
                 "the measure dirichlet decreases as the map shrinks, and no vertex is constrained");
  expect_failure("--source " + s + " --target " + t, 2, "--output is required");

  const std::string fewer = temp("fewer.off");
  std::ofstream(fewer) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_failure(base + " --target " + fewer, 1, "vertices");

  IO::Triangle_soup rewired = IO::read_triangle_soup(t);
  std::swap(rewired.cells[3][1], rewired.cells[3][2]);
  const std::string other = temp("other_connectivity.off");
  IO::write_triangle_soup(other, rewired);
  expect_failure(base + " --target " + other, 1, "face 3 differs from the source's");

  const std::string empty = temp("empty.off");
  std::ofstream(empty) << "OFF\n0 0 0\n";
  expect_failure("--source " + empty + " --output " + o, 1, "no triangle");
  std::ofstream(temp("blank.off")) << "";
  expect_failure("--source " + temp("blank.off") + " --output " + o, 1, "empty file");

  // A source triangle of zero area (three collinear points).
  std::ofstream(temp("collinear.off")) << "OFF\n3 1 0\n0 0 0\n1 1 0\n2 2 0\n3 0 1 2\n";
  expect_failure("--source " + temp("collinear.off") + " --target " + temp("collinear.off") + " --output " + o, 1,
                 temp("collinear.off") + ": source face 0 is degenerate");
  // A needle whose vertices are not exactly collinear, but whose edges' rounded cross product is
  // zero (the midpoint of an edge written with few decimals): degenerate in doubles, as such.
  std::ofstream(temp("needle.off")) << "OFF\n4 2 0\n0.154 -0.207 0.953\n-0.907 0.717 -0.421\n-0.3765 0.255 0.266\n"
                                       "1 1 1\n3 0 1 2\n3 0 3 1\n";
  expect_failure("--source " + temp("needle.off") + " --output " + o, 1,
                 temp("needle.off") + ": source face 0 is degenerate in double precision");
  // A disk beside a closed surface: one border and Euler characteristic 1, yet not a disk.
  const std::string disk_and_closed = temp("disk_and_closed.off");
  std::ofstream(disk_and_closed) << "OFF\n7 5 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n5 0 1\n"
                                    "3 0 1 2\n3 3 5 4\n3 3 4 6\n3 4 5 6\n3 5 3 6\n";
  expect_failure("--source " + disk_and_closed + " --output " + o + " --measure arap", 1,
                 "has a closed piece or a handle, so its map to the plane is an atlas with seams, whose UVs are per corner: give an .obj output");
  expect_failure("--source " + disk_and_closed + " --output " + temp("atlas.obj") + " --subdivide 1 --subdivided-source " + temp("atlas_fine.off"), 1,
                 "--subdivide does not apply to it");
  expect_failure("--source " + disk_and_closed + " --output " + temp("atlas.obj") + " --fix boundary", 1,
                 "--fix boundary (an atlas's borders are free) does not apply to it");
  // Its closed piece mapped into the plane: no untangling can help, and the messages say why.
  const std::string flat = temp("disk_and_closed_flat.off");
  std::ofstream(flat) << "OFF\n7 5 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n5.3 0.3 0\n"
                         "3 0 1 2\n3 3 5 4\n3 3 4 6\n3 4 5 6\n3 5 3 6\n";
  expect_failure("--source " + disk_and_closed + " --target " + flat + " --output " + o, 1,
                 "the piece of the mesh with cell 1 has no border (a closed surface)");
  expect_failure("--source " + disk_and_closed + " --target " + flat + " --output " + o + " --untangle", 1,
                 "untangling cannot succeed: the piece of the mesh with cell 1 has no border");

  const std::string truncated = temp("truncated.off");
  std::ofstream(truncated) << "OFF\n4 2 0\n0 0 0\n1 0 0\n";
  expect_failure("--source " + truncated + " --output " + o, 1, "truncated");

  const std::string nan = temp("nan.off");
  std::ofstream(nan) << "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n";
  expect_failure("--source " + nan + " --output " + o, 1, "not a finite number");

  const std::string quad = temp("quad.off");
  std::ofstream(quad) << "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  expect_failure("--source " + quad + " --output " + o, 1, "not a triangle");

  // Three triangles on one edge: non-manifold.
  const std::string fan = temp("fan.off");
  std::ofstream(fan) << "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
  expect_failure("--source " + fan + " --output " + o, 1, "non-manifold");

  const std::string fix = temp("bad_fix.txt");
  std::ofstream(fix) << "3\n999\n";
  expect_failure(base + " --target " + t + " --fix " + fix, 1, "vertex index 999 out of range");

  // An inverted start under a regular measure: the message names the cell.
  IO::Triangle_soup flipped = IO::read_triangle_soup(t);
  flipped.points[14] = {1.9, 0.95, 0};
  const std::string inverted = temp("inverted.off");
  IO::write_triangle_soup(inverted, flipped);
  expect_failure(base + " --target " + inverted + " --measure conformal", 1, "inverted");

  // A target 2^-600 times the source's size: no measure can be evaluated in doubles.
  IO::Triangle_soup tiny = IO::read_triangle_soup(t);
  for(auto& q : tiny.points)
    for(double& x : q) x = std::ldexp(x, -600);
  IO::write_triangle_soup(temp("tiny.off"), tiny);
  expect_failure(base + " --target " + temp("tiny.off"), 1, "and the source's (2^0) differ by more than 2^150");

  EXPECT_EQ(run("--help").status, 0);
}

TEST(CommandLine, ErrorsAreOneLine)
{
  for(const std::string arguments : {"--source a.off", "--source a.off --output b.off --solver newton", "--bogus 1"}) {
    const Tool_run result = run(arguments);
    EXPECT_EQ(result.status, 2) << arguments;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_NE(result.output.find("run with --help for the usage"), std::string::npos) << result.output;
  }
  // A misspelt flag is unknown wherever it comes; a known option given last lacks its value.
  for(const std::string last : {"", " --source a.off"}) {
    EXPECT_NE(run("--output b.off --untangel" + last).output.find("unknown option --untangel"), std::string::npos) << last;
    EXPECT_NE(run("--output b.off --center" + last).output.find(last.empty() ? "--center needs a value" : "--center expects"),
              std::string::npos) << last;
  }
  // Output names are quoted as input names are, control bytes escaped: one line still.
  const std::string s = temp("s_lines.off"), t = temp("t_lines.off");
  write_planar_pair(s, t);
  for(const std::string& output : {"--output '" + temp("no\nsuch") + "/o.off'", "--output " + temp("o_lines.off") + " --report '" +
                                  temp("no\nsuch") + "/r.json'"}) {
    const Tool_run result = run("--source " + s + " --target " + t + " " + output);
    EXPECT_EQ(result.status, 1) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_NE(result.output.find("no\\x0asuch"), std::string::npos) << result.output;
  }
}

TEST(CommandLine, CountsMeasuresAndFoldersAreCheckedBeforeAnyWork)
{
  const std::string s = temp("s4.off"), t = temp("t4.off"), o = temp("o4.off");
  write_planar_pair(s, t);
  const std::string base = "--source " + s + " --target " + t + " --output " + o;
  for(const std::string& bad : {std::string(" --threads -5"), std::string(" --iterations -1 --threshold 0"),
                                std::string(" --measure conformal*"), std::string(" --measure '*'"),
                                std::string(" --measure CONFORMAL"), " --fix " + ::testing::TempDir()}) {
    std::remove(o.c_str());
    const Tool_run result = run(base + bad);
    EXPECT_EQ(result.status, 2) << bad << "\n" << result.output;
    EXPECT_FALSE(exists(o)) << bad;
  }
  // The measure is checked before the meshes are read: a missing source is not what fails.
  Tool_run result = run("--source " + temp("no_such_file.off") + " --output " + o + " --measure 'conformal*'");
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_NE(result.output.find("empty factor"), std::string::npos) << result.output;
  // An input that is no regular file (/dev/zero never ends) is refused before it is read (issue 66).
  for(const std::string extension : {"ply", "stl", "ts", "off"}) {
    const std::string zero = temp("zero." + extension);
    std::remove(zero.c_str());
    ASSERT_EQ(::symlink("/dev/zero", zero.c_str()), 0);
    result = run("--source " + zero + " --output " + o);
    EXPECT_EQ(result.status, 2) << result.output;
    EXPECT_NE(result.output.find(zero + " is not a regular file"), std::string::npos) << result.output;
    std::remove(zero.c_str());
  }
}

TEST(CommandLine, NoOutputNamesAnInputOrAnotherOutput)
{
  const std::string s = temp("s5.off"), t = temp("t5.off"), o = temp("o5.off"), link = temp("link5.off");
  write_planar_pair(s, t);
  const std::string source = slurp(s), target = slurp(t);
  std::remove(link.c_str());
  ASSERT_EQ(symlink(s.c_str(), link.c_str()), 0);
  const std::string folder = ::testing::TempDir(), dotted = folder + "./" + s.substr(folder.size());
  const std::string base = "--source " + s + " --target " + t;
  for(const std::string& bad : {" --output " + s, " --output " + dotted, " --output " + link, " --output " + t,
                                " --output " + o + " --report " + s, " --output " + o + " --report " + t,
                                " --output " + o + " --report " + folder + "./" + o.substr(folder.size())}) {
    std::remove(o.c_str());
    const Tool_run result = run(base + bad);
    EXPECT_EQ(result.status, 2) << bad << "\n" << result.output;
    EXPECT_FALSE(exists(o)) << bad;
  }
  EXPECT_EQ(slurp(s), source);
  EXPECT_EQ(slurp(t), target);

  // A TetGen mesh is read from its .node and its .ele, whichever is named: --report, which takes
  // any name, overwrote the other one (exit 0).
  const IO::Tetrahedron_soup cube = kuhn_block(2);
  const auto write_tetgen = [&](const std::string& stem, double stretch) {
    std::ofstream node(stem + ".node"), ele(stem + ".ele");
    node << cube.points.size() << " 3 0 0\n";
    for(std::size_t v = 0; v < cube.points.size(); ++v)
      node << v << ' ' << stretch * cube.points[v][0] << ' ' << cube.points[v][1] << ' ' << cube.points[v][2] << '\n';
    ele << cube.cells.size() << " 4 0\n";
    for(std::size_t c = 0; c < cube.cells.size(); ++c)
      ele << c << ' ' << cube.cells[c][0] << ' ' << cube.cells[c][1] << ' ' << cube.cells[c][2] << ' ' << cube.cells[c][3] << '\n';
  };
  const std::string ts = temp("tetgen_s"), tt = temp("tetgen_t"), mesh = temp("tetgen_o.mesh");
  write_tetgen(ts, 1);
  write_tetgen(tt, 2);
  const std::string node = slurp(ts + ".node"), target_node = slurp(tt + ".node"), ele = slurp(ts + ".ele");
  for(const std::string& bad : {" --report " + ts + ".node", " --report " + tt + ".node", " --source " + ts + ".node --report " + ts + ".ele"}) {
    std::remove(mesh.c_str());
    const std::string arguments = (bad.find("--source") == std::string::npos ? "--source " + ts + ".ele" : std::string()) +
                                  " --target " + tt + ".ele --output " + mesh + " --fix none" + bad;
    const Tool_run result = run(arguments);
    EXPECT_EQ(result.status, 2) << arguments << "\n" << result.output;
    EXPECT_NE(result.output.find("it would be overwritten"), std::string::npos) << result.output;
    EXPECT_FALSE(exists(mesh)) << bad;
  }
  EXPECT_EQ(slurp(ts + ".node"), node);
  EXPECT_EQ(slurp(tt + ".node"), target_node);
  EXPECT_EQ(slurp(ts + ".ele"), ele);
  const Tool_run good = run("--source " + ts + ".ele --target " + tt + ".node --output " + mesh + " --fix none --iterations 1");
  EXPECT_EQ(good.status, 0) << good.output;
}

TEST(CommandLine, AllOutputsOrNoneAndNoFileOfTheUserTouched)
{
  const std::string s = temp("s6.off"), t = temp("t6.off"), o = temp("o6.off"), r = temp("r6.json");
  write_planar_pair(s, t);
  std::remove(o.c_str());
  // A report that cannot be written: the output is not written either.
  Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --report /nonexistent/r.json");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_FALSE(exists(o));
  EXPECT_EQ(leftovers(o), 0u);
  result = run("--source " + s + " --target " + t + " --output " + o + " --report " + ::testing::TempDir());
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_FALSE(exists(o));
  // A user's file named like a temporary of old ("o.off.partial") is left as it is.
  std::ofstream(o + ".partial") << "mine\n";
  result = run("--source " + s + " --target " + t + " --output " + o + " --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(slurp(o + ".partial"), "mine\n");
  EXPECT_TRUE(exists(o));
  EXPECT_TRUE(exists(r));
  EXPECT_EQ(leftovers(o), 0u);
  EXPECT_EQ(leftovers(r), 0u);
}

// An output that is a symbolic link fills the file it names, and the link stays; a device or a
// pipe (/dev/stdout, /dev/null) is written into, never replaced by a file.
TEST(CommandLine, OutputsGoThroughLinksAndIntoDevices)
{
  const std::string s = temp("s6l.off"), t = temp("t6l.off"), o = temp("o6l.off"), r = temp("r6l.json"), link = temp("link6l.json");
  write_planar_pair(s, t);
  std::remove(r.c_str());
  std::remove(link.c_str());
  std::ofstream(r) << "old\n";
  ASSERT_EQ(symlink(r.c_str(), link.c_str()), 0);
  Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --report " + link);
  ASSERT_EQ(result.status, 0) << result.output;
  struct stat st;
  ASSERT_EQ(::lstat(link.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode));
  EXPECT_NE(slurp(r).find("\"final_energy\""), std::string::npos);
  EXPECT_EQ(leftovers(r), 0u);
  result = run("--source " + s + " --target " + t + " --output " + o + " --quiet --report /dev/stdout");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("\"final_energy\""), std::string::npos) << result.output;
  result = run("--source " + s + " --target " + t + " --output " + o + " --report /dev/null");
  ASSERT_EQ(result.status, 0) << result.output;
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  // A device whose write fails fails the run before any file is renamed into place.
  if(::stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode)) {
    std::remove(o.c_str());
    expect_failed_cleanly(run("--source " + s + " --target " + t + " --output " + o + " --report /dev/full"),
                          "/dev/full: write error", o);
  }
  // A link to nothing is refused before any work, and nothing is written.
  std::remove(o.c_str());
  std::remove(link.c_str());
  ASSERT_EQ(symlink(temp("nowhere/r.json").c_str(), link.c_str()), 0);
  result = run("--source " + s + " --target " + t + " --output " + o + " --report " + link);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("a symbolic link to nothing"), std::string::npos) << result.output;
  EXPECT_FALSE(exists(o));
  // A named pipe that no program reads fails the run at the end instead of waiting for a reader
  // without end (issue 66); nothing is written.
  const std::string fifo = temp("fifo6l.svg");
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  expect_failed_cleanly(run("--source " + s + " --target " + t + " --output " + o + " --svg " + fifo),
                        fifo + ": a pipe that no program reads", o);
  std::remove(fifo.c_str());
  // A read-only output is replaced and stays read-only.
  std::ofstream(o) << "old\n";
  ASSERT_EQ(::chmod(o.c_str(), 0444), 0);
  result = run("--source " + s + " --target " + t + " --output " + o);
  ASSERT_EQ(result.status, 0) << result.output;
  ASSERT_EQ(::stat(o.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0444u);
  EXPECT_NE(slurp(o), "old\n");
  std::remove(o.c_str());
}

TEST(CommandLine, AnEndlessLineInTheFixFileCostsNoMemory)
{
  const std::string s = temp("s7.off"), t = temp("t7.off"), o = temp("o7.off"), fix = temp("endless.txt");
  write_planar_pair(s, t);
  {
    std::ofstream out(fix, std::ios::binary);
    const std::string block(1 << 20, '7');
    for(int k = 0; k < 64; ++k) out << block;   // 64 MB, no newline
  }
  const Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --fix " + fix);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("longer than"), std::string::npos) << result.output;
  rusage usage;
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 48 * 1024) << "kB at most in any child so far";
  std::remove(fix.c_str());
}

TEST(CommandLine, TheToolsOwnStartHasTheSourcesOrientation)
{
  // A planar disk listed clockwise, without --target: the Tutte start is mirrored to match it.
  const std::string s = temp("s8.off"), t = temp("t8.off"), cw = temp("cw8.off"), o = temp("o8.off");
  write_planar_pair(s, t);
  IO::Triangle_soup clockwise = IO::read_triangle_soup(s);
  for(auto& c : clockwise.cells) std::swap(c[1], c[2]);
  IO::write_triangle_soup(cw, clockwise);
  const Tool_run result = run("--source " + cw + " --output " + o + " --measure symmetric_dirichlet");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("inverted_cells  0"), std::string::npos) << result.output;
  // A planar source that folds over itself: every start inverts its folded triangles. Refused,
  // naming --untangle, which unfolds the start to match them.
  IO::Triangle_soup folding = IO::read_triangle_soup(s);
  folding.points[6 * 13 + 6][0] += 0.2;   // the middle vertex, past its right neighbour
  IO::write_triangle_soup(temp("fold8.off"), folding);
  Tool_run fold = run("--source " + temp("fold8.off") + " --output " + o);
  EXPECT_EQ(fold.status, 1) << fold.output;
  EXPECT_NE(fold.output.find("the planar source folds over itself ("), std::string::npos) << fold.output;
  fold = run("--source " + temp("fold8.off") + " --output " + o + " --untangle");
  ASSERT_EQ(fold.status, 0) << fold.output;
  EXPECT_NE(fold.output.find("inverted_cells  0"), std::string::npos) << fold.output;
  // Far from unit size (CGAL's parameterizer squares lengths): the same optimized energy, listed
  // either way, and a valid map. (Not the same map to the bit: the start is parameterized on a copy,
  // and the runs stop at the threshold.)
  const std::string far = temp("far8.off"), report = temp("far8.json");
  for(const std::string& name : {s, cw}) {
    const Tool_run unit = run("--source " + name + " --output " + o + " --measure symmetric_dirichlet --report " + report);
    ASSERT_EQ(unit.status, 0) << unit.output;
    const double expected = json_value(slurp(report), "final_energy");
    for(const int e : {300, -1000}) {
      IO::Triangle_soup scaled = IO::read_triangle_soup(name);
      for(auto& p : scaled.points)
        for(double& x : p) x = std::ldexp(x, e);
      IO::write_triangle_soup(far, scaled);
      const Tool_run scaled_run = run("--source " + far + " --output " + o + " --measure symmetric_dirichlet --report " + report);
      ASSERT_EQ(scaled_run.status, 0) << e << ": " << scaled_run.output;
      const std::string json = slurp(report);
      EXPECT_NEAR(json_value(json, "final_energy"), expected, 1e-3 * expected) << e;
      EXPECT_EQ(json_value(json, "inverted_cells"), 0) << e;
    }
  }
}

namespace {

// The cube [-1, 1]^3 as a closed, outward-oriented OFF surface, and an octahedron of the given
// radius about c (a surface to carry).
void write_cube(const std::string& path)
{
  std::ofstream(path) << "OFF\n8 12 0\n-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n1 1 1\n"
                         "3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n"
                         "3 1 3 5\n3 3 7 5\n";
}

// The icosahedron's faces split in four `levels` times, on the unit sphere, with y scaled by
// `squash` (0.01 makes a knife-edged disc); with `spike`, its first vertex pulled out to
// y = spike (a needle); with `star`, its 12 first vertices pushed out `star` times as far (twelve
// spikes Mesh_3 takes minutes to protect).
void write_icosphere(const std::string& path, int levels, double squash, double spike = 0, double star = 0)
{
  const double g = (1 + std::sqrt(5.)) / 2;
  std::vector<std::array<double, 3>> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                          {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<std::size_t, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                               {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                               {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  const auto unit = [](std::array<double, 3> x) {
    const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    return std::array<double, 3>{x[0] / n, x[1] / n, x[2] / n};
  };
  for(auto& x : p) x = unit(x);
  for(int level = 0; level < levels; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    const auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::minmax(a, b);
      if(const auto m = middle.find(key); m != middle.end()) return m->second;
      p.push_back(unit({p[a][0] + p[b][0], p[a][1] + p[b][1], p[a][2] + p[b][2]}));
      return middle[key] = p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> finer;
    for(const auto& t : f) {
      const std::size_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    f = finer;
  }
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << p.size() << ' ' << f.size() << " 0\n";
  if(spike > 0) p[0][1] = spike / squash;
  for(std::size_t i = 0; i < 12 && star > 0; ++i) p[i] = {star * p[i][0], star * p[i][1], star * p[i][2]};
  for(const auto& x : p) out << x[0] << ' ' << squash * x[1] << ' ' << x[2] << '\n';
  for(const auto& t : f) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void write_octahedron(const std::string& path, double r, double c = 0)
{
  std::ofstream out(path);
  out << "OFF\n6 8 0\n";
  for(int a = 0; a < 3; ++a)
    for(double s : {r, -r}) out << (a == 0 ? c + s : c) << ' ' << (a == 1 ? s : 0) << ' ' << (a == 2 ? s : 0) << '\n';
  out << "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
}

// The vertices on the boundary facets of a tetrahedron soup (facets in one tetrahedron only).
std::vector<std::size_t> boundary_of(const IO::Tetrahedron_soup& soup)
{
  std::map<std::array<std::size_t, 3>, int> facets;
  for(const auto& t : soup.cells)
    for(int i = 0; i < 4; ++i) {
      std::array<std::size_t, 3> f = {t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4]};
      std::sort(f.begin(), f.end());
      ++facets[f];
    }
  std::vector<std::size_t> vertices;
  for(const auto& [f, count] : facets)
    if(count == 1) vertices.insert(vertices.end(), f.begin(), f.end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

std::size_t non_positive_tetrahedra(const IO::Tetrahedron_soup& soup)
{
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::size_t count = 0;
  for(const auto& t : soup.cells) {
    auto p = [&](int k) { return P(soup.points[t[k]][0], soup.points[t[k]][1], soup.points[t[k]][2]); };
    count += CGAL::orientation(p(0), p(1), p(2), p(3)) != CGAL::POSITIVE;
  }
  return count;
}

} // namespace

// The volume mode end to end (issue 14): a closed surface meshed by Mesh_3, mapped onto the ball
// with its boundary sliding on the sphere, a surface carried through; the two .mesh files form a
// source/target pair.
TEST(CommandLine, VolumeModeMapsAClosedSurfaceOntoTheBallAndCarriesASurface)
{
  const std::string cube = temp("cube.off"), inner = temp("inner.off"), o = temp("ball.mesh"), m = temp("cube.mesh"),
                    carried = temp("carried.off"), r = temp("ball.json");
  write_cube(cube);
  write_octahedron(inner, 0.5, 0.2);
  const Tool_run result = run("--source " + cube + " --start ball --output " + o + " --mesh-output " + m +
                              " --cell-size 0.4 --measure isometric --carry " + inner + " --carry-output " + carried +
                              " --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const IO::Tetrahedron_soup source = IO::read_tetrahedron_soup(m), target = IO::read_tetrahedron_soup(o);
  ASSERT_EQ(source.cells, target.cells);
  ASSERT_EQ(source.points.size(), target.points.size());
  EXPECT_GT(source.cells.size(), 500u);
  EXPECT_EQ(non_positive_tetrahedra(source), 0u);
  EXPECT_EQ(non_positive_tetrahedra(target), 0u);
  const auto boundary = boundary_of(source);
  for(std::size_t v : boundary) {
    const auto& p = source.points[v];
    EXPECT_NEAR(std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}), 1., 1e-12);   // on the cube
    const auto& q = target.points[v];
    EXPECT_NEAR(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), 1., 1e-12);          // on the sphere
  }
  const std::string json = slurp(r);
  EXPECT_EQ(json_value(json, "tets"), double(source.cells.size()));
  EXPECT_EQ(json_value(json, "boundary_vertices"), double(boundary.size()));
  EXPECT_EQ(json_value(json, "inverted_cells"), 0.);
  EXPECT_EQ(json_value(json, "carried_vertices"), 6.);
  EXPECT_EQ(json_value(json, "carried_outside"), 0.);
  EXPECT_GE(json_value(json, "mesh_seconds"), 0.);
  EXPECT_LT(json_value(json, "final_energy"), json_value(json, "initial_energy"));
  EXPECT_GE(json_value(json, "start_energy_carried"), 1.);
  EXPECT_GE(json_value(json, "final_energy_carried"), 1.);
  // The table gives the added reals as its own: seconds to the millisecond, energies to 12 digits.
  for(const auto& [name, format] : {std::pair<std::string, const char*>{"mesh_seconds", "%.3f"}, {"final_energy_carried", "%.12g"}}) {
    char expected[64];
    std::snprintf(expected, sizeof expected, format, json_value(json, name));
    EXPECT_NE(result.output.find("\n" + name + std::string(21 - name.size() + 1, ' ') + expected + "\n"), std::string::npos)
      << name << " " << expected << "\n" << result.output;
  }
  const IO::Triangle_soup in = IO::read_triangle_soup(inner), out = IO::read_triangle_soup(carried);
  EXPECT_EQ(in.cells, out.cells);
  ASSERT_EQ(out.points.size(), 6u);
  for(const auto& q : out.points) EXPECT_LT(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), 1.);

  // A point in no tetrahedron, far away, is no part of the volume's size: it keeps its position.
  IO::Tetrahedron_soup with_unused = source;
  with_unused.points.push_back({1e40, 0, 0});
  if(!with_unused.point_labels.empty()) with_unused.point_labels.push_back(0);
  const std::string unused = temp("unused.mesh"), o3 = temp("unused_out.mesh");
  IO::write_MEDIT_soup(unused, with_unused);
  const Tool_run far = run("--source " + unused + " --start ball --output " + o3 + " --iterations 2");
  ASSERT_EQ(far.status, 0) << far.output;
  EXPECT_EQ(IO::read_tetrahedron_soup(o3).points.back(), with_unused.points.back());

  // The written source again, radial start about the origin with a fixed boundary: the boundary
  // keeps the radial map's image, x |x|.
  const std::string o2 = temp("radial.mesh");
  const Tool_run radial = run("--source " + m + " --start radial --center 0,0,0 --boundary fixed --output " + o2 +
                              " --iterations 5");
  ASSERT_EQ(radial.status, 0) << radial.output;
  const IO::Tetrahedron_soup radial_map = IO::read_tetrahedron_soup(o2);
  EXPECT_EQ(non_positive_tetrahedra(radial_map), 0u);
  for(std::size_t v : boundary) {
    const auto& p = source.points[v];
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for(int k = 0; k < 3; ++k) EXPECT_EQ(radial_map.points[v][k], n * p[k]);
  }

  // --fix none frees the ball start's boundary, as --help says (it slid on the sphere, issue 66):
  // the boundary leaves the sphere, no cell inverted.
  const std::string o4 = temp("ball_free.mesh");
  const Tool_run free_ball = run("--source " + m + " --start ball --fix none --output " + o4 + " --iterations 5");
  ASSERT_EQ(free_ball.status, 0) << free_ball.output;
  const IO::Tetrahedron_soup freed = IO::read_tetrahedron_soup(o4);
  EXPECT_EQ(non_positive_tetrahedra(freed), 0u);
  double off_sphere = 0;
  for(std::size_t v : boundary) {
    const auto& q = freed.points[v];
    off_sphere = std::max(off_sphere, std::abs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) - 1.));
  }
  EXPECT_GT(off_sphere, 1e-3);
}

// The temporary files exist only while the outputs are written: a run killed while it computes
// (SIGKILL cannot be caught, nor the out-of-memory killer) leaves nothing behind (issue 66).
TEST(CommandLine, ARunKilledWhileItComputesLeavesNoFile)
{
  const std::string cube = temp("cube_killed.off"), o = temp("killed.mesh"), m = temp("killed_source.mesh"),
                    r = temp("killed.json");
  write_cube(cube);
  for(const std::string& f : {o, m, r}) std::remove(f.c_str());
  for(const char* signal : {"KILL", "USR1"}) {
    const std::string command = "timeout --preserve-status -s " + std::string(signal) + " 1 " + std::string(DISTORTION_OPTIMIZER) +
                                " --source " + cube + " --start ball --cell-size 0.04 --output " + o + " --mesh-output " +
                                m + " --report " + r + " > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_GE(WEXITSTATUS(status), 128) << signal << ": the run was to be ended by the signal";
    for(const std::string& f : {o, m, r}) {
      EXPECT_FALSE(exists(f)) << signal << " " << f;
      EXPECT_EQ(leftovers(f), 0u) << signal << " " << f;
    }
  }
}

// --time-limit covers the meshing too (issue 66): Mesh_3 stops at the limit (it would run far
// past it at this size), and the run fails with nothing written.
TEST(CommandLine, TheTimeLimitStopsTheMeshing)
{
  const std::string cube = temp("cube_limit.off"), o = temp("limit.mesh");
  write_cube(cube);
  std::remove(o.c_str());
  expect_failed_cleanly(run("--source " + cube + " --start ball --cell-size 0.02 --time-limit 0.5 --output " + o),
                        "Mesh_3 did not finish within the time limit of 0.5 s", o);
  // Twelve spikes (17 s in Mesh_3 without a limit; over two minutes before the exudation had one)
  // stop at the limit too.
  const std::string star = temp("star.off");
  write_icosphere(star, 2, 1, 0, 8);
  expect_failed_cleanly(run("--source " + star + " --start radial --time-limit 1 --output " + o),
                        "Mesh_3 did not finish within the time limit of 1 s", o);
  // A needle's tip (faces meeting within 0.25 degrees there) is refused before Mesh_3 runs (92 s
  // for this one).
  const std::string spike = temp("spike.off");
  write_icosphere(spike, 2, 1, 255);
  expect_failed_cleanly(run("--source " + spike + " --start radial --output " + o), "has a needle tip at a corner of face", o);
  // A knife-edged disc is refused before Mesh_3 runs (its rim's protection took minutes at the
  // sizes its thickness allows).
  const std::string disc = temp("flat_disc.off");
  write_icosphere(disc, 2, 0.01);
  expect_failed_cleanly(run("--source " + disc + " --start radial --cell-size 0.026 --output " + o),
                        "is a slab whose rim is a knife edge", o);
}

TEST(CommandLine, VolumeModeBadInputGivesAOneLineErrorAndWritesNothing)
{
  const std::string cube = temp("cube2.off"), o = temp("vol.mesh"), m = temp("vol_source.mesh"), c = temp("vol_carried.off");
  write_cube(cube);
  auto expect_failure = [&](const std::string& arguments, int status, const std::string& fragment) {
    const Tool_run result = run(arguments);
    EXPECT_EQ(result.status, status) << arguments << "\n" << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_NE(result.output.find(fragment), std::string::npos) << arguments << "\n" << result.output;
    for(const std::string& f : {o, m, c}) {
      EXPECT_FALSE(exists(f)) << arguments;
      EXPECT_EQ(leftovers(f), 0u) << arguments;
    }
  };
  const std::string base = " --output " + o + " --mesh-output " + m + " --cell-size 0.5";
  // An open surface: the cube without its last face.
  const std::string open = temp("open.off");
  IO::Triangle_soup soup = IO::read_triangle_soup(cube);
  soup.cells.pop_back();
  IO::write_triangle_soup(open, soup);
  expect_failure("--source " + open + " --start ball" + base, 1, "border");
  // Two cubes that cross each other.
  const std::string crossing = temp("crossing.off");
  IO::Triangle_soup two = IO::read_triangle_soup(cube);
  for(std::size_t i = 0; i < 8; ++i) two.points.push_back({two.points[i][0] + 1, two.points[i][1] + 0.5, two.points[i][2] + 0.25});
  for(std::size_t f = 0; f < 12; ++f) two.cells.push_back({two.cells[f][0] + 8, two.cells[f][1] + 8, two.cells[f][2] + 8});
  IO::write_triangle_soup(crossing, two);
  expect_failure("--source " + crossing + " --start ball" + base, 1, "cross");
  expect_failure("--source " + cube + " --start ball --center 5,0,0" + base, 1, "--center is not inside the volume");
  expect_failure("--source " + cube + " --start radial --center 5,0,0" + base, 1, "--center is not inside the volume");
  // Nor on its boundary: a corner (a vertex of the mesh), a point of an edge, of a face.
  for(const std::string centre : {"-1,-1,-1", "1,1,0", "1,0.25,0.5"})
    for(const std::string start : {"ball", "radial"})
      expect_failure("--source " + cube + " --start " + start + " --center " + centre + base, 1, "--center is not inside the volume");
  // Two cubes apart: their centroid, the default centre, is in neither.
  const std::string apart = temp("apart.off");
  IO::Triangle_soup pair = IO::read_triangle_soup(cube);
  for(std::size_t i = 0; i < 8; ++i) pair.points.push_back({pair.points[i][0] + 3, pair.points[i][1], pair.points[i][2]});
  for(std::size_t f = 0; f < 12; ++f) pair.cells.push_back({pair.cells[f][0] + 8, pair.cells[f][1] + 8, pair.cells[f][2] + 8});
  IO::write_triangle_soup(apart, pair);
  expect_failure("--source " + apart + " --start radial" + base, 1, "the centroid of the volume is outside it");
  // A tetrahedral source whose cells fold over each other is refused before any work.
  const std::string folded = temp("folded.mesh");
  IO::Tetrahedron_soup fold;
  fold.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 1}};
  fold.cells = {{0, 1, 2, 3}, {2, 1, 0, 4}};
  IO::write_MEDIT_soup(folded, fold);
  expect_failure("--source " + folded + " --start radial --center 0.1,0.1,0.1 --output " + o, 1, "lie on the same side of their common facet");
  // So is one whose separate parts overlap (issue 66), here as a mesh to improve.
  const std::string overlapping = temp("overlapping.mesh");
  fold.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 0.2}, {1.2, 0.2, 0.2}, {0.2, 1.2, 0.2}, {0.2, 0.2, 1.2}};
  fold.cells = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  IO::write_MEDIT_soup(overlapping, fold);
  expect_failure("--source " + overlapping + " --reference ideal --output " + temp("overlapping_out.mesh"), 1,
                 "the tetrahedra overlap: their boundary passes through itself");
  const std::string outside = temp("outside.off");
  write_octahedron(outside, 0.5, 0.8);   // reaches x = 1.3
  expect_failure("--source " + cube + " --start ball" + base + " --carry " + outside + " --carry-output " + c, 1,
                 "1 point is outside the volume (in no cell of the complex): 0 (--snap moves such points onto its boundary)");
  // Wholly outside, --snap would flatten it onto the boundary (issue 66); a coordinate too large
  // for the computations (it crashed the snap) is refused as the file is read.
  const std::string away = temp("away.off"), far = temp("far.off");
  write_octahedron(away, 0.5, 10);
  expect_failure("--source " + cube + " --start ball" + base + " --carry " + away + " --carry-output " + c + " --snap", 1,
                 "all its 6 vertices are outside the volume, and --snap would flatten it onto the volume's boundary");
  write_octahedron(far, 0.5, 1e307);
  expect_failure("--source " + cube + " --start ball" + base + " --carry " + far + " --carry-output " + c + " --snap", 1,
                 "is beyond 1e+100 in magnitude");
  // The command line.
  expect_failure("--source " + cube + " --start sphere" + base, 2, "--start is ball or radial");
  expect_failure("--source " + cube + " --start ball --target " + cube + base, 2, "give one");
  expect_failure("--source " + cube + " --output " + temp("x.off") + " --mesh-output " + m, 2, "--mesh-output needs --start");
  expect_failure("--source " + cube + " --start ball --boundary loose" + base, 2, "--boundary is slide or fixed");
  expect_failure("--source " + cube + " --start ball --fix boundary" + base, 2, "contradict");
  expect_failure("--source " + cube + " --start ball --center 1,2" + base, 2, "--center expects X,Y,Z");
  expect_failure("--source " + cube + " --start ball --cell-size 0" + " --output " + o, 2, "--cell-size must be a positive number");
  expect_failure("--source " + cube + " --start ball --cell-size 1e-4 --output " + o, 1,
                 "vertices, more than 2 million (cell size 0.0001, facet size");
  expect_failure("--source " + cube + " --start ball --cell-size 1e-4 --output " + o, 1, "; give a larger --cell-size");
  const std::string plate = temp("plate.off");   // 2 x 2 x 2e-6: thinner than the default facet distance
  std::ofstream(plate) << "OFF\n8 12 0\n-1 -1 -1e-6\n1 -1 -1e-6\n-1 1 -1e-6\n1 1 -1e-6\n-1 -1 1e-6\n1 -1 1e-6\n-1 1 1e-6\n"
                          "1 1 1e-6\n3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n3 2 6 3\n3 3 6 7\n3 0 4 2\n"
                          "3 2 4 6\n3 1 3 5\n3 3 7 5\n";
  expect_failure("--source " + plate + " --start ball --output " + o, 1,
                 "the volume is thinner (2 volume / area = 2e-06) than half the facet size");
  // The size that would mesh it asks for far more vertices than fit: no advice that cannot work.
  expect_failure("--source " + plate + " --start ball --output " + o, 1,
                 "its boundary, and a facet size that would (below 2e-06) asks for about 4.2e+12 vertices, more than the "
                 "maximum: the part is too thin to mesh");
  expect_failure("--source " + cube + " --start ball" + base + " --carry " + cube, 2, "go together");
  expect_failure("--source " + cube + " --start ball --output " + temp("x.off"), 2, "--output must end in .mesh or .vtu");
}

// A closed surface far from the origin (a cube centred at (10^9, 10^9, 10^9)) is meshed and mapped
// like any other: its volume, summed about the origin, once came out as none.
TEST(CommandLine, VolumeModeTakesASurfaceFarFromTheOrigin)
{
  const std::string cube = temp("cube_far.off"), o = temp("far.mesh"), m = temp("far_source.mesh");
  write_cube(cube);
  IO::Triangle_soup far = IO::read_triangle_soup(cube);
  for(auto& p : far.points)
    for(double& x : p) x += 1e9;
  IO::write_triangle_soup(cube, far);
  const Tool_run result = run("--source " + cube + " --start ball --cell-size 0.5 --iterations 3 --output " + o + " --mesh-output " + m);
  ASSERT_EQ(result.status, 0) << result.output;
  const IO::Tetrahedron_soup source = IO::read_tetrahedron_soup(m), target = IO::read_tetrahedron_soup(o);
  EXPECT_EQ(non_positive_tetrahedra(target), 0u);
  EXPECT_EQ(source.cells, target.cells);
  for(const auto& p : source.points)
    for(double x : p) EXPECT_NEAR(x, 1e9, 1.000001);
}

// An elongated volume, an 8 x 2 x 2 box, onto the ball: a ball map that squeezes it across its
// length onto narrow cones about its axis leaves cells that untangling with the boundary sliding
// cannot repair. The ball map whitens the volume first (volume_maps.h).
TEST(CommandLine, VolumeModeMapsAnElongatedBoxOntoTheBall)
{
  const std::string box = temp("long_box.off"), o = temp("long_box.mesh");
  write_cube(box);
  IO::Triangle_soup soup = IO::read_triangle_soup(box);
  for(auto& p : soup.points) p[0] *= 4;
  IO::write_triangle_soup(box, soup);
  const Tool_run result = run("--source " + box + " --start ball --iterations 3 --output " + o);
  ASSERT_EQ(result.status, 0) << result.output;
  const IO::Tetrahedron_soup target = IO::read_tetrahedron_soup(o);
  EXPECT_GT(target.cells.size(), 20000u);
  EXPECT_EQ(non_positive_tetrahedra(target), 0u);
  double farthest = 0;
  for(const auto& p : target.points) farthest = std::max(farthest, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
  EXPECT_NEAR(farthest, 1., 1e-12);
}

TEST(CommandLine, ABallMapAboutASpikeStartsFromItsHarmonicInside)
{
  // Hostile round 3's sphere with one vertex pulled out three times (D6e): the ball map's rays
  // crush the spike's inside, and untangling it with the boundary sliding left one cell inverted
  // after a minute. From the harmonic map of the same boundary, where untangle() starts since it
  // flattens fewer cells, it untangles at once.
  const std::string spike = temp("spike_ball.off"), o = temp("spike_ball.mesh"), r = temp("spike_ball.json");
  write_icosphere(spike, 2, 1);
  IO::Triangle_soup soup = IO::read_triangle_soup(spike);
  for(double& x : soup.points[11]) x *= 3;
  IO::write_triangle_soup(spike, soup);
  const Tool_run result = run("--source " + spike + " --start ball --iterations 3 --output " + o + " --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string json = slurp(r);
  EXPECT_GT(json_value(json, "inverted_start_cells"), 0) << json;
  EXPECT_EQ(json_value(json, "inverted_cells"), 0) << json;
  EXPECT_EQ(non_positive_tetrahedra(IO::read_tetrahedron_soup(o)), 0u);
}

TEST(CommandLine, EnergiesFarAboveOneAndSubnormalCoordinatesAreOptimizedAsAnyOther)
{
  // A source 2^140 and 2^150 times larger than its target: symmetric Dirichlet is then |J^-1|^2
  // alone, 2^280 and 2^300 times larger, and the two problems are exact power-of-two rescalings of
  // each other: the same map, bit for bit, with energies in the ratio 2^20. Before the optimizer
  // scaled its weights, the local steps' squared gradients overflowed from about 2^146 and the
  // run stopped near its start, converged.
  const std::string s = temp("s9.off"), t = temp("t9.off"), far = temp("far9.off"), o = temp("o9.off"), report = temp("r9.json");
  write_planar_pair(s, t);
  const IO::Triangle_soup unit = IO::read_triangle_soup(s);
  std::vector<std::array<double, 3>> optimized;
  std::vector<double> energies;
  for(const int k : {140, 150}) {
    IO::Triangle_soup scaled = unit;
    for(auto& p : scaled.points)
      for(double& x : p) x = std::ldexp(x, k);
    IO::write_triangle_soup(far, scaled);
    const Tool_run result = run("--source " + far + " --target " + t + " --output " + o + " --measure symmetric_dirichlet --schedule local --report " + report);
    ASSERT_EQ(result.status, 0) << k << ": " << result.output;
    const std::string json = slurp(report);
    EXPECT_LT(json_value(json, "final_energy"), 0.9 * json_value(json, "initial_energy")) << k;
    EXPECT_EQ(json_value(json, "inverted_cells"), 0) << k;
    energies.push_back(json_value(json, "final_energy"));
    const auto points = IO::read_triangle_soup(o).points;
    if(!optimized.empty()) {
      EXPECT_TRUE(points == optimized) << k;
    }
    optimized = points;
  }
  EXPECT_EQ(energies[1], std::ldexp(energies[0], 20));
  // Source and target both subnormal (2^-1040): scaled by 2^1023, the largest power of two a double
  // holds (the factor 2^1040 overflowed, and every face was called degenerate). The coordinates keep
  // 34 bits: the energy is the unscaled pair's to about 1e-9.
  const Tool_run unscaled = run("--source " + s + " --target " + t + " --output " + o + " --measure conformal --report " + report);
  ASSERT_EQ(unscaled.status, 0) << unscaled.output;
  const double expected = json_value(slurp(report), "final_energy");
  const std::string tiny_target = temp("tiny_t9.off");
  for(const auto& [from, to] : {std::pair<std::string, std::string>{s, far}, {t, tiny_target}}) {
    IO::Triangle_soup scaled = IO::read_triangle_soup(from);
    for(auto& p : scaled.points)
      for(double& x : p) x = std::ldexp(x, -1040);
    IO::write_triangle_soup(to, scaled);
  }
  const Tool_run tiny = run("--source " + far + " --target " + tiny_target + " --output " + o + " --measure conformal --report " + report);
  ASSERT_EQ(tiny.status, 0) << tiny.output;
  const std::string json = slurp(report);
  EXPECT_NEAR(json_value(json, "final_energy"), expected, 1e-8 * expected);
  EXPECT_EQ(json_value(json, "inverted_cells"), 0);
}

TEST(CommandLine, VolumeModeGivesTheSameMapAtAnyScale)
{
  // The cube scaled by 2^k: Mesh_3 meshes a copy at unit size (on its own it crashed at 2^-60),
  // so the source mesh written is the unscaled one scaled, bit for bit; the conformal distortion,
  // invariant under scaling, optimizes to the same energy though the unit ball is 2^100 times
  // larger or smaller than the source. Beyond 2^100 in 3D, the sizes are refused as such.
  const std::string cube = temp("cube_k.off"), o = temp("k.mesh"), m = temp("k_source.mesh"), report = temp("k.json");
  write_cube(cube);
  const IO::Triangle_soup unit = IO::read_triangle_soup(cube);
  IO::Tetrahedron_soup reference;
  double reference_energy = 0;
  for(const int k : {0, -100, 100, 120}) {
    IO::Triangle_soup scaled = unit;
    for(auto& p : scaled.points)
      for(double& x : p) x = std::ldexp(x, k);
    IO::write_triangle_soup(cube, scaled);
    std::ostringstream size;
    size << std::setprecision(17) << std::ldexp(0.5, k);
    const Tool_run result = run("--source " + cube + " --start ball --measure conformal --cell-size " + size.str() +
                                " --iterations 3 --output " + o + " --mesh-output " + m + " --report " + report);
    if(k == 120) {
      EXPECT_EQ(result.status, 1) << result.output;
      EXPECT_NE(result.output.find("differ by more than 2^100: distortions cannot be evaluated in double precision; "
                                   "scale the source"), std::string::npos) << result.output;
      continue;
    }
    ASSERT_EQ(result.status, 0) << k << ": " << result.output;
    IO::Tetrahedron_soup source = IO::read_tetrahedron_soup(m);
    const IO::Tetrahedron_soup target = IO::read_tetrahedron_soup(o);
    EXPECT_EQ(non_positive_tetrahedra(target), 0u) << k;
    const double energy = json_value(slurp(report), "final_energy");
    for(auto& p : source.points)
      for(double& x : p) x = std::ldexp(x, -k);
    if(k == 0) {
      reference = source;
      reference_energy = energy;
      continue;
    }
    EXPECT_TRUE(source.points == reference.points && source.cells == reference.cells) << k;
    EXPECT_NEAR(energy, reference_energy, 1e-9 * reference_energy) << k;
  }
}

// --reference ideal (issue 16): the source mesh itself improved against regular cells, 2D with a
// fixed border, 3D with the boundary sliding on the source's and its sharp edges fixed.
TEST(CommandLine, ReferenceIdealImprovesTheSourceMesh)
{
  const std::string unused = temp("ideal_unused.off"), planar = temp("ideal_planar.off"), o = temp("ideal_out.off"),
                    r = temp("ideal.json");
  write_planar_pair(unused, planar, 0.03);   // the perturbed grid is the mesh to improve
  const std::string picture = temp("ideal_quality.svg");
  Tool_run result = run("--source " + planar + " --reference ideal --output " + o + " --report " + r + " --svg " + picture +
                        " --svg-both");
  ASSERT_EQ(result.status, 0) << result.output;
  // The picture: the radius ratio of each triangle, before and after.
  const std::string svg = slurp(picture);
  EXPECT_EQ(occurrences(svg, "<polygon"), 2 * 288u);
  EXPECT_NE(svg.find(">radius ratio per cell, "), std::string::npos);
  EXPECT_NE(svg.find(">after</text>"), std::string::npos);
  const IO::Triangle_soup before = IO::read_triangle_soup(planar), after = IO::read_triangle_soup(o);
  EXPECT_EQ(before.cells, after.cells);
  for(std::size_t v = 0; v < before.points.size(); ++v) {
    const auto& p = before.points[v];
    if(p[0] == 0 || p[1] == 0 || p[0] == 2 || p[1] == 1) {
      EXPECT_EQ(after.points[v], p);   // the border is fixed
    }
  }
  std::string json = slurp(r);
  EXPECT_EQ(json_value(json, "inverted_cells"), 0.);
  EXPECT_GT(json_value(json, "mean_radius_ratio_after"), json_value(json, "mean_radius_ratio_before"));
  EXPECT_GE(json_value(json, "min_dihedral_after"), json_value(json, "min_dihedral_before"));
  EXPECT_LE(json_value(json, "slivers_after"), json_value(json, "slivers_before"));

  // A Mesh_3 cube (from the volume mode), improved with its boundary sliding on the cube.
  const std::string cube = temp("ideal_cube.off"), m = temp("ideal_cube.mesh"), ball = temp("ideal_ball.mesh"),
                    improved = temp("ideal_cube_out.mesh");
  write_cube(cube);
  ASSERT_EQ(run("--source " + cube + " --start ball --cell-size 0.3 --iterations 1 --output " + ball + " --mesh-output " + m).status, 0);
  result = run("--source " + m + " --reference ideal --boundary slide --output " + improved + " --report " + r);
  ASSERT_EQ(result.status, 0) << result.output;
  const IO::Tetrahedron_soup source = IO::read_tetrahedron_soup(m), target = IO::read_tetrahedron_soup(improved);
  EXPECT_EQ(source.cells, target.cells);
  EXPECT_EQ(non_positive_tetrahedra(target), 0u);
  std::size_t moved = 0;
  for(std::size_t v : boundary_of(source)) {
    const auto& p = source.points[v];
    const auto& q = target.points[v];
    EXPECT_NEAR(std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])}), 1., 1e-12);   // on the cube
    int on_faces = 0;
    for(int k = 0; k < 3; ++k) on_faces += std::abs(p[k]) == 1;
    if(on_faces >= 2) {
      EXPECT_EQ(q, p);   // on an edge or a corner: sharp, fixed
    }
    moved += q != p;
  }
  EXPECT_GT(moved, 0u);
  json = slurp(r);
  EXPECT_EQ(json_value(json, "inverted_cells"), 0.);
  EXPECT_GT(json_value(json, "mean_radius_ratio_after"), json_value(json, "mean_radius_ratio_before"));
  EXPECT_GT(json_value(json, "min_dihedral_after"), json_value(json, "min_dihedral_before"));
  EXPECT_LE(json_value(json, "slivers_after"), json_value(json, "slivers_before"));

  // A Medit file's vertex references and boundary triangles (CGAL's surface patches) are kept.
  const std::string sphere = temp("ideal_sphere.mesh");
  ASSERT_EQ(run("--source " + data("sphere.mesh") + " --reference ideal --iterations 1 --output " + sphere).status, 0);
  const IO::Tetrahedron_soup given = IO::read_tetrahedron_soup(data("sphere.mesh")), kept = IO::read_tetrahedron_soup(sphere);
  EXPECT_EQ(kept.cells, given.cells);
  EXPECT_EQ(kept.labels, given.labels);
  EXPECT_EQ(kept.point_labels, given.point_labels);
  EXPECT_EQ(kept.triangles, given.triangles);
  EXPECT_EQ(kept.triangle_labels, given.triangle_labels);
  EXPECT_EQ(kept.triangles.size(), 694u);

  // Scaled by a power of two (exactly), the sphere slides to the same result scaled: the ideal
  // cells' cube roots once differed in the last place, and the sliding run in the fifth digit.
  IO::Tetrahedron_soup unit_result;
  for(double scale : {1., 2., 0x1p-10}) {
    IO::Tetrahedron_soup scaled = given;
    for(auto& p : scaled.points)
      for(double& x : p) x *= scale;
    const std::string in = temp("ideal_sphere_in.mesh"), out = temp("ideal_sphere_slid.mesh");
    IO::write_MEDIT_soup(in, scaled);
    ASSERT_EQ(run("--source " + in + " --reference ideal --boundary slide --iterations 4 --output " + out).status, 0);
    IO::Tetrahedron_soup slid = IO::read_tetrahedron_soup(out);
    for(auto& p : slid.points)
      for(double& x : p) x /= scale;
    if(scale == 1) unit_result = slid;
    EXPECT_EQ(slid.points, unit_result.points) << scale;
  }

  // A measure finite on flat cells would trade cells down to numerically flat ones.
  result = run("--source " + m + " --reference ideal --measure arap --output " + improved);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("the measure arap is finite on flat cells"), std::string::npos) << result.output;

  // A folded source is refused in 2D as in 3D, --untangle or not (it repairs a map's target).
  IO::Triangle_soup folded = IO::read_triangle_soup(planar);
  const std::size_t middle = std::size_t(std::max_element(folded.points.begin(), folded.points.end(), [](const auto& a, const auto& b) {
                               return std::abs(a[0] - 1) + std::abs(a[1] - 0.5) > std::abs(b[0] - 1) + std::abs(b[1] - 0.5);
                             }) - folded.points.begin());
  folded.points[middle][0] += 0.5;
  const std::string folded_file = temp("ideal_folded.off");
  IO::write_triangle_soup(folded_file, folded);
  for(const std::string untangle : {"", " --untangle"})
    expect_failed_cleanly(run("--source " + folded_file + " --reference ideal" + untangle + " --output " + temp("ideal_folded_out.off")),
                          "of its triangles are inverted or flat (--reference ideal takes a valid mesh", temp("ideal_folded_out.off"));

  // The command line.
  for(const auto& [arguments, fragment] : std::vector<std::pair<std::string, std::string>>{
        {"--source " + planar + " --reference ideal --boundary fixed --fix none", "--boundary fixed and --fix none contradict"},
        {"--source " + m + " --reference ideal --boundary fixed --fix " + r + " --output " + temp("ideal_bad.mesh"),
         "--boundary fixed and --fix FILE contradict"},
        {"--source " + planar + " --reference ideal --target " + planar, "no --target"},
        {"--source " + planar + " --reference ideal --boundary slide", "needs a tetrahedral mesh"},
        {"--source " + planar + " --reference regular", "--reference is ideal"},
        {"--source " + m + " --reference ideal --output " + temp("ideal.vtu"), "--output must end in .mesh"},
        {"--source " + planar + " --reference ideal --output " + temp("ideal.vtu"), "--output must end in .off or .obj"},
        {"--source " + planar + " --reference ideal --output " + temp("ideal.mesh"), "--output must end in .off or .obj"}}) {
    const std::string out = arguments.find("--output") == std::string::npos ? " --output " + temp("ideal_bad.off") : "";
    const Tool_run bad = run(arguments + out);
    EXPECT_EQ(bad.status, 2) << arguments << "\n" << bad.output;
    EXPECT_NE(bad.output.find(fragment), std::string::npos) << arguments << "\n" << bad.output;
  }
}

// --subdivide (issue 16.3): the optimized map and its source refined together; linear keeps the energy.
// A subdivision that cannot fit in the memory this run may take is refused before the run
// (issue 66): under a 1 GB address space, five levels of mushroom (4.7 million triangles) are;
// three levels are not.
TEST(CommandLine, ASubdivisionThatCannotFitIsRefusedAtOnce)
{
  const std::string o = temp("mushroom_sub.obj"), s2 = temp("mushroom_sub_source.off");
  std::remove(o.c_str());
  const std::string limited = "ulimit -v 1000000; " + std::string(DISTORTION_OPTIMIZER) + " --source " + data("mushroom.off") +
                              " --output " + o + " --subdivided-source " + s2 + " --subdivide ";
  Tool_run result = run_in_shell(limited + "5");
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_NE(result.output.find("--subdivide 5: about 4.71859e+06 triangles"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("give fewer levels"), std::string::npos) << result.output;
  EXPECT_FALSE(exists(o));
  result = run_in_shell(limited + "3 --iterations 2");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(exists(o));
}

// A surface whose Newton systems take the sparse solver's CHOLMOD path (lion-head subdivided once:
// more unknowns than the library's default cholmod_threshold()), with the tool's own allocator
// settings and OpenMP regions (solver_runtime.cpp): Newton's few iterations, and an
// energy below the coarse mesh's optimum, which the refined problem contains (a map of the coarse
// mesh is one of the fine mesh with the same energy: --subdivide says so above).
TEST(CommandLine, ASurfaceForTheSupernodalSolverConvergesAsNewtonDoes)
{
  const std::string coarse = temp("lion_coarse.obj"), fine_source = temp("lion_fine_source.off"),
                    fine = temp("lion_fine.obj"), r1 = temp("lion_coarse.json"), r2 = temp("lion_fine.json");
  Tool_run result = run("--source " + data("lion-head.off") + " --output " + coarse + " --measure symmetric_dirichlet --subdivide 1" +
                        " --subdivided-source " + fine_source + " --report " + r1 + " --quiet");
  ASSERT_EQ(result.status, 0) << result.output;
  result = run("--source " + fine_source + " --output " + fine + " --measure symmetric_dirichlet --report " + r2 + " --quiet");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string coarse_json = slurp(r1), fine_json = slurp(r2);
  ASSERT_EQ(json_value(fine_json, "cells"), 4 * json_value(coarse_json, "cells"));
  EXPECT_EQ(json_value(fine_json, "inverted_cells"), 0.);
  EXPECT_LE(json_value(fine_json, "sweeps"), 15.);
  const double coarse_energy = json_value(coarse_json, "final_energy");
  EXPECT_LT(json_value(fine_json, "final_energy"), (1 - 1e-3) * coarse_energy);
  EXPECT_GT(json_value(fine_json, "final_energy"), 0.99 * coarse_energy);
}

// CHOLMOD's OpenMP regions bind to the tool's own GOMP_parallel (solver_runtime.cpp), which the
// executable must define and export for the dynamic linker to prefer it to libgomp's.
TEST(CommandLine, TheToolRunsCholmodsOpenMPRegionsItself)
{
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
  const Tool_run symbols = run_in_shell("nm -D --defined-only " + std::string(DISTORTION_OPTIMIZER));
  ASSERT_EQ(symbols.status, 0) << symbols.output;
  EXPECT_TRUE(std::regex_search(symbols.output, std::regex(" T GOMP_parallel\\b"))) << symbols.output.substr(0, 2000);
#else
  GTEST_SKIP() << "built without CHOLMOD";
#endif
}

TEST(CommandLine, SubdivideRefinesTheSourceAndTheResultTogether)
{
  const std::string s = temp("sub_source.off"), t = temp("sub_target.off"), o = temp("sub_out.off"),
                    s2 = temp("sub_source2.off"), r = temp("sub.json");
  write_planar_pair(s, t);
  for(const std::string scheme : {"linear", "loop"}) {
    const Tool_run result = run("--source " + s + " --target " + t + " --output " + o + " --subdivide 2 --scheme " + scheme +
                                " --subdivided-source " + s2 + " --report " + r);
    ASSERT_EQ(result.status, 0) << result.output;
    const IO::Triangle_soup source = IO::read_triangle_soup(s), refined = IO::read_triangle_soup(s2),
                            map = IO::read_triangle_soup(o);
    EXPECT_EQ(refined.cells.size(), 16 * source.cells.size());
    EXPECT_EQ(refined.cells, map.cells);
    EXPECT_EQ(refined.points.size(), map.points.size());
    const std::string json = slurp(r);
    EXPECT_EQ(json_value(json, "cells"), double(source.cells.size()));
    EXPECT_EQ(json_value(json, "subdivided_cells"), double(refined.cells.size()));
    EXPECT_EQ(json_value(json, "subdivided_vertices"), double(refined.points.size()));
    EXPECT_EQ(json_value(json, "subdivided_inverted_cells"), 0.);
    if(scheme == "linear") {
      EXPECT_NEAR(json_value(json, "subdivided_energy"), json_value(json, "final_energy"), 1e-12 * json_value(json, "final_energy"));
      for(std::size_t v = 0; v < source.points.size(); ++v) EXPECT_EQ(refined.points[v], source.points[v]);
    } else {
      EXPECT_GE(json_value(json, "subdivided_energy"), 1.);
    }
  }
  // subdivided_energy under the run's cell weighting (cells of different areas, so that the
  // weightings differ): with linear, final_energy again.
  const std::string graded = temp("sub_graded.off");
  {
    IO::Triangle_soup g = IO::read_triangle_soup(s);
    for(auto& p : g.points) p[0] = p[0] * (0.5 + p[0]) / 1.5;
    IO::write_triangle_soup(graded, g);
  }
  for(const std::string weighting : {"uniform", "volume"}) {
    const Tool_run result = run("--source " + graded + " --target " + t + " --output " + o + " --subdivide 1 --subdivided-source " +
                                s2 + " --report " + r + " --cell-weighting " + weighting);
    ASSERT_EQ(result.status, 0) << result.output;
    const std::string json = slurp(r);
    EXPECT_NEAR(json_value(json, "subdivided_energy"), json_value(json, "final_energy"), 1e-12 * json_value(json, "final_energy"))
      << weighting;
  }
  // A valid triangle so nearly flat that the rounded midpoints of its linear subdivision invert
  // three of its four children (exact orientations): status 1, nothing written.
  {
    IO::Triangle_soup one, thin;
    one.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    one.cells = {{0, 1, 2}};
    thin = one;
    thin.points = {{0.7104511603865951, -0.15770297486718032, 0}, {0.6669542399922945, 0.14804547057912476, 0},
                   {0.6872193210164589, 0.005598213076417389, 0}};
    const std::string a = temp("sub_one.off"), b = temp("sub_thin.off"), o1 = temp("sub_thin_out.off"),
                      s1 = temp("sub_thin_source.off");
    IO::write_triangle_soup(a, one);
    IO::write_triangle_soup(b, thin);
    std::remove(o1.c_str());
    std::remove(s1.c_str());
    const Tool_run thin_run = run("--source " + a + " --target " + b + " --output " + o1 + " --measure arap --iterations 0 "
                                  "--harmonic-start off --subdivide 1 --subdivided-source " + s1);
    EXPECT_EQ(thin_run.status, 1) << thin_run.output;
    EXPECT_NE(thin_run.output.find("the subdivided map has 3 inverted or flat cells"), std::string::npos) << thin_run.output;
    EXPECT_FALSE(std::ifstream(o1).good());
    EXPECT_FALSE(std::ifstream(s1).good());
  }
  // Loop's border rule moves the reflex corner of an L into its notch, where a separate triangle
  // lies 0.01 from it: the refined pieces would overlap; status 1, nothing
  // written. --scheme linear keeps the optimized map.
  {
    IO::Triangle_soup l_source, l_start;
    const std::vector<std::array<double, 2>> corners = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}};
    for(const auto& p : corners) l_source.points.push_back({p[0], p[1], 0});
    l_start = l_source;
    for(const auto& p : std::vector<std::array<double, 2>>{{1.01, 1.01}, {1.9, 1.01}, {1.01, 1.9}}) {
      l_source.points.push_back({p[0] + 10, p[1], 0});
      l_start.points.push_back({p[0], p[1], 0});
    }
    l_source.cells = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}, {8, 9, 10}};
    l_start.cells = l_source.cells;
    const std::string a = temp("sub_l.off"), b = temp("sub_l_start.off"), o1 = temp("sub_l_out.off"), s1 = temp("sub_l_source.off");
    IO::write_triangle_soup(a, l_source);
    IO::write_triangle_soup(b, l_start);
    for(const std::string scheme : {"loop", "linear"}) {
      std::remove(o1.c_str());
      std::remove(s1.c_str());
      const Tool_run l_run = run("--source " + a + " --target " + b + " --output " + o1 + " --fix none --measure symmetric_dirichlet "
                                 "--subdivide 1 --subdivided-source " + s1 + " --scheme " + scheme);
      if(scheme == "loop") {
        EXPECT_EQ(l_run.status, 1) << l_run.output;
        EXPECT_NE(l_run.output.find("the subdivided map's border crosses itself or one of its pieces overlaps another (Loop's"),
                  std::string::npos) << l_run.output;
        EXPECT_FALSE(std::ifstream(o1).good());
        EXPECT_FALSE(std::ifstream(s1).good());
      } else {
        EXPECT_EQ(l_run.status, 0) << l_run.output;
      }
    }
  }
  for(const auto& [arguments, fragment] : std::vector<std::pair<std::string, std::string>>{
        {" --subdivide 1", "go together"},
        {" --subdivide 0 --subdivided-source " + s2, "--subdivide expects 1 to 6 levels"},
        {" --scheme loop", "--scheme needs --subdivide"},
        {" --subdivide 1 --scheme cubic --subdivided-source " + s2, "--scheme is linear or loop"},
        {" --subdivide 1 --subdivided-source " + t, "would be overwritten"}}) {
    const Tool_run bad = run("--source " + s + " --target " + t + " --output " + temp("sub_bad.off") + arguments);
    EXPECT_EQ(bad.status, 2) << arguments << "\n" << bad.output;
    EXPECT_NE(bad.output.find(fragment), std::string::npos) << arguments << "\n" << bad.output;
  }
}

// An empty value is a usage error, never "not given": --target '' once computed a Tutte map.
TEST(CommandLine, EmptyOptionValuesAreUsageErrors)
{
  for(const std::string option : {"--target", "--vertex-weights", "--report", "--svg", "--energy-plot", "--flat-output",
                                   "--mesh-output", "--fix", "--measure", "--source"}) {
    const Tool_run result = run("--source a.off --output b.off " + option + " ''");
    EXPECT_EQ(result.status, 2) << option;
    EXPECT_NE(result.output.find(option + " needs a value, not an empty one"), std::string::npos) << result.output;
  }
}

// A closed standard output does not kill the tool once its files are written: the exit status is
// the run's (it was SIGPIPE's, 141, with every output in place).
// Threads that the machine's limits cannot give are a message, not an abort in TBB (issue 66):
// 1000 threads' stacks do not fit in 3 GB of address space.
TEST(CommandLine, ThreadsThatCannotStartAreAMessage)
{
  const std::string s = temp("s_threads.off"), t = temp("t_threads.off"), o = temp("o_threads.off");
  write_planar_pair(s, t);
  std::remove(o.c_str());
  expect_failed_cleanly(run_in_shell("ulimit -v 3000000; " + std::string(DISTORTION_OPTIMIZER) + " --source " + s +
                                     " --target " + t + " --output " + o + " --threads 1000"),
                        "--threads 1000: cannot start that many threads here", o);
}

TEST(CommandLine, AClosedStandardOutputLeavesTheExitStatusToTheRun)
{
  const std::string s = temp("s_pipe.off"), t = temp("t_pipe.off"), o = temp("o_pipe.off"), r = temp("r_pipe.json");
  write_planar_pair(s, t);
  std::remove(o.c_str());
  std::remove(r.c_str());
  const std::string command = "set -o pipefail; " + std::string(DISTORTION_OPTIMIZER) + " --source " + s + " --target " + t +
                              " --output " + o + " --report " + r + " | head -c 0";
  const int status = std::system(("bash -c '" + command + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_TRUE(exists(o));
  EXPECT_TRUE(exists(r));
}
