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
#include <utility>
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
/// The contraction of `contract_samples()` one support-radius stage at a time, for a
/// caller that looks at the samples between stages (`DF_L1_skeletonization::contract()`).
/// Running `contract()` until it returns `false` and then `result()` gives exactly what
/// `contract_samples()` returns.
///
/// The field and the initial skeleton must outlive the object.
/// \tparam Traits a model of `Kernel`
/// \tparam ConcurrencyTag as for `contract_samples()`
template <class Traits, class ConcurrencyTag = CGAL::Parallel_if_available_tag>
class Sample_contraction
{
  typedef typename Traits::Point_3 Point_3;

public:
  /// Picks the samples and prepares the contraction; the parameters and exceptions are
  /// those of `contract_samples()`.
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
  Sample_contraction(const PointRange& points, const Distance_field<Traits>& field,
                     const Initial_skeleton<Traits>& initial, const NamedParameters& np = parameters::default_values())
      : lookup_(field)
  {
    using namespace internal;
    static constexpr const char* stage = "contract_samples";
    const auto point_map = parameters::choose_parameter(parameters::get_parameter(np, internal_np::point_map),
                                                        CGAL::Identity_property_map<Point_3>());
    diagonal_ = internal::diagonal(checked_bbox(points, point_map, stage));
    result_.method = skeletonization_method(np);
    guided_ = result_.method == Skeletonization_method::DISTANCE_FIELD_GUIDED;
    const std::vector<Vec3> input = to_xyz(points, point_map);
    const std::size_t m = number_of_samples(np, input.size(), stage);
    u_ = repulsion_coefficient(np, stage);
    const double h0 = initial_support_radius(np, diagonal_, input.size(), stage);
    growth_ = support_radius_growth(np, stage);
    const double sigma_threshold = branch_directionality(np, stage);
    max_iterations_ = iterations_per_stage(np, stage);
    max_stages_ = contraction_stages(np, stage);
    result_.initial_support_radius = h0;

    voxel_ = lookup_.voxel_size();
    tolerance_ = (guided_ ? 0.2 : 0.05) * voxel_;
    if(guided_)
      for(std::size_t v = 0; v < boost::num_vertices(initial.graph); ++v)
        attractors_.push_back(to_vec3(initial.graph[v].point));
    attractor_grid_.emplace(attractors_, 2 * voxel_);

    // The pick of the samples and the gathering of the points for the data term (with
    // the levels the first stage reads) are independent and both sequential: one each.
    std::vector<std::size_t> picked;
    run_both<ConcurrencyTag>([&] { picked = select_samples(input, m); },
                             [&] {
                               gathered_.emplace(input, voxel_ / 4);
                               gathered_->cover_radius(h0);
                             });
    for(std::size_t i : picked)
      s_.x.push_back(input[i]);
    s_.role.assign(s_.x.size(), Sample_role::FREE);
    s_.radius.assign(s_.x.size(), h0);
    s_.adj.resize(s_.x.size());
    s_.junction.assign(s_.x.size(), 0);
    record();
    tracer_.emplace(s_, guided_ ? &lookup_ : nullptr, sigma_threshold, h0,
                    guided_ ? junction_zones(initial.graph, lookup_) : std::vector<Junction_zone>());
  }

