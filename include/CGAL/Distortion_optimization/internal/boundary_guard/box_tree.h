// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A bounding volume hierarchy over boxes that move a little at a time (the boundary guard's faces
// under single-vertex moves). Each leaf stores its box enlarged by a margin (a quarter of its
// largest extent), so that most moves leave a face inside it; refit() gives a leaf that has left
// its stored box a fresh enlarged one and grows its ancestors to contain it (O(log B)). Boxes only
// grow, so the owner rebuilds once refits() passes a fraction of the leaves: O(log B) amortized.
// CGAL::AABB_tree cannot refit a single leaf (and is 3D only), hence this tree. Not thread-safe:
// visit() shares scratch space.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_BOX_TREE_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_BOX_TREE_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/internal/cell_derivatives.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {
namespace boundary_guard {

template <int n>
class Box_tree
{
public:
  using Box = Eigen::AlignedBox<double, n>;

  // Leaf i stores boxes[i], enlarged; replaces what the tree held.
  void build(std::vector<Box> boxes)
  {
    const std::size_t B = boxes.size();
    std::vector<Vector<n>> centres(B);
    for(std::uint32_t f = 0; f < B; ++f) {
      boxes[f] = enlarged(boxes[f]);
      centres[f] = boxes[f].center();
    }
    std::vector<std::uint32_t> order(B);
    std::iota(order.begin(), order.end(), 0u);
    nodes_.clear();
    nodes_.reserve(2 * B);
    leaf_.assign(B, 0);
    refits_ = 0;
    if(B > 0) build_subtree(order.data(), order.data() + B, -1, boxes, centres);
  }

  // Whether the last build() was given `leaves` boxes.
  bool holds(std::size_t leaves) const { return nodes_.size() == 2 * leaves - (leaves == 0 ? 0 : 1); }

  // Makes leaf f's stored box contain `now`: unless it does already, a fresh enlarged box.
  void refit(std::uint32_t f, const Box& now)
  {
    std::int32_t node = leaf_[f];
    if(nodes_[node].box.contains(now)) return;
    const Box stored = enlarged(now);
    nodes_[node].box = stored;
    // Ancestors grow until one already holds the new box (then all above it do too).
    for(node = nodes_[node].parent; node >= 0 && !nodes_[node].box.contains(stored);
        node = nodes_[node].parent)
      nodes_[node].box.extend(stored);
    ++refits_;
  }

  // How many leaves refit() gave a fresh box since the last build().
  std::size_t refits() const { return refits_; }

  // Calls report(leaf) for each leaf whose stored box meets `query` (closed boxes) until it
  // returns false; returns false iff stopped.
  template <class Report>
  bool visit(const Box& query, const Report& report)
  {
    if(nodes_.empty()) return true;
    stack_.assign(1, 0);
    while(!stack_.empty()) {
      const Node& node = nodes_[stack_.back()];
      stack_.pop_back();
      if(!node.box.intersects(query)) continue;
      if(node.child[0] < 0) {
        if(!report(static_cast<std::uint32_t>(-1 - node.child[0]))) return false;
      } else {
        stack_.push_back(node.child[0]);
        stack_.push_back(node.child[1]);
      }
    }
    return true;
  }

private:
  struct Node
  {
    Box box;
    std::int32_t parent;
    std::array<std::int32_t, 2> child;   // a leaf holds child[0] = -1 - leaf
  };
  static constexpr double margin = 0.25;   // of a box's largest extent

  std::vector<Node> nodes_;                  // root is nodes_[0]
  std::vector<std::int32_t> leaf_;           // node of each leaf
  std::size_t refits_ = 0;
  std::vector<std::int32_t> stack_;          // scratch of visit()

  static Box enlarged(Box b)
  {
    const double m = margin * b.sizes().maxCoeff();
    b.min().array() -= m;
    b.max().array() += m;
    return b;
  }

  // Median split on the longest axis of the centres: depth ceil(log2 B).
  std::int32_t build_subtree(std::uint32_t* begin, std::uint32_t* end, std::int32_t parent,
                             const std::vector<Box>& boxes, const std::vector<Vector<n>>& centres)
  {
    const auto index = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(Node{Box(), parent, {{0, 0}}});
    if(end - begin == 1) {
      nodes_[index].box = boxes[*begin];
      nodes_[index].child[0] = -1 - static_cast<std::int32_t>(*begin);
      leaf_[*begin] = index;
      return index;
    }
    Box span;
    for(const std::uint32_t* f = begin; f != end; ++f) span.extend(centres[*f]);
    int axis = 0;
    span.sizes().maxCoeff(&axis);
    std::uint32_t* mid = begin + (end - begin) / 2;
    std::nth_element(begin, mid, end,
                     [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
    const std::int32_t left = build_subtree(begin, mid, index, boxes, centres);
    const std::int32_t right = build_subtree(mid, end, index, boxes, centres);
    nodes_[index].child = {{left, right}};
    nodes_[index].box = nodes_[left].box.merged(nodes_[right].box);
    return index;
  }
};

} // namespace boundary_guard
} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_BOUNDARY_GUARD_BOX_TREE_H
