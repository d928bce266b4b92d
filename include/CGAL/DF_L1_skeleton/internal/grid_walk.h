// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_GRID_WALK_H
#define CGAL_DF_L1_SKELETON_INTERNAL_GRID_WALK_H

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Calls visit(i, j, k) for every voxel the segment pq passes through, from p's voxel to
// q's, in order (Amanatides and Woo's traversal); the cells may lie outside the grid.
// Stops and returns false as soon as visit returns false.
template <class Traits, class Visitor>
bool walk_segment(const Grid_geometry<Traits>& grid, const typename Traits::Point_3& p,
                  const typename Traits::Point_3& q, const Visitor& visit)
{
  const double s = CGAL::to_double(grid.voxel_size);
  const std::array<double, 3> a = {{CGAL::to_double(p.x() - grid.origin.x()) / s, CGAL::to_double(p.y() - grid.origin.y()) / s,
                                    CGAL::to_double(p.z() - grid.origin.z()) / s}};
  const std::array<double, 3> b = {{CGAL::to_double(q.x() - grid.origin.x()) / s, CGAL::to_double(q.y() - grid.origin.y()) / s,
                                    CGAL::to_double(q.z() - grid.origin.z()) / s}};
  std::array<int, 3> cell, last, step;
  std::array<double, 3> next_t, delta_t;
  int remaining = 0;
  for(int d = 0; d < 3; ++d)
  {
    cell[d] = int(std::floor(a[d]));
    last[d] = int(std::floor(b[d]));
    remaining += std::abs(last[d] - cell[d]);
    const double length = b[d] - a[d];
    step[d] = length > 0 ? 1 : (length < 0 ? -1 : 0);
    if(step[d] == 0)
    {
      next_t[d] = delta_t[d] = std::numeric_limits<double>::infinity();
      continue;
    }
    delta_t[d] = 1 / std::abs(length);
    const double boundary = step[d] > 0 ? cell[d] + 1 : cell[d];
    next_t[d] = (boundary - a[d]) / length;
  }
  if(!visit(cell[0], cell[1], cell[2]))
    return false;
  // Each step crosses one voxel face; there are exactly `remaining` faces between the
  // end cells, which also bounds the loop against rounding.
  for(; remaining > 0; --remaining)
  {
    const int d = next_t[0] <= next_t[1] ? (next_t[0] <= next_t[2] ? 0 : 2) : (next_t[1] <= next_t[2] ? 1 : 2);
    if(cell[d] == last[d]) // rounding chose an axis already done: take another
    {
      int other = -1;
      for(int e = 0; e < 3; ++e)
        if(cell[e] != last[e] && (other < 0 || next_t[e] < next_t[other]))
          other = e;
      if(other < 0)
        break;
      cell[other] += step[other];
      next_t[other] += delta_t[other];
    }
    else
    {
      cell[d] += step[d];
      next_t[d] += delta_t[d];
    }
    if(!visit(cell[0], cell[1], cell[2]))
      return false;
  }
  return true;
}

// Whether the segment pq crosses no exterior or outlier voxel and does not leave the
// grid: the test that a bridge between two skeleton points stays inside the shape.
template <class Traits>
bool segment_stays_inside(const Grid_geometry<Traits>& grid, const std::vector<Voxel_label>& labels,
                          const typename Traits::Point_3& p, const typename Traits::Point_3& q)
{
  return walk_segment(grid, p, q, [&](int i, int j, int k) {
    return grid.contains(i, j, k) && Voxel_grid<Traits>::is_occupied(labels[grid.index(i, j, k)]);
  });
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_GRID_WALK_H
