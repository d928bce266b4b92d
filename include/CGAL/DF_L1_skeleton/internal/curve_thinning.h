// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_CURVE_THINNING_H
#define CGAL_DF_L1_SKELETON_INTERNAL_CURVE_THINNING_H

#include <CGAL/DF_L1_skeleton/internal/voxel_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The 26-neighbourhood of voxel v in the set `in`; voxels outside the grid are not in it.
template <class Geometry>
Neighbourhood neighbourhood_in(const Geometry& grid, const std::vector<char>& in, std::size_t v)
{
  const std::array<int, 3> c = grid.coordinates(v);
  Neighbourhood n = 0;
  const bool inside = c[0] > 0 && c[1] > 0 && c[2] > 0 && c[0] + 1 < grid.dims[0] &&
                      c[1] + 1 < grid.dims[1] && c[2] + 1 < grid.dims[2];
  const std::ptrdiff_t sx = 1, sy = grid.dims[0], sz = std::ptrdiff_t(grid.dims[0]) * grid.dims[1];
  for(int cell = 0; cell < 27; ++cell)
  {
    const int dx = cell % 3 - 1, dy = (cell / 3) % 3 - 1, dz = cell / 9 - 1;
    if(cell == 13 || (!inside && !grid.contains(c[0] + dx, c[1] + dy, c[2] + dz)))
      continue;
    if(in[std::size_t(std::ptrdiff_t(v) + dx * sx + dy * sy + dz * sz)])
      n |= Neighbourhood(1) << cell;
  }
  return n;
}

inline int neighbour_count(Neighbourhood n)
{
  int count = 0;
  for(n &= ~(Neighbourhood(1) << 13); n; n &= n - 1)
    ++count;
  return count;
}

// Thins the voxel set `in` to 26-connected curves without changing its topology
// (components, tunnels, cavities), in the order of increasing `depth`: what remains
// follows the ridges of the depth (the medial curves, when depth is a distance field).
//
// Depth is processed in slices of half a voxel. Within a slice, the voxels are peeled
// one face direction at a time (a voxel is a candidate for direction d when its
// neighbour in direction d is outside the set), sequentially, each removal re-checked;
// that keeps a tied ridge two voxels wide from being eaten from one end, which a plain
// sequential order would do. A curve end (one neighbour) is kept only when
// `keeps_end(v)` says so: ends elsewhere are bumps of the surface, not branches.
template <class Geometry, class EndPredicate>
void thin_to_curves(const Geometry& grid, const std::vector<float>& depth, std::vector<char>& in,
                    const EndPredicate& keeps_end)
{
  std::vector<std::size_t> order;
  for(std::size_t v = 0; v < in.size(); ++v)
    if(in[v])
      order.push_back(v);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return depth[a] != depth[b] ? depth[a] < depth[b] : a < b;
  });
  const int faces[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::size_t> pending; // voxels of the processed slices still in the set
  std::size_t next = 0;
  for(double slice = 0.5; next < order.size() || slice == 0.5; slice += 0.5)
  {
    while(next < order.size() && depth[order[next]] <= slice)
      pending.push_back(order[next++]);
    for(bool changed = true; changed;)
    {
      changed = false;
      for(int d = 0; d < 6; ++d)
        for(std::size_t v : pending)
        {
          if(!in[v])
            continue;
          const std::array<int, 3> c = grid.coordinates(v);
          const int i = c[0] + faces[d][0], j = c[1] + faces[d][1], k = c[2] + faces[d][2];
          if(grid.contains(i, j, k) && in[grid.index(i, j, k)])
            continue; // not on the border facing d
          const Neighbourhood n = neighbourhood_in(grid, in, v);
          const int count = neighbour_count(n);
          if(count == 0 || (count == 1 && keeps_end(v)) || !is_simple(n))
            continue;
          in[v] = 0;
          changed = true;
        }
      pending.erase(std::remove_if(pending.begin(), pending.end(), [&](std::size_t v) { return !in[v]; }),
                    pending.end());
    }
  }
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_CURVE_THINNING_H
