// The grid walk behind the inside test of bridges (issue 4).
#include "evaluation/synthetic_shapes.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/internal/grid_walk.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace DF = CGAL::DF_L1;
using DF_L1_test::Point_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;

TEST_CASE("grid walk: visits a face-connected run of the voxels the segment meets", "[walk]")
{
  DF::Grid_geometry<Kernel> grid;
  grid.origin = Point_3(-1, -2, 0.5);
  grid.voxel_size = 0.25;
  grid.dims = {{40, 40, 40}};
  DF_L1_test::internal::Rng rng(5);
  for(int trial = 0; trial < 500; ++trial)
  {
    const auto random_point = [&] {
      return Point_3(-1 + 10 * rng.uniform(), -2 + 10 * rng.uniform(), 0.5 + 10 * rng.uniform());
    };
    const Point_3 p = random_point(), q = trial % 50 == 0 ? p : random_point();
    std::vector<std::array<int, 3>> cells;
    DF::internal::walk_segment(grid, p, q, [&](int i, int j, int k) {
      cells.push_back({{i, j, k}});
      return true;
    });
    REQUIRE(!cells.empty());
    CHECK(cells.front() == grid.locate(p));
    CHECK(cells.back() == grid.locate(q));
    for(std::size_t c = 1; c < cells.size(); ++c) // one face step at a time
      CHECK(std::abs(cells[c][0] - cells[c - 1][0]) + std::abs(cells[c][1] - cells[c - 1][1]) +
              std::abs(cells[c][2] - cells[c - 1][2]) == 1);
    // Points sampled along the segment fall in visited cells.
    const std::set<std::array<int, 3>> visited(cells.begin(), cells.end());
    for(int t = 0; t <= 200; ++t)
    {
      const double u = t / 200.0;
      const Point_3 x(p.x() + u * (q.x() - p.x()), p.y() + u * (q.y() - p.y()), p.z() + u * (q.z() - p.z()));
      const auto c = grid.locate(x);
      // a sample on a voxel face may round either way: accept a face neighbour of the path
      bool near = visited.count(c) > 0;
      for(int d = 0; d < 3 && !near; ++d)
        for(int side = -1; side <= 1 && !near; side += 2)
        {
          auto n = c;
          n[d] += side;
          near = visited.count(n) > 0;
        }
      CHECK(near);
    }
  }
}

TEST_CASE("grid walk: a bridge across the hole of a torus leaves the shape, one along the tube does not", "[walk]")
{
  const DF_L1_test::Shape torus = DF_L1_test::shape_by_name("torus");
  CGAL::DF_L1_skeletonization<Kernel> s(DF_L1_test::make_sample(torus, DF_L1_test::Variant::clean, 20000, 1).points);
  const auto& field = s.distance_field();
  // Two points of the centre circle, opposite and a few degrees apart.
  const auto polylines = torus.skeleton_polylines();
  REQUIRE(!polylines.empty());
  const std::vector<Point_3>& circle = polylines.front().points;
  REQUIRE(circle.size() > 40);
  const Point_3 a = circle[0], near_a = circle[2], opposite = circle[circle.size() / 2];
  CHECK(DF::internal::segment_stays_inside(field, field.labels, a, near_a));
  CHECK_FALSE(DF::internal::segment_stays_inside(field, field.labels, a, opposite));
  // Leaving the grid counts as leaving the shape.
  const Point_3 far(a.x() + 100 * CGAL::to_double(field.voxel_size) * field.dims[0], a.y(), a.z());
  CHECK_FALSE(DF::internal::segment_stays_inside(field, field.labels, a, far));
}
