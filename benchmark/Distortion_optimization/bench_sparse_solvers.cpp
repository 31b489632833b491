// The sparse direct solvers for the Newton systems of triangle maps (issue 64): for each mesh,
// the system's sparsity (2 unknowns per vertex, a 2 x 2 block per pair of vertices sharing a
// triangle; the border fixed) with the values of a positive definite matrix of that pattern,
// factored by each candidate. Printed per solver: the symbolic analysis, the numeric factorization
// (the median of three; the package refactors the same pattern many times per run), one solve,
// the factor's nonzeros and the relative residual. The package's own (internal/sparse_cholesky.h)
// is Eigen's simplicial LDL^T below cholmod_threshold() unknowns and CHOLMOD's supernodal LL^T
// with METIS on the graph of the vertices above; OpenBLAS takes its threads from
// OPENBLAS_NUM_THREADS (one thread in the tool's setting, below).
//
//   build/benchmark/Distortion_optimization/bench_sparse_solvers [mesh.off ...]
//   (default: lion-head.off of libcgal-demo and its linear subdivisions, 1 to 3 levels:
//   16.7K, 67K, 267K and 1.07M triangles)
//
// bench_sparse_solvers_as_the_tool, built from the same file, measures in the command-line tool's
// setting (BENCH_AS_THE_TOOL; the tool's solver_runtime.cpp, linked in): CHOLMOD's OpenMP regions
// on the calling thread, freed blocks kept in the heap, the BLAS on one thread, and the tool's
// threshold (set_cholmod_threshold()), which these figures chose.

#include <CGAL/Distortion_optimization/internal/block_amd_ordering.h>
#include <CGAL/Distortion_optimization/internal/sparse_cholesky.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/SparseCholesky>
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#ifdef BENCH_AS_THE_TOOL
#include "solver_runtime.h"
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace DOI = CGAL::Distortion_optimization::internal;
using Matrix = Eigen::SparseMatrix<double>;
using Point = CGAL::Simple_cartesian<double>::Point_3;
using Triangle = std::array<std::size_t, 3>;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Each triangle split into four at its edges' midpoints.
void subdivide(std::vector<Point>& points, std::vector<Triangle>& triangles)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
  const auto middle = [&](std::size_t a, std::size_t b) {
    const auto key = std::minmax(a, b);
    auto [it, inserted] = midpoint.emplace(key, points.size());
    if(inserted) points.push_back(CGAL::midpoint(points[a], points[b]));
    return it->second;
  };
  std::vector<Triangle> finer;
  for(const Triangle& t : triangles) {
    const std::size_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
    finer.push_back({t[0], ab, ca});
    finer.push_back({ab, t[1], bc});
    finer.push_back({ca, bc, t[2]});
    finer.push_back({ab, bc, ca});
  }
  triangles.swap(finer);
}

// A positive definite matrix with the Newton system's pattern: the graph Laplacian of the inner
// vertices (border fixed: a border neighbour adds to the diagonal only), each entry times the 2 x 2
// block [[2, 0.5], [0.5, 1]], which couples a vertex's two coordinates as Hessians do.
Matrix newton_pattern(std::size_t nv, const std::vector<Triangle>& triangles)
{
  std::map<std::pair<std::size_t, std::size_t>, int> edges;   // edge -> triangles on it
  for(const Triangle& t : triangles)
    for(int i = 0; i < 3; ++i) ++edges[std::minmax(t[i], t[(i + 1) % 3])];
  std::vector<unsigned char> border(nv, 0);
  for(const auto& [e, count] : edges)
    if(count == 1) border[e.first] = border[e.second] = 1;
  std::vector<int> column(nv, -1);
  int size = 0;
  for(std::size_t v = 0; v < nv; ++v)
    if(!border[v]) column[v] = size++;
  const double block[2][2] = {{2, 0.5}, {0.5, 1}};
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> degree(size, 0);
  for(const auto& [e, count] : edges) {
    const int a = column[e.first], b = column[e.second];
    if(a >= 0) degree[a] += 1;
    if(b >= 0) degree[b] += 1;
    if(a < 0 || b < 0) continue;
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j) {
        entries.emplace_back(2 * a + i, 2 * b + j, -block[i][j]);
        entries.emplace_back(2 * b + i, 2 * a + j, -block[i][j]);
      }
  }
  for(int a = 0; a < size; ++a)
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j) entries.emplace_back(2 * a + i, 2 * a + j, degree[a] * block[i][j]);
  Matrix H(2 * size, 2 * size);
  H.setFromTriplets(entries.begin(), entries.end());
  return H;
}

struct Candidate
{
  const char* name;
  std::function<void(const Matrix&)> analyze;
  std::function<bool(const Matrix&)> factorize;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> solve;
  std::function<double()> factor_nonzeros;
};

template <class Solver>
Candidate eigen_candidate(const char* name, Solver& solver)
{
  return {name, [&solver](const Matrix& H) { solver.analyzePattern(H); },
          [&solver](const Matrix& H) { solver.factorize(H); return solver.info() == Eigen::Success; },
          [&solver](const Eigen::VectorXd& b) -> Eigen::VectorXd { return solver.solve(b); },
          [&solver]() { return double(solver.matrixL().nestedExpression().nonZeros()); }};
}

