// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_BUILD_SKELETON_GRAPH_H
#define CGAL_DF_L1_SKELETON_BUILD_SKELETON_GRAPH_H

/// \file build_skeleton_graph.h
/// Stage 6: the skeleton graph from the branches of the contraction.

#include <CGAL/DF_L1_skeleton/Contracted_samples.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/distance_field.h>
#include <CGAL/DF_L1_skeleton/extract_initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/internal/curve_graph_editing.h>
#include <CGAL/DF_L1_skeleton/internal/l1_median_iteration.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Reconciles the traced branches with the topology of the initial skeleton, which the
// voxel thinning gets right (one component per part of the shape, one loop per handle):
// the branches of a part are joined into one component, extra loops are opened, missing
// ones closed, and ends stopped short of the initial skeleton's ends are extended to them.
// Every edge added stays inside the shape.
template <class Traits>
class Topology_guide
{
public:
  Topology_guide(Curve_graph& g, const Skeleton_graph<Traits>& initial, const Field_lookup<Traits>& field)
    : g_(g), field_(field)
  {
    const std::size_t n = boost::num_vertices(initial);
    s_.resize(n);
    for(std::size_t v = 0; v < n; ++v)
    {
      s_[v] = to_vec3(initial[v].point);
      s_adj_.emplace_back();
      for(auto e : CGAL::make_range(boost::out_edges(v, initial)))
        s_adj_[v].push_back(boost::target(e, initial));
    }
    part_of_s_.resize(n);
    parts_ = n == 0 ? 0 : std::size_t(boost::connected_components(initial, part_of_s_.data()));
    part_cycles_.assign(parts_, 0);
    std::vector<long> twice_edges(parts_, 0), vertices(parts_, 0);
    for(std::size_t v = 0; v < n; ++v)
    {
      twice_edges[part_of_s_[v]] += long(s_adj_[v].size());
      ++vertices[part_of_s_[v]];
    }
    for(std::size_t p = 0; p < parts_; ++p)
      part_cycles_[p] = twice_edges[p] / 2 - vertices[p] + 1;
  }

  void run()
  {
    if(parts_ == 0)
      return;
    join_components();
    fix_cycles();
    extend_ends();
  }

  // whether an end of the initial skeleton lies within a local radius (and two voxels) of p
  bool supports_end(const Vec3& p) const
  {
    const double r = local_radius(p) + 2 * field_.voxel_size();
    for(std::size_t v = 0; v < s_.size(); ++v)
      if(s_adj_[v].size() == 1 && distance(s_[v], p) < r)
        return true;
    return false;
  }

private:
  double local_radius(const Vec3& p) const { return (std::max)(field_.distance(p), field_.voxel_size()); }

  std::size_t nearest_s(const Vec3& p) const
  {
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for(std::size_t v = 0; v < s_.size(); ++v)
    {
      const double d = distance(p, s_[v]);
      if(d < best_d)
      {
        best = v;
        best_d = d;
      }
    }
    return best;
  }

  // the part of the shape of each component of g: majority of the nearest initial
  // skeleton vertices
  std::vector<std::size_t> parts_of_components(const std::vector<std::size_t>& label, std::size_t count) const
  {
    std::vector<std::map<std::size_t, std::size_t>> votes(count);
    for(std::size_t v = 0; v < g_.x.size(); ++v)
      if(g_.alive[v])
        ++votes[label[v]][part_of_s_[nearest_s(g_.x[v])]];
    std::vector<std::size_t> part(count, 0);
    for(std::size_t c = 0; c < count; ++c)
    {
      std::size_t best = 0;
      for(const auto& kv : votes[c])
        if(kv.second > best)
        {
          best = kv.second;
          part[c] = kv.first;
        }
    }
    return part;
  }

