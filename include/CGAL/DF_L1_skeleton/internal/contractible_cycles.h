// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_CONTRACTIBLE_CYCLES_H
#define CGAL_DF_L1_SKELETON_INTERNAL_CONTRACTIBLE_CYCLES_H

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/Voxel_grid.h>

#include <CGAL/Iterator_range.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The voxel offsets within `radius` voxels (centre to centre), nearest first.
inline std::vector<std::array<int, 3>> offsets_within(double radius)
{
  std::vector<std::array<int, 3>> offsets;
  const int reach = int(std::floor(radius));
  for(int k = -reach; k <= reach; ++k)
    for(int j = -reach; j <= reach; ++j)
      for(int i = -reach; i <= reach; ++i)
        if(i * i + j * j + k * k <= radius * radius)
          offsets.push_back({{i, j, k}});
  auto norm2 = [](const std::array<int, 3>& x) { return x[0] * x[0] + x[1] * x[1] + x[2] * x[2]; };
  std::stable_sort(offsets.begin(), offsets.end(),
                   [&](const std::array<int, 3>& x, const std::array<int, 3>& y) { return norm2(x) < norm2(y); });
  return offsets;
}

// Whether the cone from the centroid of `cycle` over its edges (a disk that the cycle
// bounds), sampled every `step` voxels, lies in the solid (occupied and interior voxels)
// closed by the `closing` offsets (`offsets_within()` the closing radius): each sample
// that falls in an exterior or outlier voxel has a voxel of the solid at one of them. A
// local search costs less than a distance transform of the grid, which took a third of
// the initial skeleton's time on a torus at V = 100. False when a sample leaves the grid.
template <class Traits>
bool spans_closed_disk(const Grid_geometry<Traits>& grid, const std::vector<Voxel_label>& labels,
                       const std::vector<std::array<double, 3>>& cycle, double step,
                       const std::vector<std::array<int, 3>>& closing)
{
  std::array<double, 3> c{{0, 0, 0}};
  for(const auto& p : cycle)
    for(int d = 0; d < 3; ++d)
      c[d] += p[d] / double(cycle.size());
  const double size = CGAL::to_double(grid.voxel_size);
  const double o[3] = {CGAL::to_double(grid.origin.x()), CGAL::to_double(grid.origin.y()),
                       CGAL::to_double(grid.origin.z())};
  auto solid = [&](int i, int j, int k) {
    if(!grid.contains(i, j, k))
      return false;
    const Voxel_label l = labels[grid.index(i, j, k)];
    return l == Voxel_label::INTERIOR || l == Voxel_label::BOUNDARY;
  };
  auto closed = [&](const std::array<double, 3>& p) {
    int ijk[3];
    for(int d = 0; d < 3; ++d)
      ijk[d] = int(std::floor((p[d] - o[d]) / size));
    if(!grid.contains(ijk[0], ijk[1], ijk[2]))
      return false;
    for(const auto& off : closing)
      if(solid(ijk[0] + off[0], ijk[1] + off[1], ijk[2] + off[2]))
        return true;
    return false;
  };
  for(std::size_t e = 0; e < cycle.size(); ++e)
  {
    const std::array<double, 3>& a = cycle[e];
    const std::array<double, 3>& b = cycle[(e + 1) % cycle.size()];
    double far = 0;
    for(const auto* p : {&a, &b})
      far = (std::max)(far, std::sqrt((c[0] - (*p)[0]) * (c[0] - (*p)[0]) + (c[1] - (*p)[1]) * (c[1] - (*p)[1]) +
                                      (c[2] - (*p)[2]) * (c[2] - (*p)[2])));
    const int m = (std::max)(1, int(std::ceil(far / (step * size))));
    for(int i = 0; i <= m; ++i)
      for(int j = 0; i + j <= m; ++j)
      {
        const double s = double(i) / m, t = double(j) / m;
        std::array<double, 3> p;
        for(int d = 0; d < 3; ++d)
          p[d] = c[d] + s * (a[d] - c[d]) + t * (b[d] - c[d]);
        if(!closed(p))
          return false;
      }
  }
  return true;
}

// sqrt(3) voxels: one step of the 26-neighbourhood
constexpr double one_voxel_closing = 1.7321;

