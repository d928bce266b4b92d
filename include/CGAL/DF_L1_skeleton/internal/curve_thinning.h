// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_CURVE_THINNING_H
#define CGAL_DF_L1_SKELETON_INTERNAL_CURVE_THINNING_H

#include <CGAL/DF_L1_skeleton/internal/voxel_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Linear-index offsets of the 27 cells of a 3x3x3 neighbourhood (cell 13 is the centre).
template <class Geometry>
std::array<std::ptrdiff_t, 27> neighbourhood_offsets(const Geometry& grid)
{
  std::array<std::ptrdiff_t, 27> offsets;
  const std::ptrdiff_t sy = grid.dims[0], sz = std::ptrdiff_t(grid.dims[0]) * grid.dims[1];
  for(int cell = 0; cell < 27; ++cell)
    offsets[cell] = (cell % 3 - 1) + ((cell / 3) % 3 - 1) * sy + (cell / 9 - 1) * sz;
  return offsets;
}

// The 26-neighbourhood of voxel v in the set of the voxels w where `flags[w] & member`;
// v must not be on the outer layer of the grid.
inline Neighbourhood neighbourhood_in(const std::vector<std::uint8_t>& flags, std::uint8_t member, std::size_t v,
                                      const std::array<std::ptrdiff_t, 27>& offsets)
{
  Neighbourhood n = 0;
  for(int cell = 0; cell < 27; ++cell)
    if(cell != 13 && (flags[std::size_t(std::ptrdiff_t(v) + offsets[cell])] & member))
      n |= Neighbourhood(1) << cell;
  return n;
}

inline int neighbour_count(Neighbourhood n)
{
  return bit_count(n & ~(Neighbourhood(1) << 13));
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
// Voxels on the outer layer of the grid are dropped from the set first (a padded grid
// has none), so that neighbourhoods need no bounds checks.
template <class Geometry, class EndPredicate>
void thin_to_curves(const Geometry& grid, const std::vector<float>& depth, std::vector<char>& in,
                    const EndPredicate& keeps_end)
{
  const auto deeper = [&](std::size_t a, std::size_t b) {
    return depth[a] != depth[b] ? depth[a] < depth[b] : a < b;
  };
  std::vector<std::size_t> order;
  for(std::size_t v = 0; v < in.size(); ++v)
  {
    if(!in[v])
      continue;
    const std::array<int, 3> c = grid.coordinates(v);
    if(c[0] == 0 || c[1] == 0 || c[2] == 0 || c[0] + 1 == grid.dims[0] || c[1] + 1 == grid.dims[1] ||
       c[2] + 1 == grid.dims[2])
      in[v] = 0;
    else
      order.push_back(v);
  }
  std::sort(order.begin(), order.end(), deeper);
  const std::array<std::ptrdiff_t, 27> offsets = neighbourhood_offsets(grid);
  const int face_cells[6] = {14, 12, 16, 10, 22, 4};
  // One byte per voxel: in the set, on the work list, and reached by the slices (its
  // depth at most the current slice). Reading one array rather than `in`, a list flag
  // and the depth keeps the neighbourhoods, most of the cost, in fewer cache lines.
  enum : std::uint8_t { IN = 1, LISTED = 2, REACHED = 4 };
  std::vector<std::uint8_t> state(in.size(), 0);
  for(std::size_t v : order)
    state[v] = IN;
  // Only a voxel whose neighbourhood changed can become removable: the work list holds
  // the new voxels of the slice and the neighbours of the voxels just removed.
  std::vector<std::size_t> work, next_work;
  std::size_t next = 0;
  for(double slice = 0.5; next < order.size(); slice += 0.5)
  {
    for(; next < order.size() && depth[order[next]] <= slice; ++next)
    {
      state[order[next]] |= LISTED | REACHED;
      work.push_back(order[next]);
    }
    while(!work.empty())
    {
      std::sort(work.begin(), work.end(), deeper);
      for(std::size_t v : work)
        state[v] &= std::uint8_t(~LISTED);
      for(int d = 0; d < 6; ++d)
        for(std::size_t v : work)
        {
          if(!(state[v] & IN) || (state[std::size_t(std::ptrdiff_t(v) + offsets[face_cells[d]])] & IN))
            continue; // gone, or not on the border facing d
          const Neighbourhood n = neighbourhood_in(state, IN, v, offsets);
          const int count = neighbour_count(n);
          if(count == 0 || (count == 1 && keeps_end(v)) || !is_simple(n))
            continue;
          state[v] &= std::uint8_t(~IN);
          for(int cell = 0; cell < 27; ++cell)
          {
            const std::size_t w = std::size_t(std::ptrdiff_t(v) + offsets[cell]);
            if((state[w] & (IN | LISTED | REACHED)) == (IN | REACHED))
            {
              state[w] |= LISTED;
              next_work.push_back(w);
            }
          }
        }
      work.swap(next_work);
      next_work.clear();
    }
  }
  for(std::size_t v : order)
    in[v] = (state[v] & IN) != 0;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_CURVE_THINNING_H
