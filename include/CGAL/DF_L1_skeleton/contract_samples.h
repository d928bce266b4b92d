// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_CONTRACT_SAMPLES_H
#define CGAL_DF_L1_SKELETON_CONTRACT_SAMPLES_H

/// \file contract_samples.h
/// Stage 5 (paper, section 6): the distance-field guided L1-median contraction.

#include <CGAL/DF_L1_skeleton/Contracted_samples.h>
#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/Initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/internal/branch_tracing.h>
#include <CGAL/DF_L1_skeleton/internal/l1_median_iteration.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/sample_directionality.h>
#include <CGAL/DF_L1_skeleton/internal/sample_selection.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace DF_L1 {

namespace internal {

inline double median_of(std::vector<double> v)
{
  if(v.empty())
    return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The junctions of the initial skeleton graph: clusters of adjacent vertices of degree 3
// or more, each a ball around the cluster's mean of radius the local radius plus a voxel.
template <class Graph, class Lookup>
std::vector<Junction_zone> junction_zones(const Graph& g, const Lookup& lookup)
{
  const std::size_t n = boost::num_vertices(g);
  std::vector<std::size_t> cluster(n, std::size_t(-1));
  std::vector<Junction_zone> zones;
  for(std::size_t v = 0; v < n; ++v)
  {
    if(boost::degree(v, g) < 3 || cluster[v] != std::size_t(-1))
      continue;
    std::vector<std::size_t> members{v}, stack{v};
    cluster[v] = zones.size();
    while(!stack.empty())
    {
      const std::size_t a = stack.back();
      stack.pop_back();
      for(auto e : CGAL::make_range(boost::out_edges(a, g)))
      {
        const std::size_t b = boost::target(e, g);
        if(boost::degree(b, g) >= 3 && cluster[b] == std::size_t(-1))
        {
          cluster[b] = zones.size();
          members.push_back(b);
          stack.push_back(b);
        }
      }
    }
    Vec3 centre{{0, 0, 0}};
    for(std::size_t a : members)
      centre = centre + (1.0 / double(members.size())) * to_vec3(g[a].point);
    zones.push_back({centre, lookup.distance(centre) + lookup.voxel_size()});
  }
  // Overlapping zones are one junction whose thinning left several junction vertices.
  for(bool merged = true; merged;)
  {
    merged = false;
    for(std::size_t a = 0; a < zones.size() && !merged; ++a)
      for(std::size_t b = a + 1; b < zones.size() && !merged; ++b)
        if(distance(zones[a].centre, zones[b].centre) < zones[a].radius + zones[b].radius)
        {
          const Vec3 centre = 0.5 * (zones[a].centre + zones[b].centre);
          const double radius = (std::max)(zones[a].radius, zones[b].radius) + 0.5 * distance(zones[a].centre, zones[b].centre);
          zones[a] = {centre, radius};
          zones.erase(zones.begin() + b);
          merged = true;
        }
  }
  return zones;
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Contracts samples of the points onto the curve skeleton (paper, section 6): the
/// L1-median fixed-point iteration of Eq. 8, stage after stage of growing support radius,
/// with branch tracing and bridge points between stages.
///
/// - **Samples.** About `number_of_samples` points are picked by a voxel-grid pick (the
///   point nearest the centre of each occupied cell, the cell size chosen so that about M
///   cells are occupied): deterministic and even, where the L1-medial method draws them
///   at random.
/// - **Iteration.** Every free sample moves by Eq. 8, all from the previous iterate, in
///   the convergent form x <- (A + v B + u (x - R)) / (1 + v), which has the fixed point of
///   Eq. 7 (see `internal/l1_median_iteration.h` for the derivation and for our reading of
///   the weight theta_i(n/N) of the skeleton term as N/n). The paper's literal form
///   x <- (u - v) x + ... diverges when v > 1 + u. With the distance-field guidance a
///   sample whose step would end in an exterior or outlier voxel, or in a voxel of smaller
///   distance value, stays where it is for that iteration. A stage ends after
///   `number_of_iterations` iterations or when the mean step is under 0.05 voxel (about
///   the L1-medial code's 0.0005 of the longest bounding-box side at V = 100), 0.2 voxel
///   with the guidance: its graph is the initial skeleton re-centred on the samples, and
///   over 5 x 72 test cases (5 seeds and sizes) the looser stop gave the same topology in
///   355 cases instead of 356 and mean axis ratios within 0.002, with 15 to 40 % fewer
///   iterations (noisy 35k stick figure: 35 to 21). The data term
///   of a sample sums over the points gathered in cells of h/6 to h/3 (centroid and
///   count of each cell): the same topology and centring on our test cases as the
///   single points, many times faster (cells of h/8 to h/4, used before, cost 10 to 15 %
///   more of the whole run for no measured gain; h/5 to h/2.5 lost a case).
/// - **Support radius.** Every sample starts with h0 = 2 d_bb / cbrt(N). After a stage,
///   with the guidance (Eq. 9): the theta-weighted centre c of the initial-skeleton points
///   in the sample's ball (normalised by the sum of the weights; the paper's division by
///   n would shrink it towards the origin); if c is within a voxel of the sample, h becomes
///   the distance value at c (at least two voxels), otherwise h grows by the factor
///   1 + `support_radius_growth`. Without guidance all samples share h, which grows by
///   that factor each stage (the L1-medial schedule). A free sample whose h exceeds d_bb
///   is settled: its ball holds the whole object, so it stays where it is (the
///   L1-medial stopping rule, applied per sample since the guided radii differ). The
///   contraction stops when (almost) no sample is left to move; with the guidance also after three
///   stages that make no new branch point (the free samples left are then settled at the
///   initial skeleton's junctions or stuck against the distance-field constraint).
///   At most `contraction_stages` stages run (default 64). With the guidance, where
///   `build_skeleton_graph()` re-centres the initial skeleton on the samples, one stage
///   gave the same topology and centring on our 72 test cases in about half the time,
///   but at h0 the samples of thick parts are still far from the axis (6.8 voxels on
///   average on the capsule with holes, 1.1 after all stages) and the re-centring then
///   relies on their symmetry around it.
/// - **Branches and bridges** between stages: see `internal/branch_tracing.h`.
///
/// \tparam ConcurrencyTag the iteration and the directionality run with TBB when it is
///         `CGAL::Parallel_tag`; results do not depend on the number of threads
/// \param points the points to contract towards (non-outlier input points and points
///        added by upsampling)
/// \param field the distance field (its grid fixes the voxel size for every method)
/// \param initial the initial skeleton; its graph vertices are the attractors S
/// \param np optional named parameters: `skeletonization_method`, `number_of_samples`
///        (CGAL's, default 1500, at most the number of points), `repulsion_coefficient`
///        (0.35), `initial_support_radius` (2 d_bb / cbrt N), `support_radius_growth` (0.5),
///        `branch_directionality` (0.9), `number_of_iterations` (CGAL's: the maximum per
///        stage, default 30), `contraction_stages` (64)
/// \throws Invalid_input if `points` is empty or has a non-finite coordinate, or a
///         parameter is out of range
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class Traits,
          class NamedParameters = parameters::Default_named_parameters>
Contracted_samples<Traits> contract_samples(const std::vector<typename Traits::Point_3>& points,
                                            const Distance_field<Traits>& field,
                                            const Initial_skeleton<Traits>& initial,
                                            const NamedParameters& np = parameters::default_values())
{
  using namespace internal;
  static constexpr const char* stage = "contract_samples";
  typedef typename Traits::Point_3 Point_3;
  const CGAL::Identity_property_map<Point_3> identity;
  const double diagonal = internal::diagonal(checked_bbox(points, identity, stage));

  Contracted_samples<Traits> result;
  result.method = skeletonization_method(np);
  const bool guided = result.method == Skeletonization_method::DISTANCE_FIELD_GUIDED;
  const std::vector<Vec3> input = to_xyz(points, identity);
  const std::size_t m = number_of_samples(np, points.size(), stage);
  const double u = repulsion_coefficient(np, stage);
  const double h0 = initial_support_radius(np, diagonal, points.size(), stage);
  const double growth = support_radius_growth(np, stage);
  const double sigma_threshold = branch_directionality(np, stage);
  const int max_iterations = iterations_per_stage(np, stage);
  result.initial_support_radius = h0;

  const Field_lookup<Traits> lookup(field);
  const double voxel = lookup.voxel_size();
  const double tolerance = (guided ? 0.2 : 0.05) * voxel;

  std::vector<Vec3> attractors;
  if(guided)
    for(std::size_t v = 0; v < boost::num_vertices(initial.graph); ++v)
      attractors.push_back(to_vec3(initial.graph[v].point));
  const Uniform_grid attractor_grid(attractors, 2 * voxel);

  // The pick of the samples and the gathering of the points for the data term (with
  // the levels the first stage reads) are independent and both sequential: one each.
  std::vector<std::size_t> picked;
  std::optional<Gathered_input> gathered;
  run_both<ConcurrencyTag>([&] { picked = select_samples(input, m); },
                           [&] {
                             gathered.emplace(input, voxel / 4);
                             gathered->cover_radius(h0);
                           });
  Sample_set s;
  for(std::size_t i : picked)
    s.x.push_back(input[i]);
  s.role.assign(s.x.size(), Sample_role::FREE);
  s.radius.assign(s.x.size(), h0);
  s.adj.resize(s.x.size());
  s.junction.assign(s.x.size(), 0);
  const auto record = [&]() {
    std::vector<Point_3> positions;
    positions.reserve(s.size());
    for(const Vec3& p : s.x)
      positions.emplace_back(p[0], p[1], p[2]);
    result.iterations.push_back(std::move(positions));
  };
  record();

  Branch_tracer<Traits> tracer(s, guided ? &lookup : nullptr, sigma_threshold, h0,
                               guided ? junction_zones(initial.graph, lookup) : std::vector<Junction_zone>());
  int stages_without_branch = 0;
  const int max_stages = contraction_stages(np, stage);
  for(int stage_index = 0; stage_index < max_stages; ++stage_index)
  {
    std::vector<std::size_t> free;
    std::vector<double> free_radii;
    for(std::size_t i = 0; i < s.size(); ++i)
      if(s.role[i] == Sample_role::FREE && s.radius[i] <= diagonal) // a larger ball holds the whole object: settled
      {
        free.push_back(i);
        free_radii.push_back(s.radius[i]);
      }
    if(free.empty() || (stage_index > 0 && free.size() <= 6)) // the L1-medial rule: (almost) none left
      break;
    Contraction_stage stats;
    stats.free_samples = free.size();
    stats.min_radius = *std::min_element(free_radii.begin(), free_radii.end());
    stats.max_radius = *std::max_element(free_radii.begin(), free_radii.end());
    double sum = 0;
    for(double h : free_radii)
      sum += h;
    stats.mean_radius = std::clamp(sum / double(free_radii.size()), stats.min_radius, stats.max_radius);

    const double cell = (std::max)(median_of(free_radii) / 2, voxel / 2);
    gathered->cover_radius(stats.max_radius);
    const L1_median_step step{*gathered, attractors, guided ? &attractor_grid : nullptr, u};
    for(int it = 0; it < max_iterations; ++it)
    {
      const std::vector<Vec3> previous = s.x;
      const Uniform_grid sample_grid(previous, cell);
      std::vector<double> moved(free.size(), 0);
      const auto start = std::chrono::steady_clock::now();
      for_each_index<ConcurrencyTag>(free.size(), [&](std::size_t f) {
        const std::size_t i = free[f];
        const Vec3 next = step(previous, sample_grid, i, s.radius[i]);
        if(guided && !lookup.allows_step(previous[i], next))
          return;
        s.x[i] = next;
        moved[f] = distance(next, previous[i]);
      }, 16);
      stats.projection_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ++stats.iterations;
      record();
      double mean = 0;
      for(double d : moved)
        mean += d / double(moved.size());
      if(mean < tolerance)
        break;
    }

    std::vector<char> active(s.size());
    for(std::size_t i = 0; i < s.size(); ++i)
      active[i] = s.role[i] != Sample_role::REMOVED;
    const std::vector<Vec3> positions = s.x;
    const Uniform_grid sample_grid(positions, cell);
    const Directionality directionality = compute_directionality<ConcurrencyTag>(positions, active, s.radius, sample_grid);
    std::vector<char> centred;
    if(guided)
    {
      centred.assign(s.size(), 0);
      for_each_index<ConcurrencyTag>(s.size(), [&](std::size_t i) {
        const double tolerance_i = (std::max)(1.5 * voxel, 0.5 * lookup.distance(s.x[i]));
        attractor_grid.for_each_in_ball(s.x[i], tolerance_i, [&](std::size_t, double) {
          centred[i] = 1;
          return false;
        });
      });
    }
    const std::size_t new_branch_points = tracer.run(directionality, centred);
    stats.branch_samples = std::size_t(std::count(s.role.begin(), s.role.end(), Sample_role::BRANCH));
    result.stages.push_back(stats);
    stages_without_branch = new_branch_points > 0 ? 0 : stages_without_branch + 1;
    if(guided && stages_without_branch >= 3) // every sample has reached the initial skeleton or gave up
      break;

    // Next support radius.
    for(std::size_t i = 0; i < s.size(); ++i)
    {
      if(s.role[i] != Sample_role::FREE)
        continue;
      double& h = s.radius[i];
      if(guided)
      {
        const Ball_sums c = ball_sums(attractor_grid, attractors, s.x[i], h, 0);
        if(c.count > 0 && distance(c.mean(), s.x[i]) < voxel)
        {
          h = (std::max)(lookup.distance(c.mean()), 2 * voxel);
          continue;
        }
      }
      h = (1 + growth) * h;
    }
  }

  for(const Vec3& p : s.x)
    result.points.emplace_back(p[0], p[1], p[2]);
  result.roles = s.role;
  result.support_radii = s.radius;
  for(std::size_t a = 0; a < s.size(); ++a)
    for(std::size_t b : s.adj[a])
      if(a < b)
        result.edges.emplace_back(a, b);
  return result;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_CONTRACT_SAMPLES_H
