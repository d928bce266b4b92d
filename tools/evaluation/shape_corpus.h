// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef DF_L1_TEST_SUPPORT_SHAPE_CORPUS_H
#define DF_L1_TEST_SUPPORT_SHAPE_CORPUS_H

/// \file shape_corpus.h
/// A seeded procedural corpus of random shapes with known skeletons, in families that
/// cover what real objects do, and the degradations every shape is judged under.
///
/// Every shape is built as a graph of parts (tubes along polylines, balls, plates) that
/// meet only at the graph's nodes; a part is kept only when its surface stays at least
/// a gap away from every part it does not share a node with, so that the designed
/// topology is the topology of the solid. The expected topology is read off the graph
/// (`Shape::skeleton_topology()`), never typed in. Sizes: the longest side of a shape's
/// bounding box is 1.1 to 3.2; the lengths that matter to the voxel grid are set in voxels
/// of the shape's own default grid (longest side / 100, see `Corpus_sizes`): no tube is
/// thinner than 1.75 voxels (1.35 on one shape), and parts that do not meet are 3 voxels
/// apart or more.
///
/// Families (`corpus_families()`):
/// - `thick_limbs`: a thick body (ball or torso) with thin limbs, body/tip radius 3:1 to 15:1;
/// - `tapering`: cones, horns, fingers and spikes whose radius falls 4:1 to 10:1;
/// - `wavy`: long wavy or curled limbs and snakes;
/// - `trees`: trees of 2 to 5 levels with 10 to 87 tips;
/// - `loops`: rings, handles, wire frames and ladders (1 to 7 cycles);
/// - `sheets`: plates and wings thinner than a tenth of their width (only components and
///   cycles are designed, see `Shape::has_sheets()`);
/// - `close_parts`: parts that come within 1 to 2 voxels of each other without touching;
/// - `disjoint`: 2 to 5 separate objects.

#include "evaluation/synthetic_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace DF_L1_test {

/// The lengths of a shape that are tied to the voxel grid, in input units: a shape is
/// built with the voxel of a first build, then rebuilt with the voxel of that one
/// (`corpus_shape()`), so that they hold in the grid of its cloud.
struct Corpus_sizes
{
  double voxel = 0.02;                                  ///< the shape's longest side / 100
  double thinnest_radius() const { return 1.75 * voxel; } ///< no tube is thinner
  double gap() const { return 3 * voxel; }               ///< clearance between parts that do not meet
};

namespace corpus_internal {

using internal::V3;
using internal::Primitive;
using internal::Rng;
using internal::pi;

inline V3 lerp(const V3& a, const V3& b, double t) { return a + t * (b - a); }

/// `d` turned by `angle` away from itself, towards the azimuth `azimuth` of its frame.
inline V3 deviate(const V3& d, double angle, double azimuth)
{
  V3 u, v;
  internal::complete_frame(internal::normalized(d), u, v);
  const V3 side = std::cos(azimuth) * u + std::sin(azimuth) * v;
  return internal::normalized(std::cos(angle) * internal::normalized(d) + std::sin(angle) * side);
}

inline double angle_between(const V3& a, const V3& b)
{
  const double c = internal::dot(a, b) / (internal::norm(a) * internal::norm(b));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

/// Builds a shape as a graph of parts, refusing parts that would touch parts they do not
/// share a node with (see the file comment).
class Builder
{
public:
  explicit Builder(const Corpus_sizes& sizes, double gap = -1, double min_branch_angle = 30 * pi / 180)
      : gap_(gap >= 0 ? gap : sizes.gap()), min_angle_(min_branch_angle), voxel_(sizes.voxel)
  {
  }

  /// A new node (a point where parts meet or end).
  int node(const V3& p)
  {
    nodes_.push_back({p, 0.0, false});
    return int(nodes_.size()) - 1;
  }
  const V3& position(int n) const { return nodes_[std::size_t(n)].p; }
  /// The largest radius of a part at node `n` so far.
  double node_radius(int n) const { return nodes_[std::size_t(n)].radius; }

  /// A ball of radius `r` centred on node `n` (a body, a knob); always kept.
  void ball(int n, double r)
  {
    shape_.add_sphere(internal::to_point(position(n)), r);
    owned_.push_back({Primitive::make_sphere(position(n), r), {n}});
    bump(n, r);
    nodes_[std::size_t(n)].body = true;
  }

  /// A tube along `path` (path.front() is node `from`'s position), radius `radii[i]` at
  /// `path[i]`, ending at node `to` (its position must be path.back()) or, when `to` is
  /// -1, at a new node. Returns the end node, or -1 (nothing added) when the tube would
  /// come closer than the gap to a part it does not meet, or leave a node at less than
  /// the minimum angle from another part there. With `checked` false the tube is kept
  /// without these tests (a body split into pieces at the nodes where limbs attach).
  int tube(int from, const std::vector<V3>& path, const std::vector<double>& radii, int to = -1, bool checked = true)
  {
    if(path.size() < 2 || radii.size() != path.size())
      throw std::invalid_argument("Builder::tube: one radius per path point, at least two points");
    // A bend tighter than twice the radius folds the tube onto itself: its medial axis
    // would leave the centre line.
    for(std::size_t i = 1; checked && i + 1 < path.size(); ++i) {
      const double turn = angle_between(path[i] - path[i - 1], path[i + 1] - path[i]);
      const double step = 0.5 * (internal::norm(path[i] - path[i - 1]) + internal::norm(path[i + 1] - path[i]));
      if(turn / step * radii[i] > 0.5)
        return -1;
    }
    std::vector<Primitive> prims;
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      if(!(internal::norm(path[i + 1] - path[i]) > std::abs(radii[i] - radii[i + 1])))
        return -1;
      prims.push_back(Primitive::make_round_cone(path[i], path[i + 1], radii[i], radii[i + 1]));
    }
    std::vector<Probe> probes;
    double arclength = 0;
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      const double length = internal::norm(path[i + 1] - path[i]);
      const int k = std::max(1, int(std::ceil(length / (0.5 * voxel_))));
      for(int j = 0; j < k; ++j) {
        const double t = double(j) / k;
        probes.push_back({lerp(path[i], path[i + 1], t), radii[i] + t * (radii[i + 1] - radii[i]), arclength + t * length});
      }
      arclength += length;
    }
    probes.push_back({path.back(), radii.back(), arclength});
    for(Probe& p : probes)
      p.from_end = arclength - p.from_start;
    const V3 start_dir = path[1] - path[0], end_dir = path[path.size() - 2] - path.back();
    if(checked && (!clear_of_itself(probes) || !clear(probes, from, start_dir, radii.front(), to, end_dir, radii.back())))
      return -1;
    const int end = to >= 0 ? to : node(path.back());
    std::vector<Point_3> pts;
    for(const V3& p : path)
      pts.push_back(internal::to_point(p));
    shape_.add_tube(pts, radii);
    for(const Primitive& p : prims)
      owned_.push_back({p, {from, end}});
    bump(from, radii.front());
    bump(end, radii.back());
    directions_.push_back({from, start_dir});
    directions_.push_back({end, end_dir});
    return end;
  }

