// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_MEMORY_ESTIMATE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_MEMORY_ESTIMATE_H

// The peak memory of a skeletonization, estimated before its large allocations, so that
// a parameter (a voxel resolution of 2048) cannot exhaust the machine. The model is
// linear in the points and in the voxels of the finest grid; its coefficients are the
// measured peaks of the tool (doc/memory.md), which hold the caller's copy of the points
// too: per point, the class's points, the kept and added points and the k-nearest
// tables of the outlier test (its peak); per voxel, the labels, the distance field and
// the transforms and flags of the thinning.

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
  double points = 0; // number of points
  double voxels = 0; // voxels of the finest grid
  double bytes() const
  {
    return memory_base_bytes + memory_bytes_per_point * points + memory_bytes_per_voxel * voxels;
  }
};

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
  const bool grid = memory_bytes_per_voxel * estimate.voxels >= memory_bytes_per_point * estimate.points;
  std::ostringstream out;
  out.precision(3);
  out << stage << ": the estimated peak memory, " << format_bytes(estimate.bytes()) << " ("
      << static_cast<unsigned long long>(estimate.points) << " points, " << estimate.voxels << " voxels at voxel_resolution " << voxel_resolution
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
