// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H
#define CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H

/// \file flag_sparse_outliers.h
/// Stage 0a: outlier points far from every other sample, flagged before voxelization.

#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/density_cap.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/internal/vec3.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

namespace internal {

// The tests of flag_sparse_outliers() on the points of `grid` in cell order: every
// per-point array is indexed by position in grid.sorted_points(), so that the tests of
// neighbouring points read nearby memory (on a cloud given in random order, indexing by
// input index made every neighbour a cache miss). `Index` holds a position: 32 bits
// halve the neighbour lists of clouds below 4 billion points. Returns a flag per position;
// `distances`, when given, receives the distance of each position to its k-th nearest
// unflagged point as the last pass measured it.
template <class Index, class ConcurrencyTag>
std::vector<char> flag_sparse_outliers_in_cell_order(const Uniform_grid& grid, unsigned int k, double ratio,
                                                     double local_ratio, std::vector<double>* distances = nullptr)
{
  const std::vector<std::array<double, 3>>& xyz = grid.sorted_points();
  const std::size_t n = xyz.size();
  // kth[s]: distance to the k-th nearest unflagged point; neighbours[s*k..]: those k points.
  std::vector<double> kth(n);
  std::vector<Index> neighbours(n * k);
  std::vector<char> flagged(n, 0);
  // `nearest` is scratch memory shared by the searches of a range (an allocation per
  // search cost a tenth of the stage)
  const auto measure = [&](std::size_t s, bool none_flagged, std::vector<std::pair<double, std::size_t>>& nearest) {
    if(none_flagged) // the first pass: flagged is not read
      grid.k_nearest_positions(xyz[s], k, [&](std::size_t t) { return t != s; }, nearest);
    else
      grid.k_nearest_positions(xyz[s], k, [&](std::size_t t) { return t != s && !flagged[t]; }, nearest);
    for(std::size_t m = 0; m < k; ++m) // fewer than k unflagged points left: the point itself
      neighbours[s * k + m] = Index(m < nearest.size() ? nearest[m].second : s);
    kth[s] = nearest.empty() ? 0 : std::sqrt(nearest.back().first);
  };
  for_each_range<ConcurrencyTag>(n, [&](std::size_t begin, std::size_t end) {
    std::vector<std::pair<double, std::size_t>> nearest;
    for(std::size_t s = begin; s < end; ++s)
      measure(s, true, nearest);
  });
  std::vector<double> sorted = kth;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double threshold = ratio * sorted[n / 2];
  std::vector<double>().swap(sorted);

  const auto is_outlier = [&](std::size_t s, std::vector<double>& around) {
    if(kth[s] > threshold)
      return true;
    around.resize(k);
    for(std::size_t m = 0; m < k; ++m)
      around[m] = kth[neighbours[s * k + m]];
    std::nth_element(around.begin(), around.begin() + k / 2, around.end());
    return kth[s] > local_ratio * around[k / 2];
  };
  // Only the points that lost a neighbour to the last pass need a new test: removing
  // points makes the distances of the others grow or stay, and a point whose own
  // distance stays is not flagged by its neighbours' growing. Each pass decides on the
  // distances of the previous one, whatever the order of the candidates.
  // mark[s]: the verdict of the pass on s, then whether s is a candidate of the next
  std::vector<char> mark(n, 0);
  std::vector<std::size_t> candidates; // empty: all the points (the first pass)
  std::size_t remaining = n;
  for(;;)
  {
    const std::size_t count = candidates.empty() ? n : candidates.size();
    for_each_range<ConcurrencyTag>(count, [&](std::size_t begin, std::size_t end) {
      std::vector<double> around;
      for(std::size_t c = begin; c < end; ++c)
      {
        const std::size_t s = candidates.empty() ? c : candidates[c];
        mark[s] = is_outlier(s, around);
      }
    });
    std::size_t added = 0;
    for(std::size_t c = 0; c < count; ++c)
    {
      const std::size_t s = candidates.empty() ? c : candidates[c];
      if(mark[s])
        flagged[s] = 1, ++added;
    }
    remaining -= added;
    if(added == 0 || remaining <= k + 1)
      break;
    for_each_range<ConcurrencyTag>(n, [&](std::size_t begin, std::size_t end) {
      for(std::size_t s = begin; s < end; ++s)
        mark[s] = !flagged[s] && std::any_of(neighbours.begin() + s * k, neighbours.begin() + (s + 1) * k,
                                             [&](Index t) { return flagged[t] != 0; });
    }, 1 << 14);
    candidates.clear();
    for(std::size_t s = 0; s < n; ++s)
      if(mark[s])
        candidates.push_back(s);
    if(candidates.empty())
      break;
    for_each_range<ConcurrencyTag>(candidates.size(), [&](std::size_t begin, std::size_t end) {
      std::vector<std::pair<double, std::size_t>> nearest;
      for(std::size_t c = begin; c < end; ++c)
        measure(candidates[c], false, nearest);
    });
  }
  if(distances)
    distances->swap(kth);
  return flagged;
}

} // namespace internal

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
  std::vector<std::array<double, 3>> xyz = internal::to_xyz(points, point_map);
  const std::size_t n = xyz.size();
  std::vector<bool> flags(n, false);
  if(n <= k + 1)
    return flags;
  const internal::Uniform_grid grid(xyz, 0, ConcurrencyTag()); // cells for k-nearest searches
  std::vector<std::array<double, 3>>().swap(xyz); // the grid has its own copy
  const std::vector<char> flagged =
      n <= std::numeric_limits<std::uint32_t>::max()
          ? internal::flag_sparse_outliers_in_cell_order<std::uint32_t, ConcurrencyTag>(grid, k, ratio, local_ratio)
          : internal::flag_sparse_outliers_in_cell_order<std::size_t, ConcurrencyTag>(grid, k, ratio, local_ratio);
  const std::vector<std::size_t>& index = grid.indices_by_cell();
  for(std::size_t s = 0; s < n; ++s)
    flags[index[s]] = flagged[s] != 0;
  return flags;
}

