// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_CURVE_GRAPH_EDITING_H
#define CGAL_DF_L1_SKELETON_INTERNAL_CURVE_GRAPH_EDITING_H

#include <CGAL/DF_L1_skeleton/internal/l1_median_iteration.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// A small editable curve graph (points and adjacency lists, vertices removed by flag) for
// finishing the skeleton; converted to the public boost graph at the end.
struct Curve_graph
{
  std::vector<Vec3> x;
  std::vector<std::vector<std::size_t>> adj;
  std::vector<char> alive;

  std::size_t add_vertex(const Vec3& p)
  {
    x.push_back(p);
    adj.emplace_back();
    alive.push_back(1);
    return x.size() - 1;
  }
  bool adjacent(std::size_t a, std::size_t b) const
  {
    return std::find(adj[a].begin(), adj[a].end(), b) != adj[a].end();
  }
  void add_edge(std::size_t a, std::size_t b)
  {
    if(a != b && !adjacent(a, b))
    {
      adj[a].push_back(b);
      adj[b].push_back(a);
    }
  }
  void remove_edge(std::size_t a, std::size_t b)
  {
    adj[a].erase(std::remove(adj[a].begin(), adj[a].end(), b), adj[a].end());
    adj[b].erase(std::remove(adj[b].begin(), adj[b].end(), a), adj[b].end());
  }
  void remove_vertex(std::size_t v)
  {
    for(std::size_t w : std::vector<std::size_t>(adj[v]))
      remove_edge(v, w);
    alive[v] = 0;
  }
  std::size_t degree(std::size_t v) const { return adj[v].size(); }
  double length(std::size_t a, std::size_t b) const { return distance(x[a], x[b]); }

  // The chain from end point `tip` to the first vertex of degree other than 2 (its
  // junction, or the other end of an isolated curve): its vertices from the tip, not the
  // junction, and its length.
  struct Terminal_chain
  {
    std::vector<std::size_t> chain;
    std::size_t junction;
    double length;
  };
  Terminal_chain terminal_chain(std::size_t tip) const
  {
    Terminal_chain t{{tip}, tip, 0.0};
    std::size_t prev = tip, v = adj[tip][0];
    while(adj[v].size() == 2)
    {
      t.chain.push_back(v);
      t.length += length(prev, v);
      const std::size_t next = adj[v][0] == prev ? adj[v][1] : adj[v][0];
      prev = v;
      v = next;
    }
    t.length += length(prev, v);
    t.junction = v;
    return t;
  }

  // Removes the terminal chains (from an end point to the first vertex of degree 3 or
  // more) shorter than `too_short(junction, tip)`, repeatedly, never removing a whole
  // component.
  template <class Threshold>
  void prune_spurs(const Threshold& too_short)
  {
    for(bool changed = true; changed;)
    {
      changed = false;
      for(std::size_t e = 0; e < x.size(); ++e)
      {
        if(!alive[e] || adj[e].size() != 1)
          continue;
        const Terminal_chain t = terminal_chain(e);
        if(adj[t.junction].size() < 3 || t.length >= too_short(t.junction, e))
          continue;
        for(std::size_t c : t.chain)
          remove_vertex(c);
        changed = true;
      }
    }
  }

  // Of two terminal chains that leave the same junction and whose end points lie within
  // `twins(tip_a, tip_b)` of each other, removes the shorter (repeatedly): the two
  // halves of one limb that the thinning parted around a pocket of its interior.
  template <class Threshold>
  void merge_twin_ends(const Threshold& twins)
  {
    for(bool changed = true; changed;)
    {
      changed = false;
      std::vector<Terminal_chain> terminals;
      for(std::size_t e = 0; e < x.size(); ++e)
        if(alive[e] && adj[e].size() == 1)
        {
          Terminal_chain t = terminal_chain(e);
          if(adj[t.junction].size() >= 3)
            terminals.push_back(std::move(t));
        }
      for(std::size_t i = 0; i < terminals.size() && !changed; ++i)
        for(std::size_t j = i + 1; j < terminals.size() && !changed; ++j)
        {
          const Terminal_chain& a = terminals[i];
          const Terminal_chain& b = terminals[j];
          const std::size_t tip_a = a.chain.front(), tip_b = b.chain.front();
          if(a.junction != b.junction || length(tip_a, tip_b) >= twins(tip_a, tip_b))
            continue;
          const Terminal_chain& shorter = a.length < b.length || (a.length == b.length && tip_a > tip_b) ? a : b;
          for(std::size_t c : shorter.chain)
            remove_vertex(c);
          changed = true;
        }
    }
  }