  /// Runs one support-radius stage: the L1-median iterations of the free samples, then
  /// the branch tracing. Returns `false`, running nothing, once the contraction has
  /// converged (no free sample left, the maximum number of stages reached, or, guided,
  /// three stages without a new branch point).
  bool contract()
  {
    using namespace internal;
    if(converged_ || stage_index_ >= max_stages_)
    {
      converged_ = true;
      return false;
    }
    std::vector<std::size_t> free;
    std::vector<double> free_radii;
    for(std::size_t i = 0; i < s_.size(); ++i)
      if(s_.role[i] == Sample_role::FREE && s_.radius[i] <= diagonal_) // a larger ball holds the whole object: settled
      {
        free.push_back(i);
        free_radii.push_back(s_.radius[i]);
      }
    if(free.empty() || (stage_index_ > 0 && free.size() <= 6)) // the L1-medial rule: (almost) none left
    {
      converged_ = true;
      return false;
    }
    Contraction_stage stats;
    stats.free_samples = free.size();
    stats.min_radius = *std::min_element(free_radii.begin(), free_radii.end());
    stats.max_radius = *std::max_element(free_radii.begin(), free_radii.end());
    double sum = 0;
    for(double h : free_radii)
      sum += h;
    stats.mean_radius = std::clamp(sum / double(free_radii.size()), stats.min_radius, stats.max_radius);

    const double cell = (std::max)(median_of(free_radii) / 2, voxel_ / 2);
    gathered_->cover_radius(stats.max_radius);
    const L1_median_step step{*gathered_, attractors_, guided_ ? &*attractor_grid_ : nullptr, u_};
    for(int it = 0; it < max_iterations_; ++it)
    {
      const std::vector<Vec3> previous = s_.x;
      const Uniform_grid sample_grid(previous, cell);
      std::vector<double> moved(free.size(), 0);
      const auto start = std::chrono::steady_clock::now();
      for_each_index<ConcurrencyTag>(free.size(), [&](std::size_t f) {
        const std::size_t i = free[f];
        const Vec3 next = step(previous, sample_grid, i, s_.radius[i]);
        if(guided_ && !lookup_.allows_step(previous[i], next))
          return;
        s_.x[i] = next;
        moved[f] = distance(next, previous[i]);
      }, 16);
      stats.projection_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ++stats.iterations;
      record();
      double mean = 0;
      for(double d : moved)
        mean += d / double(moved.size());
      if(mean < tolerance_)
        break;
    }

    std::vector<char> active(s_.size());
    for(std::size_t i = 0; i < s_.size(); ++i)
      active[i] = s_.role[i] != Sample_role::REMOVED;
    const std::vector<Vec3> positions = s_.x;
    const Uniform_grid sample_grid(positions, cell);
    const Directionality directionality = compute_directionality<ConcurrencyTag>(positions, active, s_.radius, sample_grid);
    std::vector<char> centred;
    if(guided_)
    {
      centred.assign(s_.size(), 0);
      for_each_index<ConcurrencyTag>(s_.size(), [&](std::size_t i) {
        const double tolerance_i = (std::max)(1.5 * voxel_, 0.5 * lookup_.distance(s_.x[i]));
        attractor_grid_->for_each_in_ball(s_.x[i], tolerance_i, [&](std::size_t, double) {
          centred[i] = 1;
          return false;
        });
      });
    }
    const std::size_t new_branch_points = tracer_->run(directionality, centred);
    stats.branch_samples = std::size_t(std::count(s_.role.begin(), s_.role.end(), Sample_role::BRANCH));
    result_.stages.push_back(stats);
    ++stage_index_;
    stages_without_branch_ = new_branch_points > 0 ? 0 : stages_without_branch_ + 1;
    if(guided_ && stages_without_branch_ >= 3) // every sample has reached the initial skeleton or gave up
    {
      converged_ = true;
      return true;
    }

    // Next support radius.
    for(std::size_t i = 0; i < s_.size(); ++i)
    {
      if(s_.role[i] != Sample_role::FREE)
        continue;
      double& h = s_.radius[i];
      if(guided_)
      {
        const Ball_sums c = ball_sums(*attractor_grid_, attractors_, s_.x[i], h, 0);
        if(c.count > 0 && distance(c.mean(), s_.x[i]) < voxel_)
        {
          h = (std::max)(lookup_.distance(c.mean()), 2 * voxel_);
          continue;
        }
      }
      h = (1 + growth_) * h;
    }
    return true;
  }

  /// whether `contract()` has nothing left to do
  bool converged() const { return converged_; }

  /// The samples as they are now (after the stages run so far), their branches and the
  /// record of every stage and iteration.
  Contracted_samples<Traits> result() const&
  {
    Contracted_samples<Traits> r = result_;
    complete(r);
    return r;
  }
  /// the same, moving the record of the iterations out of a contraction that is done with
  Contracted_samples<Traits> result() &&
  {
    Contracted_samples<Traits> r = std::move(result_);
    complete(r);
    return r;
  }

private:
  // the current samples, their roles, radii and edges, added to the record `r`
  void complete(Contracted_samples<Traits>& r) const
  {
    for(const internal::Vec3& p : s_.x)
      r.points.emplace_back(p[0], p[1], p[2]);
    r.roles = s_.role;
    r.support_radii = s_.radius;
    for(std::size_t a = 0; a < s_.size(); ++a)
      for(std::size_t b : s_.adj[a])
        if(a < b)
          r.edges.emplace_back(a, b);
  }

  void record()
  {
    std::vector<Point_3> positions;
    positions.reserve(s_.size());
    for(const internal::Vec3& p : s_.x)
      positions.emplace_back(p[0], p[1], p[2]);
    result_.iterations.push_back(std::move(positions));
  }

