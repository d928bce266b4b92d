// Tests of the skeleton quality harness (tools/evaluation/skeleton_quality.h) on graphs
// built by hand from the true axes of synthetic shapes, and perturbed in known ways.
#include "evaluation/skeleton_quality.h"
#include "evaluation/synthetic_shapes.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using namespace DF_L1_test;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::DF_L1::Skeleton_graph<K> Graph;
typedef boost::graph_traits<Graph>::vertex_descriptor Vertex;

Vector_3 unit(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

/// The graph of a set of polylines: one vertex per polyline point, polyline ends
/// merged where they coincide (so closed polylines make cycles and arms meeting at a
/// point make a junction).
Graph graph_from_polylines(const std::vector<Skeleton_polyline>& polylines, double merge_tolerance)
{
  Graph g;
  std::vector<Vertex> ends;
  auto end_vertex = [&](const Point_3& p) {
    for(Vertex v : ends)
      if(CGAL::squared_distance(g[v].point, p) <= merge_tolerance * merge_tolerance)
        return v;
    const Vertex v = boost::add_vertex(g);
    g[v].point = p;
    ends.push_back(v);
    return v;
  };
  for(const Skeleton_polyline& pl : polylines) {
    Vertex prev = end_vertex(pl.points.front());
    for(std::size_t i = 1; i < pl.points.size(); ++i) {
      Vertex v;
      if(i + 1 == pl.points.size())
        v = end_vertex(pl.points[i]);
      else {
        v = boost::add_vertex(g);
        g[v].point = pl.points[i];
      }
      boost::add_edge(prev, v, g);
      prev = v;
    }
  }
  return g;
}

/// The voxel size used to judge the hand-built graphs: 1 % of the bbox diagonal
/// (the library default is about that).
double voxel_of(const Shape& shape) { return 0.01 * shape.bbox_diagonal(); }

/// The true axis of `shape` as a graph with one vertex per voxel of length.
Graph axis_graph(const Shape& shape)
{
  return graph_from_polylines(shape.skeleton_polylines(voxel_of(shape)), 1e-9 * shape.bbox_diagonal());
}

Vertex nearest_vertex(const Graph& g, const Point_3& p)
{
  Vertex best = 0;
  for(Vertex v = 0; v < boost::num_vertices(g); ++v)
    if(CGAL::squared_distance(g[v].point, p) < CGAL::squared_distance(g[best].point, p))
      best = v;
  return best;
}

/// Adds a spur of `length` from `v` in direction `dir`; returns its tip.
Vertex add_spur(Graph& g, Vertex v, const Vector_3& dir, double length)
{
  const Vertex tip = boost::add_vertex(g);
  g[tip].point = g[v].point + length * unit(dir);
  boost::add_edge(v, tip, g);
  return tip;
}

/// Moves the edges from `v` to the `neighbours` onto a new vertex at `anchor + offset`,
/// joined to `anchor` (by default `v`): splits a junction into nearby ones.
Vertex split_vertex(Graph& g, Vertex v, const std::vector<Vertex>& neighbours, const Vector_3& offset,
                    Vertex anchor = boost::graph_traits<Graph>::null_vertex())
{
  if(anchor == boost::graph_traits<Graph>::null_vertex())
    anchor = v;
  const Vertex w = boost::add_vertex(g);
  g[w].point = g[anchor].point + offset;
  for(Vertex n : neighbours) {
    REQUIRE(boost::edge(v, n, g).second);
    boost::remove_edge(v, n, g);
    boost::add_edge(w, n, g);
  }
  boost::add_edge(anchor, w, g);
  return w;
}

std::vector<Vertex> neighbours_of(const Graph& g, Vertex v)
{
  std::vector<Vertex> result;
  for(auto range = boost::adjacent_vertices(v, g); range.first != range.second; ++range.first)
    result.push_back(*range.first);
  return result;
}

} // namespace

TEST_CASE("quality: topology_matches is exact, with +-1 end point when noisy", "[quality]")
{
  const Topology expected{3, 1, 0, 1};
  CHECK(topology_matches(expected, {3, 1, 0, 1}, false));
  CHECK(topology_matches(expected, {3, 1, 0, 1}, true));
  CHECK_FALSE(topology_matches(expected, {4, 1, 0, 1}, false));
  CHECK(topology_matches(expected, {4, 1, 0, 1}, true));
  CHECK(topology_matches(expected, {2, 1, 0, 1}, true));
  CHECK_FALSE(topology_matches(expected, {5, 1, 0, 1}, true));
  CHECK_FALSE(topology_matches(expected, {3, 2, 0, 1}, true));
  CHECK_FALSE(topology_matches(expected, {3, 1, 1, 1}, true));
  CHECK_FALSE(topology_matches(expected, {3, 1, 0, 2}, true));
}

