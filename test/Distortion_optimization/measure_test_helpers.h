// What the measure tests share (test_measures.cpp, test_measure_derivatives.cpp): every measure
// as a tuple, random rotations and Jacobians with given singular values, and the paper's closed
// forms written independently, and central differences.

#ifndef DISTORTION_OPTIMIZATION_TEST_MEASURE_TEST_HELPERS_H
#define DISTORTION_OPTIMIZATION_TEST_MEASURE_TEST_HELPERS_H

#include <CGAL/Distortion_optimization/internal/cell_distortion.h>
#include <CGAL/Distortion_optimization/measure_by_name.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <tuple>

namespace measure_tests {

namespace DO = CGAL::Distortion_optimization;
using DO::internal::Matrix;
using DO::internal::Vector;

inline const double inf = std::numeric_limits<double>::infinity();

inline auto all_measures()
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

inline std::mt19937& rng()
{
  static std::mt19937 g(12345);
  return g;
}

inline double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng()); }

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

} // namespace measure_tests

#endif // DISTORTION_OPTIMIZATION_TEST_MEASURE_TEST_HELPERS_H
