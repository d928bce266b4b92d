// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_MISSING_BRANCHES_H
#define CGAL_DF_L1_SKELETON_INTERNAL_MISSING_BRANCHES_H

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/internal/deepest_path.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The default of add_missing_branches(): every branch is kept.
struct Accept_every_branch
{
  bool operator()(const std::vector<std::size_t>&, std::size_t) const { return true; }
};

// Adds the branches that thinning lost: the parts of the solid that reach farther from
// the curve graph than its balls explain. Thinning in the order of depth eats a limb
// from its tip when the depth there is flat (a twig two or three voxels wide is one
// plateau of quantized depth) and none of its voxels is ever a curve end; the voxels
// still show the limb.
//
// The excess of an occupied voxel u is the least, over the vertices s of the graph, of
// its geodesic distance to s through the occupied voxels less `per_radius` times the
// radius of s (the vertex radius, or its depth in the occupied voxels less half a
// voxel when that is larger: points inside a thick part lower the distance field, not
// the occupied depth). Inside the enlarged balls the excess is at most 0; at the tip of
// a limb that no curve enters it is about the length of the limb beyond the balls.
// While some voxel where `tips` is set has an excess of `reach` voxels or more, the one
// with the largest gets a branch: the path through the occupied voxels that keeps
// deepest (a step costs its length over the depth of the voxel plus half a voxel) from
// it to the graph, without its leading voxels less than `min_depth` deep (the surface
// layer at the tip). The excess is then lowered from the new vertices; a tip whose path
// is all surface layer adds nothing, and the excess is lowered from that path instead.
// `depth`: per voxel, the distance (voxels) to the nearest voxel that is not occupied.
// `accept(path, beyond)` may refuse a branch, told its path (voxels from the graph to the
// tip) and where the part beyond the enlarged balls (of positive excess) starts in it; a
// refused path lowers the excess as a path of surface layer does.
// Returns the number of branches added.
template <class Traits, class Accept = Accept_every_branch>
std::size_t add_missing_branches(Skeleton_graph<Traits>& g, const Distance_field<Traits>& field,
                                 const std::vector<float>& depth, const std::vector<char>& tips, double reach,
                                 double per_radius, double min_depth, const Accept& accept = Accept())
{
  typedef typename boost::graph_traits<Skeleton_graph<Traits>>::vertex_descriptor vertex;
  typedef std::pair<double, std::size_t> Entry;
  typedef std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> Min_queue;
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  const double infinity = std::numeric_limits<double>::infinity();
  if(boost::num_vertices(g) == 0)
    return 0;
  const double voxel = CGAL::to_double(field.voxel_size);
  auto occupied = [&](std::size_t v) { return Voxel_grid<Traits>::is_occupied(field.labels[v]); };

  // A multi-source Dijkstra whose sources (voxel, radius in voxels) start at minus
  // their enlarged radius, lowering the excess where it can.
  std::vector<double> excess(field.size(), infinity);
  auto spread = [&](const std::vector<std::pair<std::size_t, double>>& sources) {
    Min_queue queue;
    for(const std::pair<std::size_t, double>& s : sources)
      if(-per_radius * s.second < excess[s.first])
      {
        excess[s.first] = -per_radius * s.second;
        queue.push({excess[s.first], s.first});
      }
    while(!queue.empty())
    {
      const Entry e = queue.top();
      queue.pop();
      if(e.first > excess[e.second])
        continue;
      for_each_neighbour_26_step(field, e.second, [&](std::size_t w, double step) {
        const double next = e.first + step;
        if(occupied(w) && next < excess[w])
        {
          excess[w] = next;
          queue.push({next, w});
        }
      });
    }
  };

  std::vector<std::size_t> vertex_at(field.size(), none);
  std::vector<std::pair<std::size_t, double>> sources;
  for(vertex v = 0; v < boost::num_vertices(g); ++v)
  {
    const std::array<int, 3> c = field.locate(g[v].point);
    if(!field.contains(c[0], c[1], c[2]))
      continue;
    const std::size_t at = field.index(c[0], c[1], c[2]);
    vertex_at[at] = v;
    sources.push_back({at, (std::max)(CGAL::to_double(g[v].radius) / voxel, double(depth[at]) - 0.5)});
  }
  spread(sources);

  // the voxels beyond reach, largest excess first; an entry whose excess has dropped
  // since it was queued goes back with its new value
  std::priority_queue<Entry> candidates;
  for(std::size_t v = 0; v < field.size(); ++v)
    if(tips[v] && excess[v] >= reach && excess[v] < infinity)
      candidates.push({excess[v], v});

  std::size_t added = 0;
  Deepest_path_search<Traits> search(field, depth);
  while(!candidates.empty())
  {
    const Entry top = candidates.top();
    candidates.pop();
    const std::size_t tip = top.second;
    if(excess[tip] < reach)
      continue;
    if(excess[tip] < top.first)
    {
      candidates.push({excess[tip], tip});
      continue;
    }
    // the deepest path from the tip to the graph, from the graph to the tip
    std::vector<std::size_t> path = search.find(std::vector<std::size_t>(1, tip), occupied,
                                                [&](std::size_t v) { return vertex_at[v] != none; });
    std::vector<std::pair<std::size_t, double>> shallow(1, {tip, 0.0}), new_sources;
    while(path.size() > 1 && double(depth[path.back()]) < min_depth)
    {
      shallow.push_back({path.back(), 0.0});
      path.pop_back();
    }
    std::size_t beyond = path.size();
    while(beyond > 1 && excess[path[beyond - 1]] > 0)
      --beyond;
    if(path.size() > 1 && !accept(path, beyond))
    {
      for(std::size_t v : path)
        shallow.push_back({v, 0.0});
      path.resize(1);
    }
    if(path.size() > 1)
    {
      vertex previous = vertex_at[path.front()];
      for(std::size_t i = 1; i < path.size(); ++i)
      {
        const std::size_t v = path[i];
        const vertex w = add_path_vertex(g, field, depth, v);
        boost::add_edge(previous, w, g);
        previous = w;
        vertex_at[v] = w;
        new_sources.push_back({v, CGAL::to_double(g[w].radius) / voxel});
      }
      ++added;
    }
    spread(path.size() > 1 ? new_sources : shallow);
  }
  return added;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_MISSING_BRANCHES_H
