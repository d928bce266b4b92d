// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H
#define CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H

/// \file extract_initial_skeleton.h
/// Stage 4 (paper, section 5): multi-scale parameter-controlled thinning.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/distance_field.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/box_sum.h>
#include <CGAL/DF_L1_skeleton/internal/contractible_cycles.h>
#include <CGAL/DF_L1_skeleton/internal/curve_thinning.h>
#include <CGAL/DF_L1_skeleton/internal/join_pieces.h>
#include <CGAL/DF_L1_skeleton/internal/missing_branches.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_curve_graph.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_morphology.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <numeric>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The initial skeleton: the skeleton voxels and a thin graph through them.
/// \tparam Traits a model of `Kernel`
template <class Traits>
struct Initial_skeleton
{
  /// S: the centres of all skeleton voxels (the attractors of the refinement)
  std::vector<typename Traits::Point_3> points;
  /// the linear grid index of each point of `points`
  std::vector<std::size_t> voxels;
  /// a curve graph through a subset of the skeleton voxels: 26-connected, one voxel
  /// thick, with the spurs shorter than the local radius pruned
  Skeleton_graph<Traits> graph;
  /// TP1, TP2, TP3 of Eq. 2, in voxel units
  std::array<double, 3> thinning_parameters = {{0, 0, 0}};
};

