// Copyright (c) 2026 The Distortion_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H
#define CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H

#include <CGAL/license/Distortion_optimization.h>

#include <CGAL/Distortion_optimization/errors.h>
#include <CGAL/Distortion_optimization/parameters.h>
#include <CGAL/Distortion_optimization/internal/boundary_guard.h>
#include <CGAL/Distortion_optimization/internal/parallel.h>
#include <CGAL/Distortion_optimization/internal/simplicial_map.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <unordered_map>
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

// Positively oriented tetrahedra sharing a facet must lie on its two sides; two on the same side
// overlap (a folded mesh, or one whose cells' orientations disagree). Replacing the vertex of t
// off the facet by that of its neighbour t' gives t' in another order, which must be an odd
// permutation of it (negative): a parity count, exact without any predicate.
inline void check_cells_do_not_fold(const std::vector<std::array<std::size_t, 4>>& cells,
                                    const std::vector<std::uint32_t>& across, const Workers& workers = Workers())
{
  constexpr std::size_t block = 8192;
  std::vector<First_failure> failures((cells.size() + block - 1) / block);
  workers.for_each_block(cells.size(), block, [&](std::size_t begin, std::size_t size) {
    for(std::size_t t = begin; t < begin + size; ++t)
      for(int j = 0; j < 4; ++j) {
        const std::uint32_t other = across[4 * t + j];
        if(other == no_tetrahedron || other / 4 < t) continue;
        std::array<std::size_t, 4> swapped = cells[t];
        swapped[j] = cells[other / 4][other % 4];
        int position[4], inversions = 0;
        for(int i = 0; i < 4; ++i)
          position[i] = int(std::find(cells[other / 4].begin(), cells[other / 4].end(), swapped[i]) - cells[other / 4].begin());
        for(int a = 0; a < 4; ++a)
          for(int b = a + 1; b < 4; ++b) inversions += position[a] > position[b];
        if(inversions % 2 == 0) {
          failures[begin / block] = {t, "tetrahedra " + std::to_string(t) + " and " + std::to_string(other / 4) +
                                            " lie on the same side of their common facet: they overlap (a folded mesh)"};
          return;
        }
      }
  });
  First_failure::throw_lowest(failures);
}

