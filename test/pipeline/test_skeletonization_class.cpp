// The DF_L1_skeletonization class: stages one by one, derived parameters, errors.
#include "evaluation/synthetic_shapes.h"

#include <CGAL/DF_L1_skeleton.h>

#include <catch2/catch.hpp>

#include <utility>
#include <vector>

namespace DF = CGAL::DF_L1;
using DF_L1_test::Point_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;

TEST_CASE("skeletonization class: stages run in order and on demand", "[class]")
{
  const std::vector<Point_3> points =
    DF_L1_test::make_sample(DF_L1_test::shape_by_name("y_junction"), DF_L1_test::Variant::outliers, 8000, 2).points;
  Skeletonization staged(points), direct(points);
  staged.flag_outliers();
  staged.upsample();
  staged.voxelize();
  staged.remove_outlier_voxels();
  staged.compute_distance_field();
  staged.extract_initial_skeleton();
  const auto& a = staged.initial_skeleton();
  const auto& b = direct.initial_skeleton(); // runs every stage before it
  CHECK(a.points == b.points);
  CHECK(boost::num_vertices(a.graph) == boost::num_vertices(b.graph));
  CHECK(boost::num_edges(a.graph) == boost::num_edges(b.graph));
  CHECK(staged.distance_field().values == direct.distance_field().values);

  // Every non-outlier input point belongs to exactly one skeleton vertex.
  std::vector<int> owners(points.size(), 0);
  for(std::size_t v = 0; v < boost::num_vertices(a.graph); ++v)
    for(std::size_t i : a.graph[v].points)
      ++owners[i];
  std::size_t outliers = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    outliers += staged.outlier_flags()[i];
    CHECK(owners[i] == (staged.outlier_flags()[i] ? 0 : 1));
  }
  CHECK(outliers == staged.number_of_outliers());
  CHECK(staged.number_of_sparse_outliers() <= outliers);
  CHECK(staged.outlier_voxel_statistics().components_kept == 1);
}

TEST_CASE("skeletonization class: derived lengths scale with the input", "[class][scale]")
{
  std::vector<Point_3> points =
    DF_L1_test::make_sample(DF_L1_test::shape_by_name("capsule"), DF_L1_test::Variant::clean, 5000, 1).points;
  std::vector<Point_3> scaled;
  for(const Point_3& p : points)
    scaled.emplace_back(1000 * p.x(), 1000 * p.y(), 1000 * p.z());
  Skeletonization unit(points), big(scaled);
  CHECK(big.bbox_diagonal() == Approx(1000 * unit.bbox_diagonal()));
  CHECK(big.initial_voxel_size() == Approx(1000 * unit.initial_voxel_size()));
  CHECK(unit.initial_voxel_size() == Approx(unit.bbox_diagonal() / 9));
  CHECK(big.upsampling_radius() == Approx(1000 * unit.upsampling_radius()));
  CHECK(big.outlier_component_size() == unit.outlier_component_size());
  CHECK(unit.outlier_component_size() >= 3);
  // A point on a voxel face may round to either side once scaled: compare counts.
  const auto interior = [](Skeletonization& s) { return double(s.voxel_grid().count(DF::Voxel_label::INTERIOR)); };
  CHECK(interior(big) == Approx(interior(unit)).epsilon(0.01));
  CHECK(CGAL::to_double(big.voxel_grid().voxel_size) == Approx(1000 * CGAL::to_double(unit.voxel_grid().voxel_size)));
}

TEST_CASE("skeletonization class: setters discard what depends on them", "[class]")
{
  const std::vector<Point_3> points =
    DF_L1_test::make_sample(DF_L1_test::shape_by_name("torus"), DF_L1_test::Variant::clean, 6000, 3).points;
  Skeletonization s(points);
  const std::size_t levels = s.voxel_grid().levels.size();
  REQUIRE(boost::num_vertices(s.initial_skeleton().graph) > 0);
  s.set_initial_voxel_size(s.bbox_diagonal() / 20); // finer s0: fewer refinement levels, same V
  CHECK(s.initial_voxel_size() == Approx(s.bbox_diagonal() / 20));
  CHECK(s.voxel_grid().levels.size() < levels);
  CHECK(boost::num_vertices(s.initial_skeleton().graph) > 0);
  s.set_outlier_component_size(0);
  CHECK(s.outlier_component_size() == 0);
  CHECK(s.outlier_voxel_statistics().components_removed == 0); // nothing is small enough now

  Skeletonization fixed(points, CGAL::parameters::outlier_component_size(7));
  CHECK(fixed.outlier_component_size() == 7);
}

TEST_CASE("skeletonization class: bad input and parameters throw Invalid_input", "[class][errors]")
{
  CHECK_THROWS_AS(Skeletonization(std::vector<Point_3>()), DF::Invalid_input);
  CHECK_THROWS_AS(Skeletonization(std::vector<Point_3>(5, Point_3(1, 2, 3))), DF::Invalid_input);
  const std::vector<Point_3> points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1)};
  CHECK_THROWS_AS(Skeletonization(points, CGAL::parameters::voxel_resolution(2)), DF::Invalid_input);
  CHECK_THROWS_AS(Skeletonization(points, CGAL::parameters::initial_voxel_size(-1.0)), DF::Invalid_input);
  CHECK_THROWS_AS(Skeletonization(points, CGAL::parameters::thinning_coefficient(0.0)), DF::Invalid_input);
  CHECK_THROWS_AS(Skeletonization(points, CGAL::parameters::spur_length_ratio(-1.0)), DF::Invalid_input);
  CHECK_THROWS_AS(Skeletonization(points, CGAL::parameters::outlier_component_size(-2)), DF::Invalid_input);
  CHECK_THROWS_AS(Skeletonization(points, CGAL::parameters::upsampling_neighbors(0)), DF::Invalid_input);
  std::vector<Point_3> tilted_plane; // coplanar, but not along an axis
  for(int i = 0; i < 30; ++i)
    for(int j = 0; j < 30; ++j)
      tilted_plane.emplace_back(i * 0.1, j * 0.1, 1 - 0.5 * i * 0.1 + 0.25 * j * 0.1);
  CHECK_THROWS_WITH(Skeletonization(tilted_plane), Catch::Contains("plane"));
  Skeletonization s(points);
  CHECK_THROWS_AS(s.set_upsampling_radius(0), DF::Invalid_input);
  CHECK_THROWS_AS(s.set_outlier_component_size(-1), DF::Invalid_input);
}