namespace internal {

// Whether the point of index i belongs to the sample of one point in `every`: a hash of
// the index, so that the sample is spread evenly whatever the order of the points (a
// scan's lines, a generator's shapes).
inline bool in_sample(std::size_t i, std::size_t every)
{
  std::uint64_t z = std::uint64_t(i) + 0x9e3779b97f4a7c15ull; // splitmix64
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return z % every == 0;
}

// The flags of flag_sparse_outliers() (k = 6, ratio 4, local ratio 2) for a cloud far
// denser than its voxels, where a test of every point would cost a neighbour search per
// point: the test runs on a uniform sample of one point in `every`, which thins the
// surface and the scattered points alike and so keeps them apart (one point per cell
// would not: it would bring the surface down to the density of the outliers). A point
// outside the sample is an outlier unless an unflagged point s of the sample lies within
// twice the distance from s to its 6th nearest neighbour in the sample (the local ratio
// of the test): in a sparse region of the surface that distance is larger, and the
// points there are judged at their own spacing. The balls are rounded up to the cells of
// `lattice` they touch. Returns an empty vector when the sample is too small for this to
// hold (the caller then tests every point).
template <class ConcurrencyTag, class Point>
std::vector<bool> sampled_sparse_outliers(const std::vector<Point>& points, const Cell_lattice& lattice,
                                          std::size_t every)
{
  const unsigned int k = 6;
  const double ratio = 4, local_ratio = 2;
  const std::size_t n = points.size();
  std::vector<std::size_t> sample;
  for(std::size_t i = 0; i < n; ++i)
    if(in_sample(i, every))
      sample.push_back(i);
  if(sample.size() < 1000 || sample.size() > std::numeric_limits<std::uint32_t>::max())
    return {};
  std::vector<std::array<double, 3>> xyz(sample.size());
  for(std::size_t s = 0; s < sample.size(); ++s)
    xyz[s] = to_vec3(points[sample[s]]);
  const Uniform_grid grid(xyz, 0, ConcurrencyTag());
  std::vector<std::array<double, 3>>().swap(xyz);
  std::vector<double> kth; // in cell order
  const std::vector<char> flagged =
    flag_sparse_outliers_in_cell_order<std::uint32_t, ConcurrencyTag>(grid, k, ratio, local_ratio, &kth);

  // the cells within reach of an unflagged point of the sample
  std::vector<std::uint64_t> covered((lattice.size() + 63) / 64, 0);
  const std::vector<std::array<double, 3>>& sorted = grid.sorted_points();
  for(std::size_t s = 0; s < sorted.size(); ++s)
  {
    if(flagged[s])
      continue;
    const double reach = local_ratio * kth[s];
    const std::array<std::size_t, 3> lo = lattice.cell_of({{sorted[s][0] - reach, sorted[s][1] - reach, sorted[s][2] - reach}}),
                                     hi = lattice.cell_of({{sorted[s][0] + reach, sorted[s][1] + reach, sorted[s][2] + reach}});
    for(std::size_t z = lo[2]; z <= hi[2]; ++z)
      for(std::size_t y = lo[1]; y <= hi[1]; ++y)
        for(std::size_t x = lo[0]; x <= hi[0]; ++x)
        {
          const std::size_t c = lattice.index({{x, y, z}});
          covered[c / 64] |= std::uint64_t(1) << (c % 64);
        }
  }
  std::vector<char> flags(n, 0);
  for_each_range<ConcurrencyTag>(n, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
    {
      const std::size_t c = lattice.index(lattice.cell_of(to_vec3(points[i])));
      flags[i] = !((covered[c / 64] >> (c % 64)) & 1);
    }
  }, 1 << 14);
  const std::vector<std::size_t>& order = grid.indices_by_cell();
  for(std::size_t s = 0; s < sorted.size(); ++s)
    flags[sample[order[s]]] = flagged[s];
  return std::vector<bool>(flags.begin(), flags.end());
}

} // namespace internal

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_FLAG_SPARSE_OUTLIERS_H
