// Voxelization of degraded samples: the interior must survive one-sided holes, sparse
// and uneven sampling and noise, without filling the real holes of the shape.
#include "evaluation/synthetic_shapes.h"
#include "support/voxel_checks.h"

#include <CGAL/DF_L1_skeleton/compute_distance_field.h>
#include <CGAL/DF_L1_skeleton/upsample_sparse_regions.h>
#include <CGAL/DF_L1_skeleton/voxelize_point_set.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <iterator>
#include <vector>

namespace DF = CGAL::DF_L1;
using DF_L1_test::Point_3;
using DF_L1_test::Variant;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;

namespace {

// The sample with the points that upsampling adds, as the tool feeds the voxelization.
std::vector<Point_3> with_upsampling(const std::vector<Point_3>& points)
{
  std::vector<Point_3> all = points;
  DF::upsample_sparse_regions(points, std::back_inserter(all));
  return all;
}

double max_inscribed_radius(const DF_L1_test::Shape& shape)
{
  double r = 0;
  for(const auto& polyline : shape.skeleton_polylines())
    for(double x : polyline.radii)
      r = (std::max)(r, x);
  return r;
}

} // namespace

TEST_CASE("voxels: the interior survives holes, sparse and uneven sampling, and noise", "[voxels][variants]")
{
  // The dumbbell's balls are round chambers behind one-sided holes: the old depth test
  // found them shallow and swept them (9 skeleton pieces).
  const char* shapes[] = {"capsule", "torus", "figure_eight", "helix", "many_armed", "dumbbell"};
  const Variant variants[] = {Variant::holes, Variant::sparse, Variant::uneven, Variant::noise};
  for(const char* name : shapes)
    for(Variant variant : variants)
    {
      INFO(name << " / " << DF_L1_test::to_string(variant));
      const auto shape = DF_L1_test::shape_by_name(name);
      const auto sample = DF_L1_test::make_sample(shape, variant, 20000, 7);
      const auto grid = DF::voxelize_point_set(with_upsampling(sample.points));
      const auto field = DF::compute_distance_field(grid);
      const double s = grid.voxel_size;
      const bool noisy = variant == Variant::noise;

      // Deep inside, the distance field reaches most of the inscribed radius. Before the
      // interior was protected from holes and sampling gaps, it was 1 voxel on the
      // capsule and torus with holes and on the sparse helix and many-armed star.
      CHECK(field.maximum() >= (noisy ? 0.45 : 0.6) * max_inscribed_radius(shape) / s);

      const DF_L1_test::Interior_census census = DF_L1_test::interior_census(shape, grid);
      REQUIRE(census.deep > 0);
      // Noise puts points inside the shape, whose voxels are boundary, not interior.
      CHECK(double(census.deep_interior) >= (noisy ? 0.6 : 0.75) * double(census.deep));
      if(noisy) // the noisy shell encloses empty voxels up to about 3 sigma outside
        CHECK(census.worst <= 3 * 0.01 * shape.bbox_diagonal() / s + 1.5);
      else
        CHECK(double(census.outside) <= 0.05 * double(census.interior));

      CHECK(DF_L1_test::exterior_is_one_region(grid));
      // The real holes of the shape stay exterior.
      auto label_at = [&](const Point_3& p) {
        const auto c = grid.locate(p);
        return grid.label(c[0], c[1], c[2]);
      };
      if(std::string(name) == "torus")
        CHECK(label_at(Point_3(0, 0, 0)) == DF::Voxel_label::EXTERIOR);
      if(std::string(name) == "figure_eight")
      {
        CHECK(label_at(Point_3(0.45, 0, 0)) == DF::Voxel_label::EXTERIOR);
        CHECK(label_at(Point_3(-0.45, 0, 0)) == DF::Voxel_label::EXTERIOR);
      }
      if(std::string(name) == "helix") // between two coils, on the tube's outer radius
        CHECK(label_at(Point_3(0.35, 0, 0.075)) == DF::Voxel_label::EXTERIOR);
    }
}

TEST_CASE("voxels: the hole-aware sweep gives the same labels for 1 and 2 threads", "[voxels][determinism]")
{
  const auto shape = DF_L1_test::shape_by_name("helix");
  const auto points = with_upsampling(DF_L1_test::make_sample(shape, Variant::sparse, 20000, 7).points);
  const auto sequential = DF::voxelize_point_set<CGAL::Sequential_tag>(points);
  const auto parallel = DF::voxelize_point_set<CGAL::Parallel_if_available_tag>(points);
  CHECK(sequential.labels == parallel.labels);
  CHECK(sequential.dims == parallel.dims);
}
