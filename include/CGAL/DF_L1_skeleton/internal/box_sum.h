// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_BOX_SUM_H
#define CGAL_DF_L1_SKELETON_INTERNAL_BOX_SUM_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Summed-volume table: the sum of any axis-aligned box of a 3D array in 8 lookups,
// whatever the box size. This makes the 26/124/342-neighbour means of the thinning
// stage cost the same, instead of 27, 125 and 343 reads per voxel.
class Box_sum
{
public:
  Box_sum(const std::vector<float>& values, const std::array<int, 3>& dims)
    : nx_(dims[0] + 1), ny_(dims[1] + 1), nz_(dims[2] + 1), dims_(dims),
      table_(std::size_t(nx_) * ny_ * nz_, 0.0)
  {
    for(int k = 0; k < dims[2]; ++k)
      for(int j = 0; j < dims[1]; ++j)
      {
        double row = 0;
        for(int i = 0; i < dims[0]; ++i)
        {
          row += values[(std::size_t(k) * dims[1] + j) * dims[0] + i];
          at(i + 1, j + 1, k + 1) = row + at(i + 1, j, k + 1) + at(i + 1, j + 1, k) - at(i + 1, j, k);
        }
      }
  }

  // Sum over the cube of half-width r around voxel (i,j,k), clipped to the grid.
  double cube(int i, int j, int k, int r) const
  {
    const int i0 = (std::max)(i - r, 0), i1 = (std::min)(i + r + 1, dims_[0]);
    const int j0 = (std::max)(j - r, 0), j1 = (std::min)(j + r + 1, dims_[1]);
    const int k0 = (std::max)(k - r, 0), k1 = (std::min)(k + r + 1, dims_[2]);
    return at(i1, j1, k1) - at(i0, j1, k1) - at(i1, j0, k1) - at(i1, j1, k0) + at(i0, j0, k1) +
           at(i0, j1, k0) + at(i1, j0, k0) - at(i0, j0, k0);
  }

private:
  double& at(int i, int j, int k) { return table_[(std::size_t(k) * ny_ + j) * nx_ + i]; }
  double at(int i, int j, int k) const { return table_[(std::size_t(k) * ny_ + j) * nx_ + i]; }

  int nx_, ny_, nz_;
  std::array<int, 3> dims_;
  std::vector<double> table_;
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_BOX_SUM_H
