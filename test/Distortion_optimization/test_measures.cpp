// Measures, signed SVD and the per-cell kernel (no mesh involved).

#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/cell_hessian.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/Distortion_optimization/measures.h>

#include "reference_svd.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <tuple>
#include <type_traits>

namespace DO = CGAL::Distortion_optimization;
using DO::internal::Matrix;
using DO::internal::Vector;

namespace {

const double inf = std::numeric_limits<double>::infinity();

auto all_measures()
{
  auto custom = DO::make_measure(
    [](const auto& s) { return (s.array() - 2.).square().sum(); },
    [](const auto& s) { return (2. * (s.array() - 2.)).matrix().eval(); }, "custom", false, false);
  return std::make_tuple(DO::Conformal_dilatation(), DO::Condition_number(), DO::MIPS(),
                         DO::Isometric_dilatation(), DO::ARAP(), DO::Symmetric_dirichlet(),
                         DO::Volume_distortion(), DO::Dirichlet(),
                         DO::Product<DO::Conformal_dilatation, DO::Isometric_dilatation>(),
                         DO::Weighted_sum<DO::Symmetric_dirichlet, DO::ARAP>(0.7, {}, 0.3, {}), custom,
                         DO::Product_of_measures({"conformal", "isometric"}),
                         DO::Sum_of_measures(DO::measures_internal::parse_sum("0.5*conformal+2*isometric*mips")));
}

template <class F>
void for_each_measure(F f)
{
  std::apply([&](const auto&... m) { (f(m), ...); }, all_measures());
}

std::mt19937& rng()
{
  static std::mt19937 g(12345);
  return g;
}

double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng()); }

template <int n>
Matrix<n> random_rotation()
{
  if constexpr(n == 2) {
    const double a = uniform(-M_PI, M_PI);
    Matrix<2> R;
    R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    return R;
  } else {
    Eigen::Quaterniond q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    return q.normalized().toRotationMatrix();
  }
}

template <int n>
Matrix<n> with_singular_values(const Vector<n>& s)
{
  return random_rotation<n>() * s.asDiagonal() * random_rotation<n>().transpose();
}

// Independent formulas, written from the paper's equations 8-16.
template <int n>
double expected(const std::string& name, const Vector<n>& s)
{
  const double p = s.prod();
  if(name == "conformal") {
    if(n == 2) return s[0] / s[1];
    return std::max(s[0] * s[1] / (s[2] * s[2]), s[0] * s[0] / (s[1] * s[2]));
  }
  if(name == "condition") return s[0] / s[n - 1];
  if(name == "mips") return n == 2 ? s[0] / s[1] + s[1] / s[0] : s.squaredNorm() / std::cbrt(p * p);
  if(name == "isometric") return std::max(s[0], 1 / s[n - 1]);
  if(name == "arap") { double e = 0; for(int i = 0; i < n; ++i) e += (s[i] - 1) * (s[i] - 1); return e; }
  if(name == "symmetric_dirichlet") { double e = 0; for(int i = 0; i < n; ++i) e += s[i] * s[i] + 1 / (s[i] * s[i]); return e / (2 * n); }
  if(name == "volume") return std::max(p, 1 / p);
  if(name == "dirichlet") return s.squaredNorm() / n;
  if(name == "conformal*isometric") return expected<n>("conformal", s) * expected<n>("isometric", s);
  if(name == "custom") return (s.array() - 2.).square().sum();
  if(name == "0.5*conformal+2*isometric*mips")
    return 0.5 * expected<n>("conformal", s) + 2 * expected<n>("isometric", s) * expected<n>("mips", s);
  return 0.7 * expected<n>("symmetric_dirichlet", s) + 0.3 * expected<n>("arap", s);
}

template <int n>
void check_closed_forms(const Vector<n>& s)
{
  for_each_measure([&](const auto& m) {
    const double e = expected<n>(m.name(), s);
    EXPECT_NEAR(m.template value<n>(s), e, 1e-13 * std::abs(e)) << m.name() << " n=" << n;
    // Jacobians with these singular values, rotated at random on both sides (Definition 2.1).
    for(int k = 0; k < 5; ++k) {
      const Matrix<n> J = with_singular_values<n>(s);
      EXPECT_NEAR(DO::internal::jacobian_distortion<n>(m, J), e, 1e-11 * std::abs(e)) << m.name() << " n=" << n;
    }
  });
}

} // namespace

