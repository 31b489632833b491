// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Which sparse direct solver factors the systems of triangle maps: the size from which CHOLMOD
// takes over from Eigen's simplicial factorization. A setting of the process, as Eigen's
// setNbThreads(): it depends on how the program runs CHOLMOD, not on a call.

#ifndef CGAL_DISTORTION_OPTIMIZATION_SPARSE_SOLVER_H
#define CGAL_DISTORTION_OPTIMIZATION_SPARSE_SOLVER_H

#include <CGAL/license/Distortion_optimization.h>

#include <atomic>
#include <cstddef>

namespace CGAL {
namespace Distortion_optimization {

namespace internal {
inline std::atomic<std::size_t>& cholmod_threshold_setting()
{
  static std::atomic<std::size_t> unknowns{32768};
  return unknowns;
}
} // namespace internal

/// \ingroup PkgDistortionOptimizationRef
/// The number of unknowns from which a sparse system of the package (the Newton systems of
/// triangle maps, their harmonic starts, Tutte's maps, the atlas's cones) is factored by CHOLMOD's
/// supernodal Cholesky factorization, where the program links
/// `Distortion_optimization::CHOLMOD_support`; smaller ones, and all of them without CHOLMOD, by
/// Eigen's simplicial \f$ LDL^T \f$. The default, 32,768, suits a program that runs CHOLMOD as
/// it comes; one that runs CHOLMOD's OpenMP regions on the calling thread and keeps freed memory
/// in its heap, as the command-line tool does, gains from CHOLMOD on much smaller systems (see the
/// section \ref ssecDistortionCHOLMOD of the user manual). Thread-safe; read as a run sets up its
/// factorizations.
inline std::size_t cholmod_threshold() { return internal::cholmod_threshold_setting().load(); }

/// \ingroup PkgDistortionOptimizationRef
/// Sets `cholmod_threshold()` to `unknowns` (0: CHOLMOD for every system) for the whole program,
/// and returns the value it had.
inline std::size_t set_cholmod_threshold(std::size_t unknowns) { return internal::cholmod_threshold_setting().exchange(unknowns); }

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_SPARSE_SOLVER_H
