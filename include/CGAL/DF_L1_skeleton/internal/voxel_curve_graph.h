// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_CURVE_GRAPH_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_CURVE_GRAPH_H

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>

#include <CGAL/Iterator_range.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// First Betti number (number of independent loops) of a set of voxels in (26,6) digital
// topology, which is the topology of the union of the closed voxel cubes:
// b1 = b0 + b2 - chi, with chi = vertices - edges + faces - cubes of that union.
// `cavities` is b2, the number of bounded background components.
template <class Geometry>
long first_betti_number(const Geometry& grid, const std::vector<std::size_t>& voxels, long components,
                        long cavities)
{
  // Cells of the cubical complex on the doubled lattice: a cell is a point with
  // coordinates 2i + {0,1,2}; its dimension is the number of odd coordinates.
  std::unordered_set<std::uint64_t> cells[4];
  const std::uint64_t nx = 2 * std::uint64_t(grid.dims[0]) + 1, ny = 2 * std::uint64_t(grid.dims[1]) + 1;
  for(std::size_t v : voxels)
  {
    const std::array<int, 3> c = grid.coordinates(v);
    for(int dz = 0; dz < 3; ++dz)
      for(int dy = 0; dy < 3; ++dy)
        for(int dx = 0; dx < 3; ++dx)
        {
          const std::uint64_t x = 2 * std::uint64_t(c[0]) + dx, y = 2 * std::uint64_t(c[1]) + dy,
                              z = 2 * std::uint64_t(c[2]) + dz;
          cells[(dx == 1) + (dy == 1) + (dz == 1)].insert((z * ny + y) * nx + x);
        }
  }
  const long chi = long(cells[0].size()) - long(cells[1].size()) + long(cells[2].size()) - long(cells[3].size());
  return components + cavities - chi;
}

// Graph of the 26-adjacent voxels (sorted linear indices; vertex d is voxels[d]), without the diagonal edges that a shorter two-edge
// path already spans (they would make triangles at every staircase step).
template <class Traits, class Geometry>
Skeleton_graph<Traits> adjacency_graph(const Geometry& grid, const std::vector<std::size_t>& voxels)
{
  Skeleton_graph<Traits> g;
  for(std::size_t v : voxels)
    g[boost::add_vertex(g)].point = grid.center(v);
  const auto vertex_of = [&](int i, int j, int k) {
    if(!grid.contains(i, j, k))
      return voxels.size();
    const std::size_t v = grid.index(i, j, k);
    const auto it = std::lower_bound(voxels.begin(), voxels.end(), v);
    return it != voxels.end() && *it == v ? std::size_t(it - voxels.begin()) : voxels.size();
  };
  for(std::size_t d = 0; d < voxels.size(); ++d)
  {
    const std::array<int, 3> c = grid.coordinates(voxels[d]);
    for(int cell = 14; cell < 27; ++cell) // half of the neighbourhood: each edge once
    {
      const int dx = cell % 3 - 1, dy = (cell / 3) % 3 - 1, dz = cell / 9 - 1;
      const std::size_t n = vertex_of(c[0] + dx, c[1] + dy, c[2] + dz);
      if(n == voxels.size())
        continue;
      const int norm = dx * dx + dy * dy + dz * dz;
      bool spanned = false;
      for(int other = 0; other < 27 && !spanned && norm > 1; ++other)
      {
        const int ex = other % 3 - 1, ey = (other / 3) % 3 - 1, ez = other / 9 - 1;
        const int fx = dx - ex, fy = dy - ey, fz = dz - ez; // from w to the neighbour
        if(other == 13 || std::abs(fx) > 1 || std::abs(fy) > 1 || std::abs(fz) > 1)
          continue;
        spanned = ex * ex + ey * ey + ez * ez < norm && fx * fx + fy * fy + fz * fz < norm &&
                  vertex_of(c[0] + ex, c[1] + ey, c[2] + ez) != voxels.size();
      }
      if(!spanned)
        boost::add_edge(d, n, g);
    }
  }
  return g;
}

// Length, in edges, of the shortest path from s to t that does not use the edge (s,t);
// max_hops + 1 when there is none within max_hops.
template <class Graph>
int detour_length(const Graph& g, std::size_t s, std::size_t t, int max_hops)
{
  std::vector<std::pair<std::size_t, int>> queue(1, std::make_pair(s, 0));
  std::unordered_set<std::size_t> seen{s};
  for(std::size_t head = 0; head < queue.size(); ++head)
  {
    const std::size_t u = queue[head].first;
    const int hops = queue[head].second;
    if(hops == max_hops)
      break;
    for(auto w : CGAL::make_range(boost::adjacent_vertices(u, g)))
    {
      if(u == s && w == t)
        continue;
      if(w == t)
        return hops + 1;
      if(seen.insert(w).second)
        queue.emplace_back(w, hops + 1);
    }
  }
  return max_hops + 1;
}

// The curve graph of a thin voxel set whose background has `cavities` bounded
// components: the adjacency graph, with the edges of its shortest cycles removed until
// it has as many independent cycles as the voxel set has loops. Voxel clusters at
// junctions make small graph cycles that enclose no background; they go first, the
// loops of the shape are long and stay.
template <class Traits, class Geometry>
Skeleton_graph<Traits> voxel_curve_graph(const Geometry& grid, const std::vector<std::size_t>& voxels, long cavities = 0)
{
  Skeleton_graph<Traits> g = adjacency_graph<Traits>(grid, voxels);
  long components = 0;
  if(boost::num_vertices(g) > 0)
  {
    std::vector<int> component(boost::num_vertices(g));
    components = long(boost::connected_components(g, component.data()));
  }
  const long cycles = long(boost::num_edges(g)) + components - long(boost::num_vertices(g));
  const long loops = (std::max)(0L, first_betti_number(grid, voxels, components, cavities));
  const int max_hops = 16;
  for(long extra = cycles - loops; extra > 0; --extra)
  {
    // The edge with the shortest detour (ties: the longest edge, then the first).
    std::size_t best_s = 0, best_t = 0;
    int best = max_hops + 1, best_norm = 0;
    for(const auto& e : CGAL::make_range(boost::edges(g)))
    {
      const std::size_t s = boost::source(e, g), t = boost::target(e, g);
      if(boost::degree(s, g) < 2 || boost::degree(t, g) < 2)
        continue;
      const int hops = detour_length(g, s, t, (std::min)(best, max_hops));
      const std::array<int, 3> a = grid.coordinates(voxels[s]), b = grid.coordinates(voxels[t]);
      const int norm = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
      const std::pair<std::size_t, std::size_t> key((std::min)(s, t), (std::max)(s, t));
      if(hops < best || (hops == best && hops <= max_hops &&
                         (norm > best_norm || (norm == best_norm && key < std::make_pair(best_s, best_t)))))
      {
        best = hops;
        best_norm = norm;
        best_s = key.first;
        best_t = key.second;
      }
    }
    if(best > max_hops)
      break; // only long cycles are left: keep them
    boost::remove_edge(best_s, best_t, g);
  }
  return g;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_CURVE_GRAPH_H
