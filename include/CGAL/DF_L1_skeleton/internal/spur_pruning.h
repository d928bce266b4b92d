// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_SPUR_PRUNING_H
#define CGAL_DF_L1_SKELETON_INTERNAL_SPUR_PRUNING_H

/// \file spur_pruning.h
/// Removal of the terminal branches of a skeleton graph that add nothing to the shape.
/// Not part of the public API.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/internal/curve_graph_editing.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>

#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The points a skeleton was extracted from, as evidence for its terminal branches
// (`prune_spurs()`); `grid` holds `points`. Empty: no evidence.
struct Point_support
{
  const std::vector<std::array<double, 3>>* points = nullptr;
  const Uniform_grid* grid = nullptr;
  bool empty() const { return points == nullptr || grid == nullptr || points->empty(); }
};

// The balls of a skeleton graph (vertex, local radius), to ask whether those of a chain
// of vertices, or points near it, reach beyond the union of the others.
class Ball_cover
{
public:
  template <class Traits>
  explicit Ball_cover(const Skeleton_graph<Traits>& g)
  {
    const std::size_t n = boost::num_vertices(g);
    xyz_.resize(n);
    radius_.resize(n);
    for(std::size_t v = 0; v < n; ++v)
    {
      xyz_[v] = {{CGAL::to_double(g[v].point.x()), CGAL::to_double(g[v].point.y()), CGAL::to_double(g[v].point.z())}};
      radius_[v] = CGAL::to_double(g[v].radius);
      max_radius_ = (std::max)(max_radius_, radius_[v]);
    }
    by_x_.resize(n);
    std::iota(by_x_.begin(), by_x_.end(), std::size_t(0));
    std::sort(by_x_.begin(), by_x_.end(), [&](std::size_t a, std::size_t b) {
      return xyz_[a][0] != xyz_[b][0] ? xyz_[a][0] < xyz_[b][0] : a < b;
    });
  }

  // Whether some vertex v of `chain` sticks out of the union of the balls of the
  // vertices u with `excluded[u] == 0` by at least enough + per_radius r(v): whether
  // one of 26 points on the sphere of v (and v itself) lies that far outside every ball.
  bool sticks_out(const std::vector<std::size_t>& chain, const std::vector<char>& excluded, double enough,
                  double per_radius) const
  {
    static const std::array<std::array<double, 3>, 27> directions = [] {
      std::array<std::array<double, 3>, 27> d;
      for(int cell = 0; cell < 27; ++cell)
      {
        const double x = cell % 3 - 1, y = cell / 3 % 3 - 1, z = cell / 9 - 1, l = std::sqrt(x * x + y * y + z * z);
        d[cell] = l > 0 ? std::array<double, 3>{{x / l, y / l, z / l}} : std::array<double, 3>{{0, 0, 0}};
      }
      return d;
    }();
    for(std::size_t v : chain)
    {
      const double need = enough + per_radius * radius_[v];
      for(const std::array<double, 3>& d : directions)
      {
        const std::array<double, 3> p{{xyz_[v][0] + radius_[v] * d[0], xyz_[v][1] + radius_[v] * d[1],
                                       xyz_[v][2] + radius_[v] * d[2]}};
        if(!covered(p, need, excluded))
          return true;
      }
    }
    return false;
  }

  // Whether the points of `support` within `window` of `tip` stick out of the union of
  // the balls of the vertices u with `excluded[u] == 0` by more than `slack`: at least 3
  // of them and a tenth, so that a few outliers or noisy points do not count.
  bool points_stick_out(const Point_support& support, const std::array<double, 3>& tip, double window, double slack,
                        const std::vector<char>& excluded) const
  {
    std::size_t near = 0, out = 0;
    support.grid->for_each_in_ball(tip, window, [&](std::size_t i, double) {
      ++near;
      if(!covered((*support.points)[i], slack, excluded))
        ++out;
      return true;
    });
    return out >= 3 && 10 * out >= near;
  }

private:
  // Whether p lies within `slack` of a ball of a vertex u with `excluded[u] == 0`.
  bool covered(const std::array<double, 3>& p, double slack, const std::vector<char>& excluded) const
  {
    const double reach = max_radius_ + slack;
    auto first = std::lower_bound(by_x_.begin(), by_x_.end(), p[0] - reach,
                                  [&](std::size_t u, double x) { return xyz_[u][0] < x; });
    for(auto it = first; it != by_x_.end() && xyz_[*it][0] <= p[0] + reach; ++it)
    {
      const std::size_t u = *it;
      if(excluded[u])
        continue;
      const double dx = xyz_[u][0] - p[0], dy = xyz_[u][1] - p[1], dz = xyz_[u][2] - p[2];
      const double r = radius_[u] + slack;
      if(dx * dx + dy * dy + dz * dz < r * r)
        return true;
    }
    return false;
  }