TEST(Measures, ClosedFormsOnDiagonalAndRotatedJacobians)
{
  check_closed_forms<2>(Vector<2>(3., 0.5));
  check_closed_forms<2>(Vector<2>(1.3, 1.1));
  check_closed_forms<3>(Vector<3>(3., 2., 0.5));
  check_closed_forms<3>(Vector<3>(1.2, 0.9, 0.8));
  check_closed_forms<3>(Vector<3>(4., 0.5, 0.4));   // K_O branch of eq. 8
}

TEST(Measures, MipsIsEquation10In2D)
{
  for(int k = 0; k < 20; ++k) {
    const double a = uniform(0.1, 5), b = uniform(0.1, 5);
    const Vector<2> s(std::max(a, b), std::min(a, b));
    EXPECT_NEAR(DO::MIPS().value<2>(s), s[0] / s[1] + s[1] / s[0], 1e-13 * (s[0] / s[1]));
  }
}

TEST(Measures, RigidMapsGiveTheMinimum)
{
  const std::map<std::string, double> m2 = {{"conformal", 1}, {"condition", 1}, {"mips", 2}, {"isometric", 1},
    {"arap", 0}, {"symmetric_dirichlet", 1}, {"volume", 1}, {"dirichlet", 1}, {"conformal*isometric", 1}};
  for_each_measure([&](const auto& m) {
    auto it = m2.find(m.name());
    if(it == m2.end()) return;
    EXPECT_DOUBLE_EQ(DO::value_on_rigid_maps<2>(m), it->second) << m.name();
    const double m3 = m.name() == "mips" ? 3. : it->second;
    EXPECT_DOUBLE_EQ(DO::value_on_rigid_maps<3>(m), m3) << m.name();
    EXPECT_NEAR(DO::internal::jacobian_distortion<3>(m, random_rotation<3>()), m3, 1e-12) << m.name();
    EXPECT_NEAR(DO::internal::jacobian_distortion<2>(m, random_rotation<2>()), it->second, 1e-12) << m.name();
  });
}

template <int n>
void check_symmetry(const Vector<n>& s)
{
  Vector<n> inverse_s;
  for(int i = 0; i < n; ++i) inverse_s[i] = 1. / s[n - 1 - i];
  for_each_measure([&](const auto& m) {
    const double a = m.template value<n>(s), b = m.template value<n>(inverse_s);
    if(m.template is_symmetric<n>())
      EXPECT_NEAR(a, b, 1e-12 * a) << m.name() << " n=" << n;
    else
      EXPECT_GT(std::abs(a - b), 1e-3 * std::abs(a)) << m.name() << " claims no symmetry, n=" << n;
  });
}

TEST(Measures, SymmetricMeasuresAreInvariantUnderInversion)
{
  check_symmetry<2>(Vector<2>(2.5, 0.7));
  check_symmetry<3>(Vector<3>(2.5, 1.4, 0.7));
  EXPECT_TRUE(DO::is_regular<2>(DO::MIPS()));
  EXPECT_FALSE(DO::is_regular<3>(DO::MIPS()));
  EXPECT_FALSE(DO::is_regular<3>(DO::ARAP()));
  EXPECT_TRUE(DO::is_regular<3>(DO::Symmetric_dirichlet()));
}

template <int n>
void check_barrier()
{
  for_each_measure([&](const auto& m) {
    if(!m.is_normalized()) return;
    Vector<n> s = Vector<n>::Constant(1.5);
    double previous = m.template value<n>(s);
    for(double t : {1e-2, 1e-4, 1e-6, 1e-8, 1e-12}) {
      s[n - 1] = t;
      const double v = m.template value<n>(s);
      EXPECT_GT(v, previous) << m.name();
      previous = v;
    }
    EXPECT_GT(previous, 1e6) << m.name();
    s[n - 1] = 0;
    EXPECT_EQ(m.template value<n>(s), inf) << m.name();
    s[n - 1] = -0.5;
    EXPECT_EQ(m.template value<n>(s), inf) << m.name();
    Matrix<n> reflection = Matrix<n>::Identity();
    reflection(0, 0) = -1;
    Matrix<n> dJ;
    EXPECT_EQ(DO::internal::jacobian_distortion<n>(m, reflection), inf) << m.name();
    EXPECT_EQ(DO::internal::jacobian_distortion<n>(m, reflection, dJ), inf) << m.name();
    EXPECT_TRUE(dJ.array().isNaN().all()) << m.name();
  });
}

