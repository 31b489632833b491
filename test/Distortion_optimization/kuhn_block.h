// A block of k x k x k unit cubes, each cut into six tetrahedra about its diagonal (Kuhn's
// subdivision), all positively oriented: a small regular tetrahedral mesh for IO and tool tests.

#ifndef DISTORTION_OPTIMIZATION_TEST_KUHN_BLOCK_H
#define DISTORTION_OPTIMIZATION_TEST_KUHN_BLOCK_H

#include "../../examples/Distortion_optimization/cube_tetrahedra.h"

#include <CGAL/Distortion_optimization/IO/simplex_soup.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

inline CGAL::Distortion_optimization::IO::Tetrahedron_soup kuhn_block(int k)
{
  auto cut = volume_examples::cube_tetrahedra(k, [](int i) { return double(i); });
  CGAL::Distortion_optimization::IO::Tetrahedron_soup block;
  block.points = std::move(cut.points);
  block.cells = std::move(cut.cells);
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
