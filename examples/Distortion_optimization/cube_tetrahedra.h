// A block of n x n x n cubes, each cut into the six tetrahedra around its main diagonal
// (Freudenthal's, or Kuhn's, subdivision: the cuts of neighbouring cubes match across their common
// face), as points and cells for CGAL::Distortion_optimization::c3t3_from_tetrahedra() or a
// tetrahedron writer. Shared by the volume examples, the tests and the benchmarks.

#ifndef DISTORTION_OPTIMIZATION_EXAMPLES_CUBE_TETRAHEDRA_H
#define DISTORTION_OPTIMIZATION_EXAMPLES_CUBE_TETRAHEDRA_H

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace volume_examples {

struct Cube_tetrahedra
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> cells;
};

// The grid point (i, j, k), 0 <= i, j, k <= n, is at (coordinate(i), coordinate(j), coordinate(k))
// and has index i + (n + 1) (j + (n + 1) k); `coordinate` must increase. The cube with lowest
// corner (i, j, k) is cut only if keep(i, j, k). Each tetrahedron is a path from the cube's
// lowest corner to its highest along the three axes in one of their six orders; those of odd
// orders have their last two vertices swapped, so that every tetrahedron is positively oriented.
template <class Coordinate, class Keep>
Cube_tetrahedra cube_tetrahedra(int n, const Coordinate& coordinate, const Keep& keep)
{
  Cube_tetrahedra block;
  for(int k = 0; k <= n; ++k)
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) block.points.push_back({coordinate(i), coordinate(j), coordinate(k)});
  const auto at = [n](const int c[3]) { return std::size_t((c[2] * (n + 1) + c[1]) * (n + 1) + c[0]); };
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const bool odd[6] = {false, true, true, false, false, true};
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        if(!keep(i, j, k)) continue;
        for(int o = 0; o < 6; ++o) {
          int c[3] = {i, j, k};
          std::array<std::size_t, 4> t;
          t[0] = at(c);
          for(int s = 0; s < 3; ++s) {
            ++c[orders[o][s]];
            t[s + 1] = at(c);
          }
          if(odd[o]) std::swap(t[2], t[3]);
          block.cells.push_back(t);
        }
      }
  return block;
}

template <class Coordinate>
Cube_tetrahedra cube_tetrahedra(int n, const Coordinate& coordinate)
{
  return cube_tetrahedra(n, coordinate, [](int, int, int) { return true; });
}

} // namespace volume_examples

#endif // DISTORTION_OPTIMIZATION_EXAMPLES_CUBE_TETRAHEDRA_H