TEST_CASE("quality: the true axis of every shape scores perfectly", "[quality]")
{
  for(const auto& entry : all_shapes()) {
    const Shape& shape = entry.second;
    const Graph g = axis_graph(shape);
    const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
    INFO(describe(shape, Variant::clean, q));
    CHECK(q.topology == shape.expected_topology());
    CHECK(topology_matches(shape.expected_topology(), q.topology, false));
    CHECK(q.mean_axis_ratio < 0.01); // arcs are sampled as chords
    CHECK(q.max_axis_distance_in_voxels < 0.1);
    CHECK(q.outside_fraction == 0);
    CHECK(q.axis_coverage > 0.999);
    CHECK(q.total_length > 0);
  }
}

TEST_CASE("quality: an axis shifted by a fraction of the radius has that ratio", "[quality]")
{
  SECTION("torus, shifted along its axis")
  {
    const Shape shape = torus();
    const Vector_3 axis = unit(Vector_3(0.2, 0.1, 1)); // as in torus()
    for(double fraction : {0.4, 0.5, 0.8, 1.5}) {
      Graph g = axis_graph(shape);
      for(Vertex v = 0; v < boost::num_vertices(g); ++v)
        g[v].point = g[v].point + fraction * 0.12 * axis;
      const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
      INFO("shift " << fraction << " r: " << describe(shape, Variant::clean, q));
      CHECK(q.topology == shape.expected_topology());
      CHECK(q.mean_axis_ratio == Approx(fraction).epsilon(0.02));
      CHECK(q.max_axis_ratio == Approx(fraction).epsilon(0.02));
      if(fraction < 1) {
        CHECK(q.outside_fraction == 0);
      } else {
        CHECK(q.outside_fraction == 1);
      }
      // 0.5 r is the coverage tolerance (the radius exceeds 3 voxels here)
      if(fraction < 0.5) {
        CHECK(q.axis_coverage == 1);
      } else if(fraction > 0.5) {
        CHECK(q.axis_coverage == 0);
      }
    }
  }
  SECTION("tapered capsule, shifted across its axis by a fraction of the local radius")
  {
    const Shape shape = capsule();
    const Vector_3 across = unit(CGAL::cross_product(Vector_3(1, 0.3, 0.2), Vector_3(0, 0, 1)));
    const std::vector<Skeleton_polyline> axis = shape.skeleton_polylines(voxel_of(shape));
    REQUIRE(axis.size() == 1);
    for(double fraction : {0.5, 0.8}) {
      Graph g = graph_from_polylines(axis, 0);
      for(Vertex v = 0; v < boost::num_vertices(g); ++v) // vertex v is axis point v
        g[v].point = g[v].point + fraction * axis[0].radii[v] * across;
      const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
      INFO("shift " << fraction << " r: " << describe(shape, Variant::clean, q));
      CHECK(q.topology == shape.expected_topology());
      CHECK(q.mean_axis_ratio == Approx(fraction).epsilon(0.02));
      CHECK(q.outside_fraction == 0);
      CHECK(q.max_axis_distance_in_voxels > fraction * 0.07 / voxel_of(shape));
      if(fraction == 0.8) {
        CHECK(q.axis_coverage < 0.05);
      }
    }
  }
}

