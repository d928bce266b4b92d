// The final skeleton (paper, section 6): the contraction, the branches and the graph, on
// synthetic shapes with known skeletons.
#include "evaluation/skeleton_quality.h"
#include "evaluation/synthetic_shapes.h"
#include "support/threads.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/internal/attach_fragments.h>
#include <CGAL/DF_L1_skeleton/internal/curve_graph_editing.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace DF = CGAL::DF_L1;
using namespace DF_L1_test;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef DF::Skeleton_graph<Kernel> Graph;

namespace {

Sample sample_of(const std::string& shape, Variant variant, unsigned seed = 7)
{
  return make_sample(shape_by_name(shape), variant, variant == Variant::sparse ? 2000 : 20000, seed);
}

Skeleton_quality quality_of(const std::string& shape, Variant variant, DF::Skeletonization_method method,
                            std::string& line)
{
  const Sample sample = sample_of(shape, variant);
  CGAL::DF_L1_skeletonization<Kernel> s(sample.points, CGAL::parameters::skeletonization_method(method));
  const Skeleton_quality q = measure_quality(shape_by_name(shape), s.skeleton(), CGAL::to_double(s.distance_field().voxel_size));
  line = describe(shape_by_name(shape), variant, q);
  return q;
}

bool same_graph(const Graph& a, const Graph& b)
{
  if(boost::num_vertices(a) != boost::num_vertices(b) || boost::num_edges(a) != boost::num_edges(b))
    return false;
  for(std::size_t v = 0; v < boost::num_vertices(a); ++v)
    if(a[v].point != b[v].point || a[v].radius != b[v].radius || a[v].points != b[v].points)
      return false;
  return true;
}

} // namespace

TEST_CASE("final skeleton: clean shapes have the designed topology, centred and inside", "[final]")
{
  for(const auto& entry : all_shapes())
  {
    const std::string& shape = entry.first;
    std::string line;
    const Skeleton_quality q = quality_of(shape, Variant::clean, DF::Skeletonization_method::DISTANCE_FIELD_GUIDED, line);
    INFO(line);
    CHECK(topology_matches(shape_by_name(shape).expected_topology(), q.topology, false));
    CHECK(q.mean_axis_ratio <= 0.25);
    CHECK(q.outside_fraction <= 0.01);
    CHECK(q.axis_coverage >= 0.9);
  }
}

// The six shapes and six variants of the issue. Every case must stay centred and inside;
// all 36 have the designed topology (end points within one on the degraded variants).
TEST_CASE("final skeleton: 6 shapes x 6 variants stay centred and inside", "[final]")
{
  int passes = 0, cases = 0;
  for(const std::string shape : {"y_junction", "star", "torus", "figure_eight", "branching_tree", "helix"})
    for(Variant variant : all_variants())
    {
      std::string line;
      const Skeleton_quality q = quality_of(shape, variant, DF::Skeletonization_method::DISTANCE_FIELD_GUIDED, line);
      INFO(line);
      CHECK(q.topology.components == shape_by_name(shape).expected_topology().components);
      CHECK(q.outside_fraction <= 0.01);
      CHECK(q.mean_axis_ratio <= 0.25);
      passes += topology_matches(shape_by_name(shape).expected_topology(), q.topology, variant != Variant::clean);
      ++cases;
    }
  INFO(passes << " of " << cases << " cases with the designed topology");
  CHECK(passes == cases);
}

// The thinnest limbs of the synthetic shapes under 1 % noise: the stick figure's arms,
// whose smoothed boundary shell leaves them almost no interior (see `occupied_depth`).
TEST_CASE("final skeleton: the noisy stick figure keeps its arms, centred and inside", "[final][noise]")
{
  for(unsigned seed : {2u, 7u})
  {
    const Sample sample = sample_of("stick_figure", Variant::noise, seed);
    CGAL::DF_L1_skeletonization<Kernel> s(sample.points);
    const Skeleton_quality q =
      measure_quality(shape_by_name("stick_figure"), s.skeleton(), CGAL::to_double(s.distance_field().voxel_size));
    INFO("seed " << seed << ": " << describe(shape_by_name("stick_figure"), Variant::noise, q));
    CHECK(topology_matches(shape_by_name("stick_figure").expected_topology(), q.topology, true));
    CHECK(q.mean_axis_ratio <= 0.25);
    CHECK(q.outside_fraction <= 0.01);
    CHECK(q.axis_coverage >= 0.9);
  }
}

