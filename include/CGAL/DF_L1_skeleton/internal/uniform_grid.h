// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_UNIFORM_GRID_H
#define CGAL_DF_L1_SKELETON_INTERNAL_UNIFORM_GRID_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Points bucketed in cubic cells (counting sort, so building is O(N) and the order of the
// points inside a cell is their input order: queries are deterministic). For radius
// queries whose radius is comparable to the cell size this beats a kd-tree by a wide
// margin, which is the case of the fixed-radius searches of this package.
class Uniform_grid
{
public:
  Uniform_grid(const std::vector<std::array<double, 3>>& points, double cell_size)
    : points_(points)
  {
    std::array<double, 3> hi;
    lo_ = hi = points.empty() ? std::array<double, 3>{{0, 0, 0}} : points[0];
    for(const auto& p : points)
      for(int a = 0; a < 3; ++a)
      {
        lo_[a] = (std::min)(lo_[a], p[a]);
        hi[a] = (std::max)(hi[a], p[a]);
      }
    // Never more cells than about 4 per point: a tiny radius must not allocate a huge grid.
    cell_ = cell_size > 0 ? cell_size : 1;
    const double max_cells = 4.0 * double(points.size()) + 64;
    for(;;)
    {
      double cells = 1;
      for(int a = 0; a < 3; ++a)
        cells *= std::floor((hi[a] - lo_[a]) / cell_) + 1;
      if(cells <= max_cells)
        break;
      cell_ *= 1.5;
    }
    for(int a = 0; a < 3; ++a)
      dims_[a] = int(std::floor((hi[a] - lo_[a]) / cell_)) + 1;
    start_.assign(std::size_t(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    std::vector<std::size_t> cell_of(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      cell_of[i] = cell_index(cell_coordinates(points[i]));
      ++start_[cell_of[i] + 1];
    }
    for(std::size_t c = 1; c < start_.size(); ++c)
      start_[c] += start_[c - 1];
    order_.resize(points.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for(std::size_t i = 0; i < points.size(); ++i)
      order_[fill[cell_of[i]]++] = i;
  }

  double cell_size() const { return cell_; }

  // The point indices cell by cell: queries made in this order reuse the cells in cache.
  const std::vector<std::size_t>& indices_by_cell() const { return order_; }

  // Calls f(index, squared distance) for every point within `radius` of `q`, cell by cell;
  // f returns false to stop the search early.
  template <class F>
  void for_each_in_ball(const std::array<double, 3>& q, double radius, const F& f) const
  {
    const double r2 = radius * radius;
    for_each_cell_in_ball(q, radius, [&](std::size_t c) { return for_each_in_cell(c, q, r2, f); });
  }

  // Whether at least `count` points lie within `radius` of `q`. The cell of `q` is
  // searched first: in a dense region it holds enough points, and the test costs one cell
  // instead of the whole ball.
  bool has_at_least(const std::array<double, 3>& q, double radius, std::size_t count) const
  {
    if(count == 0)
      return true;
    const double r2 = radius * radius;
    std::size_t found = 0;
    const auto counted = [&](std::size_t, double) { return ++found < count; }; // false: enough
    const std::size_t own = cell_index(cell_coordinates(q));
    if(!for_each_in_cell(own, q, r2, counted))
      return true;
    bool enough = false;
    for_each_cell_in_ball(q, radius, [&](std::size_t c) {
      enough = c != own && !for_each_in_cell(c, q, r2, counted);
      return !enough;
    });
    return enough;
  }

private:
  // Calls f(cell index) for every cell meeting the bounding box of the ball; f returns
  // false to stop.
  template <class F>
  void for_each_cell_in_ball(const std::array<double, 3>& q, double radius, const F& f) const
  {
    std::array<int, 3> lo, hi;
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = (std::max)(0, int(std::floor((q[a] - radius - lo_[a]) / cell_)));
      hi[a] = (std::min)(dims_[a] - 1, int(std::floor((q[a] + radius - lo_[a]) / cell_)));
      if(lo[a] > hi[a])
        return;
    }
    for(int k = lo[2]; k <= hi[2]; ++k)
      for(int j = lo[1]; j <= hi[1]; ++j)
        for(int i = lo[0]; i <= hi[0]; ++i)
          if(!f(cell_index({{i, j, k}})))
            return;
  }

  // Calls f(index, squared distance) for the points of cell `c` within sqrt(r2) of `q`;
  // false when f stopped the search.
  template <class F>
  bool for_each_in_cell(std::size_t c, const std::array<double, 3>& q, double r2, const F& f) const
  {
    for(std::size_t s = start_[c]; s < start_[c + 1]; ++s)
    {
      const std::array<double, 3>& p = points_[order_[s]];
      const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
      if(d2 <= r2 && !f(order_[s], d2))
        return false;
    }
    return true;
  }

  std::array<int, 3> cell_coordinates(const std::array<double, 3>& p) const
  {
    std::array<int, 3> c;
    for(int a = 0; a < 3; ++a)
      c[a] = std::clamp(int(std::floor((p[a] - lo_[a]) / cell_)), 0, dims_[a] - 1);
    return c;
  }
  std::size_t cell_index(const std::array<int, 3>& c) const
  {
    return (std::size_t(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
  }

  const std::vector<std::array<double, 3>>& points_;
  std::array<double, 3> lo_;
  std::array<int, 3> dims_ = {{1, 1, 1}};
  double cell_ = 1;
  std::vector<std::size_t> start_, order_;
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_UNIFORM_GRID_H
