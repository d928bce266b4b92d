// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_EUCLIDEAN_DISTANCE_TRANSFORM_H
#define CGAL_DF_L1_SKELETON_INTERNAL_EUCLIDEAN_DISTANCE_TRANSFORM_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
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

// What a row needs: 0 when every f[q] is EDT_INFINITY (nothing), 1 when every f[q] is 0
// or above `limit` (the two scans), 2 otherwise (the lower envelope). No early exit: the
// loop vectorizes.
inline int row_kind(const float* f, int n, float limit)
{
  int finite = 0, other = 0;
  for(int q = 0; q < n; ++q)
  {
    finite += f[q] < EDT_INFINITY;
    other += (f[q] != 0) & (f[q] <= limit);
  }
  return other > 0 ? 2 : finite > 0 ? 1 : 0;
}

template <class ConcurrencyTag, class Function>
void for_each_row(std::size_t rows, const Function& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows, 64),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        std::vector<int> v;
                        std::vector<double> z, h;
                        std::vector<float> in, out;
                        for(std::size_t row = r.begin(); row != r.end(); ++row)
                          f(row, v, z, h, in, out);
                      });
    return;
  }
#endif
  std::vector<int> v;
  std::vector<double> z, h;
  std::vector<float> in, out;
  for(std::size_t row = 0; row < rows; ++row)
    f(row, v, z, h, in, out);
}

// In place: on input 0 at sites and EDT_INFINITY elsewhere; on output the exact squared
// Euclidean distance (in voxel units) to the nearest site. One separable pass per axis,
// each parallel over the independent rows of that axis; the result does not depend on
// the number of threads.
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
  const std::size_t nx = dims[0], ny = dims[1];
  const std::size_t strides[3] = {1, nx, nx * ny};
  for(int axis = 0; axis < 3; ++axis)
  {
    const std::size_t n = dims[axis];
    const std::size_t stride = strides[axis];
    // Consecutive rows along the fastest other axis: the strided reads and writes of the
    // passes along y and z then share cache lines between neighbouring rows.
    const int a1 = axis == 0 ? 1 : 0, a2 = 3 - axis - a1;
    const std::size_t n1 = dims[a1];
    for_each_row<ConcurrencyTag>(n1 * dims[a2], [&](std::size_t row, std::vector<int>& v,
                                                    std::vector<double>& z, std::vector<double>& h,
                                                    std::vector<float>& in,
                                                    std::vector<float>& out) {
      const std::size_t start = (row % n1) * strides[a1] + (row / n1) * strides[a2];
      in.resize(n);
      out.resize(n);
      for(std::size_t q = 0; q < n; ++q)
        in[q] = grid[start + q * stride];
      const int kind = row_kind(in.data(), int(n), limit);
      if(kind == 0)
        return;
      if(kind == 1)
        squared_distance_to_sites_1d(in.data(), out.data(), int(n));
      else
        squared_distance_transform_1d(in.data(), out.data(), int(n), limit, v, z, h);
      for(std::size_t q = 0; q < n; ++q)
        grid[start + q * stride] = out[q] > limit ? EDT_INFINITY : out[q];
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

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_EUCLIDEAN_DISTANCE_TRANSFORM_H
