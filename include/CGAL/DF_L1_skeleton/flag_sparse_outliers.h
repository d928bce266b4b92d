// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H
#define CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H

/// \file flag_sparse_outliers.h
/// Stage 0a: outlier points far from every other sample, flagged before voxelization.

#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Flags the points that are far from all others: those whose distance to their k-th
/// nearest neighbour exceeds `ratio` times the median of that distance over the cloud.
///
/// The paper removes outliers after voxelization, as boundary voxels disconnected from
/// the volume, and admits that heavy outliers need a pre-filter (LOP). Scattered
/// outliers are dense enough, at the coarsest voxel size d_bb / 9, to fill most coarse
/// voxels: the exterior flood then cannot pass between them and encloses them as
/// "interior". This test removes them first; the voxel test of
/// `remove_outlier_voxels()` then catches the clusters. An outlier glued to the surface
/// (closer than the sampling spacing) is not flagged: it is noise of the surface.
/// Uniform sampling density is not needed: a region ten times sparser than the median
/// has a k-th neighbour about 3.2 times farther, below the default ratio of 4.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \param points the input points
/// \param k the neighbour whose distance is measured (default 6)
/// \param ratio the multiple of the median distance above which a point is an outlier (default 4)
/// \param np optional named parameters: `point_map`, `geom_traits`
/// \returns one flag per point, `true` for an outlier
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange,
          class NamedParameters = parameters::Default_named_parameters>
std::vector<bool> flag_sparse_outliers(const PointRange& points, unsigned int k = 6, double ratio = 4,
                                       const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Traits;
  typedef typename Traits::Point_3 Point_3;
  typedef CGAL::Search_traits_3<Traits> Base_traits;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Index_point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Index_point_map, Base_traits> Search_traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Search_traits> Search;
  typedef typename Search::Tree Tree;

  if(k < 1 || !(ratio > 1) || !std::isfinite(ratio))
    throw Invalid_input("outlier points: k must be positive and ratio a finite number > 1");
  const auto point_map = NP_helper::get_const_point_map(points, np);
  internal::checked_bbox(points, point_map, "outlier points");
  std::vector<Point_3> xyz;
  for(const auto& value : points)
    xyz.push_back(get(point_map, value));
  const std::size_t n = xyz.size();
  std::vector<bool> flags(n, false);
  if(n <= k + 1)
    return flags;

  const Index_point_map ipm(xyz.data());
  std::vector<std::size_t> ids(n);
  for(std::size_t i = 0; i < n; ++i)
    ids[i] = i;
  Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Search_traits(ipm));
  tree.build();
  const typename Search::Distance distance(ipm);
  std::vector<double> kth(n);
  const auto measure = [&](std::size_t i) {
    Search search(tree, xyz[i], k + 1, 0, true, distance); // the point itself comes first
    double d2 = 0;
    for(const auto& neighbour : search)
      d2 = (std::max)(d2, CGAL::to_double(neighbour.second));
    kth[i] = std::sqrt(d2);
  };
  internal::for_each_index<ConcurrencyTag>(n, measure);
  std::vector<double> sorted = kth;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double threshold = ratio * sorted[n / 2];
  for(std::size_t i = 0; i < n; ++i)
    flags[i] = kth[i] > threshold;
  return flags;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H
