// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef DF_L1_TEST_SUPPORT_SKELETON_QUALITY_H
#define DF_L1_TEST_SUPPORT_SKELETON_QUALITY_H

/// \file skeleton_quality.h
/// Measures how well a skeleton graph matches the known skeleton of a synthetic
/// `Shape` (see synthetic_shapes.h): its topology counted the way the shapes count
/// theirs, how far its edges run from the true axis (relative to the local radius),
/// how much of it leaves the solid, and how much of the true axis it covers.
///
/// The graph is any `boost::adjacency_list` whose bundled vertex property has a
/// `point` member (an Epick `Point_3`, or any point with `x()`, `y()`, `z()`), such as
/// `CGAL::DF_L1::Skeleton_graph<K>`. Nothing else of the bundle is read.
///
/// Also: `run_quality_table()`, which runs a skeleton producer on every shape and
/// variant and prints one line per case with a per-variant summary.

#include "evaluation/synthetic_shapes.h"

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <numeric>
#include <ostream>
#include <queue>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace DF_L1_test {

/// Tolerances of `measure_quality()`, in voxels unless said otherwise.
struct Quality_options
{
  /// Two vertices of degree >= 3 joined by an edge shorter than this many voxels
  /// belong to the same junction (see `Skeleton_quality::topology`).
  double junction_merge_voxels = 2.0;
  /// Off (0) by default. When > 0, two vertices of degree >= 3 also belong to the same
  /// junction when a path of the graph (through vertices of any degree) joins them with
  /// a length below this fraction of the TRUE local radius at the first one (the depth
  /// at its nearest axis point): a small tree of junctions inside one junction ball
  /// then counts once (the voxel graph of many_armed has such trees).
  double junction_merge_radius_fraction = 0.0;
  /// Off by default. When true, the vertices of degree >= 3 that lie in the junction
  /// zone of the same designed junction (`junction_zones()`) count once: where k parts
  /// leave a node at small angles they overlap for several radii, and a skeleton may
  /// resolve the k-way junction as up to k - 2 three-way ones anywhere in that overlap.
  bool merge_within_junction_zones = false;
  /// The gap between two parts' surfaces, in voxels, from which a junction zone
  /// (`junction_zones()`) takes them for separate: the resolution of the grid.
  double junction_zone_separation_voxels = 2.0;
  /// Edges are sampled at most this many voxels apart.
  double sample_step_voxels = 0.25;
  /// A point of the true axis is covered when the graph passes within
  /// max(coverage_voxels * voxel, coverage_radius_fraction * local radius).
  double coverage_voxels = 1.5;
  double coverage_radius_fraction = 0.5;
};

/// What `measure_quality()` reports.
struct Skeleton_quality
{
  /// Topology counted like `Shape::expected_topology()`:
  /// - end_points: vertices of degree 1;
  /// - junctions: vertices of degree >= 3, where a cluster of such vertices linked
  ///   (transitively) by edges shorter than `junction_merge_voxels` (2) voxels counts
  ///   as ONE junction. Only direct edges between two degree->=3 vertices link them;
  ///   a degree-2 vertex in between separates them, however short the path (unless
  ///   `Quality_options::junction_merge_radius_fraction` is set);
  /// - components: connected components, an isolated vertex (degree 0) being one
  ///   component of its own (and neither an end point nor a junction);
  /// - cycles: E - V + C (the first Betti number; parallel edges and loops count).
  Topology topology;
  /// Length-weighted mean over the edges (sampled every `sample_step_voxels`) of
  /// distance_to_axis(p) / radius_at_nearest_axis_point(p): 0 on the axis, 1 on the
  /// surface. Without edges, the plain mean over the vertices.
  double mean_axis_ratio = 0;
  /// The largest value of that ratio over the samples.
  double max_axis_ratio = 0;
  /// Fraction of the edge length whose samples lie outside the true solid
  /// (`shape.inside()` false). Without edges, the fraction of vertices outside.
  double outside_fraction = 0;
  /// Fraction of the true skeleton length (`shape.skeleton_polylines()`) lying within
  /// max(1.5 voxels, 0.5 * local radius) of the graph's edges (or of its isolated
  /// vertices): shortened end branches and missing arms lower it.
  double axis_coverage = 0;
  /// The largest distance_to_axis over the samples, in voxels.
  double max_axis_distance_in_voxels = 0;
  /// Total edge length, in input units.
  double total_length = 0;
  /// Raw counts, for diagnostics.
  std::size_t vertices = 0, edges = 0;
  std::size_t junction_vertices = 0; ///< vertices of degree >= 3 before clustering
};