  // Passes of Laplacian smoothing of the vertices of degree 2 (ends and junctions stay,
  // so that branches keep their length and meet where they met); a move is made only
  // when `accept(from, to)` agrees.
  template <class Accept>
  void smooth(int passes, const Accept& accept)
  {
    for(int p = 0; p < passes; ++p)
    {
      const std::vector<Vec3> old = x;
      for(std::size_t v = 0; v < x.size(); ++v)
        if(alive[v] && adj[v].size() == 2)
        {
          const Vec3 target = 0.5 * old[v] + 0.25 * (old[adj[v][0]] + old[adj[v][1]]);
          if(accept(old[v], target))
            x[v] = target;
        }
    }
  }

  // The chains between vertices of degree other than 2 (and the closed loops without such
  // a vertex), as vertex sequences.
  std::vector<std::vector<std::size_t>> chains() const
  {
    std::vector<std::vector<std::size_t>> out;
    std::vector<char> done_edge_at(x.size(), 0);
    std::vector<char> visited(x.size(), 0);
    const auto walk = [&](std::size_t start, std::size_t first) {
      std::vector<std::size_t> chain{start};
      std::size_t prev = start, v = first;
      for(;;)
      {
        chain.push_back(v);
        if(adj[v].size() != 2 || v == start)
          break;
        visited[v] = 1;
        const std::size_t next = adj[v][0] == prev ? adj[v][1] : adj[v][0];
        prev = v;
        v = next;
      }
      return chain;
    };
    for(std::size_t s = 0; s < x.size(); ++s)
    {
      if(!alive[s] || adj[s].size() == 2)
        continue;
      for(std::size_t w : adj[s])
      {
        // each chain is found from both ends: keep it from its lower end, or from the
        // lower first step when both ends are the same vertex
        std::vector<std::size_t> chain = walk(s, w);
        const std::size_t t = chain.back();
        if(t < s || (t == s && chain[chain.size() - 2] < w))
          continue;
        out.push_back(std::move(chain));
      }
    }
    for(std::size_t s = 0; s < x.size(); ++s) // loops made of degree-2 vertices only
    {
      if(!alive[s] || adj[s].size() != 2 || visited[s])
        continue;
      visited[s] = 1;
      out.push_back(walk(s, adj[s][0]));
    }
    return out;
  }

  // A copy with every chain replaced by points spaced about `step` apart along it (at
  // least one segment per chain, two for a closed loop, three for a loop on itself).
  // An interpolated point for which `inside` is false (a chord across a thin bend) is
  // replaced by the nearer end of its segment.
  template <class Inside>
  Curve_graph resampled(double step, const Inside& inside) const
  {
    Curve_graph out;
    std::vector<std::size_t> kept(x.size(), npos);
    const auto vertex = [&](std::size_t v) {
      if(kept[v] == npos)
        kept[v] = out.add_vertex(x[v]);
      return kept[v];
    };
    for(std::size_t v = 0; v < x.size(); ++v)
      if(alive[v] && adj[v].empty())
        vertex(v);
    for(const std::vector<std::size_t>& chain : chains())
    {
      std::vector<double> at{0};
      for(std::size_t i = 1; i < chain.size(); ++i)
        at.push_back(at.back() + length(chain[i - 1], chain[i]));
      const bool loop = chain.front() == chain.back();
      const int pieces = (std::max)(loop ? 3 : 1, int(std::lround(at.back() / step)));
      std::size_t prev = vertex(chain.front());
      std::size_t seg = 1;
      for(int k = 1; k < pieces; ++k)
      {
        const double s = at.back() * k / pieces;
        while(seg + 1 < at.size() && at[seg] < s)
          ++seg;
        const double t = at[seg] > at[seg - 1] ? (s - at[seg - 1]) / (at[seg] - at[seg - 1]) : 0;
        const Vec3& a = x[chain[seg - 1]];
        const Vec3& b = x[chain[seg]];
        const Vec3 p = a + t * (b - a);
        const std::size_t v = out.add_vertex(inside(p) ? p : (t < 0.5 ? a : b));
        out.add_edge(prev, v);
        prev = v;
      }
      out.add_edge(prev, vertex(chain.back()));
    }
    return out;
  }

  static constexpr std::size_t npos = std::size_t(-1);
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_CURVE_GRAPH_EDITING_H
