// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_MORPHOLOGY_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_MORPHOLOGY_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The voxels within sqrt(r2) voxels (centre to centre) of a marked voxel: the set that
// thresholding the distance transform of the marked voxels at r2 gives, for a fraction of
// its cost when the radius is a few voxels and the marked voxels are a thin shell (the
// transform scans the whole grid three times, whatever its bound). The ball is written
// around each marked voxel as one run per row.
inline std::vector<char> dilate_by_ball(const std::vector<char>& marked, const std::array<int, 3>& dims, double r2)
{
  struct Row { int dj, dk, half; };
  std::vector<Row> rows;
  const int r = int(std::sqrt((std::max)(r2, 0.0))) + 1;
  for(int dk = -r; dk <= r; ++dk)
    for(int dj = -r; dj <= r; ++dj)
    {
      const double rest = r2 - double(dj * dj + dk * dk);
      if(rest < 0)
        continue;
      int half = 0;
      while(double((half + 1) * (half + 1)) <= rest)
        ++half;
      rows.push_back({dj, dk, half});
    }
  const int nx = dims[0], ny = dims[1], nz = dims[2];
  std::vector<char> out(marked.size(), 0);
  for(int k = 0; k < nz; ++k)
    for(int j = 0; j < ny; ++j)
      for(int i = 0; i < nx; ++i)
      {
        if(!marked[(std::size_t(k) * ny + j) * nx + i])
          continue;
        for(const Row& row : rows)
        {
          const int jj = j + row.dj, kk = k + row.dk;
          if(jj < 0 || jj >= ny || kk < 0 || kk >= nz)
            continue;
          const int i0 = (std::max)(0, i - row.half), i1 = (std::min)(nx - 1, i + row.half);
          std::fill_n(out.begin() + std::ptrdiff_t((std::size_t(kk) * ny + jj) * nx + i0), i1 - i0 + 1, char(1));
        }
      }
  return out;
}

// Dilation (dilate = true) or erosion of the flags by the 3x3x3 cube: the cube is
// separable, so three passes of a 3-wide window along x, y and z. Voxels outside the grid
// count as 0: they are read from a row of zeros (along y and z) or a zero-padded copy of
// the row (along x), so that the loops over a row have no test and vectorize.
inline void cube_filter(std::vector<char>& flags, const std::array<int, 3>& dims, bool dilate)
{
  const std::size_t nx = std::size_t(dims[0]);
  const std::size_t stride[3] = {1, nx, nx * std::size_t(dims[1])};
  std::vector<char> from(flags.size()), zeros(nx, 0), padded(nx + 2, 0);
  for(int axis = 0; axis < 3; ++axis)
  {
    from.swap(flags);
    const std::size_t step = stride[axis];
    for(int k = 0; k < dims[2]; ++k)
      for(int j = 0; j < dims[1]; ++j)
      {
        const std::size_t row = (std::size_t(k) * dims[1] + j) * nx;
        const char* at = from.data() + row;
        const char *before, *after;
        if(axis == 0)
        {
          std::copy(at, at + nx, padded.begin() + 1);
          before = padded.data();
          after = padded.data() + 2;
        }
        else
        {
          const int position = axis == 1 ? j : k;
          before = position > 0 ? at - step : zeros.data();
          after = position + 1 < dims[axis] ? at + step : zeros.data();
        }
        char* out = flags.data() + row;
        if(dilate)
          for(std::size_t i = 0; i < nx; ++i)
            out[i] = char(at[i] | before[i] | after[i]);
        else
          for(std::size_t i = 0; i < nx; ++i)
            out[i] = char(at[i] & before[i] & after[i]);
      }
  }
}

// Adds to `in` the voxels that no 6-connected path of voxels outside `in` joins to a
// voxel of `outside` (the cavities the set encloses). Only the voxels in neither set can
// be in a cavity, so only they are walked.
inline void fill_cavities(std::vector<char>& in, const std::vector<char>& outside, const std::array<int, 3>& dims)
{
  const std::size_t stride[3] = {1, std::size_t(dims[0]), std::size_t(dims[0]) * dims[1]};
  std::vector<char> seen(in.size(), 0);
  std::vector<std::size_t> component;
  for(std::size_t seed = 0; seed < in.size(); ++seed)
  {
    if(in[seed] || outside[seed] || seen[seed])
      continue;
    component.assign(1, seed);
    seen[seed] = 1;
    bool enclosed = true;
    for(std::size_t head = 0; head < component.size(); ++head)
    {
      const std::size_t v = component[head];
      const std::size_t coordinate[3] = {v % stride[1], (v / stride[1]) % std::size_t(dims[1]), v / stride[2]};
      for(int axis = 0; axis < 3; ++axis)
        for(int side = -1; side <= 1; side += 2)
        {
          if((side < 0 && coordinate[axis] == 0) || (side > 0 && coordinate[axis] + 1 == std::size_t(dims[axis])))
          {
            enclosed = false; // the grid border
            continue;
          }
          const std::size_t w = side < 0 ? v - stride[axis] : v + stride[axis];
          if(outside[w])
            enclosed = false;
          else if(!in[w] && !seen[w])
          {
            seen[w] = 1;
            component.push_back(w);
          }
        }
    }
    if(enclosed)
      for(std::size_t v : component)
        in[v] = 1;
  }
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_MORPHOLOGY_H
