// The sparse direct solver (internal/sparse_cholesky.h), on the systems of a real mesh: built twice,
// with CHOLMOD where CMake found it (test_sparse_cholesky) and with Eigen's factorization always
// (test_sparse_cholesky_without_cholmod), so that both paths are tested wherever CHOLMOD is.

#include <CGAL/Distortion_optimization/internal/sparse_cholesky.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace DOI = CGAL::Distortion_optimization::internal;
using Sparse = Eigen::SparseMatrix<double>;

namespace {

// lion-head (a disk of 8,355 vertices) with its border fixed: the uniform graph Laplacian of the
// inner vertices, each entry times a 2 x 2 block coupling a vertex's coordinates (the pattern of a
// triangle map's Newton system), or times 1 (a harmonic or Tutte system).
Sparse lion_head_system(int block)
{
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  const std::string file = DISTORTION_OPTIMIZATION_DATA_DIR "/lion-head.off";
  if(!CGAL::IO::read_OFF(file, points, triangles) || triangles.empty()) {
    ADD_FAILURE() << "cannot read " << file;
    return Sparse();
  }
  std::map<std::pair<std::size_t, std::size_t>, int> edges;
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i) ++edges[std::minmax(t[i], t[(i + 1) % 3])];
  std::vector<int> column(points.size(), 0);
  for(const auto& [e, count] : edges)
    if(count == 1) column[e.first] = column[e.second] = -1;
  int size = 0;
  for(int& c : column)
    if(c == 0) c = size++;
    else c = -1;
  const double coupling[2][2] = {{2, 0.5}, {0.5, 1}};
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](int a, int b, double value) {
    for(int i = 0; i < block; ++i)
      for(int j = 0; j < block; ++j)
        entries.emplace_back(block * a + i, block * b + j, value * (block == 1 ? 1. : coupling[i][j]));
  };
  for(const auto& [e, count] : edges) {
    const int a = column[e.first], b = column[e.second];
    if(a >= 0) add(a, a, 1);
    if(b >= 0) add(b, b, 1);
    if(a >= 0 && b >= 0) {
      add(a, b, -1);
      add(b, a, -1);
    }
  }
  Sparse A(block * size, block * size);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

double relative_residual(const Sparse& A, const Eigen::MatrixXd& x, const Eigen::MatrixXd& b)
{
  return (A.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm();
}

} // namespace

// With CHOLMOD, from how many unknowns it is used: the tests below run both factorizations on one
// mesh by asking for CHOLMOD from 0 unknowns.
const std::ptrdiff_t cholmod_always = 0, cholmod_default = DOI::Sparse_cholesky<2>::default_cholmod_from();
// Whether this build links CHOLMOD, as CMake found it: what a solver asked for CHOLMOD must use.
#ifdef DISTORTION_OPTIMIZATION_EXPECT_CHOLMOD
constexpr bool cholmod_linked = true;
#else
constexpr bool cholmod_linked = false;
#endif

TEST(SparseCholesky, BackendIsTheOneCMakeChose)
{
  const Sparse A = lion_head_system(2);
  DOI::Sparse_cholesky<2> forced(cholmod_always), by_size;
  ASSERT_TRUE(forced.factorize(A));
  ASSERT_TRUE(by_size.factorize(A));
  EXPECT_EQ(forced.uses_cholmod(), cholmod_linked);
  // lion-head's 16.6K unknowns are fewer than CHOLMOD's threshold.
  EXPECT_LT(A.rows(), cholmod_default);
  EXPECT_FALSE(by_size.uses_cholmod());
}