  /// A straight tube from node `from` to `to_point`, radius `r0` -> `r1`, in `segments` pieces.
  int straight(int from, const V3& to_point, double r0, double r1, int segments = 1)
  {
    std::vector<V3> path;
    std::vector<double> radii;
    for(int i = 0; i <= segments; ++i) {
      const double t = double(i) / segments;
      path.push_back(lerp(position(from), to_point, t));
      radii.push_back(r0 + t * (r1 - r0));
    }
    return tube(from, path, radii);
  }

  /// A plate attached at node `from`: the points within `half_thickness` of the
  /// rectangle whose short side (half extent `half_width`, along `across`) passes through
  /// the node and which extends `length` along `along`. Its skeleton curve runs from the
  /// node along the mid-line. Returns the tip node or -1 (as `tube()`).
  int plate(int from, const V3& along, const V3& across, double length, double half_width, double half_thickness)
  {
    const V3 a = internal::normalized(along);
    V3 c = across - internal::dot(across, a) * a;
    c = internal::normalized(c);
    const V3 centre = position(from) + (0.5 * length) * a;
    const Primitive prim = Primitive::make_slab(centre, a, c, 0.5 * length, half_width, half_thickness);
    std::vector<Probe> probes;
    const int nu = std::max(2, int(std::ceil(length / voxel_)));
    const int nv = std::max(2, int(std::ceil(2 * half_width / voxel_)));
    for(int i = 0; i <= nu; ++i)
      for(int j = 0; j <= nv; ++j) {
        const double s = length * i / nu, t = -half_width + 2 * half_width * j / nv;
        const V3 p = position(from) + s * a + t * c;
        probes.push_back({p, half_thickness, std::sqrt(s * s + t * t), 1e300});
      }
    if(!clear(probes, from, a, half_width, -1, V3{}, 0))
      return -1;
    const V3 tip_point = position(from) + (length - std::min(half_width, 0.5 * length)) * a;
    const int tip = node(tip_point);
    shape_.add_slab(internal::to_point(centre), internal::to_vector(a), internal::to_vector(c), 0.5 * length, half_width,
                    half_thickness, internal::to_point(position(from)), internal::to_point(tip_point));
    owned_.push_back({prim, {from, tip}});
    bump(from, half_width);
    directions_.push_back({from, a});
    return tip;
  }

  /// A closed ring (torus) with no node: a separate loop, kept when clear of everything.
  bool ring(const V3& centre, const V3& axis, double major, double minor)
  {
    const Primitive t = Primitive::make_torus(centre, axis, major, minor);
    std::vector<Probe> probes;
    const int k = std::max(8, int(std::ceil(2 * pi * major / (0.5 * voxel_))));
    for(int i = 0; i < k; ++i) {
      const double phi = 2 * pi * i / k;
      probes.push_back({centre + major * (std::cos(phi) * t.u + std::sin(phi) * t.v), minor, 1e300, 1e300});
    }
    if(!clear(probes, -1, V3{}, 0, -1, V3{}, 0))
      return false;
    shape_.add_torus(internal::to_point(centre), internal::to_vector(axis), major, minor);
    owned_.push_back({t, {}});
    return true;
  }

  /// The shape, its expected topology read off the graph of its axis curves.
  Shape finish(const std::string& name)
  {
    Shape s = shape_;
    s.set_name(name);
    Topology t = s.skeleton_topology();
    s.set_expected_topology(t);
    return s;
  }

  std::size_t parts() const { return owned_.size(); }

private:
  struct Node
  {
    V3 p;
    double radius;
    bool body;
  };
  struct Owned
  {
    Primitive prim;
    std::vector<int> nodes; ///< nodes the part meets
  };
  struct Probe
  {
    V3 p;
    double r;
    double from_start, from_end; ///< arclength to the part's start and end nodes
  };
  struct Direction
  {
    int node;
    V3 d;
  };

  void bump(int n, double r) { nodes_[std::size_t(n)].radius = std::max(nodes_[std::size_t(n)].radius, r); }

  /// The clearance a probe at `p` (radius `r`) must keep from a part `other` that also
  /// meets node `n`: what two straight parts of these radii leaving `n` at the node's
  /// minimum angle keep (negative near the node, where they merge), at most the gap.
  double clearance_near(int n, const V3& p, double r, const Primitive& other) const
  {
    const double s = internal::norm(p - position(n));
    return std::min(gap_, s * std::sin(node_angle(n)) - r - local_radius(other, p));
  }

  /// The radius of a part near its point nearest to `p`.
  static double local_radius(const Primitive& prim, const V3& p)
  {
    switch(prim.kind) {
    case Primitive::round_cone: {
      const double t = std::clamp(internal::dot(p - prim.a, prim.w) / prim.length, 0.0, 1.0);
      return prim.ra + t * (prim.rb - prim.ra);
    }
    case Primitive::torus:
      return prim.rb;
    default: // sphere: its radius; slab: its half thickness
      return prim.ra;
    }
  }

  /// Parts leave a body (a ball) at 60 degrees from each other or more, so that they
  /// separate within it; elsewhere at the builder's minimum angle.
  double node_angle(int n) const { return nodes_[std::size_t(n)].body ? std::max(min_angle_, pi / 3) : min_angle_; }

  /// A tube must not come back near itself: two of its points farther apart along it
  /// than twice their radii and the gap must be that far apart in space too.
  bool clear_of_itself(const std::vector<Probe>& probes) const
  {
    for(std::size_t i = 0; i < probes.size(); ++i)
      for(std::size_t j = i + 1; j < probes.size(); ++j) {
        const double reach = probes[i].r + probes[j].r + gap_;
        if(probes[j].from_start - probes[i].from_start > 2 * reach && internal::norm(probes[j].p - probes[i].p) < reach)
          return false;
      }
    return true;
  }

