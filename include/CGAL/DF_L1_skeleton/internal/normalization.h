// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_NORMALIZATION_H
#define CGAL_DF_L1_SKELETON_INTERNAL_NORMALIZATION_H

// The frame the skeletonization works in: the points moved to the centre of their
// bounding box, divided by its diagonal, and rounded to multiples of 2^-32. Products of
// lengths then neither overflow nor underflow, whatever the magnitude of the input (1e300
// or 1e-300), and a cloud scaled by any factor gives the same internal cloud: the scaling
// and the division differ by a few units in the last place, which the rounding removes
// (but for a coordinate within those units of a multiple of 2^-32, one in about 2^18).
// Without the rounding, such differences reach the discrete decisions of the method (a
// voxel boundary, a tie) and move a vertex by 1e-5 of the diagonal. Scaling by a power of
// two is exact throughout: the same skeleton, bit for bit.

#include <CGAL/DF_L1_skeleton/Contracted_samples.h>
#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/Initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/errors.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Internal coordinates are multiples of this, 2.3e-10 of the diagonal: far below the
// precision of any scanner (float32 coordinates keep 6e-8 of the extent).
constexpr double coordinate_quantum = 0x1p-32;

template <class FT>
FT quantized(const FT& x)
{
  if constexpr(std::is_floating_point<FT>::value)
    return std::nearbyint(x / coordinate_quantum) * coordinate_quantum;
  else
    return x;
}

// The diagonal of a box without squaring its sides; +inf when a side overflows.
inline double overflow_free_diagonal(const CGAL::Bbox_3& b)
{
  const double d[3] = {b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()};
  const double m = (std::max)({d[0], d[1], d[2]});
  if(!(m > 0) || !std::isfinite(m))
    return m;
  return m * std::sqrt(CGAL::square(d[0] / m) + CGAL::square(d[1] / m) + CGAL::square(d[2] / m));
}

class Normalization
{
public:
  Normalization() = default;

  // The frame of the points of `box`. Throws when the extent of the box exceeds the
  // largest double: such a cloud cannot be represented even as differences.
  Normalization(const CGAL::Bbox_3& box, const std::string& stage)
  {
    const double diagonal = overflow_free_diagonal(box);
    if(!std::isfinite(diagonal))
    {
      std::ostringstream out;
      out.precision(3);
      out << stage << ": the points span [" << box.xmin() << ", " << box.xmax() << "] x [" << box.ymin() << ", "
          << box.ymax() << "] x [" << box.zmin() << ", " << box.zmax()
          << "], an extent beyond the largest double (1.8e308); it cannot be represented";
      throw Invalid_input(out.str());
    }
    if(!(diagonal > 0))
      return; // the caller refuses coincident points
    if(diagonal < std::numeric_limits<double>::min())
    {
      std::ostringstream out;
      out.precision(3);
      out << stage << ": the points span a box of diagonal " << diagonal
          << ", below the smallest normal double (2.2e-308); it cannot be represented";
      throw Invalid_input(out.str());
    }
    scale_ = diagonal;
    center_ = {{box.xmin() / 2 + box.xmax() / 2, box.ymin() / 2 + box.ymax() / 2, box.zmin() / 2 + box.zmax() / 2}};
  }

  double scale() const { return scale_; }
  const std::array<double, 3>& center() const { return center_; }

  double to_internal(double length) const { return length / scale_; }
  double to_input(double length) const { return length * scale_; }

  template <class Point>
  Point to_internal(const Point& p) const
  {
    typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
    return Point(quantized(FT((p.x() - FT(center_[0])) / FT(scale_))),
                 quantized(FT((p.y() - FT(center_[1])) / FT(scale_))),
                 quantized(FT((p.z() - FT(center_[2])) / FT(scale_))));
  }

  template <class Point>
  Point to_input(const Point& p) const
  {
    typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
    return Point(FT(p.x() * FT(scale_) + FT(center_[0])), FT(p.y() * FT(scale_) + FT(center_[1])),
                 FT(p.z() * FT(scale_) + FT(center_[2])));
  }

  template <class Point>
  std::vector<Point> to_input(const std::vector<Point>& points) const
  {
    std::vector<Point> mapped;
    mapped.reserve(points.size());
    for(const Point& p : points)
      mapped.push_back(to_input(p));
    return mapped;
  }

  template <class Traits>
  void to_input_in_place(Grid_geometry<Traits>& grid) const
  {
    grid.origin = to_input(grid.origin);
    typedef typename Traits::FT FT;
    grid.voxel_size = FT(grid.voxel_size * FT(scale_));
  }

  template <class Traits>
  Voxel_grid<Traits> to_input(Voxel_grid<Traits> grid) const
  {
    to_input_in_place(grid);
    for(Voxelization_level& level : grid.levels)
      level.voxel_size = to_input(level.voxel_size);
    return grid;
  }

  template <class Traits>
  Distance_field<Traits> to_input(Distance_field<Traits> field) const
  {
    to_input_in_place(field);
    return field;
  }

  template <class Traits>
  Skeleton_graph<Traits> to_input(Skeleton_graph<Traits> graph) const
  {
    for(auto [v, end] = boost::vertices(graph); v != end; ++v)
    {
      graph[*v].point = to_input(graph[*v].point);
      graph[*v].radius = typename Traits::FT(graph[*v].radius * typename Traits::FT(scale_));
    }
    return graph;
  }

  template <class Traits>
  Initial_skeleton<Traits> to_input(const Initial_skeleton<Traits>& initial) const
  {
    Initial_skeleton<Traits> mapped;
    mapped.points = to_input(initial.points);
    mapped.voxels = initial.voxels;
    mapped.graph = to_input(initial.graph);
    for(int i = 0; i < 3; ++i)
      mapped.thinning_parameters[i] = to_input(initial.thinning_parameters[i]);
    return mapped;
  }

  template <class Traits>
  Contracted_samples<Traits> to_input(const Contracted_samples<Traits>& samples) const
  {
    Contracted_samples<Traits> mapped = samples;
    mapped.points = to_input(samples.points);
    for(double& h : mapped.support_radii)
      h = to_input(h);
    for(Contraction_stage& stage : mapped.stages)
    {
      stage.min_radius = to_input(stage.min_radius);
      stage.mean_radius = to_input(stage.mean_radius);
      stage.max_radius = to_input(stage.max_radius);
    }
    for(std::vector<typename Traits::Point_3>& iteration : mapped.iterations)
      iteration = to_input(iteration);
    mapped.initial_support_radius = to_input(samples.initial_support_radius);
    return mapped;
  }

private:
  std::array<double, 3> center_ = {{0, 0, 0}};
  double scale_ = 1;
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_NORMALIZATION_H