TEST_CASE("final skeleton: the free function, the class run at once and stage by stage agree", "[final]")
{
  const Sample sample = sample_of("y_junction", Variant::outliers);
  Graph direct;
  CGAL::extract_df_l1_skeleton(sample.points, direct);
  CGAL::DF_L1_skeletonization<Kernel> staged(sample.points);
  staged.extract_initial_skeleton();
  staged.contract();
  staged.convert_to_skeleton();
  Graph from_class;
  staged(from_class);
  CHECK(same_graph(direct, from_class));

  // every non-outlier input point belongs to exactly one vertex
  std::vector<int> owner(sample.points.size(), 0);
  for(std::size_t v = 0; v < boost::num_vertices(direct); ++v)
    for(std::size_t i : direct[v].points)
      ++owner[i];
  const std::vector<bool>& outliers = staged.outlier_flags();
  for(std::size_t i = 0; i < owner.size(); ++i)
    REQUIRE(owner[i] == (outliers[i] ? 0 : 1));
  // each radius is the distance value at its vertex, at least half a voxel; most
  // vertices lie deeper than that
  const auto& field = staged.distance_field();
  const double half_voxel = 0.5 * CGAL::to_double(field.voxel_size);
  std::size_t deeper = 0;
  for(std::size_t v = 0; v < boost::num_vertices(direct); ++v)
  {
    const double expected = (std::max)(CGAL::to_double(field.value_at(direct[v].point)), half_voxel);
    CHECK(CGAL::to_double(direct[v].radius) == Approx(expected).epsilon(1e-12));
    deeper += expected > half_voxel;
  }
  CHECK(deeper > boost::num_vertices(direct) / 2);
}

TEST_CASE("threads: with_threads(2) runs two threads at once, even on one core", "[determinism]")
{
  // Each of two tasks waits for the other: with one thread the first would wait alone.
  std::atomic<int> arrived{0};
  std::atomic<int> met{0};
  DF_L1_test::with_threads(2, [&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, 2, 1), [&](const tbb::blocked_range<int>&) {
      ++arrived;
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while(arrived.load() < 2 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::yield();
      met += arrived.load() == 2;
    }, tbb::simple_partitioner());
  });
  CHECK(met.load() == 2);
}

TEST_CASE("final skeleton: 1 and 2 threads give the same skeleton", "[final]")
{
  const Sample sample = sample_of("star", Variant::noise, 3);
  Graph one, two;
  DF_L1_test::with_threads(1, [&] { CGAL::extract_df_l1_skeleton(sample.points, one); });
  DF_L1_test::with_threads(2, [&] { CGAL::extract_df_l1_skeleton(sample.points, two); });
  CHECK(same_graph(one, two));
  Graph sequential;
  CGAL::extract_df_l1_skeleton<CGAL::Sequential_tag>(sample.points, sequential);
  CHECK(same_graph(one, sequential));
}