  bool clear(const std::vector<Probe>& probes, int a, const V3& da, double ra, int b, const V3& db, double rb) const
  {
    for(const Direction& d : directions_) {
      if(a >= 0 && d.node == a && angle_between(d.d, da) < node_angle(a))
        return false;
      if(b >= 0 && d.node == b && angle_between(d.d, db) < node_angle(b))
        return false;
    }
    (void)ra;
    (void)rb;
    // Probes buried in the parts at an end node, from that node on, are where the part
    // is rooted in a body: they cannot touch anything apart from it.
    // A probe whose whole ball is inside them cannot touch anything outside the body.
    std::vector<bool> buried_a(probes.size(), false), buried_b(probes.size(), false), deep(probes.size(), false);
    auto depth_in_parts_at = [&](int n, const V3& p) {
      double d = 1e300;
      for(const Owned& o : owned_)
        if(std::find(o.nodes.begin(), o.nodes.end(), n) != o.nodes.end())
          d = std::min(d, o.prim.signed_distance(p));
      return -d;
    };
    if(a >= 0)
      for(std::size_t i = 0; i < probes.size() && probes[i].from_start < 1e299; ++i) {
        const double depth = depth_in_parts_at(a, probes[i].p);
        if(!(depth > 0))
          break;
        buried_a[i] = true;
        deep[i] = depth > probes[i].r;
      }
    if(b >= 0)
      for(std::size_t i = probes.size(); i-- > 0;) {
        const double depth = depth_in_parts_at(b, probes[i].p);
        if(!(depth > 0))
          break;
        buried_b[i] = true;
        deep[i] = deep[i] || depth > probes[i].r;
      }
    for(const Owned& o : owned_) {
      const bool at_a = a >= 0 && std::find(o.nodes.begin(), o.nodes.end(), a) != o.nodes.end();
      const bool at_b = b >= 0 && std::find(o.nodes.begin(), o.nodes.end(), b) != o.nodes.end();
      for(std::size_t i = 0; i < probes.size(); ++i) {
        const Probe& p = probes[i];
        // buried in a body it is rooted in: it can only meet the parts at that node
        if(deep[i] || (at_a && buried_a[i]) || (at_b && buried_b[i]))
          continue;
        double need = gap_;
        if(at_a)
          need = std::min(need, clearance_near(a, p.p, p.r, o.prim));
        if(at_b)
          need = std::min(need, clearance_near(b, p.p, p.r, o.prim));
        if(o.prim.signed_distance(p.p) - p.r < need) {
#ifdef DF_L1_CORPUS_DEBUG
          std::cerr << "probe " << i << "/" << probes.size() << " at " << p.p.x << ' ' << p.p.y << ' ' << p.p.z << " s " << p.from_start
                    << " sd " << o.prim.signed_distance(p.p) << " r " << p.r << " need " << need << '\n';
#endif
          return false;
        }
      }
    }
    return true;
  }

  double gap_, min_angle_, voxel_;
  Shape shape_;
  std::vector<Node> nodes_;
  std::vector<Owned> owned_;
  std::vector<Direction> directions_;
};

inline V3 random_unit(Rng& rng) { return rng.unit_vector(); }

/// Radius along a tapering limb: `r0` at the root, `r1` at the tip, with a profile
/// exponent (1 linear, < 1 thinning early, > 1 late).
inline std::vector<double> taper(std::size_t n, double r0, double r1, double exponent = 1)
{
  std::vector<double> r(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double t = n > 1 ? double(i) / double(n - 1) : 0;
    r[i] = r0 + (r1 - r0) * std::pow(t, exponent);
  }
  return r;
}

/// A polyline from `start` along `dir` of length `length`, bending with curvature
/// `curvature` (1/units) about a random fixed axis and waving sideways by `wave`
/// amplitude with `waves` periods; `n` segments.
inline std::vector<V3> limb_path(const V3& start, const V3& dir, double length, double curvature, double wave,
                                 double waves, int n, double azimuth)
{
  V3 u, v;
  const V3 d0 = internal::normalized(dir);
  internal::complete_frame(d0, u, v);
  const V3 side = std::cos(azimuth) * u + std::sin(azimuth) * v;
  const V3 other = internal::cross(d0, side);
  std::vector<V3> path;
  V3 p = start, d = d0;
  const double step = length / n;
  path.push_back(p);
  for(int i = 1; i <= n; ++i) {
    // Integrate a curve whose tangent turns about `other` at the given curvature.
    d = internal::normalized(internal::rotate_about(start + d, start, other, curvature * step) - start);
    p = p + step * d;
    const double s = double(i) / n;
    path.push_back(p + (wave * std::sin(2 * pi * waves * s) * std::sin(pi * s)) * side);
  }
  return path;
}

inline double uniform(Rng& rng, double lo, double hi) { return rng.uniform(lo, hi); }
inline int uniform_int(Rng& rng, int lo, int hi) { return lo + int(rng.index(std::size_t(hi - lo + 1))); }

/// Tries `attempts` times to add a limb; returns its end node or -1.
template <class F>
int attempt(int attempts, F&& f)
{
  for(int i = 0; i < attempts; ++i) {
    const int n = f();
    if(n >= 0)
      return n;
  }
  return -1;
}

// ----------------------------------------------------------------------------------
// Families. Each takes the index of the shape in its family and a random stream.

