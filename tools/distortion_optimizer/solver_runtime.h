// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the tool runs the libraries of its sparse solver (CHOLMOD, OpenBLAS); the figures behind
// each setting are in the manual's section on the sparse solver. bench_sparse_solvers_as_the_tool
// links solver_runtime.cpp to measure them as the tool runs them.

#ifndef DISTORTION_OPTIMIZER_SOLVER_RUNTIME_H
#define DISTORTION_OPTIMIZER_SOLVER_RUNTIME_H

namespace distortion_optimizer {

// Once, before any factorization: the BLAS on one thread whatever --threads says, large freed
// blocks kept in the heap for the next factorization, and CHOLMOD from 4,096 unknowns on
// (set_cholmod_threshold()). CHOLMOD's OpenMP regions run on the calling thread whenever the
// program links solver_runtime.cpp (its GOMP_parallel, built only with CHOLMOD).
void set_up_sparse_solvers();

} // namespace distortion_optimizer

#endif // DISTORTION_OPTIMIZER_SOLVER_RUNTIME_H
