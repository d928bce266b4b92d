// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_EUCLIDEAN_DISTANCE_TRANSFORM_H
#define CGAL_DF_L1_SKELETON_INTERNAL_EUCLIDEAN_DISTANCE_TRANSFORM_H

#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Squared distance of "no site in this row yet"; larger than any real squared distance
// in a grid of fewer than 2^12 voxels a side, yet exact in float arithmetic.
constexpr float EDT_INFINITY = 1e20f;

// Lower envelope of the parabolas y = f[q] + (x - q)^2 (Felzenszwalb & Huttenlocher
// 2012): the exact 1D squared distance transform in linear time. `v`, `z` and `h` are
// scratch; h[k] = f[v[k]] + v[k]^2 is kept rather than recomputed at each test.
// The intersection s of two parabolas is compared with z[k] by cross-multiplication
// (the denominator is positive), so that a division is made only for the parabola kept:
// the divisions were most of the cost of the transform. The f[q] above `limit` are left
// out (EDT_INFINITY always is).
inline void squared_distance_transform_1d(const float* f, float* d, int n, float limit, std::vector<int>& v,
                                          std::vector<double>& z, std::vector<double>& h)
{
  v.resize(n);
  z.resize(n + 1);
  h.resize(n);
  int k = -1;
  for(int q = 0; q < n; ++q)
  {
    if(f[q] > limit)
      continue;
    const double fq = double(f[q]) + double(q) * q;
    double numerator = 0, denominator = 1;
    while(k >= 0)
    {
      numerator = fq - h[k];
      denominator = 2.0 * (q - v[k]);
      if(numerator > z[k] * denominator)
        break;
      --k;
    }
    ++k;
    v[k] = q;
    h[k] = fq;
    z[k] = k == 0 ? -std::numeric_limits<double>::infinity() : numerator / denominator;
    z[k + 1] = std::numeric_limits<double>::infinity();
  }
  if(k < 0)
  {
    for(int q = 0; q < n; ++q)
      d[q] = EDT_INFINITY;
    return;
  }
  int j = 0;
  for(int q = 0; q < n; ++q)
  {
    while(z[j + 1] < q)
      ++j;
    const double dq = q - v[j];
    d[q] = float(dq * dq + f[v[j]]);
  }
}

// The same transform when every f[q] is 0 (a site) or left out, as in the first pass
// from a set of sites: the squared distance to the nearest site, in two scans.
inline void squared_distance_to_sites_1d(const float* f, float* d, int n)
{
  int last = -1;
  for(int q = 0; q < n; ++q)
  {
    if(f[q] == 0)
      last = q;
    d[q] = last < 0 ? EDT_INFINITY : float(q - last) * float(q - last);
  }
  last = -1;
  for(int q = n - 1; q >= 0; --q)
  {
    if(f[q] == 0)
      last = q;
    if(last >= 0)
      d[q] = (std::min)(d[q], float(last - q) * float(last - q));
  }
}

// What a row needs: 0 when the transform leaves it unchanged (every f[q] is
// EDT_INFINITY, or every f[q] is 0: after the first pass, most rows of a grid whose
// sites are the exterior), 1 when every f[q] is 0 or above `limit` (the two scans), 2
// otherwise (the lower envelope). No early exit: the loop vectorizes.
inline int row_kind(const float* f, int n, float limit)
{
  int finite = 0, zero = 0, other = 0;
  for(int q = 0; q < n; ++q)
  {
    finite += f[q] < EDT_INFINITY;
    zero += f[q] == 0;
    other += (f[q] != 0) & (f[q] <= limit);
  }
  return other > 0 ? 2 : finite > 0 && zero < n ? 1 : 0;
}

// Scratch of the 1D transforms, one per thread.
struct Transform_scratch
{
  std::vector<int> v;
  std::vector<double> z, h;
  std::vector<float> row, tile;
  std::vector<char> finite;
};

