// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_JOIN_PIECES_H
#define CGAL_DF_L1_SKELETON_INTERNAL_JOIN_PIECES_H

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/internal/deepest_path.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Joins the pieces of a curve graph that lie in one 26-connected component of the
// occupied voxels: the skeleton of a connected solid is connected. A thin plate or a
// limb whose smoothed shell leaves no voxel deep enough on a stretch is thinned to
// pieces; they are joined by the path through the occupied voxels that keeps deepest
// (a step costs its length over the depth of the voxel it enters plus half a voxel),
// from the piece with the lowest vertex index to the nearest other piece, until one
// piece is left. `depth`: per voxel, the distance (voxels) to the nearest voxel that is
// not occupied. Returns the number of joins.
template <class Traits>
std::size_t join_pieces_within_shape(Skeleton_graph<Traits>& g, const Distance_field<Traits>& field,
                                     const std::vector<float>& depth)
{
  typedef typename boost::graph_traits<Skeleton_graph<Traits>>::vertex_descriptor vertex;
  const std::size_t n = boost::num_vertices(g);
  if(n < 2)
    return 0;
  std::vector<int> piece(n);
  const int pieces = boost::connected_components(g, piece.data());
  if(pieces < 2)
    return 0;
  // the voxel of each vertex, and the vertex of each voxel (the path vertices added by
  // the joins belong to the piece they join to, so later paths end on them)
  std::vector<std::size_t> voxel_of(n);
  std::vector<std::size_t> vertex_at(field.size(), std::numeric_limits<std::size_t>::max());
  for(vertex v = 0; v < n; ++v)
  {
    const std::array<int, 3> c = field.locate(g[v].point);
    voxel_of[v] = field.index(c[0], c[1], c[2]);
    vertex_at[voxel_of[v]] = v;
  }
  int components = 0;
  const std::vector<int> shape_component = label_26_components(
    field, [&](std::size_t v) { return Voxel_grid<Traits>::is_occupied(field.labels[v]); }, components);
  // pieces grouped by the shape component of their first vertex
  std::vector<std::vector<int>> pieces_in(static_cast<std::size_t>(components));
  std::vector<char> listed(std::size_t(pieces), 0);
  for(vertex v = 0; v < n; ++v)
  {
    if(listed[std::size_t(piece[v])])
      continue;
    listed[std::size_t(piece[v])] = 1;
    const int c = shape_component[voxel_of[v]];
    if(c >= 0)
      pieces_in[std::size_t(c)].push_back(piece[v]);
  }
  // union-find over the pieces, as joins merge them
  std::vector<int> parent(static_cast<std::size_t>(pieces));
  for(int p = 0; p < pieces; ++p)
    parent[std::size_t(p)] = p;
  auto root = [&](int p) {
    while(parent[std::size_t(p)] != p)
      p = parent[std::size_t(p)] = parent[std::size_t(parent[std::size_t(p)])];
    return p;
  };
  std::size_t joins = 0;
  Deepest_path_search<Traits> search(field, depth);
  for(std::size_t c = 0; c < std::size_t(components); ++c)
  {
    const std::vector<int>& here = pieces_in[c];
    for(std::size_t join = 1; join < here.size(); ++join)
    {
      const int grown = root(here.front());
      std::vector<std::size_t> seeds;
      for(vertex v = 0; v < boost::num_vertices(g); ++v)
        if(root(piece[v]) == grown)
          seeds.push_back(voxel_of[v]);
      const std::vector<std::size_t> path = search.find(
        seeds, [&](std::size_t w) { return shape_component[w] == int(c); },
        [&](std::size_t w) {
          return vertex_at[w] != std::numeric_limits<std::size_t>::max() && root(piece[vertex_at[w]]) != grown;
        });
      if(path.empty())
        break; // cannot happen within one component; stay safe
      // the path, from the reached piece back to the grown one, as new vertices
      const int other = root(piece[vertex_at[path.front()]]);
      vertex previous = vertex_at[path.front()];
      for(std::size_t i = 1; i < path.size(); ++i)
      {
        const std::size_t v = path[i];
        vertex here_vertex = vertex_at[v];
        if(here_vertex == std::numeric_limits<std::size_t>::max())
        {
          here_vertex = add_path_vertex(g, field, depth, v);
          piece.push_back(grown);
          voxel_of.push_back(v);
          vertex_at[v] = here_vertex;
        }
        boost::add_edge(previous, here_vertex, g);
        previous = here_vertex;
      }
      parent[std::size_t(other)] = grown;
      ++joins;
    }
  }
  return joins;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_JOIN_PIECES_H