TEST_CASE("final skeleton: a scaled cloud gives the scaled skeleton", "[final][scale]")
{
  for(Variant variant : {Variant::clean, Variant::noise})
  {
    const Sample sample = sample_of("y_junction", variant);
    std::vector<Point_3> scaled;
    for(const Point_3& p : sample.points)
      scaled.emplace_back(1000 * p.x(), 1000 * p.y(), 1000 * p.z());
    CGAL::DF_L1_skeletonization<Kernel> unit(sample.points), big(scaled);
    const Graph& a = unit.skeleton();
    const Graph& b = big.skeleton();
    CHECK(big.denoised() == unit.denoised());
    const DF::Skeleton_statistics sa = DF::skeleton_statistics(a), sb = DF::skeleton_statistics(b);
    CHECK(sa.components == sb.components);
    CHECK(sa.cycles == sb.cycles);
    CHECK(sa.end_points == sb.end_points);
    CHECK(sa.junctions == sb.junctions);
    // every vertex of one lies within a voxel of the other, scaled (a point on a voxel
    // face may round to either side once scaled, so vertices need not match one to one)
    const double voxel = CGAL::to_double(unit.distance_field().voxel_size);
    const auto farthest = [](const Graph& from, double from_scale, const Graph& to, double to_scale) {
      double worst = 0;
      for(std::size_t v = 0; v < boost::num_vertices(from); ++v)
      {
        double best = std::numeric_limits<double>::infinity();
        for(std::size_t w = 0; w < boost::num_vertices(to); ++w)
        {
          const Point_3& p = from[v].point;
          const Point_3& q = to[w].point;
          best = std::min(best, std::sqrt(CGAL::square(p.x() / from_scale - q.x() / to_scale) +
                                          CGAL::square(p.y() / from_scale - q.y() / to_scale) +
                                          CGAL::square(p.z() / from_scale - q.z() / to_scale)));
        }
        worst = std::max(worst, best);
      }
      return worst;
    };
    INFO(to_string(variant) << ": voxel " << voxel);
    CHECK(farthest(a, 1, b, 1000) <= voxel);
    CHECK(farthest(b, 1000, a, 1) <= voxel);
    CHECK(CGAL::to_double(b[0].radius) > 0);
  }
}

TEST_CASE("contraction: the guidance pulls the samples onto the initial skeleton and keeps them inside", "[final]")
{
  const Sample sample = sample_of("capsule", Variant::holes);
  const auto mean_distance_to_initial = [&](DF::Skeletonization_method method, bool check_inside) {
    CGAL::DF_L1_skeletonization<Kernel> s(sample.points, CGAL::parameters::skeletonization_method(method));
    const auto& c = s.contracted_samples();
    const auto& g = s.initial_skeleton().graph;
    const auto& field = s.distance_field();
    double sum = 0;
    std::size_t n = 0;
    for(std::size_t i = 0; i < c.iterations.front().size(); ++i)
    {
      if(c.roles[i] == DF::Sample_role::REMOVED)
        continue;
      double best = 1e300;
      for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
        best = (std::min)(best, std::sqrt(CGAL::squared_distance(g[v].point, c.points[i])));
      sum += best;
      ++n;
      if(check_inside && c.points[i] != c.iterations.front()[i]) // a sample that moved ended in the shape
      {
        const auto cell = field.locate(c.points[i]);
        const DF::Voxel_label label = field.labels[field.index(cell[0], cell[1], cell[2])];
        CHECK((label == DF::Voxel_label::BOUNDARY || label == DF::Voxel_label::INTERIOR));
      }
    }
    return sum / double(n) / CGAL::to_double(field.voxel_size);
  };
  const double guided = mean_distance_to_initial(DF::Skeletonization_method::DISTANCE_FIELD_GUIDED, true);
  const double plain = mean_distance_to_initial(DF::Skeletonization_method::L1_MEDIAL, false);
  INFO("mean distance to the initial skeleton, in voxels: guided " << guided << ", plain L1 " << plain);
  CHECK(guided < 1.5);
  CHECK(guided < plain);
}