namespace internal {

// The solid that the curve graph is thinned from: the interior voxels, closed by one
// voxel (a dilation then an erosion by the 3x3x3 cube) and with enclosed cavities filled,
// but never taking an exterior or outlier voxel. Noise puts boundary voxels inside thin
// parts, and each such pit or tunnel would survive thinning as a small loop or shell;
// the holes of the shape are exterior voxels, so closing leaves them alone.
template <class Traits>
std::vector<char> shape_volume(const Distance_field<Traits>& df)
{
  std::vector<char> in(df.size()), outside(df.size());
  for(std::size_t v = 0; v < df.size(); ++v)
  {
    in[v] = df.labels[v] == Voxel_label::INTERIOR;
    outside[v] = df.labels[v] == Voxel_label::EXTERIOR || df.labels[v] == Voxel_label::OUTLIER;
  }
  std::vector<char> closed = in;
  cube_filter(closed, df.dims, true);
  cube_filter(closed, df.dims, false);
  for(std::size_t v = 0; v < df.size(); ++v)
    in[v] = in[v] || (closed[v] && !outside[v]);
  fill_cavities(in, outside, df.dims);
  return in;
}

// The distance (voxels) from every voxel to the nearest voxel that is not occupied
// (neither boundary nor interior): 0 outside the occupied voxels, 1 in their outer layer.
template <class Traits>
std::vector<float> occupied_depth(const Distance_field<Traits>& df)
{
  std::vector<float> depth = squared_distance_to_sites<CGAL::Parallel_if_available_tag>(
    df.dims, [&](std::size_t v) { return !Voxel_grid<Traits>::is_occupied(df.labels[v]); });
  for(float& d : depth)
    d = std::sqrt(d);
  return depth;
}

// The parts thinner than two voxels (twigs, the lower legs of a scanned animal): they
// have no skeleton voxel, so without them the curves stop where a limb gets that thin.
struct Thin_parts
{
  std::vector<char> voxels; // occupied voxels that may carry a curve and end it
  std::vector<char> solid;  // the voxels to add to the thinned solid: `voxels` and the
                            // occupied voxels that join them to the thick parts
  std::vector<float> depth; // in `solid`: the distance (voxels) to the nearest voxel
                            // that is not occupied, the depth the thin parts have
};

// The thick parts are the union of the balls of radius DT + `margin` centred on the
// voxels at least two voxels deep (`margin` takes in the boundary shell); it is one
// distance transform of the power of the balls, min over v of |u - v|^2 - R_v^2 <= 0.
// A thin part is a 26-connected component of the occupied voxels outside it that
// touches it and reaches `reach` voxels beyond it: a bump of the surface, a web between
// two limbs near their junction or a clump of outliers on the surface does not reach
// that far. A component that touches no thick part is a thin object of its own (a
// twig, a wire or a plate apart from the rest) when it spans `2 reach` voxels or more
// and is three voxels thick somewhere (a voxel two voxels from the unoccupied ones): a
// layer of points one or two voxels thick (a flat scan) encloses nothing.
template <class Traits>
Thin_parts thin_parts(const Distance_field<Traits>& df, double margin, double reach)
{
  typedef CGAL::Parallel_if_available_tag Tag; // the transforms do not depend on the threads
  const std::size_t n = df.size();
  std::vector<float> power(n, EDT_INFINITY);
  for(std::size_t v = 0; v < n; ++v)
    if(df.values[v] >= 2)
      power[v] = -float((df.values[v] + margin) * (df.values[v] + margin));
  squared_euclidean_distance_transform<Tag>(power, df.dims, 0.f); // only its sign is used
  std::vector<char> thick(n, 0), occupied(n, 0);
  bool outside_balls = false;
  for(std::size_t v = 0; v < n; ++v)
  {
    thick[v] = power[v] <= 0;
    occupied[v] = Voxel_grid<Traits>::is_occupied(df.labels[v]);
    outside_balls = outside_balls || (occupied[v] && !thick[v]);
  }
  Thin_parts result;
  result.voxels.assign(n, 0);
  result.solid.assign(n, 0);
  // The balls often cover every occupied voxel (smooth shapes): no thin part, and no
  // need for the transforms below.
  if(!outside_balls)
    return result;
  const std::vector<float> beyond = squared_distance_to_sites<Tag>(
    df.dims, [&](std::size_t v) { return thick[v]; }, float((std::max)(reach * reach, 3.0))); // compared with both
  result.depth = occupied_depth(df);
  bool any = false;
  for_each_26_component(df, [&](std::size_t v) { return occupied[v] && !thick[v]; },
                        [&](const std::vector<std::size_t>& component) {
    const bool far = std::any_of(component.begin(), component.end(),
                                 [&](std::size_t v) { return beyond[v] >= reach * reach; });
    const bool attached = std::any_of(component.begin(), component.end(), [&](std::size_t v) { return beyond[v] <= 3; });
    bool apart = false;
    if(!attached)
    {
      std::array<int, 3> lo = df.coordinates(component.front()), hi = lo;
      for(std::size_t v : component)
      {
        const std::array<int, 3> c = df.coordinates(v);
        for(int d = 0; d < 3; ++d)
        {
          lo[d] = (std::min)(lo[d], c[d]);
          hi[d] = (std::max)(hi[d], c[d]);
        }
      }
      apart = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) + 1 >= 2 * reach &&
              std::any_of(component.begin(), component.end(), [&](std::size_t v) { return result.depth[v] >= 2; });
    }
    if(far && (attached || apart))
      for(std::size_t v : component)
        result.voxels[v] = any = 1;
  });
  if(!any)
    return result;
  // The occupied voxels within margin + 1 of a thin part join it to the thick solid
  // across the shell that the balls cover.
  const std::vector<float> near = squared_distance_to_sites<Tag>(
    df.dims, [&](std::size_t v) { return result.voxels[v]; }, float((margin + 1) * (margin + 1)));
  for(std::size_t v = 0; v < n; ++v)
    result.solid[v] = occupied[v] && near[v] <= (margin + 1) * (margin + 1);
  return result;
}

// The ridge voxels of Eq. 2 in `values`: at least two voxels deep, and deeper by TP_s
// than the mean over their 26, 124 and 342 neighbours (s = 1, 2, 3), where TP_s is c
// times the mean of that difference over the voxels of positive value. Fills
// `result.voxels`, `result.points`, `result.thinning_parameters` and the flags `in`;
// false when no voxel has a positive value.
template <class Traits>
bool ridge_voxels(const Distance_field<Traits>& field, const std::vector<float>& values, double c,
                  Initial_skeleton<Traits>& result, std::vector<char>& in)
{
  const Box_sum sums(values, field.dims);
  const int radii[3] = {1, 2, 3};
  const double counts[3] = {26, 124, 342};

  // Mean of DT - MNT_k over the interior voxels, for the three thresholds.
  double mean_gap[3] = {0, 0, 0};
  std::size_t interior = 0;
  for(int k = 0; k < field.dims[2]; ++k)
    for(int j = 0; j < field.dims[1]; ++j)
      for(int i = 0; i < field.dims[0]; ++i)
      {
        const float dt = values[field.index(i, j, k)];
        if(dt <= 0)
          continue;
        ++interior;
        for(int s = 0; s < 3; ++s)
          mean_gap[s] += dt - (sums.cube(i, j, k, radii[s]) - dt) / counts[s];
      }
  if(interior == 0)
    return false;
  for(int s = 0; s < 3; ++s)
    result.thinning_parameters[s] = c * std::abs(mean_gap[s] / double(interior));

  in.assign(field.size(), 0);
  for(int k = 0; k < field.dims[2]; ++k)
    for(int j = 0; j < field.dims[1]; ++j)
      for(int i = 0; i < field.dims[0]; ++i)
      {
        const std::size_t v = field.index(i, j, k);
        const float dt = values[v];
        // One voxel deep is what a flat, linear or noisy sheet of points encloses
        // between its samples: no volume, no skeleton.
        if(dt < 2)
          continue;
        bool ridge = true;
        for(int s = 0; s < 3 && ridge; ++s)
          ridge = (sums.cube(i, j, k, radii[s]) - dt) / counts[s] < dt - result.thinning_parameters[s];
        if(ridge)
        {
          in[v] = 1;
          result.voxels.push_back(v);
          result.points.push_back(field.center(v));
        }
      }
  return true;
}

