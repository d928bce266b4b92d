// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_VOXELIZE_POINT_SET_H
#define CGAL_DF_L1_SKELETON_VOXELIZE_POINT_SET_H

/// \file voxelize_point_set.h
/// Stage 1 (paper, section 4): multi-scale voxelization of an unoriented point cloud.

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/exterior_sweep.h>
#include <CGAL/DF_L1_skeleton/internal/lines_of_sight.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/sampling_spacing.h>
#include <CGAL/DF_L1_skeleton/internal/voted_interior.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_refinement.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Voxelizes a point cloud into boundary, interior and exterior voxels (paper, section 4).
///
/// The coarsest grid has voxels of size about s0 = d_bb / 9, coarse enough for the points
/// to close the surface over small holes; each level splits every voxel into 3x3x3 until
/// the longest side of the bounding box spans V voxels. Boundary voxels hold points, the
/// exterior is flooded from the grid border and the rest is interior. Where the paper is
/// loose we are exact: s0 is rounded down so that the finest grid has exactly V voxels;
/// the exterior spreads through face neighbours, which cannot slip diagonally through a
/// one-voxel shell; the concave regions that a coarse level saw enclosed are swept by two
/// balls rolled in from the exterior, after a parity vote along the 26 grid directions
/// has said what lies inside a scan with a missing flank; crotches narrower than the balls
/// (between the twigs of a tree) open where their voxels see the exterior along lines of
/// sight. The rules and their measurements: \ref design_voxelization.
///
/// The returned grid is cropped to the occupied voxels plus a margin of 4 exterior
/// voxels (room for the 7x7x7 neighbourhoods of the thinning).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag` (the distance transforms of the sweep)
/// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
/// \tparam NamedParameters a sequence of CGAL named parameters
///
/// \param points the input points (together with the points added by `upsample_sparse_regions()`)
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of
///       the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxel_resolution}
///     \cgalParamDescription{V, the number of voxels along the longest side of the bounding box}
///     \cgalParamType{`int`, in [3, 2048]}
///     \cgalParamDefault{100}
///   \cgalParamNEnd
///   \cgalParamNBegin{initial_voxel_size}
///     \cgalParamDescription{s0, the size of the coarsest voxels before rounding, in input units}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{d_bb / 9, d_bb the diagonal of the bounding box}
///   \cgalParamNEnd
///   \cgalParamNBegin{open_crotches}
///     \cgalParamDescription{whether the interior voxels that see the exterior along 10 or more grid
///       directions are opened; `DF_L1_skeletonization` turns it off for the clouds it smoothed, whose
///       ragged shell lets the lines of sight into the surface layer}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{local_shell_bands}
///     \cgalParamDescription{whether the shell of dilated boundary voxels that the parity vote and the lines of
///       sight cross is dilated by the local sampling spacing (half the distance from a point of the voxel to
///       its 6th nearest neighbour, at least the global band, at most half the coarsest voxel) rather than by
///       one band for the whole cloud; `DF_L1_skeletonization` turns it off for the clouds it smoothed, whose
///       scattered residual points would thicken the shell across the crotches}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{exterior_propagation_steps}
///     \cgalParamDescription{neighbour steps of the exterior inside boundary voxels at each level
///       (the paper takes one)}
///     \cgalParamType{`int`, in [1, 27]}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the labelled grid, with one `Voxelization_level` per level
/// \throws Invalid_input if `points` is empty, holds a non-finite coordinate, all its
///         points coincide, or a parameter is out of range
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange,
          class NamedParameters = parameters::Default_named_parameters>