  std::vector<std::array<double, 3>> xyz_;
  std::vector<double> radius_;
  std::vector<std::size_t> by_x_;
  double max_radius_ = 0;
};

// Removes, repeatedly, the terminal branches that add nothing to the shape: those
// shorter than `ratio` times the local radius at their junction plus a voxel, and those
// whose balls the balls of the rest of the skeleton cover to within 2.5 voxels plus half
// their radius, or 2 voxels plus their radius for a branch ending less than two voxels
// deep (the hair that thinning grows on bumps of the surface, in the crotches of
// junctions and on the ragged sides of thin parts), plus twice the surface `noise`, the
// height of the bumps it raises. A limb, however short or tapered, sticks out of the body
// it leaves.
// The balls are as coarse as the voxels, and that slack also covers the cap of a short
// twig beside its parent. With `support`, a covered branch is kept when the points within
// its tip's radius plus 2 voxels stick out of the rest's balls by more than 3 voxels plus
// twice the noise: the cap of a twig does, the points around hair lie on the surface that
// the rest's balls reach.
template <class Traits>
void prune_spurs(Skeleton_graph<Traits>& g, double ratio, double voxel_size, double noise = 0,
                 const Point_support& support = Point_support())
{
  typedef typename boost::graph_traits<Skeleton_graph<Traits>>::vertex_descriptor vertex;
  // Thin ends get less slack (a twig tip is a voxel or two wide) but more per radius.
  const double deep_slack = 2.5 * voxel_size + 2 * noise, deep_per_radius = 0.5;
  const double thin_slack = 2.0 * voxel_size + 2 * noise, thin_per_radius = 1.0;
  const double point_slack = 3.0 * voxel_size + 2 * noise;
  for(bool changed = true; changed;)
  {
    changed = false;
    std::vector<char> doomed(boost::num_vertices(g), 0);
    // the terminal chains not doomed by length
    struct Candidate
    {
      std::vector<std::size_t> chain;
      double length;        // up to the edge to the junction
      bool thin;            // ends less than two voxels deep
      std::size_t junction; // where the chain meets the rest
    };
    std::vector<Candidate> candidates;
    // Chains to remove. Two of them at one junction go in different rounds: once one is
    // gone, the other may merge with the branch behind it (a hair on the side of a twig
    // near its tip leaves the tip on a short chain that the hair and the twig cover).
    std::vector<Candidate> removals;
    for(vertex end = 0; end < boost::num_vertices(g); ++end)
    {
      if(boost::degree(end, g) != 1)
        continue;
      std::vector<vertex> chain(1, end);
      double length = 0;
      vertex previous = end, current = *boost::adjacent_vertices(end, g).first;
      while(boost::degree(current, g) == 2)
      {
        length += std::sqrt(CGAL::to_double(CGAL::squared_distance(g[previous].point, g[current].point)));
        chain.push_back(current);
        auto next = boost::adjacent_vertices(current, g).first;
        const vertex n = *next == previous ? *(++next) : *next;
        previous = current;
        current = n;
      }
      if(boost::degree(current, g) < 3)
      {
        // A whole component: the skeleton of a separate part (a ball gives a point or a
        // short curve), unless it is shallower than two voxels and shorter than four
        // times that, a fold of the surface (a thin object apart is longer).
        double max_radius = 0;
        for(vertex v : chain)
          max_radius = (std::max)(max_radius, CGAL::to_double(g[v].radius));
        max_radius = (std::max)(max_radius, CGAL::to_double(g[current].radius));
        length += std::sqrt(CGAL::to_double(CGAL::squared_distance(g[previous].point, g[current].point)));
        if(boost::degree(current, g) == 1 && max_radius < 2 * voxel_size && length < 8 * voxel_size)
        {
          chain.push_back(current);
          for(vertex v : chain)
            doomed[v] = 1;
        }
        continue;
      }
      const double chain_length = length;
      length += std::sqrt(CGAL::to_double(CGAL::squared_distance(g[previous].point, g[current].point)));
      Candidate k{std::vector<std::size_t>(chain.begin(), chain.end()), chain_length,
                  CGAL::to_double(g[end].radius) < 2 * voxel_size, current};
      if(length < ratio * CGAL::to_double(g[current].radius) + voxel_size)
        removals.push_back(std::move(k));
      else
        candidates.push_back(std::move(k));
    }
    if(!candidates.empty())
    {
      // Covered against everything else first; a chain covered only by other covered
      // chains (two hairs side by side) is kept unless it is covered without them.
      const Ball_cover cover(g);
      auto sticks_out = [&](std::size_t c, const std::vector<char>& excluded) {
        const Candidate& k = candidates[c];
        if(k.thin ? cover.sticks_out(k.chain, excluded, thin_slack, thin_per_radius)
                  : cover.sticks_out(k.chain, excluded, deep_slack, deep_per_radius))
          return true;
        if(support.empty())
          return false;
        const auto& tip = g[k.chain.front()];
        const std::array<double, 3> at{{CGAL::to_double(tip.point.x()), CGAL::to_double(tip.point.y()),
                                        CGAL::to_double(tip.point.z())}};
        return cover.points_stick_out(support, at, CGAL::to_double(tip.radius) + 2 * voxel_size, point_slack, excluded);
      };
      std::vector<char> excluded(boost::num_vertices(g), 0);
      std::vector<std::size_t> covered;
      for(std::size_t c = 0; c < candidates.size(); ++c)
      {
        for(std::size_t v : candidates[c].chain)
          excluded[v] = 1;
        if(!sticks_out(c, excluded))
          covered.push_back(c);
        for(std::size_t v : candidates[c].chain)
          excluded[v] = 0;
      }
      for(std::size_t c : covered)
        for(std::size_t v : candidates[c].chain)
          excluded[v] = 1;
      bool any = false;
      for(std::size_t c : covered)
        if(!sticks_out(c, excluded))
        {
          removals.push_back(candidates[c]);
          any = true;
        }
      if(!any && !covered.empty())
      {
        // Chains that only cover each other (a hair beside a branch tip, two hairs side
        // by side): the shortest goes, one per round.
        const std::size_t shortest = *std::min_element(covered.begin(), covered.end(), [&](std::size_t a, std::size_t b) {
          return candidates[a].length < candidates[b].length;
        });
        removals.push_back(candidates[shortest]);
      }
    }
    std::stable_sort(removals.begin(), removals.end(),
                     [](const Candidate& a, const Candidate& b) { return a.length < b.length; });
    std::vector<char> touched(boost::num_vertices(g), 0);
    for(const Candidate& k : removals)
    {
      if(touched[k.junction])
        continue;
      touched[k.junction] = 1;
      for(std::size_t v : k.chain)
        doomed[v] = 1;
    }
    // Remove the doomed vertices, from the last so that indices stay valid (vecS).
    for(vertex v = 0; v < boost::num_vertices(g); ++v)
      if(boost::degree(v, g) == 0 && g[v].radius > 0 && 2 * voxel_size > CGAL::to_double(g[v].radius))
        doomed[v] = 1; // a lone voxel near the surface
    for(vertex v = boost::num_vertices(g); v-- > 0;)
      if(doomed[v])
      {
        boost::clear_vertex(v, g);
        boost::remove_vertex(v, g);
        changed = true;
      }
  }
}


} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_SPUR_PRUNING_H
