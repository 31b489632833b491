// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The global steps of a map whose boundary slides on a surface (named parameter
// sliding_boundary): the sliding vertices take a step's part in their tangent planes. Newton's
// step is restricted to them (each cell's Hessian and gradient), the Laplacian's solves for the
// gradient's part in them, and the direction found is projected on them; the line search then
// projects each trial back onto the surface.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_TANGENT_PLANES_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_TANGENT_PLANES_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/cell_hessian.h>
#include <CGAL/Distortion_optimization/internal/laplacian_system.h>

#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The unit normals of the sliding vertices' surfaces where they are (empty without sliding).
template <class State>
std::vector<Vector<State::dimension>> sliding_normals(State& state)
{
  const auto& p = state.problem();
  std::vector<Vector<State::dimension>> normal(p.is_sliding.empty() ? 0 : p.number_of_vertices());
  state.workers().for_each(normal.size(), 1024, [&](std::size_t v) {
    if(p.slides(v)) p.slide(v, state.targets()[v], normal[v]);
  });
  return normal;
}

// Each sliding vertex's row of g (rows: the system's unknowns) in its tangent plane. Its part
// along the normal is a force the surface holds: solved for, it would spread through the interior
// and the step would no longer descend.
template <int n>
void project_on_tangent_planes(const Optimization_problem<n>& p, const Laplacian_system<n>& system,
                               const std::vector<Vector<n>>& normal, Eigen::MatrixXd& g)
{
  for(std::size_t v = 0; v < normal.size(); ++v)
    if(p.slides(v) && system.column(v) >= 0) {
      auto row = g.row(system.column(v));
      row -= row.dot(normal[v].transpose()) * normal[v].transpose();
    }
}

// A cell's Hessian and gradient for Newton's step with its sliding vertices in their tangent
// planes: with P_v = I - n_v n_v^T (P_v = I for the others), P H P and P g, plus a stiffness
// along each sliding vertex's normal (the mean of its diagonal block's, for the scale). The
// normal components then decouple from the rest, with a zero right-hand side, so the direction
// is exactly Newton's restricted to the tangent planes, on the same sparsity pattern.
template <int n>
void restrict_to_tangent_planes(const Optimization_problem<n>& p, const typename Simplicial_map<n>::Cell& cell,
                                const std::vector<Vector<n>>& normal, Cell_hessian<n>& H,
                                std::array<Vector<n>, n + 1>& gradient)
{
  for(int a = 0; a <= n; ++a) {
    if(!p.slides(cell[a])) continue;
    const Vector<n>& u = normal[cell[a]];
    const Matrix<n> P = Matrix<n>::Identity() - u * u.transpose();
    const double stiffness = H.template block<n, n>(n * a, n * a).trace() / n;
    H.template middleRows<n>(n * a) = P * H.template middleRows<n>(n * a);
    H.template middleCols<n>(n * a) = H.template middleCols<n>(n * a) * P;
    H.template block<n, n>(n * a, n * a) += stiffness * u * u.transpose();
    gradient[a] = P * gradient[a];
  }
}

// A step's direction (one per vertex) with the sliding vertices' part in their tangent planes,
// and its slope (slope_of(), the gradient's dot product with it). In the tangent planes the step
// may no longer descend: then the sliding vertices stay (their direction zero).
template <int n, class SlopeOf>
double restrict_direction_to_tangent_planes(const Optimization_problem<n>& p, const Workers& workers,
                                            const std::vector<Vector<n>>& normal, std::vector<Vector<n>>& direction,
                                            const SlopeOf& slope_of)
{
  workers.for_each(direction.size(), 1024, [&](std::size_t v) {
    if(p.slides(v)) direction[v] -= direction[v].dot(normal[v]) * normal[v];
  });
  double slope = slope_of();
  if(!(slope < 0)) {
    for(std::size_t v = 0; v < direction.size(); ++v)
      if(p.slides(v)) direction[v].setZero();
    slope = slope_of();
  }
  return slope;
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GLOBAL_STEP_TANGENT_PLANES_H
