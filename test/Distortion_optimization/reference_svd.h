// Test and benchmark helper: Eigen's JacobiSVD in the package's signed convention, the reference
// the closed forms of internal/svd.h are checked and timed against.

#ifndef DISTORTION_OPTIMIZATION_TEST_REFERENCE_SVD_H
#define DISTORTION_OPTIMIZATION_TEST_REFERENCE_SVD_H

#include <CGAL/Distortion_optimization/internal/svd.h>

#include <Eigen/SVD>

namespace reference {

template <int n>
bool signed_svd_jacobi(const CGAL::Distortion_optimization::internal::Matrix<n>& J,
                       CGAL::Distortion_optimization::internal::Signed_svd<n>& out)
{
  if(!J.allFinite()) {
    out.sigma = CGAL::Distortion_optimization::internal::not_a_number_vector<n>();
    return false;
  }
  Eigen::JacobiSVD<CGAL::Distortion_optimization::internal::Matrix<n>> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  out.U = svd.matrixU();
  out.V = svd.matrixV();
  out.sigma = svd.singularValues();
  // Reflections go into the last singular value, so that U and V are rotations.
  if(out.U.determinant() < 0) { out.U.col(n - 1) *= -1; out.sigma[n - 1] *= -1; }
  if(out.V.determinant() < 0) { out.V.col(n - 1) *= -1; out.sigma[n - 1] *= -1; }
  return true;
}

} // namespace reference

#endif // DISTORTION_OPTIMIZATION_TEST_REFERENCE_SVD_H
