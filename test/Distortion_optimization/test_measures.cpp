// Measures, signed SVD and the per-cell kernel (no mesh involved): values, closed forms, barriers,
// the SVD-free forms and the SVD; their derivatives are in test_measure_derivatives.cpp.

#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/internal/cell_hessian.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/Distortion_optimization/measures.h>

#include "measure_test_helpers.h"
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

using namespace measure_tests;

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
