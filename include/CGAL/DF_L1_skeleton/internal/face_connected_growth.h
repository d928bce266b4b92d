// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_FACE_CONNECTED_GROWTH_H
#define CGAL_DF_L1_SKELETON_INTERNAL_FACE_CONNECTED_GROWTH_H

/// \file face_connected_growth.h
/// The 6-connected growth of a set of voxels through the voxels a predicate lets in,
/// by union-find over runs of voxels. Not part of the public API.

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>
#include <numeric>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Marks every voxel that a 6-connected walk from the marked voxels reaches through
// voxels where `can_enter` holds: the 6-connected components of the marked and
// enterable voxels that hold a marked voxel. The components are found on runs along x
// (one union-find node per run, joined to the runs it overlaps in the rows below and
// behind it), so that the cost is a scan of the grid and a few operations per run: the
// exterior, most of the grid in drop_enclosed_exterior(), is a few runs per row; a
// scanline fill reads each voxel several times.
template <class Traits, class CanEnter>
void grow_face_connected(const Grid_geometry<Traits>& g, std::vector<char>& marked, const CanEnter& can_enter)
{
  const std::size_t nx = g.dims[0], rows = std::size_t(g.dims[1]) * g.dims[2];
  struct Run
  {
    std::size_t first, last; // linear indices, inclusive
    std::size_t parent;      // union-find
    bool marked;
  };
  std::vector<Run> runs;
  std::vector<std::size_t> row_start(rows + 1); // runs of row r: [row_start[r], row_start[r + 1])
  for(std::size_t r = 0; r < rows; ++r)
  {
    row_start[r] = runs.size();
    const std::size_t base = r * nx;
    for(std::size_t i = 0; i < nx; ++i) // each voxel is tested once; i ends past a run
    {
      Run run{base + i, base + i, runs.size(), false};
      for(; i < nx && (marked[base + i] || can_enter(base + i)); ++i)
      {
        run.last = base + i;
        run.marked = run.marked || marked[base + i];
      }
      if(run.first < base + i)
        runs.push_back(run);
    }
  }
  row_start[rows] = runs.size();
  auto root = [&](std::size_t a) {
    while(runs[a].parent != a)
      a = runs[a].parent = runs[runs[a].parent].parent;
    return a;
  };
  auto join_rows = [&](std::size_t r, std::size_t s) { // rows r and s = r - 1 (along y) or r - ny (along z)
    std::size_t a = row_start[r], b = row_start[s];
    const std::size_t shift = (r - s) * nx;
    while(a < row_start[r + 1] && b < row_start[s + 1])
    {
      const std::size_t a_first = runs[a].first - shift, a_last = runs[a].last - shift;
      if(runs[b].last < a_first)
        ++b;
      else if(a_last < runs[b].first)
        ++a;
      else
      {
        const std::size_t x = root(a), y = root(b);
        if(x != y)
        {
          runs[(std::max)(x, y)].parent = (std::min)(x, y);
          runs[(std::min)(x, y)].marked = runs[x].marked || runs[y].marked;
        }
        if(runs[a].last - shift < runs[b].last)
          ++a;
        else
          ++b;
      }
    }
  };
  const std::size_t ny = g.dims[1];
  for(std::size_t r = 0; r < rows; ++r)
  {
    if(r % ny != 0)
      join_rows(r, r - 1);
    if(r >= ny)
      join_rows(r, r - ny);
  }
  for(std::size_t a = 0; a < runs.size(); ++a)
    if(runs[root(a)].marked)
      std::fill(marked.begin() + runs[a].first, marked.begin() + runs[a].last + 1, char(1));
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_FACE_CONNECTED_GROWTH_H
