// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_DENSITY_CAP_H
#define CGAL_DF_L1_SKELETON_INTERNAL_DENSITY_CAP_H

/// \file density_cap.h
/// The points that the stages analyse when a cloud is far denser than its voxels can
/// show: one per cell of a fraction of the finest voxel. Not part of the public API.

#include <CGAL/DF_L1_skeleton/internal/cell_lattice.h>

#include <CGAL/assertions.h>

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

// The representatives of a cloud: in every cell of a lattice, the first eligible point in
// input order. An eligible point left out shares its cell with its representative (its
// owner), which stands for it: it lies within a cell diagonal of it. Linear in the
// points: one pass in input order.
class Density_cap
{
public:
  Density_cap() = default;

  // Over the `n` points `xyz(i)`, of which those with `eligible(i)` count (the others
  // are neither representatives nor owned). In force only when at most `max_kept_share`
  // of the eligible points are representatives; the lattice must fit in memory.
  template <class Xyz, class Eligible>
  Density_cap(const Cell_lattice& lattice, std::size_t n, const Xyz& xyz, const Eligible& eligible,
              double max_kept_share)
    : lattice_(lattice)
  {
    if(n == 0 || n > std::numeric_limits<std::uint32_t>::max())
      return;
    first_.assign(lattice_.size(), none);
    representative_.assign(n, 0);
    std::size_t eligible_points = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(!eligible(i))
        continue;
      ++eligible_points;
      std::uint32_t& first = first_[lattice_.index_of(xyz(i))];
      if(first != none)
        continue;
      first = std::uint32_t(representatives_.size());
      representative_[i] = 1;
      representatives_.push_back(i);
    }
    if(double(representatives_.size()) > max_kept_share * double(eligible_points)) // the plain cloud
    {
      std::vector<std::size_t>().swap(representatives_);
      std::vector<char>().swap(representative_);
      std::vector<std::uint32_t>().swap(first_);
    }
  }

  // whether the cap is in force (some eligible points are left out)
  bool active() const { return !representatives_.empty(); }
  // the input indices of the representatives, ascending (empty when not active())
  const std::vector<std::size_t>& representatives() const { return representatives_; }
  // whether the point of input index i is analysed (every point when not active())
  bool is_representative(std::size_t i) const { return !active() || representative_[i]; }
  // the position in representatives() of the owner of an eligible point left out, at `p`
  std::size_t owner(const std::array<double, 3>& p) const
  {
    const std::uint32_t first = first_[lattice_.index_of(p)];
    CGAL_assertion(first != none);
    return first;
  }

private:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  Cell_lattice lattice_;
  std::vector<std::size_t> representatives_;
  std::vector<char> representative_;
  std::vector<std::uint32_t> first_;
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_DENSITY_CAP_H
