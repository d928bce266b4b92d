// Geometry and topology of the initial skeleton (paper, section 5) on synthetic shapes
// with known skeletons, and the voxel topology it relies on.
#include "evaluation/shape_corpus.h"
#include "evaluation/skeleton_quality.h"
#include "evaluation/synthetic_shapes.h"
#include "support/threads.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/internal/contractible_cycles.h>
#include <CGAL/DF_L1_skeleton/internal/missing_branches.h>
#include <CGAL/DF_L1_skeleton/internal/spur_pruning.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_curve_graph.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_topology.h>

#include <tbb/global_control.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace DF = CGAL::DF_L1;
using DF_L1_test::Point_3;
using DF_L1_test::Variant;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;

namespace {

struct Volumetric_result
{
  DF::Distance_field<Kernel> field;
  DF::Initial_skeleton<Kernel> initial;
  double voxel_size = 0;
};

// The volumetric stages as the tool runs them.
Volumetric_result run_volumetric_stages(const std::vector<Point_3>& points)
{
  CGAL::DF_L1_skeletonization<Kernel> skeletonization(points);
  Volumetric_result r;
  r.field = skeletonization.distance_field();
  r.initial = skeletonization.initial_skeleton();
  r.voxel_size = CGAL::to_double(r.field.voxel_size);
  return r;
}

Volumetric_result run_on(const std::string& shape_name, Variant variant, unsigned seed)
{
  const DF_L1_test::Shape shape = DF_L1_test::shape_by_name(shape_name);
  return run_volumetric_stages(DF_L1_test::make_sample(shape, variant, 20000, seed).points);
}

std::string describe(const std::string& name, Variant variant, unsigned seed, const DF::Skeleton_statistics& s)
{
  return name + " variant " + std::to_string(int(variant)) + " seed " + std::to_string(seed) + ": " +
         std::to_string(s.components) + " components, " + std::to_string(s.cycles) + " cycles, " +
         std::to_string(s.end_points) + " end points";
}

} // namespace

TEST_CASE("initial skeleton: capsule, Y-junction and torus lie within 1.5 voxels of the true axis", "[initial]")
{
  for(const std::string name : {"capsule", "y_junction", "torus"})
    for(unsigned seed : {1u, 2u})
    {
      const DF_L1_test::Shape shape = DF_L1_test::shape_by_name(name);
      const Volumetric_result r = run_on(name, Variant::clean, seed);
      const auto& g = r.initial.graph;
      REQUIRE(boost::num_vertices(g) > 10);
      double sum = 0, worst_far = 0, worst_near = 0;
      for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
      {
        const double to_axis = shape.distance_to_axis(g[v].point) / r.voxel_size;
        sum += to_axis;
        // Where tubes meet, the medial axis of their union bends away from the segments
        // that make the true axis, over about the radius of the junction.
        bool near_junction = false;
        for(const DF_L1_test::Skeleton_node& node : shape.skeleton_nodes())
          near_junction = near_junction ||
                          (node.degree >= 3 && std::sqrt(CGAL::to_double(CGAL::squared_distance(node.point, g[v].point))) <
                                                 -shape.signed_distance(node.point) + r.voxel_size);
        (near_junction ? worst_near : worst_far) = (std::max)(near_junction ? worst_near : worst_far, to_axis);
      }
      INFO(name << " seed " << seed << ": mean " << sum / double(boost::num_vertices(g)) << ", max " << worst_far
                << " (near a junction " << worst_near << ") voxels");
      CHECK(worst_far <= 1.5);
      CHECK(worst_near <= 2.5);
      CHECK(sum / double(boost::num_vertices(g)) <= 0.75);
      for(const Point_3& p : r.initial.points) // S, the ridge voxels, are inside the shape
        CHECK(shape.signed_distance(p) < 0);
    }
}

TEST_CASE("initial skeleton: right components, loops and end points on every shape", "[initial]")
{
  const std::vector<std::string> shapes = {"capsule", "y_junction", "torus", "figure_eight", "star",
                                           "stick_figure", "branching_tree", "helix", "many_armed"};
  for(Variant variant : {Variant::clean, Variant::uneven})
    for(const std::string& name : shapes)
    {
      const DF_L1_test::Topology expected = DF_L1_test::shape_by_name(name).expected_topology();
      const DF::Skeleton_statistics s = DF::skeleton_statistics(run_on(name, variant, 3).initial.graph);
      INFO(describe(name, variant, 3, s));
      CHECK(long(s.components) == expected.components);
      CHECK(long(s.cycles) == expected.cycles);
      CHECK(long(s.end_points) == expected.end_points);
    }
}