TEST_CASE("quality: a shortened or missing arm lowers the coverage, not the topology", "[quality]")
{
  SECTION("y_junction with its stem cut in half")
  {
    const Shape shape = y_junction();
    std::vector<Skeleton_polyline> axis = shape.skeleton_polylines(voxel_of(shape));
    REQUIRE(axis.size() == 3);
    // The stem, added first, runs from the junction (0,0,0) down to (0,-0.6,0).
    REQUIRE(CGAL::squared_distance(axis[0].points.back(), Point_3(0, -0.6, 0)) < 1e-12);
    axis[0].points.resize(axis[0].points.size() / 2 + 1);
    const Graph g = graph_from_polylines(axis, 1e-9);
    const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
    INFO(describe(shape, Variant::clean, q));
    CHECK(q.topology == shape.expected_topology()); // still 3 ends
    CHECK(q.mean_axis_ratio < 0.01);
    CHECK(q.outside_fraction == 0);
    // 0.3 of 1.6 missing, minus half a radius of tolerance at the cut
    CHECK(q.axis_coverage > 0.78);
    CHECK(q.axis_coverage < 0.86);
  }
  SECTION("star with one arm removed")
  {
    const Shape shape = star();
    std::vector<Skeleton_polyline> axis = shape.skeleton_polylines(voxel_of(shape));
    REQUIRE(axis.size() == 6);
    axis.pop_back();
    const Graph g = graph_from_polylines(axis, 1e-9);
    const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
    INFO(describe(shape, Variant::clean, q));
    CHECK(q.topology.end_points == 5);
    CHECK(q.topology.junctions == 1);
    CHECK_FALSE(topology_matches(shape.expected_topology(), q.topology, false));
    CHECK(topology_matches(shape.expected_topology(), q.topology, true)); // only coverage tells
    CHECK(q.axis_coverage > 0.80);
    CHECK(q.axis_coverage < 5.0 / 6 + 0.02);
  }
}

TEST_CASE("quality: coverage and distances come from the edges, not only the vertices", "[quality]")
{
  // The capsule axis as ONE edge: covered all along, though its vertices are 1.1 apart.
  const Shape shape = capsule();
  Graph g;
  const Vertex a = boost::add_vertex(g), b = boost::add_vertex(g);
  g[a].point = Point_3(-0.5, -0.15, -0.1);
  g[b].point = Point_3(0.5, 0.15, 0.1);
  boost::add_edge(a, b, g);
  Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
  INFO(describe(shape, Variant::clean, q));
  CHECK(q.topology == shape.expected_topology());
  CHECK(q.axis_coverage == 1);
  CHECK(q.mean_axis_ratio < 1e-9);
  CHECK(q.total_length == Approx(std::sqrt(1 + 0.09 + 0.04)));
  // Its middle pushed out of the solid: vertices stay on the axis, the edges do not.
  const Vertex m = boost::add_vertex(g);
  g[m].point = Point_3(0, 0, 0.3);
  boost::remove_edge(a, b, g);
  boost::add_edge(a, m, g);
  boost::add_edge(m, b, g);
  q = measure_quality(shape, g, voxel_of(shape));
  INFO(describe(shape, Variant::clean, q));
  CHECK(q.outside_fraction > 0.3);
  CHECK(q.mean_axis_ratio > 1);
  CHECK(q.axis_coverage < 0.5);
}

TEST_CASE("quality: an edge across the torus hole leaves the solid and adds a cycle", "[quality]")
{
  const Shape shape = torus();
  Graph g = axis_graph(shape);
  const std::size_t n = boost::num_vertices(g);
  boost::add_edge(Vertex(0), Vertex(n / 2), g); // opposite points of the centre circle
  const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
  INFO(describe(shape, Variant::clean, q));
  CHECK(q.topology.cycles == 2);
  CHECK(q.topology.junctions == 2);
  CHECK(q.topology.end_points == 0);
  CHECK_FALSE(topology_matches(shape.expected_topology(), q.topology, true));
  // The chord has length 1, of which 2 * 0.12 inside; the ring has length pi.
  CHECK(q.outside_fraction == Approx(0.76 / (1 + 3.14159265)).epsilon(0.05));
  CHECK(q.mean_axis_ratio > 0.5);
  CHECK(q.max_axis_distance_in_voxels > 0.4 / voxel_of(shape));
  CHECK(q.axis_coverage > 0.999);
}

TEST_CASE("quality: a short spur adds an end point", "[quality]")
{
  SECTION("at the junction of the y_junction: one end more, same junction")
  {
    const Shape shape = y_junction();
    Graph g = axis_graph(shape);
    const Vertex centre = nearest_vertex(g, Point_3(0, 0, 0));
    REQUIRE(boost::degree(centre, g) == 3);
    add_spur(g, centre, Vector_3(0, 0, 1), 3 * voxel_of(shape)); // out of plane, inside the tube
    const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
    INFO(describe(shape, Variant::clean, q));
    CHECK(q.topology == Topology{4, 1, 0, 1});
    CHECK_FALSE(topology_matches(shape.expected_topology(), q.topology, false));
    CHECK(topology_matches(shape.expected_topology(), q.topology, true));
    CHECK(q.outside_fraction == 0);
    CHECK(q.mean_axis_ratio > 0.001);
  }
  SECTION("in the middle of the capsule: one end and one junction more")
  {
    const Shape shape = capsule();
    Graph g = axis_graph(shape);
    const Vertex middle = nearest_vertex(g, Point_3(0, 0, 0));
    add_spur(g, middle, Vector_3(0, 0, 1), 3 * voxel_of(shape));
    const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
    INFO(describe(shape, Variant::clean, q));
    CHECK(q.topology == Topology{3, 1, 0, 1});
    CHECK_FALSE(topology_matches(shape.expected_topology(), q.topology, true));
  }
}