  internal::Field_lookup<Traits> lookup_;
  double diagonal_ = 0, u_ = 0, growth_ = 0, voxel_ = 0, tolerance_ = 0;
  bool guided_ = true;
  int max_iterations_ = 0, max_stages_ = 0;
  std::vector<internal::Vec3> attractors_;
  std::optional<internal::Uniform_grid> attractor_grid_;
  std::optional<internal::Gathered_input> gathered_;
  internal::Sample_set s_;
  std::optional<internal::Branch_tracer<Traits>> tracer_; // refers to s_: the object is not copied
  Contracted_samples<Traits> result_; // method, h0, stages and iterations so far
  int stage_index_ = 0, stages_without_branch_ = 0;
  bool converged_ = false;

public:
  Sample_contraction(const Sample_contraction&) = delete;
  Sample_contraction& operator=(const Sample_contraction&) = delete;
};

/// \ingroup PkgDFL1SkeletonRef
/// Contracts samples of the points onto the curve skeleton (paper, section 6): the
/// L1-median fixed-point iteration of Eq. 8, stage after stage of growing support radius,
/// with branch tracing and bridge points between stages.
///
/// About `number_of_samples` samples are picked evenly on a voxel grid (deterministic,
/// where the L1-medial method draws them at random). Each iteration moves every free
/// sample from the previous iterate by a convergent form of Eq. 8 with the same fixed
/// point (the paper's literal form diverges when v > 1 + u); with the guidance, a step
/// that would end in an exterior voxel or at a smaller distance value is not taken, the
/// attraction term pulls towards the initial skeleton, and each sample's support radius
/// follows Eq. 9 (the distance value at the centre of the skeleton points in its ball).
/// Without guidance all samples share one radius growing by 1 + `support_radius_growth`
/// per stage (the L1-medial schedule). The contraction stops when no sample is left to
/// move. The rules and their measurements: \ref design_contraction.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: the iteration and the directionality run with
///         TBB when parallel; results do not depend on the number of threads
/// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
/// \tparam Traits a model of `Kernel`
/// \param points the points to contract towards (non-outlier input points and points
///        added by upsampling)
/// \param field the distance field (its grid fixes the voxel size for every method)
/// \param initial the initial skeleton; its graph vertices are the attractors
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<Traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{skeletonization_method}
///     \cgalParamDescription{the distance-field guided method or the plain L1-medial skeleton}
///     \cgalParamType{`Skeletonization_method`}
///     \cgalParamDefault{`Skeletonization_method::DISTANCE_FIELD_GUIDED`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_samples}
///     \cgalParamDescription{M, the number of samples contracted (at most the number of points)}
///     \cgalParamType{`std::size_t`, in [1, 10^8]}
///     \cgalParamDefault{1500}
///   \cgalParamNEnd
///   \cgalParamNBegin{repulsion_coefficient}
///     \cgalParamDescription{u of Eq. 8, the weight of the repulsion between samples}
///     \cgalParamType{`double`, in [0, 0.5)}
///     \cgalParamDefault{0.35}
///   \cgalParamNEnd
///   \cgalParamNBegin{initial_support_radius}
///     \cgalParamDescription{h0, the support radius of the first stage, in input units}
///     \cgalParamType{`double`, > 0}
///     \cgalParamDefault{2 d_bb / cbrt(N), N the number of points}
///   \cgalParamNEnd
///   \cgalParamNBegin{support_radius_growth}
///     \cgalParamDescription{the growth of a support radius between stages, h <- (1 + growth) h}
///     \cgalParamType{`double`, in (0, 4]}
///     \cgalParamDefault{0.5}
///   \cgalParamNEnd
///   \cgalParamNBegin{branch_directionality}
///     \cgalParamDescription{the directionality sigma above which a sample may become a branch point}
///     \cgalParamType{`double`, in (1/3, 1)}
///     \cgalParamDefault{0.9}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the most iterations of one support-radius stage}
///     \cgalParamType{`int`, in [1, 10000]}
///     \cgalParamDefault{30}
///   \cgalParamNEnd
///   \cgalParamNBegin{contraction_stages}
///     \cgalParamDescription{the most support-radius stages}
///     \cgalParamType{`int`, in [1, 64]}
///     \cgalParamDefault{64}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the contracted samples, the traced branches and bridges, and the iterations
/// \throws Invalid_input if `points` is empty or has a non-finite coordinate, or a
///         parameter is out of range
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange, class Traits,
          class NamedParameters = parameters::Default_named_parameters>
Contracted_samples<Traits> contract_samples(const PointRange& points,
                                            const Distance_field<Traits>& field,
                                            const Initial_skeleton<Traits>& initial,
                                            const NamedParameters& np = parameters::default_values())
{
  Sample_contraction<Traits, ConcurrencyTag> contraction(points, field, initial, np);
  while(contraction.contract())
  {
  }
  return std::move(contraction).result();
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_CONTRACT_SAMPLES_H
