// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_UNIFORM_GRID_H
#define CGAL_DF_L1_SKELETON_INTERNAL_UNIFORM_GRID_H

#include <CGAL/DF_L1_skeleton/internal/cell_lattice.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Points bucketed in cubic cells (counting sort, so building is O(N) and the order of the
// points inside a cell is their input order: queries are deterministic). For radius
// queries whose radius is comparable to the cell size this beats a kd-tree by a wide
// margin, which is the case of the fixed-radius searches of this package. The grid keeps
// a copy of the coordinates in cell order, so that a query reads them one after the
// other instead of at random places of the input (the input order of a scan or a
// generator is often random in space).
class Uniform_grid
{
public:
  // `cell_size` <= 0: cells for k-nearest searches, holding a few points each where
  // there are points (see coarsened_for_k_nearest()).
  // With ConcurrencyTag = CGAL::Parallel_tag, the cells of the points and the sorted copy
  // are computed in parallel (the same grid).
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  Uniform_grid(const std::vector<std::array<double, 3>>& points, double cell_size, ConcurrencyTag = ConcurrencyTag())
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
    const double max_cells = 4.0 * double(points.size()) + 64;
    cell_ = cell_size;
    if(!(cell_size > 0))
      cell_ = (std::max)({hi[0] - lo_[0], hi[1] - lo_[1], hi[2] - lo_[2]}) / max_cells;
    if(!(cell_ > 0))
      cell_ = 1; // all the points at one place
    for(;;)
    {
      double cells = 1;
      for(int a = 0; a < 3; ++a)
        cells *= std::floor((hi[a] - lo_[a]) / cell_) + 1;
      if(cells <= max_cells)
        break;
      cell_ *= 1.5;
    }
    if(!(cell_size > 0))
      cell_ = coarsened_for_k_nearest(points, hi);
    for(int a = 0; a < 3; ++a)
      dims_[a] = int(std::floor((hi[a] - lo_[a]) / cell_)) + 1;
    start_.assign(std::size_t(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    std::vector<std::size_t> cell_of(points.size());
    for_each_range<ConcurrencyTag>(points.size(), [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        cell_of[i] = cell_index(cell_coordinates(points[i]));
    }, 1 << 14);
    for(std::size_t c : cell_of)
      ++start_[c + 1];
    for(std::size_t c = 1; c < start_.size(); ++c)
      start_[c] += start_[c - 1];
    order_.resize(points.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for(std::size_t i = 0; i < points.size(); ++i)
      order_[fill[cell_of[i]]++] = i;
    sorted_.resize(points.size());
    for_each_range<ConcurrencyTag>(points.size(), [&](std::size_t begin, std::size_t end) {
      for(std::size_t s = begin; s < end; ++s)
        sorted_[s] = points[order_[s]];
    }, 1 << 14);
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

  // The `k` points nearest to `q` among those for which `keep(index)` holds, into
  // `nearest` as (squared distance, index) pairs sorted by distance, ties by index (fewer
  // than `k` when fewer are kept). The cells are searched in rings of growing Chebyshev
  // distance around the cell of `q`, skipping those farther than the k-th point found so
  // far, until the k-th distance is below the distance to every cell not searched yet.
  // The squared distance is (q - p)^2 summed over x, y, z in this order, as CGAL's
  // kd-tree computes it, so that the neighbours and their distances are those of a
  // kd-tree search up to the order of exactly tied points.
  template <class Keep>
  void k_nearest(const std::array<double, 3>& q, std::size_t k, const Keep& keep,
                 std::vector<std::pair<double, std::size_t>>& nearest) const
  {
    k_nearest_search<false>(q, k, keep, nearest);
  }

  // The same search in cell order: `keep` receives, and `nearest` holds, positions in
  // sorted_points() instead of indices (ties still ordered by index, so the points found
  // are those of k_nearest()). A caller that keeps its per-point data in cell order reads
  // and writes it at nearby places instead of all over a large cloud.
  template <class Keep>
  void k_nearest_positions(const std::array<double, 3>& q, std::size_t k, const Keep& keep,
                           std::vector<std::pair<double, std::size_t>>& nearest) const
  {
    k_nearest_search<true>(q, k, keep, nearest);
  }

  // The points in cell order: position s holds the point of index indices_by_cell()[s].
  const std::vector<std::array<double, 3>>& sorted_points() const { return sorted_; }

private:
  template <bool positions, class Keep>
  void k_nearest_search(const std::array<double, 3>& q, std::size_t k, const Keep& keep,
                        std::vector<std::pair<double, std::size_t>>& nearest) const
  {
    // (squared distance, index) order; a position is compared by its index
    const auto before = [&](const std::pair<double, std::size_t>& a, const std::pair<double, std::size_t>& b) {
      if(a.first != b.first)
        return a.first < b.first;
      return positions ? order_[a.second] < order_[b.second] : a.second < b.second;
    };
    if(k == 0)
    {
      nearest.clear();
      return;
    }
    std::array<double, 3> t; // q in cell units
    std::array<int, 3> c;    // the cell of q
    for(int a = 0; a < 3; ++a)
    {
      t[a] = (q[a] - lo_[a]) / cell_;
      c[a] = std::clamp(int(std::floor(t[a])), 0, dims_[a] - 1);
    }
    const double cell2 = cell_ * cell_;
    // The squared distance from q to the cells of coordinate i along axis a; a millionth
    // of a cell is taken off for the rounding of t.
    const auto gap2 = [&](int a, int i) {
      const double g = (std::max)((i > c[a] ? i - t[a] : i < c[a] ? t[a] - (i + 1) : 0) - 1e-6, 0.0);
      return g * g * cell2;
    };
    // nearest[0, found): the points found so far, sorted; kth: the squared distance of the
    // k-th one, infinite until k are found (no point or cell farther can be among the k).
    nearest.resize((std::min)(k, sorted_.size())); // no more can be found; no-op when reused
    std::size_t found = 0;
    double kth = std::numeric_limits<double>::infinity();
    const auto visit = [&](int i, int j, int l) {
      const std::size_t cell = cell_index({{i, j, l}});
      for(std::size_t s = start_[cell]; s < start_[cell + 1]; ++s)
      {
        const std::array<double, 3>& p = sorted_[s];
        double d2 = (q[0] - p[0]) * (q[0] - p[0]);
        d2 += (q[1] - p[1]) * (q[1] - p[1]);
        d2 += (q[2] - p[2]) * (q[2] - p[2]);
        if(d2 > kth)
          continue;
        const std::pair<double, std::size_t> point(d2, positions ? s : order_[s]);
        if((found == k && !before(point, nearest[k - 1])) || !keep(point.second))
          continue;
        std::size_t m = found < k ? found++ : k - 1; // sorted into place from the back
        for(; m > 0 && before(point, nearest[m - 1]); --m)
          nearest[m] = nearest[m - 1];
        nearest[m] = point;
        if(found == k)
          kth = nearest[k - 1].first;
      }
    };
    for(int r = 0;; ++r)
    {
      std::array<int, 3> lo, hi;
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = (std::max)(c[a] - r, 0);
        hi[a] = (std::min)(c[a] + r, dims_[a] - 1);
      }
      for(int l = lo[2]; l <= hi[2]; ++l)
      {
        const double z2 = gap2(2, l);
        if(z2 > kth)
          continue;
        for(int j = lo[1]; j <= hi[1]; ++j)
        {
          const double yz2 = z2 + gap2(1, j);
          if(yz2 > kth)
            continue;
          if(std::abs(l - c[2]) == r || std::abs(j - c[1]) == r) // the whole row is in the ring
          {
            // from the cell nearest to q outwards, while the cells may hold a point
            for(int i = c[0]; i <= hi[0] && yz2 + gap2(0, i) <= kth; ++i)
              visit(i, j, l);
            for(int i = c[0] - 1; i >= lo[0] && yz2 + gap2(0, i) <= kth; --i)
              visit(i, j, l);
          }
          else
          {
            if(c[0] - r >= 0 && yz2 + gap2(0, c[0] - r) <= kth)
              visit(c[0] - r, j, l);
            if(c[0] + r < dims_[0] && yz2 + gap2(0, c[0] + r) <= kth)
              visit(c[0] + r, j, l);
          }
        }
      }
      // The cells not searched yet lie beyond the faces of the searched box that are
      // inside the grid.
      double beyond = std::numeric_limits<double>::infinity();
      for(int a = 0; a < 3; ++a)
      {
        if(c[a] - r > 0)
          beyond = (std::min)(beyond, gap2(a, c[a] - r - 1));
        if(c[a] + r < dims_[a] - 1)
          beyond = (std::min)(beyond, gap2(a, c[a] + r + 1));
      }
      if(beyond == std::numeric_limits<double>::infinity() || beyond > kth)
      {
        nearest.resize(found);
        return;
      }
    }
  }

  // The finest cells (about 4 per point over the bounding box) are mostly empty on a
  // sampled surface, and a search then reads a scattered cell table as large as the
  // cloud: memory-bound, and slower per point as the cloud grows (20 s for 10M points
  // against 0.75 s for 1M). Doubling the cell size until the occupied cells hold
  // `per_cell` points on average keeps the table small and the searches to a few cells
  // of contiguous points, whatever the dimension of the sampled set. The occupancy is
  // counted on bit sets, one level from the previous. The neighbours found do not depend
  // on the cells.
  double coarsened_for_k_nearest(const std::vector<std::array<double, 3>>& points, const std::array<double, 3>& hi,
                                 double per_cell = 4) const
  {
    const Cell_lattice lattice(lo_, {{hi[0] - lo_[0], hi[1] - lo_[1], hi[2] - lo_[2]}}, cell_);
    Cell_occupancy occupancy = occupied_cells(lattice, points.size(), [&](std::size_t i) { return points[i]; });
    std::vector<bool>& occupied = occupancy.cells;
    std::size_t count = occupancy.count;
    std::array<std::size_t, 3> dims = lattice.dims();
    double cell = cell_;
    while(count > 1 && double(points.size()) < per_cell * double(count))
    {
      std::array<std::size_t, 3> coarse;
      for(int a = 0; a < 3; ++a)
        coarse[a] = (dims[a] + 1) / 2;
      std::vector<bool> merged(coarse[0] * coarse[1] * coarse[2], false);
      count = 0;
      for(std::size_t z = 0; z < dims[2]; ++z)
        for(std::size_t y = 0; y < dims[1]; ++y)
          for(std::size_t x = 0; x < dims[0]; ++x)
            if(occupied[(z * dims[1] + y) * dims[0] + x])
            {
              const std::size_t index = ((z / 2) * coarse[1] + y / 2) * coarse[0] + x / 2;
              count += !merged[index];
              merged[index] = true;
            }
      occupied.swap(merged);
      dims = coarse;
      cell *= 2;
    }
    return cell;
  }

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
      const std::array<double, 3>& p = sorted_[s];
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

  std::array<double, 3> lo_;
  std::array<int, 3> dims_ = {{1, 1, 1}};
  double cell_ = 1;
  std::vector<std::size_t> start_, order_;
  std::vector<std::array<double, 3>> sorted_; // the points in the order of order_
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_UNIFORM_GRID_H