TEST(Measures, NormalizedMeasuresGrowToInfinityAndRejectInversions)
{
  check_barrier<2>();
  check_barrier<3>();
}

template <int n>
Matrix<n> random_well_conditioned()
{
  // Distinct singular values: max-type measures (K, C, condition) have kinks where they meet,
  // and central differences straddling a kink are no reference.
  Vector<n> s;
  do {
    for(int i = 0; i < n; ++i) s[i] = uniform(0.5, 2.);
    std::sort(s.data(), s.data() + n, std::greater<double>());
  } while(((s.head(n - 1) - s.tail(n - 1)).array() < 0.05).any());
  return with_singular_values<n>(s);
}

// dD/dJ by central differences of step h in each entry.
template <int n, class Measure>
Matrix<n> central_differences(const Measure& m, const Matrix<n>& J, double h)
{
  Matrix<n> fd;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      Matrix<n> Jp = J, Jm = J;
      Jp(i, j) += h;
      Jm(i, j) -= h;
      fd(i, j) = (DO::internal::jacobian_distortion<n>(m, Jp) - DO::internal::jacobian_distortion<n>(m, Jm)) / (2 * h);
    }
  return fd;
}

template <int n>
void check_gradient_against_finite_differences()
{
  for_each_measure([&](const auto& m) {
    for(int trial = 0; trial < 50; ++trial) {
      const Matrix<n> J = random_well_conditioned<n>();
      Matrix<n> dJ;
      DO::internal::jacobian_distortion<n>(m, J, dJ);
      const double h = 1e-6;
      const Matrix<n> fd = central_differences<n>(m, J, h);
      EXPECT_LE((dJ - fd).norm(), 1e-6 * std::max(1., fd.norm())) << m.name() << " n=" << n << "\nJ=\n" << J;
      // And the derivative in sigma itself.
      const Vector<n> s = DO::internal::signed_singular_values(J);
      const Vector<n> g = m.template gradient<n>(s);
      for(int i = 0; i < n; ++i) {
        Vector<n> sp = s, sm = s;
        sp[i] += h;
        sm[i] -= h;
        const double fdi = (m.template value<n>(sp) - m.template value<n>(sm)) / (2 * h);
        EXPECT_NEAR(g[i], fdi, 1e-6 * std::max(1., std::abs(fdi))) << m.name() << " i=" << i;
      }
    }
  });
}

TEST(Measures, JacobianGradientMatchesFiniteDifferences2D) { check_gradient_against_finite_differences<2>(); }
TEST(Measures, JacobianGradientMatchesFiniteDifferences3D) { check_gradient_against_finite_differences<3>(); }

