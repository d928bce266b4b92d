// The whole pipeline on the real scans of ../shared/data (skipped, with a message, when
// the folder is absent): what must hold on any scan, and the topology the issue names
// for the fertility statue (genus 4).
#include "evaluation/scan_variants.h"
#include "evaluation/skeleton_quality.h"
#include "support/shared_data.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/bounding_box.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace DF = CGAL::DF_L1;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;

namespace {

// The points of a shared scan, or none when it is absent (the helper says so).
std::vector<Point> scan_points(const std::string& file)
{
  const std::string path = DF_L1_test::shared_data_file(file);
  return path.empty() ? std::vector<Point>() : DF::read_point_cloud<Kernel>(path).points;
}

} // namespace

TEST_CASE("real scans: one skeleton inside the occupied voxels, every point assigned", "[real][shared_data]")
{
    for(const std::string file : {"camel_scan.off", "fertility_partial_scan.off", "woman_scan.off", "dinopet_noisy.xyz",
                                "bunny_noisy.ply", "tree_scan.off", "lidar_tree_lille_2.xyz"})
  {
    const std::string path = DF_L1_test::shared_data_file(file);
    if(path.empty())
      continue;
    INFO(file);
    const auto cloud = DF::read_point_cloud<Kernel>(path);
    CGAL::DF_L1_skeletonization<Kernel> s(cloud.points);
    const DF::Skeleton_graph<Kernel>& g = s.skeleton();
    REQUIRE(boost::num_vertices(g) > 1);
    const auto& field = s.distance_field();
    std::size_t outside = 0;
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
    {
      const Point& p = g[v].point;
      REQUIRE((std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())));
      CHECK(g[v].radius > 0);
      const auto cell = field.locate(p);
      const DF::Voxel_label label = field.labels[field.index(cell[0], cell[1], cell[2])];
      outside += !(label == DF::Voxel_label::BOUNDARY || label == DF::Voxel_label::INTERIOR);
    }
    CHECK(outside == 0);
    std::vector<int> owner(cloud.points.size(), 0);
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
      for(std::size_t i : g[v].points)
        ++owner[i];
    const std::vector<bool>& outliers = s.outlier_flags();
    std::size_t wrong = 0;
    for(std::size_t i = 0; i < owner.size(); ++i)
      wrong += owner[i] != (outliers[i] ? 0 : 1);
    CHECK(wrong == 0);
    // the noisy scans are smoothed, the others are not (the LiDAR crown's twigs are
    // thinner than the neighbourhoods of the noise estimate, not noise)
    CHECK(s.denoised() == (file == "dinopet_noisy.xyz" || file == "bunny_noisy.ply"));
  }
}

TEST_CASE("real scans: the partial fertility scan gives one component with its 4 handles", "[real][shared_data]")
{
  const std::vector<Point> points = scan_points("fertility_partial_scan.off");
  if(points.empty())
    return;
  CGAL::DF_L1_skeletonization<Kernel> s(points);
  const DF::Skeleton_statistics st = DF::skeleton_statistics(s.skeleton());
  CHECK(st.components == 1);
  CHECK(st.cycles == 4);
}

TEST_CASE("real scans: the camel is a tree whose branches reach the four feet and the nose", "[real][shared_data]")
{
  const std::vector<Point> points = scan_points("camel_scan.off");
  if(points.empty())
    return;
  CGAL::DF_L1_skeletonization<Kernel> s(points);
  const DF::Skeleton_statistics st = DF::skeleton_statistics(s.skeleton());
  CHECK(st.components == 1);
  CHECK(st.cycles == 0);
  // legs, head and tail, and a few short branches where the legs touch and on the
  // unscanned flank (10 today; 9 before the shell took the local spacing, whose interior
  // reaches 1 % further into the flank)
  CHECK(st.end_points >= 6);
  CHECK(st.end_points <= 10);
  const auto& g = s.skeleton();
  std::vector<Point> ends;
  for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
    if(boost::degree(v, g) == 1)
      ends.push_back(g[v].point);
  const auto box = CGAL::bounding_box(points.begin(), points.end());
  const double diagonal = std::sqrt(CGAL::squared_distance(box.min(), box.max()));
  // the scan stands on y = min: the lower legs are thinner than two voxels, and the
  // curves must still run down them to the ground; the head points to x = max
  int on_the_ground = 0, at_the_nose = 0;
  for(const Point& e : ends)
  {
    on_the_ground += e.y() - box.ymin() < 0.02 * diagonal;
    at_the_nose += box.xmax() - e.x() < 0.03 * diagonal;
  }
  CHECK(on_the_ground == 4);
  CHECK(at_the_nose == 1);
  // separate extremities, not spurs beside one another
  for(std::size_t a = 0; a < ends.size(); ++a)
    for(std::size_t b = a + 1; b < ends.size(); ++b)
      CHECK(std::sqrt(CGAL::squared_distance(ends[a], ends[b])) > 0.05 * diagonal);
}

TEST_CASE("real scans: the tree is one skeleton through its twigs", "[real][shared_data]")
{
  const std::vector<Point> points = scan_points("tree_scan.off");
  if(points.empty())
    return;
  CGAL::DF_L1_skeletonization<Kernel> s(points);
  const DF::Skeleton_statistics st = DF::skeleton_statistics(s.skeleton());
  // most twigs are thinner than two voxels at V = 100
  CHECK(st.components == 1);
  CHECK(st.cycles == 0);
  CHECK(st.end_points >= 30);
}