/// Components, cycles and junctions must be equal; end points too, or within +-1 when
/// `noisy` (a noisy surface may leave or remove one short end branch).
inline bool topology_matches(const Topology& expected, const Topology& got, bool noisy)
{
  const int end_slack = noisy ? 1 : 0;
  return expected.components == got.components && expected.cycles == got.cycles &&
         expected.junctions == got.junctions && std::abs(expected.end_points - got.end_points) <= end_slack;
}

namespace quality_internal {

using internal::V3;

template <class P>
V3 to_v3(const P& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline double squared_distance_to_segment(const V3& p, const V3& a, const V3& b)
{
  const V3 ab = b - a, ap = p - a;
  const double len2 = internal::dot(ab, ab);
  double t = len2 > 0 ? internal::dot(ap, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const V3 d = ap - t * ab;
  return internal::dot(d, d);
}

/// Segments binned in a uniform grid, for "distance to the nearest segment, if it is
/// within r" queries. Long segments are split into pieces no longer than a cell, so
/// that each piece touches at most 2x2x2 cells; the grid is dense over the bbox of the
/// segments, its cell grown if needed to keep at most ~2M cells.
class Segment_grid
{
public:
  Segment_grid(const std::vector<std::pair<V3, V3>>& segments, double cell)
  {
    if(segments.empty())
      return;
    V3 lo = segments.front().first, hi = lo;
    auto extend = [&](const V3& p) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    };
    for(const auto& s : segments) {
      extend(s.first);
      extend(s.second);
    }
    const V3 extent = hi - lo;
    const double max_cells = 2.0e6;
    const double biggest = std::max({extent.x, extent.y, extent.z, 1e-300});
    cell = std::max({cell, biggest * 1e-6, std::cbrt((extent.x + cell) * (extent.y + cell) * (extent.z + cell) / max_cells)});
    cell_ = cell;
    origin_ = lo;
    dims_[0] = int(extent.x / cell) + 1;
    dims_[1] = int(extent.y / cell) + 1;
    dims_[2] = int(extent.z / cell) + 1;

    for(const auto& s : segments) {
      const double length = internal::norm(s.second - s.first);
      const std::size_t n = std::max<std::size_t>(1, std::size_t(std::ceil(length / cell)));
      V3 prev = s.first;
      for(std::size_t i = 1; i <= n; ++i) {
        const V3 next = i == n ? s.second : s.first + (double(i) / double(n)) * (s.second - s.first);
        pieces_.emplace_back(prev, next);
        prev = next;
      }
    }
    // Two passes (count, fill) into one flat array: compressed rows per cell.
    const std::size_t cells = std::size_t(dims_[0]) * std::size_t(dims_[1]) * std::size_t(dims_[2]);
    start_.assign(cells + 1, 0);
    for(int pass = 0; pass < 2; ++pass) {
      std::vector<std::size_t> fill;
      if(pass == 1) {
        std::partial_sum(start_.begin(), start_.end(), start_.begin());
        items_.resize(start_.back());
        fill.assign(start_.begin(), start_.end() - 1);
      }
      for(std::size_t k = 0; k < pieces_.size(); ++k) {
        int a[3], b[3];
        cell_range(pieces_[k].first, pieces_[k].second, 0.0, a, b);
        for(int z = a[2]; z <= b[2]; ++z)
          for(int y = a[1]; y <= b[1]; ++y)
            for(int x = a[0]; x <= b[0]; ++x) {
              const std::size_t c = index(x, y, z);
              if(pass == 0)
                ++start_[c + 1];
              else
                items_[fill[c]++] = k;
            }
      }
    }
  }

  /// Distance from `p` to the nearest segment when it is <= `r`, +infinity otherwise.
  double distance_within(const V3& p, double r) const
  {
    double best2 = std::numeric_limits<double>::infinity();
    if(pieces_.empty())
      return best2;
    int a[3], b[3];
    if(!cell_range(p, p, r, a, b))
      return best2;
    for(int z = a[2]; z <= b[2]; ++z)
      for(int y = a[1]; y <= b[1]; ++y)
        for(int x = a[0]; x <= b[0]; ++x) {
          const std::size_t c = index(x, y, z);
          for(std::size_t i = start_[c]; i < start_[c + 1]; ++i) {
            const auto& s = pieces_[items_[i]];
            best2 = std::min(best2, squared_distance_to_segment(p, s.first, s.second));
          }
        }
    const double best = std::sqrt(best2);
    return best <= r ? best : std::numeric_limits<double>::infinity();
  }

private:
  std::size_t index(int x, int y, int z) const
  {
    return (std::size_t(z) * std::size_t(dims_[1]) + std::size_t(y)) * std::size_t(dims_[0]) + std::size_t(x);
  }

  /// Cells overlapping the box of p, q grown by r, clamped to the grid; false if none.
  bool cell_range(const V3& p, const V3& q, double r, int a[3], int b[3]) const
  {
    const double lo[3] = {std::min(p.x, q.x) - r - origin_.x, std::min(p.y, q.y) - r - origin_.y,
                          std::min(p.z, q.z) - r - origin_.z};
    const double hi[3] = {std::max(p.x, q.x) + r - origin_.x, std::max(p.y, q.y) + r - origin_.y,
                          std::max(p.z, q.z) + r - origin_.z};
    for(int d = 0; d < 3; ++d) {
      const double l = std::floor(lo[d] / cell_), h = std::floor(hi[d] / cell_);
      if(h < 0 || l > dims_[d] - 1)
        return false;
      a[d] = int(std::max(0.0, l));
      b[d] = int(std::min(double(dims_[d] - 1), h));
    }
    return true;
  }

  double cell_ = 1;
  V3 origin_;
  int dims_[3] = {0, 0, 0};
  std::vector<std::pair<V3, V3>> pieces_;
  std::vector<std::size_t> start_, items_;
};

/// Distance from `p` to the polyline `pl` and the radius of `pl` at its nearest sample.
inline std::pair<double, double> distance_to_polyline(const V3& p, const Skeleton_polyline& pl)
{
  double best2 = std::numeric_limits<double>::infinity(), radius = 0;
  for(std::size_t i = 0; i + 1 < pl.points.size(); ++i) {
    const double d2 = squared_distance_to_segment(p, to_v3(pl.points[i]), to_v3(pl.points[i + 1]));
    if(d2 < best2) {
      best2 = d2;
      radius = std::max(pl.radii[i], pl.radii[i + 1]);
    }
  }
  return {std::sqrt(best2), radius};
}

inline std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while(parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

/// The curves of `axis` that start or end within `eps` of `c`, as (curve, walked from its
/// back): a closed curve through `c` comes twice, once each way.
inline std::vector<std::pair<std::size_t, bool>> curves_at(const std::vector<Skeleton_polyline>& axis, const V3& c,
                                                         double eps)
{
  std::vector<std::pair<std::size_t, bool>> arms;
  for(std::size_t i = 0; i < axis.size(); ++i) {
    if(axis[i].points.size() < 2)
      continue;
    if(internal::norm(to_v3(axis[i].points.front()) - c) <= eps)
      arms.emplace_back(i, false);
    if(internal::norm(to_v3(axis[i].points.back()) - c) <= eps)
      arms.emplace_back(i, true);
  }
  return arms;
}

} // namespace quality_internal

/// A designed junction and the ball around it where its parts still overlap.
struct Junction_zone
{
  quality_internal::V3 centre;
  double radius = 0;
};

/// The junction zones of `shape`: for every node of its skeleton graph of degree >= 3,
/// the ball centred there that reaches as far as the farthest point where two of the
/// parts leaving the node are not yet `separation` apart (walking out along each axis
/// curve, the first sample where the distance to the other axis exceeds the sum of the
/// radii plus `separation`), and at least the local radius at the node. With
/// `separation` 0, parts leaving at 25 degrees from each other overlap for about 4.6 of
/// their radii; a voxel grid tells two parts apart only when their surfaces are a voxel
/// or two apart (the occupied voxels of each reach up to a voxel beyond its surface).
inline std::vector<Junction_zone> junction_zones(const Shape& shape, double separation = 0)
{
  using quality_internal::V3;
  using quality_internal::to_v3;
  std::vector<Junction_zone> zones;
  const std::vector<Skeleton_polyline> axis = shape.skeleton_polylines();
  const double eps = 1e-9 * shape.bbox_diagonal();
  for(const Skeleton_node& node : shape.skeleton_nodes()) {
    if(node.degree < 3)
      continue;
    const V3 c = to_v3(node.point);
    const std::vector<std::pair<std::size_t, bool>> arms = quality_internal::curves_at(axis, c, eps);
    Junction_zone zone{c, std::max(0.0, -shape.signed_distance(node.point))};
    for(const auto& a : arms)
      for(const auto& b : arms) {
        if(a == b)
          continue;
        const Skeleton_polyline& pa = axis[a.first];
        const Skeleton_polyline& pb = axis[b.first];
        const std::size_t count = pa.points.size();
        for(std::size_t k = 0; k < count; ++k) {
          const std::size_t i = a.second ? count - 1 - k : k;
          const V3 p = to_v3(pa.points[i]);
          const std::pair<double, double> other = quality_internal::distance_to_polyline(p, pb);
          zone.radius = std::max(zone.radius, internal::norm(p - c));
          if(other.first > pa.radii[i] + other.second + separation)
            break;
        }
      }
    zones.push_back(zone);
  }
  return zones;
}

/// A designed end point of a shape and whether a skeleton shows it.
struct Tip_recall
{
  /// How far the limb stands apart: the length (voxels) of its axis, from the tip back,
  /// along which its surface stays at least a voxel away from every other part (the
  /// first axis sample closer than that ends it). A twig fused with a sibling to near its
  /// end scores about 0: in the voxel grid it is one lobe with the sibling.
  double free_voxels = 0;
  bool found = false; ///< an end point of the skeleton within max(3 voxels, 3 radii) of the tip
};

/// For each designed end point of `shape` (none on shapes with plates), how far its limb
/// stands apart and whether `g` has an end point there: what `Skeleton_quality`'s end
/// count cannot tell, which tips are missed, the resolvable ones or those fused with
/// their neighbours.
template <class Graph>
std::vector<Tip_recall> tip_recall(const Shape& shape, const Graph& g, double voxel_size)
{
  using quality_internal::V3;
  using quality_internal::to_v3;
  std::vector<Tip_recall> result;
  if(shape.has_sheets() || !(voxel_size > 0))
    return result;
  std::vector<V3> ends;
  for(auto range = boost::vertices(g); range.first != range.second; ++range.first)
    if(boost::degree(*range.first, g) == 1)
      ends.push_back(to_v3(g[*range.first].point));
  const std::vector<Skeleton_polyline> axis = shape.skeleton_polylines(0.5 * voxel_size);
  const double eps = 1e-9 * shape.bbox_diagonal();
  for(const Skeleton_node& node : shape.skeleton_nodes()) {
    if(node.degree != 1)
      continue;
    const V3 tip = to_v3(node.point);
    Tip_recall t;
    const double radius = std::max(0.0, -shape.signed_distance(node.point));
    const double reach = std::max(3 * voxel_size, 3 * radius);
    for(const V3& e : ends)
      t.found = t.found || internal::norm(e - tip) <= reach;
    const std::vector<std::pair<std::size_t, bool>> arms = quality_internal::curves_at(axis, tip, eps);
    if(!arms.empty()) {
      const std::size_t a = arms.front().first;
      const bool from_back = arms.front().second;
      const Skeleton_polyline& own = axis[a];
      const std::size_t count = own.points.size();
      double length = 0;
      for(std::size_t k = 0; k < count; ++k) {
        const std::size_t i = from_back ? count - 1 - k : k;
        const V3 p = to_v3(own.points[i]);
        if(k > 0)
          length += internal::norm(p - to_v3(own.points[from_back ? i + 1 : i - 1]));
        double clearance = std::numeric_limits<double>::infinity();
        for(std::size_t b = 0; b < axis.size(); ++b)
          if(b != a) {
            const std::pair<double, double> other = quality_internal::distance_to_polyline(p, axis[b]);
            clearance = std::min(clearance, other.first - own.radii[i] - other.second);
          }
        if(clearance < voxel_size)
          break;
        t.free_voxels = length / voxel_size;
      }
    }
    result.push_back(t);
  }
  return result;
}

/// Measures `g` against the known skeleton of `shape`; `voxel_size` (input units) sets
/// the tolerances (see `Quality_options` and the fields of `Skeleton_quality`).
template <class Graph>
Skeleton_quality measure_quality(const Shape& shape, const Graph& g, double voxel_size,
                                 const Quality_options& options = Quality_options())
{
  using quality_internal::V3;
  typedef typename boost::graph_traits<Graph>::vertex_descriptor Vertex;
  if(!(voxel_size > 0))
    throw std::invalid_argument("measure_quality: the voxel size must be positive");

  Skeleton_quality q;
  // Vertices in iteration order, with their positions and degrees.
  std::vector<Vertex> vertices;
  std::unordered_map<Vertex, std::size_t> index_of;
  std::vector<V3> position;
  for(auto range = boost::vertices(g); range.first != range.second; ++range.first) {
    const Vertex v = *range.first;
    index_of.emplace(v, vertices.size());
    vertices.push_back(v);
    position.push_back(quality_internal::to_v3(g[v].point));
  }
  const std::size_t n = vertices.size();
  std::vector<std::size_t> degree(n, 0);
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for(auto range = boost::edges(g); range.first != range.second; ++range.first) {
    const std::size_t a = index_of.at(boost::source(*range.first, g)), b = index_of.at(boost::target(*range.first, g));
    edges.emplace_back(a, b);
    ++degree[a];
    ++degree[b]; // a loop adds 2, as in Shape::skeleton_topology()
  }
  q.vertices = n;
  q.edges = edges.size();

  // --- Topology.
  std::vector<std::size_t> parent(n), junction_parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::iota(junction_parent.begin(), junction_parent.end(), std::size_t(0));
  const double merge_length = options.junction_merge_voxels * voxel_size;
  for(const auto& e : edges) {
    parent[quality_internal::find_root(parent, e.first)] = quality_internal::find_root(parent, e.second);
    if(degree[e.first] >= 3 && degree[e.second] >= 3 && internal::norm(position[e.first] - position[e.second]) < merge_length)
      junction_parent[quality_internal::find_root(junction_parent, e.first)] =
        quality_internal::find_root(junction_parent, e.second);
  }
  if(options.junction_merge_radius_fraction > 0) {
    // Bounded Dijkstra from every junction vertex over the graph.
    std::vector<std::vector<std::pair<std::size_t, double>>> adjacency(n);
    for(const auto& e : edges) {
      const double length = internal::norm(position[e.first] - position[e.second]);
      adjacency[e.first].emplace_back(e.second, length);
      adjacency[e.second].emplace_back(e.first, length);
    }
    std::vector<double> reach(n, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> touched;
    for(std::size_t j = 0; j < n; ++j) {
      if(degree[j] < 3)
        continue;
      const double limit =
        options.junction_merge_radius_fraction * shape.radius_at_nearest_axis_point(internal::to_point(position[j]));
      typedef std::pair<double, std::size_t> Item;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
      reach[j] = 0;
      touched.push_back(j);
      queue.emplace(0.0, j);
      while(!queue.empty()) {
        const Item top = queue.top();
        queue.pop();
        if(top.first > reach[top.second])
          continue;
        if(degree[top.second] >= 3)
          junction_parent[quality_internal::find_root(junction_parent, top.second)] =
            quality_internal::find_root(junction_parent, j);
        for(const auto& next : adjacency[top.second]) {
          const double d = top.first + next.second;
          if(d < limit && d < reach[next.first]) {
            if(reach[next.first] == std::numeric_limits<double>::infinity())
              touched.push_back(next.first);
            reach[next.first] = d;
            queue.emplace(d, next.first);
          }
        }
      }
      for(std::size_t t : touched)
        reach[t] = std::numeric_limits<double>::infinity();
      touched.clear();
    }
  }
  if(options.merge_within_junction_zones) {
    // Each junction vertex joins the zone it lies deepest in (relative to the radius).
    const std::vector<Junction_zone> zones = junction_zones(shape, options.junction_zone_separation_voxels * voxel_size);
    std::vector<std::size_t> first_in_zone(zones.size(), n);
    for(std::size_t j = 0; j < n; ++j) {
      if(degree[j] < 3)
        continue;
      std::size_t best = zones.size();
      double best_ratio = 1;
      for(std::size_t z = 0; z < zones.size(); ++z) {
        const double ratio = internal::norm(position[j] - zones[z].centre) / zones[z].radius;
        if(ratio <= best_ratio) {
          best_ratio = ratio;
          best = z;
        }
      }
      if(best == zones.size())
        continue;
      if(first_in_zone[best] == n)
        first_in_zone[best] = j;
      else
        junction_parent[quality_internal::find_root(junction_parent, j)] =
          quality_internal::find_root(junction_parent, first_in_zone[best]);
    }
  }
  for(std::size_t i = 0; i < n; ++i) {
    q.topology.components += quality_internal::find_root(parent, i) == i;
    q.topology.end_points += degree[i] == 1;
    q.junction_vertices += degree[i] >= 3;
    q.topology.junctions += degree[i] >= 3 && quality_internal::find_root(junction_parent, i) == i;
  }
  q.topology.cycles = int(edges.size()) - int(n) + q.topology.components;

  // --- Distance to the axis and inside test, on dense edge samples (weight = length).
  double weight_sum = 0, ratio_sum = 0, outside_sum = 0;
  auto sample = [&](const V3& p, double weight) {
    const Point_3 point = internal::to_point(p);
    const Point_3 axis_point = shape.nearest_axis_point(point); // distance_to_axis, radius_at_nearest_axis_point
    const double d = internal::norm(p - internal::to_v3(axis_point));
    const double radius = std::max(-shape.signed_distance(axis_point), 1e-12 * shape.bbox_diagonal());
    const double ratio = d / radius;
    ratio_sum += weight * ratio;
    q.max_axis_ratio = std::max(q.max_axis_ratio, ratio);
    q.max_axis_distance_in_voxels = std::max(q.max_axis_distance_in_voxels, d / voxel_size);
    if(!shape.inside(point))
      outside_sum += weight;
    weight_sum += weight;
  };
  const double step = options.sample_step_voxels * voxel_size;
  for(const auto& e : edges) {
    const V3 a = position[e.first], b = position[e.second];
    const double length = internal::norm(b - a);
    q.total_length += length;
    if(!(length > 0))
      continue;
    const std::size_t k = std::max<std::size_t>(1, std::size_t(std::ceil(length / step)));
    for(std::size_t i = 0; i < k; ++i) // midpoints of k equal pieces
      sample(a + ((double(i) + 0.5) / double(k)) * (b - a), length / double(k));
  }
  if(!(weight_sum > 0)) { // no edge of positive length: the vertices, with equal weights
    for(std::size_t i = 0; i < n; ++i)
      sample(position[i], 1.0);
  }
  if(weight_sum > 0) {
    q.mean_axis_ratio = ratio_sum / weight_sum;
    q.outside_fraction = outside_sum / weight_sum;
  }

  // --- Coverage of the true axis by the edges (and isolated vertices, as points).
  const std::vector<Skeleton_polyline> axis = shape.skeleton_polylines();
  double max_tolerance = options.coverage_voxels * voxel_size;
  for(const Skeleton_polyline& pl : axis)
    for(double r : pl.radii)
      max_tolerance = std::max({max_tolerance, options.coverage_radius_fraction * r,
                                options.coverage_radius_fraction * pl.sheet_half_width});
  std::vector<std::pair<V3, V3>> segments;
  segments.reserve(edges.size() + n);
  for(const auto& e : edges)
    segments.emplace_back(position[e.first], position[e.second]);
  for(std::size_t i = 0; i < n; ++i)
    if(degree[i] == 0)
      segments.emplace_back(position[i], position[i]);
  const quality_internal::Segment_grid grid(segments, std::max(max_tolerance, voxel_size));
  double axis_length = 0, covered = 0;
  for(const Skeleton_polyline& pl : axis)
    for(std::size_t i = 0; i + 1 < pl.points.size(); ++i) {
      const V3 a = internal::to_v3(pl.points[i]), b = internal::to_v3(pl.points[i + 1]);
      const double length = internal::norm(b - a);
      const double tolerance = std::max({options.coverage_voxels * voxel_size,
                                         options.coverage_radius_fraction * 0.5 * (pl.radii[i] + pl.radii[i + 1]),
                                         options.coverage_radius_fraction * pl.sheet_half_width});
      axis_length += length;
      if(grid.distance_within(0.5 * (a + b), tolerance) <= tolerance)
        covered += length;
    }
  q.axis_coverage = axis_length > 0 ? covered / axis_length : 0.0;
  return q;
}

/// "ends/junctions/cycles/components", e.g. "3/1/0/1".
inline std::string compact(const Topology& t)
{
  return std::to_string(t.end_points) + "/" + std::to_string(t.junctions) + "/" + std::to_string(t.cycles) + "/" +
         std::to_string(t.components);
}

/// The column titles of `describe()`.
inline std::string describe_header()
{
  char line[256];
  std::snprintf(line, sizeof line, "%-16s %-8s %-11s %-11s %-4s %6s %6s %7s %8s %7s", "shape", "variant",
                "got e/j/c/k", "expected", "topo", "ratio", "max", "outside", "coverage", "maxdist");
  return line;
}

/// One line: shape, variant, topology got vs expected (ends/junctions/cycles/components),
/// whether `topology_matches()` (noisy = variant != clean), mean and max axis ratio,
/// outside fraction, axis coverage and max distance to the axis in voxels.
inline std::string describe(const std::string& shape_name, Variant variant, const Topology& expected,
                            const Skeleton_quality& q)
{
  const bool ok = topology_matches(expected, q.topology, variant != Variant::clean);
  char line[256];
  std::snprintf(line, sizeof line, "%-16s %-8s %-11s %-11s %-4s %6.3f %6.3f %7.4f %8.4f %7.2f", shape_name.c_str(),
                to_string(variant), compact(q.topology).c_str(), compact(expected).c_str(), ok ? "ok" : "FAIL",
                q.mean_axis_ratio, q.max_axis_ratio, q.outside_fraction, q.axis_coverage,
                q.max_axis_distance_in_voxels);
  return line;
}

inline std::string describe(const Shape& shape, Variant variant, const Skeleton_quality& q)
{
  return describe(shape.name(), variant, shape.expected_topology(), q);
}

// ---------------------------------------------------------------------------------
// The table over all shapes and variants.

/// What a skeleton producer returns: the graph and the voxel size to judge it with.
template <class Graph>
struct Skeleton_run
{
  Graph graph;
  double voxel_size = 0;
};

struct Quality_table_options
{
  std::size_t points = 20000; ///< make_sample size (the sparse variant ignores it)
  std::uint64_t seed = 7;
  std::vector<std::pair<std::string, Shape>> shapes = all_shapes();
  std::vector<Variant> variants = all_variants();
  Quality_options quality;
};

struct Quality_table_row
{
  std::string shape;
  Variant variant = Variant::clean;
  Topology expected;
  Skeleton_quality quality;
  bool topology_ok = false;
  double seconds = 0;  ///< time of the producer
  std::string error;   ///< what the producer threw, if it did (the row then fails)
};

struct Quality_table
{
  std::vector<Quality_table_row> rows;
  /// Rows with `topology_ok` for `variant`.
  std::size_t passes(Variant variant) const
  {
    return std::size_t(std::count_if(rows.begin(), rows.end(), [&](const Quality_table_row& r) {
      return r.variant == variant && r.topology_ok;
    }));
  }
  std::size_t cases(Variant variant) const
  {
    return std::size_t(std::count_if(rows.begin(), rows.end(), [&](const Quality_table_row& r) { return r.variant == variant; }));
  }
};

/// Runs `produce` on `make_sample(shape, variant, points, seed).points` for every shape
/// and variant of `options`, measures each graph and prints one `describe()` line per
/// case (plus the producer's time), then one summary line per variant (topology passes,
/// mean ratio, mean outside fraction, mean and minimum coverage). `produce` is any
/// callable `Skeleton_run<Graph>(const std::vector<Point_3>&)`, e.g. a
/// `std::function`; an exception it throws is printed and makes the case fail.
template <class Producer>
Quality_table run_quality_table(const Producer& produce, std::ostream& os,
                                const Quality_table_options& options = Quality_table_options())
{
  Quality_table table;
  os << describe_header() << "  seconds\n";
  for(Variant variant : options.variants)
    for(const auto& entry : options.shapes) {
      Quality_table_row row;
      row.shape = entry.first;
      row.variant = variant;
      row.expected = entry.second.expected_topology();
      const Sample sample = make_sample(entry.second, variant, options.points, options.seed);
      const auto start = std::chrono::steady_clock::now();
      try {
        const auto run = produce(sample.points);
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        row.quality = measure_quality(entry.second, run.graph, run.voxel_size, options.quality);
        row.topology_ok = topology_matches(row.expected, row.quality.topology, variant != Variant::clean);
        char time[32];
        std::snprintf(time, sizeof time, "  %7.2f", row.seconds);
        os << describe(row.shape, variant, row.expected, row.quality) << time << '\n';
      } catch(const std::exception& e) {
        row.error = e.what();
        os << row.shape << ' ' << to_string(variant) << ": ERROR " << row.error << '\n';
      }
      os.flush();
      table.rows.push_back(row);
    }
  os << "\nper variant: topology passes, mean ratio, mean outside, mean coverage, min coverage\n";
  std::size_t total_pass = 0, total = 0;
  for(Variant variant : options.variants) {
    double ratio = 0, outside = 0, coverage = 0, min_coverage = 1;
    std::size_t measured = 0;
    for(const Quality_table_row& r : table.rows)
      if(r.variant == variant && r.error.empty()) {
        ratio += r.quality.mean_axis_ratio;
        outside += r.quality.outside_fraction;
        coverage += r.quality.axis_coverage;
        min_coverage = std::min(min_coverage, r.quality.axis_coverage);
        ++measured;
      }
    const double m = double(std::max<std::size_t>(1, measured));
    char line[200];
    std::snprintf(line, sizeof line, "%-8s %2zu/%-2zu  ratio %.3f  outside %.4f  coverage %.4f  (min %.4f)",
                  to_string(variant), table.passes(variant), table.cases(variant), ratio / m, outside / m,
                  coverage / m, measured ? min_coverage : 0.0);
    os << line << '\n';
    total_pass += table.passes(variant);
    total += table.cases(variant);
  }
  os << "all      " << total_pass << '/' << total << '\n';
  return table;
}

} // namespace DF_L1_test

#endif // DF_L1_TEST_SUPPORT_SKELETON_QUALITY_H
