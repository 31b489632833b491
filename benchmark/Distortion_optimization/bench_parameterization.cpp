// Surface parametrization: CGAL's ARAP parameterizer against a Tutte start improved by
// CGAL::minimize_distortion(), on real disk meshes.
//
//   (a) Surface_mesh_parameterization::ARAP_parameterizer_3 with its default settings (free
//       border, its own LSCM start; the time includes that start);
//   (b) the Tutte map (border on a circle), then minimize_distortion() with the border fixed, for
//       the symmetric Dirichlet energy (SD) and for the conformal dilatation K;
//   (c) as (b) for SD, but from the Tutte map scaled first by its optimal uniform scale, so that
//       the fixed circle has about the right size for an isometric measure;
//   (d) free border: the Tutte map, then minimize_distortion() for SD with every vertex free and
//       preserve_global_injectivity (the border may not cross itself), on 1 and 2 threads;
//   (e) as (d), but from CGAL's ARAP map of (a), which has flipped triangles: untangle_first(true)
//       untangles it, then SD is minimized (the seconds include both; the untangling is also
//       reported on its own). Issue 15's target: within 2% of (d)'s SD in at most 1 s;
//   (f) SD from the Tutte map, fixed and free border: the energy reached after 0.1 ... 2 s for
//       each global step and schedule and for the defaults, and the time to SLIM's energy.
//
// Every map is scored by the same code: CGAL::compute_distortion() volume-weighted means of SD,
// K and ARAP, and the number of inverted triangles. SD and ARAP depend on the scale of the map:
// ARAP's map has about the size of the surface, so has the Tutte map (scaled to the surface's area,
// but on a fixed circle). So "SD*" is
// also reported: SD after the uniform rescale s of the map that minimizes it (golden-section
// search on log s), the fair comparison between maps of different sizes.
// The seconds are those of the step named in the row (the Tutte start is its own row).
//
//   build/benchmark/Distortion_optimization/bench_parameterization [mesh.off ...]

#include <CGAL/Distortion_optimization/initial_maps.h>
#include <CGAL/compute_distortion.h>
#include <CGAL/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace DO = CGAL::Distortion_optimization;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using UV_map = Mesh::Property_map<vertex_descriptor, K::Point_2>;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void progress(const std::string& message)
{
  std::fprintf(stderr, "  ... %s\n", message.c_str());
  std::fflush(stderr);
}

struct Score
{
  double sd, sd_rescaled, best_scale, k, arap;
  std::size_t inverted;
};

// SD of the map scaled by s (about the origin: distortion does not see translations).
double scaled_sd(const Mesh& mesh, const UV_map& uv, UV_map& scratch, double s)
{
  for(vertex_descriptor v : mesh.vertices())
    scratch[v] = K::Point_2(s * uv[v].x(), s * uv[v].y());
  return CGAL::compute_distortion(mesh, scratch, DO::Symmetric_dirichlet()).mean_volume;
}

Score score(const Mesh& mesh, const UV_map& uv, UV_map& scratch)
{
  Score r;
  const auto sd = CGAL::compute_distortion(mesh, uv, DO::Symmetric_dirichlet());
  r.sd = sd.mean_volume;
  r.inverted = sd.inverted_cells;
  r.k = CGAL::compute_distortion(mesh, uv, DO::Conformal_dilatation()).mean_volume;
  r.arap = CGAL::compute_distortion(mesh, uv, DO::ARAP()).mean_volume;
  r.sd_rescaled = r.sd;
  r.best_scale = 1;
  if(r.inverted > 0)
    return r;   // SD is infinite at every scale

  // Golden-section search of the scale, on t = log s, around the scale that matches the areas.
  double area_2 = 0;
  for(auto f : mesh.faces()) {
    std::vector<vertex_descriptor> t;
    for(vertex_descriptor v : vertices_around_face(mesh.halfedge(f), mesh))
      t.push_back(v);
    area_2 += std::abs(CGAL::area(uv[t[0]], uv[t[1]], uv[t[2]]));
  }
  const double t0 = 0.5 * std::log(PMP::area(mesh) / area_2);
  const double phi = 0.5 * (std::sqrt(5.) - 1);
  double a = t0 - 6, b = t0 + 6;
  double c = b - phi * (b - a), d = a + phi * (b - a);
  double fc = scaled_sd(mesh, uv, scratch, std::exp(c)), fd = scaled_sd(mesh, uv, scratch, std::exp(d));
  while(b - a > 1e-7) {
    if(fc < fd) { b = d; d = c; fd = fc; c = b - phi * (b - a); fc = scaled_sd(mesh, uv, scratch, std::exp(c)); }
    else        { a = c; c = d; fc = fd; d = a + phi * (b - a); fd = scaled_sd(mesh, uv, scratch, std::exp(d)); }
  }
  r.best_scale = std::exp(0.5 * (a + b));
  r.sd_rescaled = scaled_sd(mesh, uv, scratch, r.best_scale);

  // Cross-check with the closed form: SD(s) = (s^2 A + B / s^2) / 4 with A = mean(s1^2 + s2^2)
  // = 2 Dirichlet and B = mean(s1^-2 + s2^-2) = 4 SD - A, minimal at s = (B / A)^(1/4).
  const double A = 2 * CGAL::compute_distortion(mesh, uv, DO::Dirichlet()).mean_volume, B = 4 * r.sd - A;
  const double s_closed = std::pow(B / A, 0.25), sd_closed = 0.5 * std::sqrt(A * B);
  if(std::abs(s_closed / r.best_scale - 1) > 1e-4 || std::abs(sd_closed / r.sd_rescaled - 1) > 1e-6)
    std::printf("  warning: golden-section scale %.8g (SD %.10g) but closed form %.8g (SD %.10g)\n", r.best_scale,
                r.sd_rescaled, s_closed, sd_closed);
  return r;
}

