// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optimizer compiled once for the whole build: every file of the tool, the examples, the tests
// and the benchmarks that calls it is compiled with this header first, precompiled
// (CMakeLists.txt), which declares the instantiations of internal::minimize() and
// internal::untangle() that they share; the files minimize_*.cpp beside it define them, once, a
// few measures per file so that each compiles in well under two minutes. Without it each file
// compiled the whole optimizer again for each measure it uses. A measure or kernel not listed is
// still compiled where it is used, so the sources need nothing of this. The Mesh_3 front end has
// its own list (extern_mesh_interior.h), read only by the files that mesh.

#ifndef DISTORTION_OPTIMIZATION_EXTERN_TEMPLATES_H
#define DISTORTION_OPTIMIZATION_EXTERN_TEMPLATES_H

#include <CGAL/Distortion_optimization/Any_measure.h>
#include <CGAL/Distortion_optimization/internal/minimize.h>
#include <CGAL/Distortion_optimization/internal/untangle.h>
#include <CGAL/Distortion_optimization/measures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

// The groups of instantiations, each defined by one file (minimize_<group>.cpp): `extern` here,
// nothing there.
#define DISTORTION_MINIMIZE(n, extern_or_not, M)                                                                        \
  extern_or_not template Result minimize<n, M, Shared_kernel>(Optimization_problem<n>&, const M&,                       \
                                                              const Shared_kernel&, const Options&);
#define DISTORTION_GROUP_1(n, extern_or_not)                                                                            \
  DISTORTION_MINIMIZE(n, extern_or_not, Conformal_dilatation)                                                           \
  DISTORTION_MINIMIZE(n, extern_or_not, MIPS)                                                                           \
  DISTORTION_MINIMIZE(n, extern_or_not, Isometric_dilatation)                                                           \
  DISTORTION_MINIMIZE(n, extern_or_not, ARAP)
#define DISTORTION_GROUP_2(n, extern_or_not)                                                                            \
  DISTORTION_MINIMIZE(n, extern_or_not, Symmetric_dirichlet)                                                            \
  DISTORTION_MINIMIZE(n, extern_or_not, Dirichlet)                                                                      \
  DISTORTION_MINIMIZE(n, extern_or_not, Volume_distortion)                                                              \
  DISTORTION_MINIMIZE(n, extern_or_not, Condition_number)
#define DISTORTION_GROUP_3(n, extern_or_not)                                                                            \
  extern_or_not template Untangle_result untangle<n, Shared_kernel>(Optimization_problem<n>&, const Shared_kernel&,     \
                                                                    const Options&);                                    \
  DISTORTION_MINIMIZE(n, extern_or_not, Any_measure)

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

using Shared_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// Groups 1-3 are the triangle maps', 4-6 the tetrahedral maps'. Groups 3 and 6 (the measure
// chosen at run time, and untangling) are all the tool needs: a library of their own; a target
// that links only that one is compiled with DISTORTION_ANY_MEASURE_ONLY, and so compiles the
// other measures it uses itself. The file that defines a group (minimize_<group>.cpp) follows
// these declarations with the definitions, as the language allows.
#ifndef DISTORTION_ANY_MEASURE_ONLY
DISTORTION_GROUP_1(2, extern)
DISTORTION_GROUP_2(2, extern)
DISTORTION_GROUP_1(3, extern)
DISTORTION_GROUP_2(3, extern)
#endif
DISTORTION_GROUP_3(2, extern)
DISTORTION_GROUP_3(3, extern)

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // DISTORTION_OPTIMIZATION_EXTERN_TEMPLATES_H
