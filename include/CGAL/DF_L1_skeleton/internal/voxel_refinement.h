// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_REFINEMENT_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_REFINEMENT_H

/// \file voxel_refinement.h
/// The levels of the multi-scale voxelization: marking the voxels that hold points, the
/// exterior flood fill, cropping, and the 3x3x3 refinement of a level. Not part of the
/// public API.

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Sub-voxels of boundary voxels whose label is not known yet.
constexpr std::uint8_t UNDECIDED = 255;

// The index of the voxel that holds `p`: the same arithmetic as Grid_geometry::locate(),
// so that a point is later found in the voxel it marked; clamping only matters for points
// on the grid's last face.
template <class Traits>
std::size_t voxel_of_point(const Grid_geometry<Traits>& g, const std::array<double, 3>& p)
{
  const double s = CGAL::to_double(g.voxel_size);
  const int i = std::clamp(int(std::floor((p[0] - CGAL::to_double(g.origin.x())) / s)), 0, g.dims[0] - 1);
  const int j = std::clamp(int(std::floor((p[1] - CGAL::to_double(g.origin.y())) / s)), 0, g.dims[1] - 1);
  const int k = std::clamp(int(std::floor((p[2] - CGAL::to_double(g.origin.z())) / s)), 0, g.dims[2] - 1);
  return g.index(i, j, k);
}

template <class Traits>
void mark_points(Grid_geometry<Traits>& g, std::vector<std::uint8_t>& labels,
                 const std::vector<std::array<double, 3>>& xyz)
{
  for(const std::array<double, 3>& p : xyz)
    labels[voxel_of_point(g, p)] = std::uint8_t(Voxel_label::BOUNDARY);
}

// Exterior = what a 6-connected walk from the grid border reaches without entering a
// boundary voxel. 6-connectivity keeps the exterior out of diagonal gaps of a coarse
// shell: a leak at the coarsest level would empty a whole part.
template <class Traits>
void flood_exterior(const Grid_geometry<Traits>& g, std::vector<std::uint8_t>& labels)
{
  const std::uint8_t B = std::uint8_t(Voxel_label::BOUNDARY), E = std::uint8_t(Voxel_label::EXTERIOR);
  std::vector<std::size_t> stack;
  auto push = [&](int i, int j, int k) {
    if(!g.contains(i, j, k))
      return;
    const std::size_t v = g.index(i, j, k);
    if(labels[v] == B || labels[v] == E)
      return;
    labels[v] = E;
    stack.push_back(v);
  };
  for(int k = 0; k < g.dims[2]; ++k)
    for(int j = 0; j < g.dims[1]; ++j)
      for(int i = 0; i < g.dims[0]; ++i)
        if(i == 0 || j == 0 || k == 0 || i == g.dims[0] - 1 || j == g.dims[1] - 1 || k == g.dims[2] - 1)
          push(i, j, k);
  while(!stack.empty())
  {
    const std::array<int, 3> c = g.coordinates(stack.back());
    stack.pop_back();
    push(c[0] - 1, c[1], c[2]); push(c[0] + 1, c[1], c[2]);
    push(c[0], c[1] - 1, c[2]); push(c[0], c[1] + 1, c[2]);
    push(c[0], c[1], c[2] - 1); push(c[0], c[1], c[2] + 1);
  }
}

// Shrinks the grid to its occupied voxels plus `margin` exterior layers.
template <class Traits>
void crop(Grid_geometry<Traits>& g, std::vector<std::uint8_t>& labels, int margin)
{
  std::array<int, 3> lo = {{g.dims[0], g.dims[1], g.dims[2]}}, hi = {{-1, -1, -1}};
  for(std::size_t v = 0; v < labels.size(); ++v)
    if(labels[v] != std::uint8_t(Voxel_label::EXTERIOR))
    {
      const std::array<int, 3> c = g.coordinates(v);
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = (std::min)(lo[a], c[a]);
        hi[a] = (std::max)(hi[a], c[a]);
      }
    }
  Grid_geometry<Traits> out = g;
  for(int a = 0; a < 3; ++a)
  {
    lo[a] -= margin;
    hi[a] += margin;
    out.dims[a] = hi[a] - lo[a] + 1;
  }
  out.origin = typename Traits::Point_3(g.origin.x() + lo[0] * g.voxel_size,
                                        g.origin.y() + lo[1] * g.voxel_size,
                                        g.origin.z() + lo[2] * g.voxel_size);
  std::vector<std::uint8_t> cropped(out.size(), std::uint8_t(Voxel_label::EXTERIOR));
  for(int k = 0; k < out.dims[2]; ++k)
    for(int j = 0; j < out.dims[1]; ++j)
      for(int i = 0; i < out.dims[0]; ++i)
        if(g.contains(i + lo[0], j + lo[1], k + lo[2]))
          cropped[out.index(i, j, k)] = labels[g.index(i + lo[0], j + lo[1], k + lo[2])];
  g = out;
  labels.swap(cropped);
}

