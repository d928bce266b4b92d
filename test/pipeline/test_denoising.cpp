// Stage 0b: the surface-noise estimate and the smoothing onto local quadrics.
#include "evaluation/shape_corpus.h"
#include "support/threads.h"
#include "evaluation/synthetic_shapes.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/denoise_point_set.h>

#include <tbb/global_control.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace DF = CGAL::DF_L1;
using namespace DF_L1_test;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;

namespace {

Sample sample_of(const std::string& shape, Variant variant)
{
  return make_sample(shape_by_name(shape), variant, variant == Variant::sparse ? 2000 : 20000, 7);
}

// the finest voxel size at V = 100, the unit of the AUTOMATIC threshold
double finest_voxel(const std::vector<Point_3>& points)
{
  const CGAL::Bbox_3 b = CGAL::bbox_3(points.begin(), points.end());
  return std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()}) / 100;
}

double mean_surface_distance(const Shape& shape, const std::vector<Point_3>& points)
{
  double sum = 0;
  for(const Point_3& p : points)
    sum += std::abs(shape.signed_distance(p));
  return sum / double(points.size());
}

} // namespace

TEST_CASE("noise estimate: clean, sparse, holed and uneven samples are quiet, 1 % noise is not", "[denoising]")
{
  for(const std::string name : {"y_junction", "torus", "helix", "many_armed", "stick_figure"})
    for(Variant variant : all_variants())
    {
      if(variant == Variant::outliers) // outliers are flagged before the estimate
        continue;
      const Sample sample = sample_of(name, variant);
      const double noise = DF::estimate_surface_noise(sample.points) / finest_voxel(sample.points);
      INFO(name << ' ' << to_string(variant) << ": " << noise << " voxel");
      // the class smooths above 0.2 voxel
      if(variant == Variant::noise)
        CHECK(noise > 0.3);
      else
        CHECK(noise < 0.12);
    }
}

TEST_CASE("noise estimate: scales with the cloud and measures the added noise", "[denoising]")
{
  const Sample noisy = sample_of("capsule", Variant::noise);
  const double noise = DF::estimate_surface_noise(noisy.points);
  std::vector<Point_3> scaled;
  for(const Point_3& p : noisy.points)
    scaled.push_back(Point_3(3 * p.x(), 3 * p.y(), 3 * p.z()));
  CHECK(DF::estimate_surface_noise(scaled) == Approx(3 * noise).epsilon(1e-6));
  // the true deviation of the noisy points from the surface, RMS
  double squares = 0;
  for(const Point_3& p : noisy.points)
    squares += CGAL::square(shape_by_name("capsule").signed_distance(p));
  const double rms = std::sqrt(squares / double(noisy.points.size()));
  INFO("estimate " << noise << ", true RMS " << rms);
  // the fit follows part of the noise: a fraction of it, but a steady one
  CHECK(noise > 0.25 * rms);
  CHECK(noise < 0.75 * rms);
}

TEST_CASE("denoising: smoothed points lie closer to the surface, the same for any threads", "[denoising]")
{
  for(const std::string name : {"capsule", "torus", "star"})
  {
    const Sample noisy = sample_of(name, Variant::noise);
    const std::vector<Point_3> smoothed = DF::denoise_point_set(noisy.points);
    REQUIRE(smoothed.size() == noisy.points.size());
    const double before = mean_surface_distance(shape_by_name(name), noisy.points);
    const double after = mean_surface_distance(shape_by_name(name), smoothed);
    INFO(name << ": mean distance to the surface " << before << " -> " << after);
    CHECK(after < 0.75 * before);
    const std::vector<Point_3> one_thread =
      DF_L1_test::with_threads(1, [&] { return DF::denoise_point_set(noisy.points); });
    CHECK(one_thread == smoothed);
    CHECK(DF_L1_test::with_threads(2, [&] { return DF::denoise_point_set(noisy.points); }) == smoothed);
    CHECK(DF::denoise_point_set<CGAL::Sequential_tag>(noisy.points) == smoothed);
  }
  // a clean sample barely moves: the quadric follows the surface
  const Sample clean = sample_of("torus", Variant::clean);
  const std::vector<Point_3> smoothed = DF::denoise_point_set(clean.points);
  CHECK(mean_surface_distance(shape_by_name("torus"), smoothed) < 0.05 * finest_voxel(clean.points));
}

