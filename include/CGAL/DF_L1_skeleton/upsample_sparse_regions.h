// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_UPSAMPLE_SPARSE_REGIONS_H
#define CGAL_DF_L1_SKELETON_UPSAMPLE_SPARSE_REGIONS_H

/// \file upsample_sparse_regions.h
/// Stage 0 (paper, sections 4 and 7): upsampling of sparsely sampled regions.

#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Inserts points in the sparsely sampled regions of a point cloud (paper, sections 4
/// and 7), so that the voxelization sees a closed boundary there.
///
/// The density at q_i is rho_i = k / r_i^3, r_i the radius of the smallest ball around
/// q_i holding its k nearest neighbours; q_i is sparse when rho_i < k / r^3, that is when
/// fewer than k other points lie within r. The paper's defaults are k = 5 and
/// r = 3 d_bb / cbrt(N). Around a sparse point, the search radius grows (x1.5, at most
/// three times) until it holds 3 neighbours, and points are inserted by linear
/// interpolation along the segments to its sparse neighbours, spaced by the finest
/// voxel size (longest bbox side / V) as the paper suggests ("denser than the
/// threshold, to facilitate the voxelization").
///
/// Only pairs of sparse points are joined. The paper is silent here, but joining an
/// isolated outlier to the dense surface next to it would glue the outlier to the shape
/// and defeat `remove_outlier_voxels()`; a sparse region next to a dense one needs no
/// bridge, the dense side already closes the voxel boundary.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`: the density test runs in parallel
/// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
/// \tparam OutputIterator an output iterator accepting `Point_3`
/// \param points the input points
/// \param output receives the inserted points (the input is not changed)
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
///   \cgalParamNBegin{upsampling_neighbors}
///     \cgalParamDescription{k of the density k / r^3}
///     \cgalParamType{`int`, in [1, 64]}
///     \cgalParamDefault{5}
///   \cgalParamNEnd
///   \cgalParamNBegin{upsampling_radius}
///     \cgalParamDescription{r of the density k / r^3, in input units}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{3 d_bb / cbrt(N), N the number of points}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxel_resolution}
///     \cgalParamDescription{V; the spacing of inserted points is the longest bbox side / V}
///     \cgalParamType{`int`, in [3, 2048]}
///     \cgalParamDefault{100}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the output iterator past the last inserted point
/// \throws Invalid_input for an empty range, a non-finite coordinate or a bad parameter
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
OutputIterator upsample_sparse_regions(const PointRange& points, OutputIterator output,
                                       const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Traits;
  typedef typename Traits::Point_3 Point_3;

  const auto point_map = NP_helper::get_const_point_map(points, np);
  const CGAL::Bbox_3 box = internal::checked_bbox(points, point_map, "upsampling");
  const std::vector<std::array<double, 3>> xyz = internal::to_xyz(points, point_map);
  const std::size_t n = xyz.size();
  const double diagonal = internal::diagonal(box);
  if(n < 2 || !(diagonal > 0))
    return output; // nothing to interpolate between

  const int k = internal::upsampling_neighbors(np, "upsampling");
  const double r = internal::upsampling_radius(np, diagonal, n, "upsampling");
  const int V = internal::voxel_resolution(np, "upsampling");
  const double spacing = internal::longest_side(box) / V;

  // Cells of r/4: in a dense region the query's own cell holds more than k points, so
  // the test reads one cell. With cells of r it scanned hundreds of points per query
  // at a million points (r grows like n^(1/6) against the spacing).
  std::vector<char> sparse(n, 0);
  {
    const internal::Uniform_grid fine(xyz, r / 4);
    const std::vector<std::size_t>& by_cell = fine.indices_by_cell();
    internal::for_each_index<ConcurrencyTag>(
      n, [&](std::size_t q) { sparse[by_cell[q]] = !fine.has_at_least(xyz[by_cell[q]], r, std::size_t(k) + 1); }, 1024);
  }
  if(std::find(sparse.begin(), sparse.end(), 1) == sparse.end())
    return output;
  const internal::Uniform_grid grid(xyz, r);

  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::vector<std::size_t> neighbours;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!sparse[i])
      continue;
    double radius = r;
    for(int growth = 0; growth <= 3; ++growth, radius *= 1.5)
    {
      neighbours.clear();
      grid.for_each_in_ball(xyz[i], radius, [&](std::size_t j, double) {
        if(j != i)
          neighbours.push_back(j);
        return true;
      });
      if(neighbours.size() >= 3)
        break;
    }
    if(neighbours.size() < 3)
      continue; // an isolated point: nothing to interpolate with
    for(std::size_t j : neighbours)
      if(sparse[j])
        pairs.emplace_back((std::min)(i, j), (std::max)(i, j));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  for(const auto& pair : pairs)
  {
    const std::array<double, 3>& a = xyz[pair.first];
    const std::array<double, 3>& b = xyz[pair.second];
    const double length = std::sqrt(CGAL::square(a[0] - b[0]) + CGAL::square(a[1] - b[1]) +
                                    CGAL::square(a[2] - b[2]));
    const int segments = int(std::ceil(length / spacing));
    for(int s = 1; s < segments; ++s)
    {
      const double t = double(s) / segments;
      *output++ = Point_3(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]));
    }
  }
  return output;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_UPSAMPLE_SPARSE_REGIONS_H
