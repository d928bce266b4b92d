// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H

#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/assertions.h>
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

// The grid direction numbered `direction` (0 to 25 in the order of dk, dj, di, the
// centre left out).
inline std::array<int, 3> grid_direction(int direction)
{
  const int cell = direction < 13 ? direction : direction + 1; // the centre, 13, is no direction
  return {{cell % 3 - 1, cell / 3 % 3 - 1, cell / 9 - 1}};
}

// Adds to `votes`, for every voxel, the number of the grid directions d = (di, dj, dk) in
// `directions` in which the ray leaving the voxel crosses an odd number of runs of
// `shell` voxels. The directions must not go both up and down along z: the parity of the
// runs from w on is that from w + d on, flipped when w starts a run (w is in the shell
// and w + d is not), so the z slices are visited so that w + d comes first.
//
// The slices are visited once for all the directions: each direction keeps the parities
// of its last two slices, so that the grid is read and the votes written once, instead
// of once per direction (a pass over the grid per direction, through three grid-sized
// arrays, took about twice as long).
inline void add_odd_crossing_votes(const std::vector<char>& shell, const std::array<int, 3>& dims,
                                   const std::vector<int>& directions, std::vector<std::uint8_t>& votes)
{
  const std::ptrdiff_t nx = dims[0], ny = dims[1], nz = dims[2], slice = nx * ny;
  int dk = 0; // the sweep goes against the directions' dk
  for(int direction : directions)
  {
    const int dz = grid_direction(direction)[2];
    CGAL_precondition(dz == 0 || dk == 0 || dz == dk);
    dk = dz != 0 ? dz : dk;
  }
  auto first = [](std::ptrdiff_t n, int d) { return d > 0 ? n - 1 : std::ptrdiff_t(0); };
  // parity of the runs from the voxel on, itself included: two slices per direction
  std::vector<char> parity(directions.size() * 2 * std::size_t(slice));
  for(std::ptrdiff_t k = first(nz, dk); k >= 0 && k < nz; k += dk > 0 ? -1 : 1)
  {
    const char* s_slice = shell.data() + k * slice;
    std::uint8_t* out_slice = votes.data() + k * slice;
    for(std::size_t n = 0; n < directions.size(); ++n)
    {
      const std::array<int, 3> d = grid_direction(directions[n]);
      const int di = d[0], dj = d[1];
      char* p_slice = parity.data() + (2 * n + std::size_t(k & 1)) * slice;
      const char* next_p_slice = d[2] == 0 ? p_slice : parity.data() + (2 * n + std::size_t((k & 1) ^ 1)) * slice;
      const char* next_s_slice = s_slice + d[2] * slice;
      if(d[2] != 0 && k + d[2] >= 0 && k + d[2] < nz)
      {
        // Every voxel of the slice reads the slice done before: one loop over the rows
        // whose rays stay in the grid, as if the slice were one row (the loop
        // vectorizes, and rows of about 100 voxels made the setup of a loop per row a
        // large part of the cost). Then the rays that leave the grid at once: the last
        // row, and the column that the loop wrapped into the next row.
        const std::ptrdiff_t j0 = dj < 0 ? 1 : 0, j1 = dj > 0 ? ny - 1 : ny, off = dj * nx + di;
        const std::ptrdiff_t lo = (std::max)(j0 * nx, -off), hi = (std::min)(j1 * nx, slice - off);
        char* p = p_slice;
        std::uint8_t* out = out_slice;
        const char *s = s_slice, *next_s = next_s_slice + off, *next_p = next_p_slice + off;
        for(std::ptrdiff_t v = lo; v < hi; ++v)
        {
          p[v] = char(next_p[v] ^ ((s[v] != 0) & (next_s[v] == 0)));
          out[v] = std::uint8_t(out[v] + next_p[v]);
        }
        if(dj != 0)
          for(std::ptrdiff_t v = first(ny, dj) * nx; v < first(ny, dj) * nx + nx; ++v)
            p[v] = s[v] != 0;
        if(di != 0)
          for(std::ptrdiff_t j = j0; j < j1; ++j)
          {
            const std::ptrdiff_t v = j * nx + first(nx, di);
            if(v >= lo && v < hi)
              out[v] = std::uint8_t(out[v] - next_p[v]);
            p[v] = s[v] != 0;
          }
        continue;
      }
      const std::ptrdiff_t sj = dj > 0 ? -1 : 1;
      for(std::ptrdiff_t j = first(ny, dj); j >= 0 && j < ny; j += sj)
      {
        const char* s = s_slice + j * nx;
        char* p = p_slice + j * nx;
        std::uint8_t* out = out_slice + j * nx;
        if(k + d[2] < 0 || k + d[2] >= nz || j + dj < 0 || j + dj >= ny)
        {
          for(std::ptrdiff_t i = 0; i < nx; ++i) // every ray leaves the grid at once
            p[i] = s[i] != 0;
          continue;
        }
        if(!dj && !d[2])
        {
          // Along x, each voxel needs the one before it in the row: a running parity in a
          // register, without branches (their mispredictions were most of the cost of
          // the two x directions), and no other row reads these parities. A row without
          // shell votes 0 (most rows of a grid that is mostly exterior).
          char any = 0;
          for(std::ptrdiff_t i = 0; i < nx; ++i)
            any |= s[i];
          if(!any)
            continue;
          std::uint8_t next_parity = s[first(nx, di)] != 0;
          for(std::ptrdiff_t i = first(nx, di) - di; i >= 0 && i < nx; i -= di)
          {
            out[i] = std::uint8_t(out[i] + next_parity);
            next_parity = std::uint8_t(next_parity ^ ((s[i] != 0) & (s[i + di] == 0)));
          }
          continue;
        }
        // w + d lies in a row done before: the voxels of this row are independent, and
        // the loop vectorizes. The voxel whose ray leaves the grid sideways votes 0.
        const char* next_s = next_s_slice + (j + dj) * nx + di;
        const char* next_p = next_p_slice + (j + dj) * nx + di;
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
}

// For every voxel, the number of the 26 grid directions in which the ray leaving it
// crosses an odd number of runs of `shell` voxels (a run: the consecutive shell voxels
// the ray meets at a time), i.e. the directions that vote "inside" in a parity count
// (Nooruddin and Turk, 2003). A closed shell gives 26 inside and 0 outside, but for rays
// that run along a face; a hole in the shell only changes the votes of the rays through
// it. The ray of voxel v starts at v + d; the votes of shell voxels (which may count
// their own run) are meaningless.
// Two sweeps over the z slices, one down for the directions going up along z, one up for
// those going down, each with half of the horizontal directions; in parallel, one thread
// each, with their own counts, added at the end.
template <class ConcurrencyTag = CGAL::Sequential_tag>
std::vector<std::uint8_t> odd_crossing_votes(const std::vector<char>& shell, const std::array<int, 3>& dims)
{
  // 0-8 go down along z, 9-16 are horizontal, 17-25 go up
  const std::vector<int> down{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12},
    up{13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25};
  std::vector<std::uint8_t> votes(shell.size(), 0);
  if(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    add_odd_crossing_votes(shell, dims, down, votes);
    add_odd_crossing_votes(shell, dims, up, votes);
    return votes;
  }
  std::vector<std::uint8_t> other_votes(shell.size(), 0);
  run_both<ConcurrencyTag>([&] { add_odd_crossing_votes(shell, dims, down, votes); },
                           [&] { add_odd_crossing_votes(shell, dims, up, other_votes); });
  for(std::size_t v = 0; v < votes.size(); ++v)
    votes[v] = std::uint8_t(votes[v] + other_votes[v]);
  return votes;
}

// Sums over windows of 2 lag + 1 values along `width` lines at a time (so that the loop
// over the lines vectorizes): the lines start at in[0], ..., in[width - 1] and their
// values are `in_step` apart; out[t * out_step + i] is the sum of values t - lag to
// t + lag of line i, within the line. `sum`: scratch of `width` values.
inline void window_sums(const std::int32_t* in, std::size_t in_step, std::int32_t* out, std::size_t out_step,
                        std::size_t width, std::size_t len, std::size_t lag, std::int32_t* sum)
{
  const std::size_t window = 2 * lag + 1;
  std::fill(sum, sum + width, 0);
  for(std::size_t t = 0; t < len + lag; ++t)
  {
    if(t < len)
    {
      const std::int32_t* add = in + t * in_step;
      for(std::size_t i = 0; i < width; ++i)
        sum[i] += add[i];
    }
    if(t >= window)
    {
      const std::int32_t* sub = in + (t - window) * in_step;
      for(std::size_t i = 0; i < width; ++i)
        sum[i] -= sub[i];
    }
    if(t >= lag)
    {
      std::int32_t* o = out + (t - lag) * out_step;
      for(std::size_t i = 0; i < width; ++i)
        o[i] = sum[i];
    }
  }
}

// The mean of `votes` over the (2r+1)^3 box around each voxel, counting only the voxels
// where `used` holds (0 where no voxel of the box is used), rounded to an integer.
// Separable window sums of (vote, count) pairs packed in one integer, in two passes
// over the grid: along x and y slice by slice (a slice stays in cache), then along z a
// chunk of columns at a time, with the division. Each pass is parallel over slices or
// chunks. (A pass per axis through two grid-sized integer arrays, running sums along x
// and an integer division per voxel took about twice as long.)
template <class ConcurrencyTag = CGAL::Sequential_tag>
std::vector<std::uint8_t> box_mean_votes(const std::vector<std::uint8_t>& votes, const std::vector<char>& used,
                                         const std::array<int, 3>& dims, int r)
{
  const std::size_t n = votes.size(), nx = std::size_t(dims[0]), ny = std::size_t(dims[1]),
                    nz = std::size_t(dims[2]), slice = nx * ny, lag = std::size_t(r), window = 2 * lag + 1;
  // vote sum * 2^12 + count: at most 26 * 11^3 * 2^12 + 11^3 < 2^31 for r <= 5
  std::vector<std::int32_t> xy(n);
  for_each_range<ConcurrencyTag>(nz, [&](std::size_t first, std::size_t last) {
    // a line along x with `lag` zeros on both sides, so that the window sums along x
    // are 2 lag + 1 shifted additions (the loops vectorize)
    std::vector<std::int32_t> along_x(slice), sum(nx), line(nx + 2 * lag, 0);
    for(std::size_t k = first; k < last; ++k)
    {
      const std::uint8_t* vote = votes.data() + k * slice;
      const char* use = used.data() + k * slice;
      for(std::size_t j = 0; j < ny; ++j)
      {
        const std::size_t row = j * nx;
        for(std::size_t i = 0; i < nx; ++i)
          line[lag + i] = std::int32_t(use[row + i] != 0) * ((std::int32_t(vote[row + i]) << 12) + 1);
        std::int32_t* out = along_x.data() + row;
        std::fill(out, out + nx, 0);
        for(std::size_t d = 0; d < window; ++d)
          for(std::size_t i = 0; i < nx; ++i)
            out[i] += line[i + d];
      }
      window_sums(along_x.data(), nx, xy.data() + k * slice, nx, nx, ny, lag, sum.data());
    }
  }, 1);
  std::vector<std::uint8_t> mean(n, 0);
  const std::size_t chunk = 2048, chunks = (slice + chunk - 1) / chunk;
  for_each_range<ConcurrencyTag>(chunks, [&](std::size_t first, std::size_t last) {
    std::vector<std::int32_t> column(chunk * nz), sum(chunk);
    for(std::size_t c = first; c < last; ++c)
    {
      const std::size_t begin = c * chunk, width = (std::min)(chunk, slice - begin);
      window_sums(xy.data() + begin, slice, column.data(), width, width, nz, lag, sum.data());
      // sum / count rounded half up, as std::lround: floor((2 sum + count) / (2 count)),
      // 0 without count. The quotient of these small integers (< 2^13) in float is
      // exact when it is an integer, and otherwise at least 1/250 from the next integer,
      // far beyond the rounding of a float: the floor is exact, and the loop vectorizes,
      // where an integer division per voxel was most of the cost of the box mean.
      for(std::size_t t = 0; t < nz; ++t)
      {
        const std::int32_t* a = column.data() + t * width;
        std::uint8_t* out = mean.data() + t * slice + begin;
        for(std::size_t i = 0; i < width; ++i)
        {
          const std::int32_t count = a[i] & 0xfff, divisor = 2 * count + (count == 0); // no count: 0 / 1
          out[i] = std::uint8_t(std::int32_t(float(2 * (a[i] >> 12) + count) / float(divisor)));
        }
      }
    }
  }, 1);
  return mean;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_PARITY_VOTE_H
