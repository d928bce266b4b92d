// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_SKELETON_GRAPH_H
#define CGAL_DF_L1_SKELETON_SKELETON_GRAPH_H

/// \file Skeleton_graph.h
/// The curve-skeleton graph type produced by the package (initial and final skeletons).

#include <boost/graph/adjacency_list.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The property bundle of a skeleton vertex.
/// \tparam Traits a model of `Kernel`
template <class Traits>
struct Skeleton_vertex
{
  /// position of the vertex
  typename Traits::Point_3 point;
  /// local radius of the shape around the vertex (distance-field value, input units; at
  /// least half a voxel in the final skeleton)
  typename Traits::FT radius = 0;
  /// indices, in the input point range, of the input points this vertex stands for
  std::vector<std::size_t> points;
};

/// \ingroup PkgDFL1SkeletonRef
/// The skeleton: an undirected `boost::adjacency_list` whose vertices carry a
/// `Skeleton_vertex`, like the `Skeleton` of `CGAL::Mean_curvature_flow_skeletonization`.
template <class Traits>
using Skeleton_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                             Skeleton_vertex<Traits>>;

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_SKELETON_GRAPH_H
