// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// For every voxel, the number of the 26 grid directions (di, dj, dk in {-1, 0, 1}) in
// which the ray leaving it crosses an odd number of runs of `shell` voxels (a run: the
// consecutive shell voxels the ray meets at a time), i.e. the directions that vote
// "inside" in a parity count (Nooruddin and Turk, 2003). A closed shell gives 26 inside
// and 0 outside, but for rays that run along a face; a hole in the shell only changes
// the votes of the rays through it. The ray of voxel v starts at v + d; the votes of
// shell voxels (which may count their own run) are meaningless.
//
// One linear pass over the grid per direction: the parity of the runs from w on is that
// from w + d on, flipped when w starts a run (w is in the shell and w + d is not); the
// voxels are visited so that w + d comes first. Sequential: 26 passes over a million
// voxels take about 0.05 s, and splitting them into dependent slabs for 2 threads was
// slower (0.07 s).
inline std::vector<std::uint8_t> odd_crossing_votes(const std::vector<char>& shell, const std::array<int, 3>& dims)
{
  const std::ptrdiff_t nx = dims[0], ny = dims[1], nz = dims[2];
  std::vector<std::uint8_t> votes(shell.size(), 0);
  std::vector<char> parity(shell.size(), 0); // parity of the runs from the voxel on, itself included
  auto first = [](std::ptrdiff_t n, int d) { return d > 0 ? n - 1 : std::ptrdiff_t(0); };
  for(int dk = -1; dk <= 1; ++dk)
    for(int dj = -1; dj <= 1; ++dj)
      for(int di = -1; di <= 1; ++di)
      {
        if(!di && !dj && !dk)
          continue;
        const std::ptrdiff_t step = (dk * ny + dj) * nx + di;
        const std::ptrdiff_t sk = dk > 0 ? -1 : 1, sj = dj > 0 ? -1 : 1, si = di > 0 ? -1 : 1;
        for(std::ptrdiff_t k = first(nz, dk); k >= 0 && k < nz; k += sk)
        {
          const bool k_next = k + dk >= 0 && k + dk < nz;
          for(std::ptrdiff_t j = first(ny, dj); j >= 0 && j < ny; j += sj)
          {
            const bool jk_next = k_next && j + dj >= 0 && j + dj < ny;
            const std::ptrdiff_t row = (k * ny + j) * nx;
            for(std::ptrdiff_t i = first(nx, di); i >= 0 && i < nx; i += si)
            {
              const std::size_t v = std::size_t(row + i);
              char next_shell = 0, next_parity = 0;
              if(jk_next && i + di >= 0 && i + di < nx)
              {
                next_shell = shell[std::size_t(std::ptrdiff_t(v) + step)];
                next_parity = parity[std::size_t(std::ptrdiff_t(v) + step)];
              }
              parity[v] = char(next_parity ^ (shell[v] && !next_shell));
              votes[v] = std::uint8_t(votes[v] + next_parity);
            }
          }
        }
      }
  return votes;
}

// The mean of `votes` over the (2r+1)^3 box around each voxel, counting only the voxels
// where `used` holds (0 where no voxel of the box is used), rounded to an integer.
// Separable running sums of (vote, count) pairs packed in one integer.
inline std::vector<std::uint8_t> box_mean_votes(const std::vector<std::uint8_t>& votes, const std::vector<char>& used,
                                                const std::array<int, 3>& dims, int r)
{
  const std::size_t n = votes.size();
  const std::size_t strides[3] = {1, std::size_t(dims[0]), std::size_t(dims[0]) * std::size_t(dims[1])};
  // vote sum * 2^12 + count: at most 26 * 11^3 * 2^12 + 11^3 < 2^31 for r <= 5
  std::vector<std::int32_t> a(n), b(n);
  for(std::size_t v = 0; v < n; ++v)
    a[v] = used[v] ? (std::int32_t(votes[v]) << 12) + 1 : 0;
  for(int axis = 0; axis < 3; ++axis)
  {
    const std::size_t stride = strides[axis], len = std::size_t(dims[axis]);
    for(std::size_t v = 0; v < n; ++v)
    {
      if((v / stride) % len != 0)
        continue; // v starts a line along `axis`
      std::int32_t sum = 0;
      for(std::size_t t = 0; t < len + std::size_t(r); ++t)
      {
        if(t < len)
          sum += a[v + t * stride];
        if(t >= std::size_t(2 * r + 1))
          sum -= a[v + (t - std::size_t(2 * r + 1)) * stride];
        if(t >= std::size_t(r))
          b[v + (t - std::size_t(r)) * stride] = sum;
      }
    }
    a.swap(b);
  }
  std::vector<std::uint8_t> mean(n, 0);
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::int32_t count = a[v] & 0xfff;
    if(count > 0)
      mean[v] = std::uint8_t(std::lround(double(a[v] >> 12) / double(count)));
  }
  return mean;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H