TEST_CASE("initial skeleton: the curve runs along a part thinner than two voxels to its tip", "[initial][thin]")
{
  // A body 10 voxels in radius and a rod of 0.75 voxel radius: the rod has no skeleton
  // voxel, only occupied ones.
  DF_L1_test::Shape shape("body_and_twig", {2, 0, 0, 1});
  shape.add_round_cone(Point_3(-0.5, 0, 0), Point_3(0, 0, 0), 0.15, 0.15);
  shape.add_round_cone(Point_3(0, 0, 0), Point_3(0.6, 0, 0), 0.01, 0.01);
  const Volumetric_result r = run_volumetric_stages(DF_L1_test::make_sample(shape, Variant::clean, 20000, 7).points);
  REQUIRE(r.voxel_size > 0.01); // the rod is under a voxel in radius
  const auto farthest_x = [](const DF::Skeleton_graph<Kernel>& g) {
    double x = -1e9;
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
      x = (std::max)(x, CGAL::to_double(g[v].point.x()));
    return x;
  };
  const DF::Skeleton_statistics s = DF::skeleton_statistics(r.initial.graph);
  CHECK(s.components == 1);
  CHECK(s.cycles == 0);
  CHECK(s.end_points == 2);
  CHECK(farthest_x(r.initial.graph) > 0.6 - 5 * r.voxel_size);
  // every vertex on the rod stays on its axis
  for(std::size_t v = 0; v < boost::num_vertices(r.initial.graph); ++v)
  {
    const Point_3& p = r.initial.graph[v].point;
    if(p.x() > 0.2)
      CHECK(std::hypot(CGAL::to_double(p.y()), CGAL::to_double(p.z())) < 1.5 * r.voxel_size);
  }
  // without the thin parts, the curve stops in the body
  const auto stopped = DF::extract_initial_skeleton(r.field, CGAL::parameters::thin_parts(false));
  CHECK(farthest_x(stopped.graph) < 0.1);
}

TEST_CASE("initial skeleton: noisy capsule, Y-junction and torus keep their topology", "[initial]")
{
  for(const std::string name : {"capsule", "y_junction", "torus"})
    for(unsigned seed : {4u, 5u})
    {
      const DF_L1_test::Topology expected = DF_L1_test::shape_by_name(name).expected_topology();
      const DF::Skeleton_statistics s = DF::skeleton_statistics(run_on(name, Variant::noise, seed).initial.graph);
      INFO(describe(name, Variant::noise, seed, s));
      CHECK(s.components == 1);
      CHECK(long(s.cycles) == expected.cycles); // the torus keeps exactly its one loop
      CHECK(std::abs(long(s.end_points) - expected.end_points) <= 1);
    }
}

// A smoothed noisy cloud keeps a boundary shell several voxels thick: the stick figure's
// arms have almost no interior voxel two deep, and the distance field alone lost them.
// The depth in the occupied voxels (which the class turns on for smoothed clouds) keeps
// the two arms, the two legs and the head.
TEST_CASE("initial skeleton: depth in the occupied voxels keeps the thin limbs of a noisy cloud", "[initial][noise]")
{
  const DF_L1_test::Shape shape = DF_L1_test::shape_by_name("stick_figure");
  for(unsigned seed : {2u, 7u})
  {
    const std::vector<Point_3> points = DF_L1_test::make_sample(shape, Variant::noise, 20000, seed).points;
    CGAL::DF_L1_skeletonization<Kernel> skeletonization(points);
    REQUIRE(skeletonization.denoised());
    const DF::Distance_field<Kernel>& field = skeletonization.distance_field();
    const DF::Initial_skeleton<Kernel> in_occupied =
      DF::extract_initial_skeleton(field, CGAL::parameters::occupied_depth(true));
    const DF::Skeleton_statistics s = DF::skeleton_statistics(in_occupied.graph);
    INFO(describe("stick_figure", Variant::noise, seed, s) << ", " << s.junctions << " junctions");
    CHECK(s.components == 1);
    CHECK(s.cycles == 0);
    CHECK(std::abs(long(s.end_points) - 5) <= 1);
    // the shoulders' four-way junction may be two three-way ones a voxel apart
    CHECK(s.junctions >= 2);
    CHECK(s.junctions <= 3);
    // the class uses it for this smoothed cloud
    CHECK(DF::skeleton_statistics(skeletonization.initial_skeleton().graph).end_points == s.end_points);
    // every curve vertex lies in an occupied voxel, and its radius is positive
    for(std::size_t v = 0; v < boost::num_vertices(in_occupied.graph); ++v)
    {
      const std::array<int, 3> c = field.locate(in_occupied.graph[v].point);
      REQUIRE(field.contains(c[0], c[1], c[2]));
      CHECK(DF::Voxel_grid<Kernel>::is_occupied(field.labels[field.index(c[0], c[1], c[2])]));
      CHECK(in_occupied.graph[v].radius > 0);
    }
    // the distance field alone misses limbs there
    const DF::Initial_skeleton<Kernel> from_field =
      DF::extract_initial_skeleton(field, CGAL::parameters::thin_parts(false));
    CHECK(DF::skeleton_statistics(from_field.graph).end_points < s.end_points);
  }
}

