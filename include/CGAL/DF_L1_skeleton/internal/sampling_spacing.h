// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_SAMPLING_SPACING_H
#define CGAL_DF_L1_SKELETON_INTERNAL_SAMPLING_SPACING_H

/// \file sampling_spacing.h
/// The sampling spacing of a point cloud: the median distance from a point to its k-th
/// nearest neighbour, and that distance at chosen points. Not part of the public API.

#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The distance from xyz[i] to its k-th nearest neighbour, searched in balls of radius
// `guess`, doubled until they hold k other points; the cloud has more than k points.
// `d2` is scratch memory.
inline double kth_neighbour_distance(const std::vector<std::array<double, 3>>& xyz, std::size_t i, int k, double guess,
                                     const Uniform_grid& grid, std::vector<double>& d2)
{
  for(double r = guess;; r *= 2)
  {
    d2.clear();
    grid.for_each_in_ball(xyz[i], r, [&](std::size_t j, double d) {
      if(j != i)
        d2.push_back(d);
      return true;
    });
    if(d2.size() >= std::size_t(k))
      break;
  }
  std::nth_element(d2.begin(), d2.begin() + (k - 1), d2.end());
  return std::sqrt(d2[std::size_t(k - 1)]);
}

// Median distance from a point to its k-th nearest neighbour, over up to 4000 points
// taken at a regular stride (deterministic): the sampling spacing of the cloud, in
// input units. `guess` is the first search radius; `grid` holds `xyz`.
inline double median_kth_neighbour_distance(const std::vector<std::array<double, 3>>& xyz, int k, double guess,
                                            const Uniform_grid& grid)
{
  const std::size_t n = xyz.size();
  if(n <= std::size_t(k) || !(guess > 0))
    return 0;
  const std::size_t samples = (std::min)(n, std::size_t(4000));
  std::vector<double> kth, d2;
  kth.reserve(samples);
  for(std::size_t s = 0; s < samples; ++s)
    kth.push_back(kth_neighbour_distance(xyz, s * n / samples, k, guess, grid, d2));
  std::nth_element(kth.begin(), kth.begin() + kth.size() / 2, kth.end());
  return kth[kth.size() / 2];
}

// The distance from each point xyz[queries[q]] to its k-th nearest neighbour (input
// units; infinity when the cloud has k points or fewer). Each query writes only its own
// result, so the result does not depend on the threads.
template <class ConcurrencyTag>
std::vector<double> kth_neighbour_distances(const std::vector<std::array<double, 3>>& xyz,
                                            const std::vector<std::size_t>& queries, int k, double guess,
                                            const Uniform_grid& grid)
{
  std::vector<double> out(queries.size(), std::numeric_limits<double>::infinity());
  if(xyz.size() <= std::size_t(k) || !(guess > 0))
    return out;
  for_each_range<ConcurrencyTag>(queries.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<double> d2;
    for(std::size_t q = begin; q < end; ++q)
      out[q] = kth_neighbour_distance(xyz, queries[q], k, guess, grid, d2);
  }, 256);
  return out;
}

// The same, on a grid of cell size `guess` built here.
inline double median_kth_neighbour_distance(const std::vector<std::array<double, 3>>& xyz, int k, double guess)
{
  if(xyz.size() <= std::size_t(k) || !(guess > 0))
    return 0;
  return median_kth_neighbour_distance(xyz, k, guess, Uniform_grid(xyz, guess));
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_SAMPLING_SPACING_H