TEST(SparseCholesky, TheProgramsThresholdChoosesTheBackend)
{
  // set_cholmod_threshold() is read as a solver is set up: CHOLMOD from that many unknowns on.
  namespace DO = CGAL::Distortion_optimization;
  const Sparse A = lion_head_system(2);
  const std::size_t unknowns = static_cast<std::size_t>(A.rows());
  EXPECT_EQ(DO::cholmod_threshold(), 32768u);   // the library's default
  const std::size_t before = DO::set_cholmod_threshold(unknowns);
  EXPECT_EQ(before, 32768u);
  DOI::Sparse_cholesky<2> at_threshold;
  DO::set_cholmod_threshold(unknowns + 1);
  DOI::Sparse_cholesky<2> below_threshold;
  EXPECT_EQ(DO::set_cholmod_threshold(before), unknowns + 1);
  ASSERT_TRUE(at_threshold.factorize(A));
  ASSERT_TRUE(below_threshold.factorize(A));
  EXPECT_EQ(at_threshold.uses_cholmod(), cholmod_linked);
  EXPECT_FALSE(below_threshold.uses_cholmod());
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  EXPECT_LT(relative_residual(A, at_threshold.solve(b), b), 1e-10);
  EXPECT_LT(relative_residual(A, below_threshold.solve(b), b), 1e-10);
}

TEST(SparseCholesky, SolvesNewtonAndLaplacianSystemsOfARealMesh)
{
  for(int cholmod_from : {cholmod_always, cholmod_default})
    for(int block : {1, 2}) {
      const Sparse A = lion_head_system(block);
      ASSERT_GT(A.rows(), 8000 * block);
      const Eigen::MatrixXd b = Eigen::MatrixXd::Random(A.rows(), 2);
      Eigen::MatrixXd x;
      if(block == 1) {
        DOI::Sparse_cholesky<1> cholesky(cholmod_from);
        ASSERT_TRUE(cholesky.factorize(A));
        x = cholesky.solve(b);
        EXPECT_GT(cholesky.factor_nonzeros(), A.nonZeros() / 2);
      } else {
        DOI::Sparse_cholesky<2> cholesky(cholmod_from);
        ASSERT_TRUE(cholesky.factorize(A));
        x = cholesky.solve(b);
      }
      EXPECT_LT(relative_residual(A, x, b), 1e-10) << block << " " << cholmod_from;
    }
}

TEST(SparseCholesky, RefactorsNewValuesAndShiftsOnOneAnalysis)
{
  for(int cholmod_from : {cholmod_always, cholmod_default}) {
    const Sparse A = lion_head_system(2);
    DOI::Sparse_cholesky<2> cholesky(cholmod_from);
    cholesky.analyze(A);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1, 1);
    ASSERT_TRUE(cholesky.factorize(A));
    const Eigen::VectorXd x = cholesky.solve(b);
    EXPECT_LT(relative_residual(A, x, b), 1e-10);
    // The same pattern, other values: 3 A + diagonal, then A shifted by 0.25 I.
    Sparse B = 3 * A;
    for(int i = 0; i < B.rows(); ++i) B.coeffRef(i, i) += 1 + i % 7;
    ASSERT_TRUE(cholesky.factorize(B));
    EXPECT_LT(relative_residual(B, cholesky.solve(b), b), 1e-10);
    ASSERT_TRUE(cholesky.factorize(A, 0.25));
    Sparse shifted = A;
    for(int i = 0; i < A.rows(); ++i) shifted.coeffRef(i, i) += 0.25;
    const Eigen::VectorXd y = cholesky.solve(b);
    EXPECT_LT(relative_residual(shifted, y, b), 1e-10);
    EXPECT_GT((y - x).norm(), 1e-3 * x.norm());   // the shift was applied
    // As a preconditioner: a vector in, a vector out.
    const Eigen::VectorXd z = cholesky.solve(Eigen::VectorXd(b));
    EXPECT_EQ(z, y);
  }
}

TEST(SparseCholesky, RefusesMatricesThatAreNotPositiveDefinite)
{
  for(int cholmod_from : {cholmod_always, cholmod_default}) {
    Sparse A = lion_head_system(1);
    DOI::Sparse_cholesky<1> cholesky(cholmod_from);
    ASSERT_TRUE(cholesky.factorize(A));
    // The last unknown's diagonal entry negated: indefinite.
    const int last = int(A.rows()) - 1;
    A.coeffRef(last, last) = -A.coeff(last, last);
    EXPECT_FALSE(cholesky.factorize(A));
    EXPECT_FALSE(cholesky.is_factored());
    // Negated: negative definite.
    EXPECT_FALSE(cholesky.factorize(-lion_head_system(1)));
    // And back to a good matrix on the same analysis.
    EXPECT_TRUE(cholesky.factorize(lion_head_system(1)));
  }
}

