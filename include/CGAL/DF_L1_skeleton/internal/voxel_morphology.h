// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_MORPHOLOGY_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_MORPHOLOGY_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Dilation (value = 1) or erosion (value = 0) of the flags by the 3x3x3 cube: the cube is
// separable, so three passes of a 3-wide window along x, y and z. Voxels outside the grid
// count as 0.
inline void cube_filter(std::vector<char>& flags, const std::array<int, 3>& dims, bool dilate)
{
  const std::size_t stride[3] = {1, std::size_t(dims[0]), std::size_t(dims[0]) * dims[1]};
  std::vector<char> from;
  for(int axis = 0; axis < 3; ++axis)
  {
    from = flags;
    for(std::size_t v = 0; v < flags.size(); ++v)
    {
      const int position = int((v / stride[axis]) % std::size_t(dims[axis]));
      const char before = position > 0 ? from[v - stride[axis]] : 0;
      const char after = position + 1 < dims[axis] ? from[v + stride[axis]] : 0;
      flags[v] = dilate ? (from[v] | before | after) : (from[v] & before & after);
    }
  }
}

// Adds to `in` the voxels that no 6-connected path of voxels outside `in` joins to a
// voxel of `outside` (cavities enclosed by the set).
inline void fill_cavities(std::vector<char>& in, const std::vector<char>& outside, const std::array<int, 3>& dims)
{
  std::vector<char> reached(in.size(), 0);
  std::vector<std::size_t> stack;
  for(std::size_t v = 0; v < in.size(); ++v)
    if(outside[v] && !in[v])
    {
      reached[v] = 1;
      stack.push_back(v);
    }
  const std::size_t stride[3] = {1, std::size_t(dims[0]), std::size_t(dims[0]) * dims[1]};
  while(!stack.empty())
  {
    const std::size_t v = stack.back();
    stack.pop_back();
    for(int axis = 0; axis < 3; ++axis)
    {
      const int position = int((v / stride[axis]) % std::size_t(dims[axis]));
      for(int side = -1; side <= 1; side += 2)
      {
        if(position + side < 0 || position + side >= dims[axis])
          continue;
        const std::size_t w = side < 0 ? v - stride[axis] : v + stride[axis];
        if(!in[w] && !reached[w])
        {
          reached[w] = 1;
          stack.push_back(w);
        }
      }
    }
  }
  for(std::size_t v = 0; v < in.size(); ++v)
    in[v] = in[v] || !reached[v];
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_MORPHOLOGY_H
