// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_SKELETON_STATISTICS_H
#define CGAL_DF_L1_SKELETON_SKELETON_STATISTICS_H

/// \file skeleton_statistics.h
/// Topological counts of a skeleton graph (what the report and the tests look at).

#include <CGAL/Iterator_range.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Counts describing the topology of a skeleton graph.
struct Skeleton_statistics
{
  std::size_t vertices = 0;   ///< number of vertices
  std::size_t edges = 0;      ///< number of edges
  std::size_t components = 0; ///< connected components
  std::size_t cycles = 0;     ///< independent cycles (first Betti number: E - V + C)
  std::size_t end_points = 0; ///< vertices of degree 1
  std::size_t junctions = 0;  ///< vertices of degree 3 or more
  double length = 0;          ///< total length of the edges
};

/// \ingroup PkgDFL1SkeletonRef
/// Computes the `Skeleton_statistics` of a graph whose vertices have a `point` member.
/// \tparam Graph a `boost::adjacency_list` with `vecS` vertices, such as `Skeleton_graph`
template <class Graph>
Skeleton_statistics skeleton_statistics(const Graph& g)
{
  Skeleton_statistics s;
  s.vertices = boost::num_vertices(g);
  s.edges = boost::num_edges(g);
  if(s.vertices > 0)
  {
    std::vector<int> component(s.vertices);
    s.components = std::size_t(boost::connected_components(g, component.data()));
  }
  s.cycles = s.edges + s.components - s.vertices;
  for(std::size_t v = 0; v < s.vertices; ++v)
  {
    const std::size_t d = boost::degree(v, g);
    s.end_points += (d == 1);
    s.junctions += (d >= 3);
  }
  for(const auto& e : CGAL::make_range(boost::edges(g)))
    s.length += std::sqrt(CGAL::to_double(
      CGAL::squared_distance(g[boost::source(e, g)].point, g[boost::target(e, g)].point)));
  return s;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_SKELETON_STATISTICS_H
