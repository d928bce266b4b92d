// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H

#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Adds to `votes`, for every voxel, the number of the grid directions d = (di, dj, dk)
// (in {-1, 0, 1}^3 \ {0}, numbered 0 to 25 in the order of dk, dj, di) in [first, last)
// in which the ray leaving it crosses an odd number of runs of `shell` voxels. `parity`:
// scratch of the grid's size.
//
// One linear pass over the grid per direction: the parity of the runs from w on is that
// from w + d on, flipped when w starts a run (w is in the shell and w + d is not); the
// voxels are visited so that w + d comes first.
inline void add_odd_crossing_votes(const std::vector<char>& shell, const std::array<int, 3>& dims, int first_direction,
                                   int last_direction, std::vector<std::uint8_t>& votes, std::vector<char>& parity)
{
  const std::ptrdiff_t nx = dims[0], ny = dims[1], nz = dims[2];
  auto first = [](std::ptrdiff_t n, int d) { return d > 0 ? n - 1 : std::ptrdiff_t(0); };
  for(int direction = first_direction; direction < last_direction; ++direction)
  {
    const int cell = direction < 13 ? direction : direction + 1; // the centre, 13, is no direction
    const int di = cell % 3 - 1, dj = cell / 3 % 3 - 1, dk = cell / 9 - 1;
    const std::ptrdiff_t step = (dk * ny + dj) * nx + di;
    const std::ptrdiff_t sk = dk > 0 ? -1 : 1, sj = dj > 0 ? -1 : 1;
    for(std::ptrdiff_t k = first(nz, dk); k >= 0 && k < nz; k += sk)
      for(std::ptrdiff_t j = first(ny, dj); j >= 0 && j < ny; j += sj)
      {
        const std::ptrdiff_t row = (k * ny + j) * nx;
        const char* s = shell.data() + row;
        char* p = parity.data() + row;
        std::uint8_t* out = votes.data() + row;
        if(k + dk < 0 || k + dk >= nz || j + dj < 0 || j + dj >= ny)
        {
          for(std::ptrdiff_t i = 0; i < nx; ++i) // every ray leaves the grid at once
            p[i] = s[i] != 0;
          continue;
        }
        if(!dj && !dk)
        {
          // Along x, each voxel needs the one before it in the row (kept in a register).
          char next_parity = p[first(nx, di)] = s[first(nx, di)] != 0;
          for(std::ptrdiff_t i = first(nx, di) - di; i >= 0 && i < nx; i -= di)
          {
            out[i] = std::uint8_t(out[i] + next_parity);
            next_parity = p[i] = char(next_parity ^ (s[i] && !s[i + di]));
          }
          continue;
        }
        // w + d lies in a row done before: the voxels of this row are independent, and
        // the loop vectorizes. The voxel whose ray leaves the grid sideways votes 0.
        const char* next_s = s + step;
        const char* next_p = p + step;
        const std::ptrdiff_t lo = di < 0 ? 1 : 0, hi = di > 0 ? nx - 1 : nx;
        for(std::ptrdiff_t i = lo; i < hi; ++i)
        {
          p[i] = char(next_p[i] ^ ((s[i] != 0) & (next_s[i] == 0)));
          out[i] = std::uint8_t(out[i] + next_p[i]);
        }
        if(di != 0)
          p[first(nx, di)] = s[first(nx, di)] != 0;
      }
  }
}

// For every voxel, the number of the 26 grid directions in which the ray leaving it
// crosses an odd number of runs of `shell` voxels (a run: the consecutive shell voxels
// the ray meets at a time), i.e. the directions that vote "inside" in a parity count
// (Nooruddin and Turk, 2003). A closed shell gives 26 inside and 0 outside, but for rays
// that run along a face; a hole in the shell only changes the votes of the rays through
// it. The ray of voxel v starts at v + d; the votes of shell voxels (which may count
// their own run) are meaningless.
// A pass is sequential along its direction (splitting it into dependent slabs for 2
// threads was slower); in parallel, two threads take half of the directions each, with
// their own counts, added at the end.
template <class ConcurrencyTag = CGAL::Sequential_tag>
std::vector<std::uint8_t> odd_crossing_votes(const std::vector<char>& shell, const std::array<int, 3>& dims)
{
  std::vector<std::uint8_t> votes(shell.size(), 0);
  std::vector<char> parity(shell.size()); // parity of the runs from the voxel on, itself included
  if(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    add_odd_crossing_votes(shell, dims, 0, 26, votes, parity);
    return votes;
  }
  std::vector<std::uint8_t> other_votes(shell.size(), 0);
  std::vector<char> other_parity(shell.size());
  run_both<ConcurrencyTag>([&] { add_odd_crossing_votes(shell, dims, 0, 13, votes, parity); },
                           [&] { add_odd_crossing_votes(shell, dims, 13, 26, other_votes, other_parity); });
  for(std::size_t v = 0; v < votes.size(); ++v)
    votes[v] = std::uint8_t(votes[v] + other_votes[v]);
  return votes;
}

