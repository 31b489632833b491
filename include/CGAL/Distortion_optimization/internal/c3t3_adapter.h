// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Translates the cells of a Mesh_complex_3_in_triangulation_3 (only those in the complex) and a
// target map keyed by Vertex_handle into the flat arrays of Simplicial_map<3>, and writes the
// targets back.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// True for the complexes of CGAL's Mesh_3 (what the C3T3 overloads accept).
template <class T, class = void>
struct Is_c3t3 : std::false_type {};
template <class T>
struct Is_c3t3<T, std::void_t<typename T::Triangulation, typename T::Cells_in_complex_iterator>> : std::true_type {};

// Dense indices of handles by open addressing on their addresses. The adapter looks up four per
// cell, and std::unordered_map's (a division and a list node per lookup) were a large share of the
// adapter's time.
class Handle_index
{
public:
  explicit Handle_index(std::size_t expected)
  {
    while(slots_ < 2 * expected + 2) slots_ *= 2, ++bits_;
    keys_.assign(slots_, 0);
    values_.resize(slots_);
  }

  // The index of `address`, or `fresh` if it had none (then `inserted`).
  std::uint32_t find_or_insert(const void* address, std::uint32_t fresh, bool& inserted)
  {
    if(2 * (size_ + 1) > slots_) grow();
    const std::uintptr_t key = reinterpret_cast<std::uintptr_t>(address);
    std::size_t i = slot(key);
    for(; keys_[i] != 0; i = (i + 1) & (slots_ - 1))
      if(keys_[i] == key) return inserted = false, values_[i];
    keys_[i] = key;
    values_[i] = fresh;
    ++size_;
    return inserted = true, fresh;
  }

private:
  // Fibonacci hashing: the high bits of the product mix all of the address's.
  std::size_t slot(std::uintptr_t key) const
  {
    return static_cast<std::size_t>((std::uint64_t(key) * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
  }

  void grow()
  {
    std::vector<std::uintptr_t> keys;
    std::vector<std::uint32_t> values;
    keys.swap(keys_);
    values.swap(values_);
    slots_ *= 2;
    ++bits_;
    keys_.assign(slots_, 0);
    values_.resize(slots_);
    size_ = 0;
    bool inserted;
    for(std::size_t i = 0; i < keys.size(); ++i)
      if(keys[i] != 0) find_or_insert(reinterpret_cast<const void*>(keys[i]), values[i], inserted);
  }

  std::size_t slots_ = 2, size_ = 0;
  int bits_ = 1;
  std::vector<std::uintptr_t> keys_;   // 0: empty (no handle is at address 0)
  std::vector<std::uint32_t> values_;
};

template <class C3T3, class GeomTraits>
class C3t3_adapter
{
public:
  static constexpr int dimension = 3;
  using Triangulation = typename C3T3::Triangulation;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Cell_handle = typename Triangulation::Cell_handle;
  using Geom_traits = GeomTraits;

  Simplicial_map<3> map;
  std::vector<Vertex_handle> vertex_of;       // vertex index -> handle (vertices of complex cells)
  std::vector<Cell_handle> cell_of;           // cell index -> handle
  std::vector<unsigned char> on_boundary;     // vertex on a facet shared with a cell not in the complex
  GeomTraits traits;
  double scale = 1;                           // of map's coordinates (coordinate_scale)

  // The cells in the complex's order, their vertices numbered in the order the cells first reach
  // them. Two passes: the handles first, then the geometry and the boundary facets, whose four
  // neighbours per cell lie anywhere in memory: in a loop of its own their loads overlap. Errors
  // are those a single pass in order meets first.
  template <class TargetMap>
  C3t3_adapter(const C3T3& c3t3, const TargetMap& target, const GeomTraits& gt) : traits(gt)
  {
    const Triangulation& tr = c3t3.triangulation();
    auto point = tr.geom_traits().construct_point_3_object();
    const std::size_t expected = c3t3.number_of_cells_in_complex();
    Handle_index index(tr.number_of_vertices());
    std::vector<typename Simplicial_map<3>::Cell> cells;
    std::vector<Vector<3>> source;   // per vertex
    cells.reserve(expected);
    cell_of.reserve(expected);
    map.reserve(expected, tr.number_of_vertices());
    vertex_of.reserve(tr.number_of_vertices());
    on_boundary.reserve(tr.number_of_vertices());
    source.reserve(tr.number_of_vertices());
    // Up to the first vertex with a non-finite target, whose message then follows the earlier
    // cells' orientation tests.
    std::string non_finite;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      typename Simplicial_map<3>::Cell cell;
      for(int i = 0; i < 4; ++i) {
        const Vertex_handle v = c->vertex(i);
        bool inserted;
        cell[i] = index.find_or_insert(&*v, static_cast<std::uint32_t>(vertex_of.size()), inserted);
        if(!inserted) continue;
        const auto& y = get(target, v);
        const Vector<3> x(CGAL::to_double(y.x()), CGAL::to_double(y.y()), CGAL::to_double(y.z()));
        if(!x.allFinite()) {
          non_finite = "vertex " + std::to_string(vertex_of.size()) + " has a non-finite target coordinate";
          break;
        }
        const auto& q = point(tr.point(c, i));
        source.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
        map.target.push_back(x);
        vertex_of.push_back(v);
        on_boundary.push_back(0);
      }
      if(!non_finite.empty()) break;
      cells.push_back(cell);
      cell_of.push_back(Cell_handle(c));
    }
    scale = coordinate_scale(source, map.target);
    map.resize_cells(cells.size());
    std::size_t flat = cells.size();   // the first cell flat in doubles
    using P = typename GeomTraits::Point_3;
    for(std::size_t k = 0; k < cells.size(); ++k) {
      const auto& cell = cells[k];
      std::array<P, 4> p;
      for(int i = 0; i < 4; ++i) p[i] = P(source[cell[i]][0], source[cell[i]][1], source[cell[i]][2]);
      if(traits.orientation_3_object()(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE)
        throw Invalid_input("source cell " + std::to_string(k) + " of the complex is not positively oriented (degenerate)");
      // The source's edges are scaled rather than its points, which the exact orientation test
      // reads as they are: a difference scaled once is rounded once, where points scaled down
      // below 2^-1022 would lose bits before it.
      Matrix<3> Dm;
      for(int j = 0; j < 3; ++j) Dm.col(j) = source[cell[j + 1]] - source[cell[0]];
      if(!map.set_cell(k, cell, scale * Dm, +1)) flat = std::min(flat, k);
      for(int i = 0; i < 4; ++i)
        if(!c3t3.is_in_complex(cell_of[k]->neighbor(i)))
          for(int j = 0; j < 4; ++j)
            if(j != i) on_boundary[cell[j]] = 1;
    }
    if(!non_finite.empty()) throw Invalid_input(non_finite);
    if(cells.empty()) throw Invalid_input("the complex has no cell");
    check_comparable_sizes<3>(largest_extent(source), largest_extent(map.target));
    if(flat < cells.size())
      throw Invalid_input("source cell " + std::to_string(flat) + " of the complex is degenerate in double precision (its "
                          "vertices are not exactly coplanar, but so nearly that its rounded edges are)");
    scale_exactly(map.target, scale);
  }

  // Writes the targets x of the free vertices into the target map.
  template <class TargetMap>
  void write_targets(TargetMap target, const std::vector<Vector<3>>& x, const std::vector<unsigned char>& is_free) const
  {
    using Point_3 = typename boost::property_traits<TargetMap>::value_type;
    for(std::size_t i = 0; i < vertex_of.size(); ++i)
      if(is_free[i]) put(target, vertex_of[i], Point_3(x[i][0] / scale, x[i][1] / scale, x[i][2] / scale));
  }
};

// The adapter with the predicates of `geom_traits` (default: the kernel of the triangulation's points).
template <class C3T3, class TargetMap, class NamedParameters>
auto make_c3t3_adapter(const C3T3& c3t3, const TargetMap& target, const NamedParameters& np)
{
  using Default = typename CGAL::Kernel_traits<typename C3T3::Triangulation::Geom_traits::Point_3>::Kernel;
  using GT = typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters, Default>::type;
  const GT gt = CGAL::parameters::choose_parameter<GT>(CGAL::parameters::get_parameter(np, CGAL::internal_np::geom_traits));
  return C3t3_adapter<C3T3, GT>(c3t3, target, gt);
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H