TEST_CASE("denoising: the class smooths only noisy clouds by default, as told otherwise", "[denoising]")
{
  const Sample noisy = sample_of("y_junction", Variant::noise);
  const Sample clean = sample_of("y_junction", Variant::clean);
  CGAL::DF_L1_skeletonization<Kernel> on_noisy(noisy.points);
  CHECK(on_noisy.denoised());
  CHECK(on_noisy.surface_noise() > 0.25 * finest_voxel(noisy.points));
  CHECK(on_noisy.kept_points().size() == noisy.points.size() - on_noisy.number_of_sparse_outliers());
  // the input is never changed: only rounded to the 2^-32 of the diagonal the stages work in
  REQUIRE(on_noisy.input_points().size() == noisy.points.size());
  double moved = 0;
  for(std::size_t i = 0; i < noisy.points.size(); ++i)
    moved = (std::max)(moved, std::sqrt(CGAL::squared_distance(on_noisy.input_points()[i], noisy.points[i])));
  CHECK(moved <= 1e-9 * on_noisy.bbox_diagonal());

  CGAL::DF_L1_skeletonization<Kernel> on_clean(clean.points);
  CHECK_FALSE(on_clean.denoised());
  CHECK(on_clean.kept_points().size() == clean.points.size() - on_clean.number_of_sparse_outliers());

  CGAL::DF_L1_skeletonization<Kernel> never(noisy.points, CGAL::parameters::denoising(DF::Denoising::NEVER));
  CHECK_FALSE(never.denoised());
  CGAL::DF_L1_skeletonization<Kernel> always(clean.points, CGAL::parameters::denoising(DF::Denoising::ALWAYS));
  CHECK(always.denoised());
  CHECK(always.kept_points() != on_clean.kept_points());

  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(clean.points, CGAL::parameters::denoising_neighbors(5)),
                  DF::Invalid_input);
  CHECK_THROWS_AS(DF::denoise_point_set(clean.points, CGAL::parameters::denoising_neighbors(300)), DF::Invalid_input);
  CHECK_THROWS_AS(DF::estimate_surface_noise(std::vector<Point_3>{Point_3(0, 0, NAN)}), DF::Invalid_input);
  CHECK(DF::estimate_surface_noise(std::vector<Point_3>(3, Point_3(1, 2, 3))) == 0);
}

TEST_CASE("denoising: thin parts sampled sparsely are not taken for noise", "[denoising]")
{
  // 2,000 points on a tree of 2 to 5 levels: fits to 16 neighbours span whole twigs
  // and leave residuals above a fifth of a voxel, but they grow with the neighbourhood
  // (the twigs' curvature), where noise would not; a noisy surface keeps its smoothing.
  const Shape tree = corpus_shape("trees", 14);
  const Degradation sparse = corpus_degradation("sparse_2000");
  const Sample thin = corpus_sample(tree, 14, sparse);
  CGAL::DF_L1_skeletonization<Kernel> on_thin(thin.points);
  CHECK(on_thin.surface_noise() > 0.2 * finest_voxel(thin.points));
  CHECK(on_thin.residual_growth() >= 3);
  CHECK_FALSE(on_thin.denoised());

  const Sample noisy = sample_of("y_junction", Variant::noise);
  CGAL::DF_L1_skeletonization<Kernel> on_noisy(noisy.points);
  CHECK(on_noisy.residual_growth() > 1);
  CHECK(on_noisy.residual_growth() < 3);
  CHECK(on_noisy.denoised());
}