TEST_CASE("contraction: stages, iterations and support radii are recorded", "[final]")
{
  const Sample sample = sample_of("torus", Variant::clean);
  CGAL::DF_L1_skeletonization<Kernel> s(sample.points, CGAL::parameters::number_of_samples(500));
  const auto& c = s.contracted_samples();
  CHECK(c.iterations.front().size() <= 500);
  CHECK(c.iterations.front().size() >= 400);
  REQUIRE(!c.stages.empty());
  int iterations = 0;
  for(const DF::Contraction_stage& stage : c.stages)
  {
    CHECK(stage.iterations >= 1);
    CHECK(stage.min_radius <= stage.mean_radius);
    CHECK(stage.mean_radius <= stage.max_radius);
    iterations += stage.iterations;
  }
  CHECK(c.iterations.size() == std::size_t(iterations) + 1);
  CHECK(c.stages.front().min_radius == Approx(s.initial_support_radius()));
  CHECK(c.stages.size() >= 2);
  CHECK(s.contraction_stages() == 64);

  // contraction_stages caps the schedule; one stage still gives the designed skeleton
  CGAL::DF_L1_skeletonization<Kernel> one(sample.points, CGAL::parameters::contraction_stages(1));
  CHECK(one.contracted_samples().stages.size() == 1);
  CHECK(one.contraction_stages() == 1);
  const DF::Skeleton_statistics st = DF::skeleton_statistics(one.skeleton());
  CHECK(st.cycles == 1);
  CHECK(st.components == 1);
  CHECK(s.initial_support_radius() == Approx(2 * s.bbox_diagonal() / std::cbrt(double(sample.points.size()))).epsilon(0.05));

  // h0 can be set after construction: the contraction reruns with it
  const double h0 = 0.8 * s.initial_support_radius();
  s.set_initial_support_radius(h0);
  CHECK(s.initial_support_radius() == h0);
  CHECK(s.contracted_samples().stages.front().min_radius == Approx(h0));
  CHECK(s.contracted_samples().initial_support_radius == h0);
  CHECK_THROWS_AS(s.set_initial_support_radius(0.0), DF::Invalid_input);
  CHECK_THROWS_AS(s.set_initial_support_radius(NAN), DF::Invalid_input);
  CHECK(s.initial_support_radius() == h0); // a refused value changes nothing
}

TEST_CASE("contraction: bad parameters are refused", "[final]")
{
  const Sample sample = sample_of("capsule", Variant::clean);
  namespace params = CGAL::parameters;
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::repulsion_coefficient(0.5)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::repulsion_coefficient(-0.1)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::initial_support_radius(0.0)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::support_radius_growth(0.0)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::branch_directionality(1.0)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::number_of_samples(0)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::number_of_iterations(0)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::contraction_stages(0)), DF::Invalid_input);
  CHECK_THROWS_AS(CGAL::DF_L1_skeletonization<Kernel>(sample.points, params::contraction_stages(65)), DF::Invalid_input);
}

TEST_CASE("plain L1-medial baseline: runs the same engine without guidance", "[final]")
{
  const Sample sample = sample_of("torus", Variant::clean);
  CGAL::DF_L1_skeletonization<Kernel> s(sample.points, CGAL::parameters::skeletonization_method(DF::Skeletonization_method::L1_MEDIAL));
  CHECK(s.contracted_samples().method == DF::Skeletonization_method::L1_MEDIAL);
  CHECK(boost::num_vertices(s.skeleton()) > 0);
  // the global schedule: every stage's free samples share one support radius
  for(const DF::Contraction_stage& stage : s.contracted_samples().stages)
    CHECK(stage.min_radius == Approx(stage.max_radius));
}

TEST_CASE("final skeleton: contract() runs one support-radius stage at a time", "[final][class]")
{
  const Sample sample = sample_of("y_junction", Variant::clean);
  CGAL::DF_L1_skeletonization<Kernel> stepped(sample.points), at_once(sample.points);
  std::size_t stages = 0;
  while(stepped.contract())
  {
    ++stages;
    REQUIRE(stepped.contracted_samples().stages.size() == stages); // the samples after this stage
    REQUIRE(stages <= 64);
  }
  CHECK(stages >= 2);
  CHECK_FALSE(stepped.contract()); // converged: nothing more runs
  CHECK(stepped.contracted_samples().stages.size() == stages);
  at_once.contract_until_convergence();
  const auto& a = stepped.contracted_samples();
  const auto& b = at_once.contracted_samples();
  CHECK(a.points == b.points);
  CHECK(a.edges == b.edges);
  CHECK(a.iterations.size() == b.iterations.size());
  Graph g1, g2;
  stepped(g1);
  at_once(g2);
  CHECK(same_graph(g1, g2));

  // the free stage function gives the same samples
  std::vector<Kernel::Point_3> contracted_points = stepped.kept_points();
  contracted_points.insert(contracted_points.end(), stepped.added_points().begin(), stepped.added_points().end());
  const auto direct = CGAL::DF_L1::contract_samples(contracted_points, stepped.distance_field(), stepped.initial_skeleton());
  // the class works on the points divided by their diagonal and rounded to 2^-32 of it
  REQUIRE(direct.points.size() == a.points.size());
  double moved = 0;
  for(std::size_t i = 0; i < a.points.size(); ++i)
    moved = (std::max)(moved, std::sqrt(CGAL::squared_distance(direct.points[i], a.points[i])));
  CHECK(moved <= 1e-9 * stepped.bbox_diagonal());

  // a contraction parameter restarts the contraction from its first stage
  stepped.set_repulsion_coefficient(0.3);
  CHECK(stepped.contract());
  CHECK(stepped.contracted_samples().stages.size() == 1);
}