// One refinement level: every voxel becomes 3x3x3 sub-voxels. Sub-voxels of exterior
// and interior voxels keep their parent's label; those of a boundary voxel are boundary
// when they hold a point, exterior when the exterior reaches them within
// `propagation_steps` face-neighbour steps, interior otherwise (the paper: one step).
// The paper lets the exterior spread to the 26 neighbours; but a boundary shell one
// sub-voxel thick is often only 26-connected, and a 26-step then crosses it diagonally
// and eats a sub-voxel of the inside (3 finest voxels at the second level). With face
// steps, a 26-connected shell separates, as in the (26, 6) digital topology.
template <class Traits>
void refine(Grid_geometry<Traits>& g, std::vector<std::uint8_t>& labels,
            const std::vector<std::array<double, 3>>& xyz, int propagation_steps)
{
  Grid_geometry<Traits> fine = g;
  fine.voxel_size = g.voxel_size / 3;
  for(int a = 0; a < 3; ++a)
    fine.dims[a] = 3 * g.dims[a];
  std::vector<std::uint8_t> fl(fine.size());
  for(int k = 0; k < fine.dims[2]; ++k)
    for(int j = 0; j < fine.dims[1]; ++j)
    {
      const std::size_t row = fine.index(0, j, k);
      for(int i = 0; i < fine.dims[0]; ++i)
      {
        const std::uint8_t parent = labels[g.index(i / 3, j / 3, k / 3)];
        fl[row + i] = parent == std::uint8_t(Voxel_label::BOUNDARY) ? UNDECIDED : parent;
      }
    }
  mark_points(fine, fl, xyz);

  std::vector<std::size_t> undecided;
  for(std::size_t v = 0; v < fl.size(); ++v)
    if(fl[v] == UNDECIDED)
      undecided.push_back(v);
  std::vector<std::size_t> reached;
  for(int step = 0; step < propagation_steps && !undecided.empty(); ++step)
  {
    reached.clear();
    std::size_t kept = 0;
    for(std::size_t v : undecided)
    {
      const std::array<int, 3> c = fine.coordinates(v);
      bool near_exterior = false;
      for(int n = 0; n < 6 && !near_exterior; ++n)
      {
        const int i = c[0] + (n == 0) - (n == 1), j = c[1] + (n == 2) - (n == 3), k = c[2] + (n == 4) - (n == 5);
        near_exterior = !fine.contains(i, j, k) || fl[fine.index(i, j, k)] == std::uint8_t(Voxel_label::EXTERIOR);
      }
      if(near_exterior)
        reached.push_back(v);
      else
        undecided[kept++] = v;
    }
    undecided.resize(kept);
    if(reached.empty())
      break;
    for(std::size_t v : reached) // synchronous update: one step per pass
      fl[v] = std::uint8_t(Voxel_label::EXTERIOR);
  }
  for(std::size_t v : undecided)
    fl[v] = std::uint8_t(Voxel_label::INTERIOR);
  g = fine;
  labels.swap(fl);
}

template <class Traits>
Voxelization_level level_statistics(const Grid_geometry<Traits>& g, const std::vector<std::uint8_t>& labels)
{
  Voxelization_level s;
  s.voxel_size = CGAL::to_double(g.voxel_size);
  s.dims = g.dims;
  for(std::uint8_t l : labels)
  {
    s.boundary += (l == std::uint8_t(Voxel_label::BOUNDARY));
    s.interior += (l == std::uint8_t(Voxel_label::INTERIOR));
    s.exterior += (l == std::uint8_t(Voxel_label::EXTERIOR));
  }
  return s;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_REFINEMENT_H
