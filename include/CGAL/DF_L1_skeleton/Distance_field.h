// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_DISTANCE_FIELD_H
#define CGAL_DF_L1_SKELETON_DISTANCE_FIELD_H

/// \file Distance_field.h
/// The result of `compute_distance_field()`: the distance of every voxel to the shape's
/// boundary.

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// For every voxel of a grid, the Euclidean distance from its centre to the centre of
/// the nearest voxel that is not interior: 0 on boundary, exterior and outlier voxels.
/// \tparam Traits a model of `Kernel`
template <class Traits>
class Distance_field : public Grid_geometry<Traits>
{
public:
  typedef typename Traits::FT FT;           ///< number type
  typedef typename Traits::Point_3 Point_3; ///< point type

  /// distance of each voxel, in voxel units
  std::vector<float> values;
  /// the labels of the grid the field was computed from (later stages need to know
  /// which voxels are exterior, not only which have distance 0)
  std::vector<Voxel_label> labels;

  /// distance of the voxel with linear index `v`, in input units
  FT distance(std::size_t v) const { return FT(values[v]) * this->voxel_size; }

  /// distance of the voxel that contains `p`, in input units; 0 outside the grid
  FT value_at(const Point_3& p) const
  {
    const std::array<int, 3> c = this->locate(p);
    return this->contains(c[0], c[1], c[2]) ? distance(this->index(c[0], c[1], c[2])) : FT(0);
  }

  /// largest distance, in voxel units
  float maximum() const
  {
    float m = 0;
    for(float x : values)
      m = (std::max)(m, x);
    return m;
  }
};

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_DISTANCE_FIELD_H