TEST_CASE("quality: degree->=3 vertices joined by edges under 2 voxels make one junction", "[quality]")
{
  SECTION("figure_eight, its crossing split into two degree-3 vertices")
  {
    const Shape shape = figure_eight();
    const double voxel = voxel_of(shape);
    for(double gap : {1.0, 1.9, 2.1, 4.0}) {
      Graph g = axis_graph(shape);
      const Vertex centre = nearest_vertex(g, Point_3(0, 0, 0));
      const std::vector<Vertex> around = neighbours_of(g, centre);
      REQUIRE(around.size() == 4);
      // Keep the crossing's geometry: move the two neighbours on the +x side.
      std::vector<Vertex> right;
      for(Vertex n : around)
        if(g[n].point.x() > 0)
          right.push_back(n);
      REQUIRE(right.size() == 2);
      split_vertex(g, centre, right, Vector_3(gap * voxel, 0, 0));
      const Skeleton_quality q = measure_quality(shape, g, voxel);
      INFO("gap " << gap << " voxels: " << describe(shape, Variant::clean, q));
      CHECK(q.junction_vertices == 2);
      CHECK(q.topology.cycles == 2);
      CHECK(q.topology.junctions == (gap < 2 ? 1 : 2));
      CHECK(topology_matches(shape.expected_topology(), q.topology, false) == (gap < 2));
    }
  }
  SECTION("star, its centre split into a chain of three junction vertices")
  {
    const Shape shape = star();
    const double voxel = voxel_of(shape);
    for(double gap : {1.0, 3.0}) {
      Graph g = axis_graph(shape);
      const Vertex centre = nearest_vertex(g, Point_3(0, 0, 0));
      const std::vector<Vertex> around = neighbours_of(g, centre);
      REQUIRE(around.size() == 6);
      const Vertex w = split_vertex(g, centre, {around[0], around[1]}, Vector_3(voxel, 0, 0));
      split_vertex(g, centre, {around[2], around[3]}, Vector_3(gap * voxel, 0, 0), w); // centre - w - x
      INFO("gap " << gap << " voxels");
      const Skeleton_quality q = measure_quality(shape, g, voxel);
      INFO(describe(shape, Variant::clean, q));
      CHECK(q.junction_vertices == 3);
      CHECK(q.topology.end_points == 6);
      CHECK(q.topology.junctions == (gap < 2 ? 1 : 2));
    }
  }
}

TEST_CASE("quality: optionally, junction vertices joined by a path within the local radius make one junction", "[quality]")
{
  const Shape shape = figure_eight(); // tube radius 0.07, about 3.2 voxels
  const double voxel = voxel_of(shape);
  Graph g = axis_graph(shape);
  const Vertex centre = nearest_vertex(g, Point_3(0, 0, 0));
  std::vector<Vertex> right;
  for(Vertex n : neighbours_of(g, centre))
    if(g[n].point.x() > 0)
      right.push_back(n);
  REQUIRE(right.size() == 2);
  const Vertex w = split_vertex(g, centre, right, Vector_3(1.5 * voxel, 0, 0));
  // A degree-2 vertex halfway between the two degree-3 vertices.
  boost::remove_edge(centre, w, g);
  const Vertex middle = boost::add_vertex(g);
  g[middle].point = CGAL::midpoint(g[centre].point, g[w].point);
  boost::add_edge(centre, middle, g);
  boost::add_edge(middle, w, g);

  const Skeleton_quality strict = measure_quality(shape, g, voxel);
  INFO("strict: " << describe(shape, Variant::clean, strict));
  CHECK(strict.topology.junctions == 2); // not adjacent
  Quality_options lenient;
  lenient.junction_merge_radius_fraction = 1;
  const Skeleton_quality q = measure_quality(shape, g, voxel, lenient);
  INFO("lenient: " << describe(shape, Variant::clean, q));
  CHECK(q.topology == shape.expected_topology());
  lenient.junction_merge_radius_fraction = 0.3; // under 1.5 voxels
  CHECK(measure_quality(shape, g, voxel, lenient).topology.junctions == 2);
  // Distinct junctions stay distinct: theta's are a diameter apart.
  lenient.junction_merge_radius_fraction = 1;
  const Shape t = theta();
  CHECK(measure_quality(t, axis_graph(t), voxel_of(t), lenient).topology == t.expected_topology());
}