#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
template <class Solver>
Candidate cholmod_candidate(const char* name, Solver& solver, int ordering)
{
  // ordering: a CHOLMOD_* method, or -1 for CHOLMOD's default choice (AMD, and METIS where AMD fills badly).
  if(ordering >= 0) {
    solver.cholmod().nmethods = 1;
    solver.cholmod().method[0].ordering = ordering;
  }
  return {name, [&solver](const Matrix& H) { solver.analyzePattern(H); },
          [&solver](const Matrix& H) { solver.factorize(H); return solver.info() == Eigen::Success; },
          [&solver](const Eigen::VectorXd& b) -> Eigen::VectorXd { return solver.solve(b); },
          [&solver]() { return solver.cholmod().lnz; }};
}
#endif

void measure(const Candidate& candidate, const Matrix& H)
{
  auto start = std::chrono::steady_clock::now();
  candidate.analyze(H);
  const double analysis = seconds_since(start);
  std::vector<double> times;
  bool ok = true;
  for(int i = 0; i < 3; ++i) {
    start = std::chrono::steady_clock::now();
    ok = candidate.factorize(H) && ok;
    times.push_back(seconds_since(start));
  }
  std::sort(times.begin(), times.end());
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(H.rows());
  start = std::chrono::steady_clock::now();
  const Eigen::VectorXd x = candidate.solve(b);
  const double solving = seconds_since(start);
  const double residual = (H * x - b).norm() / b.norm();
  std::printf("  %-34s %9.3f %9.3f %9.3f %12.0f %10.1e%s\n", candidate.name, analysis, times[1], solving,
              candidate.factor_nonzeros(), residual, ok ? "" : "  FAILED");
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
#ifdef BENCH_AS_THE_TOOL
  distortion_optimizer::set_up_sparse_solvers();
#endif
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i) files.push_back(argv[i]);
  const bool subdivisions = files.empty();
  if(subdivisions) files = {DISTORTION_OPTIMIZATION_DATA_DIR "/lion-head.off"};
  for(const std::string& file : files) {
    std::vector<Point> points;
    std::vector<Triangle> triangles;
    if(!CGAL::IO::read_OFF(file, points, triangles) || triangles.empty()) {
      std::fprintf(stderr, "Error: cannot read a triangle mesh from %s\n", file.c_str());
      return 1;
    }
    for(int level = 0; level <= (subdivisions ? 3 : 0); ++level) {
      if(level > 0) subdivide(points, triangles);
      const Matrix H = newton_pattern(points.size(), triangles);
      std::printf("\n%s, %d subdivisions: %zu triangles, %ld unknowns, %ld nonzeros\n", file.c_str(), level,
                  triangles.size(), long(H.rows()), long(H.nonZeros()));
      std::printf("  %-34s %9s %9s %9s %12s %10s\n", "solver", "analyze s", "factor s", "solve s", "nnz(L)", "residual");
      {
        Eigen::SimplicialLDLT<Matrix, Eigen::Lower, DOI::Block_AMD_ordering<2>> solver;
        measure(eigen_candidate("Eigen SimplicialLDLT, block AMD", solver), H);
      }
      {
        Eigen::SimplicialLLT<Matrix, Eigen::Lower, DOI::Block_AMD_ordering<2>> solver;
        measure(eigen_candidate("Eigen SimplicialLLT, block AMD", solver), H);
      }
#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD
      {
        Eigen::CholmodSimplicialLDLT<Matrix> solver;
        measure(cholmod_candidate("CHOLMOD simplicial LDLT, AMD", solver, CHOLMOD_AMD), H);
      }
      for(const auto& [name, ordering] : std::vector<std::pair<const char*, int>>{
            {"CHOLMOD supernodal, default", -1}, {"CHOLMOD supernodal, AMD", CHOLMOD_AMD},
            {"CHOLMOD supernodal, METIS", CHOLMOD_METIS}, {"CHOLMOD supernodal, NESDIS", CHOLMOD_NESDIS}}) {
        Eigen::CholmodSupernodalLLT<Matrix> solver;
        measure(cholmod_candidate(name, solver, ordering), H);
      }
#endif
      for(std::ptrdiff_t cholmod_from : {DOI::Sparse_cholesky<2>::default_cholmod_from(), std::ptrdiff_t(0)}) {
        DOI::Sparse_cholesky<2> solver(cholmod_from);
        measure({cholmod_from == 0 ? "the package's, CHOLMOD at any size" : "the package's, by size (the default)",
                 [&](const Matrix& A) { solver.analyze(A); }, [&](const Matrix& A) { return solver.factorize(A); },
                 [&](const Eigen::VectorXd& b) -> Eigen::VectorXd { return solver.solve(b); },
                 [&]() { return double(solver.factor_nonzeros()); }}, H);
      }
    }
  }
  return 0;
}