TEST(SparseCholesky, EmptySystem)
{
  DOI::Sparse_cholesky<2> cholesky(cholmod_always);
  EXPECT_TRUE(cholesky.factorize(Sparse(0, 0)));
  EXPECT_EQ(cholesky.solve(Eigen::VectorXd(0)).rows(), 0);
}

// The harmonic start's order of the vertices, taken by the Newton system's analysis (same graph
// of vertices, two unknowns each): the same order as the Newton system's own, hence the same
// factor; an order of the wrong length is not taken. Eigen's path has none.
TEST(SparseCholesky, AnalysisTakesTheOrderOfAnotherOnTheSameGraph)
{
  const Sparse laplacian = lion_head_system(1), newton = lion_head_system(2);
  DOI::Sparse_cholesky<1> harmonic(cholmod_always);
  EXPECT_TRUE(harmonic.needs_analysis());
  harmonic.analyze(laplacian);
  ASSERT_TRUE(harmonic.factorize(laplacian));
  const std::vector<int>& order = harmonic.block_order();
  if(!harmonic.uses_cholmod()) {
    EXPECT_TRUE(order.empty());
    return;
  }
  ASSERT_EQ(static_cast<Eigen::Index>(order.size()), laplacian.rows());
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for(std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], static_cast<int>(i));

  // Orders that are not permutations of the vertices are not taken (METIS's is computed instead).
  std::vector<int> repeated = order, out_of_range = order;
  repeated[0] = repeated[1];
  out_of_range[0] = static_cast<int>(order.size());
  DOI::Sparse_cholesky<2> own(cholmod_always), given(cholmod_always), wrong_length(cholmod_always),
    with_repeat(cholmod_always), with_out_of_range(cholmod_always);
  own.analyze(newton);
  given.analyze(newton, order);
  wrong_length.analyze(newton, std::vector<int>(order.begin(), order.end() - 1));
  with_repeat.analyze(newton, repeated);
  with_out_of_range.analyze(newton, out_of_range);
  for(DOI::Sparse_cholesky<2>* cholesky : {&own, &given, &wrong_length, &with_repeat, &with_out_of_range}) {
    EXPECT_FALSE(cholesky->needs_analysis());
    ASSERT_TRUE(cholesky->factorize(newton));
    EXPECT_EQ(cholesky->block_order(), order);
  }
  EXPECT_EQ(given.factor_nonzeros(), own.factor_nonzeros());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(newton.rows(), 2, -1);
  EXPECT_LT(relative_residual(newton, given.solve(b), b), 1e-10);

  // An order that is not METIS's still gives the solution, with more fill: the identity.
  std::vector<int> identity(order.size());
  std::iota(identity.begin(), identity.end(), 0);
  DOI::Sparse_cholesky<2> natural(cholmod_always);
  natural.analyze(newton, identity);
  ASSERT_TRUE(natural.factorize(newton));
  EXPECT_EQ(natural.block_order(), identity);
  EXPECT_GT(natural.factor_nonzeros(), 2 * own.factor_nonzeros());
  EXPECT_LT(relative_residual(newton, natural.solve(b), b), 1e-10);
}

// One solve (Tutte's maps) takes the minimum degree's order on CHOLMOD's path: another order than
// nested dissection's, the same solution.
TEST(SparseCholesky, MinimumDegreeOrderForOneSolve)
{
  const Sparse A = lion_head_system(1);
  DOI::Sparse_cholesky<1> dissection(cholmod_always),
    degree(cholmod_always, DOI::Fill_reducing_order::MINIMUM_DEGREE);
  ASSERT_TRUE(dissection.factorize(A));
  ASSERT_TRUE(degree.factorize(A));
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(A.rows(), 2);
  EXPECT_LT(relative_residual(A, degree.solve(b), b), 1e-10);
  EXPECT_LT((degree.solve(b) - dissection.solve(b)).norm(), 1e-9 * dissection.solve(b).norm());
  if(degree.uses_cholmod()) {
    std::vector<int> sorted = degree.block_order();
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(static_cast<Eigen::Index>(sorted.size()), A.rows());
    for(std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], static_cast<int>(i));
    EXPECT_NE(degree.block_order(), dissection.block_order());
  }
}