TEST_CASE("initial skeleton: the same for 1 and 2 threads", "[initial][determinism]")
{
  const std::vector<Point_3> points =
    DF_L1_test::make_sample(DF_L1_test::shape_by_name("branching_tree"), Variant::noise, 20000, 6).points;
  const auto run_with = [&](int threads) {
    return DF_L1_test::with_threads(threads, [&] { return run_volumetric_stages(points); });
  };
  const Volumetric_result one = run_with(1), two = run_with(2);
  REQUIRE(one.initial.points == two.initial.points);
  const auto& a = one.initial.graph;
  const auto& b = two.initial.graph;
  REQUIRE(boost::num_vertices(a) == boost::num_vertices(b));
  REQUIRE(boost::num_edges(a) == boost::num_edges(b));
  for(std::size_t v = 0; v < boost::num_vertices(a); ++v)
  {
    CHECK(a[v].point == b[v].point);
    CHECK(boost::degree(v, a) == boost::degree(v, b));
  }
}

TEST_CASE("voxel topology: simple voxels and loops of voxel sets", "[initial][topology]")
{
  using DF::internal::Neighbourhood;
  const auto cell = [](int dx, int dy, int dz) { return Neighbourhood(1) << ((dz + 1) * 9 + (dy + 1) * 3 + dx + 1); };
  CHECK_FALSE(DF::internal::is_simple(0));                                    // isolated voxel
  CHECK(DF::internal::is_simple(cell(1, 0, 0)));                              // end of a curve
  CHECK(DF::internal::is_simple(cell(1, 1, 1)));                              // end, diagonal neighbour
  CHECK_FALSE(DF::internal::is_simple(cell(1, 0, 0) | cell(-1, 0, 0)));       // inside a curve
  CHECK_FALSE(DF::internal::is_simple(cell(1, 1, 0) | cell(-1, -1, 1)));      // inside a diagonal curve
  CHECK(DF::internal::is_simple(cell(1, 0, 0) | cell(1, 1, 0) | cell(0, 1, 0))); // corner of a square
  Neighbourhood all = 0;
  for(int c = 0; c < 27; ++c)
    all |= c == 13 ? 0 : Neighbourhood(1) << c;
  CHECK_FALSE(DF::internal::is_simple(all));                       // removal makes a cavity
  CHECK(DF::internal::is_simple(all & ~cell(0, 0, 1)));            // on a flat face
  // a ring of 8 voxels around the centre in the plane z = 0: removing the centre makes a tunnel
  Neighbourhood disc = 0;
  for(int dx = -1; dx <= 1; ++dx)
    for(int dy = -1; dy <= 1; ++dy)
      disc |= (dx || dy) ? cell(dx, dy, 0) : 0;
  CHECK_FALSE(DF::internal::is_simple(disc));

  DF::Grid_geometry<Kernel> grid;
  grid.dims = {{10, 10, 10}};
  std::vector<std::size_t> ring, block, line;
  for(int i = 2; i <= 6; ++i)
    for(int j = 2; j <= 6; ++j)
    {
      if(i == 2 || i == 6 || j == 2 || j == 6)
        ring.push_back(grid.index(i, j, 4));
      block.push_back(grid.index(i, j, 4));
    }
  for(int i = 1; i < 9; ++i)
    line.push_back(grid.index(i, i / 2 + 1, 3));
  std::sort(ring.begin(), ring.end());
  std::sort(block.begin(), block.end());
  std::sort(line.begin(), line.end());
  CHECK(DF::internal::first_betti_number(grid, ring, 1, 0) == 1);
  CHECK(DF::internal::first_betti_number(grid, block, 1, 0) == 0);
  CHECK(DF::internal::first_betti_number(grid, line, 1, 0) == 0);
  // The graph of the ring keeps its loop; the graph of the block loses every small cycle
  // that the 26-adjacency makes between its voxels.
  CHECK(DF::skeleton_statistics(DF::internal::voxel_curve_graph<Kernel>(grid, ring)).cycles == 1);
  const DF::Skeleton_statistics filled = DF::skeleton_statistics(DF::internal::voxel_curve_graph<Kernel>(grid, block));
  CHECK(filled.cycles == 0);
  CHECK(filled.components == 1);
  CHECK(DF::skeleton_statistics(DF::internal::voxel_curve_graph<Kernel>(grid, line)).cycles == 0);
}

