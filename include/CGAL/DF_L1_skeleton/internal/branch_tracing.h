// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_BRANCH_TRACING_H
#define CGAL_DF_L1_SKELETON_INTERNAL_BRANCH_TRACING_H

#include <CGAL/DF_L1_skeleton/Contracted_samples.h>
#include <CGAL/DF_L1_skeleton/internal/l1_median_iteration.h>
#include <CGAL/DF_L1_skeleton/internal/sample_directionality.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// The samples of the contraction and the branches grown through them: branch samples are
// frozen and joined by edges; junctions are extra frozen samples appended at the end.
struct Sample_set
{
  std::vector<Vec3> x;
  std::vector<Sample_role> role;
  std::vector<double> radius;                // support radius h of each sample
  std::vector<std::vector<std::size_t>> adj; // branch edges
  std::vector<char> junction;                // junction points made by bridges

  std::size_t size() const { return x.size(); }
  void link(std::size_t a, std::size_t b)
  {
    if(a == b || std::find(adj[a].begin(), adj[a].end(), b) != adj[a].end())
      return;
    adj[a].push_back(b);
    adj[b].push_back(a);
    role[a] = role[b] = Sample_role::BRANCH;
  }
  std::size_t add(const Vec3& p, double h)
  {
    x.push_back(p);
    role.push_back(Sample_role::BRANCH);
    radius.push_back(h);
    adj.emplace_back();
    junction.push_back(1);
    return x.size() - 1;
  }
  bool is_end(std::size_t i) const { return role[i] == Sample_role::BRANCH && adj[i].size() == 1 && !junction[i]; }
  // outward direction of a branch end
  Vec3 end_direction(std::size_t e) const { return normalized(x[e] - x[adj[e][0]]); }
};

// Where the initial skeleton has a junction (a cluster of adjacent graph vertices of
// degree 3 or more): its centre and the local radius there. Near a junction the samples
// of several arms mix and sigma stays high over the arms' scale, so the L1-medial tracing
// runs straight through it and joins arms wrongly; with the initial skeleton known, the
// guided method traces no branch inside these balls and joins the ends that reach one
// at its centre instead.
struct Junction_zone
{
  Vec3 centre;
  double radius;
};

// Branch tracing and bridge points (L1-medial method, with the distance-field guidance
// of section 6.1 when `field` is set: every new connection must stay inside the shape,
// and lengths scale with the local radius instead of the global support radius).
template <class Traits>
class Branch_tracer
{
public:
  Branch_tracer(Sample_set& s, const Field_lookup<Traits>* field, double sigma_threshold, double initial_radius,
                std::vector<Junction_zone> zones = {})
    : s_(s), field_(field), sigma_threshold_(sigma_threshold), h0_(initial_radius), zones_(std::move(zones))
  {
    junction_of_zone_.assign(zones_.size(), npos);
  }

  // the zone that holds p, or npos
  std::size_t zone_of(const Vec3& p) const
  {
    for(std::size_t z = 0; z < zones_.size(); ++z)
      if(distance(p, zones_[z].centre) < zones_[z].radius)
        return z;
    return npos;
  }

  // Grows the existing branches and traces new ones through the candidates (free samples
  // with smoothed sigma above the threshold), then adds bridges; returns how many samples
  // became branch points.
  //
  // `centred` (empty without guidance) flags the samples that have reached the initial
  // skeleton; only those may become branch points: a line of samples away from it is a
  // sheet still contracting, and tracing it early gives parallel and stray branches.
  std::size_t run(const Directionality& d, const std::vector<char>& centred = {})
  {
    centred_ = &centred;
    const std::size_t before = count(Sample_role::BRANCH);
    std::vector<Vec3> positions = s_.x;
    Uniform_grid grid(positions, cell_size());
    grid_ = &grid;
    d_ = &d;
    used_.assign(s_.size(), 0);
    update_max_exclusion();
    extend_ends(/*bridge*/ false);
    trace_new_branches();
    remove_samples_near_branches();
    join_ends();
    extend_ends(/*bridge*/ true);
    connect_ends_to_branches();
    grid_ = nullptr;
    d_ = nullptr;
    return count(Sample_role::BRANCH) - before;
  }