// Builds `tr` from positively oriented tetrahedra and their adjacency (check_manifold_tetrahedra()),
// the way CGAL's build_triangulation() does (tet_soup_to_c3t3.h), but from the adjacency already
// found rather than from a hash map of facets, which took most of its time.
// Each boundary facet gets an infinite cell, and those meet across the boundary's edges. A point
// in no tetrahedron gets no vertex: its handle is Vertex_handle(). With threads it runs beside the
// edge and vertex checks, on input they may still refuse (an edge or vertex pinched): it must then
// at most throw or build a triangulation that is thrown away, never assume a manifold.
template <class Tr>
std::vector<typename Tr::Vertex_handle> build_triangulation(Tr& tr, const std::vector<typename Tr::Point>& points,
                                                            const std::vector<std::array<std::size_t, 4>>& cells,
                                                            const std::vector<std::uint32_t>& across, int label)
{
  using Vertex_handle = typename Tr::Vertex_handle;
  using Cell_handle = typename Tr::Cell_handle;
  auto& tds = tr.tds();
  tds.clear();   // not tr.clear(), which would create an infinite vertex of a 0-dimensional triangulation
  tds.set_dimension(3);   // before any adjacency: set_adjacency() asserts that the facet index is within it
  const Vertex_handle infinite = tds.create_vertex();
  infinite->set_dimension(-1);
  tr.set_infinite_vertex(infinite);
  std::vector<Vertex_handle> handles(points.size());
  for(const auto& cell : cells)
    for(std::size_t v : cell)
      if(handles[v] == Vertex_handle()) {
        handles[v] = tds.create_vertex();
        handles[v]->set_point(points[v]);
        handles[v]->set_dimension(3);
      }
  std::vector<Cell_handle> finite(cells.size());
  for(std::size_t t = 0; t < cells.size(); ++t) {
    const auto& k = cells[t];
    finite[t] = tds.create_cell(handles[k[0]], handles[k[1]], handles[k[2]], handles[k[3]]);
    finite[t]->set_subdomain_index(label);
    for(std::size_t v : k)
      if(handles[v]->cell() == Cell_handle()) handles[v]->set_cell(finite[t]);
  }
  // Each facet between two tetrahedra, set once from its lower one; a boundary facet gets an
  // infinite cell, oriented as CGAL's, whose facets through the infinite vertex are keyed by
  // their boundary edge (smaller point index in the high bits).
  std::vector<std::pair<std::uint64_t, std::pair<Cell_handle, int>>> edges;
  for(std::size_t t = 0; t < cells.size(); ++t)
    for(int j = 0; j < 4; ++j) {
      const std::uint32_t other = across[4 * t + j];
      if(other != no_tetrahedron) {
        if(other / 4 > t) tds.set_adjacency(finite[t], j, finite[other / 4], other % 4);
        continue;
      }
      const auto& k = cells[t];
      const std::array<std::size_t, 3> f = (j == 0 || j == 2) ? std::array<std::size_t, 3>{k[(j + 2) % 4], k[(j + 1) % 4], k[(j + 3) % 4]}
                                                              : std::array<std::size_t, 3>{k[(j + 3) % 4], k[(j + 1) % 4], k[(j + 2) % 4]};
      const Cell_handle c = tds.create_cell(infinite, handles[f[0]], handles[f[1]], handles[f[2]]);
      tds.set_adjacency(c, 0, finite[t], j);
      for(int m = 1; m < 4; ++m) {
        const std::size_t a = f[m % 3], b = f[(m + 1) % 3];
        edges.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), {c, m}});
      }
    }
  // Tetrahedra in space have a boundary; without one (the five of a 4-simplex's boundary, say)
  // they overlap and there is no infinite cell to give the infinite vertex.
  if(edges.empty()) throw Invalid_input("every facet is shared by two tetrahedra: the complex has no boundary, so its cells overlap");
  infinite->set_cell(edges.front().second.first);
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for(std::size_t e = 0; e < edges.size(); e += 2) {
    if(e + 1 == edges.size() || edges[e + 1].first != edges[e].first || (e + 2 < edges.size() && edges[e + 2].first == edges[e].first))
      throw Invalid_input("the boundary of the tetrahedra is not a surface at the edge (" + std::to_string(edges[e].first >> 32) +
                          ", " + std::to_string(edges[e].first & 0xffffffffu) + ")");
    tds.set_adjacency(edges[e].second.first, edges[e].second.second, edges[e + 1].second.first, edges[e + 1].second.second);
  }
  return handles;
}

} // namespace internal

namespace internal_np {
enum subdomain_index_t { subdomain_index };
} // namespace internal_np

namespace parameters {
/// `int`: the subdomain (> 0) of the tetrahedra that `c3t3_from_tetrahedra()` puts in the complex; default 1.
CGAL_DISTORTION_OPTIMIZATION_ADD_NAMED_PARAMETER(subdomain_index_t, subdomain_index)
} // namespace parameters

namespace internal {

// Positively oriented tetrahedra that form a manifold complex and do not fold may still overlap:
// separate parts one across or inside another, or a part whose boundary passes through itself.
// Such a map is not injective, which its boundary tells (Aigerman and Lipman 2013): the boundary
// guard's exact test, with the nesting of the parts.
inline void check_cells_do_not_overlap(const std::vector<std::array<double, 3>>& points,
                                       const std::vector<std::array<std::size_t, 4>>& cells)
{
  using Guard = Boundary_guard<3>;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra(cells.size());
  for(std::size_t t = 0; t < cells.size(); ++t)
    for(int i = 0; i < 4; ++i) tetrahedra[t][i] = static_cast<std::uint32_t>(cells[t][i]);
  std::vector<Vector<3>> x(points.size());
  for(std::size_t v = 0; v < points.size(); ++v) x[v] = Vector<3>(points[v][0], points[v][1], points[v][2]);
  bool nested = false;
  if(!Guard(Guard::boundary_faces(tetrahedra), x.size(), connected_pieces(tetrahedra, x.size())).is_injective(x, nullptr, 0, &nested))
    throw Invalid_input(nested ? "the tetrahedra overlap: a part of the mesh lies inside another (separate parts must be apart)"
                               : "the tetrahedra overlap: their boundary passes through itself (separate parts must be apart)");
}

} // namespace internal