// The measures with a Hessian in the singular values: it matches central differences of their
// gradient. Then the cell Hessian in the vertices (cell_hessian.h, unprojected) matches central
// differences of the cell's vertex gradient, and its projection is positive semi-definite, equal
// to it where it already was.
template <int n>
void check_hessians()
{
  std::size_t measures_with_hessian = 0;
  for_each_measure([&](const auto& m) {
    using Measure = std::decay_t<decltype(m)>;
    if constexpr(DO::measures_internal::Has_hessian<Measure, n>::value) {
      ++measures_with_hessian;
      for(int trial = 0; trial < 30; ++trial) {
        const Matrix<n> J = random_well_conditioned<n>();
        const Vector<n> s = DO::internal::signed_singular_values(J);
        const Matrix<n> h = m.template hessian<n>(s);
        const double step = 1e-6;
        for(int j = 0; j < n; ++j) {
          Vector<n> sp = s, sm = s;
          sp[j] += step;
          sm[j] -= step;
          const Vector<n> fd = (m.template gradient<n>(sp) - m.template gradient<n>(sm)) / (2 * step);
          EXPECT_LE((h.col(j) - fd).norm(), 1e-6 * std::max(1., fd.norm())) << m.name() << " n=" << n << " j=" << j;
        }
        // A cell: a random source, its target edges J Dm.
        const Matrix<n> Dm = random_well_conditioned<n>(), M = Dm.inverse();
        const Matrix<n> Ds = J * Dm;
        DO::internal::Cell_hessian<n> H, projected;
        std::array<Vector<n>, n + 1> gradient, other;
        ASSERT_TRUE(DO::internal::cell_hessian<n>(m, J, M, H, gradient, false)) << m.name();
        ASSERT_TRUE(DO::internal::cell_hessian<n>(m, J, M, projected, other, true)) << m.name();
        EXPECT_LE((H - H.transpose()).norm(), 1e-10 * H.norm()) << m.name();
        // Moving vertex i by e_a moves Ds: every column for vertex 0 (with a minus), column i-1 otherwise.
        const auto gradient_at = [&](int i, int a, double t) {
          Matrix<n> D = Ds;
          if(i == 0) D.row(a).array() -= t;
          else D(a, i - 1) += t;
          DO::internal::Cell_hessian<n> unused;
          std::array<Vector<n>, n + 1> g;
          DO::internal::cell_hessian<n>(m, Matrix<n>(D * M), M, unused, g, false);
          Eigen::Matrix<double, n * (n + 1), 1> flat;
          for(int k = 0; k <= n; ++k) flat.template segment<n>(n * k) = g[k];
          return flat;
        };
        for(int i = 0; i <= n; ++i)
          for(int a = 0; a < n; ++a) {
            const Eigen::Matrix<double, n * (n + 1), 1> fd = (gradient_at(i, a, step) - gradient_at(i, a, -step)) / (2 * step);
            EXPECT_LE((H.col(n * i + a) - fd).norm(), 1e-5 * std::max(1., fd.norm())) << m.name() << " n=" << n;
          }
        const Eigen::SelfAdjointEigenSolver<DO::internal::Cell_hessian<n>> unprojected(H), psd(projected), added(projected - H);
        EXPECT_GE(psd.eigenvalues().minCoeff(), -1e-10 * std::max(1., psd.eigenvalues().maxCoeff())) << m.name();
        // Only negative modes are dropped: what the projection adds is positive semi-definite.
        EXPECT_GE(added.eigenvalues().minCoeff(), -1e-10 * std::max(1., psd.eigenvalues().maxCoeff())) << m.name();
        if(unprojected.eigenvalues().minCoeff() > 1e-8 * unprojected.eigenvalues().maxCoeff()) {
          EXPECT_LE((H - projected).norm(), 1e-10 * H.norm()) << m.name();
        }
      }
    }
  });
  // symmetric_dirichlet, mips, arap, dirichlet and the weighted sum of SD and ARAP.
  EXPECT_EQ(measures_with_hessian, 5u);
}

TEST(Measures, HessiansMatchFiniteDifferences2D) { check_hessians<2>(); }
TEST(Measures, HessiansMatchFiniteDifferences3D) { check_hessians<3>(); }

template <int n, class M>
void check_svd_free_form(const M& m)
{
  for(int trial = 0; trial < 50; ++trial) {
    const Matrix<n> J = random_well_conditioned<n>();
    Matrix<n> a = Matrix<n>::Zero(), b;
    const double va = DO::internal::distortion_from_invariants<n>(m, J, &a);
    DO::internal::Signed_svd<n> svd;
    DO::internal::signed_svd(J, svd);
    const double vb = m.template value<n>(svd.sigma);
    b = svd.U * m.template gradient<n>(svd.sigma).asDiagonal() * svd.V.transpose();
    EXPECT_NEAR(va, vb, 1e-12 * vb) << m.name();
    EXPECT_LE((a - b).norm(), 1e-11 * b.norm()) << m.name();
  }
}

