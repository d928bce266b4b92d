// The method on a sample of the procedural corpus (tools/evaluation/shape_corpus.h): a
// sample of families and degradations keeps the quality that the full run
// (scripts/quality.sh) measured; cases that earlier changes fixed stay fixed. The full
// corpus is not run here: it takes minutes.
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

// The share of the shape's end points that an end point of `g` stands for: pairs
// (tip, end) taken nearest first, each used once, no farther apart than `reach`.
template <class Graph>
double matched_tip_share(const Shape& shape, const Graph& g, double reach)
{
  std::vector<Point_3> tips;
  for(const Skeleton_node& n : shape.skeleton_nodes())
    if(n.degree == 1)
      tips.push_back(n.point);
  std::vector<std::size_t> ends;
  for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
    if(boost::degree(v, g) == 1)
      ends.push_back(v);
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for(std::size_t t = 0; t < tips.size(); ++t)
    for(std::size_t e = 0; e < ends.size(); ++e) {
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(tips[t], g[ends[e]].point)));
      if(d <= reach)
        pairs.emplace_back(d, t, e);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<char> tip_used(tips.size(), 0), end_used(ends.size(), 0);
  std::size_t matched = 0;
  for(const auto& p : pairs)
    if(!tip_used[std::get<1>(p)] && !end_used[std::get<2>(p)]) {
      tip_used[std::get<1>(p)] = end_used[std::get<2>(p)] = 1;
      ++matched;
    }
  return tips.empty() ? 1.0 : double(matched) / double(tips.size());
}

// The tip recall (within 5 voxels) of trees_`index` under `degradation`, skeletonized
// with the defaults, printed; `denoised`, when given, receives whether the cloud was
// smoothed.
double tree_tip_recall(int index, const std::string& degradation, bool* denoised = nullptr)
{
  const Shape shape = corpus_shape("trees", index);
  const Sample sample = corpus_sample(shape, index, corpus_degradation(degradation));
  CGAL::DF_L1_skeletonization<K> s(sample.points);
  if(denoised)
    *denoised = s.denoised();
  const double voxel = CGAL::to_double(s.distance_field().voxel_size);
  const double recall = matched_tip_share(shape, s.skeleton(), 5 * voxel);
  std::cout << shape.name() << ' ' << degradation << ": " << recall << " of the tips kept\n";
  return recall;
}

// The quality of the skeleton of a corpus case, measured as scripts/quality.sh does.
Skeleton_quality corpus_case_quality(const Shape& shape, int index, const Degradation& d)
{
  const Sample sample = corpus_sample(shape, index, d);
  CGAL::DF_L1_skeletonization<K> s(sample.points);
  Quality_options qo;
  qo.junction_merge_radius_fraction = 1.0;
  qo.merge_within_junction_zones = true;
  return measure_quality(shape, s.skeleton(), CGAL::to_double(s.distance_field().voxel_size), qo);
}

// The topology of the skeleton of a corpus case, after checking that it is the designed one.
Topology designed_topology_checked(const std::string& family, int index, const std::string& degradation)
{
  const Shape shape = corpus_shape(family, index);
  const Degradation d = corpus_degradation(degradation);
  const Skeleton_quality q = corpus_case_quality(shape, index, d);
  INFO(shape.name() << ' ' << degradation << ": " << compact(q.topology) << " expected " << compact(shape.expected_topology()));
  CHECK(corpus_topology_matches(shape, q.topology, d.noisy));
  return q.topology;
}

} // namespace

TEST_CASE("corpus: a sample of families and degradations keeps its quality", "[corpus]")
{
  // One shape per family under three degradations, with the defaults. The floors are
  // the sample's figures in the last full run (benchmark/QUALITY.md), less a margin:
  // a change that loses cases here has to show its full table.
  const std::vector<Degradation> all = corpus_degradations();
  std::vector<Degradation> picked;
  for(const Degradation& d : all)
    if(d.name == "clean" || d.name == "noise_0.6" || d.name == "outliers_3")
      picked.push_back(d);
  int cases = 0, passes = 0;
  double outside = 0, coverage = 0;
  for(const std::string& family : corpus_families()) {
    const int index = 7;
    const Shape shape = corpus_shape(family, index);
    for(const Degradation& d : picked) {
      const Skeleton_quality q = corpus_case_quality(shape, index, d);
      const bool ok = corpus_topology_matches(shape, q.topology, d.noisy);
      std::cout << "corpus sample " << shape.name() << ' ' << d.name << ": " << compact(q.topology) << " expected "
                << compact(shape.expected_topology()) << (ok ? " ok" : " FAIL") << ", coverage " << q.axis_coverage
                << ", outside " << q.outside_fraction << '\n';
      ++cases;
      passes += ok;
      outside += q.outside_fraction;
      coverage += q.axis_coverage;
      CHECK(q.outside_fraction < 0.2);
    }
  }
  std::cout << "corpus sample: " << passes << "/" << cases << " designed topology\n";
  CHECK(passes >= 19);
  CHECK(coverage / cases >= 0.80);
  CHECK(outside / cases <= 0.03);
}

