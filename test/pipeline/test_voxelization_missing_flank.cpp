// Voxelization of scans that miss a region of the surface as wide as a part (a whole
// flank): the parity vote keeps the part's interior, without closing the real holes of
// the shape; and the vote itself on small voxel shells.
#include "evaluation/synthetic_shapes.h"
#include "support/threads.h"
#include "support/voxel_checks.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/internal/euclidean_distance_transform.h>
#include <CGAL/DF_L1_skeleton/internal/parity_vote.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_morphology.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace DF = CGAL::DF_L1;
using DF_L1_test::Point_3;
using DF_L1_test::Vector_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;

namespace {

// The clean sample of `shape` without the points whose surface normal lies within 60
// degrees of `side` and whose position passes `in_patch`: a flank open over 120 degrees
// around the part's axis.
std::vector<Point_3> without_flank(const DF_L1_test::Shape& shape, const std::function<Vector_3(const Point_3&)>& side,
                                   const std::function<bool(const Point_3&)>& in_patch)
{
  const auto sample = DF_L1_test::make_sample(shape, DF_L1_test::Variant::clean, 20000, 5);
  std::vector<Point_3> kept;
  for(std::size_t i = 0; i < sample.points.size(); ++i)
    if(!(in_patch(sample.points[i]) && sample.normals[i] * side(sample.points[i]) > 0.5))
      kept.push_back(sample.points[i]);
  return kept;
}

// The interior of a part behind a missing flank: nearly every voxel more than 2 voxels
// deep is interior, none bulges more than 2 voxels out of the gap, the exterior is one
// region.
template <class Grid>
void check_kept_interior(const DF_L1_test::Shape& shape, const Grid& grid)
{
  const DF_L1_test::Interior_census c = DF_L1_test::interior_census(shape, grid);
  const double deep_interior = c.deep > 0 ? double(c.deep_interior) / double(c.deep) : 0;
  INFO("deep interior " << deep_interior << ", worst outside " << c.worst);
  CHECK(deep_interior >= 0.95);
  CHECK(c.worst <= 2.0);
  CHECK(DF_L1_test::exterior_is_one_region(grid));
}

template <class Graph>
void check_topology(const Graph& g, std::size_t components, std::size_t cycles, std::size_t end_points)
{
  const DF::Skeleton_statistics st = DF::skeleton_statistics(g);
  INFO(st.components << " components, " << st.cycles << " cycles, " << st.end_points << " end points");
  CHECK(st.components == components);
  CHECK(st.cycles == cycles);
  CHECK(st.end_points == end_points);
}

} // namespace

TEST_CASE("voxels: a capsule missing a whole flank keeps its interior and one axis", "[voxels][holes]")
{
  // Radius 0.15 (11.5 voxels at V = 100), the flank facing +z missing over 70 % of the
  // length: a slot 1.7 radii wide. Before the parity vote, the coarse flood leaked into
  // the capsule and the balls swept the rest: no deep voxel stayed interior, and the
  // skeleton was 37 pieces.
  DF_L1_test::Shape shape("slotted_capsule", {2, 0, 0, 1});
  shape.add_round_cone(Point_3(-0.5, 0, 0), Point_3(0.5, 0, 0), 0.15, 0.15);
  const std::vector<Point_3> points = without_flank(
    shape, [](const Point_3&) { return Vector_3(0, 0, 1); }, [](const Point_3& p) { return std::abs(p.x()) < 0.35; });
  CGAL::DF_L1_skeletonization<Kernel> s(points);
  const auto& grid = s.voxel_grid();
  check_kept_interior(shape, grid);
  CHECK(s.distance_field().maximum() >= 0.7 * 0.15 / CGAL::to_double(grid.voxel_size));
  check_topology(s.initial_skeleton().graph, 1, 0, 2);
}