  // Local radius of the shape at p: the distance value, or the support radius without
  // a field.
  double local_radius(std::size_t i) const
  {
    const double v = field_ ? field_->voxel_size() : 0;
    return field_ ? (std::max)(field_->distance(s_.x[i]), v) : s_.radius[i];
  }
  bool connection_allowed(const Vec3& a, const Vec3& b) const
  {
    return field_ == nullptr || field_->segment_inside(a, b);
  }

private:
  static constexpr double cos_turn = 0.90630778703665; // cos 25 degrees
  static constexpr double cos_bridge = 0.86602540378444; // cos 30 degrees
  static constexpr double cos_facing = -0.76604444311898; // cos 140 degrees

  std::size_t count(Sample_role r) const { return std::size_t(std::count(s_.role.begin(), s_.role.end(), r)); }

  double cell_size() const
  {
    std::vector<double> h;
    for(std::size_t i = 0; i < s_.size(); ++i)
      if(s_.role[i] != Sample_role::REMOVED)
        h.push_back(s_.radius[i]);
    if(h.empty())
      return h0_;
    std::nth_element(h.begin(), h.begin() + h.size() / 2, h.end());
    return (std::max)(h[h.size() / 2] / 2, 1e-12);
  }

  bool is_centred(std::size_t q) const { return centred_->empty() || (q < centred_->size() && (*centred_)[q]); }

  // How far a branch may step from p: its support radius, and with the field at most two
  // local radii (a step across a thin part must not reach the next one).
  double reach(std::size_t p) const
  {
    return field_ ? (std::min)(s_.radius[p], 2 * local_radius(p)) : s_.radius[p];
  }

  bool candidate(std::size_t q) const
  {
    return q < d_->sigma.size() && s_.role[q] == Sample_role::FREE && !used_[q] && d_->sigma[q] > sigma_threshold_ &&
           is_centred(q) && zone_of(s_.x[q]) == npos;
  }

  // The nearest sample q within the support radius of p whose direction from p is
  // within the given angle of d and that passes `accept`.
  template <class Accept>
  std::size_t next_sample(std::size_t p, const Vec3& d, double cos_max, double reach, const Accept& accept) const
  {
    std::size_t best = npos;
    double best_d2 = 0;
    grid_->for_each_in_ball(s_.x[p], reach, [&](std::size_t q, double d2) {
      if(q == p || d2 <= 0 || !accept(q))
        return true;
      if(dot(s_.x[q] - s_.x[p], d) < cos_max * std::sqrt(d2))
        return true;
      if(best == npos || d2 < best_d2 || (d2 == best_d2 && q < best))
      {
        best = q;
        best_d2 = d2;
      }
      return true;
    });
    if(best != npos && !connection_allowed(s_.x[p], s_.x[best]))
      return npos;
    return best;
  }

  Vec3 oriented_direction(std::size_t q, const Vec3& d) const
  {
    Vec3 e = q < d_->direction.size() ? d_->direction[q] : d;
    if(dot(e, d) < 0)
      e = -1.0 * e;
    return normalized(e + d);
  }

  // Follows candidates from p along d; returns the samples met, in order.
  std::vector<std::size_t> follow(std::size_t p, Vec3 d)
  {
    std::vector<std::size_t> chain;
    for(;;)
    {
      const std::size_t q = next_sample(p, d, cos_turn, reach(p), [&](std::size_t c) { return candidate(c); });
      if(q == npos)
        return chain;
      used_[q] = 1;
      chain.push_back(q);
      d = oriented_direction(q, normalized(s_.x[q] - s_.x[p]));
      p = q;
    }
  }

  // Existing branches grow through new candidates (or, as bridges, through any free
  // sample ahead of them).
  void extend_ends(bool bridge)
  {
    const std::size_t n = s_.size();
    for(std::size_t e = 0; e < n; ++e)
    {
      if(!s_.is_end(e))
        continue;
      if(bridge)
      {
        const std::size_t q = next_sample(e, s_.end_direction(e), cos_bridge, reach(e), [&](std::size_t c) {
          return s_.role[c] == Sample_role::FREE && is_centred(c) && zone_of(s_.x[c]) == npos;
        });
        if(q != npos)
        {
          s_.link(e, q);
          remove_samples_near({q});
        }
        continue;
      }
      std::size_t p = e;
      const std::vector<std::size_t> grown = follow(e, s_.end_direction(e));
      for(std::size_t q : grown)
      {
        s_.link(p, q);
        p = q;
      }
      remove_samples_near(grown);
    }
  }

  // Minimum number of points of a new branch: 6, plus one per multiple of h0 that the
  // support radius has reached (the L1-medial rule).
  std::size_t minimum_branch_size(std::size_t seed) const
  {
    return s_.radius[seed] > h0_ ? 5 + std::size_t(std::floor(s_.radius[seed] / h0_)) : 6;
  }