Voxel_grid<typename Point_set_processing_3_np_helper<const PointRange, NamedParameters>::Geom_traits>
voxelize_point_set(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Traits;
  typedef typename Traits::Point_3 Point_3;

  const auto point_map = NP_helper::get_const_point_map(points, np);
  const CGAL::Bbox_3 box = internal::checked_bbox(points, point_map, "voxelization");
  const double longest = internal::longest_side(box);
  if(!(longest > 0))
    throw Invalid_input("voxelization: all points coincide, there is no shape to voxelize");
  const int V = internal::voxel_resolution(np, "voxelization");
  const double s0 = internal::initial_voxel_size(np, internal::diagonal(box), "voxelization");
  const int steps = internal::exterior_propagation_steps(np, "voxelization");
  const bool open_crotches =
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_open_crotches), true);
  const bool local_bands =
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_local_shell_bands), true);

  const double finest = longest / V;
  // Rounded down: a coarsest level coarser than s0 would enclose more empty space.
  const int refinements = (std::max)(0, int(std::floor(std::log(s0 / finest) / std::log(3.0) + 1e-9)));

  const std::vector<std::array<double, 3>> xyz = internal::to_xyz(points, point_map);

  // Coarsest grid, centred on the bounding box with one empty layer around it.
  Grid_geometry<Traits> g;
  g.voxel_size = finest * std::pow(3.0, refinements);
  const double extent[3] = {box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()};
  const double centre[3] = {(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                            (box.zmin() + box.zmax()) / 2};
  double origin[3];
  for(int a = 0; a < 3; ++a)
  {
    g.dims[a] = (std::max)(1, int(std::ceil(extent[a] / CGAL::to_double(g.voxel_size) - 1e-9))) + 2;
    origin[a] = centre[a] - g.dims[a] * CGAL::to_double(g.voxel_size) / 2;
  }
  g.origin = Point_3(origin[0], origin[1], origin[2]);

  std::vector<std::uint8_t> labels(g.size(), std::uint8_t(Voxel_label::INTERIOR));
  internal::mark_points(g, labels, xyz);
  internal::flood_exterior(g, labels);

  Voxel_grid<Traits> result;
  result.levels.push_back(internal::level_statistics(g, labels));
  // The sampling spacing h (in finest voxels) for the correction after the last level,
  // measured on the second thread while the levels refine (it reads only the points).
  // The search radius starts at half a voxel and doubles until the ball holds 6 points
  // (the distance found does not depend on it): a first radius of 2 voxels gathered
  // thousands of points per ball in dense clouds (1M points: about 1 s).
  double h = 0;
  std::unique_ptr<internal::Uniform_grid> point_grid; // kept for the local bands of the shell
  internal::run_both<ConcurrencyTag>(
    [&] {
      for(int level = 0; level < refinements; ++level)
      {
        internal::crop(g, labels, 1);
        internal::refine(g, labels, xyz, steps);
        result.levels.push_back(internal::level_statistics(g, labels));
      }
    },
    [&] {
      if(refinements > 0 && xyz.size() > 6)
      {
        point_grid = std::make_unique<internal::Uniform_grid>(xyz, finest / 2);
        h = internal::median_kth_neighbour_distance(xyz, 6, finest / 2, *point_grid) / finest;
        if(!local_bands)
          point_grid.reset();
      }
    });
  if(refinements > 0)
  {
    // Radii in finest voxels. s0' = 3^refinements.
    const double coarsest = std::pow(3.0, refinements);
    const double large = (std::max)(coarsest, 2 * h), small = (std::max)(coarsest / 2, h);
    const double small_ball_volume = 4.0 / 3.0 * 3.14159265358979 * small * small * small;
    const double band = (std::max)(1.0, h / 2);
    const std::vector<char> shell =
      point_grid ? internal::boundary_shell(
                     g, labels, internal::local_shell_bands<ConcurrencyTag>(g, labels, xyz, *point_grid, band, coarsest / 2))
                 : internal::boundary_shell(g, labels, band);
    point_grid.reset();
    const std::vector<char> inside =
      internal::voted_interior<ConcurrencyTag>(g, labels, shell, band, small_ball_volume);
    internal::sweep_exterior_with_balls<ConcurrencyTag>(g, labels, inside, large, small, 3 * large);
    // Crotches narrower than the small ball: the lines of sight through them, which stop
    // at the same shell (the sweep leaves the boundary voxels as they were).
    if(open_crotches)
      internal::open_lines_of_sight(g, labels, inside, shell, 10, 2);
    result.levels.back() = internal::level_statistics(g, labels);
  }
  internal::crop(g, labels, 4);
  // Cropping moved the origin; re-marking with the final origin guarantees that every
  // point lies in a boundary voxel of the returned grid despite rounding.
  internal::mark_points(g, labels, xyz);
  result.levels.back() = internal::level_statistics(g, labels);

  static_cast<Grid_geometry<Traits>&>(result) = g;
  result.labels.resize(labels.size());
  std::transform(labels.begin(), labels.end(), result.labels.begin(),
                 [](std::uint8_t l) { return Voxel_label(l); });
  return result;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_VOXELIZE_POINT_SET_H
