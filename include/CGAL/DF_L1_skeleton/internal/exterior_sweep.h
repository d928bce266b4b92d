// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_EXTERIOR_SWEEP_H
#define CGAL_DF_L1_SKELETON_INTERNAL_EXTERIOR_SWEEP_H

/// \file exterior_sweep.h
/// The correction of the labels after the last level: balls rolling in from the exterior
/// sweep the concave regions the coarse levels saw enclosed. Not part of the public API.

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/internal/euclidean_distance_transform.h>
#include <CGAL/DF_L1_skeleton/internal/face_connected_growth.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_morphology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Centres that a ball of radius sqrt(r2) reaches by rolling in from the exterior without
// touching a boundary voxel centre: a 6-connected walk, clear of the boundary.
template <class Traits>
std::vector<char> ball_centres(const Grid_geometry<Traits>& g, const std::vector<std::uint8_t>& labels,
                               const std::vector<float>& to_boundary, float r2)
{
  std::vector<char> centre(labels.size(), 0);
  for(std::size_t v = 0; v < labels.size(); ++v)
    centre[v] = labels[v] == std::uint8_t(Voxel_label::EXTERIOR) && to_boundary[v] > r2;
  grow_face_connected(g, centre, [&](std::size_t w) { return to_boundary[w] > r2; });
  return centre;
}

// The exterior voxels that a 6-connected walk through exterior voxels does not reach from
// the grid border become interior: the exterior is one region.
template <class Traits>
void drop_enclosed_exterior(const Grid_geometry<Traits>& g, std::vector<std::uint8_t>& labels)
{
  const std::uint8_t E = std::uint8_t(Voxel_label::EXTERIOR), I = std::uint8_t(Voxel_label::INTERIOR);
  std::vector<char> reached(labels.size(), 0);
  for(int k = 0; k < g.dims[2]; ++k)
    for(int j = 0; j < g.dims[1]; ++j)
    {
      const bool side = k == 0 || j == 0 || k == g.dims[2] - 1 || j == g.dims[1] - 1;
      const std::size_t row = g.index(0, j, k);
      for(int i = 0; i < g.dims[0]; ++i)
        reached[row + i] = labels[row + i] == E && (side || i == 0 || i == g.dims[0] - 1);
    }
  grow_face_connected(g, reached, [&](std::size_t w) { return labels[w] == E; });
  for(std::size_t v = 0; v < labels.size(); ++v)
    if(labels[v] == E && !reached[v])
      labels[v] = I;
}

// The paper's correction-free labels keep every sub-voxel of an interior voxel
// interior, so an empty concave region that a coarse level saw enclosed (the hole of a
// torus, the gap between two close arms) stays interior at every level; and the one
// neighbour step per level leaves empty sub-voxels outside the points interior. Balls
// rolling in from the exterior without touching a boundary voxel centre sweep both:
// - a large ball (radius `large`, voxel units) cannot pass through a gap of the scan
//   narrower than its diameter: what it sweeps is exterior;
// - a small ball (radius `small`) also enters the concave regions the large one misses,
//   but it may pass through a hole of the scan or between sparse samples. Where it got
//   in, its centres form regions beyond the large ball's centres; a region whose centres
//   reach farther than `depth` face steps from them is the inside of the shape, entered
//   through a hole, and is not swept. A concave pocket is shallow.
// The voxels of `inside` (voted_interior()) are obstacles to the balls, as the boundary,
// and end interior.
template <class ConcurrencyTag, class Traits>
void sweep_exterior_with_balls(const Grid_geometry<Traits>& g, std::vector<std::uint8_t>& labels,
                               const std::vector<char>& inside, double large, double small, double depth)
{
  const std::uint8_t B = std::uint8_t(Voxel_label::BOUNDARY), E = std::uint8_t(Voxel_label::EXTERIOR),
                     I = std::uint8_t(Voxel_label::INTERIOR);
  const std::size_t n = labels.size();
  const float L2 = float(large * large), S2 = float(small * small);
  // Bounded by L2: the ball centres only compare it with L2 and S2 <= L2.
  std::vector<float> dist =
    squared_distance_to_sites<ConcurrencyTag>(g.dims, [&](std::size_t v) { return labels[v] == B || inside[v]; }, L2);
  std::vector<char> large_centre, small_centre;
  run_both<ConcurrencyTag>([&] { large_centre = ball_centres(g, labels, dist, L2); },
                           [&] { small_centre = ball_centres(g, labels, dist, S2); });

  // Face-step depth of the small ball's centres beyond the large ball's centres and the
  // exterior (BFS), and the deepest centre of each 6-connected region of them.
  // The search starts from the step-1 centres: they are few, while the step-0 ones (the
  // exterior) are most of the grid.
  std::vector<int> steps(n, -1);
  for(std::size_t v = 0; v < n; ++v)
    if(small_centre[v] && (labels[v] == E || large_centre[v]))
      steps[v] = 0;
  std::vector<std::size_t> queue;
  for(std::size_t v = 0; v < n; ++v)
    if(small_centre[v] && steps[v] != 0 && has_face_neighbour(g, v, [&](std::size_t w) { return steps[w] == 0; }))
    {
      steps[v] = 1;
      queue.push_back(v);
    }
  for(std::size_t head = 0; head < queue.size(); ++head)
  {
    const std::size_t v = queue[head];
    for_each_face_neighbour(g, v, [&](std::size_t w) {
      if(small_centre[w] && steps[w] < 0)
      {
        steps[w] = steps[v] + 1;
        queue.push_back(w);
      }
    });
  }
  for_each_region(g, [&](std::size_t v) { return small_centre[v] && steps[v] != 0; },
                  [&](const std::vector<std::size_t>& region) {
                    int deepest = 0; // >= 1: every centre is reached from the exterior
                    for(std::size_t u : region)
                      deepest = (std::max)(deepest, steps[u]);
                    if(deepest > depth)
                      for(std::size_t u : region)
                        small_centre[u] = 0;
                  });

  // One transform for both sweeps: a small centre starts at L2 - S2, so that a voxel
  // within `small` of it gets a value <= L2, as one within `large` of a large centre.
  for(std::size_t v = 0; v < n; ++v)
    dist[v] = large_centre[v] ? 0.f : small_centre[v] ? L2 - S2 : EDT_INFINITY;
  squared_euclidean_distance_transform<ConcurrencyTag>(dist, g.dims, L2);
  for(std::size_t v = 0; v < n; ++v)
  {
    if(inside[v])
      labels[v] = I;
    else if(labels[v] == I && dist[v] <= L2)
      labels[v] = E;
  }
  drop_enclosed_exterior(g, labels);
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_EXTERIOR_SWEEP_H
