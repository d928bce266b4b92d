// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_SPLIT_INTO_POLYLINES_H
#define CGAL_DF_L1_SKELETON_SPLIT_INTO_POLYLINES_H

/// \file split_into_polylines.h
/// Splitting a skeleton graph into polylines: the maximal chains of degree-2
/// vertices between junctions and end points.

#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

/// The graph as compact adjacency lists of (neighbour index, edge id), so that
/// parallel edges and self-loops are told apart and each edge is used once.
/// A self-loop appears twice in the list of its vertex, as it counts 2 in the degree.
struct Polyline_adjacency
{
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> adj;
  std::size_t num_edges = 0;

  template <class Graph>
  explicit Polyline_adjacency(const Graph& g)
  {
    const auto index = get(boost::vertex_index, g);
    adj.resize(num_vertices(g));
    for(auto e : boost::make_iterator_range(edges(g))) {
      const std::size_t s = static_cast<std::size_t>(get(index, source(e, g)));
      const std::size_t t = static_cast<std::size_t>(get(index, target(e, g)));
      adj[s].emplace_back(t, num_edges);
      adj[t].emplace_back(s, num_edges);
      ++num_edges;
    }
    // Deterministic walks whatever the storage order of the edges.
    for(auto& a : adj)
      std::sort(a.begin(), a.end());
  }

  std::size_t degree(std::size_t v) const { return adj[v].size(); }
};

/// Walks from `start` along the unused edge in slot `slot` and goes on through
/// degree-2 vertices until it reaches a vertex of another degree or `start`
/// again. Marks the edges it uses; returns the vertex indices of the chain.
inline std::vector<std::size_t> walk_chain(const Polyline_adjacency& a,
                                           std::vector<bool>& used,
                                           std::size_t start, std::size_t slot)
{
  std::vector<std::size_t> chain{start};
  std::size_t cur = start;
  std::size_t next = a.adj[start][slot].first;
  std::size_t edge = a.adj[start][slot].second;
  for(;;) {
    used[edge] = true;
    chain.push_back(next);
    if(next == start || a.degree(next) != 2)
      break;
    cur = next;
    // The other edge of a degree-2 vertex; it is unused: had it been walked,
    // the walk would have gone on through `cur` along the edge we came by.
    const auto& nb = a.adj[cur];
    const std::size_t k = (nb[0].second == edge) ? 1 : 0;
    if(used[nb[k].second])
      break; // cannot happen on a consistent graph; guards against an endless loop
    next = nb[k].first;
    edge = nb[k].second;
  }
  return chain;
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Splits a graph into polylines.
///
/// Each polyline is a maximal chain of edges whose inner vertices have degree 2:
/// - a chain between two vertices of degree other than 2 (end points and
///   junctions) starts at its end with the smaller index;
/// - a chain leaving a junction and coming back to it is closed: its first
///   vertex is repeated at the end;
/// - a connected component whose vertices all have degree 2 (a pure cycle)
///   gives one closed polyline, starting (and ending) at its smallest vertex
///   and going on towards the smaller of its two neighbours;
/// - an isolated vertex gives a polyline with this vertex only.
///
/// Every edge is in exactly one polyline. Polylines are output ordered by the
/// index of their first vertex, and the chains leaving one vertex in the order
/// of the index of their second vertex. A self-loop counts 2 in the degree of
/// its vertex.
///
/// \tparam Graph a model of `VertexListGraph` and `EdgeListGraph` with an
///         internal `vertex_index` property map (such as `Skeleton_graph`)
/// \tparam OutputIterator an output iterator accepting
///         `std::vector<boost::graph_traits<Graph>::vertex_descriptor>`
/// \param g the graph
/// \param out receives the polylines
/// \returns the output iterator past the last polyline written
template <class Graph, class OutputIterator>
OutputIterator split_into_polylines(const Graph& g, OutputIterator out)
{
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;

  const internal::Polyline_adjacency a(g);
  const std::size_t n = a.adj.size();
  std::vector<bool> used(a.num_edges, false);
  std::vector<std::vector<std::size_t>> chains;

  // Chains from end points and junctions, then what is left: pure cycles.
  for(std::size_t v = 0; v < n; ++v) {
    if(a.degree(v) == 0) {
      chains.push_back({v});
    } else if(a.degree(v) != 2) {
      for(std::size_t k = 0; k < a.adj[v].size(); ++k)
        if(!used[a.adj[v][k].second])
          chains.push_back(internal::walk_chain(a, used, v, k));
    }
  }
  for(std::size_t v = 0; v < n; ++v) {
    if(a.degree(v) == 2 && !used[a.adj[v][0].second])
      chains.push_back(internal::walk_chain(a, used, v, 0));
  }

  // Within the first loop chains come out ordered by first vertex already; the
  // stable sort interleaves the cycles and keeps the order of ties.
  std::stable_sort(chains.begin(), chains.end(),
                   [](const auto& c1, const auto& c2) { return c1.front() < c2.front(); });

  // Map indices back to descriptors (they coincide for `vecS` vertex storage).
  std::vector<vertex_descriptor> by_index(n);
  const auto index = get(boost::vertex_index, g);
  for(auto v : boost::make_iterator_range(vertices(g)))
    by_index[static_cast<std::size_t>(get(index, v))] = v;

  for(const auto& c : chains) {
    std::vector<vertex_descriptor> polyline;
    polyline.reserve(c.size());
    for(std::size_t i : c)
      polyline.push_back(by_index[i]);
    *out++ = std::move(polyline);
  }
  return out;
}

/// \ingroup PkgDFL1SkeletonRef
/// The polylines of `split_into_polylines()` as sequences of vertex positions
/// `g[v].point`; closed polylines repeat their first point at the end.
///
/// \tparam Graph a graph as for `split_into_polylines()` whose vertex bundle has a
///         `point` member, such as `Skeleton_graph<Traits>`
/// \param g the graph
/// \returns one point sequence per polyline, in the order of `split_into_polylines()`
template <class Graph>
auto skeleton_polylines(const Graph& g)
    -> std::vector<std::vector<std::decay_t<decltype(
        g[*vertices(g).first].point)>>>
{
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;
  using Point = std::decay_t<decltype(g[*vertices(g).first].point)>;

  std::vector<std::vector<vertex_descriptor>> chains;
  split_into_polylines(g, std::back_inserter(chains));

  std::vector<std::vector<Point>> result;
  result.reserve(chains.size());
  for(const auto& c : chains) {
    std::vector<Point> pts;
    pts.reserve(c.size());
    for(vertex_descriptor v : c)
      pts.push_back(g[v].point);
    result.push_back(std::move(pts));
  }
  return result;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_SPLIT_INTO_POLYLINES_H
