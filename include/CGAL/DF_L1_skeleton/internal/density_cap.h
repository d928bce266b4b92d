// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_DENSITY_CAP_H
#define CGAL_DF_L1_SKELETON_INTERNAL_DENSITY_CAP_H

/// \file density_cap.h
/// The points that the stages analyse when a cloud is far denser than its voxels can
/// show: a few per cell of a fraction of the finest voxel. Not part of the public API.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The representatives of a cloud: in every cubic cell, the first `capacity` eligible
// points in input order. An eligible point left out shares its cell with `capacity`
// representatives, the first of which (its owner) stands for it: it lies within a cell
// diagonal of it. Linear in the points: one pass in input order.
class Density_cap
{
public:
  Density_cap() = default;

  // Cells of size `cell` over the `n` points `xyz(i)` (an array of 3 doubles); only the
  // points with `eligible(i)` count, the others are neither representatives nor owned.
  // No cap (every eligible point a representative) when the cells would outnumber
  // `max_cells_per_point` times the points (the cloud is then sparser than a point per
  // cell on average, and a cell array that large would cost more than the points), nor
  // when more than `max_kept_share` of the points would be representatives.
  template <class Xyz, class Eligible>
  Density_cap(std::size_t n, const Xyz& xyz, const Eligible& eligible, double cell, std::size_t capacity,
              double max_cells_per_point, double max_kept_share)
    : cell_(cell)
  {
    if(n == 0 || !(cell > 0) || capacity == 0 || capacity > 255 || n > std::numeric_limits<std::uint32_t>::max())
      return;
    std::array<double, 3> hi = xyz(0);
    lo_ = hi;
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::array<double, 3> p = xyz(i);
      for(int a = 0; a < 3; ++a)
      {
        lo_[a] = (std::min)(lo_[a], p[a]);
        hi[a] = (std::max)(hi[a], p[a]);
      }
    }
    double cells = 1;
    for(int a = 0; a < 3; ++a)
    {
      const double d = std::floor((hi[a] - lo_[a]) / cell_) + 1;
      dims_[a] = d < 1e9 ? std::size_t(d) : std::size_t(1e9);
      cells *= d;
    }
    if(!(cells <= max_cells_per_point * double(n)))
      return;
    const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint8_t> count(dims_[0] * dims_[1] * dims_[2], 0);
    first_.assign(count.size(), none);
    representative_.assign(n, 0);
    representatives_.reserve(n / 4);
    for(std::size_t i = 0; i < n; ++i)
    {
      if(!eligible(i))
        continue;
      const std::size_t c = cell_of(xyz(i));
      if(count[c] >= capacity)
        continue;
      if(count[c]++ == 0)
        first_[c] = std::uint32_t(representatives_.size());
      representative_[i] = 1;
      representatives_.push_back(i);
    }
    if(double(representatives_.size()) > max_kept_share * double(n)) // not worth it: the plain cloud
    {
      std::vector<std::size_t>().swap(representatives_);
      std::vector<char>().swap(representative_);
      std::vector<std::uint32_t>().swap(first_);
    }
  }

  // whether some eligible points are left out
  bool active() const { return !representatives_.empty(); }
  // the input indices of the representatives, ascending (empty when not active())
  const std::vector<std::size_t>& representatives() const { return representatives_; }
  // whether the point of input index i is analysed (every point when not active())
  bool is_representative(std::size_t i) const { return !active() || representative_[i]; }
  // the position in representatives() of the owner of an eligible point left out, at `p`
  std::size_t owner(const std::array<double, 3>& p) const { return first_[cell_of(p)]; }

private:
  std::size_t cell_of(const std::array<double, 3>& p) const
  {
    std::size_t c[3];
    for(int a = 0; a < 3; ++a)
    {
      const double x = std::floor((p[a] - lo_[a]) / cell_);
      c[a] = x <= 0 ? 0 : (std::min)(std::size_t(x), dims_[a] - 1);
    }
    return (c[2] * dims_[1] + c[1]) * dims_[0] + c[0];
  }

  double cell_ = 0;
  std::array<double, 3> lo_ = {{0, 0, 0}};
  std::array<std::size_t, 3> dims_ = {{1, 1, 1}};
  std::vector<std::size_t> representatives_;
  std::vector<char> representative_;
  std::vector<std::uint32_t> first_;
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_DENSITY_CAP_H