inline Shape thick_limbs(int index, Rng& rng, const Corpus_sizes& sz)
{
  Builder b(sz);
  const double tip = sz.thinnest_radius();
  const double ratio = uniform(rng, 3, 15);
  const double body_r = std::min(0.5, std::max(0.12, ratio * tip));
  const int limbs = uniform_int(rng, 3, 8);
  if(index % 2 == 0) {
    // A ball body with limbs from its centre.
    const int c = b.node({0, 0, 0});
    b.ball(c, body_r);
    const std::vector<V3> dirs = internal::sphere_directions(limbs);
    const double spin = uniform(rng, 0, 2 * pi);
    for(int i = 0; i < limbs; ++i) {
      attempt(6, [&] {
        const V3 d = deviate(internal::rotate_about(dirs[std::size_t(i)], V3{}, V3{0, 0, 1}, spin), uniform(rng, 0, 0.3),
                             uniform(rng, 0, 2 * pi));
        const double length = body_r + uniform(rng, 0.45, 0.9);
        const double root = std::max(tip, body_r * uniform(rng, 0.25, 0.45));
        const std::vector<V3> path = limb_path({0, 0, 0}, d, length, uniform(rng, -0.6, 0.6), 0, 0, 8, uniform(rng, 0, 2 * pi));
        return b.tube(c, path, taper(path.size(), root, tip, uniform(rng, 0.5, 1.5)));
      });
    }
  } else {
    // A torso with a head, a tail and limbs at the shoulders and hips.
    const double half = uniform(rng, 0.45, 0.7);
    const int hip = b.node({-half, 0, 0}), shoulder = b.node({half, 0, 0});
    b.tube(hip, {{-half, 0, 0}, {half, 0, 0}}, {body_r * 0.9, body_r}, shoulder);
    // the head reaches beyond the body by at least three of its tip radii: no mere bump
    const double head_tip = std::max(tip, body_r * 0.4);
    b.tube(shoulder, limb_path({half, 0, 0}, {1, 0, 0.6}, body_r + std::max(0.35, 3 * head_tip) + uniform(rng, 0, 0.25), 0, 0, 0, 3, 0),
           taper(4, body_r * 0.6, head_tip));
    b.tube(hip, limb_path({-half, 0, 0}, {-1, 0, 0.3}, body_r + uniform(rng, 0.3, 0.7), uniform(rng, -1, 1), 0, 0, 6, 1.57),
           taper(7, body_r * 0.4, tip));
    const int per_end = std::max(1, limbs / 2);
    for(int end = 0; end < 2; ++end)
      for(int k = 0; k < per_end; ++k)
        attempt(6, [&] {
          const int at = end == 0 ? hip : shoulder;
          const double side = (k % 2 == 0 ? 1 : -1) * uniform(rng, 0.25, 0.6);
          const V3 d = internal::normalized(V3{uniform(rng, -0.3, 0.3), -1, side + (k / 2) * 0.4 * (k % 2 ? -1 : 1)});
          const double length = body_r + uniform(rng, 0.5, 0.9);
          const std::vector<V3> path = limb_path(b.position(at), d, length, uniform(rng, -0.5, 0.5), 0, 0, 8, uniform(rng, 0, 2 * pi));
          return b.tube(at, path, taper(path.size(), std::max(tip, body_r * uniform(rng, 0.3, 0.45)), tip));
        });
  }
  return b.finish("thick_limbs_" + std::to_string(index));
}

inline Shape tapering(int index, Rng& rng, const Corpus_sizes& sz)
{
  Builder b(sz);
  const double tip = sz.thinnest_radius();
  const int kind = index % 4;
  if(kind == 0) { // one horn: a curved cone
    const int base = b.node({0, 0, 0});
    const double r0 = tip * uniform(rng, 4, 10);
    const std::vector<V3> path = limb_path({0, 0, 0}, random_unit(rng), uniform(rng, 1.6, 2.2), uniform(rng, 0.3, 1.4), 0, 0, 14,
                                           uniform(rng, 0, 2 * pi));
    b.tube(base, path, taper(path.size(), r0, tip, uniform(rng, 0.6, 1.4)));
  } else if(kind == 1) { // a hand: a palm and five tapering fingers
    const double palm = uniform(rng, 0.14, 0.22);
    const int wrist = b.node({0, -0.5, 0}), knuckle = b.node({0, 0, 0});
    b.tube(wrist, {{0, -0.5, 0}, {0, 0, 0}}, {palm * 0.8, palm}, knuckle);
    for(int f = 0; f < 5; ++f) {
      attempt(6, [&] {
        const double a = (f - 2) * uniform(rng, 0.55, 0.65) + (f == 0 ? -0.3 : 0);
        const V3 d{std::sin(a), std::cos(a), uniform(rng, -0.2, 0.2)};
        const std::vector<V3> path = limb_path({0, 0, 0}, d, palm + uniform(rng, 0.5, 0.9), uniform(rng, -0.8, 0.8), 0, 0, 8,
                                               uniform(rng, 0, 2 * pi));
        return b.tube(knuckle, path, taper(path.size(), std::max(tip, palm * 0.45), tip));
      });
    }
  } else if(kind == 2) { // a head with two tapering horns and a neck
    const double r = uniform(rng, 0.2, 0.3);
    const int c = b.node({0, 0, 0});
    b.ball(c, r);
    b.straight(c, {0, -r - uniform(rng, 0.4, 0.7), 0}, r * 0.6, r * 0.5, 2);
    for(int side = -1; side <= 1; side += 2)
      attempt(6, [&] {
        const V3 d{side * uniform(rng, 0.5, 1), 1, uniform(rng, -0.4, 0.4)};
        const std::vector<V3> path = limb_path({0, 0, 0}, d, r + uniform(rng, 0.7, 1.1), side * uniform(rng, 0.8, 1.8), 0, 0, 12, 0);
        return b.tube(c, path, taper(path.size(), r * 0.6, tip, 0.8));
      });
  } else { // a spiky ball: conical spikes
    const double r = uniform(rng, 0.2, 0.35);
    const int c = b.node({0, 0, 0});
    b.ball(c, r);
    const int spikes = uniform_int(rng, 5, 12);
    for(const V3& d0 : internal::sphere_directions(spikes))
      attempt(4, [&] {
        const V3 d = deviate(d0, uniform(rng, 0, 0.25), uniform(rng, 0, 2 * pi));
        return b.straight(c, (r + uniform(rng, 0.45, 0.8)) * d, r * uniform(rng, 0.35, 0.55), tip, 4);
      });
  }
  return b.finish("tapering_" + std::to_string(index));
}

inline Shape wavy(int index, Rng& rng, const Corpus_sizes& sz)
{
  Builder b(sz);
  const double tip = sz.thinnest_radius();
  if(index % 3 == 0) { // a snake
    const int head = b.node({0, 0, 0});
    attempt(20, [&] {
      const std::vector<V3> path = limb_path({0, 0, 0}, random_unit(rng), uniform(rng, 2.0, 2.6), uniform(rng, -0.8, 0.8),
                                             uniform(rng, 0.1, 0.25), uniform(rng, 1.5, 3.0), 40, uniform(rng, 0, 2 * pi));
      return b.tube(head, path, taper(path.size(), tip * uniform(rng, 1.5, 2.5), tip));
    });
  } else { // a body with long wavy or curled arms, thinning to a tenth of the body
    const double body_r = uniform(rng, 0.18, 0.3);
    const int c = b.node({0, 0, 0});
    b.ball(c, body_r);
    const int arms = uniform_int(rng, 2, 8);
    const bool curled = index % 3 == 2;
    for(const V3& d0 : internal::sphere_directions(arms))
      attempt(8, [&] {
        const V3 d = deviate(d0, uniform(rng, 0, 0.3), uniform(rng, 0, 2 * pi));
        const double length = body_r + uniform(rng, 0.7, 1.2);
        const std::vector<V3> path =
          curled ? limb_path({0, 0, 0}, d, length, uniform(rng, 2.0, 3.5) * (rng.uniform() < 0.5 ? -1 : 1), 0, 0, 30,
                             uniform(rng, 0, 2 * pi))
                 : limb_path({0, 0, 0}, d, length, uniform(rng, -0.5, 0.5), uniform(rng, 0.06, 0.15), uniform(rng, 1, 3), 30,
                             uniform(rng, 0, 2 * pi));
        return b.tube(c, path, taper(path.size(), std::max(tip, body_r * 0.45), std::max(tip, body_r * 0.1)));
      });
  }
  return b.finish("wavy_" + std::to_string(index));
}