TEST_CASE("initial skeleton: a cycle that bounds a disk in the solid closed by a voxel is cut, one around a hole is kept", "[initial]")
{
  // A 30 x 30 x 8 plate of interior voxels inside a boundary layer; in the second case
  // with a square hole through its middle, 2, 4 or 8 voxels wide.
  DF::Grid_geometry<Kernel> grid;
  grid.dims = {{34, 34, 12}};
  auto labels_with_hole = [&](int hole) {
    std::vector<DF::Voxel_label> labels(grid.size(), DF::Voxel_label::EXTERIOR);
    for(int k = 1; k <= 10; ++k)
      for(int j = 1; j <= 32; ++j)
        for(int i = 1; i <= 32; ++i)
        {
          const bool in_hole = std::abs(i - 16.5) < hole / 2.0 + 1 && std::abs(j - 16.5) < hole / 2.0 + 1;
          const bool rim = k == 1 || k == 10 || i == 1 || i == 32 || j == 1 || j == 32 ||
                           (hole > 0 && std::abs(i - 16.5) < hole / 2.0 + 1.5 && std::abs(j - 16.5) < hole / 2.0 + 1.5);
          if(hole > 0 && in_hole)
            continue;
          labels[grid.index(i, j, k)] = rim ? DF::Voxel_label::BOUNDARY : DF::Voxel_label::INTERIOR;
        }
    return labels;
  };
  // A square loop of 24 vertices around the plate's centre, in its mid-plane, with a
  // tail at two corners (junctions).
  auto loop_graph = [&]() {
    DF::Skeleton_graph<Kernel> g;
    std::vector<std::size_t> ring;
    const int corners[4][2] = {{8, 8}, {25, 8}, {25, 25}, {8, 25}};
    for(int c = 0; c < 4; ++c)
      for(int s = 0; s < 6; ++s)
      {
        const double t = s / 6.0;
        const double x = corners[c][0] + t * (corners[(c + 1) % 4][0] - corners[c][0]);
        const double y = corners[c][1] + t * (corners[(c + 1) % 4][1] - corners[c][1]);
        const std::size_t v = boost::add_vertex(g);
        g[v].point = Point_3(x + 0.5, y + 0.5, 5.5);
        g[v].radius = 2;
        ring.push_back(v);
      }
    for(std::size_t i = 0; i < ring.size(); ++i)
      boost::add_edge(ring[i], ring[(i + 1) % ring.size()], g);
    for(std::size_t corner : {std::size_t(0), std::size_t(12)})
    {
      const std::size_t tail = boost::add_vertex(g);
      g[tail].point = Point_3(g[ring[corner]].point.x() - 4, g[ring[corner]].point.y() - 4, 5.5);
      g[tail].radius = 2;
      boost::add_edge(ring[corner], tail, g);
    }
    return g;
  };
  SECTION("solid plate: the loop goes")
  {
    DF::Skeleton_graph<Kernel> g = loop_graph();
    CHECK(DF::internal::cut_contractible_cycles(g, grid, labels_with_hole(0)) == 1);
    const DF::Skeleton_statistics s = DF::skeleton_statistics(g);
    CHECK(s.cycles == 0);
    CHECK(s.components == 1);
  }
  SECTION("plate with a hole two voxels wide, below the resolution: the loop goes")
  {
    DF::Skeleton_graph<Kernel> g = loop_graph();
    CHECK(DF::internal::cut_contractible_cycles(g, grid, labels_with_hole(1)) == 1);
    CHECK(DF::skeleton_statistics(g).cycles == 0);
  }
  SECTION("plate with a hole four voxels wide: the loop around it stays")
  {
    DF::Skeleton_graph<Kernel> g = loop_graph();
    CHECK(DF::internal::cut_contractible_cycles(g, grid, labels_with_hole(2)) == 0);
    CHECK(DF::skeleton_statistics(g).cycles == 1);
  }
  SECTION("plate with a hole: the loop around it stays")
  {
    DF::Skeleton_graph<Kernel> g = loop_graph();
    CHECK(DF::internal::cut_contractible_cycles(g, grid, labels_with_hole(6)) == 0);
    CHECK(DF::skeleton_statistics(g).cycles == 1);
  }
}

