// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_MEMORY_ESTIMATE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_MEMORY_ESTIMATE_H

// The peak memory of a skeletonization, estimated before its large allocations, so that
// a parameter (a voxel resolution of 2048) cannot exhaust the machine. Two estimates
// (doc/memory.md):
//
// - initial_memory_estimate(), from the parameters and the number of points alone (the
//   constructor): linear in the points and in the voxels of the finest grid, with
//   coefficients measured on the tool, which holds the caller's copy of the points too;
// - refined_memory_estimate(), once the distance field exists: the largest of the
//   phases of the run, each the sum of the arrays it holds, counted from the grid as
//   built (its voxels, its interior voxels) and from the path the initial skeleton
//   takes (thin parts or occupied depth, with or without the graph repairs).

#include <CGAL/DF_L1_skeleton/errors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace DF_L1 {
namespace internal {

constexpr double memory_base_bytes = 10.0 * 1024 * 1024;
constexpr double memory_bytes_per_point = 250;
constexpr double memory_bytes_per_voxel = 30;

// The voxels of the finest grid of voxelize_point_set() for a box of these extents:
// voxel_resolution along the longest side, the same voxel size along the others, and
// the empty layers around the box (9 or 10 voxels in all, measured).
inline double finest_voxel_count(const std::array<double, 3>& extent, int voxel_resolution)
{
  const double longest = (std::max)({extent[0], extent[1], extent[2]});
  if(!(longest > 0) || voxel_resolution < 1)
    return 0;
  const double voxel = longest / voxel_resolution;
  double voxels = 1;
  for(int a = 0; a < 3; ++a)
    voxels *= std::ceil(extent[a] / voxel - 1e-9) + 10;
  return voxels;
}

struct Memory_estimate
{
  double points = 0;      // number of input points
  double voxels = 0;      // voxels of the finest grid (estimated, or as built once refined)
  double point_bytes = 0; // the share of the points
  double voxel_bytes = 0; // the share of the voxels
  bool refined = false;   // from the grid as built (refined_memory_estimate())
  double bytes() const { return memory_base_bytes + point_bytes + voxel_bytes; }
};

// The estimate from the number of points and the voxels the finest grid will have:
// 10 MiB + 250 B per point + 30 B per voxel, fitted on the tool's peak.
inline Memory_estimate initial_memory_estimate(double points, double voxels)
{
  Memory_estimate e;
  e.points = points;
  e.voxels = voxels;
  e.point_bytes = memory_bytes_per_point * points;
  e.voxel_bytes = memory_bytes_per_voxel * voxels;
  return e;
}

// What the refined estimate is counted from: the grid as built and the path of the
// initial skeleton.
struct Voxel_stage_counts
{
  double points = 0;          // input points
  double analysed_points = -1; // the points the stages after the outlier test analyse (< 0: all)
  double added_points = 0;    // points added by the upsampling
  double voxels = 0;          // voxels of the finest grid
  double interior_voxels = 0; // of the distance field
  bool grid_copy = false;     // the caller took the grid in input units
  bool field_copy = false;    // the caller took the distance field in input units
  bool denoised = false;      // occupied depth instead of the thin-part search
  bool repair = false;        // the graph repairs run (pieces joined, missing branches)
};

// Bytes held per voxel, by the arrays that hold them (doc/memory.md, "Where the memory
// goes"). Held from the voxelization to the end: the labels of the raw grid and of
// the grid without outliers (1 + 1), the distance field (labels 1, distances 4); the
// copies in input units when the caller asked for them (the tool does): grid 1, field 5.
constexpr double memory_held_bytes_per_voxel = 7;
constexpr double memory_grid_copy_bytes_per_voxel = 1;
constexpr double memory_field_copy_bytes_per_voxel = 5;
// The initial skeleton, phase by phase, per voxel of the grid (every array is
// field.size() long):
// - the search, thin-part path (clouds that were not smoothed): the ridge test on one
//   thread (its box sums in double 8, in 1), then the shape volume (in, outside, closed,
//   with the ridge flags: 4), beside the thin-part search on the other (power 4, thick
//   1, occupied 1, thin voxels 1, solid 1: 8 from its start; then beyond 4, depth 4,
//   near 4: 20); the thin-part search takes most of the stage's time, and the box sums
//   are gone before its transforms: max(9 + 8, 4 + 20) (also the sequential order);
constexpr double memory_thin_search_bytes_per_voxel = 24;
// - the search, occupied-depth path (smoothed clouds): the occupied depth (4), then the
//   ridge test (box sums 8, in 1);
constexpr double memory_occupied_search_bytes_per_voxel = 13;
// - in every phase, the ridge voxels found: 32 B each (index 8, centre 24) in vectors
//   grown by doubling (1.5 times that on average), up to a third of the interior voxels
//   (1 to 33 % on the inputs we measured): 16 B per interior voxel;
constexpr double memory_ridge_bytes_per_interior_voxel = 16;
// - the thinning: in 1, curves 1, depth 4, the memo of curve ends 1, the thinning state
//   1, and the thin parts (voxels 1, solid 1, depth 4) or the occupied depth (4);
constexpr double memory_thin_thinning_bytes_per_voxel = 14;
constexpr double memory_occupied_thinning_bytes_per_voxel = 12;
//   plus the thinning order, 8 B per voxel of the solid (about the interior voxels),
//   in a vector grown by doubling (up to 16 B);
constexpr double memory_thinning_bytes_per_interior_voxel = 16;
// - the graph repairs, when the curves leave pieces in one component of the shape or a
//   thin part without a branch: the thinning's arrays less its state (13, or 11 with
//   the occupied depth) and those of the repair, the larger of joining the pieces
//   (vertex of each voxel 8, shape components 4, the deepest-path search's costs 8 and
//   predecessors 8, and the occupied depth 4 when there is no thin-part depth) and
//   adding the missing branches (excess 8, vertex of each voxel 8, costs 8,
//   predecessors 8): 32. In a smoothed cloud the twigs given back after the gap cuts
//   hold the occupied depth (4) and the thin-part candidates (1) beside those 32, and
//   before them the occupied depth beside the thin-part search (4 + 20): within 11 + 32.
constexpr double memory_thin_repair_bytes_per_voxel = 13 + 32;
constexpr double memory_occupied_repair_bytes_per_voxel = 11 + 32;
// Per point, while the voxels exist: the caller's points and normals (24 + 24, the
// tool's cloud) and the class's points and kept points (24 + 24); 24 per added point.
constexpr double memory_held_bytes_per_point = 96;
constexpr double memory_kept_bytes_per_point = 24; // of those 96: the kept (analysed) points
// Per input point of a cloud analysed through representatives (whose point stages
// hold only a sample or the representatives): the caller's and the class's points
// (24 + 24), the pages of the file being read (the tool), the flags and the density
// cap's arrays; 100 to 115 B measured at 10M points (clean and noisy stick figures).
constexpr double memory_dense_cloud_bytes_per_point = 110;
constexpr double memory_held_bytes_per_added_point = 24;
// Per analysed point, from the initial skeleton on: the evidence of its spur pruning and
// gap cuts (their coordinates 24, and a grid of them: a sorted copy 24 and the order 8).
constexpr double memory_support_bytes_per_analysed_point = 56;

// The largest of the phases of the run, for the grid as built: the point stages (the
// outlier test, the smoothing, the contraction: the per-point bytes of the initial model,
// or for a cloud analysed through representatives the larger of the dense-cloud bytes per
// input point and the initial model's per analysed point; with the voxels held during
// the contraction) and the phases of the initial
// skeleton (the points and voxels held, and the phase's own arrays).
inline Memory_estimate refined_memory_estimate(const Voxel_stage_counts& c)
{
  const double held = memory_held_bytes_per_voxel + (c.grid_copy ? memory_grid_copy_bytes_per_voxel : 0) +
                      (c.field_copy ? memory_field_copy_bytes_per_voxel : 0);
  const double search = c.denoised ? memory_occupied_search_bytes_per_voxel : memory_thin_search_bytes_per_voxel;
  const double thinning = c.denoised ? memory_occupied_thinning_bytes_per_voxel : memory_thin_thinning_bytes_per_voxel;
  const double repair = c.repair ? (c.denoised ? memory_occupied_repair_bytes_per_voxel : memory_thin_repair_bytes_per_voxel) : 0;
  const double stage = memory_ridge_bytes_per_interior_voxel * c.interior_voxels +
                       (std::max)({search * c.voxels,
                                   thinning * c.voxels + memory_thinning_bytes_per_interior_voxel * c.interior_voxels,
                                   repair * c.voxels});
  const double analysed = c.analysed_points < 0 ? c.points : c.analysed_points;
  // the kept points are the analysed ones
  const double held_points = (memory_held_bytes_per_point - memory_kept_bytes_per_point) * c.points +
                             (memory_kept_bytes_per_point + memory_support_bytes_per_analysed_point) * analysed +
                             memory_held_bytes_per_added_point * c.added_points;
  Memory_estimate e;
  e.points = c.points;
  e.voxels = c.voxels;
  e.refined = true;
  const double point_stages =
    (std::max)(memory_dense_cloud_bytes_per_point * c.points, memory_bytes_per_point * analysed);
  const double point_phase = point_stages + held * c.voxels;
  const double voxel_phase = held_points + held * c.voxels + stage;
  if(point_phase >= voxel_phase)
  {
    e.point_bytes = point_stages;
    e.voxel_bytes = held * c.voxels;
  }
  else
  {
    e.point_bytes = held_points;
    e.voxel_bytes = held * c.voxels + stage;
  }
  return e;
}

// The memory available to this process now: MemAvailable of /proc/meminfo on Linux,
// +infinity where it cannot be read.
inline double available_memory_bytes()
{
  double bytes = std::numeric_limits<double>::infinity();
#if defined(__linux__)
  if(std::FILE* f = std::fopen("/proc/meminfo", "r"))
  {
    char line[256];
    while(std::fgets(line, sizeof line, f))
    {
      unsigned long long kib = 0;
      if(std::sscanf(line, "MemAvailable: %llu kB", &kib) == 1)
      {
        bytes = double(kib) * 1024;
        break;
      }
    }
    std::fclose(f);
  }
#endif
  return bytes;
}

inline std::string format_bytes(double bytes)
{
  std::ostringstream out;
  out.precision(3);
  if(bytes >= 1024.0 * 1024 * 1024)
    out << bytes / (1024.0 * 1024 * 1024) << " GiB";
  else
    out << bytes / (1024.0 * 1024) << " MiB";
  return out.str();
}

// Throws Invalid_input when `estimate` exceeds `limit`, naming what to lower.
inline void check_memory(const Memory_estimate& estimate, double limit, int voxel_resolution, const std::string& stage)
{
  if(!(estimate.bytes() > limit))
    return;
  const bool grid = estimate.voxel_bytes >= estimate.point_bytes;
  std::ostringstream out;
  out.precision(3);
  out << stage << ": the estimated peak memory, " << format_bytes(estimate.bytes()) << " ("
      << static_cast<unsigned long long>(estimate.points) << " points, " << estimate.voxels << (estimate.refined ? " voxels in the grid" : " voxels") << " at voxel_resolution " << voxel_resolution
      << "), exceeds the limit of " << format_bytes(limit)
      << " (max_memory; by default the memory available at the start); "
      << (grid ? "lower voxel_resolution" : "thin the cloud (e.g. CGAL::grid_simplify_point_set())")
      << " or raise max_memory";
  throw Invalid_input(out.str());
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_MEMORY_ESTIMATE_H