// In 3D the kernel forms U diag(g) V^T without singular vectors where the eigenvalues of J^T J
// are apart (Sylvester's formula): compare it with the explicit vectors of Eigen's Jacobi SVD,
// from well-separated values down to the 1e-2 relative gap where the kernel switches to them,
// and on inverted cells (ARAP and Dirichlet are finite there; the sign sits in sigma_3).
TEST(Measures, GradientWithoutSingularVectorsMatchesTheExplicitOnes)
{
  const DO::ARAP arap;
  const DO::Conformal_dilatation conformal;
  const DO::Isometric_dilatation isometric;
  int fast_path = 0;
  for(double gap : {0.3, 0.1, 0.03, 0.0101, 0.0099})
    for(int trial = 0; trial < 40; ++trial) {
      // sigma_1^2 - sigma_2^2 = gap sigma_1^2 and sigma_2^2 - sigma_3^2 = u gap sigma_1^2, u in [1, 1.5].
      const double s1 = uniform(0.5, 2.), s2 = s1 * std::sqrt(1 - gap), s3 = s1 * std::sqrt(1 - gap * (1 + uniform(1., 1.5)));
      for(double sign : {1., -1.}) {
        const Matrix<3> J = with_singular_values<3>(Vector<3>(s1, s2, sign * s3));
        Matrix<3> A;
        Vector<3> l;
        fast_path += DO::internal::separated_gram_eigenvalues(J, A, l);
        DO::internal::Signed_svd<3> svd;
        ASSERT_TRUE(reference::signed_svd_jacobi(J, svd));
        const auto check = [&](const auto& m) {
          if(!(m.template value<3>(svd.sigma) < std::numeric_limits<double>::infinity())) return;
          Matrix<3> dJ;
          const double value = DO::internal::jacobian_distortion<3>(m, J, dJ);
          const Matrix<3> expected = svd.U * m.template gradient<3>(svd.sigma).asDiagonal() * svd.V.transpose();
          EXPECT_NEAR(value, m.template value<3>(svd.sigma), 1e-13 * value) << m.name();
          EXPECT_LE((dJ - expected).norm(), 1e-10 * expected.norm()) << m.name() << " gap " << gap << "\nJ=\n" << J;
        };
        check(arap);
        check(conformal);
        check(isometric);
      }
    }
  EXPECT_GT(fast_path, 200);   // both paths were exercised
  EXPECT_LT(fast_path, 400);
}

// The kernel on several cells at once (in SIMD lanes) gives what it gives cell by cell: on
// separated and nearly conformal cells (the 3D fallback), an inverted one, a flat one and one
// with a NaN vertex, over a count that is not a multiple of the lanes.
template <int n>
void check_batched_kernel()
{
  DO::internal::Simplicial_map<n> map;
  const int cells = 29;
  for(int c = 0; c < cells; ++c) {
    std::array<std::uint32_t, n + 1> cell;
    Matrix<n> Dm = with_singular_values<n>(Vector<n>::Constant(1.));
    for(int i = 0; i <= n; ++i) {
      cell[i] = static_cast<std::uint32_t>(map.target.size());
      Vector<n> x = Vector<n>::Zero();
      if(i > 0) x = Dm.col(i - 1);
      if(c % 3 == 1) x = 1.7 * x;                                                  // conformal: fallback
      else if(c % 3 == 2) x = with_singular_values<n>(Vector<n>::LinSpaced(2., 0.6)) * x;   // separated
      map.target.push_back(x);
    }
    if(c == 5) std::swap(map.target[cell[1]], map.target[cell[2]]);               // inverted
    if(c == 8) map.target[cell[n]] = map.target[cell[1]];                          // flat
    if(c == 11) map.target[cell[0]][0] = std::numeric_limits<double>::quiet_NaN();
    map.add_cell(cell, Dm, 1);
  }
  const auto check = [&](const auto& m) {
    std::vector<double> values(cells);
    std::vector<std::array<Vector<n>, n + 1>> gradients(cells);
    std::vector<Vector<n>> sigma(cells);
    DO::internal::cell_distortions<n>(m, map, cells, [](std::size_t k) { return k; }, values.data(), gradients.data(), sigma.data());
    std::vector<double> values_only(cells);
    DO::internal::cell_distortions<n>(m, map, cells, [](std::size_t k) { return k; }, values_only.data());
    for(int c = 0; c < cells; ++c) {
      std::array<Vector<n>, n + 1> g;
      Vector<n> s;
      // Cell by cell: a measure with an invariant form through the lanes alone (a cell's value must
      // not depend on its neighbours in a batch, to the last bit), the others from the Jacobian.
      double v;
      if constexpr(DO::internal::Has_invariant_form<std::decay_t<decltype(m)>, n>::value) {
        DO::internal::cell_distortions<n>(m, map, 1, [c](std::size_t) { return std::size_t(c); }, &v, &g, &s);
      } else {
        Matrix<n> dJ;
        v = DO::internal::jacobian_distortion<n>(m, map.jacobian(c), dJ, &s);
        DO::internal::vertex_gradients_from_jacobian_gradient(map, c, dJ, g);
      }
      // The same formulas; only the Jacobian's products may be ordered differently, and values
      // alone may come from the Gram eigenvalues where the full SVD gives the others (singular
      // values within 1e-16 of each other's: ARAP's (s - 1)^2 on a rotation differ by 1e-32).
      for(double batched : {values[c], values_only[c]}) {
        if(std::isnan(v)) EXPECT_TRUE(std::isnan(batched)) << m.name() << " cell " << c;
        else if(std::isinf(v)) EXPECT_EQ(batched, v) << m.name() << " cell " << c;
        else EXPECT_NEAR(batched, v, 1e-14 * (1 + v)) << m.name() << " cell " << c;
      }
      if(!std::isfinite(v)) continue;
      EXPECT_LE((sigma[c] - s).norm(), 1e-14 * s.norm()) << m.name() << " cell " << c;
      for(int i = 0; i <= n; ++i) EXPECT_LE((gradients[c][i] - g[i]).norm(), 1e-13 * (1 + g[i].norm())) << m.name() << " cell " << c;
    }
  };
  for_each_measure(check);
}

