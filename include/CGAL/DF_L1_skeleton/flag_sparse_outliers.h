// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H
#define CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H

/// \file flag_sparse_outliers.h
/// Stage 0a: outlier points far from every other sample, flagged before voxelization.

#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Flags the points that are far from the others. With d(p) the distance from p to its
/// k-th nearest neighbour, p is an outlier when
/// - d(p) exceeds `ratio` times the median of d over the cloud (an isolated point), or
/// - d(p) exceeds `local_ratio` times the median of d over the k neighbours of p (a
///   point hovering a few voxels over a denser surface).
///
/// The tests repeat without the points already flagged until none is added, so that a
/// chance cluster of outliers loses its flagged members and the others stand out. The
/// paper removes outliers after voxelization only; scattered outliers fill most voxels of
/// the coarsest grid, and the exterior flood could not pass between them. An outlier
/// closer to the surface than the sampling spacing is noise of the surface and stays.
/// Each pass measures every point independently, so the result does not depend on the
/// number of threads. The rules and their measurements: \ref design_outliers.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \param points the input points
/// \param k the neighbour whose distance is measured (default 6)
/// \param ratio the multiple of the cloud's median distance above which a point is an
///        outlier (default 4)
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of
///       the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param local_ratio the multiple of the median distance of a point's k neighbours
///        above which it is an outlier (default 2; `std::numeric_limits<double>::infinity()`
///        leaves the global test alone, still repeated)
/// \returns one flag per point, `true` for an outlier
/// \throws Invalid_input if `k` is 0, `ratio` or `local_ratio` not > 1 (or `ratio` not
///         finite), or a point is not finite
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange,
          class NamedParameters = parameters::Default_named_parameters>
std::vector<bool> flag_sparse_outliers(const PointRange& points, unsigned int k = 6, double ratio = 4,
                                       const NamedParameters& np = parameters::default_values(),
                                       double local_ratio = 2)
{
  typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;

  if(k < 1 || !(ratio > 1) || !std::isfinite(ratio) || !(local_ratio > 1))
    throw Invalid_input("outlier points: k must be positive, ratio a finite number > 1 and local_ratio > 1");
  const auto point_map = NP_helper::get_const_point_map(points, np);
  internal::checked_bbox(points, point_map, "outlier points");
  const std::vector<std::array<double, 3>> xyz = internal::to_xyz(points, point_map);
  const std::size_t n = xyz.size();
  std::vector<bool> flags(n, false);
  if(n <= k + 1)
    return flags;

  const internal::Uniform_grid grid(xyz, 0); // cells for k-nearest searches

  // kth[i]: distance to the k-th nearest unflagged point; neighbours[i*k..]: those k points.
  std::vector<double> kth(n);
  std::vector<std::size_t> neighbours(n * k);
  std::vector<char> flagged(n, 0); // a copy of flags that threads may read
  // `nearest` is scratch memory shared by the searches of a range (an allocation per
  // search cost a tenth of the stage)
  const auto measure = [&](std::size_t i, bool none_flagged, std::vector<std::pair<double, std::size_t>>& nearest) {
    if(none_flagged) // the first pass: flagged is not read (at random places, on a large cloud)
      grid.k_nearest(xyz[i], k, [&](std::size_t j) { return j != i; }, nearest);
    else
      grid.k_nearest(xyz[i], k, [&](std::size_t j) { return j != i && !flagged[j]; }, nearest);
    for(std::size_t m = 0; m < k; ++m) // fewer than k unflagged points left: the point itself
      neighbours[i * k + m] = m < nearest.size() ? nearest[m].second : i;
    kth[i] = nearest.empty() ? 0 : std::sqrt(nearest.back().first);
  };
  // in cell order: consecutive searches read the same cells
  const std::vector<std::size_t>& query_order = grid.indices_by_cell();
  internal::for_each_range<ConcurrencyTag>(n, [&](std::size_t begin, std::size_t end) {
    std::vector<std::pair<double, std::size_t>> nearest;
    for(std::size_t q = begin; q < end; ++q)
      measure(query_order[q], true, nearest);
  });
  std::vector<double> sorted = kth;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double threshold = ratio * sorted[n / 2];

  const auto is_outlier = [&](std::size_t i, std::vector<double>& around) {
    if(kth[i] > threshold)
      return true;
    around.resize(k);
    for(std::size_t m = 0; m < k; ++m)
      around[m] = kth[neighbours[i * k + m]];
    std::nth_element(around.begin(), around.begin() + k / 2, around.end());
    return kth[i] > local_ratio * around[k / 2];
  };
  // Only the points that lost a neighbour to the last pass need a new test: removing
  // points makes the distances of the others grow or stay, and a point whose own
  // distance stays is not flagged by its neighbours' growing.
  // first all the points, in cell order: the tests of neighbours read the same distances
  std::vector<std::size_t> candidates = query_order;
  std::vector<char> verdict(n, 0);
  std::size_t remaining = n;
  while(!candidates.empty())
  {
    internal::for_each_range<ConcurrencyTag>(candidates.size(), [&](std::size_t begin, std::size_t end) {
      std::vector<double> around;
      for(std::size_t c = begin; c < end; ++c)
        verdict[candidates[c]] = is_outlier(candidates[c], around);
    });
    std::size_t added = 0;
    for(std::size_t i : candidates)
      if(verdict[i])
        flags[i] = true, flagged[i] = 1, ++added;
    remaining -= added;
    if(added == 0 || remaining <= k + 1)
      break;
    candidates.clear();
    for(std::size_t i = 0; i < n; ++i)
      if(!flagged[i] && std::any_of(neighbours.begin() + i * k, neighbours.begin() + (i + 1) * k,
                                    [&](std::size_t j) { return flagged[j] != 0; }))
        candidates.push_back(i);
    internal::for_each_range<ConcurrencyTag>(candidates.size(), [&](std::size_t begin, std::size_t end) {
      std::vector<std::pair<double, std::size_t>> nearest;
      for(std::size_t c = begin; c < end; ++c)
        measure(candidates[c], false, nearest);
    });
  }
  return flags;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H