TEST_CASE("corpus: the short twigs of trees with many tips keep their ends", "[corpus]")
{
  // The twigs are 1.75 voxels in radius and stick out 4 to 8 voxels beyond their parent:
  // their curves may end where they are the deepest within a few voxels (not within the
  // 4-voxel blocks that reach the parent), a hair beside a twig tip, that the tip's
  // short branch and the twig cover as much as the hair, is pruned before the tip, and a
  // twig that thinning ate from its flat tip gets its branch back, also when it leaves a
  // sibling it was fused with (its excess counted from one radius of the fused part, its
  // path sqrt(2) voxels deep). The floor of each tree guards against a collapse; the mean
  // is the measure (0.92, 0.80, 0.90 and 0.87 today; 0.85, 0.67, 0.78 and 0.79 with the
  // excess from 1.5 radii and paths 1.5 voxels deep; 0.71 on average without the
  // branches given back).
  double sum = 0;
  for(int index : {14, 15, 19, 23}) {
    const double recall = tree_tip_recall(index, "clean");
    CHECK(recall >= 0.7);
    sum += recall;
  }
  CHECK(sum / 4 >= 0.84);
}

TEST_CASE("corpus: the twigs of smoothed noisy trees keep their ends", "[corpus]")
{
  // Smoothed, a twig 1.75 voxels in radius is 1.4 voxels deep in the occupied voxels:
  // its curve may end there when its radius (not its depth less one, 0.4 voxel) is 0.6
  // of the deepest nearby, and the bumps of the noise are told from twig tips by their
  // height over the noise. The twigs that the thinning still eats get their branches back
  // where the points surround them as a tube. Kept at 0.3 % noise: 0.22 to 0.59 of the
  // tips at first, 0.55 to 0.83 with the curve ends, 0.66 to 0.94 (mean 0.80) with the
  // twigs given back.
  double sum = 0;
  for(int index : {3, 14, 22, 23}) {
    bool denoised = false;
    const double recall = tree_tip_recall(index, "noise_0.3", &denoised);
    CHECK(denoised);
    CHECK(recall >= 0.6);
    sum += recall;
  }
  CHECK(sum / 4 >= 0.74);
  // trees whose twigs all come back (12 of 16 ends, 27 of 28 and 16 of 17 without)
  designed_topology_checked("trees", 1, "noise_0.3");
  designed_topology_checked("trees", 2, "noise_0.6");
  designed_topology_checked("trees", 10, "noise_1.0");
  // The ragged shell of a noisy frame or palm surrounds a curve through it as a twig's
  // surface does, but spreads beyond it: without that test, 3 ends on the frame of
  // loops_12 and 6 on close_parts_19 (3 designed) at 1 % noise. (The test of the radius
  // against the noise is the real-scan test of the noisy dinosaurs: a finger on a hand.)
  designed_topology_checked("loops", 12, "noise_1.0");
  designed_topology_checked("close_parts", 19, "noise_1.0");
}

TEST_CASE("corpus: a plate thinned to pieces is joined through its occupied voxels", "[corpus]")
{
  // Smoothed, a plate two or three voxels thick keeps too few voxels a voxel deep to hold
  // one curve; the pieces lie in one component of the occupied voxels. Disjoint objects
  // stay apart.
  auto components = [](const std::string& family, int index, const std::string& degradation) {
    const Shape shape = corpus_shape(family, index);
    const Degradation d = corpus_degradation(degradation);
    const Sample sample = corpus_sample(shape, index, d);
    CGAL::DF_L1_skeletonization<K> s(sample.points);
    const CGAL::DF_L1::Skeleton_statistics st = CGAL::DF_L1::skeleton_statistics(s.skeleton());
    INFO(shape.name() << ' ' << degradation);
    CHECK(st.cycles == std::size_t(shape.expected_topology().cycles));
    return int(st.components);
  };
  for(int index : {1, 2, 5})
    CHECK(components("sheets", index, "noise_0.3") == 1);
  for(int index : {0, 1})
    CHECK(components("disjoint", index, "noise_0.3") == corpus_shape("disjoint", index).expected_topology().components);
}

