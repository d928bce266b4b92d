// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Degraded copies of the real scans: a scan meets the same expectation with fewer,
// unevenly spread, noisier points or with outliers, as a user's scan of the same object
// would. The generated corpus degrades uniform samples of ideal shapes; a scan's own
// sampling (a mesh's large triangles on a horse's body, the occlusions of a LiDAR crown)
// thins out unevenly under the same degradations, which the corpus never shows.

#ifndef DF_L1_EVALUATION_SCAN_VARIANTS_H
#define DF_L1_EVALUATION_SCAN_VARIANTS_H

#include "synthetic_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace DF_L1_test {

/// One way to degrade a scan.
struct Scan_variant
{
  std::string name;        ///< the degradation column of the rows
  std::string description; ///< for the report
};

/// The degradations of the real scans, in the report's order.
inline const std::vector<Scan_variant>& scan_variants()
{
  static const std::vector<Scan_variant> variants{
    {"sparse_2000", "2,000 of its points, drawn at random"},
    {"uneven", "beyond the median along the longest side of the box, one point in 8 kept"},
    {"noise_0.5", "Gaussian noise of 0.5 % of d_bb on every coordinate"},
    {"outliers_5", "5 % more points, uniform in the bounding box"},
  };
  return variants;
}

/// FNV-1a of a file name: the seed of its variants, the same on every platform.
inline std::uint64_t scan_seed(const std::string& name)
{
  std::uint64_t h = 14695981039346656037ull;
  for(unsigned char c : name)
    h = (h ^ c) * 1099511628211ull;
  return h;
}

/// The points of `variant` of a scan; the scan's own points come first and number
/// `scan_points` (the added outliers follow). A variant that does not apply (2,000
/// points of a smaller scan) gives no points.
inline std::vector<std::array<double, 3>> degrade_scan(const std::vector<std::array<double, 3>>& points,
                                                       const std::string& variant, std::uint64_t seed,
                                                       std::size_t& scan_points)
{
  internal::Rng rng(seed);
  std::vector<std::array<double, 3>> out;
  std::array<double, 3> lo{points[0]}, hi{points[0]};
  for(const auto& p : points)
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  const double diagonal =
    std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  if(variant == "sparse_2000") {
    if(points.size() <= 2000)
      return out;
    // A partial Fisher-Yates shuffle of the indices; kept in input order.
    std::vector<std::size_t> index(points.size());
    for(std::size_t i = 0; i < index.size(); ++i)
      index[i] = i;
    for(std::size_t i = 0; i < 2000; ++i)
      std::swap(index[i], index[i + rng.index(index.size() - i)]);
    index.resize(2000);
    std::sort(index.begin(), index.end());
    for(std::size_t i : index)
      out.push_back(points[i]);
  } else if(variant == "uneven") {
    int axis = 0;
    for(int a = 1; a < 3; ++a)
      if(hi[a] - lo[a] > hi[axis] - lo[axis])
        axis = a;
    std::vector<double> c;
    for(const auto& p : points)
      c.push_back(p[std::size_t(axis)]);
    std::nth_element(c.begin(), c.begin() + std::ptrdiff_t(c.size() / 2), c.end());
    const double median = c[c.size() / 2];
    for(const auto& p : points)
      if(rng.uniform() < (p[std::size_t(axis)] <= median ? 1.0 : 0.125))
        out.push_back(p);
  } else if(variant == "noise_0.5") {
    const double sigma = 0.005 * diagonal;
    for(const auto& p : points)
      out.push_back({p[0] + sigma * rng.normal(), p[1] + sigma * rng.normal(), p[2] + sigma * rng.normal()});
  } else if(variant == "outliers_5") {
    out = points;
    for(std::size_t i = 0; i < points.size() / 20; ++i)
      out.push_back({rng.uniform(lo[0], hi[0]), rng.uniform(lo[1], hi[1]), rng.uniform(lo[2], hi[2])});
    scan_points = points.size();
    return out;
  }
  scan_points = out.size();
  return out;
}

} // namespace DF_L1_test

#endif // DF_L1_EVALUATION_SCAN_VARIANTS_H
