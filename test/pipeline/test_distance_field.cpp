// The distance field: within a voxel of the analytic distance, exact against brute
// force, the same for any number of threads.
#include "evaluation/synthetic_shapes.h"
#include "support/threads.h"
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

TEST_CASE("distance field: within a voxel of the analytic distance", "[distance]")
{
  for(const char* name : {"capsule", "torus"})
  {
    INFO(name);
    const auto shape = DF_L1_test::shape_by_name(name);
    const auto sample = DF_L1_test::make_sample(shape, DF_L1_test::Variant::clean, 20000, 5);
    const auto grid = voxels_of(sample.points);
    const auto field = DF::compute_distance_field<CGAL::Sequential_tag>(grid);
    const double s = grid.voxel_size;
    std::size_t interior = 0, within_one = 0;
    double worst = 0;
    for(std::size_t v = 0; v < grid.size(); ++v)
    {
      if(grid.labels[v] != DF::Voxel_label::INTERIOR)
      {
        REQUIRE(field.values[v] == 0.f);
        continue;
      }
      ++interior;
      // Distances are measured between voxel centres, and a boundary voxel's centre is
      // up to half a voxel diagonal (0.87) off the surface it holds.
      const double error = std::abs(CGAL::to_double(field.distance(v)) + shape.signed_distance(grid.center(v))) / s;
      worst = (std::max)(worst, error);
      within_one += error <= 1.0;
    }
    CHECK(worst <= 2.0);
    CHECK(double(within_one) >= 0.97 * double(interior));
  }
}

TEST_CASE("distance field: the same for 1 and 2 threads", "[distance][determinism]")
{
  const auto shape = DF_L1_test::shape_by_name("stick_figure");
  const auto sample = DF_L1_test::make_sample(shape, DF_L1_test::Variant::noise, 15000, 9);
  const auto grid = voxels_of(sample.points);
  const auto sequential = DF::compute_distance_field<CGAL::Sequential_tag>(grid);
  const auto parallel =
    DF_L1_test::with_threads(2, [&] { return DF::compute_distance_field<CGAL::Parallel_if_available_tag>(grid); });
  CHECK(sequential.values == parallel.values);
}

TEST_CASE("distance transform: exact against brute force, with and without a bound", "[distance]")
{
  namespace I = CGAL::DF_L1::internal;
  // Wider than one tile of the y and z passes (256 rows), and small along y and z.
  const std::array<int, 3> dims = {{270, 7, 9}};
  const std::size_t n = std::size_t(dims[0]) * dims[1] * dims[2];
  auto coordinates = [&](std::size_t v) {
    return std::array<long, 3>{{long(v % dims[0]), long(v / dims[0] % dims[1]), long(v / dims[0] / dims[1])}};
  };
  std::uint32_t state = 12345;
  auto next = [&]() { return state = state * 1664525u + 1013904223u; };
  for(int trial = 0; trial < 6; ++trial)
  {
    // Sites (0) and, from trial 2 on, starting values: positive, and negative as in the
    // power distance of balls. Integers, so that the transform is exact in floats.
    std::vector<float> start(n, I::EDT_INFINITY);
    for(std::size_t v = 0; v < n; ++v)
    {
      const std::uint32_t r = next() >> 8;
      if(r % 400 == 0)
        start[v] = 0;
      else if(trial >= 2 && r % 400 == 1)
        start[v] = float(int(next() >> 8) % 41 - 20);
    }
    if(trial == 1) // one row of sites only: most rows stay empty
    {
      std::fill(start.begin(), start.end(), I::EDT_INFINITY);
      for(int i = 0; i < dims[0]; ++i)
        start[std::size_t(i) + dims[0] * 3] = 0;
    }
    const float bound = trial % 2 == 0 ? I::EDT_INFINITY : trial == 5 ? 0.f : 30.f;
    std::vector<float> exact(n, I::EDT_INFINITY);
    for(std::size_t w = 0; w < n; ++w)
    {
      if(start[w] > bound || start[w] >= I::EDT_INFINITY)
        continue;
      const auto b = coordinates(w);
      for(std::size_t u = 0; u < n; ++u)
      {
        const auto a = coordinates(u);
        const long d2 = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
        exact[u] = (std::min)(exact[u], start[w] + float(d2));
      }
    }
    for(float& d : exact)
      d = d > bound ? I::EDT_INFINITY : d;
    std::vector<float> sequential = start, parallel = start;
    I::squared_euclidean_distance_transform<CGAL::Sequential_tag>(sequential, dims, bound);
    I::squared_euclidean_distance_transform<CGAL::Parallel_if_available_tag>(parallel, dims, bound);
    INFO("trial " << trial);
    CHECK(sequential == exact);
    CHECK(parallel == exact);
  }
}

TEST_CASE("distance transform: exact where needed, bounded first and unbounded when a needed voxel is beyond", "[distance]")
{
  namespace I = CGAL::DF_L1::internal;
  // Sites: the plane z = 0. Needed: the voxels of the plane z = depth, at distance depth^2.
  const std::array<int, 3> dims = {{12, 10, 14}};
  const std::size_t slice = std::size_t(dims[0]) * dims[1];
  const auto site = [&](std::size_t v) { return v < slice; };
  const std::vector<float> unbounded = I::squared_distance_to_sites<CGAL::Sequential_tag>(dims, site);
  for(int depth : {3, 12})
  {
    const auto needed = [&](std::size_t v) { return v / slice == std::size_t(depth); };
    const std::vector<float> d = I::squared_distance_to_sites_at<CGAL::Parallel_if_available_tag>(dims, site, needed, 25.f);
    INFO("depth " << depth);
    for(std::size_t v = 0; v < d.size(); ++v)
      if(needed(v))
        REQUIRE(d[v] == float(depth * depth)); // beyond the first bound (25) at depth 12
    // the bounded transform is kept when it is enough: nothing is computed beyond the bound
    CHECK((depth == 3) == (std::count(d.begin(), d.end(), I::EDT_INFINITY) > 0));
    CHECK((depth == 3) != (d == unbounded));
  }
}
