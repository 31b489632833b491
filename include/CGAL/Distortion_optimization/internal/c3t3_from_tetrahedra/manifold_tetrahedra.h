// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// c3t3_from_tetrahedra()'s first step: the tetrahedra form a manifold complex, and their adjacency.

#ifndef CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_MANIFOLD_TETRAHEDRA_H
#define CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_MANIFOLD_TETRAHEDRA_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Distortion_optimization {
namespace internal {

// The first failure of a check run in ranges of indices: the one at the lowest index, which a
// sequential pass would have found first, so that messages do not depend on the threads.
struct First_failure
{
  std::size_t index = std::numeric_limits<std::size_t>::max();
  std::string message;

  static void throw_lowest(const std::vector<First_failure>& failures)
  {
    const First_failure* first = nullptr;
    for(const First_failure& f : failures)
      if(f.index != std::numeric_limits<std::size_t>::max() && (first == nullptr || f.index < first->index)) first = &f;
    if(first != nullptr) throw Invalid_input(first->message);
  }
};

// The tetrahedra must form a manifold complex, and build_triangulation() would not name the cells
// of a facet shared by three of them, nor notice a tetrahedron listed twice, or two that meet only
// at an edge or a vertex (a complex whose boundary is not a surface). Around each edge and each
// vertex, the tetrahedra must be connected through facets containing it; the message names the cells.
//
// Everything is found vertex by vertex in the vertices' stars (flat arrays, no tree of keys: a
// map-based check is far slower on large meshes), in ranges of vertices shared among the threads. A
// facet or a tetrahedron is met at its smallest vertex, where the tetrahedra sharing it are paired:
// the pairings are the complex's adjacency, `across[4t + j]` = 4t' + j' for the facet opposite
// tetrahedra[t][j], which is the facet opposite tetrahedra[t'][j'], or `no_tetrahedron` on the
// boundary. Connectivity is then a walk on that adjacency: around an edge, each cell has two facets
// through it, so its cells form one path or cycle iff a walk from one reaches them all; around a
// vertex, a search through the three facets through it of each cell (faster than a union-find over
// every incidence). Failures are reported as a sequential pass finds them: the lowest vertex's,
// facets before edges before vertices.
//
// `alongside`, if given, runs once the adjacency is complete: with threads, beside the edge and
// vertex checks (sequential work that needs only the adjacency, such as building a triangulation,
// then overlaps them), so it may see an input that they refuse; without threads, only after they
// passed. It must not throw.
constexpr std::uint32_t no_tetrahedron = std::numeric_limits<std::uint32_t>::max();
inline void check_manifold_tetrahedra(const std::vector<std::array<std::size_t, 4>>& tetrahedra,
                                      std::vector<std::uint32_t>& across, const Workers& workers = Workers(),
                                      const std::function<void()>& alongside = nullptr)
{
  // 32-bit indices throughout: half the memory traffic of size_t, and a facet's two other
  // vertices or an edge's other vertex and its cell pack into one 64-bit sort key.
  using Index = std::uint32_t;
  const std::size_t count = tetrahedra.size();
  if(count >= std::numeric_limits<Index>::max() / 4) throw Invalid_input("too many tetrahedra");
  std::size_t vertices = 0;
  for(const auto& t : tetrahedra)
    for(std::size_t v : t) {
      if(v >= std::numeric_limits<Index>::max()) throw Invalid_input("too many vertices");
      vertices = std::max(vertices, v + 1);
    }
  std::vector<std::array<Index, 4>> sorted(count), cells(count);
  workers.for_each(count, 8192, [&](std::size_t t) {
    for(int i = 0; i < 4; ++i) cells[t][i] = static_cast<Index>(tetrahedra[t][i]);
    sorted[t] = cells[t];
    std::sort(sorted[t].begin(), sorted[t].end());
  });
  // The star of each vertex: the tetrahedra containing it, in increasing order.
  std::vector<Index> first(vertices + 1, 0), star(4 * count);
  for(const auto& k : sorted)
    for(Index v : k) ++first[v + 1];
  for(std::size_t v = 0; v < vertices; ++v) first[v + 1] += first[v];
  {
    std::vector<Index> next(first.begin(), first.end() - 1);
    for(std::size_t t = 0; t < count; ++t)
      for(Index v : sorted[t]) star[next[v]++] = static_cast<Index>(t);
  }
  const auto name = [](std::size_t i) { return std::to_string(i); };
  across.assign(4 * count, no_tetrahedron);
  // The position in cells[t] of its vertex off the facet (u, v, w).
  const auto opposite = [&](std::size_t t, std::size_t u, std::size_t v, std::size_t w) {
    int j = 0;
    while(cells[t][j] == u || cells[t][j] == v || cells[t][j] == w) ++j;
    return j;
  };
  // A few ranges per thread, for the balance; one without threads.
  const std::size_t ranges = std::min<std::size_t>(std::max<std::size_t>(vertices, 1), workers.threads() == 1 ? 1 : 2 * workers.threads());
  const auto range_begin = [&](std::size_t r) { return r * vertices / ranges; };

  // Tetrahedra listed twice, facets shared by three or more, and the pairings across facets. A
  // facet (u, v, w), u < v < w, is keyed by v w at u.
  std::vector<First_failure> failures(ranges);
  workers.for_each(ranges, 1, [&](std::size_t r) {
    struct Facet { std::uint64_t vw; Index t; };
    std::vector<Facet> facets;
    std::vector<Index> own;   // the star's tetrahedra whose smallest vertex is u
    for(std::size_t u = range_begin(r); u < range_begin(r + 1); ++u) {
      facets.clear();
      own.clear();
      for(Index k = first[u]; k < first[u + 1]; ++k) {
        const auto& s = sorted[star[k]];
        if(s[0] == u) own.push_back(star[k]);
        for(int i = 0; i < 4; ++i)   // the facets opposite s[i] whose smallest vertex is u
          if(s[i] != u && (s[0] == u || (i == 0 && s[1] == u))) {
            std::uint64_t vw = 0;
            for(int j = 0; j < 4; ++j)
              if(j != i && s[j] != u) vw = vw << 32 | s[j];
            facets.push_back({vw, star[k]});
          }
      }
      // (Sorts break ties by tetrahedron, as the stars list them: the stable order, without
      // stable_sort's buffer allocated at every vertex.)
      std::sort(own.begin(), own.end(), [&](Index a, Index b) { return std::tie(sorted[a], a) < std::tie(sorted[b], b); });
      for(std::size_t i = 1; i < own.size(); ++i)
        if(sorted[own[i - 1]] == sorted[own[i]]) {
          failures[r] = {u, "tetrahedra " + name(own[i - 1]) + " and " + name(own[i]) + " have the same vertices"};
          return;
        }
      std::sort(facets.begin(), facets.end(), [](const Facet& a, const Facet& b) { return std::tie(a.vw, a.t) < std::tie(b.vw, b.t); });
      for(std::size_t i = 0; i < facets.size(); ++i) {
        const Facet& f = facets[i];
        const std::size_t v = f.vw >> 32, w = f.vw & 0xffffffffu;
        std::size_t j = i + 1;
        while(j < facets.size() && facets[j].vw == f.vw) ++j;
        if(j - i > 2) {
          failures[r] = {u, "tetrahedra " + name(f.t) + ", " + name(facets[i + 1].t) + " and " + name(facets[i + 2].t) +
                            " share the facet (" + name(u) + ", " + name(v) + ", " + name(w) + "): the complex is not manifold there"};
          return;
        }
        if(j - i == 2) {
          const Index a = f.t, b = facets[i + 1].t;
          const Index facet_of_a = 4 * a + opposite(a, u, v, w), facet_of_b = 4 * b + opposite(b, u, v, w);
          across[facet_of_a] = facet_of_b;
          across[facet_of_b] = facet_of_a;
        }
        i = j - 1;
      }
    }
  });
  First_failure::throw_lowest(failures);

  // Around each edge (u, w), u < w, the cells in a path or cycle from the lowest, and around each
  // vertex, the star searched from its lowest cell; else the lowest cell and the first one not
  // reached. An edge's failure at any vertex comes before a vertex's.
  std::vector<First_failure> vertex_failures(ranges);
  failures.assign(ranges, First_failure());
  const auto check_range = [&](std::size_t r) {
    // A cell is reached when its mark is the current search's number (no clearing between searches).
    std::vector<Index> mark(count, 0);
    Index search = 0;
    // The walk, both ways from the lowest cell through its two facets containing the edge (those
    // opposite its two other vertices), ends on the boundary or where the other way closed the
    // cycle. Returns how many cells it reached.
    const auto walk_around = [&](Index lowest, Index u, Index w) {
      mark[lowest] = ++search;
      std::size_t reached = 1;
      int ends[2], m = 0;
      for(int j = 0; j < 4; ++j)
        if(cells[lowest][j] != u && cells[lowest][j] != w) ends[m++] = j;
      for(int exit : ends)
        for(Index t = lowest;;) {
          const Index next = across[4 * t + exit];
          if(next == no_tetrahedron || mark[next / 4] == search) break;
          t = next / 4;
          mark[t] = search;
          ++reached;
          exit = 0;   // out through the other facet containing the edge
          while(exit == int(next % 4) || cells[t][exit] == u || cells[t][exit] == w) ++exit;
        }
      return reached;
    };
    // Per other vertex w of u's star (stamped with u + 1, so never cleared): how many of its cells
    // contain the edge, and whether the edge has been walked around.
    std::vector<Index> stamp(vertices, 0), around(vertices, 0), queue;
    for(std::size_t u = range_begin(r); u < range_begin(r + 1); ++u) {
      const Index self = static_cast<Index>(u);
      for(Index k = first[u]; k < first[u + 1]; ++k)
        for(Index w : sorted[star[k]])
          if(w > self) {
            if(stamp[w] != self + 1) stamp[w] = self + 1, around[w] = 0;
            ++around[w];
          }
      // The star lists its cells in increasing order: an edge is first met at its lowest cell. Of
      // the edges not connected around, the message names the one with the smallest other vertex.
      Index broken = no_tetrahedron, broken_lowest = 0;
      for(Index k = first[u]; k < first[u + 1]; ++k)
        for(Index w : sorted[star[k]])
          if(w > self && stamp[w] == self + 1) {
            stamp[w] = 0;   // walked
            if(walk_around(star[k], self, w) < around[w] && w < broken) broken = w, broken_lowest = star[k];
          }
      if(broken != no_tetrahedron) {
        walk_around(broken_lowest, self, broken);
        for(Index k = first[u]; k < first[u + 1]; ++k) {
          const auto& s = sorted[star[k]];
          if(std::find(s.begin(), s.end(), broken) != s.end() && mark[star[k]] != search) {
            failures[r] = {u, "tetrahedra " + name(broken_lowest) + " and " + name(star[k]) + " meet only at the edge (" +
                                  name(u) + ", " + name(broken) + "): the complex is not manifold there"};
            return;
          }
        }
      }
      if(first[u] == first[u + 1] || !vertex_failures[r].message.empty()) continue;
      const Index lowest = star[first[u]];
      mark[lowest] = ++search;
      queue.assign(1, lowest);
      for(std::size_t q = 0; q < queue.size(); ++q)
        for(int j = 0; j < 4; ++j) {
          const Index t = queue[q], next = across[4 * t + j];
          if(cells[t][j] != u && next != no_tetrahedron && mark[next / 4] != search) {
            mark[next / 4] = search;
            queue.push_back(next / 4);
          }
        }
      if(queue.size() < first[u + 1] - first[u])
        for(Index k = first[u]; k < first[u + 1]; ++k)
          if(mark[star[k]] != search) {
            vertex_failures[r] = {u, "tetrahedra " + name(lowest) + " and " + name(star[k]) + " meet only at vertex " + name(u) +
                                         ": the complex is not manifold there"};
            break;
          }
    }
  };
  const bool beside = alongside && workers.threads() > 1;
  if(beside)
    workers.for_each(2, 1, [&](std::size_t k) { k == 0 ? workers.for_each(ranges, 1, check_range) : alongside(); });
  else
    workers.for_each(ranges, 1, check_range);
  First_failure::throw_lowest(failures);
  First_failure::throw_lowest(vertex_failures);
  if(alongside && !beside) alongside();
}

} // namespace internal
} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_INTERNAL_C3T3_FROM_TETRAHEDRA_MANIFOLD_TETRAHEDRA_H
