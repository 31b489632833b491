// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The package's only contact with TBB. As elsewhere in CGAL, parallelism exists when the program
// links CGAL::TBB_support (which defines CGAL_LINKED_WITH_TBB); without it every loop below runs
// sequentially and the results are the same.
// Every parallel loop here writes disjoint data, and reductions combine fixed chunks in a fixed
// order, so a result never depends on the number of threads or on scheduling.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_PARALLEL_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_PARALLEL_H

#include <CGAL/license/Distortion_optimization.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// A fixed number of worker threads (TBB's arena), 1 without TBB.
class Workers
{
public:
  // requested <= 0: all the hardware offers.
  explicit Workers(int requested = 1)
  {
#ifdef CGAL_LINKED_WITH_TBB
    threads_ = requested <= 0 ? tbb::this_task_arena::max_concurrency() : requested;   // TBB 2019 and oneTBB
    // More threads than the hardware's: TBB would run fewer and print a warning on the standard
    // error; the threads asked for are allowed while these workers exist.
    if(threads_ > tbb::this_task_arena::max_concurrency())
      allowance_.emplace(tbb::global_control::max_allowed_parallelism, threads_);
    if(threads_ > 1) arena_ = std::make_unique<tbb::task_arena>(threads_);
#else
    (void)requested;
#endif
  }

  int threads() const { return threads_; }

  // Runs body(i) for i in [0, count), in chunks of at least `grain`; body(i) must write only data
  // owned by i.
  template <class Body>
  void for_each(std::size_t count, std::size_t grain, const Body& body) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(arena_ && count > grain) {
      arena_->execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain), [&](const tbb::blocked_range<std::size_t>& r) {
          for(std::size_t i = r.begin(); i != r.end(); ++i) body(i);
        });
      });
      return;
    }
#endif
    (void)grain;
    for(std::size_t i = 0; i < count; ++i) body(i);
  }

  // Runs body(first, size) on the blocks [first, first + size) of at most `block` indices that
  // cover [0, count), in parallel: for kernels that work on several indices at once.
  template <class Body>
  void for_each_block(std::size_t count, std::size_t block, const Body& body) const
  {
    for_each((count + block - 1) / block, 1, [&](std::size_t k) { body(k * block, std::min(block, count - k * block)); });
  }

  // combine(..., term(i), ...) over i in [0, count), the same whatever the number of threads: fixed
  // chunks reduced in parallel, then combined in order.
  template <class T, class Term, class Combine>
  T reduce(std::size_t count, T identity, const Term& term, const Combine& combine) const
  {
    constexpr std::size_t chunk = 2048;
    const std::size_t chunks = (count + chunk - 1) / chunk;
    // An array, not a std::vector: std::vector<bool> packs bits, and chunks written by different
    // threads would share words.
    const std::unique_ptr<T[]> partial(new T[chunks]);
    for_each(chunks, 1, [&](std::size_t k) {
      T r = identity;
      for(std::size_t i = k * chunk; i < std::min(count, (k + 1) * chunk); ++i) r = combine(r, term(i));
      partial[k] = r;
    });
    T r = identity;
    for(std::size_t k = 0; k < chunks; ++k) r = combine(r, partial[k]);
    return r;
  }

  template <class Term>
  double sum(std::size_t count, const Term& term) const
  {
    return reduce(count, 0., term, [](double a, double b) { return a + b; });
  }

private:
  int threads_ = 1;
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> allowance_;   // before the arena, which it outlives
  std::unique_ptr<tbb::task_arena> arena_;
#endif
};

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_PARALLEL_H