  // Adds the vertices and edges of the initial skeleton's path between s vertices a and b
  // (breadth-first), joined to the graph vertices u and w at its ends.
  void add_initial_path(std::size_t u, std::size_t a, std::size_t w, std::size_t b)
  {
    std::vector<std::size_t> from(s_.size(), Curve_graph::npos);
    std::vector<std::size_t> queue{a};
    from[a] = a;
    for(std::size_t head = 0; head < queue.size() && from[b] == Curve_graph::npos; ++head)
      for(std::size_t c : s_adj_[queue[head]])
        if(from[c] == Curve_graph::npos)
        {
          from[c] = queue[head];
          queue.push_back(c);
        }
    if(from[b] == Curve_graph::npos)
      return;
    std::size_t prev = w;
    for(std::size_t c = b;; c = from[c])
    {
      const std::size_t v = g_.add_vertex(s_[c]);
      g_.add_edge(prev, v);
      prev = v;
      if(c == a)
        break;
    }
    g_.add_edge(prev, u);
  }

  // One component per part: parts without branches take their initial skeleton; the
  // other components of a part are joined to the largest by the shortest inside segment
  // (from an end point when there is one), or else along the initial skeleton.
  void join_components()
  {
    for(;;)
    {
      std::vector<std::size_t> label;
      const std::size_t count = g_.components(label);
      const std::vector<std::size_t> part = parts_of_components(label, count);
      std::vector<std::size_t> size(count, 0);
      for(std::size_t v = 0; v < g_.x.size(); ++v)
        if(g_.alive[v])
          ++size[label[v]];
      std::vector<std::size_t> main_of_part(parts_, Curve_graph::npos);
      for(std::size_t c = 0; c < count; ++c)
        if(main_of_part[part[c]] == Curve_graph::npos || size[c] > size[main_of_part[part[c]]])
          main_of_part[part[c]] = c;
      bool changed = false;
      for(std::size_t p = 0; p < parts_; ++p)
        if(main_of_part[p] == Curve_graph::npos)
        {
          copy_part(p);
          changed = true;
        }
      if(changed)
        continue;
      // the smallest component that is not the main one of its part
      std::size_t lone = Curve_graph::npos;
      for(std::size_t c = 0; c < count; ++c)
        if(c != main_of_part[part[c]] && (lone == Curve_graph::npos || size[c] < size[lone]))
          lone = c;
      if(lone == Curve_graph::npos)
        return;
      connect(lone, main_of_part[part[lone]], label);
    }
  }

  void copy_part(std::size_t p)
  {
    std::vector<std::size_t> id(s_.size(), Curve_graph::npos);
    for(std::size_t v = 0; v < s_.size(); ++v)
      if(part_of_s_[v] == p)
        id[v] = g_.add_vertex(s_[v]);
    for(std::size_t v = 0; v < s_.size(); ++v)
      for(std::size_t w : s_adj_[v])
        if(id[v] != Curve_graph::npos && v < w)
          g_.add_edge(id[v], id[w]);
  }