inline Shape trees(int index, Rng& rng, const Corpus_sizes& sz)
{
  Builder b(sz, sz.gap(), 25 * pi / 180);
  const double tip = sz.thinnest_radius();
  const int levels = 2 + index % 4;                                  // 2..5
  const int target_tips = uniform_int(rng, 10, levels <= 2 ? 16 : 100); // 2 levels: at most 4 per split
  const double fan = std::pow(double(target_tips), 1.0 / levels);
  const double total = 2.0;
  // Lengths fall by `shrink` per level; the trunk takes the rest of the height.
  const double shrink = levels <= 3 ? uniform(rng, 0.6, 0.8) : uniform(rng, 0.75, 0.85);
  double sum = 0;
  for(int l = 0; l <= levels; ++l)
    sum += std::pow(shrink, l);
  const double trunk = total / sum;
  const int root = b.node({0, -1, 0});
  struct Open
  {
    int node;
    V3 dir;
    double radius;
  };
  // Radii by the pipe model: a parent of k children of radius r has radius r sqrt(k).
  std::vector<double> level_radius(std::size_t(levels + 1));
  level_radius[std::size_t(levels)] = tip;
  for(int l = levels - 1; l >= 0; --l)
    level_radius[std::size_t(l)] = std::min(0.22, level_radius[std::size_t(l + 1)] * std::sqrt(fan));
  // no branch thicker than a fifth of its length: a stubby branch would reach no
  // farther than the surface of its parent
  for(int l = 0; l <= levels; ++l)
    level_radius[std::size_t(l)] =
      std::max(tip, std::min(level_radius[std::size_t(l)], 0.2 * trunk * std::pow(shrink, l)));
  std::vector<Open> open;
  const V3 up{uniform(rng, -0.1, 0.1), 1, uniform(rng, -0.1, 0.1)};
  const int top = b.straight(root, b.position(root) + trunk * internal::normalized(up), level_radius[0] * 1.1, level_radius[0], 2);
  open.push_back({top, internal::normalized(up), level_radius[0]});
  for(int l = 1; l <= levels; ++l) {
    std::vector<Open> next;
    const double length = trunk * std::pow(shrink, l) * uniform(rng, 0.9, 1.1);
    for(const Open& o : open) {
      const int k = std::max(2, int(std::floor(fan + rng.uniform())));
      const double azimuth0 = uniform(rng, 0, 2 * pi);
      for(int c = 0; c < k; ++c) {
        const int end = attempt(5, [&] {
          const double spread = uniform(rng, 0.45, 0.9);
          const V3 d = deviate(o.dir, spread, azimuth0 + 2 * pi * (c + uniform(rng, -0.15, 0.15)) / k);
          const std::vector<V3> path = limb_path(b.position(o.node), d, length * uniform(rng, 0.85, 1.15), uniform(rng, -0.6, 0.6), 0,
                                                 0, 4, uniform(rng, 0, 2 * pi));
          return b.tube(o.node, path, taper(path.size(), level_radius[std::size_t(l)] * 1.05, level_radius[std::size_t(l)]));
        });
        if(end >= 0)
          next.push_back({end, internal::normalized(b.position(end) - b.position(o.node)), level_radius[std::size_t(l)]});
      }
    }
    open = next;
  }
  return b.finish("trees_" + std::to_string(index));
}

