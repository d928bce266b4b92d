// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_POINT_RANGE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_POINT_RANGE_H

#include <CGAL/DF_L1_skeleton/errors.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The extent of the points the stage functions take: products of three lengths stay
// normal doubles. The class normalizes the points first, so it works at any scale.
constexpr double smallest_stage_extent = 1e-100;
constexpr double largest_stage_extent = 1e100;

// Every stage starts here: a clear exception for the inputs that would otherwise
// give NaN or a degenerate grid further down. With `any_scale`, the extent is not checked
// (the caller normalizes the points).
template <class PointRange, class PointMap>
CGAL::Bbox_3 checked_bbox(const PointRange& points, PointMap point_map, const char* stage, bool any_scale = false)
{
  CGAL::Bbox_3 box;
  std::size_t n = 0;
  for(const auto& value : points)
  {
    const auto& p = get(point_map, value);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw Invalid_input(std::string(stage) + ": point " + std::to_string(n) +
                          " has a coordinate that is not finite");
    box += CGAL::Bbox_3(x, y, z, x, y, z);
    ++n;
  }
  if(n == 0)
    throw Invalid_input(std::string(stage) + ": the point set is empty");
  const double extent = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  if(!any_scale && extent > 0 && !(extent >= smallest_stage_extent && extent <= largest_stage_extent))
  {
    std::ostringstream out;
    out.precision(3);
    out << stage << ": the points extend over " << extent
        << ", outside [1e-100, 1e100], the scales the stage functions compute at; "
           "DF_L1_skeletonization and extract_df_l1_skeleton() work at any scale";
    throw Invalid_input(out.str());
  }
  return box;
}

inline double diagonal(const CGAL::Bbox_3& b)
{
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

inline double longest_side(const CGAL::Bbox_3& b)
{
  return (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
}

// The points as plain double triples: the grid stages only need coordinates.
template <class PointRange, class PointMap>
std::vector<std::array<double, 3>> to_xyz(const PointRange& points, PointMap point_map)
{
  std::vector<std::array<double, 3>> xyz;
  for(const auto& value : points)
  {
    const auto& p = get(point_map, value);
    xyz.push_back({{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
  }
  return xyz;
}

template <class PointRange, class PointMap>
std::size_t range_size(const PointRange& points, PointMap)
{
  return std::size_t(std::distance(points.begin(), points.end()));
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_POINT_RANGE_H