  void connect(std::size_t from, std::size_t to, const std::vector<std::size_t>& label)
  {
    struct Pair { double score; std::size_t u, w; };
    std::vector<Pair> pairs;
    for(std::size_t u = 0; u < g_.x.size(); ++u)
    {
      if(!g_.alive[u] || label[u] != from)
        continue;
      for(std::size_t w = 0; w < g_.x.size(); ++w)
        if(g_.alive[w] && label[w] == to)
        {
          // prefer leaving from an end point: a branch end is where a bridge was missing
          const double bonus = g_.degree(u) <= 1 ? 0.5 : 1.0;
          pairs.push_back({bonus * distance(g_.x[u], g_.x[w]), u, w});
        }
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
      return a.score < b.score || (a.score == b.score && (a.u < b.u || (a.u == b.u && a.w < b.w)));
    });
    const std::size_t tries = (std::min)(pairs.size(), std::size_t(64));
    for(std::size_t t = 0; t < tries; ++t)
      if(field_.segment_inside(g_.x[pairs[t].u], g_.x[pairs[t].w]))
      {
        g_.add_edge(pairs[t].u, pairs[t].w);
        return;
      }
    const Pair& best = pairs.front();
    add_initial_path(best.u, nearest_s(g_.x[best.u]), best.w, nearest_s(g_.x[best.w]));
    std::vector<std::size_t> relabel;
    g_.components(relabel);
    if(relabel[best.u] != relabel[best.w]) // no path in the initial skeleton either
      g_.add_edge(best.u, best.w);
  }

  // Extra loops (where branches and bridges doubled up) are opened by removing the least
  // central chain of the shortest loop: the chain between two vertices of degree 3 or
  // more with the smallest mean distance value, so that no dangling piece is left. Missing
  // loops are closed between the closest pair of end points that an inside segment joins.
  void fix_cycles()
  {
    std::vector<std::size_t> label;
    const std::size_t count = g_.components(label);
    const std::vector<std::size_t> part = parts_of_components(label, count);
    std::vector<long> cycles = g_.cycles_per_component(label, count);
    for(std::size_t c = 0; c < count; ++c)
    {
      while(cycles[c] > part_cycles_[part[c]])
      {
        const std::vector<std::size_t> loop = g_.shortest_cycle(label, c);
        if(loop.empty())
          break;
        remove_least_central_chain(loop);
        --cycles[c];
      }
      while(cycles[c] < part_cycles_[part[c]] && close_loop(c, label))
        ++cycles[c];
    }
  }

  void remove_least_central_chain(const std::vector<std::size_t>& loop)
  {
    const std::size_t n = loop.size();
    std::size_t start = 0; // a vertex of degree >= 3 on the loop, if any
    for(std::size_t i = 0; i < n; ++i)
      if(g_.degree(loop[i]) >= 3)
      {
        start = i;
        break;
      }
    std::vector<std::size_t> best_chain;
    double best_depth = std::numeric_limits<double>::infinity();
    std::vector<std::size_t> chain{loop[start]};
    for(std::size_t k = 1; k <= n; ++k)
    {
      const std::size_t v = loop[(start + k) % n];
      chain.push_back(v);
      if(g_.degree(v) >= 3 || k == n)
      {
        double depth = 0;
        for(std::size_t a = 0; a + 1 < chain.size(); ++a)
          depth += field_.distance(0.5 * (g_.x[chain[a]] + g_.x[chain[a + 1]]));
        depth /= double(chain.size() - 1);
        if(depth < best_depth)
        {
          best_depth = depth;
          best_chain = chain;
        }
        chain.assign(1, v);
      }
    }
    if(best_chain.size() == 2)
      g_.remove_edge(best_chain[0], best_chain[1]);
    else
      for(std::size_t a = 1; a + 1 < best_chain.size(); ++a)
        g_.remove_vertex(best_chain[a]);
  }

  bool close_loop(std::size_t c, const std::vector<std::size_t>& label)
  {
    std::size_t a = Curve_graph::npos, b = 0;
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t u = 0; u < g_.x.size(); ++u)
    {
      if(!g_.alive[u] || label[u] != c || g_.degree(u) != 1)
        continue;
      for(std::size_t w = u + 1; w < g_.x.size(); ++w)
      {
        if(!g_.alive[w] || label[w] != c || g_.degree(w) != 1)
          continue;
        const double d = distance(g_.x[u], g_.x[w]);
        if(d < best && d < 4 * (std::max)(local_radius(g_.x[u]), local_radius(g_.x[w])) &&
           field_.segment_inside(g_.x[u], g_.x[w]))
        {
          best = d;
          a = u;
          b = w;
        }
      }
    }
    if(a != Curve_graph::npos)
    {
      g_.add_edge(a, b);
      return true;
    }
    // No short inside segment: the closest pair of ends, along the initial skeleton.
    for(std::size_t u = 0; u < g_.x.size(); ++u)
      if(g_.alive[u] && label[u] == c && g_.degree(u) == 1)
        for(std::size_t w = u + 1; w < g_.x.size(); ++w)
          if(g_.alive[w] && label[w] == c && g_.degree(w) == 1 && distance(g_.x[u], g_.x[w]) < best)
          {
            best = distance(g_.x[u], g_.x[w]);
            a = u;
            b = w;
          }
    if(a == Curve_graph::npos)
      return false;
    const std::size_t before = g_.x.size();
    add_initial_path(a, nearest_s(g_.x[a]), b, nearest_s(g_.x[b]));
    return g_.x.size() > before;
  }

  // Contraction can stop a branch short of its end: the samples of a rounded cap pile up
  // a radius inside, and a thin arm's samples may bunch up before they are traced. The
  // thinning does not stop short. From each end, the initial skeleton is followed from
  // its nearest vertex (within two local radii) onwards, away from the branch, through
  // vertices of degree 2; when that walk reaches an end of the initial skeleton ahead of
  // the branch end, the branch is extended along it.
  void extend_ends()
  {
    const std::size_t n = g_.x.size();
    for(std::size_t e = 0; e < n; ++e)
    {
      if(!g_.alive[e] || g_.degree(e) != 1)
        continue;
      const Vec3 d = normalized(g_.x[e] - g_.x[g_.adj[e][0]]);
      const std::size_t a = nearest_s(g_.x[e]);
      if(distance(s_[a], g_.x[e]) > 2 * local_radius(g_.x[e]) + field_.voxel_size())
        continue;
      std::vector<std::size_t> path{a};
      std::size_t prev = Curve_graph::npos, v = a;
      if(s_adj_[a].size() == 2)
      {
        // step away from the branch
        const std::size_t n0 = s_adj_[a][0], n1 = s_adj_[a][1];
        prev = dot(s_[n0] - s_[a], d) >= dot(s_[n1] - s_[a], d) ? n1 : n0;
      }
      else if(s_adj_[a].size() != 1)
        continue; // at a junction of the initial skeleton: nothing to follow
      while(s_adj_[v].size() == 2 || (v == a && s_adj_[v].size() == 1 && prev == Curve_graph::npos))
      {
        const std::size_t next = s_adj_[v][0] == prev ? (s_adj_[v].size() > 1 ? s_adj_[v][1] : Curve_graph::npos) : s_adj_[v][0];
        if(next == Curve_graph::npos)
          break;
        prev = v;
        v = next;
        path.push_back(v);
        if(path.size() > s_.size())
          break;
      }
      if(s_adj_[v].size() != 1 || dot(s_[v] - g_.x[e], d) <= field_.voxel_size())
        continue;
      // keep the part of the walk ahead of the branch end
      std::size_t first = 0;
      while(first + 1 < path.size() && dot(s_[path[first]] - g_.x[e], d) <= 0)
        ++first;
      if(!field_.segment_inside(g_.x[e], s_[path[first]]))
        continue;
      std::size_t last = e;
      for(std::size_t i = first; i < path.size(); ++i)
      {
        const std::size_t w = g_.add_vertex(s_[path[i]]);
        g_.add_edge(last, w);
        last = w;
      }
    }
  }

  Curve_graph& g_;
  const Field_lookup<Traits>& field_;
  std::vector<Vec3> s_;
  std::vector<std::vector<std::size_t>> s_adj_;
  std::vector<std::size_t> part_of_s_;
  std::size_t parts_ = 0;
  std::vector<long> part_cycles_;
};

