// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Algorithm 2 (GreedyGradDescent): every free vertex is optimized once per sweep, the one with the
// largest omega(v) dist_w(f, v) first. In the paper's order (greedy_sweep) the keys live in an
// indexed max-heap and follow the changes of the cells a move touches; the default order
// (sorted_sweep) sorts the keys once per sweep, for the same energies at less cost.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GREEDY_SWEEP_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GREEDY_SWEEP_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/optimization_problem.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// A binary max-heap of vertex indices whose keys can change while they are in it.
class Indexed_max_heap
{
public:
  explicit Indexed_max_heap(std::size_t size) : position_(size, absent), key_(size, 0.) {}

  bool empty() const { return heap_.empty(); }
  bool contains(std::size_t v) const { return position_[v] != absent; }

  void push(std::size_t v, double key)
  {
    key_[v] = key;
    position_[v] = heap_.size();
    heap_.push_back(static_cast<std::uint32_t>(v));
    up(heap_.size() - 1);
  }

  std::size_t pop()
  {
    const std::size_t top = heap_.front();
    move(heap_.size() - 1, 0);
    heap_.pop_back();
    position_[top] = absent;
    if(!heap_.empty()) down(0);
    return top;
  }

  void add_to_key(std::size_t v, double delta)
  {
    key_[v] += delta;
    if(delta > 0) up(position_[v]);
    else down(position_[v]);
  }

private:
  static constexpr std::size_t absent = static_cast<std::size_t>(-1);

  void move(std::size_t from, std::size_t to)
  {
    heap_[to] = heap_[from];
    position_[heap_[to]] = to;
  }
  void up(std::size_t i)
  {
    const std::uint32_t v = heap_[i];
    while(i > 0 && key_[heap_[(i - 1) / 2]] < key_[v]) { move((i - 1) / 2, i); i = (i - 1) / 2; }
    heap_[i] = v;
    position_[v] = i;
  }
  void down(std::size_t i)
  {
    const std::uint32_t v = heap_[i];
    for(;;) {
      std::size_t child = 2 * i + 1;
      if(child >= heap_.size()) break;
      if(child + 1 < heap_.size() && key_[heap_[child + 1]] > key_[heap_[child]]) ++child;
      if(!(key_[heap_[child]] > key_[v])) break;
      move(child, i);
      i = child;
    }
    heap_[i] = v;
    position_[v] = i;
  }

  std::vector<std::uint32_t> heap_;
  std::vector<std::size_t> position_;
  std::vector<double> key_;
};

// Optimizes each of the given vertices once, the most distorted (at the start) first. Ties keep
// the given order, so that the result does not depend on the sort's implementation.
template <class LocalStep>
void sorted_sweep(LocalStep& step, const std::vector<std::uint32_t>& vertices)
{
  std::vector<std::pair<double, std::uint32_t>> keyed;
  keyed.reserve(vertices.size());
  for(std::uint32_t v : vertices) keyed.emplace_back(step.state().vertex_distortion(v), v);
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for(const auto& kv : keyed) step.optimize(kv.second);
}

// The paper's order: always the most distorted remaining vertex.
template <class LocalStep>
void greedy_sweep(LocalStep& step, const std::vector<std::uint32_t>& vertices)
{
  const auto& state = step.state();
  const auto& p = state.problem();
  Indexed_max_heap heap(p.number_of_vertices());
  for(std::uint32_t v : vertices) heap.push(v, state.vertex_distortion(v));
  std::vector<double> before;
  while(!heap.empty()) {
    const std::size_t v = heap.pop();
    const std::uint32_t begin = p.ring_begin[v], end = p.ring_begin[v + 1];
    before.resize(end - begin);
    for(std::uint32_t k = begin; k < end; ++k) before[k - begin] = state.value(p.ring[k].cell);
    if(!step.optimize(v)) continue;
    // The neighbours' keys follow the change of each cell they share with v.
    for(std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t c = p.ring[k].cell;
      const double change = p.incidence_weight[c] * (state.value(c) - before[k - begin]);
      if(change == 0) continue;
      for(auto u : p.map.cells[c])
        if(u != v && heap.contains(u)) heap.add_to_key(u, p.omega[u] * change);
    }
  }
}

// One sequential sweep over the given vertices in the chosen order.
template <class LocalStep>
void sequential_sweep(LocalStep& step, const std::vector<std::uint32_t>& vertices, Vertex_order order)
{
  if(order == Vertex_order::GREEDY) greedy_sweep(step, vertices);
  else sorted_sweep(step, vertices);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_GREEDY_SWEEP_H