// Removes the cycles of `g` that bound a disk inside the solid of `labels` (occupied
// and interior voxels) closed by `closing_radius` voxels: the disk may cross exterior
// voxels, but none farther than that from the solid. Such a cycle goes around a plugged
// tunnel (a pit of a noisy surface that went through a plate, a hole between the samples
// of a sparse part) or a hole narrower than the grid resolves (one or two voxels between
// the twigs of a crown, the ends of a part that almost closes), not a hole of the shape.
// The default, sqrt(3), is one step of the 26-neighbourhood: the holes that a closing by
// one voxel fills. For each edge off a spanning tree, the shortest cycle through it is
// tested; a cycle through two junctions or more loses its arc of smallest mean radius
// (the thinner of two parallel paths), one with a single junction the edge opposite it.
// Returns the number of cuts.
template <class Traits>
std::size_t cut_contractible_cycles(Skeleton_graph<Traits>& g, const Grid_geometry<Traits>& grid,
                                    const std::vector<Voxel_label>& labels, double closing_radius = one_voxel_closing,
                                    std::size_t max_cuts = 1000)
{
  std::size_t cuts = 0;
  auto xyz = [&](std::size_t v) {
    return std::array<double, 3>{{CGAL::to_double(g[v].point.x()), CGAL::to_double(g[v].point.y()),
                                  CGAL::to_double(g[v].point.z())}};
  };
  auto length = [&](std::size_t a, std::size_t b) {
    const auto p = xyz(a), q = xyz(b);
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  };
  // Edges already tested and kept, as (min, max) vertex pairs; reset after a cut, whose
  // vertex removal renumbers the vertices.
  std::vector<std::pair<std::size_t, std::size_t>> kept;
  const std::vector<std::array<int, 3>> closing_offsets = offsets_within(closing_radius);
  while(cuts < max_cuts)
  {
    const std::size_t n = boost::num_vertices(g);
    // Spanning forest by breadth-first search; the other edges close the cycles.
    std::vector<std::size_t> parent(n, std::size_t(-1));
    std::vector<char> seen(n, 0);
    std::vector<std::pair<std::size_t, std::size_t>> closing;
    for(std::size_t root = 0; root < n; ++root)
    {
      if(seen[root])
        continue;
      seen[root] = 1;
      std::vector<std::size_t> queue(1, root);
      for(std::size_t head = 0; head < queue.size(); ++head)
      {
        const std::size_t v = queue[head];
        for(auto w : CGAL::make_range(boost::adjacent_vertices(v, g)))
        {
          if(!seen[w])
          {
            seen[w] = 1;
            parent[w] = v;
            queue.push_back(w);
          }
          else if(w != parent[v] && v < w)
            closing.emplace_back(v, w);
        }
      }
    }
    bool cut = false;
    for(const auto& e : closing)
    {
      if(std::find(kept.begin(), kept.end(), e) != kept.end())
        continue;
      // Shortest path from e.first to e.second without the edge e (Dijkstra).
      std::vector<double> dist(n, std::numeric_limits<double>::infinity());
      std::vector<std::size_t> from(n, std::size_t(-1));
      typedef std::pair<double, std::size_t> Item;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
      dist[e.first] = 0;
      queue.emplace(0.0, e.first);
      while(!queue.empty())
      {
        const Item top = queue.top();
        queue.pop();
        if(top.first > dist[top.second])
          continue;
        if(top.second == e.second)
          break;
        for(auto w : CGAL::make_range(boost::adjacent_vertices(top.second, g)))
        {
          if(top.second == e.first && w == e.second)
            continue;
          const double d = top.first + length(top.second, w);
          if(d < dist[w])
          {
            dist[w] = d;
            from[w] = top.second;
            queue.emplace(d, w);
          }
        }
      }
      if(from[e.second] == std::size_t(-1))
      {
        kept.push_back(e);
        continue;
      }
      std::vector<std::size_t> cycle;
      for(std::size_t v = e.second; v != std::size_t(-1); v = from[v])
        cycle.push_back(v);
      std::vector<std::array<double, 3>> points;
      for(std::size_t v : cycle)
        points.push_back(xyz(v));
      if(cycle.size() < 3 || !spans_closed_disk(grid, labels, points, 0.4, closing_offsets))
      {
        kept.push_back(e);
        continue;
      }
      // The arcs between the junctions of the cycle.
      std::vector<std::size_t> junctions;
      for(std::size_t i = 0; i < cycle.size(); ++i)
        if(boost::degree(cycle[i], g) >= 3)
          junctions.push_back(i);
      const std::size_t k = cycle.size();
      if(junctions.size() >= 2)
      {
        // Arc a runs from junction a to the next one, `steps` edges along the cycle.
        auto steps_of = [&](std::size_t a) {
          const std::size_t start = junctions[a], end = junctions[(a + 1) % junctions.size()];
          return (end + k - start) % k == 0 ? k : (end + k - start) % k;
        };
        double best = std::numeric_limits<double>::infinity();
        std::size_t best_arc = 0;
        for(std::size_t a = 0; a < junctions.size(); ++a)
        {
          const std::size_t steps = steps_of(a);
          double sum = 0;
          for(std::size_t s = 0; s <= steps; ++s)
            sum += CGAL::to_double(g[cycle[(junctions[a] + s) % k]].radius);
          if(sum / double(steps + 1) < best)
          {
            best = sum / double(steps + 1);
            best_arc = a;
          }
        }
        const std::size_t start = junctions[best_arc], steps = steps_of(best_arc);
        if(steps == 1)
          boost::remove_edge(cycle[start], cycle[(start + 1) % k], g);
        else
        {
          std::vector<std::size_t> doomed;
          for(std::size_t s = 1; s < steps; ++s)
            doomed.push_back(cycle[(start + s) % k]);
          std::sort(doomed.begin(), doomed.end());
          for(std::size_t i = doomed.size(); i-- > 0;)
          {
            boost::clear_vertex(doomed[i], g);
            boost::remove_vertex(doomed[i], g);
          }
        }
      }
      else
      {
        const std::size_t j = junctions.empty() ? 0 : junctions.front();
        boost::remove_edge(cycle[(j + k / 2) % k], cycle[(j + k / 2 + 1) % k], g);
      }
      ++cuts;
      kept.clear();
      cut = true;
      break;
    }
    if(!cut)
      break;
  }
  return cuts;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_CONTRACTIBLE_CYCLES_H
