// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_VOXEL_GRID_H
#define CGAL_DF_L1_SKELETON_VOXEL_GRID_H

/// \file Voxel_grid.h
/// The labelled voxel grid produced by `voxelize_point_set()`.

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The label of a voxel.
enum class Voxel_label : std::uint8_t
{
  EXTERIOR = 0, ///< outside the shape, reached by the flood fill from the grid border
  BOUNDARY = 1, ///< contains at least one point
  INTERIOR = 2, ///< enclosed by boundary voxels
  OUTLIER = 3   ///< a boundary voxel removed by `remove_outlier_voxels()`; behaves as exterior
};

/// \ingroup PkgDFL1SkeletonRef
/// The geometry of an axis-aligned regular grid: voxel `(i,j,k)` is the cube
/// `origin + [i,i+1] x [j,j+1] x [k,k+1] * voxel_size`; linear indices run with `i` fastest.
/// \tparam Traits a model of `Kernel`
template <class Traits>
struct Grid_geometry
{
  typedef typename Traits::FT FT;           ///< number type
  typedef typename Traits::Point_3 Point_3; ///< point type

  Point_3 origin = Point_3(0, 0, 0); ///< lower corner of voxel (0,0,0)
  FT voxel_size = 1;                 ///< edge length of a voxel, in input units
  std::array<int, 3> dims = {{0, 0, 0}}; ///< number of voxels along x, y, z

  /// number of voxels
  std::size_t size() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }
  /// linear index of voxel `(i,j,k)`
  std::size_t index(int i, int j, int k) const
  {
    return (std::size_t(k) * dims[1] + j) * dims[0] + i;
  }
  /// grid coordinates of the voxel with linear index `v`
  std::array<int, 3> coordinates(std::size_t v) const
  {
    const std::size_t plane = std::size_t(dims[0]) * dims[1];
    return {{int(v % dims[0]), int((v % plane) / dims[0]), int(v / plane)}};
  }
  /// whether `(i,j,k)` is a voxel of the grid
  bool contains(int i, int j, int k) const
  {
    return i >= 0 && j >= 0 && k >= 0 && i < dims[0] && j < dims[1] && k < dims[2];
  }
  /// centre of voxel `(i,j,k)`
  Point_3 center(int i, int j, int k) const
  {
    return Point_3(origin.x() + (i + FT(0.5)) * voxel_size,
                   origin.y() + (j + FT(0.5)) * voxel_size,
                   origin.z() + (k + FT(0.5)) * voxel_size);
  }
  /// centre of the voxel with linear index `v`
  Point_3 center(std::size_t v) const
  {
    const std::array<int, 3> c = coordinates(v);
    return center(c[0], c[1], c[2]);
  }
  /// grid coordinates of the voxel that contains `p` (possibly outside the grid)
  std::array<int, 3> locate(const Point_3& p) const
  {
    return {{int(std::floor(CGAL::to_double((p.x() - origin.x()) / voxel_size))),
             int(std::floor(CGAL::to_double((p.y() - origin.y()) / voxel_size))),
             int(std::floor(CGAL::to_double((p.z() - origin.z()) / voxel_size)))}};
  }
};

/// \ingroup PkgDFL1SkeletonRef
/// Statistics of one refinement level of the multi-scale voxelization.
struct Voxelization_level
{
  double voxel_size = 0;                 ///< voxel edge length at this level
  std::array<int, 3> dims = {{0, 0, 0}}; ///< grid size at this level (after cropping)
  std::size_t boundary = 0; ///< number of boundary voxels
  std::size_t interior = 0; ///< number of interior voxels
  std::size_t exterior = 0; ///< number of exterior voxels
};

/// \ingroup PkgDFL1SkeletonRef
/// A labelled voxel grid: the result of `voxelize_point_set()`, refined by
/// `remove_outlier_voxels()`. The grid always has at least one exterior voxel layer
/// around the occupied voxels, and enough margin for 7x7x7 neighbourhoods.
/// \tparam Traits a model of `Kernel`
template <class Traits>
class Voxel_grid : public Grid_geometry<Traits>
{
public:
  /// one label per voxel, indexed like `Grid_geometry::index()`
  std::vector<Voxel_label> labels;
  /// the coarse-to-fine levels of the voxelization that made the grid
  std::vector<Voxelization_level> levels;

  /// label of voxel `(i,j,k)`; voxels outside the grid are exterior
  Voxel_label label(int i, int j, int k) const
  {
    return this->contains(i, j, k) ? labels[this->index(i, j, k)] : Voxel_label::EXTERIOR;
  }
  /// whether the voxel belongs to the shape (boundary or interior)
  static bool is_occupied(Voxel_label l)
  {
    return l == Voxel_label::BOUNDARY || l == Voxel_label::INTERIOR;
  }
  /// number of voxels with label `l`
  std::size_t count(Voxel_label l) const
  {
    std::size_t n = 0;
    for(Voxel_label x : labels)
      n += (x == l);
    return n;
  }
};

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_VOXEL_GRID_H
