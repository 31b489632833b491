// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optimization compiled once for all the tests: every test file is compiled with this header
// first (CMakeLists.txt), which declares the instantiations of internal::minimize() and
// internal::untangle() that the tests share; instantiations_2.cpp and instantiations_3.cpp define
// them, once. Without it each test file compiled the whole optimizer again for each measure it
// uses. A pair not listed is still compiled where it is used.

#ifndef DISTORTION_OPTIMIZATION_TEST_EXTERN_TEMPLATES_H
#define DISTORTION_OPTIMIZATION_TEST_EXTERN_TEMPLATES_H

#include <CGAL/Distortion_optimization/internal/minimize.h>
#include <CGAL/Distortion_optimization/internal/untangle.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

// DISTORTION_TEST_INSTANTIATE(n) is defined (to the dimension) only in the file that defines the
// instantiations of that dimension.
#define DISTORTION_TEST_INSTANTIATIONS(n, extern_or_not)                                                                  \
  extern_or_not template Untangle_result untangle<n, Test_kernel>(Optimization_problem<n>&, const Test_kernel&,           \
                                                                  const Options&);                                       \
  DISTORTION_TEST_MINIMIZE(n, extern_or_not, Conformal_dilatation)                                                        \
  DISTORTION_TEST_MINIMIZE(n, extern_or_not, MIPS)                                                                        \
  DISTORTION_TEST_MINIMIZE(n, extern_or_not, Isometric_dilatation)                                                        \
  DISTORTION_TEST_MINIMIZE(n, extern_or_not, ARAP)                                                                        \
  DISTORTION_TEST_MINIMIZE(n, extern_or_not, Symmetric_dirichlet)                                                         \
  DISTORTION_TEST_MINIMIZE(n, extern_or_not, Dirichlet)
#define DISTORTION_TEST_MINIMIZE(n, extern_or_not, M)                                                                     \
  extern_or_not template Result minimize<n, M, Test_kernel>(Optimization_problem<n>&, const M&, const Test_kernel&,       \
                                                            const Options&);

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

using Test_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

#if !defined(DISTORTION_TEST_INSTANTIATE) || DISTORTION_TEST_INSTANTIATE != 2
DISTORTION_TEST_INSTANTIATIONS(2, extern)
#endif
#if !defined(DISTORTION_TEST_INSTANTIATE) || DISTORTION_TEST_INSTANTIATE != 3
DISTORTION_TEST_INSTANTIATIONS(3, extern)
#endif

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // DISTORTION_OPTIMIZATION_TEST_EXTERN_TEMPLATES_H
