// The quality tables of the closing notes, run by hand: the initial and the final
// skeleton (both methods) of every synthetic shape and variant, with the rule of the tests.
//   df_l1_test_pipeline "[.quality-table]"   df_l1_test_pipeline "[.quality-table-final]"
#include "evaluation/skeleton_quality.h"
#include "evaluation/synthetic_shapes.h"

#include <CGAL/DF_L1_skeleton.h>

#include <catch2/catch.hpp>

#include <functional>
#include <iostream>
#include <vector>

using namespace DF_L1_test;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::DF_L1::Skeleton_graph<K> Graph;

} // namespace

TEST_CASE("quality table of the initial skeleton", "[.quality-table]")
{
  const std::function<Skeleton_run<Graph>(const std::vector<Point_3>&)> initial_skeleton =
    [](const std::vector<Point_3>& points) {
      CGAL::DF_L1_skeletonization<K> skeletonization(points);
      Skeleton_run<Graph> run;
      run.graph = skeletonization.initial_skeleton().graph;
      run.voxel_size = CGAL::to_double(skeletonization.distance_field().voxel_size);
      return run;
    };
  std::cout << "Initial skeleton, 20000 points, seed 7 (topology e/j/c/k = ends/junctions/cycles/components)\n";
  const Quality_table table = run_quality_table(initial_skeleton, std::cout);
  CHECK(table.rows.size() == all_shapes().size() * all_variants().size());
}

// The table of the closing notes: the final skeleton of both methods on every shape and
// variant, with the same rule as the tests.
//   df_l1_test_pipeline "[.quality-table-final]"
TEST_CASE("quality table of the final skeleton, guided and plain L1-medial", "[.quality-table-final]")
{
  for(const auto method : {CGAL::DF_L1::Skeletonization_method::DISTANCE_FIELD_GUIDED,
                           CGAL::DF_L1::Skeletonization_method::L1_MEDIAL})
  {
    const std::function<Skeleton_run<Graph>(const std::vector<Point_3>&)> final_skeleton =
      [method](const std::vector<Point_3>& points) {
        CGAL::DF_L1_skeletonization<K> skeletonization(points, CGAL::parameters::skeletonization_method(method));
        Skeleton_run<Graph> run;
        run.graph = skeletonization.skeleton();
        run.voxel_size = CGAL::to_double(skeletonization.distance_field().voxel_size);
        return run;
      };
    std::cout << "Final skeleton ("
              << (method == CGAL::DF_L1::Skeletonization_method::L1_MEDIAL ? "plain L1-medial" : "distance-field guided")
              << "), 20000 points (2000 for sparse), seed 7\n";
    const Quality_table table = run_quality_table(final_skeleton, std::cout);
    CHECK(table.rows.size() == all_shapes().size() * all_variants().size());
  }
}