TEST_CASE("voxels: a torus missing its outer flank keeps its tube and its hole", "[voxels][holes]")
{
  // The flank facing away from the axis is missing over half of the ring. Before the
  // parity vote: 35 % of the deep voxels interior, 30 skeleton pieces and 22 cycles.
  const DF_L1_test::Shape shape = DF_L1_test::torus();
  const Vector_3 axis = Vector_3(0.2, 0.1, 1) / std::sqrt(1.05);
  auto outward = [axis](const Point_3& p) {
    const Vector_3 r = (p - CGAL::ORIGIN) - ((p - CGAL::ORIGIN) * axis) * axis;
    return r / std::sqrt(r.squared_length());
  };
  const std::vector<Point_3> points = without_flank(shape, outward, [](const Point_3& p) { return p.y() > 0; });
  CGAL::DF_L1_skeletonization<Kernel> s(points);
  const auto& grid = s.voxel_grid();
  check_kept_interior(shape, grid);
  const auto centre = grid.locate(Point_3(0, 0, 0));
  CHECK(grid.label(centre[0], centre[1], centre[2]) == DF::Voxel_label::EXTERIOR);
  check_topology(s.initial_skeleton().graph, 1, 1, 0);
}

TEST_CASE("parity votes: a closed shell votes inside everywhere, an open face keeps a majority", "[voxels][holes]")
{
  // A cubic shell of voxels (faces at 2 and 12) in a 15^3 grid.
  const std::array<int, 3> dims = {{15, 15, 15}};
  auto index = [&](int i, int j, int k) { return (std::size_t(k) * dims[1] + j) * dims[0] + i; };
  auto on_face = [](int i, int j, int k) {
    const bool in = i >= 2 && i <= 12 && j >= 2 && j <= 12 && k >= 2 && k <= 12;
    return in && (i == 2 || i == 12 || j == 2 || j == 12 || k == 2 || k == 12);
  };
  std::vector<char> closed(std::size_t(15 * 15 * 15), 0), open = closed;
  for(int k = 0; k < 15; ++k)
    for(int j = 0; j < 15; ++j)
      for(int i = 0; i < 15; ++i)
        if(on_face(i, j, k))
        {
          closed[index(i, j, k)] = 1;
          open[index(i, j, k)] = k != 12; // no top face
        }
  const std::vector<std::uint8_t> votes = DF::internal::odd_crossing_votes(closed, dims);
  int most_outside = 0;
  for(int k = 0; k < 15; ++k)
    for(int j = 0; j < 15; ++j)
      for(int i = 0; i < 15; ++i)
      {
        if(on_face(i, j, k))
          continue;
        const int vote = votes[index(i, j, k)];
        if(i > 2 && i < 12 && j > 2 && j < 12 && k > 2 && k < 12)
          REQUIRE(vote == 26);
        else // a ray in the plane of a face runs along it and counts one run: a few votes
          most_outside = (std::max)(most_outside, vote);
      }
  CHECK(most_outside <= 6); // measured: 5, far from a majority (14)
  // Without the top face, the 9 upward rays from the centre leave through the hole.
  const std::vector<std::uint8_t> open_votes = DF::internal::odd_crossing_votes(open, dims);
  CHECK(int(open_votes[index(7, 7, 7)]) == 17);
  // The box mean counts the used voxels only, clipped at the grid's border.
  std::vector<char> used(open.size());
  for(std::size_t v = 0; v < open.size(); ++v)
    used[v] = !open[v];
  const std::vector<std::uint8_t> mean = DF::internal::box_mean_votes(open_votes, used, dims, 2);
  for(const std::array<int, 3> c : {std::array<int, 3>{{7, 7, 7}}, std::array<int, 3>{{0, 3, 14}}, std::array<int, 3>{{3, 12, 11}}})
  {
    double sum = 0, count = 0;
    for(int k = c[2] - 2; k <= c[2] + 2; ++k)
      for(int j = c[1] - 2; j <= c[1] + 2; ++j)
        for(int i = c[0] - 2; i <= c[0] + 2; ++i)
          if(i >= 0 && j >= 0 && k >= 0 && i < 15 && j < 15 && k < 15 && used[index(i, j, k)])
          {
            sum += open_votes[index(i, j, k)];
            ++count;
          }
    CHECK(int(mean[index(c[0], c[1], c[2])]) == int(std::lround(sum / count)));
  }
}