// Transforms, in place, the `count` rows of length n stored one after the other from
// `rows`, leaving out the values above `limit`; returns whether any row changed.
inline bool transform_rows(float* rows, std::size_t count, std::size_t n, float limit, Transform_scratch& s)
{
  bool changed = false;
  s.row.resize(n);
  for(std::size_t r = 0; r < count; ++r)
  {
    float* f = rows + r * n;
    const int kind = row_kind(f, int(n), limit);
    if(kind == 0)
      continue;
    changed = true;
    std::copy(f, f + n, s.row.begin());
    if(kind == 1)
      squared_distance_to_sites_1d(s.row.data(), f, int(n));
    else
      squared_distance_transform_1d(s.row.data(), f, int(n), limit, s.v, s.z, s.h);
    for(std::size_t q = 0; q < n; ++q)
      f[q] = f[q] > limit ? EDT_INFINITY : f[q];
  }
  return changed;
}

// The pass along y or z when no value can travel farther than `radius` voxels: the
// minimum of in[q + d] + d^2 over |d| <= radius, whole rows along x at a time (the
// loop vectorizes), for the `count` rows of nx values from `first`, `row_stride` apart.
// The rows far from every finite row are left as they are (EDT_INFINITY). With a small
// bound, this costs less than the lower envelope of each line: the same values, since
// both round the same sums to float once.
inline void windowed_pass(float* first, std::size_t count, std::size_t row_stride, std::size_t nx, int radius,
                          float limit, Transform_scratch& s)
{
  s.finite.assign(count, 0);
  bool any = false;
  for(std::size_t q = 0; q < count; ++q)
  {
    const float* row = first + q * row_stride;
    int finite = 0;
    for(std::size_t i = 0; i < nx; ++i)
      finite += row[i] < EDT_INFINITY;
    s.finite[q] = finite > 0;
    any = any || finite > 0;
  }
  if(!any)
    return;
  s.tile.resize(count * nx);
  for(std::size_t q = 0; q < count; ++q)
    if(s.finite[q])
      std::copy(first + q * row_stride, first + q * row_stride + nx, s.tile.begin() + q * nx);
  for(std::size_t q = 0; q < count; ++q)
  {
    const std::size_t lo = q > std::size_t(radius) ? q - radius : 0, hi = (std::min)(count - 1, q + radius);
    if(std::find(s.finite.begin() + lo, s.finite.begin() + hi + 1, 1) == s.finite.begin() + hi + 1)
      continue;
    float* out = first + q * row_stride;
    std::fill(out, out + nx, EDT_INFINITY);
    for(std::size_t p = lo; p <= hi; ++p)
    {
      if(!s.finite[p])
        continue;
      const float d2 = float((double(p) - double(q)) * (double(p) - double(q)));
      const float* in = s.tile.data() + p * nx;
      for(std::size_t i = 0; i < nx; ++i)
        out[i] = (std::min)(out[i], in[i] + d2);
    }
    for(std::size_t i = 0; i < nx; ++i)
      out[i] = out[i] > limit ? EDT_INFINITY : out[i];
  }
}

// Calls f(task, scratch) for every task in [0, tasks), in parallel with a Parallel_tag;
// the tasks of a range share one scratch.
template <class ConcurrencyTag, class Function>
void for_each_task(std::size_t tasks, const Function& f)
{
  for_each_range<ConcurrencyTag>(tasks, [&](std::size_t begin, std::size_t end) {
    Transform_scratch scratch;
    for(std::size_t task = begin; task < end; ++task)
      f(task, scratch);
  }, 1);
}

