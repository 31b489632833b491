// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
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

#include <dlfcn.h>

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
