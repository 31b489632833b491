// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Translates the cells of a Mesh_complex_3_in_triangulation_3 (only those in the complex) and a
// target map keyed by Vertex_handle into the flat arrays of Simplicial_map<3>, and writes the
// targets back.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_ADAPTER_H

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
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
// cell, and std::unordered_map's (a division and a list node per lookup) took over a third of the
// adapter's time (54K cells: 6 of 17 ms).
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

  template <class TargetMap>
  C3t3_adapter(const C3T3& c3t3, const TargetMap& target, const GeomTraits& gt) : traits(gt)
  {
    const Triangulation& tr = c3t3.triangulation();
    auto point = tr.geom_traits().construct_point_3_object();
    Handle_index index(tr.number_of_vertices());
    const auto index_of = [&](Vertex_handle v) {
      bool inserted;
      const std::uint32_t i = index.find_or_insert(&*v, static_cast<std::uint32_t>(vertex_of.size()), inserted);
      if(inserted) {
        const auto& y = get(target, v);
        Vector<3> x(CGAL::to_double(y.x()), CGAL::to_double(y.y()), CGAL::to_double(y.z()));
        if(!x.allFinite())
          throw Invalid_input("vertex " + std::to_string(vertex_of.size()) + " has a non-finite target coordinate");
        map.target.push_back(x);
        vertex_of.push_back(v);
        on_boundary.push_back(0);
      }
      return i;
    };
    using P = typename GeomTraits::Point_3;
    std::vector<std::pair<typename Simplicial_map<3>::Cell, Matrix<3>>> cells;
    cells.reserve(c3t3.number_of_cells_in_complex());
    cell_of.reserve(c3t3.number_of_cells_in_complex());
    map.reserve(c3t3.number_of_cells_in_complex(), tr.number_of_vertices());
    vertex_of.reserve(tr.number_of_vertices());
    on_boundary.reserve(tr.number_of_vertices());
    double source_largest = 0, target_largest = 0;
    Vector<3> low = Vector<3>::Constant(std::numeric_limits<double>::infinity()), high = -low;  // the source's box
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      typename Simplicial_map<3>::Cell cell;
      std::array<Vector<3>, 4> x;
      std::array<P, 4> p;
      for(int i = 0; i < 4; ++i) {
        cell[i] = index_of(c->vertex(i));
        const auto& q = point(tr.point(c, i));
        x[i] = Vector<3>(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
        p[i] = P(x[i][0], x[i][1], x[i][2]);
        source_largest = std::max(source_largest, x[i].cwiseAbs().maxCoeff());
        low = low.cwiseMin(x[i]);
        high = high.cwiseMax(x[i]);
      }
      if(traits.orientation_3_object()(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE)
        throw Invalid_input("source cell " + std::to_string(cell_of.size()) + " of the complex is not positively oriented "
                            "(degenerate)");
      Matrix<3> Dm;
      for(int k = 0; k < 3; ++k) Dm.col(k) = x[k + 1] - x[0];
      cells.emplace_back(cell, Dm);
      cell_of.push_back(Cell_handle(c));
      for(int i = 0; i < 4; ++i)
        if(!c3t3.is_in_complex(c->neighbor(i)))
          for(int j = 0; j < 4; ++j)
            if(j != i) on_boundary[cell[j]] = 1;
    }
    if(cell_of.empty())
      throw Invalid_input("the complex has no cell");
    for(const Vector<3>& y : map.target) target_largest = std::max(target_largest, y.cwiseAbs().maxCoeff());
    scale = coordinate_scale(source_largest, target_largest);
    check_comparable_sizes<3>((high - low).maxCoeff(), largest_extent(map.target));
    for(Vector<3>& y : map.target) y *= scale;
    for(std::size_t c = 0; c < cells.size(); ++c)
      if(!map.add_cell(cells[c].first, scale * cells[c].second, +1))
        throw Invalid_input("source cell " + std::to_string(c) + " of the complex is degenerate in double precision (its "
                            "vertices are not exactly coplanar, but so nearly that its rounded edges are)");
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