  void trace_new_branches()
  {
    std::vector<std::size_t> seeds;
    for(std::size_t i = 0; i < d_->sigma.size(); ++i)
      if(candidate(i))
        seeds.push_back(i);
    std::stable_sort(seeds.begin(), seeds.end(), [&](std::size_t a, std::size_t b) { return d_->sigma[a] > d_->sigma[b]; });
    for(std::size_t seed : seeds)
    {
      if(!candidate(seed) || near_branch(seed))
        continue;
      used_[seed] = 1;
      std::vector<std::size_t> forward = follow(seed, d_->direction[seed]);
      std::vector<std::size_t> backward = follow(seed, -1.0 * d_->direction[seed]);
      std::vector<std::size_t> chain(backward.rbegin(), backward.rend());
      chain.push_back(seed);
      chain.insert(chain.end(), forward.begin(), forward.end());
      if(chain.size() < minimum_branch_size(seed))
        continue; // the samples stay free, but are not tried again in this stage
      for(std::size_t a = 1; a < chain.size(); ++a)
        s_.link(chain[a - 1], chain[a]);
      remove_samples_near(chain);
    }
  }

  // Free samples within the exclusion radius of the given branch points are on that
  // branch: without this, the band of samples around a branch would start parallel ones.
  void remove_samples_near(const std::vector<std::size_t>& branch_points)
  {
    for(std::size_t b : branch_points)
    {
      const double r = exclusion_radius(b);
      grid_->for_each_in_ball(s_.x[b], r, [&](std::size_t i, double) {
        if(i < s_.size() && s_.role[i] == Sample_role::FREE)
          s_.role[i] = Sample_role::REMOVED;
        return true;
      });
    }
  }

  // Exclusion radius around branch points: samples closer than this to a branch are on
  // it. The L1-medial method uses 0.05 h; with the distance field, 0.3 of the local radius
  // (and at least a voxel), the accuracy we ask of the skeleton.
  double exclusion_radius(std::size_t b) const
  {
    if(field_ == nullptr)
      return 0.05 * s_.radius[b];
    return (std::max)(field_->voxel_size(), 0.3 * field_->distance(s_.x[b]));
  }

  bool near_branch(std::size_t i) const
  {
    bool near = false;
    grid_->for_each_in_ball(s_.x[i], max_exclusion_, [&](std::size_t b, double d2) {
      if(b < s_.size() && s_.role[b] == Sample_role::BRANCH && d2 < exclusion_radius(b) * exclusion_radius(b))
      {
        near = true;
        return false;
      }
      return true;
    });
    return near;
  }

  void update_max_exclusion()
  {
    max_exclusion_ = 0;
    for(std::size_t b = 0; b < s_.size(); ++b)
      if(s_.role[b] == Sample_role::BRANCH)
        max_exclusion_ = (std::max)(max_exclusion_, exclusion_radius(b));
  }

  void remove_samples_near_branches()
  {
    update_max_exclusion();
    std::vector<Vec3> positions = s_.x;
    Uniform_grid grid(positions, (std::max)(max_exclusion_, 1e-12));
    const Uniform_grid* saved = grid_;
    grid_ = &grid;
    for(std::size_t i = 0; i < s_.size(); ++i)
      if(s_.role[i] == Sample_role::FREE && near_branch(i))
        s_.role[i] = Sample_role::REMOVED;
    grid_ = saved;
  }

  // Reach of the bridges between branch ends: three local radii with the field (ends stop
  // about a radius short of the junction they belong to), the support radius without.
  double join_radius(std::size_t e) const
  {
    return field_ ? 3 * local_radius(e) : s_.radius[e];
  }

