// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Checks on voxel grids shared by the test programs.
#ifndef DF_L1_TEST_VOXEL_CHECKS_H
#define DF_L1_TEST_VOXEL_CHECKS_H

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace DF_L1_test {

// Exterior voxels reachable from the grid border through exterior voxels (26-connected).
template <class Grid>
std::size_t exterior_reachable_from_border(const Grid& g)
{
  std::vector<char> seen(g.size(), 0);
  std::vector<std::size_t> stack;
  for(std::size_t v = 0; v < g.size(); ++v)
  {
    const auto c = g.coordinates(v);
    const bool border = c[0] == 0 || c[1] == 0 || c[2] == 0 || c[0] == g.dims[0] - 1 ||
                        c[1] == g.dims[1] - 1 || c[2] == g.dims[2] - 1;
    if(border && g.labels[v] == CGAL::DF_L1::Voxel_label::EXTERIOR)
    {
      seen[v] = 1;
      stack.push_back(v);
    }
  }
  std::size_t count = 0;
  while(!stack.empty())
  {
    const auto c = g.coordinates(stack.back());
    stack.pop_back();
    ++count;
    for(int cell = 0; cell < 27; ++cell)
    {
      const int i = c[0] + cell % 3 - 1, j = c[1] + (cell / 3) % 3 - 1, k = c[2] + cell / 9 - 1;
      if(!g.contains(i, j, k))
        continue;
      const std::size_t w = g.index(i, j, k);
      if(!seen[w] && g.labels[w] == CGAL::DF_L1::Voxel_label::EXTERIOR)
      {
        seen[w] = 1;
        stack.push_back(w);
      }
    }
  }
  return count;
}

// Whether the exterior is one region: every exterior voxel is reachable from the border.
template <class Grid>
bool exterior_is_one_region(const Grid& g)
{
  return exterior_reachable_from_border(g) == g.count(CGAL::DF_L1::Voxel_label::EXTERIOR);
}

// Where the interior voxels lie against the true shape, in voxels of signed distance
// (negative inside).
struct Interior_census
{
  std::size_t deep = 0;          // voxels more than 2 voxels inside the shape
  std::size_t deep_interior = 0; // of those, the ones labelled interior
  std::size_t interior = 0;      // interior voxels
  std::size_t outside = 0;       // interior voxels more than half a voxel outside the shape
  double worst = -1e9;           // the largest signed distance of an interior voxel centre
};

template <class Shape, class Grid>
Interior_census interior_census(const Shape& shape, const Grid& grid)
{
  const double s = CGAL::to_double(grid.voxel_size);
  Interior_census c;
  for(std::size_t v = 0; v < grid.size(); ++v)
  {
    const double sd = shape.signed_distance(grid.center(v)) / s;
    const bool is_interior = grid.labels[v] == CGAL::DF_L1::Voxel_label::INTERIOR;
    if(sd < -2)
    {
      ++c.deep;
      c.deep_interior += is_interior;
    }
    if(is_interior)
    {
      ++c.interior;
      c.outside += sd > 0.5;
      c.worst = (std::max)(c.worst, sd);
    }
  }
  return c;
}

} // namespace DF_L1_test

#endif // DF_L1_TEST_VOXEL_CHECKS_H
