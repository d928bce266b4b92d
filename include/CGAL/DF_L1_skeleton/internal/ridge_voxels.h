// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_RIDGE_VOXELS_H
#define CGAL_DF_L1_SKELETON_INTERNAL_RIDGE_VOXELS_H

/// \file ridge_voxels.h
/// The ridge voxels of the distance field (Eq. 2) and the test of whether a voxel may end
/// a curve of the initial skeleton. Not part of the public API.

#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/Initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/internal/box_sum.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The ridge voxels of Eq. 2 in `values`: at least two voxels deep, and deeper by TP_s
// than the mean over their 26, 124 and 342 neighbours (s = 1, 2, 3), where TP_s is c
// times the mean of that difference over the voxels of positive value. Fills
// `result.voxels`, `result.points`, `result.thinning_parameters` and the flags `in`;
// false when no voxel has a positive value.
template <class Traits>
bool ridge_voxels(const Distance_field<Traits>& field, const std::vector<float>& values, double c,
                  Initial_skeleton<Traits>& result, std::vector<char>& in)
{
  const Box_sum sums(values, field.dims);
  const int radii[3] = {1, 2, 3};
  const double counts[3] = {26, 124, 342};

  // Mean of DT - MNT_k over the interior voxels, for the three thresholds.
  double mean_gap[3] = {0, 0, 0};
  std::size_t interior = 0;
  for(int k = 0; k < field.dims[2]; ++k)
    for(int j = 0; j < field.dims[1]; ++j)
      for(int i = 0; i < field.dims[0]; ++i)
      {
        const float dt = values[field.index(i, j, k)];
        if(dt <= 0)
          continue;
        ++interior;
        for(int s = 0; s < 3; ++s)
          mean_gap[s] += dt - (sums.cube(i, j, k, radii[s]) - dt) / counts[s];
      }
  if(interior == 0)
    return false;
  for(int s = 0; s < 3; ++s)
    result.thinning_parameters[s] = c * std::abs(mean_gap[s] / double(interior));

  in.assign(field.size(), 0);
  for(int k = 0; k < field.dims[2]; ++k)
    for(int j = 0; j < field.dims[1]; ++j)
      for(int i = 0; i < field.dims[0]; ++i)
      {
        const std::size_t v = field.index(i, j, k);
        const float dt = values[v];
        // One voxel deep is what a flat, linear or noisy sheet of points encloses
        // between its samples: no volume, no skeleton.
        if(dt < 2)
          continue;
        bool ridge = true;
        for(int s = 0; s < 3 && ridge; ++s)
          ridge = (sums.cube(i, j, k, radii[s]) - dt) / counts[s] < dt - result.thinning_parameters[s];
        if(ridge)
        {
          in[v] = 1;
          result.voxels.push_back(v);
          result.points.push_back(field.center(v));
        }
      }
  return true;
}

// Maxima of the distance field over blocks of 4x4x4 voxels, so that the maximum over a
// large window costs a few block reads; a small window may be read voxel by voxel.
class Block_maximum
{
public:
  static constexpr int block = 4;

  // `values`: one value per voxel of the grid of `df`
  template <class Traits>
  Block_maximum(const Distance_field<Traits>& df, const std::vector<float>& values)
    : values_(&values), grid_{{df.dims[0], df.dims[1], df.dims[2]}}
  {
    for(int a = 0; a < 3; ++a)
      dims_[a] = (df.dims[a] + block - 1) / block;
    maxima_.assign(std::size_t(dims_[0]) * dims_[1] * dims_[2], 0.f);
    for(int k = 0; k < df.dims[2]; ++k)
      for(int j = 0; j < df.dims[1]; ++j)
        for(int i = 0; i < df.dims[0]; ++i)
        {
          float& m = maxima_[index(i / block, j / block, k / block)];
          m = (std::max)(m, values[df.index(i, j, k)]);
        }
  }

  // The maximum over the blocks that meet the voxel box [lo, hi] (inclusive), or with
  // `exact` over the box itself: the blocks widen a box by up to 3 voxels a side.
  float over(const std::array<int, 3>& lo, const std::array<int, 3>& hi, bool exact = false) const
  {
    if(exact)
    {
      float m = 0;
      for(int k = (std::max)(0, lo[2]); k <= (std::min)(grid_[2] - 1, hi[2]); ++k)
        for(int j = (std::max)(0, lo[1]); j <= (std::min)(grid_[1] - 1, hi[1]); ++j)
          for(int i = (std::max)(0, lo[0]); i <= (std::min)(grid_[0] - 1, hi[0]); ++i)
            m = (std::max)(m, (*values_)[(std::size_t(k) * grid_[1] + j) * grid_[0] + i]);
      return m;
    }
    std::array<int, 3> a, b;
    for(int d = 0; d < 3; ++d)
    {
      a[d] = (std::max)(0, lo[d]) / block;
      b[d] = (std::min)(dims_[d] * block - 1, hi[d]) / block;
    }
    float m = 0;
    for(int k = a[2]; k <= b[2]; ++k)
      for(int j = a[1]; j <= b[1]; ++j)
        for(int i = a[0]; i <= b[0]; ++i)
          m = (std::max)(m, maxima_[index(i, j, k)]);
    return m;
  }

private:
  std::size_t index(int i, int j, int k) const { return (std::size_t(k) * dims_[1] + j) * dims_[0] + i; }
  const std::vector<float>* values_;
  std::array<int, 3> grid_;
  std::array<int, 3> dims_;
  std::vector<float> maxima_;
};

// Whether a voxel may end a curve: its radius is at least `ratio` times the largest
// radius within about twice its depth (the blocks that meet that cube), the radius being
// the depth plus `to_radius`. The end of a real branch sits near the centre of the ball
// that caps it, where the depth peaks; the noise of the surface raises ridge voxels a few
// voxels deep on the slope of a much deeper field, and a curve ending there would be a
// spur. With `exact` (parts one or two voxels deep) the cube itself is read, at least 3
// voxels a side as the widest neighbourhood of the ridge test: the blocks would stretch a
// window of 2 to 4 voxels to 5 to 7, and the tip of a twig five voxels out of a thicker
// branch would be measured against the branch. Depths measured in the occupied voxels
// less one are half a voxel short of the radius (`to_radius` 0.5): as a ratio of such
// depths, a twig tip 1.4 voxels deep beside a voxel 2 deep read 0.4 / 1 and never ended.
template <class Traits>
bool is_deep_end(const Distance_field<Traits>& df, const std::vector<float>& depth, const Block_maximum& maxima,
                 std::size_t v, double ratio, bool exact = false, double to_radius = 0)
{
  const std::array<int, 3> c = df.coordinates(v);
  const int r = exact ? (std::max)(3, int(std::ceil(2 * depth[v]))) : int(std::ceil(2 * depth[v]));
  const float deepest = maxima.over({{c[0] - r, c[1] - r, c[2] - r}}, {{c[0] + r, c[1] + r, c[2] + r}}, exact);
  return depth[v] + to_radius >= ratio * (deepest + to_radius);
}


} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_RIDGE_VOXELS_H
