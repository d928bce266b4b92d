// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOTED_INTERIOR_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOTED_INTERIOR_H

/// \file voted_interior.h
/// The shell of dilated boundary voxels and the voxels that a parity vote across it puts
/// inside the shape, whatever the flood fill said. Not part of the public API.

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/internal/euclidean_distance_transform.h>
#include <CGAL/DF_L1_skeleton/internal/face_connected_growth.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/parity_vote.h>
#include <CGAL/DF_L1_skeleton/internal/sampling_spacing.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_morphology.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_refinement.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Per voxel, the band of boundary_shell(): at a boundary voxel, half the distance
// (voxels) from its first point to that point's 6th nearest neighbour, the local
// sampling spacing, kept within [band, max(band, cap)]; `band` elsewhere. A scan's
// sampling is rarely even (the large triangles of a mesh on a body, the occlusions of a
// crown): with one band for all, the sparse regions leave gaps that the rays and the
// lines of sight pass through, and their inside is lost. `grid` holds `xyz`.
template <class ConcurrencyTag, class Traits>
std::vector<float> local_shell_bands(const Grid_geometry<Traits>& g, const std::vector<std::uint8_t>& labels,
                                     const std::vector<std::array<double, 3>>& xyz, const Uniform_grid& grid,
                                     double band, double cap)
{
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  const double voxel = CGAL::to_double(g.voxel_size);
  std::vector<std::size_t> first(g.size(), none);
  for(std::size_t i = 0; i < xyz.size(); ++i)
  {
    const std::size_t v = voxel_of_point(g, xyz[i]); // the voxel that mark_points() marked
    if(labels[v] == std::uint8_t(Voxel_label::BOUNDARY) && first[v] == none)
      first[v] = i;
  }
  std::vector<std::size_t> voxels, queries;
  for(std::size_t v = 0; v < first.size(); ++v)
    if(first[v] != none)
    {
      voxels.push_back(v);
      queries.push_back(first[v]);
    }
  const std::vector<double> spacing = kth_neighbour_distances<ConcurrencyTag>(xyz, queries, 6, voxel / 2, grid);
  std::vector<float> bands(g.size(), float(band));
  const double most = (std::max)(band, cap);
  for(std::size_t q = 0; q < voxels.size(); ++q)
    bands[voxels[q]] = float(std::clamp(spacing[q] / voxel / 2, band, most));
  return bands;
}

// The boundary voxels, each dilated by its own band (voxels; `band` is read at the
// boundary voxels): the shell closes the gaps of a sparse region without thickening it
// where the samples are dense.
template <class Traits>
std::vector<char> boundary_shell(const Grid_geometry<Traits>& g, const std::vector<std::uint8_t>& labels,
                                 const std::vector<float>& band)
{
  // Voxel offsets have integer squared lengths: bands with the same floor(band^2) give
  // the same ball, so the boundary voxels dilate in a few groups.
  std::vector<int> radii2;
  for(std::size_t v = 0; v < labels.size(); ++v)
    if(labels[v] == std::uint8_t(Voxel_label::BOUNDARY))
      radii2.push_back(int(float(band[v] * band[v]) + 1e-3f));
  std::sort(radii2.begin(), radii2.end());
  radii2.erase(std::unique(radii2.begin(), radii2.end()), radii2.end());
  std::vector<char> shell(labels.size(), 0), group(labels.size());
  for(int r2 : radii2)
  {
    for(std::size_t v = 0; v < labels.size(); ++v)
      group[v] = labels[v] == std::uint8_t(Voxel_label::BOUNDARY) && int(float(band[v] * band[v]) + 1e-3f) == r2;
    const std::vector<char> d = dilate_by_ball(group, g.dims, double(r2) + 1e-3);
    for(std::size_t v = 0; v < labels.size(); ++v)
      shell[v] = shell[v] || d[v];
  }
  return shell;
}

// Votes (of 26) for "inside", averaged over a voxel's 5x5x5 box. A majority (14 or
// more) starts an inside region; flood-exterior voxels joined to one keep growing it down
// to 11 (hysteresis).
constexpr std::uint8_t INSIDE_VOTES = 14, INSIDE_GROWTH_VOTES = 11;

