// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_ATTACH_FRAGMENTS_H
#define CGAL_DF_L1_SKELETON_INTERNAL_ATTACH_FRAGMENTS_H

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Attaches the fragments of a shape to it: a piece of the skeleton whose points span at
// most a third of the extent of another piece's points (the longest side of their
// bounding boxes), and come nearer to that piece's points than their own extent, is a
// part of the same object whose connection the scan missed (a branch behind an
// occlusion, a clump of leaves). It gets one edge, from its vertex that stands for the
// nearest of its points to the vertex that stands for the nearest point of the other
// piece. Separate objects of comparable sizes, and small objects far from the rest
// compared with their size, stay apart; the extents, unlike the numbers of points, do
// not depend on the sampling density. The smallest pieces go first, each to the nearest
// piece it qualifies for; a piece grows by those attached to it. Edges join pieces only,
// so no cycle is made. `xyz`: the points that the vertices' `points` index. Returns the
// number of edges added.
template <class Traits>
std::size_t attach_fragments(Skeleton_graph<Traits>& g, const std::vector<std::array<double, 3>>& xyz)
{
  typedef std::array<double, 3> A;
  const std::size_t n = boost::num_vertices(g);
  if(n < 2)
    return 0;
  std::vector<int> piece_of_vertex(n);
  const int pieces = boost::connected_components(g, piece_of_vertex.data());
  if(pieces < 2)
    return 0;
  const std::size_t P = static_cast<std::size_t>(pieces);
  constexpr int NONE = -1;
  std::vector<int> piece_of_point(xyz.size(), NONE);
  std::vector<std::size_t> vertex_of_point(xyz.size(), 0);
  std::vector<std::vector<std::size_t>> members(P);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<A> lo(P, A{{inf, inf, inf}}), hi(P, A{{-inf, -inf, -inf}});
  std::vector<A> assigned;
  std::vector<std::size_t> assigned_index;
  for(std::size_t v = 0; v < n; ++v)
    for(std::size_t i : g[v].points)
    {
      const std::size_t p = static_cast<std::size_t>(piece_of_vertex[v]);
      piece_of_point[i] = piece_of_vertex[v];
      vertex_of_point[i] = v;
      members[p].push_back(i);
      for(int a = 0; a < 3; ++a)
      {
        lo[p][a] = (std::min)(lo[p][a], xyz[i][a]);
        hi[p][a] = (std::max)(hi[p][a], xyz[i][a]);
      }
      assigned.push_back(xyz[i]);
      assigned_index.push_back(i);
    }
  if(assigned.empty())
    return 0;
  auto extent = [&](std::size_t p) {
    return members[p].empty() ? 0.0 : (std::max)({hi[p][0] - lo[p][0], hi[p][1] - lo[p][1], hi[p][2] - lo[p][2]});
  };
  std::vector<double> own_extent(P);
  for(std::size_t p = 0; p < P; ++p)
    own_extent[p] = extent(p);
  const Uniform_grid grid(assigned, 0.0);
  // the pieces as they merge (union-find), with their bounding boxes
  std::vector<int> parent(P);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int p) {
    while(parent[std::size_t(p)] != p)
      p = parent[std::size_t(p)] = parent[std::size_t(parent[std::size_t(p)])];
    return p;
  };
  std::vector<std::size_t> order(P);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return own_extent[a] < own_extent[b]; });
  std::size_t added = 0;
  std::vector<std::pair<double, std::size_t>> nearest;
  for(std::size_t p : order)
  {
    if(members[p].empty())
      continue;
    const std::size_t root = std::size_t(find(int(p)));
    const double small = extent(root);
    double largest = 0;
    for(std::size_t q = 0; q < P; ++q)
      if(find(int(q)) == int(q) && q != root)
        largest = (std::max)(largest, extent(q));
    if(largest < 3 * small)
      continue; // no piece large enough: no search through the whole cloud
    // the nearest point of a piece whose extent is at least 3 times that of p's piece
    double best = inf;
    std::size_t from = 0, to = 0;
    for(std::size_t i : members[p])
    {
      grid.k_nearest(xyz[i], 1, [&](std::size_t j) {
        const std::size_t q = std::size_t(find(piece_of_point[assigned_index[j]]));
        return q != root && extent(q) >= 3 * small;
      }, nearest);
      if(!nearest.empty() && nearest.front().first < best)
      {
        best = nearest.front().first;
        from = i;
        to = assigned_index[nearest.front().second];
      }
    }
    if(!(std::sqrt(best) <= own_extent[p]))
      continue;
    boost::add_edge(vertex_of_point[from], vertex_of_point[to], g);
    ++added;
    const std::size_t other = std::size_t(find(piece_of_point[to]));
    parent[root] = int(other);
    for(int a = 0; a < 3; ++a)
    {
      lo[other][a] = (std::min)(lo[other][a], lo[root][a]);
      hi[other][a] = (std::max)(hi[other][a], hi[root][a]);
    }
  }
  return added;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_ATTACH_FRAGMENTS_H