// Maxima of the distance field over blocks of 4x4x4 voxels, so that the maximum over a
// large window costs a few block reads; a small window may be read voxel by voxel.
class Block_maximum
{
public:
  static constexpr int block = 4;

  // `values`: one value per voxel of the grid of `df`
  template <class Traits>
  Block_maximum(const Distance_field<Traits>& df, const std::vector<float>& values)
    : values_(&values), grid_{{df.dims[0], df.dims[1], df.dims[2]}}
  {
    for(int a = 0; a < 3; ++a)
      dims_[a] = (df.dims[a] + block - 1) / block;
    maxima_.assign(std::size_t(dims_[0]) * dims_[1] * dims_[2], 0.f);
    for(int k = 0; k < df.dims[2]; ++k)
      for(int j = 0; j < df.dims[1]; ++j)
        for(int i = 0; i < df.dims[0]; ++i)
        {
          float& m = maxima_[index(i / block, j / block, k / block)];
          m = (std::max)(m, values[df.index(i, j, k)]);
        }
  }

  // The maximum over the blocks that meet the voxel box [lo, hi] (inclusive), or with
  // `exact` over the box itself: the blocks widen a box by up to 3 voxels a side.
  float over(const std::array<int, 3>& lo, const std::array<int, 3>& hi, bool exact = false) const
  {
    if(exact)
    {
      float m = 0;
      for(int k = (std::max)(0, lo[2]); k <= (std::min)(grid_[2] - 1, hi[2]); ++k)
        for(int j = (std::max)(0, lo[1]); j <= (std::min)(grid_[1] - 1, hi[1]); ++j)
          for(int i = (std::max)(0, lo[0]); i <= (std::min)(grid_[0] - 1, hi[0]); ++i)
            m = (std::max)(m, (*values_)[(std::size_t(k) * grid_[1] + j) * grid_[0] + i]);
      return m;
    }
    std::array<int, 3> a, b;
    for(int d = 0; d < 3; ++d)
    {
      a[d] = (std::max)(0, lo[d]) / block;
      b[d] = (std::min)(dims_[d] * block - 1, hi[d]) / block;
    }
    float m = 0;
    for(int k = a[2]; k <= b[2]; ++k)
      for(int j = a[1]; j <= b[1]; ++j)
        for(int i = a[0]; i <= b[0]; ++i)
          m = (std::max)(m, maxima_[index(i, j, k)]);
    return m;
  }

private:
  std::size_t index(int i, int j, int k) const { return (std::size_t(k) * dims_[1] + j) * dims_[0] + i; }
  const std::vector<float>* values_;
  std::array<int, 3> grid_;
  std::array<int, 3> dims_;
  std::vector<float> maxima_;
};