TEST_CASE("real scans: the noisy scans of genus-0 objects give trees", "[real][shared_data]")
{
  // The expectations of ../shared/data/expected_topology.json that hold today: a cycle
  // around a tunnel of the noisy surface, or a hole narrower than the grid resolves, is
  // cut, and the pieces that smoothing leaves on a leg of the noisy horse are joined
  // through its occupied voxels, and the two halves of the noisy dinosaur's flat hand,
  // parted around a pocket, are one arm (ends: -1 when the file gives none).
  struct Expectation
  {
    const char* file;
    int ends;
  };
  for(const Expectation& e : {Expectation{"bunny_noisy.ply", -1}, Expectation{"corn_plant.off", -1},
                              Expectation{"dinopet_random_noise.xyz", 6}, Expectation{"horse_clean.off", 6},
                              Expectation{"horse_noisy.off", 6}, Expectation{"lamb.ply", -1},
                              Expectation{"dinopet_noisy_mesh.off", 6}})
  {
    const std::vector<Point> points = scan_points(e.file);
    if(points.empty())
      continue;
    INFO(e.file);
    CGAL::DF_L1_skeletonization<Kernel> s(points);
    const DF::Skeleton_statistics st = DF::skeleton_statistics(s.skeleton());
    CHECK(st.components == 1);
    CHECK(st.cycles == 0);
    if(e.ends >= 0)
      CHECK(std::abs(int(st.end_points) - e.ends) <= 1);
  }
}

TEST_CASE("real scans: the camel, missing most of a flank, is one tree", "[voxels][holes][real][shared_data]")
{
  const std::vector<Point> points = scan_points("camel_scan.off");
  if(points.empty())
    return;
  CGAL::DF_L1_skeletonization<Kernel> s(points);
  // Measured: 43,058 interior voxels and a deepest voxel 13.4 voxels inside (7,697 and
  // 3.7 before the parity vote: the body was a thin shell, its skeleton 14 pieces).
  CHECK(s.voxel_grid().count(DF::Voxel_label::INTERIOR) > 30000);
  CHECK(s.distance_field().maximum() > 10);
  const DF::Skeleton_statistics initial = DF::skeleton_statistics(s.initial_skeleton().graph);
  INFO("initial: " << initial.components << " components, " << initial.cycles << " cycles, " << initial.end_points
                   << " end points");
  CHECK(initial.components == 1);
  CHECK(initial.cycles == 0);
  CHECK(initial.end_points >= 5); // 4 legs and the head at least
  CHECK(initial.end_points <= 16); // with the hair of the thin lower legs, which the final skeleton prunes
  const DF::Skeleton_statistics final_skeleton = DF::skeleton_statistics(s.skeleton());
  INFO("final: " << final_skeleton.components << " components, " << final_skeleton.cycles << " cycles");
  CHECK(final_skeleton.components == 1);
  CHECK(final_skeleton.cycles == 0);
}

TEST_CASE("real scans: sparse and unevenly sampled scans keep their topology", "[real][shared_data]")
{
  // The shell of the voxelization closes the gaps between samples at the local spacing:
  // with one band for the whole cloud, the sparse half of a scan lost its inside (the
  // horse at 2,000 points: 3 pieces and 11 ends), and the occluded, sparse crowns of the
  // LiDAR trees kept 3 and 1 cycles. The variants are made by our own code
  // (tools/evaluation/scan_variants.h) from the shared files.
  struct Expectation
  {
    const char* file;
    const char* variant; // "-": the scan itself
    int cycles, ends;    // ends: -1 when the file gives none
  };
  for(const Expectation& e : {Expectation{"lidar_tree_13.xyz", "-", 0, -1}, Expectation{"lidar_tree_33.xyz", "-", 0, -1},
                              Expectation{"horse_clean.off", "sparse_2000", 0, 6}, Expectation{"horse_clean.off", "uneven", 0, 6},
                              Expectation{"horse_noisy.off", "sparse_2000", 0, 6},
                              Expectation{"fertility_partial_scan.off", "sparse_2000", 4, -1},
                              Expectation{"fertility_partial_scan.off", "uneven", 4, -1}})
  {
    const std::vector<Point> scan = scan_points(e.file);
    if(scan.empty())
      continue;
    INFO(e.file << " " << e.variant);
    std::vector<Point> points = scan;
    if(std::string(e.variant) != "-")
    {
      std::vector<std::array<double, 3>> xyz;
      for(const Point& p : scan)
        xyz.push_back({p.x(), p.y(), p.z()});
      std::size_t kept = 0;
      xyz = DF_L1_test::degrade_scan(xyz, e.variant, DF_L1_test::scan_seed(e.file), kept);
      REQUIRE(!xyz.empty());
      points.clear();
      for(const auto& p : xyz)
        points.emplace_back(p[0], p[1], p[2]);
    }
    CGAL::DF_L1_skeletonization<Kernel> s(points);
    const DF::Skeleton_statistics st = DF::skeleton_statistics(s.skeleton());
    CHECK(st.components == 1);
    CHECK(st.cycles == e.cycles);
    if(e.ends >= 0)
      CHECK(std::abs(int(st.end_points) - e.ends) <= 1);
  }
}
