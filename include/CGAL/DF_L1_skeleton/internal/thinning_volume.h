// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_THINNING_VOLUME_H
#define CGAL_DF_L1_SKELETON_INTERNAL_THINNING_VOLUME_H

/// \file thinning_volume.h
/// The voxels the initial skeleton is thinned from: the closed interior, the depth
/// measured in the occupied voxels, and the parts thinner than two voxels. Not part of
/// the public API.

#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/internal/euclidean_distance_transform.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_morphology.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The solid that the curve graph is thinned from: the interior voxels, closed by one
// voxel (a dilation then an erosion by the 3x3x3 cube) and with enclosed cavities filled,
// but never taking an exterior or outlier voxel. Noise puts boundary voxels inside thin
// parts, and each such pit or tunnel would survive thinning as a small loop or shell;
// the holes of the shape are exterior voxels, so closing leaves them alone.
template <class Traits>
std::vector<char> shape_volume(const Distance_field<Traits>& df)
{
  std::vector<char> in(df.size()), outside(df.size());
  for(std::size_t v = 0; v < df.size(); ++v)
  {
    in[v] = df.labels[v] == Voxel_label::INTERIOR;
    outside[v] = df.labels[v] == Voxel_label::EXTERIOR || df.labels[v] == Voxel_label::OUTLIER;
  }
  std::vector<char> closed = in;
  cube_filter(closed, df.dims, true);
  cube_filter(closed, df.dims, false);
  for(std::size_t v = 0; v < df.size(); ++v)
    in[v] = in[v] || (closed[v] && !outside[v]);
  fill_cavities(in, outside, df.dims);
  return in;
}

// The distance (voxels) from every voxel to the nearest voxel that is not occupied
// (neither boundary nor interior): 0 outside the occupied voxels, 1 in their outer layer.
template <class Traits>
std::vector<float> occupied_depth(const Distance_field<Traits>& df)
{
  std::vector<float> depth = squared_distance_to_sites<CGAL::Parallel_if_available_tag>(
    df.dims, [&](std::size_t v) { return !Voxel_grid<Traits>::is_occupied(df.labels[v]); });
  for(float& d : depth)
    d = std::sqrt(d);
  return depth;
}

// The parts thinner than two voxels (twigs, the lower legs of a scanned animal): they
// have no skeleton voxel, so without them the curves stop where a limb gets that thin.
struct Thin_parts
{
  std::vector<char> voxels; // occupied voxels that may carry a curve and end it
  std::vector<char> solid;  // the voxels to add to the thinned solid: `voxels` and the
                            // occupied voxels that join them to the thick parts
  std::vector<float> depth; // in `solid`: the distance (voxels) to the nearest voxel
                            // that is not occupied, the depth the thin parts have
};

// The thick parts are the union of the balls of radius DT + `margin` centred on the
// voxels at least two voxels deep (`margin` takes in the boundary shell); it is one
// distance transform of the power of the balls, min over v of |u - v|^2 - R_v^2 <= 0.
// A thin part is a 26-connected component of the occupied voxels outside it that
// touches it and reaches `reach` voxels beyond it: a bump of the surface, a web between
// two limbs near their junction or a clump of outliers on the surface does not reach
// that far. A component that touches no thick part is a thin object of its own (a
// twig, a wire or a plate apart from the rest) when it spans `2 reach` voxels or more
// and is three voxels thick somewhere (a voxel two voxels from the unoccupied ones): a
// layer of points one or two voxels thick (a flat scan) encloses nothing.
template <class Traits>
Thin_parts thin_parts(const Distance_field<Traits>& df, double margin, double reach)
{
  typedef CGAL::Parallel_if_available_tag Tag; // the transforms do not depend on the threads
  const std::size_t n = df.size();
  std::vector<float> power(n, EDT_INFINITY);
  for(std::size_t v = 0; v < n; ++v)
    if(df.values[v] >= 2)
      power[v] = -float((df.values[v] + margin) * (df.values[v] + margin));
  squared_euclidean_distance_transform<Tag>(power, df.dims, 0.f); // only its sign is used
  std::vector<char> thick(n, 0), occupied(n, 0);
  bool outside_balls = false;
  for(std::size_t v = 0; v < n; ++v)
  {
    thick[v] = power[v] <= 0;
    occupied[v] = Voxel_grid<Traits>::is_occupied(df.labels[v]);
    outside_balls = outside_balls || (occupied[v] && !thick[v]);
  }
  Thin_parts result;
  result.voxels.assign(n, 0);
  result.solid.assign(n, 0);
  // The balls often cover every occupied voxel (smooth shapes): no thin part, and no
  // need for the transforms below.
  if(!outside_balls)
    return result;
  const std::vector<float> beyond = squared_distance_to_sites<Tag>(
    df.dims, [&](std::size_t v) { return thick[v]; }, float((std::max)(reach * reach, 3.0))); // compared with both
  result.depth = occupied_depth(df);
  bool any = false;
  for_each_26_component(df, [&](std::size_t v) { return occupied[v] && !thick[v]; },
                        [&](const std::vector<std::size_t>& component) {
    const bool far = std::any_of(component.begin(), component.end(),
                                 [&](std::size_t v) { return beyond[v] >= reach * reach; });
    const bool attached = std::any_of(component.begin(), component.end(), [&](std::size_t v) { return beyond[v] <= 3; });
    bool apart = false;
    if(!attached)
    {
      std::array<int, 3> lo = df.coordinates(component.front()), hi = lo;
      for(std::size_t v : component)
      {
        const std::array<int, 3> c = df.coordinates(v);
        for(int d = 0; d < 3; ++d)
        {
          lo[d] = (std::min)(lo[d], c[d]);
          hi[d] = (std::max)(hi[d], c[d]);
        }
      }
      apart = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) + 1 >= 2 * reach &&
              std::any_of(component.begin(), component.end(), [&](std::size_t v) { return result.depth[v] >= 2; });
    }
    if(far && (attached || apart))
      for(std::size_t v : component)
        result.voxels[v] = any = 1;
  });
  if(!any)
    return result;
  // The occupied voxels within margin + 1 of a thin part join it to the thick solid
  // across the shell that the balls cover.
  const std::vector<float> near = squared_distance_to_sites<Tag>(
    df.dims, [&](std::size_t v) { return result.voxels[v]; }, float((margin + 1) * (margin + 1)));
  for(std::size_t v = 0; v < n; ++v)
    result.solid[v] = occupied[v] && near[v] <= (margin + 1) * (margin + 1);
  return result;
}


} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_THINNING_VOLUME_H