// Junction vertices joined by a chain shorter than the larger local radius of the two are
// one junction seen twice (bridges met the junction at two nearby points): the chain is
// contracted into a single vertex at its middle.
template <class Traits>
void merge_close_junctions(Curve_graph& g, const Field_lookup<Traits>& field)
{
  for(bool changed = true; changed;)
  {
    changed = false;
    for(const std::vector<std::size_t>& chain : g.chains())
    {
      const std::size_t a = chain.front(), b = chain.back();
      if(a == b || g.degree(a) < 3 || g.degree(b) < 3)
        continue;
      double len = 0;
      for(std::size_t i = 1; i < chain.size(); ++i)
        len += g.length(chain[i - 1], chain[i]);
      if(len >= (std::max)({field.distance(g.x[a]), field.distance(g.x[b]), field.voxel_size()}))
        continue;
      const Vec3 middle = 0.5 * (g.x[a] + g.x[b]);
      const std::vector<std::size_t> b_neighbours = g.adj[b];
      for(std::size_t i = 1; i < chain.size(); ++i)
        g.remove_vertex(chain[i]);
      for(std::size_t w : b_neighbours)
        if(g.alive[w])
          g.add_edge(a, w);
      g.x[a] = middle;
      changed = true;
      break;
    }
  }
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Builds the skeleton graph from the contracted samples: the branch and bridge edges,
/// finished so that the skeleton is usable as it is.
///
/// With the distance-field guidance (the method of `samples`):
/// - the branches of each connected part of the shape are joined into one component,
///   by the shortest segment that stays inside the shape or else along the initial
///   skeleton; a part where no branch formed (a ball, a short thick part) takes its
///   initial skeleton;
/// - the graph gets as many independent loops per part as the initial skeleton (the
///   shape's handles): extra small loops where branches doubled up are opened at their
///   longest edge, missing ones closed between facing ends by inside segments;
/// - ends that stopped short of the initial skeleton's ends are extended to them;
/// - terminal branches shorter than the local radius at their junction (hair) are removed.
///
/// For both methods: free samples left when the contraction stopped are dropped (the
/// input points near them are assigned to the nearest skeleton vertex instead); the
/// curves are smoothed (3 passes) and resampled every 2 voxels; each vertex gets the
/// distance value at its position as its radius. The `points` lists stay empty: fill them
/// with `assign_points_to_skeleton()`.
///
/// \param samples the result of `contract_samples()`
/// \param field the distance field the samples were contracted in
/// \param initial the initial skeleton (used by the guided method only)
template <class Traits>
Skeleton_graph<Traits> build_skeleton_graph(const Contracted_samples<Traits>& samples,
                                            const Distance_field<Traits>& field,
                                            const Initial_skeleton<Traits>& initial)
{
  using namespace internal;
  const Field_lookup<Traits> lookup(field);
  const double voxel = lookup.voxel_size();
  Curve_graph g;
  std::vector<std::size_t> id(samples.points.size(), Curve_graph::npos);
  for(const auto& e : samples.edges)
    for(std::size_t v : {e.first, e.second})
      if(id[v] == Curve_graph::npos)
        id[v] = g.add_vertex(to_vec3(samples.points[v]));
  for(const auto& e : samples.edges)
    g.add_edge(id[e.first], id[e.second]);

  if(samples.method == Skeletonization_method::DISTANCE_FIELD_GUIDED)
  {
    Topology_guide<Traits> guide(g, initial.graph, lookup);
    guide.run();
    // Hair: a terminal branch shorter than the local radius at its junction, or shorter
    // than three of them when no end of the initial skeleton supports its tip.
    g.prune_spurs([&](std::size_t junction, std::size_t tip) {
      const double r = (std::max)(lookup.distance(g.x[junction]), 2 * voxel);
      return guide.supports_end(g.x[tip]) ? r : 3 * r;
    });
    merge_close_junctions(g, lookup);
  }
  g.smooth(3);
  const Curve_graph r = g.resampled(2 * voxel);

  Skeleton_graph<Traits> skeleton;
  for(std::size_t v = 0; v < r.x.size(); ++v)
  {
    const auto u = boost::add_vertex(skeleton);
    skeleton[u].point = typename Traits::Point_3(r.x[v][0], r.x[v][1], r.x[v][2]);
    skeleton[u].radius = typename Traits::FT(lookup.distance(r.x[v]));
  }
  for(std::size_t v = 0; v < r.x.size(); ++v)
    for(std::size_t w : r.adj[v])
      if(v < w)
        boost::add_edge(v, w, skeleton);
  return skeleton;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_BUILD_SKELETON_GRAPH_H