TEST_CASE("quality: a k-way junction split within the overlap of its parts counts once with junction zones", "[quality]")
{
  // A trunk and three children leaving at 15 degrees from the trunk's direction: the
  // children overlap for several of their radii beyond the node.
  const double r = 0.05;
  Shape shape("fan", {4, 1, 0, 1});
  const Point_3 o(0, 0, 0);
  shape.add_round_cone(Point_3(0, -1, 0), o, r, r);
  const double tilt = 15 * CGAL_PI / 180;
  std::vector<Point_3> tips;
  for(int c = 0; c < 3; ++c) {
    const double azimuth = 2 * CGAL_PI * c / 3;
    tips.push_back(Point_3(std::sin(tilt) * std::cos(azimuth), std::cos(tilt), std::sin(tilt) * std::sin(azimuth)));
    shape.add_round_cone(o, tips.back(), r, r);
  }
  const std::vector<Junction_zone> zones = junction_zones(shape);
  REQUIRE(zones.size() == 1);
  // Children 2 sin(15 deg) sin(60 deg) = 0.448 apart per unit length part at 2r = 0.1.
  CHECK(zones.front().radius == Approx(0.1 / 0.448).epsilon(0.05));

  // The skeleton resolves the 4-way junction as two 3-way ones 0.15 apart (3 radii).
  Graph g;
  auto vertex = [&](const Point_3& p) {
    const Vertex v = boost::add_vertex(g);
    g[v].point = p;
    return v;
  };
  const Vertex trunk = vertex(Point_3(0, -1, 0)), j1 = vertex(o), j2 = vertex(Point_3(0, 0.15, 0));
  boost::add_edge(trunk, j1, g);
  boost::add_edge(j1, j2, g);
  boost::add_edge(j1, vertex(tips[0]), g);
  boost::add_edge(j2, vertex(tips[1]), g);
  boost::add_edge(j2, vertex(tips[2]), g);
  Quality_options options;
  options.junction_merge_radius_fraction = 1;
  CHECK(measure_quality(shape, g, voxel_of(shape), options).topology.junctions == 2);
  options.merge_within_junction_zones = true;
  CHECK(measure_quality(shape, g, voxel_of(shape), options).topology == shape.expected_topology());
  // Beyond the zone, two junctions stay two.
  boost::clear_vertex(j2, g);
  const Vertex far = vertex(Point_3(0, 0.6, 0));
  boost::add_edge(j1, far, g);
  boost::add_edge(far, vertex(tips[1]), g);
  boost::add_edge(far, vertex(tips[2]), g);
  CHECK(measure_quality(shape, g, voxel_of(shape), options).topology.junctions == 2);
  // Distinct junctions stay distinct: theta's are a diameter apart.
  const Shape t = theta();
  CHECK(measure_quality(t, axis_graph(t), voxel_of(t), options).topology == t.expected_topology());
}

TEST_CASE("quality: isolated vertices are components; a graph without edges is judged by its vertices", "[quality]")
{
  SECTION("capsule axis plus a lone vertex")
  {
    const Shape shape = capsule();
    Graph g = axis_graph(shape);
    const Vertex lone = boost::add_vertex(g);
    g[lone].point = Point_3(0.3, 0.09, 0.06); // on the axis
    const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
    INFO(describe(shape, Variant::clean, q));
    CHECK(q.topology == Topology{2, 0, 0, 2});
    CHECK_FALSE(topology_matches(shape.expected_topology(), q.topology, true));
    CHECK(q.axis_coverage > 0.999);
  }
  SECTION("a single vertex half a radius off the capsule axis")
  {
    const Shape shape = capsule();
    Graph g;
    const Vertex v = boost::add_vertex(g);
    const Point_3 on_axis(0, 0, 0);
    const double r = -shape.signed_distance(on_axis);
    g[v].point = shape.nearest_axis_point(on_axis) +
                 0.5 * r * unit(CGAL::cross_product(Vector_3(1, 0.3, 0.2), Vector_3(0, 0, 1)));
    const Skeleton_quality q = measure_quality(shape, g, voxel_of(shape));
    INFO(describe(shape, Variant::clean, q));
    CHECK(q.topology == Topology{0, 0, 0, 1});
    CHECK(q.total_length == 0);
    CHECK(q.mean_axis_ratio == Approx(0.5).epsilon(0.01));
    CHECK(q.outside_fraction == 0);
    CHECK(q.axis_coverage > 0);
    CHECK(q.axis_coverage < 0.1);
  }
  SECTION("an empty graph")
  {
    const Skeleton_quality q = measure_quality(capsule(), Graph(), 0.01);
    CHECK(q.topology == Topology{0, 0, 0, 0});
    CHECK(q.axis_coverage == 0);
  }
}