TEST(Measures, BatchedKernelMatchesTheKernelCellByCell2D) { check_batched_kernel<2>(); }
TEST(Measures, BatchedKernelMatchesTheKernelCellByCell3D) { check_batched_kernel<3>(); }

TEST(Measures, SvdFreeFormsAgreeWithTheSvdForms)
{
  static_assert(DO::internal::Has_invariant_form<DO::Symmetric_dirichlet, 3>::value, "");
  static_assert(!DO::internal::Has_invariant_form<DO::Conformal_dilatation, 3>::value, "");
  check_svd_free_form<2>(DO::Symmetric_dirichlet());
  check_svd_free_form<3>(DO::Symmetric_dirichlet());
  check_svd_free_form<2>(DO::MIPS());
  check_svd_free_form<3>(DO::MIPS());
  check_svd_free_form<2>(DO::Volume_distortion());
  check_svd_free_form<3>(DO::Volume_distortion());
  check_svd_free_form<2>(DO::Dirichlet());
  check_svd_free_form<3>(DO::Dirichlet());
}

// The lanes' cube root (Halley's iteration, measures' scale): within 3 units in the last place of
// the exact root over the whole normal range, the same bits in a lane as for one double, and
// libm's results where it hands over (zero, subnormal, negative, huge, infinite, NaN).
TEST(Measures, LanesCubeRootIsAccurateAndFallsBackOutsideItsRange)
{
  using Lanes = DO::lanes::Cell_lanes;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-1020, 1020), mantissa(1, 2);
  double worst = 0;
  for(int trial = 0; trial < 100000; ++trial) {
    Lanes x = DO::lanes::broadcast<Lanes>(0.);
    for(int i = 0; i < DO::lanes::count<Lanes>; ++i)
      DO::lanes::set(x, i, std::ldexp(mantissa(random), static_cast<int>(exponent(random))));
    const Lanes y = DO::lanes::cbrt(x);
    for(int i = 0; i < DO::lanes::count<Lanes>; ++i) {
      const double xi = DO::lanes::get(x, i), yi = DO::lanes::get(y, i);
      ASSERT_EQ(yi, DO::lanes::cbrt(xi)) << xi;
      const long double exact = std::cbrt(static_cast<long double>(xi));
      const double ulp = std::nextafter(static_cast<double>(exact), inf) - static_cast<double>(exact);
      worst = std::max(worst, static_cast<double>(std::fabs(yi - exact) / ulp));
    }
  }
  EXPECT_LE(worst, 3.) << "units in the last place";
  EXPECT_EQ(DO::lanes::cbrt(27.), 3.);
  const double largest = std::numeric_limits<double>::max(), smallest = std::numeric_limits<double>::min();
  for(double x : {0., -0., smallest / 3, -8., largest / 3, largest, inf, -inf}) {   // handed over
    EXPECT_EQ(DO::lanes::cbrt(x), std::cbrt(x)) << x;
    EXPECT_EQ(std::signbit(DO::lanes::cbrt(x)), std::signbit(x)) << x;
  }
  EXPECT_TRUE(std::isnan(DO::lanes::cbrt(DO::not_a_number)));
  EXPECT_NEAR(DO::lanes::cbrt(smallest), std::cbrt(smallest), 4e-16 * std::cbrt(smallest));   // the range's ends
  EXPECT_NEAR(DO::lanes::cbrt(largest / 4), std::cbrt(largest / 4), 4e-16 * std::cbrt(largest / 4));
}

