// Energy + gradient throughput of the per-cell kernel, per measure, 2D and 3D, one thread:
// for every cell, J = Ds Dm^-1, D(J), dD/dJ and the n+1 vertex gradients accumulated into a
// per-vertex array (what one solver pass over the mesh costs), through the blocked kernel the solver
// uses (cell_distortions: measures with an invariant form, symmetric Dirichlet among them, take two
// cells per SSE2 register; for the others, in 3D, the Gram eigenvalues of eight cells are solved
// together). Also the 3x3 SVD variants.
// Two sizes: a mesh that stays in the L2 cache (the kernel's own speed, and what a local solver
// sees on a vertex ring) and a large one (bounded by memory bandwidth: each tet streams ~100 bytes).
//
//   build/benchmark/Distortion_optimization/bench_kernel

#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <benchmark/benchmark.h>

#include "../../test/Distortion_optimization/reference_svd.h"

#include <random>

namespace DO = CGAL::Distortion_optimization;
namespace DI = CGAL::Distortion_optimization::internal;

namespace {

// A k^n grid of unit cells split into simplices (2 triangles or 6 Kuhn tetrahedra each), mapped
// by the identity plus a small random displacement that keeps every cell positive.
template <int n>
DI::Simplicial_map<n> noisy_grid(int k)
{
  DI::Simplicial_map<n> map;
  const int m = k + 1;
  auto id = [&](int i, int j, int l) { return static_cast<std::uint32_t>((l * m + j) * m + i); };
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  const int layers = n == 3 ? m : 1;
  for(int l = 0; l < layers; ++l)
    for(int j = 0; j < m; ++j)
      for(int i = 0; i < m; ++i) {
        DI::Vector<n> x;
        x[0] = i + noise(rng);
        x[1] = j + noise(rng);
        if constexpr(n == 3) x[2] = l + noise(rng);
        map.target.push_back(x);
      }
  auto rest = [](const DI::Vector<n>& x) { return x; };
  auto add = [&](const std::array<std::uint32_t, n + 1>& cell, const std::array<DI::Vector<n>, n + 1>& p) {
    DI::Matrix<n> Dm;
    for(int c = 0; c < n; ++c) Dm.col(c) = rest(p[c + 1]) - rest(p[0]);
    map.add_cell(cell, Dm, 1);
  };
  for(int l = 0; l < (n == 3 ? k : 1); ++l)
    for(int j = 0; j < k; ++j)
      for(int i = 0; i < k; ++i) {
        if constexpr(n == 2) {
          auto P = [&](int a, int b) { return DI::Vector<2>(i + a, j + b); };
          add({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0)}, {P(0, 0), P(1, 0), P(1, 1)});
          add({id(i, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)}, {P(0, 0), P(1, 1), P(0, 1)});
        } else {
          // Kuhn subdivision: one tet per permutation of the axes, all positively oriented.
          const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
          for(const auto& p : perms) {
            std::array<int, 3> c = {0, 0, 0};
            std::array<std::uint32_t, 4> cell;
            std::array<DI::Vector<3>, 4> pts;
            for(int s = 0; s <= 3; ++s) {
              if(s > 0) c[p[s - 1]] = 1;
              cell[s] = id(i + c[0], j + c[1], l + c[2]);
              pts[s] = DI::Vector<3>(i + c[0], j + c[1], l + c[2]);
            }
            if((DI::Matrix<3>() << pts[1] - pts[0], pts[2] - pts[0], pts[3] - pts[0]).finished().determinant() < 0) {
              std::swap(cell[2], cell[3]);
              std::swap(pts[2], pts[3]);
            }
            add(cell, pts);
          }
        }
      }
  return map;
}

template <int n, class Measure>
void energy_and_gradient(benchmark::State& state)
{
  const DI::Simplicial_map<n> map = noisy_grid<n>(static_cast<int>(state.range(0)));
  std::vector<DI::Vector<n>> gradient(map.number_of_vertices());
  constexpr std::size_t block = 256;   // the solver's passes also go block by block
  std::array<double, block> value;
  std::array<std::array<DI::Vector<n>, n + 1>, block> g;
  const Measure measure{};
  for(auto _ : state) {
    double energy = 0;
    for(std::size_t first = 0; first < map.number_of_cells(); first += block) {
      const std::size_t count = std::min(block, map.number_of_cells() - first);
      DI::cell_distortions<n>(measure, map, count, [&](std::size_t k) { return first + k; }, value.data(), g.data());
      for(std::size_t k = 0; k < count; ++k) {
        const std::size_t c = first + k;
        energy += map.rest_volume[c] * value[k];
        for(int i = 0; i <= n; ++i) gradient[map.cells[c][i]] += map.rest_volume[c] * g[k][i];
      }
    }
    benchmark::DoNotOptimize(energy);
    benchmark::DoNotOptimize(gradient.data());
  }
  state.SetItemsProcessed(state.iterations() * map.number_of_cells());
  state.SetLabel(n == 2 ? "triangles" : "tets");
}