// The mean of `votes` over the (2r+1)^3 box around each voxel, counting only the voxels
// where `used` holds (0 where no voxel of the box is used), rounded to an integer.
// Separable running sums of (vote, count) pairs packed in one integer; each pass is
// parallel over independent lines.
template <class ConcurrencyTag = CGAL::Sequential_tag>
std::vector<std::uint8_t> box_mean_votes(const std::vector<std::uint8_t>& votes, const std::vector<char>& used,
                                         const std::array<int, 3>& dims, int r)
{
  const std::size_t n = votes.size();
  const std::size_t strides[3] = {1, std::size_t(dims[0]), std::size_t(dims[0]) * std::size_t(dims[1])};
  // vote sum * 2^12 + count: at most 26 * 11^3 * 2^12 + 11^3 < 2^31 for r <= 5
  std::vector<std::int32_t> a(n), b(n);
  for_each_index<ConcurrencyTag>(n, [&](std::size_t v) { a[v] = used[v] ? (std::int32_t(votes[v]) << 12) + 1 : 0; },
                                 1 << 16);
  const std::size_t window = std::size_t(2 * r + 1), lag = std::size_t(r);
  for(int axis = 0; axis < 3; ++axis)
  {
    const std::size_t stride = strides[axis], len = std::size_t(dims[axis]);
    if(axis == 0)
    {
      for_each_index<ConcurrencyTag>(n / len, [&](std::size_t line) {
        const std::size_t base = line * len;
        std::int32_t s = 0;
        for(std::size_t t = 0; t < len + lag; ++t)
        {
          s += t < len ? a[base + t] : 0;
          s -= t >= window ? a[base + t - window] : 0;
          if(t >= lag)
            b[base + t - lag] = s;
        }
      }, 64);
      a.swap(b);
      continue;
    }
    // Along y and z, the lines start at the voxels `base + i`, i < stride; their running
    // sums advance together, one slice of `stride` voxels at a time. A task takes a
    // chunk of the lines of one slab (`stride * len` voxels).
    const std::size_t chunk = 2048, chunks = (stride + chunk - 1) / chunk;
    for_each_index<ConcurrencyTag>(n / (stride * len) * chunks, [&](std::size_t task) {
      const std::size_t first = (task % chunks) * chunk, width = (std::min)(chunk, stride - first);
      const std::size_t base = (task / chunks) * stride * len + first;
      std::vector<std::int32_t> sum(width, 0);
      std::int32_t* s = sum.data();
      for(std::size_t t = 0; t < len + lag; ++t)
      {
        if(t < len)
        {
          const std::int32_t* add = a.data() + base + t * stride;
          for(std::size_t i = 0; i < width; ++i)
            s[i] += add[i];
        }
        if(t >= window)
        {
          const std::int32_t* sub = a.data() + base + (t - window) * stride;
          for(std::size_t i = 0; i < width; ++i)
            s[i] -= sub[i];
        }
        if(t >= lag)
        {
          std::int32_t* out = b.data() + base + (t - lag) * stride;
          for(std::size_t i = 0; i < width; ++i)
            out[i] = s[i];
        }
      }
    }, 1);
    a.swap(b);
  }
  std::vector<std::uint8_t> mean(n, 0);
  for_each_index<ConcurrencyTag>(n, [&](std::size_t v) {
    const std::int32_t count = a[v] & 0xfff;
    if(count > 0) // sum / count rounded half up, as std::lround, in integers
      mean[v] = std::uint8_t((2 * (a[v] >> 12) + count) / (2 * count));
  }, 1 << 16);
  return mean;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H