// The untangling barrier (Garanzha et al. 2021) is finite on inverted and flat Jacobians: its
// analytic gradient against central differences there too, with eps large and small, its
// invariant form against its singular-value form, and its limits.
template <int n>
void check_untangling_barrier()
{
  for(double eps : {1., 1e-2, 1e-4}) {
    DO::Untangling_barrier m;
    m.epsilon = eps;
    m.reference_det = 0.7;
    for(int trial = 0; trial < 50; ++trial) {
      Matrix<n> J = Matrix<n>::Random();
      if(trial == 0) J.row(0) = J.row(1);   // flat
      Matrix<n> dJ;
      const double value = DO::internal::jacobian_distortion<n>(m, J, dJ);
      ASSERT_TRUE(std::isfinite(value)) << "J=\n" << J;
      const Matrix<n> fd = central_differences<n>(m, J, 1e-6 * std::max(eps, 1e-2));
      EXPECT_LE((dJ - fd).norm(), 1e-5 * std::max(1., fd.norm())) << "eps " << eps << " J=\n" << J;
      Matrix<n> a = Matrix<n>::Zero();
      DO::internal::Signed_svd<n> svd;
      DO::internal::signed_svd(J, svd);
      EXPECT_NEAR(DO::internal::distortion_from_invariants<n>(m, J, &a), m.template value<n>(svd.sigma), 1e-10 * value);
      const Matrix<n> b = svd.U * m.template gradient<n>(svd.sigma).asDiagonal() * svd.V.transpose();
      EXPECT_LE((a - b).norm(), 1e-9 * std::max(1., b.norm())) << "eps " << eps;
    }
  }
  // As eps -> 0: on a positive Jacobian, (1 - theta) MIPS-like + theta (D + 1/D); on an inverted
  // one, without bound.
  DO::Untangling_barrier m;
  const double theta = n == 2 ? m.theta_2 : m.theta_3;
  m.epsilon = 1e-12;
  const Matrix<n> I = Matrix<n>::Identity();
  EXPECT_NEAR(DO::internal::jacobian_distortion<n>(m, I), (1 - theta) * n + theta * 2, 1e-9);
  Matrix<n> inverted = I;
  inverted(0, 0) = -1;
  EXPECT_GT(DO::internal::jacobian_distortion<n>(m, inverted), 1e20);
}

TEST(Measures, UntanglingBarrier2D) { check_untangling_barrier<2>(); }
TEST(Measures, UntanglingBarrier3D) { check_untangling_barrier<3>(); }

// ---------------------------------------------------------------- signed SVD

template <int n>
void check_svd(const Matrix<n>& J, double tolerance)
{
  std::ostringstream trace;
  trace.precision(17);
  trace << "J =\n" << J;
  SCOPED_TRACE(trace.str());
  DO::internal::Signed_svd<n> a, b;
  ASSERT_TRUE(DO::internal::signed_svd(J, a));
  ASSERT_TRUE(reference::signed_svd_jacobi(J, b));
  const double scale = std::max(b.sigma[0], 1e-300);
  for(int i = 0; i < n; ++i)
    EXPECT_NEAR(a.sigma[i], b.sigma[i], tolerance * scale) << "i=" << i << "\nJ=\n" << J;
  for(int i = 0; i + 1 < n; ++i) EXPECT_GE(a.sigma[i], std::abs(a.sigma[i + 1]) - tolerance * scale);
  EXPECT_NEAR(a.sigma.prod(), J.determinant(), tolerance * std::pow(scale, n));
  EXPECT_LE((a.U * a.sigma.asDiagonal() * a.V.transpose() - J).norm(), tolerance * scale);
  EXPECT_NEAR(a.U.determinant(), 1., 1e-12);
  EXPECT_NEAR(a.V.determinant(), 1., 1e-12);
  EXPECT_LE((a.U.transpose() * a.U - Matrix<n>::Identity()).norm(), 1e-12);
  EXPECT_LE((a.V.transpose() * a.V - Matrix<n>::Identity()).norm(), 1e-12);
  const Vector<n> values_only = DO::internal::signed_singular_values(J);
  EXPECT_LE((values_only - b.sigma).norm(), tolerance * scale);
  if(std::abs(J.determinant()) > 1e-10 * std::pow(scale, n)) {
    EXPECT_EQ(a.sigma[n - 1] > 0, J.determinant() > 0);
  }
}

