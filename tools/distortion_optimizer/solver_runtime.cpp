// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the tool runs its sparse solver's libraries (solver_runtime.h); bench_sparse_solvers_as_the_tool
// links this file to measure them the same way.

#include "solver_runtime.h"

#include <CGAL/Distortion_optimization/sparse_solver.h>

#include <dlfcn.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace distortion_optimizer {

namespace {

// The BLAS of CHOLMOD's factorizations (OpenBLAS) starts a thread per core when loaded and lets
// them spin while they wait. A triangle mesh's supernodes are small: more threads did not make its
// factorizations faster, and the spinning threads took a core from the tool's own (TBB's)
// parallel steps. Looked up at run time: a build without CHOLMOD, or with another BLAS, has no
// such function.
void keep_blas_on_one_thread()
{
  using Setter = void (*)(int);
  if(const auto set = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
}

// Each numeric factorization of CHOLMOD allocates and frees its workspaces (the permuted matrix,
// the update matrices): glibc's malloc maps blocks that large afresh and unmaps them when freed,
// so that every factorization paid a page fault per page it touched.
void keep_freed_memory()
{
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

// With CHOLMOD's OpenMP regions on the calling thread (below) and its freed workspaces kept, its
// supernodal factorization is faster than Eigen's simplicial one from a few thousand unknowns on,
// not only from the library's default of 32,768, which suits a program that runs CHOLMOD as it
// comes.
void factor_systems_of_a_few_thousand_unknowns_with_cholmod()
{
#ifdef __GLIBC__
  CGAL::Distortion_optimization::set_cholmod_threshold(4096);
#endif
}

} // namespace

void set_up_sparse_solvers()
{
  keep_blas_on_one_thread();
  keep_freed_memory();
  factor_systems_of_a_few_thousand_unknowns_with_cholmod();
}

} // namespace distortion_optimizer

// CHOLMOD's OpenMP regions, run by the calling thread. The supernodal factorization of CHOLMOD 3
// (SuiteSparse 5, as Debian packages it) opens a parallel region for each supernode and each
// update it receives, with an `if` clause that keeps all but the largest on one thread. GCC's
// runtime still sets up a team for each and wakes its barrier with a system call, a large share
// of a factorization's time on a triangle mesh's Newton system (figures: the manual's section on
// the sparse solver). The loops are memory-bound copies and clears; the dense work is in the
// BLAS. The tool therefore defines GCC's entry point for a parallel region (`GOMP_parallel`, the
// only one CHOLMOD uses): the dynamic linker binds CHOLMOD's calls to the executable's definition
// first. A region met outside any other runs its body once on the calling
// thread, as a team of one would (its `omp_get_num_threads()` is then 1 and `omp_get_thread_num()`
// 0); a region nested in a running one (none in the tool) goes to the runtime's own.
// A library user on one thread can do the same in their program; the library does not.

#ifdef CGAL_DISTORTION_OPTIMIZATION_LINKED_WITH_CHOLMOD

namespace {

using Parallel = void (*)(void (*)(void*), void*, unsigned, unsigned);
using Level = int (*)();

template <class F>
F runtime_function(const char* name)
{
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

} // namespace

extern "C" void GOMP_parallel(void (*body)(void*), void* data, unsigned threads, unsigned flags)
{
  static const Parallel runtime_parallel = runtime_function<Parallel>("GOMP_parallel");
  static const Level level = runtime_function<Level>("omp_get_level");
  if(runtime_parallel && level && level() > 0)
    runtime_parallel(body, data, threads, flags);
  else
    body(data);
}

#endif