TEST_CASE("corpus: a ring whose ends come 1 to 2 voxels close is cut open, clean or noisy, legs that touch are parted, closed rings keep their loops", "[corpus]")
{
  // The voxels of the two ends of the C touch: the pocket between them is taken for
  // interior and the initial skeleton closes the ring. The points show the gap.
  const auto run = designed_topology_checked;
  for(int index : {1, 5}) {
    CHECK(run("close_parts", index, "clean").cycles == 0);
    CHECK(run("close_parts", index, "outliers_3").cycles == 0);
  }
  // Under 0.3 % noise the gap holds points too, far fewer than the two caps that bound it:
  // a valley of the points' abscissas along the ring (gaps of 1.4 and 2 voxels).
  for(int index : {21, 25})
    CHECK(run("close_parts", index, "noise_0.3").cycles == 0);
  // A shallower valley (a third as dense as its walls) is a gap only where the surfaces
  // bounding it face along the curve; the walls of a loop's thin handle run beside it.
  for(int index : {1, 13})
    CHECK(run("close_parts", index, "noise_0.3").cycles == 0);
  CHECK(run("loops", 1, "noise_0.6").cycles >= 1);
  CHECK(run("loops", 12, "noise_1.0").cycles >= 1);
  // Two legs side by side under a body: where their voxels touch, the walls that face
  // each other across the gap are denser than the gap is wide.
  for(int index : {0, 8})
    CHECK(run("close_parts", index, "outliers_3").cycles == 0);
  // Where the web between the legs is a voxel thin, the points beside the gap lie a
  // voxel from the curve's line, as a thin tube's walls would; the line that joins the
  // two legs through the web shows the gap.
  for(int index : {4, 16})
    CHECK(run("close_parts", index, "clean").cycles == 0);
  for(int index = 0; index < 5; ++index) // rings, handles, frames and ladders, 1 to 5 cycles
    CHECK(run("loops", index, "clean").cycles >= 1);
}

TEST_CASE("corpus: the pores between the samples of a sparse plate close no loop; a loop wider than the sampling keeps its own", "[corpus]")
{
  // At 2,000 points the samples of a plate lie 2 to 3 voxels apart, and the thinning of
  // its porous voxels kept a loop around each pore (sheets_4: 1 cycle, sheets_13: 4);
  // the disks of those loops lie in the solid closed by the sampling spacing. The hole
  // of loops_6 is the narrowest of its family that a closing of 1.5 spacings filled.
  const auto run = designed_topology_checked;
  for(int index : {4, 13}) {
    CHECK(run("sheets", index, "sparse_2000").cycles == 0);
    CHECK(run("sheets", index, "uneven_2000").cycles == 0);
  }
  CHECK(run("loops", 6, "sparse_2000").cycles == 1);
  CHECK(run("loops", 2, "sparse_2000").cycles == 5);
}

TEST_CASE("corpus: twigs whose tips meet across a gap are parted where their tip surfaces face each other", "[corpus]")
{
  // Twigs thinner than two voxels are 1 voxel deep, less than the distance of the points
  // that bound the gap between two tips to the curve that crosses it; the tips' surfaces
  // face along that curve, a thin tube's wall runs beside it.
  for(const char* degradation : {"clean", "outliers_3", "holes"})
    CHECK(designed_topology_checked("trees", 20, degradation).cycles == 0);
}

TEST_CASE("corpus: the halves of a curve cut across the gap between two legs go with the cut; a twig cut at its tip stays", "[corpus]")
{
  // The curve crossed the web between the front legs of close_parts_20 (1.8 voxels
  // apart); the cut left a half on each leg, whose tip faces the other leg's surface and
  // passed the spur pruning: 4 ends and 2 junctions instead of 3 and 1.
  const Topology legs = designed_topology_checked("close_parts", 20, "clean");
  CHECK(legs.end_points == 3);
  CHECK(legs.junctions == 1);
  // A twig whose tip touched another branch is cut at its tip: the half on its side is
  // the whole twig, far beyond the balls around its fork (the branch across the gap is
  // near, and must not count). trees_20 with holes and outliers, which lost a tip when
  // the whole graph's balls counted, are checked by the test of twigs meeting above.
  designed_topology_checked("trees", 24, "noise_0.6");
}

TEST_CASE("corpus: the sparse half of an unevenly sampled 2,000-point cloud keeps its inside", "[corpus]")
{
  // Density falling 10:1 along the longest side at 2,000 points: the sparse end's samples
  // lie 3 to 5 voxels apart. With one band for the voxelization's shell (from the median
  // spacing), the rays of the parity vote and the lines of sight passed between them and
  // the skeleton lost the inside there (each case below failed: a body, a ring, a scene
  // of 3 objects, a handle); the shell now takes each boundary voxel's own spacing.
  const auto run = designed_topology_checked;
  run("thick_limbs", 0, "uneven_2000");
  run("tapering", 0, "uneven_2000");
  run("loops", 0, "uneven_2000");
  run("disjoint", 1, "uneven_2000");
  run("close_parts", 4, "uneven_2000");
}

TEST_CASE("corpus: the end of a thick body keeps its branch in the skeleton graph", "[corpus]")
{
  // A capsule's stub beyond the junction where its limbs or its handle leave it is 2 to 3
  // of its radii long and its tip as deep as that junction: the initial skeleton kept it,
  // and the graph's hair rule (longer than the junction's radius plus the tip's diameter)
  // dropped it. The tip's radius now counts up to half the junction's. Each case failed.
  const auto run = designed_topology_checked;
  run("loops", 6, "clean");
  run("loops", 6, "holes");
  run("tapering", 17, "holes");
  run("tapering", 17, "sparse_2000");
}