// Whether a voxel may end a curve: its radius is at least `ratio` times the largest
// radius within about twice its depth (the blocks that meet that cube), the radius being
// the depth plus `to_radius`. The end of a real branch sits near the centre of the ball
// that caps it, where the depth peaks; the noise of the surface raises ridge voxels a few
// voxels deep on the slope of a much deeper field, and a curve ending there would be a
// spur. With `exact` (parts one or two voxels deep) the cube itself is read, at least 3
// voxels a side as the widest neighbourhood of the ridge test: the blocks would stretch a
// window of 2 to 4 voxels to 5 to 7, and the tip of a twig five voxels out of a thicker
// branch would be measured against the branch. Depths measured in the occupied voxels
// less one are half a voxel short of the radius (`to_radius` 0.5): as a ratio of such
// depths, a twig tip 1.4 voxels deep beside a voxel 2 deep read 0.4 / 1 and never ended.
template <class Traits>
bool is_deep_end(const Distance_field<Traits>& df, const std::vector<float>& depth, const Block_maximum& maxima,
                 std::size_t v, double ratio, bool exact = false, double to_radius = 0)
{
  const std::array<int, 3> c = df.coordinates(v);
  const int r = exact ? (std::max)(3, int(std::ceil(2 * depth[v]))) : int(std::ceil(2 * depth[v]));
  const float deepest = maxima.over({{c[0] - r, c[1] - r, c[2] - r}}, {{c[0] + r, c[1] + r, c[2] + r}}, exact);
  return depth[v] + to_radius >= ratio * (deepest + to_radius);
}

