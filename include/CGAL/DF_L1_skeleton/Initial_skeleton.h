// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INITIAL_SKELETON_H
#define CGAL_DF_L1_SKELETON_INITIAL_SKELETON_H

/// \file Initial_skeleton.h
/// The result of `extract_initial_skeleton()`: the skeleton voxels and a curve graph
/// through them.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The initial skeleton: the skeleton voxels and a thin graph through them.
/// \tparam Traits a model of `Kernel`
template <class Traits>
struct Initial_skeleton
{
  /// S: the centres of all skeleton voxels (the attractors of the refinement)
  std::vector<typename Traits::Point_3> points;
  /// the linear grid index of each point of `points`
  std::vector<std::size_t> voxels;
  /// a curve graph through a subset of the skeleton voxels: 26-connected, one voxel
  /// thick, with the spurs shorter than the local radius pruned
  Skeleton_graph<Traits> graph;
  /// TP1, TP2, TP3 of Eq. 2, in voxel units
  std::array<double, 3> thinning_parameters = {{0, 0, 0}};
};

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INITIAL_SKELETON_H