inline Shape loops(int index, Rng& rng, const Corpus_sizes& sz)
{
  Builder b(sz);
  const int kind = index % 5;
  const double r = uniform(rng, 0.05, 0.1);
  auto bent = [&](const V3& p, const V3& q, double bend) { // a slightly bowed path from p to q
    std::vector<V3> path;
    V3 u, v;
    internal::complete_frame(internal::normalized(q - p), u, v);
    const V3 side = std::cos(bend * 7) * u + std::sin(bend * 7) * v;
    for(int i = 0; i <= 8; ++i) {
      const double t = i / 8.0;
      path.push_back(lerp(p, q, t) + (bend * internal::norm(q - p) * std::sin(pi * t)) * side);
    }
    return path;
  };
  auto edge = [&](int a, int c, double bend) {
    const std::vector<V3> path = bent(b.position(a), b.position(c), bend);
    return b.tube(a, path, std::vector<double>(path.size(), r), c);
  };
  if(kind == 0) { // a torus or a ring with arms
    const V3 axis = random_unit(rng);
    const double major = uniform(rng, 0.6, 0.9);
    V3 u, v;
    internal::complete_frame(axis, u, v);
    const int arms = uniform_int(rng, 0, 3);
    if(arms == 0)
      b.ring({0, 0, 0}, axis, major, uniform(rng, 0.08, 0.2));
    else {
      std::vector<int> at;
      for(int i = 0; i < arms + 1; ++i) {
        const double phi = 2 * pi * (i + uniform(rng, -0.1, 0.1)) / (arms + 1);
        at.push_back(b.node(major * (std::cos(phi) * u + std::sin(phi) * v)));
      }
      for(std::size_t i = 0; i < at.size(); ++i) {
        const std::size_t j = (i + 1) % at.size();
        // the arc between two nodes of the ring
        const V3 p = b.position(at[i]), q = b.position(at[j]);
        double a0 = std::atan2(internal::dot(p, v), internal::dot(p, u)), a1 = std::atan2(internal::dot(q, v), internal::dot(q, u));
        if(a1 <= a0)
          a1 += 2 * pi;
        std::vector<V3> path;
        for(int s = 0; s <= 16; ++s) {
          const double phi = a0 + (a1 - a0) * s / 16.0;
          path.push_back(s == 16 ? q : major * (std::cos(phi) * u + std::sin(phi) * v));
        }
        b.tube(at[i], path, std::vector<double>(path.size(), r), at[j]);
      }
      for(int i = 0; i < arms; ++i) { // arms pointing outwards
        const V3 out = internal::normalized(b.position(at[std::size_t(i)]));
        b.straight(at[std::size_t(i)], b.position(at[std::size_t(i)]) + uniform(rng, 0.4, 0.7) * deviate(out, uniform(rng, 0, 0.5), uniform(rng, 0, 6.3)),
                   r, std::max(sz.thinnest_radius(), r * 0.7), 2);
      }
    }
  } else if(kind == 1) { // a mug: a body with one or two handles
    const double body = uniform(rng, 0.25, 0.4);
    // The body runs on 0.8 (at least twice its radius) below and above the handles,
    // so that its ends are not mere bumps; a second handle faces the first.
    const int bottom = b.node({0, -1, 0});
    std::vector<int> stations{bottom};
    for(int i = 1; i <= 6; ++i)
      stations.push_back(b.tube(stations.back(), {b.position(stations.back()), {0, -1 + 0.4 * i, 0}}, {body, body}, -1, false));
    const int handles = uniform_int(rng, 1, 2);
    for(int h = 0; h < handles; ++h) {
      const int s0 = stations[2], s1 = stations[4];
      const double side = h == 0 ? 1 : -1;
      const V3 p = b.position(s0), q = b.position(s1);
      std::vector<V3> path;
      const double reach = body + uniform(rng, 0.3, 0.45);
      // half an ellipse: the handle leaves the body at a right angle
      for(int s = 0; s <= 16; ++s) {
        const double t = s / 16.0;
        path.push_back(s == 16 ? q : lerp(p, q, 0.5 * (1 - std::cos(pi * t))) + (side * reach * std::sin(pi * t)) * V3{1, 0, 0});
      }
      b.tube(s0, path, std::vector<double>(path.size(), r), s1);
    }
  } else if(kind == 2) { // a wire frame: tetrahedron, prism or cube
    const int which = int(rng.index(3));
    std::vector<V3> corners;
    std::vector<std::pair<int, int>> edges;
    if(which == 0) {
      corners = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
      edges = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    } else if(which == 1) {
      for(int z = -1; z <= 1; z += 2)
        for(int i = 0; i < 3; ++i)
          corners.push_back({std::cos(2 * pi * i / 3), std::sin(2 * pi * i / 3), 0.8 * z});
      edges = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
    } else {
      for(int i = 0; i < 8; ++i)
        corners.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
      edges = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    }
    const V3 axis = random_unit(rng);
    const double angle = uniform(rng, 0, pi), scale = uniform(rng, 0.55, 0.7);
    std::vector<int> ids;
    for(const V3& c : corners)
      ids.push_back(b.node(internal::rotate_about(scale * c, V3{}, axis, angle)));
    for(const auto& e : edges)
      edge(ids[std::size_t(e.first)], ids[std::size_t(e.second)], uniform(rng, -0.08, 0.08));
  } else if(kind == 3) { // a ladder: two rails and rungs
    const int rungs = uniform_int(rng, 2, 5);
    const double width = uniform(rng, 0.5, 0.8), height = 2.0;
    std::vector<int> left, right;
    for(int i = 0; i < rungs; ++i) {
      const double y = -1 + height * (i + 0.5) / rungs;
      left.push_back(b.node({-width / 2, y, 0}));
      right.push_back(b.node({width / 2, y, 0}));
    }
    for(int i = 0; i < rungs; ++i)
      edge(left[std::size_t(i)], right[std::size_t(i)], uniform(rng, -0.1, 0.1));
    for(int i = 0; i + 1 < rungs; ++i) {
      edge(left[std::size_t(i)], left[std::size_t(i + 1)], uniform(rng, -0.05, 0.05));
      edge(right[std::size_t(i)], right[std::size_t(i + 1)], uniform(rng, -0.05, 0.05));
    }
    // The rails run on past the end rungs.
    b.straight(left.front(), b.position(left.front()) + V3{0, -uniform(rng, 0.35, 0.45), 0}, r, r);
    b.straight(right.back(), b.position(right.back()) + V3{0, uniform(rng, 0.35, 0.45), 0}, r, r);
  } else { // a chain of rings joined by bars (a pretzel)
    const int rings = uniform_int(rng, 2, 3);
    const double major = uniform(rng, 0.28, 0.35);
    std::vector<int> prev_right;
    for(int k = 0; k < rings; ++k) {
      const double cx = (k - (rings - 1) / 2.0) * (2 * major + 0.35);
      const int west = b.node({cx - major, 0, 0}), east = b.node({cx + major, 0, 0});
      for(int half = 0; half < 2; ++half) {
        std::vector<V3> path;
        for(int s = 0; s <= 16; ++s) {
          const double phi = pi - pi * s / 16.0 * (half == 0 ? 1 : -1);
          path.push_back(s == 0 ? b.position(west) : s == 16 ? b.position(east) : V3{cx + major * std::cos(phi), major * std::sin(phi), 0});
        }
        b.tube(west, path, std::vector<double>(path.size(), r), east);
      }
      if(!prev_right.empty())
        edge(prev_right.back(), west, 0);
      prev_right.push_back(east);
    }
  }
  return b.finish("loops_" + std::to_string(index));
}

