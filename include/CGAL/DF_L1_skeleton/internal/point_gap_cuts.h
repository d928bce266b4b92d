// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_POINT_GAP_CUTS_H
#define CGAL_DF_L1_SKELETON_INTERNAL_POINT_GAP_CUTS_H

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>

#include <CGAL/number_utils.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Whether each vertex of `g` has an edge on a cycle (an edge that is not a bridge of the
// graph), by an iterative depth-first search (low-link).
template <class Graph>
std::vector<char> on_cycle_vertices(const Graph& g)
{
  const std::size_t n = boost::num_vertices(g);
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> adjacency(n);
  std::size_t m = 0;
  for(auto e = boost::edges(g).first; e != boost::edges(g).second; ++e, ++m)
  {
    const std::size_t a = boost::source(*e, g), b = boost::target(*e, g);
    adjacency[a].emplace_back(b, m);
    adjacency[b].emplace_back(a, m);
  }
  std::vector<std::size_t> entry(n, std::size_t(-1)), low(n, 0), parent_edge(n, std::size_t(-1)), next(n, 0);
  std::vector<char> bridge(m, 0);
  std::size_t time = 0;
  for(std::size_t root = 0; root < n; ++root)
  {
    if(entry[root] != std::size_t(-1))
      continue;
    std::vector<std::size_t> stack(1, root);
    entry[root] = low[root] = time++;
    while(!stack.empty())
    {
      const std::size_t v = stack.back();
      if(next[v] < adjacency[v].size())
      {
        const auto [w, id] = adjacency[v][next[v]++];
        if(id == parent_edge[v])
          continue;
        if(entry[w] != std::size_t(-1))
          low[v] = (std::min)(low[v], entry[w]);
        else
        {
          parent_edge[w] = id;
          entry[w] = low[w] = time++;
          stack.push_back(w);
        }
      }
      else
      {
        stack.pop_back();
        if(!stack.empty())
        {
          const std::size_t u = stack.back();
          low[u] = (std::min)(low[u], low[v]);
          if(low[v] > entry[u])
            bridge[parent_edge[v]] = 1;
        }
      }
    }
  }
  std::vector<char> result(n, 0);
  m = 0;
  for(auto e = boost::edges(g).first; e != boost::edges(g).second; ++e, ++m)
    if(!bridge[m])
      result[boost::source(*e, g)] = result[boost::target(*e, g)] = 1;
  return result;
}

