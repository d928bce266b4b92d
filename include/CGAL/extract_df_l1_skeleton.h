// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_EXTRACT_DF_L1_SKELETON_H
#define CGAL_EXTRACT_DF_L1_SKELETON_H

/// \file extract_df_l1_skeleton.h
/// The one-call free function: `DF_L1_skeletonization` run to the end.

#include <CGAL/DF_L1_skeletonization.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

namespace CGAL {

/// \ingroup PkgDFL1SkeletonRef
/// Computes the curve skeleton of a point cloud with the distance-field guided
/// L1-median method in one call: `DF_L1_skeletonization` run to the end.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`; the result does not depend on the threads
/// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
/// \tparam Skeleton `CGAL::DF_L1::Skeleton_graph<Traits>`, with `Traits` the kernel of the
///         point map's value type (or the one given by `geom_traits`)
/// \param points the input points
/// \param skeleton receives the skeleton: each vertex has its point, its local radius and
///        the indices of the input points it stands for (every non-outlier point belongs
///        to exactly one vertex)
/// \param np optional named parameters, those of the `DF_L1_skeletonization` constructor
/// \throws DF_L1::Invalid_input on bad input or parameters
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange, class Traits,
          class NamedParameters = parameters::Default_named_parameters>
void extract_df_l1_skeleton(const PointRange& points, DF_L1::Skeleton_graph<Traits>& skeleton,
                            const NamedParameters& np = parameters::default_values())
{
  DF_L1_skeletonization<Traits, ConcurrencyTag> skeletonization(points, np);
  skeletonization(skeleton);
}

} // namespace CGAL

#endif // CGAL_EXTRACT_DF_L1_SKELETON_H
