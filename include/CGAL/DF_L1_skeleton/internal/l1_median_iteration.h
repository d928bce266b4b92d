// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_L1_MEDIAN_ITERATION_H
#define CGAL_DF_L1_SKELETON_INTERNAL_L1_MEDIAN_ITERATION_H

#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/internal/grid_walk.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/sample_selection.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The voxels as the contraction sees them: the distance value and whether a point is in
// the shape, looked up in double precision.
template <class Traits>
class Field_lookup
{
public:
  explicit Field_lookup(const Distance_field<Traits>& field)
    : field_(field), values_(field.values), labels_(field.labels), dims_(field.dims),
      origin_{{CGAL::to_double(field.origin.x()), CGAL::to_double(field.origin.y()), CGAL::to_double(field.origin.z())}},
      voxel_(CGAL::to_double(field.voxel_size))
  {}

  double voxel_size() const { return voxel_; }

  // linear index of the voxel that holds p, or npos outside the grid
  std::size_t voxel(const Vec3& p) const
  {
    std::array<int, 3> c;
    for(int a = 0; a < 3; ++a)
    {
      const double x = std::floor((p[a] - origin_[a]) / voxel_);
      if(!(x >= 0 && x < dims_[a]))
        return npos;
      c[a] = int(x);
    }
    return (std::size_t(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
  }
  // distance value at p in input units (0 outside the grid)
  double distance(const Vec3& p) const
  {
    const std::size_t v = voxel(p);
    return v == npos ? 0 : values_[v] * voxel_;
  }
  // whether p lies in a boundary or interior voxel
  bool is_inside(const Vec3& p) const
  {
    const std::size_t v = voxel(p);
    return v != npos && Voxel_grid<Traits>::is_occupied(labels_[v]);
  }
  // The distance-field constraint of section 6.1: a step from p to q is allowed unless q
  // is outside the shape or in a voxel of smaller distance value than p's.
  bool allows_step(const Vec3& p, const Vec3& q) const
  {
    const std::size_t vq = voxel(q);
    if(vq == npos || !Voxel_grid<Traits>::is_occupied(labels_[vq]))
      return false;
    const std::size_t vp = voxel(p);
    return vp == npos || values_[vq] >= values_[vp];
  }

  // whether the segment ab crosses only boundary and interior voxels (section 6.1's test
  // of a bridge), walking the grid voxel by voxel
  bool segment_inside(const Vec3& a, const Vec3& b) const
  {
    typedef typename Traits::Point_3 Point_3;
    return segment_stays_inside(field_, labels_, Point_3(a[0], a[1], a[2]), Point_3(b[0], b[1], b[2]));
  }

  static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

private:
  const Distance_field<Traits>& field_;
  const std::vector<float>& values_;
  const std::vector<Voxel_label>& labels_;
  std::array<int, 3> dims_;
  Vec3 origin_;
  double voxel_;
};

// Weighted sums over the points of a ball, for the three terms of Eq. 8.
struct Ball_sums
{
  double weight = 0;      // sum of the weights
  Vec3 moment{{0, 0, 0}}; // sum of weight * point
  double count = 0;       // points in the ball (with their multiplicity)
  Vec3 mean() const { return (1 / weight) * moment; }
};

// Sums theta(r) / r^power (power 0, 1 or 2) over the points of `grid` within h of x, r clamped below at
// 1e-3 h as in the L1-medial code (a sample sitting on a point must not divide by zero).
// A point stands for `multiplicity[j]` points when `multiplicity` is given.
inline Ball_sums ball_sums(const Uniform_grid& grid, const std::vector<Vec3>& points, const Vec3& x, double h,
                           int power, std::size_t skip = std::size_t(-1),
                           const std::vector<double>* multiplicity = nullptr)
{
  Ball_sums s;
  const double inv = 4 / (h * h), floor2 = 1e-6 * h * h;
  grid.for_each_in_ball(x, h, [&](std::size_t j, double d2) {
    if(j == skip)
      return true;
    const double r2 = (std::max)(d2, floor2);
    const double theta = std::exp(-d2 * inv);
    const double n = multiplicity != nullptr ? (*multiplicity)[j] : 1.0;
    const double w = n * (power == 0 ? theta : (power == 1 ? theta / std::sqrt(r2) : theta / r2));
    s.weight += w;
    s.moment = s.moment + w * points[j];
    s.count += n;
    return true;
  });
  return s;
}

// The points gathered by cubic cells of side `cell`: the centroid of each non-empty cell
// and its number of points, in the order of the cells (deterministic). The data term of
// Eq. 8 sums over hundreds of points per ball; with cells a third to a sixth of the
// support radius, a centroid stands for several of them and the errors of the weights
// theta / r across a cell largely cancel around the centroid (measured on our test
// cases: the same topology and centring).
struct Aggregated_points
{
  std::vector<Vec3> centroid;
  std::vector<double> multiplicity;
  std::vector<std::array<long long, 3>> cell; // integer coordinates of each centroid's cell
};

// Groups weighted points by integer cell: the weighted centroid and total weight of each
// non-empty cell, in increasing cell order. The cells are sorted by one packed 64-bit
// key when it fits (the comparison of three coordinates made this sort the largest cost
// of the contraction at 300,000 points).
inline Aggregated_points group_by_cell(const std::vector<std::array<long long, 3>>& cells,
                                       const std::vector<Vec3>& positions, const std::vector<double>* weights)
{
  Aggregated_points result;
  const std::size_t n = cells.size();
  if(n == 0)
    return result;
  std::array<long long, 3> size{{1, 1, 1}};
  for(const auto& c : cells)
    for(int a = 0; a < 3; ++a)
      size[a] = (std::max)(size[a], c[a] + 1);
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i)
    order[i] = i;
  if(double(size[0]) * double(size[1]) * double(size[2]) < 9e18)
  {
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed(n);
    for(std::size_t i = 0; i < n; ++i)
      keyed[i] = {(std::uint64_t(cells[i][0]) * std::uint64_t(size[1]) + std::uint64_t(cells[i][1])) *
                      std::uint64_t(size[2]) + std::uint64_t(cells[i][2]),
                  i};
    std::sort(keyed.begin(), keyed.end());
    for(std::size_t i = 0; i < n; ++i)
      order[i] = keyed[i].second;
  }
  else
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return cells[a] < cells[b] || (cells[a] == cells[b] && a < b);
    });
  for(std::size_t b = 0; b < n;)
  {
    std::size_t e = b;
    Vec3 sum{{0, 0, 0}};
    double weight = 0;
    for(; e < n && cells[order[e]] == cells[order[b]]; ++e)
    {
      const double w = weights ? (*weights)[order[e]] : 1.0;
      sum = sum + w * positions[order[e]];
      weight += w;
    }
    result.centroid.push_back((1.0 / weight) * sum);
    result.multiplicity.push_back(weight);
    result.cell.push_back(cells[order[b]]);
    b = e;
  }
  return result;
}