TEST_CASE("quality: describe prints the case on one line", "[quality]")
{
  const Shape shape = y_junction();
  const Skeleton_quality q = measure_quality(shape, axis_graph(shape), voxel_of(shape));
  const std::string line = describe(shape, Variant::noise, q);
  CHECK(line.find("y_junction") != std::string::npos);
  CHECK(line.find("noise") != std::string::npos);
  CHECK(line.find("3/1/0/1") != std::string::npos);
  CHECK(line.find(" ok ") != std::string::npos);
  CHECK(line.find('\n') == std::string::npos);
  Topology wrong = shape.expected_topology();
  wrong.cycles = 1;
  CHECK(describe(shape.name(), Variant::clean, wrong, q).find("FAIL") != std::string::npos);
}

TEST_CASE("quality: a dense 5000-edge axis is measured through the grid", "[quality]")
{
  const Shape shape = helix(); // 100 primitives: the slowest distance queries
  const double length = 5.6;   // about the helix length
  const Graph g = graph_from_polylines(shape.skeleton_polylines(length / 5000), 1e-9);
  REQUIRE(boost::num_edges(g) >= 5000);
  const Skeleton_quality q = measure_quality(shape, g, 0.004);
  INFO(describe(shape, Variant::clean, q));
  CHECK(q.axis_coverage > 0.999);
  CHECK(q.mean_axis_ratio < 0.01);
}

TEST_CASE("quality: tip_recall tells a missed tip, and how far its limb stands apart", "[quality]")
{
  // A stem and two arms 20 degrees apart, radius 0.05, length 1: the arms' surfaces are
  // a voxel apart from s = (2 r + voxel) / (2 sin 10 deg) on, so each arm stands apart
  // along 1 - s of its axis; the stem along its whole length but near the junction.
  const double r = 0.05, half = 10 * CGAL_PI / 180;
  Shape shape("fork", {3, 1, 0, 1});
  const Point_3 o(0, 0, 0);
  shape.add_round_cone(o, Point_3(0, -1, 0), r, r);
  shape.add_round_cone(o, Point_3(std::sin(half), std::cos(half), 0), r, r);
  shape.add_round_cone(o, Point_3(-std::sin(half), std::cos(half), 0), r, r);
  const double voxel = voxel_of(shape);
  std::vector<Skeleton_polyline> axis = shape.skeleton_polylines(voxel);
  REQUIRE(axis.size() == 3);
  axis.pop_back(); // the skeleton misses the last arm
  const Graph g = graph_from_polylines(axis, 1e-9);
  const std::vector<Tip_recall> tips = tip_recall(shape, g, voxel);
  REQUIRE(tips.size() == 3);
  const double arm_free = (1 - (2 * r + voxel) / (2 * std::sin(half))) / voxel;
  CHECK(tips[0].found);
  CHECK(tips[0].free_voxels > (1 - 4 * r) / voxel); // the depth of the union is more than r at the junction
  CHECK(tips[0].free_voxels < 1 / voxel);
  CHECK(tips[1].found);
  CHECK_FALSE(tips[2].found);
  for(int i = 1; i < 3; ++i) {
    CHECK(tips[std::size_t(i)].free_voxels > arm_free - 1);
    CHECK(tips[std::size_t(i)].free_voxels < arm_free + 1);
  }
  // shapes with plates have no designed end points to recall
  Shape plate("plate", {0, 0, 0, 1});
  plate.add_slab(o, Vector_3(1, 0, 0), Vector_3(0, 1, 0), 0.5, 0.3, 0.02, Point_3(-0.3, 0, 0), Point_3(0.3, 0, 0));
  CHECK(tip_recall(plate, g, voxel_of(plate)).empty());
}