TEST_CASE("initial skeleton: a limb that no curve enters gets a branch, a bump does not", "[initial]")
{
  // A bar 8 x 8 voxels in section along x with a limb 3 x 3 voxels in section out of its
  // side along y, `limb` voxels long; the graph runs along the bar's axis only.
  auto field_with_limb = [](int limb) {
    DF::Voxel_grid<Kernel> grid;
    grid.dims = {{44, 40, 14}};
    grid.labels.assign(grid.size(), DF::Voxel_label::EXTERIOR);
    auto inside = [&](int i, int j, int k) {
      const bool bar = i >= 2 && i <= 41 && j >= 2 && j <= 9 && k >= 3 && k <= 10;
      const bool arm = i >= 20 && i <= 22 && j >= 10 && j < 10 + limb && k >= 5 && k <= 7;
      return bar || arm;
    };
    for(int k = 0; k < grid.dims[2]; ++k)
      for(int j = 0; j < grid.dims[1]; ++j)
        for(int i = 0; i < grid.dims[0]; ++i)
          if(inside(i, j, k))
          {
            const bool rim = !inside(i - 1, j, k) || !inside(i + 1, j, k) || !inside(i, j - 1, k) ||
                             !inside(i, j + 1, k) || !inside(i, j, k - 1) || !inside(i, j, k + 1);
            grid.labels[grid.index(i, j, k)] = rim ? DF::Voxel_label::BOUNDARY : DF::Voxel_label::INTERIOR;
          }
    return DF::compute_distance_field(grid);
  };
  auto bar_axis = [](const DF::Distance_field<Kernel>& field) {
    DF::Skeleton_graph<Kernel> g;
    for(int i = 4; i <= 39; ++i)
    {
      const std::size_t v = boost::add_vertex(g);
      g[v].point = field.center(i, 5, 6);
      g[v].radius = field.distance(field.index(i, 5, 6));
      if(v > 0)
        boost::add_edge(v - 1, v, g);
    }
    return g;
  };
  // the limb's voxels may hold a tip
  auto limb_voxels = [](const DF::Distance_field<Kernel>& field) {
    std::vector<char> limb(field.size(), 0);
    for(std::size_t v = 0; v < field.size(); ++v)
      limb[v] = field.coordinates(v)[1] >= 10 && DF::Voxel_grid<Kernel>::is_occupied(field.labels[v]);
    return limb;
  };
  SECTION("a limb 14 voxels long: one branch, ending within two voxels of its tip")
  {
    const DF::Distance_field<Kernel> field = field_with_limb(14);
    DF::Skeleton_graph<Kernel> g = bar_axis(field);
    CHECK(DF::internal::add_missing_branches(g, field, DF::internal::occupied_depth(field), limb_voxels(field), 4.0, 1.5, 1.5) == 1);
    const DF::Skeleton_statistics s = DF::skeleton_statistics(g);
    CHECK(s.components == 1);
    CHECK(s.cycles == 0);
    CHECK(s.end_points == 3);
    double nearest = std::numeric_limits<double>::infinity();
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
      if(boost::degree(v, g) == 1)
        nearest = std::min(nearest, std::sqrt(CGAL::to_double(CGAL::squared_distance(g[v].point, Point_3(21.5, 23.5, 6.5)))));
    CHECK(nearest <= 2.0);
  }
  SECTION("a bump 3 voxels high, the bar alone, or a limb whose voxels may not hold a tip: nothing")
  {
    for(int limb : {0, 3, 14})
    {
      const DF::Distance_field<Kernel> field = field_with_limb(limb);
      DF::Skeleton_graph<Kernel> g = bar_axis(field);
      const std::vector<char> tips = limb == 14 ? std::vector<char>(field.size(), 0) : limb_voxels(field);
      CHECK(DF::internal::add_missing_branches(g, field, DF::internal::occupied_depth(field), tips, 4.0, 1.5, 1.5) == 0);
      CHECK(boost::num_vertices(g) == 36);
    }
  }
}