TEST_CASE("parity votes: the runs counted along every ray, as a walk voxel by voxel counts them", "[voxels][holes]")
{
  // Random blobs in a grid with unequal sides, so that rows, slices and the wrap of a
  // row into the next one all matter.
  DF_L1_test::internal::Rng rng(11);
  const std::array<int, 3> dims = {{23, 17, 13}};
  const std::size_t n = std::size_t(dims[0]) * dims[1] * dims[2];
  auto index = [&](int i, int j, int k) { return (std::size_t(k) * dims[1] + j) * dims[0] + i; };
  std::vector<char> shell(n, 0);
  for(int blob = 0; blob < 40; ++blob)
  {
    const int c[3] = {int(rng.index(23)), int(rng.index(17)), int(rng.index(13))}, r = 1 + int(rng.index(2));
    for(int k = (std::max)(0, c[2] - r); k <= (std::min)(12, c[2] + r); ++k)
      for(int j = (std::max)(0, c[1] - r); j <= (std::min)(16, c[1] + r); ++j)
        for(int i = (std::max)(0, c[0] - r); i <= (std::min)(22, c[0] + r); ++i)
          shell[index(i, j, k)] = 1;
  }
  for(std::size_t v = 0; v < n; ++v) // and single voxels
    if(rng.uniform() < 0.05)
      shell[v] = 1;
  const auto sequential = DF::internal::odd_crossing_votes<CGAL::Sequential_tag>(shell, dims);
  const auto parallel = DF_L1_test::with_threads(
    2, [&] { return DF::internal::odd_crossing_votes<CGAL::Parallel_if_available_tag>(shell, dims); });
  CHECK(sequential == parallel);
  std::size_t wrong = 0, odd = 0;
  for(int k = 0; k < dims[2]; ++k)
    for(int j = 0; j < dims[1]; ++j)
      for(int i = 0; i < dims[0]; ++i)
      {
        int expected = 0;
        for(int dk = -1; dk <= 1; ++dk)
          for(int dj = -1; dj <= 1; ++dj)
            for(int di = -1; di <= 1; ++di)
            {
              if(!di && !dj && !dk)
                continue;
              int runs = 0;
              bool in_run = false;
              for(int t = 1;; ++t)
              {
                const int a = i + t * di, b = j + t * dj, c = k + t * dk;
                if(a < 0 || b < 0 || c < 0 || a >= dims[0] || b >= dims[1] || c >= dims[2])
                  break;
                const bool on = shell[index(a, b, c)] != 0;
                runs += on && !in_run;
                in_run = on;
              }
              expected += runs % 2;
            }
        odd += expected > 0 && expected < 26;
        wrong += int(sequential[index(i, j, k)]) != expected;
      }
  CHECK(wrong == 0);
  CHECK(odd > n / 4); // the case is not trivial: most voxels get some votes, not all
}

TEST_CASE("parity votes: the same votes and box means for 1 and 2 threads", "[voxels][determinism]")
{
  // A z slice of 2500 voxels: two chunks of the box mean's y and z passes.
  DF_L1_test::internal::Rng rng(5);
  const std::array<int, 3> dims = {{50, 50, 19}};
  const std::size_t n = std::size_t(dims[0]) * dims[1] * dims[2];
  std::vector<char> shell(n), used(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    shell[v] = rng.uniform() < 0.15;
    used[v] = !shell[v];
  }
  const auto sequential = DF::internal::odd_crossing_votes<CGAL::Sequential_tag>(shell, dims);
  const auto parallel = DF_L1_test::with_threads(
    2, [&] { return DF::internal::odd_crossing_votes<CGAL::Parallel_if_available_tag>(shell, dims); });
  CHECK(sequential == parallel);
  CHECK(std::count(sequential.begin(), sequential.end(), std::uint8_t(0)) < std::ptrdiff_t(n)); // not all zero
  const auto mean = DF_L1_test::with_threads(
    2, [&] { return DF::internal::box_mean_votes<CGAL::Parallel_if_available_tag>(sequential, used, dims, 2); });
  CHECK(DF::internal::box_mean_votes<CGAL::Sequential_tag>(sequential, used, dims, 2) == mean);
  std::size_t wrong = 0;
  for(int sample = 0; sample < 300; ++sample)
  {
    const int c[3] = {int(rng.index(50)), int(rng.index(50)), int(rng.index(19))};
    double sum = 0, count = 0;
    for(int k = c[2] - 2; k <= c[2] + 2; ++k)
      for(int j = c[1] - 2; j <= c[1] + 2; ++j)
        for(int i = c[0] - 2; i <= c[0] + 2; ++i)
        {
          const std::size_t v = (std::size_t(k) * dims[1] + j) * dims[0] + i;
          if(i >= 0 && j >= 0 && k >= 0 && i < dims[0] && j < dims[1] && k < dims[2] && used[v])
          {
            sum += sequential[v];
            ++count;
          }
        }
    wrong += int(mean[(std::size_t(c[2]) * dims[1] + c[1]) * dims[0] + c[0]]) != int(std::lround(sum / count));
  }
  CHECK(wrong == 0);
}

