// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_REMOVE_OUTLIER_VOXELS_H
#define CGAL_DF_L1_SKELETON_REMOVE_OUTLIER_VOXELS_H

/// \file remove_outlier_voxels.h
/// Stage 2 (paper, end of section 4): removal of scattered boundary voxels.

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// What `remove_outlier_voxels()` found.
struct Outlier_voxel_statistics
{
  std::size_t components_kept = 0;    ///< 26-connected parts of the shape kept
  std::size_t components_removed = 0; ///< scattered voxel clusters removed
  std::size_t voxels_removed = 0;     ///< boundary voxels relabelled `Voxel_label::OUTLIER`
};

/// \ingroup PkgDFL1SkeletonRef
/// Removes the scattered boundary voxels made by outliers (paper, section 4).
///
/// The paper removes the boundary voxels into which the distance field does not
/// propagate: voxels that hold outliers are disconnected from the volume. We make that
/// precise with the 26-connected components of the occupied (boundary and interior)
/// voxels: a component that holds an interior voxel is a part of the shape and is kept,
/// whatever its size, so the separate parts of a scene each keep their own component.
/// A component without interior voxels is removed when its bounding box spans at most
/// `outlier_component_size` voxels along every axis; a longer one (a thin wire or a
/// flat sheet too thin to have an interior at this resolution) is kept.
///
/// \tparam Traits a model of `Kernel`
/// \param grid the grid made by `voxelize_point_set()`
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{outlier_component_size}
///     \cgalParamDescription{the largest extent, in voxels, of a removable component}
///     \cgalParamType{`int`, in [0, 2^20]}
///     \cgalParamDefault{max(3, V / 10), V the longest side of the grid in voxels}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \param statistics if not null, receives what was found
/// \returns a copy of `grid` where the removed voxels are labelled `Voxel_label::OUTLIER`
template <class Traits, class NamedParameters = parameters::Default_named_parameters>
Voxel_grid<Traits> remove_outlier_voxels(const Voxel_grid<Traits>& grid,
                                         const NamedParameters& np = parameters::default_values(),
                                         Outlier_voxel_statistics* statistics = nullptr)
{
  const int max_extent = internal::outlier_component_size(np, grid.dims, "outlier removal");

  Voxel_grid<Traits> result = grid;
  Outlier_voxel_statistics stats;
  internal::for_each_26_component(grid, [&](std::size_t v) { return Voxel_grid<Traits>::is_occupied(grid.labels[v]); },
                                  [&](const std::vector<std::size_t>& component) {
    bool has_interior = false;
    std::array<int, 3> lo = grid.coordinates(component.front()), hi = lo;
    for(std::size_t v : component)
    {
      has_interior = has_interior || grid.labels[v] == Voxel_label::INTERIOR;
      const std::array<int, 3> c = grid.coordinates(v);
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = (std::min)(lo[a], c[a]);
        hi[a] = (std::max)(hi[a], c[a]);
      }
    }
    const int extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) + 1;
    if(has_interior || extent > max_extent)
    {
      ++stats.components_kept;
      return;
    }
    ++stats.components_removed;
    stats.voxels_removed += component.size();
    for(std::size_t v : component)
      result.labels[v] = Voxel_label::OUTLIER;
  });
  if(statistics != nullptr)
    *statistics = stats;
  return result;
}

/// \ingroup PkgDFL1SkeletonRef
/// Flags the points that fall in voxels removed by `remove_outlier_voxels()` (or
/// outside the grid).
/// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
/// \param points the points to classify
/// \param grid the grid returned by `remove_outlier_voxels()`
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<Traits::Point_3>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns one flag per point, `true` for an outlier
template <class PointRange, class Traits, class NamedParameters = parameters::Default_named_parameters>
std::vector<bool> flag_outlier_points(const PointRange& points, const Voxel_grid<Traits>& grid,
                                      const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  std::vector<bool> flags;
  for(const auto& value : points)
  {
    const std::array<int, 3> c = grid.locate(get(point_map, value));
    // A point on the grid's far face belongs to the last voxel.
    bool inside = true;
    std::array<int, 3> cc = c;
    for(int a = 0; a < 3; ++a)
    {
      if(cc[a] == grid.dims[a])
        --cc[a];
      inside = inside && cc[a] >= 0 && cc[a] < grid.dims[a];
    }
    flags.push_back(!inside || !Voxel_grid<Traits>::is_occupied(grid.label(cc[0], cc[1], cc[2])));
  }
  return flags;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_REMOVE_OUTLIER_VOXELS_H
