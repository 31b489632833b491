// A block of k x k x k unit cubes, each cut into six tetrahedra about its diagonal (Kuhn's
// subdivision), all positively oriented: a small regular tetrahedral mesh for IO and tool tests.

#ifndef DISTORTION_OPTIMIZATION_TEST_KUHN_BLOCK_H
#define DISTORTION_OPTIMIZATION_TEST_KUHN_BLOCK_H

#include <CGAL/Distortion_optimization/IO/simplex_soup.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

inline CGAL::Distortion_optimization::IO::Tetrahedron_soup kuhn_block(int k)
{
  CGAL::Distortion_optimization::IO::Tetrahedron_soup block;
  for(int z = 0; z <= k; ++z)
    for(int y = 0; y <= k; ++y)
      for(int x = 0; x <= k; ++x) block.points.push_back({double(x), double(y), double(z)});
  const auto at = [k](int x, int y, int z) { return std::size_t((z * (k + 1) + y) * (k + 1) + x); };
  for(int z = 0; z < k; ++z)
    for(int y = 0; y < k; ++y)
      for(int x = 0; x < k; ++x) {
        const std::size_t steps[6][2] = {{at(x + 1, y, z), at(x + 1, y + 1, z)}, {at(x + 1, y, z), at(x + 1, y, z + 1)},
                                         {at(x, y + 1, z), at(x + 1, y + 1, z)}, {at(x, y + 1, z), at(x, y + 1, z + 1)},
                                         {at(x, y, z + 1), at(x + 1, y, z + 1)}, {at(x, y, z + 1), at(x, y + 1, z + 1)}};
        for(const auto& st : steps) {
          std::array<std::size_t, 4> t = {at(x, y, z), st[0], st[1], at(x + 1, y + 1, z + 1)};
          std::array<std::array<double, 3>, 3> d;
          for(int i = 0; i < 3; ++i)
            for(int c = 0; c < 3; ++c) d[i][c] = block.points[t[i + 1]][c] - block.points[t[0]][c];
          const double det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                             d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
          if(det < 0) std::swap(t[1], t[2]);
          block.cells.push_back(t);
        }
      }
  return block;
}

// A random damaged subset of a block's cells for the manifold checks (trial 0: all of them): a
// random fraction kept (edges and vertices pinched where cells go missing), a cell repeated every
// fifth trial, a third cell on a facet of cell 3 every seventh.
inline std::vector<std::array<std::size_t, 4>> damaged_cells(const std::vector<std::array<std::size_t, 4>>& block, int trial,
                                                             std::mt19937& random)
{
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<std::array<std::size_t, 4>> cells;
  const double keep = trial == 0 ? 1. : 0.4 + 0.6 * uniform(random);
  for(const auto& c : block)
    if(uniform(random) < keep) cells.push_back(c);
  if(trial % 5 == 1) cells.push_back(cells[cells.size() / 2]);
  const std::size_t apex = cells.back()[3];   // a third cell on the facet if cell 3 has a neighbour there
  if(trial % 7 == 2 && std::find(cells[3].begin(), cells[3].end(), apex) == cells[3].end())
    cells.push_back({cells[3][0], cells[3][1], cells[3][2], apex});
  return cells;
}

#endif // DISTORTION_OPTIMIZATION_TEST_KUHN_BLOCK_H