/// \ingroup PkgDistortionOptimizationRef
/// Replaces the content of `c3t3` (a `CGAL::Mesh_complex_3_in_triangulation_3`) with the given
/// tetrahedra, all in one subdomain, vertex `i` at `points[i]`: the way to hand a mesh
/// from TetGen or a Medit file to `CGAL::minimize_distortion()`. Negatively oriented tetrahedra
/// are stored with two vertices swapped (a simplicial map does not depend on the vertex order).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{subdomain_index}
///     \cgalParamDescription{the subdomain of the tetrahedra (`Distortion_optimization::parameters::subdomain_index()`)}
///     \cgalParamType{`int`, positive}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads for the orientation, manifold and fold checks, beside which the
///                           complex is then built; `0` for all the hardware offers
///                           (`Distortion_optimization::parameters::number_of_threads()`)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`1`}
///     \cgalParamExtra{Used when the program links `CGAL::TBB_support`; the result and the messages
///                     are the same for any number.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the vertex handle of each point (`Vertex_handle()` for a point in no tetrahedron).
/// \throws Invalid_input for an index out of range, a non-finite point, a flat tetrahedron (exact
/// predicate, the message names it), a tetrahedron listed twice, or tetrahedra that do not form a
/// manifold complex: a facet in more than two, or two that meet only at an edge or a vertex (the
/// message names them), two on the same side of their common facet (a folded mesh: they
/// overlap; the message names them), a complex without boundary (its cells overlap), or parts
/// that overlap otherwise (one inside another, or a boundary that passes through itself: exact
/// tests); for a negative number of threads. `c3t3` is then unchanged.
template <class C3T3, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename C3T3::Triangulation::Vertex_handle>
c3t3_from_tetrahedra(C3T3& c3t3, const std::vector<std::array<double, 3>>& points,
                     const std::vector<std::array<std::size_t, 4>>& tetrahedra,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using Tr = typename C3T3::Triangulation;
  using Bare_point = typename Tr::Geom_traits::Point_3;
  const int label = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::subdomain_index), 1);
  if(points.empty() || tetrahedra.empty()) throw Invalid_input("no tetrahedron");
  if(label <= 0) throw Invalid_input("the subdomain label must be positive");
  const int threads = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 1);
  if(threads < 0) throw Invalid_input("the number of threads must be 0 (all) or positive");
  const internal::Workers workers(threads);
  std::vector<typename Tr::Point> tr_points;
  tr_points.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Invalid_input("point " + std::to_string(i) + " is not finite");
    tr_points.push_back(typename Tr::Point(Bare_point(p[0], p[1], p[2])));
  }
  std::vector<std::array<std::size_t, 4>> cells(tetrahedra);
  constexpr std::size_t block = 4096;
  std::vector<internal::First_failure> failures((cells.size() + block - 1) / block);
  workers.for_each_block(cells.size(), block, [&](std::size_t begin, std::size_t size) {
    for(std::size_t t = begin; t < begin + size; ++t) {
      auto& cell = cells[t];
      for(std::size_t v : cell)
        if(v >= points.size()) {
          failures[begin / block] = {t, "tetrahedron " + std::to_string(t) + " has a vertex index out of range"};
          return;
        }
      auto bare = [&](int j) { return Bare_point(points[cell[j]][0], points[cell[j]][1], points[cell[j]][2]); };
      const CGAL::Orientation o = CGAL::orientation(bare(0), bare(1), bare(2), bare(3));
      if(o == CGAL::COPLANAR) {
        failures[begin / block] = {t, "tetrahedron " + std::to_string(t) + " is flat (zero volume)"};
        return;
      }
      if(o == CGAL::NEGATIVE) std::swap(cell[2], cell[3]);
    }
  });
  internal::First_failure::throw_lowest(failures);
  // The fold check (on the workers) and the construction of the complex (sequential: CGAL's
  // containers) need only the adjacency: with threads they run beside the manifold checks' last
  // part, whose failures are still told first; the overlap shortens the call.
  std::vector<std::uint32_t> across;
  std::exception_ptr error;   // the fold check's, or else the construction's
  C3T3 built;
  std::vector<typename Tr::Vertex_handle> handles;
  internal::check_manifold_tetrahedra(cells, across, workers, [&] {
    try {
      internal::check_cells_do_not_fold(cells, across, workers);
      Tr tr;
      handles = internal::build_triangulation(tr, tr_points, cells, across, label);
      built.triangulation().swap(tr);
      built.rescan_after_load_of_triangulation();
    } catch(...) {
      error = std::current_exception();
    }
  });
  if(error) std::rethrow_exception(error);
  internal::check_cells_do_not_overlap(points, cells);
  // The complex's swap() exchanges the triangulations but not Mesh_3's cache of the facets around
  // each edge (face_status()): clear() drops that cache, which would otherwise still describe the
  // old complex, keyed by vertices that go with `built`.
  c3t3.clear();
  c3t3.swap(built);
  return handles;
}