// The boundary voxels dilated by `band` voxels: a shell without the gaps that the
// samples leave between them, which the rays of the parity vote and the lines of sight
// cross.
template <class Traits>
std::vector<char> boundary_shell(const Grid_geometry<Traits>& g, const std::vector<std::uint8_t>& labels, double band)
{
  std::vector<char> boundary(labels.size());
  for(std::size_t v = 0; v < labels.size(); ++v)
    boundary[v] = labels[v] == std::uint8_t(Voxel_label::BOUNDARY);
  return dilate_by_ball(boundary, g.dims, double(float(band * band) + 1e-3f));
}

// The voxels that a parity vote puts inside the shape, whatever the labels say (see
// voxelize_point_set() for why). `shell`: the boundary voxels dilated by `band` voxels
// (boundary_shell()), the shell that the rays cross; `min_voxels`: the smallest inside
// region kept.
template <class ConcurrencyTag, class Traits>
std::vector<char> voted_interior(const Grid_geometry<Traits>& g, const std::vector<std::uint8_t>& labels,
                                 const std::vector<char>& shell, double band, double min_voxels)
{
  const std::uint8_t E = std::uint8_t(Voxel_label::EXTERIOR);
  const std::size_t n = labels.size();
  // The 26 fixed directions vote in streaks along the grid axes and diagonals (a ray
  // through a hole changes the vote of a whole line of voxels); averaged over a 5x5x5
  // box of voxels off the shell, the inside regions get smooth borders, and no tunnels.
  std::vector<char> off_shell(n);
  for(std::size_t v = 0; v < n; ++v)
    off_shell[v] = !shell[v];
  const std::vector<std::uint8_t> mean =
    box_mean_votes<ConcurrencyTag>(odd_crossing_votes<ConcurrencyTag>(shell, g.dims), off_shell, g.dims, 2);

  // A region whose border lies mostly off the shell is not enclosed by the scan: a part
  // thinner than the shell is one run where the ray crosses two surfaces, and the space
  // between thin branches gets a majority (the crown of the tree scan: 43 % of the
  // border on the shell; at least 69 % for the parts of the scans and 79 % on the
  // synthetic shapes).
  std::vector<char> inside(n, 0);
  auto voted_in = [&](std::size_t v) { return !shell[v] && mean[v] >= INSIDE_VOTES; };
  for_each_region(g, voted_in, [&](const std::vector<std::size_t>& region) {
    if(double(region.size()) < min_voxels)
      return;
    std::size_t border = 0, on_shell = 0;
    for(std::size_t v : region)
      for_each_face_neighbour(g, v, [&](std::size_t w) {
        if(!voted_in(w))
        {
          ++border;
          on_shell += shell[w] != 0;
        }
      });
    if(2 * on_shell > border)
      for(std::size_t v : region)
        inside[v] = 1;
  });
  // Hysteresis, into the flood exterior only: near a hole the vote fades, and the
  // leaked flood would otherwise leave a pocket in the part.
  grow_face_connected(g, inside, [&](std::size_t w) {
    return !shell[w] && labels[w] == E && mean[w] >= INSIDE_GROWTH_VOTES;
  });
  if(std::find(inside.begin(), inside.end(), 1) == inside.end())
    return inside;
  // Where the flood leaked into a part, it also left a film of exterior voxels on the
  // shell between the inside and the points; a shell voxel nearer to the inside than to
  // any voxel off the shell outside it belongs to the part.
  // The distance to the outside only matters on the shell's exterior voxels, a few
  // voxels from the outside: a small first bound makes the transform take windowed
  // minima (about half the time of the unbounded one on a 35k-point cloud).
  const auto film = [&](std::size_t v) { return shell[v] && labels[v] == E; };
  const double near_radius = (std::min)(12.0, 2 * band + 2);
  const float near_bound = float(near_radius * near_radius);
  const std::vector<float> to_outside = squared_distance_to_sites_at<ConcurrencyTag>(
    g.dims, [&](std::size_t v) { return !inside[v] && !shell[v]; }, film, near_bound);
  // The distance to the inside only matters below the largest of these.
  float farthest_outside = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(film(v))
      farthest_outside = (std::max)(farthest_outside, to_outside[v]);
  const std::vector<float> to_inside =
    squared_distance_to_sites<ConcurrencyTag>(g.dims, [&](std::size_t v) { return inside[v]; }, farthest_outside);
  for(std::size_t v = 0; v < n; ++v)
    if(film(v) && to_inside[v] < to_outside[v])
      inside[v] = 1;
  return inside;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOTED_INTERIOR_H
