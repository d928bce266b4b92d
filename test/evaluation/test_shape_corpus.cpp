// The procedural corpus (tools/evaluation/shape_corpus.h): its shapes are what they claim
// to be, the same for the same arguments.
#include "evaluation/shape_corpus.h"
#include "evaluation/skeleton_quality.h"

#include <CGAL/DF_L1_skeleton.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

using namespace DF_L1_test;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

double longest_side(const CGAL::Bbox_3& b)
{
  return std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()});
}

} // namespace

TEST_CASE("corpus: every shape is built, sized and designed as documented", "[corpus]")
{
  int sheets = 0, cycles = 0, disjoint = 0, max_tips = 0;
  for(const std::string& family : corpus_families())
    for(int i = 0; i < corpus_shapes_per_family; ++i) {
      const Shape s = corpus_shape(family, i);
      INFO(s.name());
      REQUIRE(!s.primitives().empty());
      CHECK(s.name() == family + "_" + std::to_string(i));
      const double side = longest_side(s.bbox());
      CHECK(side > 1.0);
      CHECK(side < 3.6);
      // the designed topology is the graph of the axis curves
      const Topology t = s.expected_topology();
      CHECK(t == s.skeleton_topology());
      CHECK(t.components >= 1);
      // no tube thinner than the documented floor (the depth at the axis): 1.75 voxels of
      // the shape's own grid, built with the voxel of a previous build (within 5 % on all
      // shapes but one whose builds do not settle: 22 %)
      Corpus_sizes sizes;
      sizes.voxel = default_voxel_size(s);
      for(const Skeleton_polyline& pl : s.skeleton_polylines())
        if(pl.sheet_half_width == 0)
          for(double r : pl.radii)
            CHECK(r >= 0.75 * sizes.thinnest_radius());
      sheets += s.has_sheets();
      cycles += t.cycles > 0;
      disjoint += t.components > 1;
      if(family == "trees")
        max_tips = std::max(max_tips, t.end_points - 1);
    }
  CHECK(sheets == corpus_shapes_per_family); // the sheets family, and only it
  CHECK(cycles >= corpus_shapes_per_family);
  CHECK(disjoint == corpus_shapes_per_family);
  CHECK(max_tips >= 80);
}

TEST_CASE("corpus: shapes and samples are the same for the same arguments", "[corpus]")
{
  for(const std::string& family : corpus_families()) {
    const Shape a = corpus_shape(family, 5), b = corpus_shape(family, 5), c = corpus_shape(family, 5, 2);
    CHECK(a.primitives().size() == b.primitives().size());
    CHECK(a.bbox() == b.bbox());
    CHECK(!(a.bbox() == c.bbox())); // another corpus seed, another shape
    const Sample sa = make_sample(a, Variant::noise, 500, 3), sb = make_sample(b, Variant::noise, 500, 3);
    CHECK(sa.points == sb.points);
  }
}

TEST_CASE("corpus: close parts come within 1 to 2 voxels of each other", "[corpus]")
{
  // kind 1: a C whose two ends face each other across the gap; kind 2: a hairpin
  for(int i : {1, 2, 5, 6, 9, 10}) {
    const Shape s = corpus_shape("close_parts", i);
    INFO(s.name());
    const double voxel = default_voxel_size(s);
    const std::vector<Skeleton_polyline> axis = s.skeleton_polylines();
    REQUIRE(axis.size() == 1);
    const auto& pl = axis.front();
    // the two ends of the curve: those of the C, or the free ends of the hairpin's arms
    const double gap =
      std::sqrt(CGAL::squared_distance(pl.points.front(), pl.points.back())) - pl.radii.front() - pl.radii.back();
    CHECK(gap / voxel >= 0.95);
    CHECK(gap / voxel <= 2.05);
    // the solid does not close the gap: the mid-point between the ends is outside
    CHECK(!s.inside(CGAL::midpoint(pl.points.front(), pl.points.back())));
  }
  // kind 0: two legs side by side under a body; kind 3: two fingers on a palm. The
  // second and third curves are the pair: the free end of one is `gap` away from the
  // other (the fingers differ in length).
  for(int i : {0, 3, 4, 7, 8, 11}) {
    const Shape s = corpus_shape("close_parts", i);
    INFO(s.name());
    const double voxel = default_voxel_size(s);
    const std::vector<Skeleton_polyline> axis = s.skeleton_polylines();
    REQUIRE(axis.size() >= 3);
    const bool first_shorter = axis[1].points.back().y() < axis[2].points.back().y();
    const auto &p = first_shorter ? axis[1] : axis[2], &q = first_shorter ? axis[2] : axis[1];
    std::size_t nearest = 0;
    for(std::size_t k = 0; k < q.points.size(); ++k)
      if(CGAL::squared_distance(p.points.back(), q.points[k]) < CGAL::squared_distance(p.points.back(), q.points[nearest]))
        nearest = k;
    const double gap =
      std::sqrt(CGAL::squared_distance(p.points.back(), q.points[nearest])) - p.radii.back() - q.radii[nearest];
    CHECK(gap / voxel >= 0.95);
    CHECK(gap / voxel <= 2.05);
    CHECK(!s.inside(CGAL::midpoint(p.points.back(), q.points[nearest])));
  }
}

TEST_CASE("corpus: a plate's distance and surface samples", "[corpus]")
{
  Shape s("plate");
  s.add_slab(Point_3(0, 0, 0), Vector_3(1, 0, 0), Vector_3(0, 1, 0), 0.8, 0.3, 0.02, Point_3(-0.5, 0, 0), Point_3(0.5, 0, 0));
  CHECK(s.has_sheets());
  CHECK(s.signed_distance(Point_3(0, 0, 0)) == Approx(-0.02));
  CHECK(s.signed_distance(Point_3(0.1, 0.1, 0.5)) == Approx(0.48));
  CHECK(s.signed_distance(Point_3(0.9, 0, 0)) == Approx(0.08));
  CHECK(s.signed_distance(Point_3(0.9, 0.4, 0.1)) == Approx(std::sqrt(0.03) - 0.02));
  const CGAL::Bbox_3 b = s.bbox();
  CHECK(b.xmax() == Approx(0.82));
  CHECK(b.ymax() == Approx(0.32));
  CHECK(b.zmax() == Approx(0.02));
  const Sample sample = make_sample(s, Variant::clean, 20000, 1);
  std::size_t on_faces = 0;
  for(const Point_3& p : sample.points) {
    CHECK(std::abs(s.signed_distance(p)) < 1e-9);
    on_faces += std::abs(p.x()) <= 0.8 && std::abs(p.y()) <= 0.3;
  }
  // the faces hold 2 * 1.6 * 0.6 of the area, the rims and corners the rest
  const double faces = 1.92, rims = 2 * (1.6 + 0.6) * 3.14159265358979 * 0.02, corners = 4 * 3.14159265358979 * 0.0004;
  CHECK(double(on_faces) / double(sample.points.size()) == Approx(faces / (faces + rims + corners)).epsilon(0.03));
  // a curve skeleton anywhere near the mid-line covers it
  const std::vector<Skeleton_polyline> axis = s.skeleton_polylines();
  REQUIRE(axis.size() == 1);
  CHECK(axis.front().sheet_half_width == Approx(0.3));
}
