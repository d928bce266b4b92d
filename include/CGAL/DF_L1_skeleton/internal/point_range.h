// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_POINT_RANGE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_POINT_RANGE_H

#include <CGAL/DF_L1_skeleton/errors.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Every stage starts here: a clear exception for the inputs that would otherwise
// give NaN or a degenerate grid further down.
template <class PointRange, class PointMap>
CGAL::Bbox_3 checked_bbox(const PointRange& points, PointMap point_map, const char* stage)
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