void print_row(const std::string& mesh, const std::string& method, double seconds, const std::string& sweeps,
               const Score& s)
{
  std::printf("%-16s %-14s %9.3f %7s %12.5g %9.5f %9.4g %9.5f %10.5f %9zu\n", mesh.c_str(), method.c_str(), seconds,
              sweeps.c_str(), s.sd, s.sd_rescaled, s.best_scale, s.k, s.arap, s.inverted);
  std::fflush(stdout);
}

void run(const std::string& filename)
{
  std::string name = filename.substr(filename.find_last_of('/') + 1);
  name = name.substr(0, name.find('.'));
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || num_faces(mesh) == 0) {
    std::fprintf(stderr, "cannot read %s\n", filename.c_str());
    return;
  }
  std::fprintf(stderr, "%s: %zu vertices, %zu triangles\n", name.c_str(), std::size_t(mesh.number_of_vertices()),
               std::size_t(mesh.number_of_faces()));
  UV_map uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  UV_map tutte = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:tutte").first;
  UV_map scratch = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:scratch").first;
  UV_map arap = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:arap").first;
  bool has_arap = false;

  // (a) CGAL's ARAP parameterizer, default settings.
  progress("ARAP_parameterizer_3");
  {
    const auto border = PMP::longest_border(mesh).first;
    const auto start = std::chrono::steady_clock::now();
    const SMP::Error_code status = SMP::parameterize(mesh, SMP::ARAP_parameterizer_3<Mesh>(), border, uv);
    const double seconds = seconds_since(start);
    if(status != SMP::OK)
      std::printf("%-16s %-14s failed: %s\n", name.c_str(), "CGAL ARAP", SMP::get_error_message(status));
    else
      print_row(name, "CGAL ARAP", seconds, "-", score(mesh, uv, scratch));
    has_arap = status == SMP::OK;
    for(vertex_descriptor v : mesh.vertices()) arap[v] = uv[v];
  }

  // (b) Tutte start, then minimize_distortion() with the border fixed.
  progress("Tutte");
  {
    const auto start = std::chrono::steady_clock::now();
    DO::initial_parameterization(mesh, tutte);
    print_row(name, "Tutte", seconds_since(start), "-", score(mesh, tutte, scratch));
  }
  auto improve_from = [&](const std::string& method, UV_map from, const auto& measure, double scale,
                          const auto& np) {
    progress(method);
    for(vertex_descriptor v : mesh.vertices())
      uv[v] = K::Point_2(scale * from[v].x(), scale * from[v].y());
    try {
      const auto start = std::chrono::steady_clock::now();
      const DO::Result r = CGAL::minimize_distortion(mesh, uv, measure, np);
      const double seconds = seconds_since(start);
      print_row(name, method, seconds, std::to_string(r.iterations) + (r.converged ? "" : "+"), score(mesh, uv, scratch));
      if(r.inverted_start_cells > 0)
        std::printf("%-16s   of which untangling %zu inverted or flat cells: %.3f s, %zu rounds\n", name.c_str(),
                    r.inverted_start_cells, r.untangle_seconds, r.untangle_iterations);
    } catch(const std::exception& e) {
      std::printf("%-16s %-14s failed: %s\n", name.c_str(), method.c_str(), e.what());
    }
  };
  auto improve = [&](const std::string& method, const auto& measure, double scale, const auto& np) {
    improve_from(method, tutte, measure, scale, np);
  };
  const auto defaults = CGAL::parameters::default_values();
  improve("Tutte+SD", DO::Symmetric_dirichlet(), 1., defaults);
  improve("Tutte+SD 2thr", DO::Symmetric_dirichlet(), 1., DO::parameters::number_of_threads(2));
  improve("Tutte+K", DO::Conformal_dilatation(), 1., defaults);
  // (c) The same SD run from the Tutte map scaled to its SD-optimal size.
  improve("Tutte*s+SD", DO::Symmetric_dirichlet(), score(mesh, tutte, scratch).best_scale, defaults);
  // (d) Free border, kept from crossing itself.
  auto none = mesh.add_property_map<vertex_descriptor, bool>("v:none", false).first;
  for(int threads : {1, 2})
    improve(threads == 1 ? "free+SD" : "free+SD 2thr", DO::Symmetric_dirichlet(), 1.,
            DO::parameters::preserve_global_injectivity(true, DO::parameters::number_of_threads(threads))
              .vertex_is_constrained_map(none));
  // (e) Free border from CGAL's ARAP map, untangled first.
  if(has_arap)
    improve_from("ARAP+unt+SD", arap, DO::Symmetric_dirichlet(), 1.,
                 DO::parameters::untangle_first(true, DO::parameters::preserve_global_injectivity(true))
                   .vertex_is_constrained_map(none));

  // (f) Time to energy: SD from the Tutte map, fixed and free border, for each global solver and
  // schedule and the defaults; the energy reached at a few times (a visitor records each iteration; no threshold,
  // the run stops after 2 s), and with the border fixed the time it gets below SLIM's energy.
  // Issue 18's targets: libigl's SLIM (20 iterations) reaches SD 1.6904 on lion-head in 1.4 s and
  // 1.9166 on mannequin-devil in 2.1 s with a nearly fixed border; a third of those times.
  const double checkpoints[] = {0.1, 0.2, 0.5, 1, 2};
  // SLIM's 20-iteration energies (issue 18), fixed border: the time at which a run gets below.
  const double slim = name == "lion-head" ? 1.6904 : name == "mannequin-devil" ? 1.9166 : 0.;
  std::printf("\n%-16s %-6s %-22s", "time to energy", "border", "global step, schedule");
  for(double t : checkpoints) std::printf(" %9.1fs", t);
  std::printf(" %10s %9s\n", "iterations", "to SLIM");
  // The explicit configurations, then the library's defaults (what users get: Newton's steps,
  // global, with a sweep after a step that gains too little or is cut short).
  struct Configuration { const char* label; std::optional<DO::Global_solver> solver; std::optional<DO::Schedule> schedule; };
  const auto laplacian = DO::Global_solver::REWEIGHTED_LAPLACIAN, newton = DO::Global_solver::PROJECTED_NEWTON;
  const Configuration configurations[] = {{"Laplacian, alternating", laplacian, DO::Schedule::ALTERNATING},
                                          {"Laplacian, global", laplacian, DO::Schedule::GLOBAL},
                                          {"Newton, alternating", newton, DO::Schedule::ALTERNATING},
                                          {"Newton, global", newton, DO::Schedule::GLOBAL},
                                          {"default", std::nullopt, std::nullopt}};
  for(const bool fixed : {true, false})
    for(const Configuration& configuration : configurations) {
        for(vertex_descriptor v : mesh.vertices()) uv[v] = tutte[v];
        std::vector<std::pair<double, double>> trace;   // (seconds, energy) after each iteration
        const auto start = std::chrono::steady_clock::now();
        const auto visitor = [&](std::size_t, double energy) {
          trace.emplace_back(seconds_since(start), energy);
          return trace.back().first < 2;
        };
        const auto np = DO::parameters::global_solver(configuration.solver, DO::parameters::schedule(configuration.schedule,
                          DO::parameters::convergence_threshold(0.))).number_of_iterations(100000).visitor(visitor);
        try {
          if(fixed) CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(), np);
          else CGAL::minimize_distortion(mesh, uv, DO::Symmetric_dirichlet(),
                                         DO::parameters::preserve_global_injectivity(true, np.vertex_is_constrained_map(none)));
        } catch(const std::exception& e) {
          std::printf("%-16s failed: %s\n", name.c_str(), e.what());
          continue;
        }
        std::printf("%-16s %-6s %-22s", name.c_str(), fixed ? "fixed" : "free", configuration.label);
        for(double t : checkpoints) {
          double reached = std::numeric_limits<double>::quiet_NaN();   // no iteration done yet
          for(const auto& [seconds, energy] : trace)
            if(seconds <= t) reached = energy;
          std::printf(" %10.6f", reached);
        }
        double below = std::numeric_limits<double>::quiet_NaN();   // never, or no SLIM figure
        for(auto it = trace.rbegin(); fixed && slim > 0 && it != trace.rend() && it->second <= slim; ++it) below = it->first;
        if(std::isnan(below)) std::printf(" %10zu %9s\n", trace.size(), "-");
        else std::printf(" %10zu %8.3fs\n", trace.size(), below);
        std::fflush(stdout);
      }
}

} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
    files.push_back(argv[i]);
  if(files.empty())
    for(const char* name : {"mushroom", "lion-head", "mannequin-devil"})
      files.push_back(std::string(DISTORTION_OPTIMIZATION_DATA_DIR) + "/" + name + ".off");

  std::printf("Volume-weighted means. SD* = SD after the best uniform rescale s of the map; sweeps: '+' = not "
              "converged\n");
  std::printf("%-16s %-14s %9s %7s %12s %9s %9s %9s %10s %9s\n", "mesh", "method", "seconds", "sweeps", "SD", "SD*",
              "s", "K", "ARAP", "inverted");
  for(const std::string& f : files)
    run(f);
  return 0;
}