TEST_CASE("final skeleton: a small fragment near a larger piece is attached, other pieces stay apart", "[final]")
{
  // Pieces of points along lines, one vertex per unit of length standing for its points.
  std::vector<std::array<double, 3>> xyz;
  Graph g;
  auto piece = [&](double x0, double x1, double y) {
    Graph::vertex_descriptor previous = Graph::null_vertex(), first = Graph::null_vertex();
    for(double x = x0; x <= x1 + 1e-9; x += 1)
    {
      const Graph::vertex_descriptor v = boost::add_vertex(g);
      g[v].point = Kernel::Point_3(x, y, 0);
      for(double t = x - 0.45; t <= x + 0.45 + 1e-9 && t <= x1 + 1e-9; t += 0.1)
        if(t >= x0 - 1e-9)
        {
          g[v].points.push_back(xyz.size());
          xyz.push_back({{t, y, 0}});
        }
      if(previous != Graph::null_vertex())
        boost::add_edge(previous, v, g);
      else
        first = v;
      previous = v;
    }
    return first;
  };
  piece(0, 10, 0);                                  // the object, extent 10
  const auto fragment = piece(10.6, 12.1, 0);       // extent 1.5, 0.6 away: attached
  piece(5, 6, 8);                                   // extent 1, 8 away: a separate small object
  piece(0, 8, 3);                                   // extent 8, 3 away: a separate object of comparable size
  REQUIRE(DF::skeleton_statistics(g).components == 4);
  CHECK(DF::internal::attach_fragments(g, xyz) == 1);
  const DF::Skeleton_statistics st = DF::skeleton_statistics(g);
  CHECK(st.components == 3);
  CHECK(st.cycles == 0);
  // the edge joins the fragment's first vertex to the object's last one
  CHECK(boost::edge(fragment, Graph::vertex_descriptor(10), g).second);
  // a second call finds nothing more to attach
  CHECK(DF::internal::attach_fragments(g, xyz) == 0);
}

TEST_CASE("final skeleton: of two ends of one junction that meet, the shorter chain goes; apart, both stay", "[final]")
{
  using CGAL::DF_L1::internal::Curve_graph;
  // a stem into a junction at the origin; two chains from it bow apart and meet again
  // 0.4 apart (the halves of one limb around a pocket); a third chain ends far away
  Curve_graph g;
  const std::size_t stem = g.add_vertex({{-10, 0, 0}}), junction = g.add_vertex({{0, 0, 0}});
  g.add_edge(stem, junction);
  auto chain = [&](std::initializer_list<std::array<double, 3>> points) {
    std::size_t previous = junction;
    for(const auto& p : points)
    {
      const std::size_t v = g.add_vertex(p);
      g.add_edge(previous, v);
      previous = v;
    }
    return previous;
  };
  const std::size_t longer = chain({{{5, 3, 0}}, {{10, 3, 0}}, {{12, 0.2, 0}}});
  const std::size_t shorter = chain({{{5, -2, 0}}, {{12, -0.2, 0}}});
  const std::size_t apart = chain({{{0, 8, 0}}, {{0, 16, 0}}});
  g.merge_twin_ends([](std::size_t, std::size_t) { return 1.0; });
  CHECK(g.alive[longer]);
  CHECK(g.alive[apart]);
  CHECK_FALSE(g.alive[shorter]);
  CHECK(g.adj[junction].size() == 3);
  // tips farther apart than the threshold stay
  Curve_graph h = g;
  h.merge_twin_ends([](std::size_t, std::size_t) { return 0.1; });
  CHECK(h.adj[junction].size() == 3);
}
