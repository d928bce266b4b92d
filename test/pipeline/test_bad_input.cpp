// Bad input to the stage functions throws Invalid_input, never crashes.
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

TEST_CASE("bad input to the stages throws Invalid_input", "[errors]")
{
  std::vector<Point_3> none;
  CHECK_THROWS_AS(DF::voxelize_point_set(none), DF::Invalid_input);
  std::vector<Point_3> same(10, Point_3(1, 2, 3));
  CHECK_THROWS_AS(DF::voxelize_point_set(same), DF::Invalid_input);
  std::vector<Point_3> nan{Point_3(0, 0, 0), Point_3(std::nan(""), 1, 1)};
  CHECK_THROWS_AS(DF::voxelize_point_set(nan), DF::Invalid_input);
  std::vector<Point_3> added;
  CHECK_THROWS_AS(DF::upsample_sparse_regions(nan, std::back_inserter(added)), DF::Invalid_input);
  const auto points = DF_L1_test::make_sample(DF_L1_test::shape_by_name("capsule"), DF_L1_test::Variant::clean, 3000, 1).points;
  CHECK_THROWS_AS(DF::voxelize_point_set(points, CGAL::parameters::voxel_resolution(2)), DF::Invalid_input);
  CHECK_THROWS_AS(DF::voxelize_point_set(points, CGAL::parameters::initial_voxel_size(-1.0)), DF::Invalid_input);
  const auto field = DF::compute_distance_field(voxels_of(points));
  CHECK_THROWS_AS(DF::extract_initial_skeleton(field, CGAL::parameters::thinning_coefficient(0.0)), DF::Invalid_input);
  CHECK_THROWS_AS(DF::extract_initial_skeleton(field, CGAL::parameters::surface_noise(-1.0)), DF::Invalid_input);
  CHECK_THROWS_AS(DF::extract_initial_skeleton(field, CGAL::parameters::surface_noise(std::nan(""))), DF::Invalid_input);
  // Flat and linear inputs have no interior: the documented result is an empty skeleton.
  std::vector<Point_3> flat;
  for(int i = 0; i < 50; ++i)
    for(int j = 0; j < 50; ++j)
      flat.emplace_back(i * 0.02, j * 0.02, 0);
  const auto flat_skeleton = DF::extract_initial_skeleton(DF::compute_distance_field(voxels_of(flat)));
  CHECK(flat_skeleton.points.empty());
  CHECK(boost::num_vertices(flat_skeleton.graph) == 0);
}
