// Upsampling of sparse regions.
#include "evaluation/synthetic_shapes.h"
#include "support/voxel_checks.h"

#include <CGAL/DF_L1_skeleton/compute_distance_field.h>
#include <CGAL/DF_L1_skeleton/extract_initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/flag_sparse_outliers.h>
#include <CGAL/DF_L1_skeleton/remove_outlier_voxels.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>
#include <CGAL/DF_L1_skeleton/upsample_sparse_regions.h>
#include <CGAL/DF_L1_skeleton/voxelize_point_set.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace DF = CGAL::DF_L1;
using DF_L1_test::Point_3;
using DF_L1_test::Variant;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;

namespace {

DF::Voxel_grid<Kernel> voxels_of(const std::vector<Point_3>& points)
{
  return DF::remove_outlier_voxels(DF::voxelize_point_set(points));
}

} // namespace

TEST_CASE("upsampling: fills a sparse part, leaves dense clouds and lone outliers alone", "[upsampling]")
{
  const auto shape = DF_L1_test::shape_by_name("capsule");
  const auto dense = DF_L1_test::make_sample(shape, DF_L1_test::Variant::clean, 20000, 2).points;
  std::vector<Point_3> added;
  DF::upsample_sparse_regions(dense, std::back_inserter(added));
  CHECK(added.empty());

  // A dense capsule and, far away, a sparse ring of 16 points (fewer than k = 5 others
  // within r = 3 d_bb / cbrt(N) of each): only the ring is densified.
  std::vector<Point_3> points = dense;
  for(int i = 0; i < 16; ++i)
    points.emplace_back(6 + 1.5 * std::cos(i * 0.3927), 1.5 * std::sin(i * 0.3927), 0);
  // and a lone outlier between them
  points.emplace_back(3, 3, 3);
  added.clear();
  DF::upsample_sparse_regions(points, std::back_inserter(added));
  CHECK(added.size() > 100);
  for(const Point_3& p : added)
  {
    REQUIRE(p.x() > 4); // only around the sparse blob
    REQUIRE(CGAL::squared_distance(p, Point_3(3, 3, 3)) > 0.25);
  }
}