// The balls of a skeleton graph (vertex, local radius), to ask whether those of a chain
// of vertices reach beyond the union of the others.
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
template <class Traits>
void prune_spurs(Skeleton_graph<Traits>& g, double ratio, double voxel_size, double noise = 0)
{
  typedef typename boost::graph_traits<Skeleton_graph<Traits>>::vertex_descriptor vertex;
  // Thin ends get less slack (a twig tip is a voxel or two wide) but more per radius.
  const double deep_slack = 2.5 * voxel_size + 2 * noise, deep_per_radius = 0.5;
  const double thin_slack = 2.0 * voxel_size + 2 * noise, thin_per_radius = 1.0;
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
        return k.thin ? cover.sticks_out(k.chain, excluded, thin_slack, thin_per_radius)
                      : cover.sticks_out(k.chain, excluded, deep_slack, deep_per_radius);
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

/// \ingroup PkgDFL1SkeletonRef
/// Extracts the initial skeleton from a distance field by multi-scale
/// parameter-controlled thinning (paper, section 5, Eq. 1-2).
///
/// For every interior voxel p and for the 3x3x3, 5x5x5 and 7x7x7 cubes around it,
/// MNT_k(p) is the mean distance of the 26, 124 and 342 neighbours (computed with a
/// summed-volume table, so each scale costs 8 reads per voxel). A voxel is a skeleton
/// voxel when, at all three scales, MNT_k(p) < DT(p) - TP_k: it stands above the mean of
/// its neighbourhood by more than TP_k. The paper writes TP_k = c (mean MNT_k - mean DT)
/// over the voxels of the model; since the distance field is concave on average that
/// difference is negative, and a negative threshold would accept the flat slopes of the
/// field. We read it as the magnitude, TP_k = c |mean over interior voxels of
/// (DT - MNT_k)|, the threshold of Gagvani and Silver that the paper builds on, with
/// c = 0.86.
///
/// The skeleton voxels S form a band a few voxels thick, broken where noise flattens
/// the ridge. `Initial_skeleton::graph` is a curve through it with the topology of the
/// shape (our addition; the paper uses S alone):
/// - the solid is the interior voxels, closed by one voxel and with cavities filled, so
///   that pits and tunnels that noise leaves in thin parts do not become loops;
/// - it is thinned to curves without changing its topology (simple voxels only), in
///   the order of increasing distance, so the curves follow the ridge of the field; a
///   torus keeps its loop, a solid becomes a tree. A curve end is kept only at a voxel
///   of S whose distance is at least half the largest distance within about twice its
///   own: the end of a branch sits near the centre of the ball that caps it, while noise
///   raises ridge voxels on the slope of a deeper field, where the distance grows by a
///   voxel per voxel (a ratio of 1/3). A cone tapering by up to 1 in 2 passes;
/// - the 26-adjacency graph of the curve voxels, without redundant diagonals and
///   without the small cycles that voxel clusters make at junctions (the graph keeps as
///   many cycles as the curve voxels have loops, computed from their Euler
///   characteristic);
/// - parts thinner than two voxels (twigs, the lower legs of a scanned animal) have no
///   voxel of S, and the curves would stop where a limb gets that thin. With
///   `thin_parts`, the occupied voxels beyond the balls of radius DT + 2 voxels around
///   the voxels two or more voxels deep join the solid, when they form a component that
///   touches those balls and reaches 4 voxels beyond them (bumps, webs between limbs and
///   clumps of outliers on the surface do not), or when it touches no ball, spans 8
///   voxels or more and is 3 voxels thick somewhere: a thin object apart from the rest (a
///   twig, a wire, a plate), which the curves would otherwise miss whole (a flat layer of
///   points stays without skeleton); there the thinning follows the distance
///   to the nearest unoccupied voxel, and a curve may end at a voxel 0.6 times as deep as
///   the deepest within twice its depth and at least 3 voxels, read voxel by voxel (3/4
///   cut the tips of twigs one voxel wider than their neighbourhood's deepest, 1.41
///   against 2.24 voxels). The
///   tree scan of our tests went from 8 pieces to one skeleton through its twigs, the
///   camel's legs now reach the ground; the 72 synthetic cases do not change (their
///   thinnest tubes are 3 voxels in radius or more);
/// - terminal branches are pruned, repeatedly, when they are shorter than
///   `spur_length_ratio` times the local radius at their junction (plus one voxel), or
///   when it ends at a voxel two or more voxels deep and the ball (vertex, local radius)
///   of every vertex v of the branch lies within the union of the balls of the other
///   vertices, to 2.5 voxels + r(v) / 2 (probed at its centre and 26 points of its
///   sphere): the branch adds nothing to the shape that the balls describe. That is the
///   hair that ridge voxels grow on bumps of a noisy surface and in the crotches of
///   junctions, while a limb sticks out of the body it leaves however short or tapered it
///   is. A branch ending less than two voxels deep (in a thin part) is covered when each
///   ball lies within 2 voxels + r(v) of the others: at a scanned hoof or a twig tip the
///   balls are a voxel or two wide, and more slack would swallow the tip. Both slacks grow
///   by twice `surface_noise`, the height of the bumps that noise raises. In a thin part,
///   the local radius is the distance to the nearest unoccupied voxel less half a voxel.
///   Of two branches removed at one junction only the shorter goes in a round: the other
///   may then continue the branch behind it (a hair beside a twig near its tip leaves the
///   tip on a short branch that the hair covers);
/// - a cycle of the graph that bounds a disk inside the solid of occupied and interior
///   voxels closed by one voxel (the cone from its centroid over its edges, sampled every
///   0.4 voxel, meets no exterior or outlier voxel farther than sqrt(3) voxels from the
///   solid) encloses no hole of the shape that the grid resolves: a tunnel of the noisy
///   surface, or a gap of one or two voxels between parts that almost touch. Such a
///   cycle loses its thinner arc between two junctions, and the spurs are pruned again.
///   A handle's hole is wider than that, so its loop stays;
/// - pieces of the graph that lie in one 26-connected component of the occupied voxels
///   are joined, nearest first, by the path through those voxels that stays deepest: a
///   smoothed plate a few voxels thick, or a stretch of a noisy limb, may keep no voxel
///   deep enough for a curve, but the skeleton of a connected solid is connected;
/// - with `thin_parts`, the thin limbs that the thinning lost get their branch back.
///   Thinning in the order of depth eats a limb from its tip where the depth is flat (a
///   twig two or three voxels wide is one plateau of quantized depth), and then no voxel
///   of it is ever a curve end. A voxel of a thin part whose geodesic distance through the
///   occupied voxels to every vertex exceeds 1.5 times the radius of that vertex by 4
///   voxels plus twice `surface_noise` lies beyond what the balls of the skeleton
///   explain: the farthest such voxel gets a branch, the path through the occupied voxels
///   that keeps deepest from it to the graph less its surface layer, and so on until no
///   such voxel is left. Thick parts are left alone: a hump, an ear or the flank of a
///   partial scan also reaches beyond the balls of its curve, and is no limb;
/// - with `occupied_depth` (our addition, for smoothed noisy clouds), the depth that the
///   ridge test, the thinning, the end test and the radii read is not the distance field
///   but the distance to the nearest unoccupied voxel less one, and the solid also takes
///   the occupied voxels more than one voxel deep; any of them may end a curve when its
///   radius (that depth plus half a voxel) is 0.6 times the largest within twice its depth,
///   read voxel by voxel below two voxels as in the thin parts. A smoothed twig 1.75 voxels
///   in radius is 1.4 voxels deep in the occupied voxels: as a ratio of depths less one
///   (0.4 against 1 a voxel from it) its tip never ended, and the noisy trees of the
///   corpus (0.3 % noise) kept 0.22 to 0.59 of their tips instead of 0.55 to 0.83. Noise
///   leaves a boundary shell several
///   voxels thick even after smoothing, so a thin limb has little or no interior two
///   voxels deep while its occupied voxels still span it; where the shell is one voxel
///   thick the two depths about agree. Measured on the 12 synthetic shapes with 1 %
///   noise (20,000 points, seed 7): the designed topology in 12 cases instead of 11 (the
///   stick figure kept its arms), mean distance to the axis 0.069 of the local radius
///   instead of 0.094, axis coverage 0.989 instead of 0.957; the other variants are not
///   smoothed and do not change.
///
/// \tparam Traits a model of `Kernel`
/// \param field the distance field returned by `compute_distance_field()`
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{thinning_coefficient}
///     \cgalParamDescription{c of Eq. 2, in (0, 10]}
///     \cgalParamDefault{0.86}
///   \cgalParamNEnd
///   \cgalParamNBegin{spur_length_ratio}
///     \cgalParamDescription{terminal branches shorter than this times the local radius are pruned; >= 0}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{thin_parts}
///     \cgalParamDescription{whether the curves run into the parts thinner than two voxels (a Boolean);
///       `DF_L1_skeletonization` turns it off for clouds it smoothed, whose ragged boundary shell cannot
///       be told from a thin part; moot with `occupied_depth`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{occupied_depth}
///     \cgalParamDescription{whether depth is measured in the occupied voxels instead of read from the
///       distance field (a Boolean); `DF_L1_skeletonization` turns it on for the clouds it smoothed}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{surface_noise}
///     \cgalParamDescription{the noise of the sampled surface, in input units (`estimate_surface_noise()`);
///       the cover test of the spur pruning grows its slack by twice it; `DF_L1_skeletonization` passes its
///       estimate}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// Skeleton voxels lie at least two voxels deep: the interior voxels one voxel deep are
/// what a flat, linear or noisy sheet of points encloses between its samples.
///
/// \returns the skeleton voxels and the graph; both are empty when the field has no
///          interior voxel two voxels deep and no thin object (a flat or linear point set, or one too
///          sparse to enclose a volume); the graph alone may hold curves when only thin objects have
///          them
template <class Traits, class NamedParameters = parameters::Default_named_parameters>
Initial_skeleton<Traits> extract_initial_skeleton(const Distance_field<Traits>& field,
                                                  const NamedParameters& np = parameters::default_values())
{
  const double c = internal::thinning_coefficient(np, "initial skeleton");
  const double spur_ratio = internal::spur_length_ratio(np, "initial skeleton");
  const double noise = internal::surface_noise(np, "initial skeleton");
  const bool in_occupied = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_occupied_depth), false);
  // The occupied solid already holds the thin parts.
  const bool with_thin_parts =
    !in_occupied && parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_thin_parts), true);

  const double ridge_end_ratio = 0.5, thin_end_ratio = 0.6;
  Initial_skeleton<Traits> result;
  // The depth that the ridge test and the thinning read: the distance field, or the
  // depth in the occupied voxels less their outer layer (about the field where the
  // boundary shell is one voxel thick).
  std::vector<float> occupied_values;
  if(in_occupied)
  {
    occupied_values = internal::occupied_depth(field);
    for(float& d : occupied_values)
      d = (std::max)(0.f, d - 1);
  }
  const std::vector<float>& values = in_occupied ? occupied_values : field.values;
  // Three independent reads of the field: the ridge voxels, the solid to thin and the
  // thin parts; the thin parts (most of the time of this stage) run beside the other two.
  std::vector<char> in, curves;
  internal::Thin_parts thin;
  bool has_interior = false;
  internal::run_both<CGAL::Parallel_if_available_tag>(
    [&] {
      has_interior = internal::ridge_voxels(field, values, c, result, in);
      if(has_interior)
        curves = internal::shape_volume(field);
    },
    [&] {
      if(with_thin_parts)
        thin = internal::thin_parts(field, 2.0, 4.0);
    });
  const bool has_thin = with_thin_parts && std::find(thin.voxels.begin(), thin.voxels.end(), 1) != thin.voxels.end();
  if(!has_interior && !has_thin)
    return result;
  if(!has_interior) // thin objects alone: no ridge voxel, no thick solid
  {
    in.assign(field.size(), 0);
    curves.assign(field.size(), 0);
  }
  if(in_occupied)
    for(std::size_t v = 0; v < field.size(); ++v)
      curves[v] = curves[v] || values[v] > 0;
  // The thinning order uses the depth above (the distance field, or the depth in the
  // occupied voxels with `occupied_depth`), and in and around the thin parts (where it
  // is 0 or 1) the distance to the nearest unoccupied voxel minus one (about the field
  // plus the boundary layer elsewhere): their curves then follow their middle.
  std::vector<float> depth = values;
  if(with_thin_parts)
  {
    for(std::size_t v = 0; v < field.size(); ++v)
      if(thin.solid[v])
      {
        curves[v] = 1;
        depth[v] = (std::max)(depth[v], thin.depth[v] - 1);
      }
  }
  // A ridge voxel may end a curve when it is half as deep as the deepest voxel within
  // twice its depth; a voxel of a thin part, or with `occupied_depth` any voxel below the
  // outer layer, when its radius is 0.6 times the largest there: the thin limbs of a
  // smoothed cloud have few ridge voxels, and their curves would stop short of the tips.
  // Those depths are the occupied ones less one, half a voxel short of the radius; the
  // occupied voxels less than two deep are read voxel by voxel, as the thin parts. The
  // hair this lets through on ragged sides is pruned by the cover test of `prune_spurs`.
  std::vector<signed char> deep_end(field.size(), -1); // memo of is_deep_end
  const internal::Block_maximum maxima(field, depth);
  internal::thin_to_curves(field, depth, curves, [&](std::size_t v) {
    const bool in_thin_part = with_thin_parts && thin.voxels[v];
    const bool thin_end = in_thin_part || (in_occupied && values[v] > 0);
    if(!in[v] && !thin_end)
      return false;
    if(deep_end[v] < 0)
      deep_end[v] = internal::is_deep_end(field, depth, maxima, v, in[v] ? ridge_end_ratio : thin_end_ratio,
                                          in_thin_part || (in_occupied && values[v] < 2), in_occupied ? 0.5 : 0.0);
    return bool(deep_end[v]);
  });
  std::vector<std::size_t> curve_voxels;
  for(std::size_t v = 0; v < curves.size(); ++v)
    if(curves[v])
      curve_voxels.push_back(v);
  result.graph = internal::voxel_curve_graph<Traits>(field, curve_voxels);
  const double voxel = CGAL::to_double(field.voxel_size);
  for(std::size_t d = 0; d < curve_voxels.size(); ++d)
  {
    const std::size_t v = curve_voxels[d];
    // In a thin part the field is 0 or 1; its radius is the distance to the nearest
    // unoccupied voxel, less the half voxel to the surface inside the boundary voxel.
    const double thin_radius = with_thin_parts && thin.solid[v] ? (thin.depth[v] - 0.5) * voxel : 0.0;
    const double occupied_radius = in_occupied ? values[v] * voxel : 0.0;
    result.graph[d].radius = (std::max)({CGAL::to_double(field.distance(v)), thin_radius, occupied_radius});
  }
  internal::prune_spurs(result.graph, spur_ratio, voxel, noise);
  if(skeleton_statistics(result.graph).cycles > 0 && internal::cut_contractible_cycles(result.graph, field, field.labels) > 0)
    internal::prune_spurs(result.graph, spur_ratio, voxel, noise);
  // Pieces within one component of the occupied voxels are joined; the depth of the
  // thin parts is the same transform when it was computed.
  if(skeleton_statistics(result.graph).components > 1)
    internal::join_pieces_within_shape(result.graph, field,
                                       thin.depth.empty() ? internal::occupied_depth(field) : thin.depth);
  // The thin limbs that the thinning ate from their flat tips get their branches back.
  if(has_thin)
    internal::add_missing_branches(result.graph, field, thin.depth, thin.voxels, 4.0 + 2 * noise / voxel, 1.5);
  return result;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H