  // Ends close to each other are joined: three or more at a new junction sample at their
  // mean, two when they face each other (the same curve, broken).
  void join_ends()
  {
    join_ends_at_zones();
    std::vector<std::size_t> ends;
    for(std::size_t i = 0; i < s_.size(); ++i)
      if(s_.is_end(i))
        ends.push_back(i);
    std::vector<std::size_t> group(ends.size());
    std::iota(group.begin(), group.end(), std::size_t(0));
    const std::function<std::size_t(std::size_t)> find = [&](std::size_t a) {
      return group[a] == a ? a : group[a] = find(group[a]);
    };
    for(std::size_t a = 0; a < ends.size(); ++a)
      for(std::size_t b = a + 1; b < ends.size(); ++b)
      {
        const double d = distance(s_.x[ends[a]], s_.x[ends[b]]);
        if(d < (std::min)(join_radius(ends[a]), join_radius(ends[b])) && !same_branch(ends[a], ends[b]) &&
           connection_allowed(s_.x[ends[a]], s_.x[ends[b]]))
          group[find(a)] = find(b);
      }
    std::vector<std::vector<std::size_t>> members(ends.size());
    for(std::size_t a = 0; a < ends.size(); ++a)
      members[find(a)].push_back(ends[a]);
    for(const std::vector<std::size_t>& g : members)
    {
      if(g.size() >= 3)
      {
        Vec3 mean{{0, 0, 0}};
        double h = 0;
        for(std::size_t e : g)
        {
          mean = mean + (1.0 / double(g.size())) * s_.x[e];
          h = (std::max)(h, s_.radius[e]);
        }
        const std::size_t j = s_.add(mean, h);
        used_.push_back(1);
        for(std::size_t e : g)
          if(connection_allowed(s_.x[e], mean))
            s_.link(e, j);
      }
      else if(g.size() == 2 && dot(s_.end_direction(g[0]), s_.end_direction(g[1])) < cos_facing)
        s_.link(g[0], g[1]);
    }
  }

  // An end within its join radius of a junction zone joins the zone's junction point (one
  // per zone, at the centre of the initial skeleton's junction).
  void join_ends_at_zones()
  {
    const std::size_t n = s_.size();
    for(std::size_t e = 0; e < n; ++e)
    {
      if(!s_.is_end(e))
        continue;
      std::size_t best = npos;
      double best_gap = 0;
      for(std::size_t z = 0; z < zones_.size(); ++z)
      {
        const double gap = distance(s_.x[e], zones_[z].centre) - zones_[z].radius;
        if(gap < join_radius(e) && (best == npos || gap < best_gap) && connection_allowed(s_.x[e], zones_[z].centre))
        {
          best = z;
          best_gap = gap;
        }
      }
      if(best == npos)
        continue;
      if(junction_of_zone_[best] == npos)
      {
        junction_of_zone_[best] = s_.add(zones_[best].centre, zones_[best].radius);
        used_.push_back(1);
      }
      s_.link(e, junction_of_zone_[best]);
    }
  }

  // An end that points at another branch within reach joins it (a T junction).
  void connect_ends_to_branches()
  {
    const std::size_t n = s_.size();
    for(std::size_t e = 0; e < n; ++e)
    {
      if(!s_.is_end(e))
        continue;
      const Vec3 d = s_.end_direction(e);
      std::size_t best = npos;
      double best_d = 0;
      const double reach = join_radius(e);
      for(std::size_t b = 0; b < n; ++b)
      {
        if(s_.role[b] != Sample_role::BRANCH || b == e || s_.is_end(b))
          continue;
        const double dist = distance(s_.x[b], s_.x[e]);
        if(dist >= reach || dot(s_.x[b] - s_.x[e], d) < 0.5 * dist) // within 60 degrees
          continue;
        if(same_branch(e, b)) // last: a walk over the branch, where the tests above are a few operations
          continue;
        if(best == npos || dist < best_d)
        {
          best = b;
          best_d = dist;
        }
      }
      if(best != npos && connection_allowed(s_.x[e], s_.x[best]))
        s_.link(e, best);
    }
  }

  // whether a and b are joined by branch edges
  bool same_branch(std::size_t a, std::size_t b) const
  {
    std::vector<std::size_t> stack{a};
    std::vector<char> seen(s_.size(), 0);
    seen[a] = 1;
    while(!stack.empty())
    {
      const std::size_t v = stack.back();
      stack.pop_back();
      if(v == b)
        return true;
      for(std::size_t w : s_.adj[v])
        if(!seen[w])
        {
          seen[w] = 1;
          stack.push_back(w);
        }
    }
    return false;
  }

  static constexpr std::size_t npos = std::size_t(-1);

  Sample_set& s_;
  const Field_lookup<Traits>* field_;
  double sigma_threshold_, h0_;
  const Uniform_grid* grid_ = nullptr;
  const Directionality* d_ = nullptr;
  const std::vector<char>* centred_ = nullptr;
  std::vector<char> used_;
  double max_exclusion_ = 0;
  std::vector<Junction_zone> zones_;
  std::vector<std::size_t> junction_of_zone_; // the junction point made for each zone
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_BRANCH_TRACING_H
