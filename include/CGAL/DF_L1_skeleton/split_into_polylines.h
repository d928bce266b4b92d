// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_SPLIT_INTO_POLYLINES_H
#define CGAL_DF_L1_SKELETON_SPLIT_INTO_POLYLINES_H

/// \file split_into_polylines.h
/// Splitting a skeleton graph into polylines: the maximal chains of degree-2
/// vertices between junctions and end points.

#include <CGAL/boost/graph/split_graph_into_polylines.h>

#include <boost/graph/adjacency_list.hpp>
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

/// Collects the polylines that `CGAL::split_graph_into_polylines()` reports.
struct Polyline_collector
{
  std::vector<std::vector<std::size_t>> chains;
  void start_new_polyline() { chains.emplace_back(); }
  void add_node(std::size_t v) { chains.back().push_back(v); }
  void end_polyline() {}
};

/// Puts a chain in the canonical form that `split_into_polylines()` documents.
/// `real` is the number of vertices of the input graph; indices from `real` on
/// are the vertices added to subdivide self-loops and parallel edges.
inline std::vector<std::size_t> canonical_chain(std::vector<std::size_t> chain,
                                                std::size_t real,
                                                const std::vector<std::size_t>& degree)
{
  const bool closed = chain.size() > 1 && chain.front() == chain.back();
  if(closed)
    chain.pop_back();
  chain.erase(std::remove_if(chain.begin(), chain.end(),
                             [real](std::size_t v) { return v >= real; }),
              chain.end());
  if(!closed) {
    if(chain.back() < chain.front())
      std::reverse(chain.begin(), chain.end());
    return chain;
  }
  // A closed chain starts at its one vertex of degree other than 2 when it has
  // one (a loop leaving a junction), else at its smallest vertex, and goes on
  // towards the smaller of that vertex's two neighbours along the chain.
  auto start = std::find_if(chain.begin(), chain.end(),
                            [&](std::size_t v) { return degree[v] != 2; });
  if(start == chain.end())
    start = std::min_element(chain.begin(), chain.end());
  std::rotate(chain.begin(), start, chain.end());
  if(chain.size() > 2 && chain.back() < chain[1])
    std::reverse(chain.begin() + 1, chain.end());
  chain.push_back(chain.front());
  return chain;
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Splits a graph into polylines with `CGAL::split_graph_into_polylines()`, in a
/// canonical order that does not depend on how the graph stores its edges.
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
/// of the index of their second vertex. Unlike `CGAL::split_graph_into_polylines()`
/// alone, self-loops and parallel edges are kept: a self-loop counts 2 in the
/// degree of its vertex and is a closed polyline of its own.
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
  using Simple_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;

  // A simple graph on the vertex indices, with the same degrees: a self-loop
  // becomes a triangle through two added vertices and a parallel edge a path
  // through one, since split_graph_into_polylines() ignores both.
  const auto index = get(boost::vertex_index, g);
  const std::size_t n = num_vertices(g);
  std::vector<vertex_descriptor> by_index(n);
  for(auto v : boost::make_iterator_range(vertices(g)))
    by_index[static_cast<std::size_t>(get(index, v))] = v;

  std::vector<std::pair<std::size_t, std::size_t>> edge_list;
  for(auto e : boost::make_iterator_range(edges(g))) {
    const std::size_t s = static_cast<std::size_t>(get(index, source(e, g)));
    const std::size_t t = static_cast<std::size_t>(get(index, target(e, g)));
    edge_list.emplace_back(std::min(s, t), std::max(s, t));
  }
  std::sort(edge_list.begin(), edge_list.end());

  Simple_graph simple(n);
  std::vector<std::size_t> degree(n, 0);
  for(std::size_t i = 0; i < edge_list.size(); ++i) {
    const auto [s, t] = edge_list[i];
    ++degree[s];
    ++degree[t];
    if(s == t) {
      const auto a = boost::add_vertex(simple);
      const auto b = boost::add_vertex(simple);
      boost::add_edge(s, a, simple);
      boost::add_edge(a, b, simple);
      boost::add_edge(b, t, simple);
    } else if(i > 0 && edge_list[i - 1] == edge_list[i]) {
      const auto m = boost::add_vertex(simple);
      boost::add_edge(s, m, simple);
      boost::add_edge(m, t, simple);
    } else {
      boost::add_edge(s, t, simple);
    }
  }

  internal::Polyline_collector collector;
  CGAL::split_graph_into_polylines(simple, collector);

  std::vector<std::vector<std::size_t>> chains;
  chains.reserve(collector.chains.size());
  for(auto& c : collector.chains)
    chains.push_back(internal::canonical_chain(std::move(c), n, degree));
  std::sort(chains.begin(), chains.end());

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