TEST_CASE("voxels: growing the marked voxels through enterable ones equals a breadth-first walk", "[voxels]")
{
  DF_L1_test::internal::Rng rng(23);
  for(int trial = 0; trial < 40; ++trial)
  {
    DF::Grid_geometry<Kernel> g;
    g.dims = {{1 + int(rng.index(14)), 1 + int(rng.index(14)), 1 + int(rng.index(14))}};
    const std::size_t n = g.size();
    const double open = trial % 2 == 0 ? 0.35 : 0.7; // below and above percolation
    std::vector<char> marked(n), enterable(n);
    for(std::size_t v = 0; v < n; ++v)
    {
      marked[v] = rng.uniform() < 0.02;
      enterable[v] = rng.uniform() < open;
    }
    std::vector<char> walked = marked;
    std::vector<std::size_t> queue;
    for(std::size_t v = 0; v < n; ++v)
      if(marked[v])
        queue.push_back(v);
    for(std::size_t head = 0; head < queue.size(); ++head)
      DF::internal::for_each_face_neighbour(g, queue[head], [&](std::size_t w) {
        if(!walked[w] && enterable[w])
        {
          walked[w] = 1;
          queue.push_back(w);
        }
      });
    DF::internal::grow_face_connected(g, marked, [&](std::size_t w) { return enterable[w] != 0; });
    INFO("trial " << trial);
    CHECK(marked == walked);
  }
}

TEST_CASE("parity votes: the shell's ball dilation equals the thresholded distance transform", "[voxels]")
{
  // Random sites (sparse and dense, on the grid's faces too) and radii from none to a few
  // voxels, as the band of the parity vote takes them (the squared band plus 0.001).
  DF_L1_test::internal::Rng rng(17);
  for(int trial = 0; trial < 40; ++trial)
  {
    const std::array<int, 3> dims = {{1 + int(rng.index(14)), 1 + int(rng.index(14)), 1 + int(rng.index(14))}};
    const std::size_t n = std::size_t(dims[0]) * dims[1] * dims[2];
    const double density = trial % 2 == 0 ? 0.02 : 0.3;
    std::vector<char> sites(n);
    for(char& s : sites)
      s = rng.uniform() < density;
    const double band = 0.25 * double(rng.index(14)); // 0 to 3.25 voxels
    const float band2 = float(band * band) + 1e-3f;
    const std::vector<char> dilated = DF::internal::dilate_by_ball(sites, dims, double(band2));
    const std::vector<float> d =
      DF::internal::squared_distance_to_sites<CGAL::Sequential_tag>(dims, [&](std::size_t v) { return sites[v] != 0; });
    std::size_t differences = 0, marked = 0;
    for(std::size_t v = 0; v < n; ++v)
    {
      differences += (dilated[v] != 0) != (d[v] <= band2);
      marked += dilated[v] != 0;
    }
    INFO("trial " << trial << ", band " << band);
    CHECK(differences == 0);
    CHECK(marked >= std::size_t(std::count(sites.begin(), sites.end(), 1)));
  }
}
