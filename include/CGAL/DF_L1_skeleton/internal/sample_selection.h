// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_SAMPLE_SELECTION_H
#define CGAL_DF_L1_SKELETON_INTERNAL_SAMPLE_SELECTION_H

#include <CGAL/DF_L1_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Key of the cubic cell of size `cell` that holds p (coordinates relative to `lo`).
inline std::uint64_t cell_key(const Vec3& p, const Vec3& lo, double cell)
{
  std::uint64_t key = 0;
  for(int a = 0; a < 3; ++a)
    key = (key << 21) | (std::uint64_t(std::floor((p[a] - lo[a]) / cell)) & 0x1FFFFF);
  return key;
}

// About m of the points, spread evenly over the cloud: the cloud is cut into cubic cells
// whose size is chosen (by bisection on a log scale) so that about m cells are occupied,
// and each occupied cell gives the point nearest its centre. Unlike the random pick of
// the L1-medial method this is deterministic and does not over-sample dense regions,
// which would otherwise pull the contraction towards them. Returns point indices in
// increasing order.
inline std::vector<std::size_t> select_samples(const std::vector<Vec3>& points, std::size_t m)
{
  std::vector<std::size_t> all(points.size());
  std::iota(all.begin(), all.end(), std::size_t(0));
  if(m >= points.size())
    return all;
  Vec3 lo = points[0], hi = points[0];
  for(const Vec3& p : points)
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = (std::min)(lo[a], p[a]);
      hi[a] = (std::max)(hi[a], p[a]);
    }
  const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  // The number of occupied cells, or m + 1 as soon as it exceeds m: the search only asks
  // whether it does, and a fine grid of a large cloud would otherwise fill a map of
  // millions of cells (most of the time of the pick at a million points).
  const auto occupied = [&](double cell) {
    std::unordered_map<std::uint64_t, std::size_t> cells;
    cells.reserve(2 * m + 2);
    for(const Vec3& p : points)
      if(cells.emplace(cell_key(p, lo, cell), 0).second && cells.size() > m)
        break;
    return cells.size();
  };
  // Cell sizes bracketing m occupied cells: many cells at extent / 2^20, one at 2 extent.
  double small = extent / double(1 << 20), large = 2 * extent;
  for(int step = 0; step < 24; ++step)
  {
    const double cell = std::sqrt(small * large);
    (occupied(cell) > m ? small : large) = cell;
    if(large < 1.02 * small)
      break;
  }
  const double cell = large; // at most m cells
  std::unordered_map<std::uint64_t, std::size_t> best;
  best.reserve(2 * m);
  const auto distance_to_centre = [&](const Vec3& p) {
    double d = 0;
    for(int a = 0; a < 3; ++a)
    {
      const double c = (std::floor((p[a] - lo[a]) / cell) + 0.5) * cell + lo[a];
      d += (p[a] - c) * (p[a] - c);
    }
    return d;
  };
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    auto it = best.emplace(cell_key(points[i], lo, cell), i).first;
    if(distance_to_centre(points[i]) < distance_to_centre(points[it->second]))
      it->second = i;
  }
  std::vector<std::size_t> picked;
  picked.reserve(best.size());
  for(const auto& kv : best)
    picked.push_back(kv.second);
  std::sort(picked.begin(), picked.end());
  return picked;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_SAMPLE_SELECTION_H