// One cell at a time (the blocked kernel on a block of one) and without the scatter into the
// per-vertex array: what one isolated evaluation of a cell's energy and vertex gradients costs.
template <int n, class Measure>
void cell_energy_and_gradient(benchmark::State& state)
{
  const DI::Simplicial_map<n> map = noisy_grid<n>(static_cast<int>(state.range(0)));
  std::array<DI::Vector<n>, n + 1> g;
  const Measure measure{};
  for(auto _ : state) {
    double energy = 0;
    DI::Vector<n> sum = DI::Vector<n>::Zero();
    for(std::size_t c = 0; c < map.number_of_cells(); ++c) {
      double value;
      DI::cell_distortions<n>(measure, map, 1, [c](std::size_t) { return c; }, &value, &g);
      energy += value;
      sum += g[c % (n + 1)];
    }
    benchmark::DoNotOptimize(energy);
    benchmark::DoNotOptimize(sum.data());
  }
  state.SetItemsProcessed(state.iterations() * map.number_of_cells());
  state.SetLabel(n == 2 ? "triangles" : "tets");
}

// 4096 Jacobians: the identity plus a random perturbation of the given size.
template <int n>
std::vector<DI::Matrix<n>> random_jacobians(double size)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<DI::Matrix<n>> Js(4096);
  for(auto& J : Js) J = DI::Matrix<n>::Identity() + size * DI::Matrix<n>::NullaryExpr([&] { return u(rng); });
  return Js;
}

template <int n, bool closed_form>
void svd(benchmark::State& state)
{
  const std::vector<DI::Matrix<n>> Js = random_jacobians<n>(0.3);
  DI::Signed_svd<n> out;
  for(auto _ : state)
    for(const auto& J : Js) {
      if constexpr(closed_form) DI::signed_svd(J, out);
      else reference::signed_svd_jacobi(J, out);
      benchmark::DoNotOptimize(out.sigma.data());
    }
  state.SetItemsProcessed(state.iterations() * Js.size());
}

// Singular values only (what a trial step of a line search needs).
template <int n>
void singular_values(benchmark::State& state)
{
  const std::vector<DI::Matrix<n>> Js = random_jacobians<n>(0.3);
  for(auto _ : state)
    for(const auto& J : Js) {
      DI::Vector<n> s = DI::signed_singular_values(J);
      benchmark::DoNotOptimize(s.data());
    }
  state.SetItemsProcessed(state.iterations() * Js.size());
}

} // namespace

// Grid sizes: 2D 50 (5K triangles) and 300 (180K); 3D 10 (6K tets) and 40 (384K).
#define DISTORTION_BENCH(MEASURE)                                                                   \
  BENCHMARK_TEMPLATE(energy_and_gradient, 2, DO::MEASURE)->Arg(50)->Arg(300)->Unit(benchmark::kMicrosecond); \
  BENCHMARK_TEMPLATE(energy_and_gradient, 3, DO::MEASURE)->Arg(10)->Arg(40)->Unit(benchmark::kMicrosecond);

DISTORTION_BENCH(Symmetric_dirichlet)
BENCHMARK_TEMPLATE(cell_energy_and_gradient, 2, DO::Symmetric_dirichlet)->Arg(50)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(cell_energy_and_gradient, 3, DO::Symmetric_dirichlet)->Arg(10)->Unit(benchmark::kMicrosecond);
DISTORTION_BENCH(MIPS)
DISTORTION_BENCH(Dirichlet)
DISTORTION_BENCH(Volume_distortion)
DISTORTION_BENCH(Conformal_dilatation)
DISTORTION_BENCH(Condition_number)
DISTORTION_BENCH(Isometric_dilatation)
DISTORTION_BENCH(ARAP)

BENCHMARK_TEMPLATE(svd, 2, true);
BENCHMARK_TEMPLATE(svd, 2, false);
BENCHMARK_TEMPLATE(svd, 3, true);
BENCHMARK_TEMPLATE(svd, 3, false);
BENCHMARK_TEMPLATE(singular_values, 2);
BENCHMARK_TEMPLATE(singular_values, 3);

BENCHMARK_MAIN();