inline Shape sheets(int index, Rng& rng, const Corpus_sizes& sz)
{
  Builder b(sz, sz.gap(), 20 * pi / 180);
  const int kind = index % 3;
  auto thickness_for = [&](double half_width) {
    // under a tenth of the width, and never below one voxel
    return std::max(0.5 * sz.voxel, std::min(0.1 * half_width, uniform(rng, 0.6, 1.0) * 0.1 * half_width));
  };
  if(kind == 0) { // one plate, maybe on a stalk
    const V3 along = random_unit(rng);
    V3 u, v;
    internal::complete_frame(along, u, v);
    const double half_width = uniform(rng, 0.3, 0.6);
    const int root = b.node({0, 0, 0});
    int at = root;
    if(rng.uniform() < 0.5)
      at = b.straight(root, -0.6 * along, 0.06, 0.06);
    (void)at;
    b.plate(root, along, u, uniform(rng, 1.2, 1.8), half_width, thickness_for(half_width));
  } else if(kind == 1) { // a bird: body, head, two wings and a tail plate
    const double body = uniform(rng, 0.12, 0.18);
    const int tail = b.node({-0.55, 0, 0}), mid = b.node({0, 0, 0});
    b.tube(tail, {{-0.55, 0, 0}, {0, 0, 0}}, {body * 0.7, body}, mid);
    const int neck = b.tube(mid, {{0, 0, 0}, {0.5, 0, 0.05}}, {body, body * 0.8});
    if(neck >= 0)
      b.straight(neck, {0.75, 0, 0.12}, body * 0.6, sz.thinnest_radius() * 1.2);
    for(int side = -1; side <= 1; side += 2) {
      const double half_width = uniform(rng, 0.18, 0.28);
      const V3 along{uniform(rng, -0.3, 0.1), double(side), uniform(rng, -0.2, 0.3)};
      b.plate(mid, along, {1, 0, 0}, uniform(rng, 0.8, 1.1), half_width, thickness_for(half_width));
    }
    const double tail_half = uniform(rng, 0.12, 0.2);
    b.plate(tail, {-1, 0, uniform(rng, -0.2, 0.2)}, {0, 1, 0}, uniform(rng, 0.35, 0.5), tail_half, thickness_for(tail_half));
  } else { // a plant: a stem with long leaves
    const int leaves = uniform_int(rng, 2, 6);
    const double stem_r = uniform(rng, 0.04, 0.07);
    int at = b.node({0, -1, 0});
    for(int i = 0; i < leaves; ++i) {
      const int next = b.straight(at, b.position(at) + V3{uniform(rng, -0.05, 0.05), 1.6 / leaves, 0}, stem_r, stem_r);
      if(next < 0)
        break;
      at = next;
      attempt(6, [&] {
        const double azimuth = 2.4 * i + uniform(rng, -0.3, 0.3);
        const V3 out{std::cos(azimuth), uniform(rng, 0.3, 0.9), std::sin(azimuth)};
        const V3 across = internal::cross(out, V3{0, 1, 0});
        const double half_width = uniform(rng, 0.06, 0.12);
        return b.plate(at, out, across, uniform(rng, 0.6, 1.0), half_width, thickness_for(half_width));
      });
    }
    b.straight(at, b.position(at) + V3{0, 0.3, 0}, stem_r, sz.thinnest_radius());
  }
  return b.finish("sheets_" + std::to_string(index));
}

/// `gap`: the clearance (input units) where the parts come close.
inline Shape close_parts(int index, Rng& rng, const Corpus_sizes& sz, double gap)
{
  // Parts elsewhere keep the usual clearance; the designed near-contacts are checked
  // against a slightly smaller one.
  Builder b(sz, 0.8 * gap, 20 * pi / 180);
  const int kind = index % 4;
  const double r = uniform(rng, 0.06, 0.1);
  if(kind == 0) { // two legs side by side under a body (the camel)
    const double body = uniform(rng, 0.18, 0.25);
    const int hip = b.node({0, 0, 0}), front = b.node({1.0, 0, 0});
    b.tube(hip, {{0, 0, 0}, {1.0, 0, 0}}, {body, body}, front);
    const double leg = uniform(rng, 1.0, 1.4);
    const double half = 0.5 * gap + r;
    // the legs splay from the body and run parallel, `gap` apart, below it
    for(int side = -1; side <= 1; side += 2) {
      std::vector<V3> path{{1.0, 0, 0}, {1.0, -body - 0.1, side * (half + 0.12)}, {1.0, -body - 0.25, side * half}, {1.0, -leg, side * half}};
      b.tube(front, path, {r * 1.3, r * 1.1, r, r});
    }
    b.straight(hip, {-0.1, -leg, 0}, r * 1.3, r);
  } else if(kind == 1) { // an almost closed ring: the ends of a C `gap` apart
    const double major = uniform(rng, 0.6, 0.9);
    const double missing = (gap + 2 * r) / major; // the angle the gap spans
    std::vector<V3> path;
    for(int s = 0; s <= 48; ++s) {
      const double phi = (2 * pi - missing) * s / 48.0;
      path.push_back({major * std::cos(phi), major * std::sin(phi), 0});
    }
    // One tube whose ends come `gap` close by design: not tested against itself.
    b.tube(b.node(path.front()), path, std::vector<double>(path.size(), r), -1, false);
  } else if(kind == 2) { // a hairpin: two arms running parallel `gap` apart
    const double length = uniform(rng, 1.2, 1.8);
    const double rad = r + 0.5 * gap;
    std::vector<V3> path{{0, -rad, 0}};
    for(int s = 0; s <= 12; ++s) {
      const double phi = -pi / 2 + pi * s / 12.0;
      path.push_back({length + rad * std::cos(phi), rad * std::sin(phi), 0});
    }
    path.push_back({0, rad, 0});
    // One tube, as tight at its bend as its arms are close: not tested against itself.
    b.tube(b.node(path.front()), path, std::vector<double>(path.size(), r), -1, false);
  } else { // two fingers side by side, `gap` apart, on a palm
    const double palm = uniform(rng, 0.18, 0.25);
    const int wrist = b.node({0, -0.6, 0}), knuckle = b.node({0, 0, 0});
    b.tube(wrist, {{0, -0.6, 0}, {0, 0, 0}}, {palm * 0.8, palm}, knuckle);
    const double half = 0.5 * gap + r;
    for(int side = -1; side <= 1; side += 2) {
      std::vector<V3> path{{0, 0, 0}, {side * half, 0.5 * palm, 0}, {side * half, palm + uniform(rng, 0.8, 1.1), 0}};
      b.tube(knuckle, path, {r * 1.2, r, r});
    }
  }
  return b.finish("close_parts_" + std::to_string(index));
}

inline Shape disjoint(int index, Rng& rng, const Corpus_sizes& sz)
{
  Builder b(sz, 2 * sz.gap());
  const int objects = 2 + index % 4; // 2..5
  const double cell = 2.0 / std::ceil(std::sqrt(double(objects)));
  int placed = 0;
  for(int k = 0; k < objects; ++k) {
    const V3 centre{-1 + cell * (k % int(std::ceil(std::sqrt(double(objects)))) + 0.5), -1 + cell * (k / int(std::ceil(std::sqrt(double(objects)))) + 0.5),
                    uniform(rng, -0.2, 0.2)};
    const double size = 0.38 * cell;
    const int kind = int(rng.index(4));
    const double r = std::max(sz.thinnest_radius(), uniform(rng, 0.12, 0.2) * size);
    if(kind == 0) { // a capsule
      const V3 d = random_unit(rng);
      const int a = b.node(centre - size * d);
      placed += b.straight(a, centre + size * d, r * 1.2, r) >= 0;
    } else if(kind == 1) { // a ring
      placed += b.ring(centre, random_unit(rng), size * 0.75, std::max(sz.thinnest_radius(), 0.18 * size));
    } else if(kind == 2) { // a Y
      const V3 d = random_unit(rng);
      const int a = b.node(centre - size * d);
      const int fork = b.straight(a, centre, r, r);
      if(fork >= 0) {
        for(int side = -1; side <= 1; side += 2)
          b.straight(fork, centre + size * deviate(d, side * 0.6, 0), r, std::max(sz.thinnest_radius(), r * 0.8));
        ++placed;
      }
    } else { // a bent tube
      const int a = b.node(centre - size * V3{1, 0, 0});
      const std::vector<V3> path = limb_path(b.position(a), {1, 0, 0}, 2 * size, uniform(rng, 0.5, 1.5) / size, 0, 0, 10, uniform(rng, 0, 6.3));
      placed += b.tube(a, path, std::vector<double>(path.size(), r)) >= 0;
    }
  }
  (void)placed;
  return b.finish("disjoint_" + std::to_string(index));
}

} // namespace corpus_internal