/// \ingroup PkgDistortionOptimizationRef
/// The converse of `c3t3_from_tetrahedra()`: the cells of the complex of `c3t3` (in the order of
/// `cells_in_complex_begin()`, each with its cell's vertex order) as `points` and `tetrahedra`,
/// indices into `points`, which are numbered in the order the cells first reach their vertices.
/// What the writers take (`IO::write_MEDIT_soup()`, `IO::write_VTU()`); `points` and `tetrahedra`
/// are cleared first.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the point written for each vertex: a target map writes the image of
///                           the tetrahedra}
///     \cgalParamType{a readable property map from `Triangulation::Vertex_handle` to a point with
///                    `x()`, `y()`, `z()`}
///     \cgalParamDefault{the triangulation's points, without their weights}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the vertex handle of each point.
template <class C3T3, class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename C3T3::Triangulation::Vertex_handle>
tetrahedra_from_c3t3(const C3T3& c3t3, std::vector<std::array<double, 3>>& points,
                     std::vector<std::array<std::size_t, 4>>& tetrahedra,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using Vertex_handle = typename C3T3::Triangulation::Vertex_handle;
  const auto& tr = c3t3.triangulation();
  const auto bare = tr.geom_traits().construct_point_3_object();
  std::vector<Vertex_handle> handles;
  std::unordered_map<Vertex_handle, std::size_t> index;
  index.reserve(tr.number_of_vertices());
  points.clear();
  tetrahedra.clear();
  tetrahedra.reserve(c3t3.number_of_cells_in_complex());
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<std::size_t, 4> cell;
    for(int i = 0; i < 4; ++i) {
      const auto [at, added] = index.emplace(c->vertex(i), points.size());
      if(added) {
        handles.push_back(c->vertex(i));
        if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value) {
          const auto p = bare(tr.point(c, i));
          points.push_back({p.x(), p.y(), p.z()});
        } else {
          const auto& p = get(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point), c->vertex(i));
          points.push_back({double(p.x()), double(p.y()), double(p.z())});
        }
      }
      cell[i] = at->second;
    }
    tetrahedra.push_back(cell);
  }
  return handles;
}

} // namespace Distortion_optimization
} // namespace CGAL

#endif // CGAL_DISTORTION_OPTIMIZATION_C3T3_FROM_TETRAHEDRA_H