template <int n>
void check_svd_family()
{
  std::vector<Vector<n>> cases;
  if constexpr(n == 2) {
    cases = {Vector<2>(1, 1), Vector<2>(2, 2), Vector<2>(3, 1e-9), Vector<2>(1, 1 - 1e-12), Vector<2>(5, -0.5),
             Vector<2>(1, -1), Vector<2>(1e-3, 1e-3), Vector<2>(1, 0)};
  } else {
    cases = {Vector<3>(1, 1, 1), Vector<3>(2, 2, 1), Vector<3>(2, 1, 1), Vector<3>(3, 1e-4, 1e-9),
             Vector<3>(1, 1 - 1e-10, 1 - 2e-10), Vector<3>(4, 2, -0.5), Vector<3>(1, 1, -1), Vector<3>(1, 0.5, 0),
             Vector<3>(2, 2, 2e-10),
             // near-conformal (nearly orthogonal columns: Jacobi without the closed form)
             Vector<3>(1.05, 1, 0.97), Vector<3>(1e-5 * 1.001, 1e-5, 1e-5 * 0.9995), Vector<3>(1 + 1e-7, 1, 1 - 1e-7),
             Vector<3>(1.02, 1.01, -0.99)};
  }
  for(const auto& s : cases)
    for(int k = 0; k < 20; ++k) check_svd<n>(with_singular_values<n>(s), 1e-12);
  for(int k = 0; k < 200; ++k) {
    Matrix<n> J = Matrix<n>::Random();
    check_svd<n>(J, 1e-12);
  }
  // Near-similarities (clustered singular values), where values alone come from the Gram
  // eigenvalues if their gaps are apart relative to their spread.
  for(double distortion : {1e-2, 1e-4, 1e-7})
    for(int k = 0; k < 100; ++k)
      check_svd<n>(with_singular_values<n>(Vector<n>::Ones() + distortion * Vector<n>::Random()), 1e-12);
  check_svd<n>(Matrix<n>::Identity(), 1e-15);
  check_svd<n>(Matrix<n>::Zero(), 1e-15);
}

TEST(Svd, ClosedForm2DMatchesJacobiSvd) { check_svd_family<2>(); }
TEST(Svd, ClosedForm3DMatchesJacobiSvd) { check_svd_family<3>(); }

TEST(Svd, NonFiniteEntriesAreReportedNotPropagatedSilently)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(double bad : {nan, inf, -inf}) {
    Matrix<2> J2 = Matrix<2>::Identity();
    J2(0, 1) = bad;
    Matrix<3> J3 = Matrix<3>::Identity();
    J3(2, 0) = bad;
    DO::internal::Signed_svd<2> s2;
    DO::internal::Signed_svd<3> s3;
    EXPECT_FALSE(DO::internal::signed_svd(J2, s2));
    EXPECT_FALSE(DO::internal::signed_svd(J3, s3));
    EXPECT_TRUE(s2.sigma.array().isNaN().all());
    EXPECT_TRUE(s3.sigma.array().isNaN().all());
    for_each_measure([&](const auto& m) {
      Matrix<3> dJ;
      EXPECT_TRUE(std::isnan(DO::internal::jacobian_distortion<2>(m, J2))) << m.name();
      EXPECT_TRUE(std::isnan(DO::internal::jacobian_distortion<3>(m, J3, dJ))) << m.name();
      EXPECT_TRUE(dJ.array().isNaN().all()) << m.name();
    });
  }
}