/// The families of the corpus, in table order.
inline const std::vector<std::string>& corpus_families()
{
  static const std::vector<std::string> names{"thick_limbs", "tapering", "wavy", "trees",
                                              "loops",       "sheets",   "close_parts", "disjoint"};
  return names;
}

/// Shapes per family in the full corpus (8 families: 208 shapes).
constexpr int corpus_shapes_per_family = 26;

/// The voxel size the library's defaults give a cloud of this shape: its longest
/// bounding-box side / 100.
inline double default_voxel_size(const Shape& shape)
{
  const CGAL::Bbox_3 b = shape.bbox();
  return std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()}) / 100.0;
}

/// Shape `index` of `family`, the same for the same arguments; `seed` selects another
/// corpus. Throws `std::invalid_argument` for an unknown family.
inline Shape corpus_shape(const std::string& family, int index, std::uint64_t seed = 1)
{
  const auto& names = corpus_families();
  const auto it = std::find(names.begin(), names.end(), family);
  if(it == names.end())
    throw std::invalid_argument("unknown corpus family '" + family + "'");
  const std::uint64_t stream = std::uint64_t(it - names.begin()) * 100003u + std::uint64_t(index);
  // close_parts: the gap, 1 to 2 voxels
  const double gap_voxels = 1.0 + double((index * 7) % 11) / 10.0;
  auto make = [&](const Corpus_sizes& sz) {
    internal::Rng rng(internal::mix_seed(seed, stream));
    switch(it - names.begin()) {
    case 0: return corpus_internal::thick_limbs(index, rng, sz);
    case 1: return corpus_internal::tapering(index, rng, sz);
    case 2: return corpus_internal::wavy(index, rng, sz);
    case 3: return corpus_internal::trees(index, rng, sz);
    case 4: return corpus_internal::loops(index, rng, sz);
    case 5: return corpus_internal::sheets(index, rng, sz);
    case 6: return corpus_internal::close_parts(index, rng, sz, gap_voxels * sz.voxel);
    default: return corpus_internal::disjoint(index, rng, sz);
    }
  };
  // Build with a guess of the voxel, then twice more with the voxel of the last build:
  // the same random draws, so usually only the lengths tied to the voxel change and the
  // bounding box barely moves (where a part then fits or not, the shape changes and its
  // voxel with it: one shape of the corpus ends 22 % off).
  Corpus_sizes sz;
  Shape s = make(sz);
  for(int pass = 0; pass < 2; ++pass) {
    sz.voxel = default_voxel_size(s);
    s = make(sz);
  }
  return s;
}

/// A degradation of the corpus: a sampling variant with its parameters.
struct Degradation
{
  std::string name;
  Variant variant = Variant::clean;
  Variant_options options;
  /// Whether the end points may differ by one (a noisy surface may leave or remove a
  /// short end branch).
  bool noisy = false;
};

/// The degradations every corpus shape is judged under, in table order.
inline std::vector<Degradation> corpus_degradations()
{
  std::vector<Degradation> d;
  d.push_back({"clean", Variant::clean, {}, false});
  for(double sigma : {0.003, 0.006, 0.01}) {
    Degradation n{"noise_" + std::string(sigma == 0.003 ? "0.3" : sigma == 0.006 ? "0.6" : "1.0"), Variant::noise, {}, true};
    n.options.noise_sigma = sigma;
    d.push_back(n);
  }
  for(double f : {0.03, 0.10}) {
    Degradation o{f == 0.03 ? "outliers_3" : "outliers_10", Variant::outliers, {}, false};
    o.options.outlier_fraction = f;
    d.push_back(o);
  }
  d.push_back({"holes", Variant::holes, {}, false});
  d.push_back({"uneven", Variant::uneven, {}, false});
  d.push_back({"sparse_2000", Variant::sparse, {}, false});
  // A scan's sparse regions are sparser still when its density varies (a mesh's large
  // triangles on a body, the far side of a LiDAR crown).
  Degradation sparse_uneven{"uneven_2000", Variant::uneven, {}, false};
  sparse_uneven.options.uneven_count = 2000;
  d.push_back(sparse_uneven);
  return d;
}

/// The degradation of that name; throws `std::invalid_argument` for an unknown name.
inline Degradation corpus_degradation(const std::string& name)
{
  for(const Degradation& d : corpus_degradations())
    if(d.name == name)
      return d;
  throw std::invalid_argument("unknown corpus degradation '" + name + "'");
}

/// The cloud of a corpus case that `scripts/quality.sh` skeletonizes: `shape` (number
/// `index` of its family) sampled with `points` points (the sparse degradation draws its
/// own number) and degraded by `d`, with the seed 1000 + `index`.
inline Sample corpus_sample(const Shape& shape, int index, const Degradation& d, std::size_t points = 20000)
{
  return make_sample(shape, d.variant, points, 1000 + std::uint64_t(index), d.options);
}

/// Whether a skeleton's topology is the designed one: components and cycles always;
/// junctions and end points (within +-1 when `noisy`) unless the shape has plates.
inline bool corpus_topology_matches(const Shape& shape, const Topology& got, bool noisy)
{
  const Topology& e = shape.expected_topology();
  if(e.components != got.components || e.cycles != got.cycles)
    return false;
  if(shape.has_sheets())
    return true;
  return e.junctions == got.junctions && std::abs(e.end_points - got.end_points) <= (noisy ? 1 : 0);
}

} // namespace DF_L1_test

#endif // DF_L1_TEST_SUPPORT_SHAPE_CORPUS_H