TEST_CASE("initial skeleton: the points keep a short twig that the balls of its parent cover, not hair", "[initial][spurs]")
{
  // A bar along x (balls of radius 4 voxels, surface sampled at 4.5) and a chain of 5
  // voxels out of its side along y, with balls of radius 1: the bar's balls cover it to
  // within the pruning's slack (2 voxels plus its radius). Either a twig 2.5 voxels in
  // radius ends there, its cap 3.5 voxels above the bar's balls, or the bar is bare.
  const double pi = 3.14159265358979323846, R = 4.5, r = 2.5, step = 0.3;
  auto ends_after_pruning = [&](bool twig, bool with_points) {
    DF::Skeleton_graph<Kernel> g;
    for(int i = 0; i <= 40; ++i)
    {
      const std::size_t v = boost::add_vertex(g);
      g[v].point = Point_3(i, 0, 0);
      g[v].radius = 4;
      if(i > 0)
        boost::add_edge(v - 1, v, g);
    }
    for(int k = 1; k <= 5; ++k)
    {
      const std::size_t v = boost::add_vertex(g);
      g[v].point = Point_3(20, k, 0);
      g[v].radius = 1;
      boost::add_edge(k == 1 ? 20 : v - 1, v, g);
    }
    std::vector<std::array<double, 3>> xyz;
    for(double x = 0; x <= 40; x += step)
      for(double a = 0; a < 2 * pi; a += step / R)
      {
        const std::array<double, 3> p{{x, R * std::cos(a), R * std::sin(a)}};
        if(!twig || p[1] < 0 || std::hypot(p[0] - 20, p[2]) >= r)
          xyz.push_back(p);
      }
    if(twig)
    {
      for(double y = std::sqrt(R * R - r * r); y <= 5; y += step)
        for(double a = 0; a < 2 * pi; a += step / r)
          xyz.push_back({{20 + r * std::cos(a), y, r * std::sin(a)}});
      for(double t = step / 2; t < pi / 2; t += step / r)
        for(double a = 0; a < 2 * pi; a += step / (r * std::sin(t)))
          xyz.push_back({{20 + r * std::sin(t) * std::cos(a), 5 + r * std::cos(t), r * std::sin(t) * std::sin(a)}});
    }
    const DF::internal::Uniform_grid grid(xyz, 2.0);
    DF::internal::prune_spurs(g, 1.0, 1.0, 0.0,
                              with_points ? DF::internal::Point_support{&xyz, &grid} : DF::internal::Point_support());
    return DF::skeleton_statistics(g).end_points;
  };
  CHECK(ends_after_pruning(true, true) == 3);
  CHECK(ends_after_pruning(true, false) == 2);
  CHECK(ends_after_pruning(false, true) == 2);
  CHECK(ends_after_pruning(false, false) == 2);

  SECTION("through the named parameter, on trees of the corpus: more of their twigs, no more ends than they have")
  {
    std::size_t found_without = 0, found_with = 0;
    for(int index : {17, 19})
    {
      const DF_L1_test::Shape shape = DF_L1_test::corpus_shape("trees", index);
      const DF_L1_test::Sample sample =
        DF_L1_test::corpus_sample(shape, index, DF_L1_test::corpus_degradation("clean"));
      const DF::Distance_field<Kernel> field = DF::compute_distance_field(DF::voxelize_point_set(sample.points));
      const double voxel = CGAL::to_double(field.voxel_size);
      auto tips_found = [&](const DF::Skeleton_graph<Kernel>& g) {
        std::size_t found = 0;
        for(const DF_L1_test::Tip_recall& t : DF_L1_test::tip_recall(shape, g, voxel))
          found += t.found;
        return found;
      };
      const DF::Skeleton_graph<Kernel> without = DF::extract_initial_skeleton(field).graph;
      const DF::Skeleton_graph<Kernel> with =
        DF::extract_initial_skeleton(field, CGAL::parameters::support_points(std::cref(sample.points))).graph;
      const std::size_t designed = DF_L1_test::tip_recall(shape, with, voxel).size();
      INFO("trees_" << index << ": designed tips " << designed << "; found without the points " << tips_found(without)
                    << ", with them " << tips_found(with) << "; end points " << DF::skeleton_statistics(with).end_points);
      CHECK(DF::skeleton_statistics(with).end_points <= designed);
      found_without += tips_found(without);
      found_with += tips_found(with);
    }
    CHECK(found_with >= found_without + 2);
  }
}
