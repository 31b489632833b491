// The measures' derivatives (no mesh involved): gradients and projected Hessians against finite
// differences, and the batched kernel against the cell-by-cell one.

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
#include <vector>

using namespace measure_tests;

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
  // Every measure but the custom one: the eight built-ins, the typed and the run-time
  // combinations of them.
  EXPECT_EQ(measures_with_hessian, 12u);
}

// Where singular values coincide (at the minimum of K, the condition number and C, and where
// their maxima change sides), the projected cell Hessian is finite and positive semi-definite;
// at a kink (D_i != D_j where s_i = s_j) the flip mode's eigenvalue stays large.
template <int n>
void check_clustered_hessians()
{
  std::vector<std::vector<double>> values = {{1, 1}, {2, 2}, {1.5, 1.5 - 1e-9}};
  if(n == 3) values = {{1, 1, 1}, {2, 2, 1}, {2, 1, 1}, {1.2, 1.2 - 1e-9, 0.5}};
  std::vector<Vector<n>> clustered;
  for(const std::vector<double>& v : values) clustered.push_back(Eigen::Map<const Vector<n>>(v.data()));
  for_each_measure([&](const auto& m) {
    using Measure = std::decay_t<decltype(m)>;
    if constexpr(DO::measures_internal::Has_hessian<Measure, n>::value) {
      for(const Vector<n>& s : clustered) {
        const Matrix<n> J = with_singular_values<n>(s), M = random_well_conditioned<n>().inverse();
        DO::internal::Cell_hessian<n> H;
        std::array<Vector<n>, n + 1> gradient;
        ASSERT_TRUE(DO::internal::cell_hessian<n>(m, J, M, H, gradient, true)) << m.name();
        ASSERT_TRUE(H.allFinite()) << m.name() << " s=" << s.transpose();
        const Eigen::SelfAdjointEigenSolver<DO::internal::Cell_hessian<n>> psd(H);
        EXPECT_GE(psd.eigenvalues().minCoeff(), -1e-10 * std::max(1., psd.eigenvalues().maxCoeff())) << m.name();
      }
    }
  });
  // K in 2D at a conformal Jacobian: moving away from it along a shear raises K linearly, so
  // the Hessian in that direction is far above the curvature of MIPS (2 there).
  const Matrix<n> M = Matrix<n>::Identity();
  DO::internal::Cell_hessian<n> H;
  std::array<Vector<n>, n + 1> gradient;
  ASSERT_TRUE(DO::internal::cell_hessian<n>(DO::Conformal_dilatation(), Matrix<n>(Matrix<n>::Identity()), M, H, gradient, true));
  EXPECT_GT(H.norm(), 1e4);
}

TEST(Measures, ClusteredSingularValuesKeepHessiansSemiDefinite2D) { check_clustered_hessians<2>(); }
TEST(Measures, ClusteredSingularValuesKeepHessiansSemiDefinite3D) { check_clustered_hessians<3>(); }

TEST(Measures, HessiansMatchFiniteDifferences2D) { check_hessians<2>(); }
TEST(Measures, HessiansMatchFiniteDifferences3D) { check_hessians<3>(); }

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