// The input points gathered at cell sizes doubling from `finest`, each with a grid for
// ball queries, so that a sample of support radius h sums over cells of h/6 to h/3.
// The cells nest (one origin, sizes doubling), so each level groups the centroids of
// the level below instead of all the points again. The levels are built once per
// contraction and extended when the support radii grow (rebuilding them for every
// stage cost as much as a sixth of the contraction and did not run in parallel).
class Gathered_input
{
public:
  Gathered_input(const std::vector<Vec3>& points, double finest)
  {
    if(points.empty())
      return;
    Vec3 lo = points.front();
    for(const Vec3& p : points)
      for(int a = 0; a < 3; ++a)
        lo[a] = (std::min)(lo[a], p[a]);
    std::vector<std::array<long long, 3>> cells(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      for(int a = 0; a < 3; ++a)
        cells[i][a] = (long long)(std::floor((points[i][a] - lo[a]) / finest));
    add_level(group_by_cell(cells, points, nullptr), finest);
  }

  // Adds coarser levels until a ball of radius `radius` finds its cells (not thread safe:
  // call it between the parallel loops).
  void cover_radius(double radius)
  {
    while(!levels_.empty() && cells_per_radius * cells_.back() < radius && levels_.back().centroid.size() > 1)
    {
      const Aggregated_points& below = levels_.back();
      std::vector<std::array<long long, 3>> parent(below.cell.size());
      for(std::size_t i = 0; i < parent.size(); ++i)
        for(int a = 0; a < 3; ++a)
          parent[i][a] = below.cell[i][a] / 2; // non-negative: floor
      add_level(group_by_cell(parent, below.centroid, &below.multiplicity), 2 * cells_.back());
    }
  }

  Ball_sums sums(const Vec3& x, double h) const
  {
    if(levels_.empty())
      return Ball_sums();
    std::size_t k = 0;
    while(k + 1 < levels_.size() && cells_per_radius * cells_[k + 1] <= h)
      ++k;
    return ball_sums(grids_[k], levels_[k].centroid, x, h, 1, std::size_t(-1), &levels_[k].multiplicity);
  }

private:
  // A ball of radius h reads the level whose cells are h/6 to h/3. With h/8 to h/4, the
  // noisy 35k stick figure's first stage read 690 centroids per ball (the level's cells
  // fell just under h/4), most of its contraction. Over 5 x 72 test cases (5 seeds and
  // sizes) the coarser cells gave the designed topology in 354 cases instead of 355
  // (a noisy many-armed star that already missed an arm) with the same mean axis
  // ratios; h/5 to h/2.5 lost a seed-7 case and a loop of the woman scan.
  static constexpr double cells_per_radius = 3;

  void add_level(Aggregated_points&& level, double cell)
  {
    levels_.push_back(std::move(level));
    cells_.push_back(cell);
    grids_.emplace_back(levels_.back().centroid, 4 * cell);
  }

  std::vector<Aggregated_points> levels_;
  std::vector<double> cells_;
  std::vector<Uniform_grid> grids_; // each with its own copy of its level's centroids
};

// One fixed-point iteration of Eq. 8 for every free sample, all from the previous
// iterate (Jacobi), so the result does not depend on the order or the threads.
//
// With A the weighted L1 median of the input points (weights alpha_ij = theta / r), B
// that of the initial-skeleton points (alpha_ik), R the repulsion mean of the other
// samples (beta_ii' = theta / r^2), v = w_i sum_k alpha_ik / sum_j alpha_ij and the
// repulsion u, Eq. 7 reads (1 + v - u) x + u R = A + v B. The paper iterates
// x <- (u - v) x + A + v B - u R, which diverges once v > 1 + u, and v grows large as a
// sample nears the initial skeleton. We iterate the same equation in the convergent
// form x <- (A + v B + u (x - R)) / (1 + v): same fixed point, contraction factor
// u / (1 + v) < 1/2. Without the skeleton term (v = 0) it is the L1-medial update.
//
// The weight of the skeleton term, theta_i(n/N) in the paper, is read as w_i = N_i / n_i
// (N_i input points and n_i skeleton points in the ball): the skeleton points then weigh
// as much in total as the input points, whatever the sampling density, and v is the
// ratio of their mean attractions, small while the sample is far from S and large once
// it is close. Taken literally (n e^{-(n/N)^2}, about n) the pull would fade as the scan
// gets denser.
struct L1_median_step
{
  const Gathered_input& input;          // Q
  const std::vector<Vec3>& attractors;  // S (empty for the plain L1-medial method)
  const Uniform_grid* attractor_grid;   // null without S
  double repulsion;                     // u

  Vec3 operator()(const std::vector<Vec3>& samples, const Uniform_grid& sample_grid, std::size_t i, double h) const
  {
    const Vec3& x = samples[i];
    const Ball_sums q = input.sums(x, h);
    Ball_sums s;
    if(attractor_grid != nullptr)
      s = ball_sums(*attractor_grid, attractors, x, h, 1);
    const Ball_sums r = ball_sums(sample_grid, samples, x, h, 2, i);
    double data_weight = 1, v = 0;
    Vec3 target{{0, 0, 0}};
    if(q.count > 0)
      target = q.mean();
    else
      data_weight = 0;
    if(s.count > 0)
    {
      v = q.count > 0 ? (q.count / s.count) * s.weight / q.weight : 1;
      target = target + v * s.mean();
    }
    if(data_weight + v == 0)
      return x; // nothing in reach: stay
    if(r.count > 0)
      target = target + repulsion * (x - r.mean());
    return (1 / (data_weight + v)) * target;
  }
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_L1_MEDIAN_ITERATION_H