// In place: on input 0 at sites and EDT_INFINITY elsewhere; on output the exact squared
// Euclidean distance (in voxel units) to the nearest site. One separable pass per axis,
// each parallel over the independent rows of that axis; the result does not depend on
// the number of threads.
// The passes along y and z copy a tile of up to 256 rows, consecutive along x (a whole
// row of the grid up to V = 256), into a buffer, reading a run of the row per step along
// the axis: read one row at a time, every step of a z row fell on another page (nx * ny
// floats on), and those strided reads were most of the cost of the transform (with
// tiles, the 7 transforms of a 35k-point cloud at V = 100 take 36 % less time).
// With a `bound` (>= 0), for callers that only compare the distances with a threshold,
// the distances above it become EDT_INFINITY: a value above the bound after a pass only
// grows in the next ones, so it is left out of them, and the rows far from every site
// (most of the grid: the exterior) cost a scan. The distances up to the bound are
// unchanged.
template <class ConcurrencyTag>
void squared_euclidean_distance_transform(std::vector<float>& grid, const std::array<int, 3>& dims,
                                          float bound = EDT_INFINITY)
{
  const float limit = (std::min)(bound, std::nextafter(EDT_INFINITY, 0.f)); // EDT_INFINITY is left out
  const std::size_t nx = dims[0], ny = dims[1], nz = dims[2];
  constexpr std::size_t rows_per_task = 64, tile_width = 256;
  // A value at most `limit` is a sum f + d^2 with d^2 <= limit - (the lowest f); when
  // that reach is short, the passes along y and z take the windowed minimum.
  const float lowest = grid.empty() ? 0.f : (std::min)(0.f, *std::min_element(grid.begin(), grid.end()));
  const double reach = double(limit) - double(lowest);
  const int radius = reach < 13 * 13 ? int(std::floor(std::sqrt(reach))) : -1;

  // Along x, the rows are contiguous.
  for_each_task<ConcurrencyTag>((ny * nz + rows_per_task - 1) / rows_per_task, [&](std::size_t task,
                                                                                 Transform_scratch& s) {
    const std::size_t first = task * rows_per_task, count = (std::min)(rows_per_task, ny * nz - first);
    transform_rows(grid.data() + first * nx, count, nx, limit, s);
  });
  for(int axis = 1; axis < 3; ++axis)
  {
    const std::size_t n = dims[axis], stride = axis == 1 ? nx : nx * ny;
    const std::size_t other_stride = axis == 1 ? nx * ny : nx; // of the third axis
    if(radius >= 0)
    {
      for_each_task<ConcurrencyTag>(axis == 1 ? nz : ny, [&](std::size_t slab, Transform_scratch& s) {
        windowed_pass(grid.data() + slab * other_stride, n, stride, nx, radius, limit, s);
      });
      continue;
    }
    const std::size_t tiles_per_line = (nx + tile_width - 1) / tile_width;
    for_each_task<ConcurrencyTag>(tiles_per_line * (axis == 1 ? nz : ny), [&](std::size_t task,
                                                                              Transform_scratch& s) {
      const std::size_t x0 = (task % tiles_per_line) * tile_width, width = (std::min)(tile_width, nx - x0);
      float* corner = grid.data() + (task / tiles_per_line) * other_stride + x0;
      s.tile.resize(width * n);
      for(std::size_t q = 0; q < n; ++q)
        for(std::size_t c = 0; c < width; ++c)
          s.tile[c * n + q] = corner[q * stride + c];
      if(!transform_rows(s.tile.data(), width, n, limit, s))
        return;
      for(std::size_t q = 0; q < n; ++q)
        for(std::size_t c = 0; c < width; ++c)
          corner[q * stride + c] = s.tile[c * n + q];
    });
  }
}

// Squared Euclidean distances (voxel units) from every voxel of a grid of `dims` to the
// nearest voxel where `is_site(v)` holds; EDT_INFINITY everywhere when there is none, and
// where the distance is above `bound`.
template <class ConcurrencyTag, class IsSite>
std::vector<float> squared_distance_to_sites(const std::array<int, 3>& dims, const IsSite& is_site,
                                             float bound = EDT_INFINITY)
{
  std::vector<float> d(std::size_t(dims[0]) * dims[1] * dims[2]);
  for(std::size_t v = 0; v < d.size(); ++v)
    d[v] = is_site(v) ? 0.f : EDT_INFINITY;
  squared_euclidean_distance_transform<ConcurrencyTag>(d, dims, bound);
  return d;
}

// Squared distances to the nearest site, exact at the voxels where `needed(v)` holds
// (elsewhere they may be EDT_INFINITY beyond `first_bound`): the bounded transform
// first, cheaper with a small bound, and the unbounded one only when a needed voxel lies
// beyond the bound.
template <class ConcurrencyTag, class IsSite, class Needed>
std::vector<float> squared_distance_to_sites_at(const std::array<int, 3>& dims, const IsSite& is_site,
                                                const Needed& needed, float first_bound)
{
  std::vector<float> d = squared_distance_to_sites<ConcurrencyTag>(dims, is_site, first_bound);
  for(std::size_t v = 0; v < d.size(); ++v)
    if(d[v] == EDT_INFINITY && needed(v))
      return squared_distance_to_sites<ConcurrencyTag>(dims, is_site);
  return d;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_EUCLIDEAN_DISTANCE_TRANSFORM_H