// Cuts the cycles of a curve graph where they cross a gap between two surfaces that the
// voxels could not separate (parts 1 or 2 voxels apart: their boundary voxels touch, and
// the pocket between them is taken for interior). Such a curve runs from one surface
// straight into the other: the input points near its line, projected on it, leave an
// empty interval near the vertex, wider than the sampling spacing or bounded by dense
// surfaces on both sides, and the points that bound it lie closer to the line than the
// local radius (the two surfaces cross it).
// Inside a part, however thin, the surface surrounds the curve: its projection has no
// such interval, and a gap in its sampling is bounded by the wall, a radius away. A
// candidate is a vertex of degree 2 on a cycle whose local radius is at most 2.5 voxels
// (the pocket is thin); the widest gaps are cut first, each only while its vertex is
// still on a cycle, so a cut never splits a component. `spacing` is the sampling spacing
// (the median distance to the 6th nearest neighbour). Returns the number of cuts.
// Where the web between two fused parts is thin (a radius of a voxel), the walls of a
// thin part would be as near the line as the surfaces across a gap, and the test above
// cannot tell them apart. A vertex in a neck between two much thicker parts (see
// `thick_part_through`) is therefore also tested along the line that joins those parts,
// without the distance test on the bounding points: inside one part that line runs
// along its axis, and only a gap between two parts leaves an empty interval across it.
// Where the distance test cannot decide (a noisy gap that holds some points, or parts
// thinner than two voxels, whose depth falls short of their radius), the surfaces that
// bound the gap must face along the line (`facing_share`).
template <class Traits>
std::size_t cut_point_gaps(Skeleton_graph<Traits>& g, const std::vector<std::array<double, 3>>& xyz, const Uniform_grid& grid,
                           double voxel, double spacing)
{
  typedef std::array<double, 3> A;
  const double reach_along = 5 * voxel, centre_window = 2 * voxel, max_radius = 2.5 * voxel, band = voxel;
  const double min_gap = 0.6 * voxel, min_width = (std::max)(min_gap, spacing);
  const std::size_t dense_wall_points = 6;
  std::vector<std::pair<double, std::size_t>> nearest;
  auto local_spacing = [&](std::size_t i) { // distance to the 6th nearest neighbour
    grid.k_nearest(xyz[i], 7, [](std::size_t) { return true; }, nearest);
    return nearest.empty() ? 0.0 : std::sqrt(nearest.back().first);
  };
  auto pos = [&](std::size_t v) {
    return A{{CGAL::to_double(g[v].point.x()), CGAL::to_double(g[v].point.y()), CGAL::to_double(g[v].point.z())}};
  };
  auto distance = [](const A& a, const A& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  };
  // one step along a curve: the neighbour of `current` (of degree 2) other than `previous`
  auto step = [&](std::size_t& previous, std::size_t& current) {
    auto it = boost::adjacent_vertices(current, g).first;
    const std::size_t n = *it == previous ? *(++it) : *it;
    previous = current;
    current = n;
  };
  // the vertex `hops` steps from v through its neighbour w, along vertices of degree 2
  auto walk = [&](std::size_t v, std::size_t w, int hops) {
    std::size_t previous = v, current = w;
    for(int h = 1; h < hops && boost::degree(current, g) == 2; ++h)
      step(previous, current);
    return current;
  };
  // The vertex where the curve from v through its neighbour w, along vertices of degree
  // 2, first reaches a part much thicker than v (radius R at least 2.5 times v's and 2.5
  // voxels) within 2 R + 2 voxels of v; `none` if it does not. A curve between two
  // parallel parts that the voxels fused crosses the web between them obliquely, within
  // about a diameter of each part's axis.
  const std::size_t none = std::size_t(-1);
  auto thick_part_through = [&](std::size_t v, std::size_t w) -> std::size_t {
    const double r = (std::max)(CGAL::to_double(g[v].radius), voxel);
    const double thick = (std::max)(2.5 * r, 2.5 * voxel);
    std::size_t previous = v, current = w;
    double along_curve = 0;
    for(;;)
    {
      along_curve += distance(pos(previous), pos(current));
      const double R = CGAL::to_double(g[current].radius);
      if(R >= thick && along_curve <= 2 * R + 2 * voxel)
        return current;
      if(along_curve > 12 * voxel || boost::degree(current, g) != 2 || current == v)
        return none;
      step(previous, current);
    }
  };
  std::vector<std::pair<double, std::size_t>> candidates; // (minus the empty width, vertex)
  {
    const std::vector<char> cyclic = on_cycle_vertices(g);
    struct Near_point
    {
      double abscissa; // along the curve
      std::size_t point;
      double offset2; // squared distance to the curve's line
      bool operator<(const Near_point& o) const
      {
        return abscissa < o.abscissa || (abscissa == o.abscissa && point < o.point);
      }
    };
    std::vector<Near_point> along;
    // The share of the points that bound the interval [lo, hi] of the line (within a voxel
    // of it, nearer the line than `near`) whose surface faces along the line: the normal
    // of their 10 nearest neighbours makes less than 60 degrees with it. The surfaces of
    // two parts face each other across a gap, while the wall of a part runs beside its
    // axis, its normals across the line.
    A direction{{0, 0, 0}}; // of the line that gap_width() examines
    auto facing_share = [&](double lo, double hi, double near) {
      std::size_t tested = 0, facing = 0;
      for(const Near_point& a : along)
      {
        if(a.abscissa < lo - voxel || a.abscissa > hi + voxel || (a.abscissa >= lo && a.abscissa <= hi) ||
           a.offset2 >= near * near)
          continue;
        grid.k_nearest(xyz[a.point], 10, [](std::size_t) { return true; }, nearest);
        if(nearest.size() < 4)
          continue;
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for(const auto& n : nearest)
          mean += Eigen::Vector3d(xyz[n.second][0], xyz[n.second][1], xyz[n.second][2]);
        mean /= double(nearest.size());
        Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
        for(const auto& n : nearest)
        {
          const Eigen::Vector3d d = Eigen::Vector3d(xyz[n.second][0], xyz[n.second][1], xyz[n.second][2]) - mean;
          covariance += d * d.transpose();
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
        const Eigen::Vector3d normal = solver.eigenvectors().col(0);
        ++tested;
        facing += std::abs(normal.dot(Eigen::Vector3d(direction[0], direction[1], direction[2]))) > 0.5;
      }
      return tested == 0 ? 0.0 : double(facing) / double(tested);
    };
    // Under noise the gap between two surfaces holds points too, but far fewer than the
    // surfaces that bound it, which cross the line there: the abscissas of the points near
    // the line show a valley between two peaks. Along a part its walls run beside the line
    // and project evenly; a hole of the scan on one side leaves half of them. The valley is
    // a voxel wide, at most a third as dense as the lower of the densest voxel-wide
    // windows within 2 voxels on either side, which hold 12 points or more and come nearer
    // the line than 0.7 of the local radius (unless `across_neck`, as for an empty gap),
    // and the surfaces that bound it face along the line (a noisy wall can thin out too).
    // Returns the valley's depth in voxels times a voxel (0 without a valley): a clean
    // empty gap of the same place ranks higher.
    std::vector<std::size_t> histogram;
    std::vector<double> histogram_offset2;
    auto valley_width = [&](double r, bool across_neck) {
      const double bin = 0.5 * voxel;
      const int bins = int(std::ceil(2 * reach_along / bin));
      histogram.assign(std::size_t(bins), 0);
      histogram_offset2.assign(std::size_t(bins), std::numeric_limits<double>::infinity());
      for(const Near_point& a : along)
      {
        const int b = (std::min)(bins - 1, (std::max)(0, int((a.abscissa + reach_along) / bin)));
        ++histogram[std::size_t(b)];
        histogram_offset2[std::size_t(b)] = (std::min)(histogram_offset2[std::size_t(b)], a.offset2);
      }
      const int wall_bins = int(std::ceil(2 * voxel / bin));
      auto pair_count = [&](int k) { return histogram[std::size_t(k)] + histogram[std::size_t(k + 1)]; };
      auto pair_offset2 = [&](int k) {
        return (std::min)(histogram_offset2[std::size_t(k)], histogram_offset2[std::size_t(k + 1)]);
      };
      double best = 0;
      for(int c = 0; c + 1 < bins; ++c)
      {
        if(std::abs((c + 1) * bin - reach_along) > centre_window)
          continue;
        std::size_t left = 0, right = 0;
        double left_offset2 = 0, right_offset2 = 0;
        for(int k = c - 2; k >= 0 && k >= c - wall_bins; --k)
          if(pair_count(k) > left)
          {
            left = pair_count(k);
            left_offset2 = pair_offset2(k);
          }
        for(int k = c + 2; k + 1 < bins && k <= c + 1 + wall_bins; ++k)
          if(pair_count(k) > right)
          {
            right = pair_count(k);
            right_offset2 = pair_offset2(k);
          }
        const std::size_t walls = (std::min)(left, right), inside = pair_count(c);
        if(walls < 2 * dense_wall_points || 3 * inside > walls)
          continue;
        if(!across_neck && std::sqrt((std::max)(left_offset2, right_offset2)) >= 0.7 * (std::max)(r, voxel))
          continue;
        const double facing = facing_share(c * bin - reach_along, (c + 2) * bin - reach_along, (std::max)(r, voxel));
        if(facing < 0.6)
          continue;
        best = (std::max)(best, voxel * (1 - double(inside) / double(walls)));
      }
      return best;
    };
    // The width of the empty interval that the points near the line through v along `t`
    // leave near v, when it passes for a gap (0 otherwise). With `across_neck`, the line
    // joins two thick parts through a neck, and the bounding points may lie anywhere in
    // the disk: the surfaces that close the gap are those of the parts themselves.
    auto gap_width = [&](std::size_t v, A t, bool across_neck) {
      const double tl = distance(t, A{{0, 0, 0}});
      if(!(tl > 0))
        return 0.0;
      for(double& c : t)
        c /= tl;
      direction = t;
      const A p = pos(v);
      const double r = CGAL::to_double(g[v].radius);
      const double disk = r + voxel; // the surface around the curve
      along.clear();
      grid.for_each_in_ball(p, std::sqrt(reach_along * reach_along + disk * disk), [&](std::size_t i, double d2) {
        const A d{{xyz[i][0] - p[0], xyz[i][1] - p[1], xyz[i][2] - p[2]}};
        const double s = d[0] * t[0] + d[1] * t[1] + d[2] * t[2];
        if(std::abs(s) <= reach_along && d2 - s * s <= disk * disk)
          along.push_back({s, i, d2 - s * s});
        return true;
      });
      std::sort(along.begin(), along.end());
      // the widest interval with a surface (6 points or more) on either side: an outlier
      // inside a part lowers its local radius, and the few points near the curve's
      // line are then that outlier and its like
      double widest = 0;
      std::size_t gap = 0; // the interval lies between along[gap] and along[gap + 1]
      for(std::size_t k = 5; k + 6 < along.size(); ++k)
        if(centre_window > along[k].abscissa && along[k + 1].abscissa > -centre_window &&
           along[k + 1].abscissa - along[k].abscissa > widest)
        {
          widest = along[k + 1].abscissa - along[k].abscissa;
          gap = k;
        }
      if(widest < min_gap)
        return valley_width(r, across_neck);
      // A curve that leaves a part crosses its surface: the points bounding the gap lie
      // near the line. Along a thin part, a sampling gap is bounded by the wall, as far
      // from the line as the local radius.
      double below_offset2 = along[gap].offset2, above_offset2 = along[gap + 1].offset2;
      for(std::size_t k = gap; k-- > 0 && along[k].abscissa >= along[gap].abscissa - band;)
        below_offset2 = (std::min)(below_offset2, along[k].offset2);
      for(std::size_t k = gap + 2; k < along.size() && along[k].abscissa <= along[gap + 1].abscissa + band; ++k)
        above_offset2 = (std::min)(above_offset2, along[k].offset2);
      const double offset = std::sqrt((std::max)({0.0, below_offset2, above_offset2}));
      // The interval is a gap when it is wider than the sampling spacing at both of its
      // ends (a sparse region of an uneven scan, or an isolated outlier, leaves wide
      // intervals that are not gaps), or when the surfaces that bound it are dense:
      // 6 points or more within its width on either side, and nearer the line (the
      // surfaces face each other across it). A gap of a voxel between two parts is
      // narrower than the spacing of a cloud of 20,000 points, and the 6th neighbour
      // misses it; a sampling gap along a thin tube is bounded by sparse walls.
      std::size_t below = 0, above = 0;
      for(std::size_t k = gap + 1; k-- > 0 && along[k].abscissa >= along[gap].abscissa - widest;)
        ++below;
      for(std::size_t k = gap + 1; k < along.size() && along[k].abscissa <= along[gap + 1].abscissa + widest; ++k)
        ++above;
      const bool near_line = across_neck || offset < 0.7 * (std::max)(r, voxel);
      const bool dense_walls = (std::min)(below, above) >= dense_wall_points && near_line;
      if(dense_walls)
        return widest;
      // the neighbour searches of the spacing test only where the walls did not decide
      if(widest < min_width || widest < local_spacing(along[gap].point) || widest < local_spacing(along[gap + 1].point))
        return 0.0;
      if(across_neck || offset < r)
        return widest;
      // The depth of a part thinner than two voxels falls short of its radius by up to a
      // voxel (its surface voxels hold its axis), so the points bounding a gap between two
      // such parts may lie farther from the line than that depth: there the gap is told
      // from a sampling gap by the surfaces facing each other across it.
      const bool thin_gap = r < 2 * voxel && offset < r + voxel &&
                            facing_share(along[gap].abscissa, along[gap + 1].abscissa, disk) >= 0.6;
      return thin_gap ? widest : 0.0;
    };
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
    {
      if(!cyclic[v] || boost::degree(v, g) != 2 || CGAL::to_double(g[v].radius) > max_radius)
        continue;
      auto it = boost::adjacent_vertices(v, g).first;
      const std::size_t a = *it, b = *(++it);
      const A pa = pos(walk(v, a, 2)), pb = pos(walk(v, b, 2));
      double widest = gap_width(v, A{{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]}}, false);
      if(!(widest > 0))
      {
        const std::size_t thick_a = thick_part_through(v, a);
        const std::size_t thick_b = thick_a != none ? thick_part_through(v, b) : none;
        if(thick_b != none)
        {
          const A qa = pos(thick_a), qb = pos(thick_b);
          widest = gap_width(v, A{{qb[0] - qa[0], qb[1] - qa[1], qb[2] - qa[2]}}, true);
        }
      }
      if(widest > 0)
        candidates.emplace_back(-widest, v);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<char> cut(boost::num_vertices(g), 0);
  std::size_t cuts = 0;
  std::vector<char> cyclic; // recomputed after each cut
  std::vector<std::size_t> cut_ends; // the neighbours of the cut vertices
  for(const auto& c : candidates)
  {
    if(cyclic.empty())
      cyclic = on_cycle_vertices(g);
    if(!cyclic[c.second] || boost::degree(c.second, g) != 2)
      continue;
    cyclic.clear();
    for(auto w = boost::adjacent_vertices(c.second, g).first; w != boost::adjacent_vertices(c.second, g).second; ++w)
      cut_ends.push_back(*w);
    boost::clear_vertex(c.second, g);
    cut[c.second] = 1;
    ++cuts;
  }
  // A cut through the web between two parts leaves the halves of the curve that crossed
  // it: each runs from a junction on a part's axis to the gap, and its tip faces the
  // other part's surface, which the spur pruning takes for the support of a limb. A half
  // (from an end of a cut to the first vertex not of degree 2) goes when that vertex is a
  // junction and the tip lies within 3 voxels of the balls of the curves around it (two
  // of its radii and 2 voxels along them: the part the half came from; the part across
  // the gap is as near). A twig cut at its tip ends a twig's length beyond them; a cut
  // through a limb (a C whose ends nearly meet) leaves ends without a junction.
  std::vector<char> in_stub(boost::num_vertices(g), 0);
  std::vector<std::pair<std::vector<std::size_t>, std::size_t>> stubs; // (vertices, where it ends)
  for(std::size_t end : cut_ends)
  {
    if(cut[end] || in_stub[end] || boost::degree(end, g) != 1)
      continue;
    std::vector<std::size_t> stub(1, end);
    std::size_t previous = end, current = *boost::adjacent_vertices(end, g).first;
    while(boost::degree(current, g) == 2)
    {
      stub.push_back(current);
      step(previous, current);
    }
    for(std::size_t v : stub)
      in_stub[v] = 1;
    stubs.emplace_back(std::move(stub), current);
  }
  for(const auto& [stub, junction] : stubs)
  {
    if(boost::degree(junction, g) < 3)
      continue;
    const double R = CGAL::to_double(g[junction].radius), within = 2 * R + 2 * voxel;
    double beyond = std::numeric_limits<double>::infinity();
    std::vector<std::pair<std::size_t, double>> open(1, {junction, 0.0});
    std::vector<std::size_t> seen(1, junction);
    while(!open.empty())
    {
      const auto [v, along_curve] = open.back();
      open.pop_back();
      beyond = (std::min)(beyond, distance(pos(v), pos(stub.front())) - CGAL::to_double(g[v].radius));
      for(auto w = boost::adjacent_vertices(v, g).first; w != boost::adjacent_vertices(v, g).second; ++w)
      {
        const double next = along_curve + distance(pos(v), pos(*w));
        if(in_stub[*w] || next > within || std::find(seen.begin(), seen.end(), *w) != seen.end())
          continue;
        seen.push_back(*w);
        open.push_back({*w, next});
      }
    }
    if(beyond <= 3 * voxel)
      for(std::size_t v : stub)
      {
        boost::clear_vertex(v, g);
        cut[v] = 1;
      }
  }
  for(std::size_t v = boost::num_vertices(g); v-- > 0;)
    if(cut[v])
      boost::remove_vertex(v, g);
  return cuts;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_POINT_GAP_CUTS_H
