// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_DEEPEST_PATH_H
#define CGAL_DF_L1_SKELETON_INTERNAL_DEEPEST_PATH_H

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Adds a vertex of a path through the occupied voxels at the centre of voxel v; its
// radius is the distance field there, or the depth in the occupied voxels less the half
// voxel to the surface when that is larger. `depth` as for `Deepest_path_search`.
template <class Traits>
typename boost::graph_traits<Skeleton_graph<Traits>>::vertex_descriptor
add_path_vertex(Skeleton_graph<Traits>& g, const Distance_field<Traits>& field, const std::vector<float>& depth,
                std::size_t v)
{
  const auto w = boost::add_vertex(g);
  g[w].point = field.center(v);
  g[w].radius = (std::max)(CGAL::to_double(field.distance(v)), (double(depth[v]) - 0.5) * CGAL::to_double(field.voxel_size));
  return w;
}

// Paths through a set of voxels that keep deepest: a step costs its length over the
// depth of the voxel it enters plus half a voxel. The work arrays are kept between
// searches, so that a search costs what it visits, not the size of the grid.
template <class Traits>
class Deepest_path_search
{
public:
  // `depth`: per voxel, the distance (voxels) to the nearest voxel that is not occupied
  Deepest_path_search(const Grid_geometry<Traits>& g, const std::vector<float>& depth)
    : grid_(&g), depth_(&depth), cost_(g.size(), infinity()), from_(g.size())
  {
  }

  // The cheapest path from one of `seeds` through the voxels where `passable` holds to the
  // first voxel reached where `is_target` holds: its voxels from that target back to the
  // seed, both included; empty when no target is reached.
  template <class Passable, class Target>
  std::vector<std::size_t> find(const std::vector<std::size_t>& seeds, const Passable& passable,
                                const Target& is_target)
  {
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for(std::size_t s : seeds)
    {
      cost_[s] = 0;
      from_[s] = s;
      touched_.push_back(s);
      queue.push({0.0, s});
    }
    std::size_t reached = std::numeric_limits<std::size_t>::max();
    while(!queue.empty())
    {
      const Entry e = queue.top();
      queue.pop();
      if(e.first > cost_[e.second])
        continue;
      if(is_target(e.second))
      {
        reached = e.second;
        break;
      }
      for_each_neighbour_26_step(*grid_, e.second, [&](std::size_t w, double step) {
        if(!passable(w))
          return;
        const double next = e.first + step / (double((*depth_)[w]) + 0.5);
        if(next < cost_[w])
        {
          if(cost_[w] == infinity())
            touched_.push_back(w);
          cost_[w] = next;
          from_[w] = e.second;
          queue.push({next, w});
        }
      });
    }
    std::vector<std::size_t> path;
    if(reached != std::numeric_limits<std::size_t>::max())
      for(std::size_t v = reached;; v = from_[v])
      {
        path.push_back(v);
        if(from_[v] == v)
          break;
      }
    for(std::size_t v : touched_)
      cost_[v] = infinity();
    touched_.clear();
    return path;
  }

private:
  static double infinity() { return std::numeric_limits<double>::infinity(); }

  const Grid_geometry<Traits>* grid_;
  const std::vector<float>* depth_;
  std::vector<double> cost_;
  std::vector<std::size_t> from_;
  std::vector<std::size_t> touched_;
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_DEEPEST_PATH_H
