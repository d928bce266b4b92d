// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_CELL_LATTICE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_CELL_LATTICE_H

/// \file cell_lattice.h
/// Cubic cells over a bounding box, and which of them hold points. Not part of the
/// public API.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Cubic cells of one size over the bounding box of a set of points; a position outside
// the box falls in the nearest cell.
class Cell_lattice
{
public:
  Cell_lattice() = default;

  // the lattice of cells of size `cell` over the box of lower corner `lo` and extent
  // `extent` (in the frame of the points it will locate)
  Cell_lattice(const std::array<double, 3>& lo, const std::array<double, 3>& extent, double cell)
    : cell_(cell), lo_(lo)
  {
    if(!(cell > 0))
      return;
    cells_ = 1;
    for(int a = 0; a < 3; ++a)
    {
      const double d = std::floor(extent[a] / cell_) + 1;
      dims_[a] = std::size_t((std::min)(d, 1e9));
      cells_ *= d;
    }
  }

  // the number of cells (a double: it may exceed what an array can hold)
  double cells() const { return cells_; }
  // the number of cells, once cells() is known to fit in memory (0 for an empty lattice)
  std::size_t size() const { return dims_[0] * dims_[1] * dims_[2]; }
  // the number of cells along each axis
  const std::array<std::size_t, 3>& dims() const { return dims_; }
  std::array<std::size_t, 3> cell_of(const std::array<double, 3>& p) const
  {
    std::array<std::size_t, 3> c;
    for(int a = 0; a < 3; ++a)
    {
      const double x = std::floor((p[a] - lo_[a]) / cell_);
      c[a] = x <= 0 ? 0 : (std::min)(std::size_t((std::min)(x, 1e18)), dims_[a] - 1);
    }
    return c;
  }
  std::size_t index(const std::array<std::size_t, 3>& c) const { return (c[2] * dims_[1] + c[1]) * dims_[0] + c[0]; }
  std::size_t index_of(const std::array<double, 3>& p) const { return index(cell_of(p)); }

private:
  double cell_ = 1, cells_ = 0;
  std::array<double, 3> lo_ = {{0, 0, 0}};
  std::array<std::size_t, 3> dims_ = {{0, 0, 0}}; // none: size() 0
};

// Which cells of a lattice hold a point, and how many do.
struct Cell_occupancy
{
  std::vector<bool> cells; // per cell index
  std::size_t count = 0;
};

// The cells of `lattice` (which must fit in memory) that hold one of the `n` points
// `xyz(i)`.
template <class Xyz>
Cell_occupancy occupied_cells(const Cell_lattice& lattice, std::size_t n, const Xyz& xyz)
{
  Cell_occupancy result;
  result.cells.assign(lattice.size(), false);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t c = lattice.index_of(xyz(i));
    result.count += !result.cells[c];
    result.cells[c] = true;
  }
  return result;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_CELL_LATTICE_H
