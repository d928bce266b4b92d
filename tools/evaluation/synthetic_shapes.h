// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef DF_L1_TEST_SUPPORT_SYNTHETIC_SHAPES_H
#define DF_L1_TEST_SUPPORT_SYNTHETIC_SHAPES_H

/// \file synthetic_shapes.h
/// Seeded generator of synthetic point clouds whose curve skeleton is known.
///
/// A `Shape` is a union of primitives with an exact signed distance (tapered
/// capsules, tori, spheres). Its ground-truth skeleton is the union of the
/// primitives' axes (segments, circles, sphere centres), given as polylines
/// with the local radius, together with the expected topology counts.
/// `make_sample()` samples the outer surface of the union uniformly by area and
/// applies a degradation (`Variant`). Everything is deterministic for a seed: the
/// only random source is `std::mt19937_64`, whose output the standard fixes, with
/// our own uniform/normal transforms (the standard distributions differ between
/// libraries). Across platforms, results may still differ in the last bits where
/// the math library (sin, cos, log) does.

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <limits>
#include <numeric>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace DF_L1_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Vector_3 = Kernel::Vector_3;

namespace internal {

constexpr double pi = 3.14159265358979323846;

/// Minimal double vector: the distance and sampling code is arithmetic-heavy and
/// reads better without going through kernel functors.
struct V3
{
  double x = 0, y = 0, z = 0;
};
inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(double s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(const V3& a, const V3& b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const V3& a) { return std::sqrt(dot(a, a)); }
inline V3 normalized(const V3& a) { return (1.0 / norm(a)) * a; }
inline V3 to_v3(const Point_3& p) { return {p.x(), p.y(), p.z()}; }
inline V3 to_v3(const Vector_3& v) { return {v.x(), v.y(), v.z()}; }
inline Point_3 to_point(const V3& a) { return Point_3(a.x, a.y, a.z); }
inline Vector_3 to_vector(const V3& a) { return Vector_3(a.x, a.y, a.z); }

/// Completes the unit vector `w` to an orthonormal frame (u, v, w), deterministically.
inline void complete_frame(const V3& w, V3& u, V3& v)
{
  // A unit vector has a coordinate of magnitude <= 1/sqrt(3) < 0.6, so the helper
  // axis is never nearly parallel to w.
  const V3 helper = std::abs(w.x) < 0.6 ? V3{1, 0, 0} : std::abs(w.y) < 0.6 ? V3{0, 1, 0} : V3{0, 0, 1};
  u = normalized(cross(w, helper));
  v = cross(w, u);
}

/// `p` rotated by `angle` about the line through `c` with unit direction `k` (Rodrigues).
inline V3 rotate_about(const V3& p, const V3& c, const V3& k, double angle)
{
  const V3 d = p - c;
  const double cs = std::cos(angle), sn = std::sin(angle);
  return c + (cs * d + sn * cross(k, d) + ((1 - cs) * dot(k, d)) * k);
}

/// Derives independent, well-mixed seeds from one user seed (splitmix64 finaliser),
/// so that each random stream of a variant does not depend on how much another consumed.
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t stream)
{
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// Portable random source. The standard distributions are implementation-defined,
/// hence these transforms of the (standard-fixed) mt19937_64 output.
class Rng
{
public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n), n > 0 (bias < n / 2^53, irrelevant here).
  std::size_t index(std::size_t n) { return std::min(n - 1, std::size_t(uniform() * double(n))); }
  /// Standard normal deviate (Box-Muller; the second value of each pair is kept).
  double normal()
  {
    if(has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double radius = std::sqrt(-2.0 * std::log(1.0 - uniform())); // 1 - u > 0
    const double angle = 2 * pi * uniform();
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }
  /// Uniform direction on the unit sphere (Archimedes: z is uniform).
  V3 unit_vector()
  {
    const double z = uniform(-1, 1), phi = 2 * pi * uniform();
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

/// One primitive of a shape, with its exact signed distance, axis and surface sampling.
struct Primitive
{
  enum Kind { round_cone, torus, sphere, slab };
  Kind kind = sphere;
  V3 a, b;               ///< round cone: axis ends; torus, sphere, slab: `a` is the centre
  double ra = 0, rb = 0; ///< round cone: radii at a and b; sphere: `ra`; torus: `ra` major, `rb` minor;
                         ///< slab: `ra` the half thickness
  V3 u, v, w;            ///< frame; `w` is the cone axis direction a->b, the torus axis or the slab normal
  double half_u = 0, half_v = 0; ///< slab: half extents of its rectangle along u and v
  double length = 0;     ///< round cone |b - a|
  double sin_a = 0, cos_a = 1; ///< round cone: slope of the flank, sin = (ra - rb) / length

  static Primitive make_round_cone(const V3& a, const V3& b, double ra, double rb)
  {
    Primitive c;
    c.kind = round_cone;
    c.a = a;
    c.b = b;
    c.ra = ra;
    c.rb = rb;
    c.length = norm(b - a);
    if(!(ra > 0 && rb > 0) || !(c.length > std::abs(ra - rb)))
      throw std::invalid_argument("round cone: radii must be positive and neither end ball may contain the other");
    c.w = (1.0 / c.length) * (b - a);
    complete_frame(c.w, c.u, c.v);
    c.sin_a = (ra - rb) / c.length;
    c.cos_a = std::sqrt(1 - c.sin_a * c.sin_a);
    return c;
  }
  static Primitive make_torus(const V3& centre, const V3& axis, double major, double minor)
  {
    if(!(minor > 0 && major > minor))
      throw std::invalid_argument("torus: need 0 < minor radius < major radius");
    Primitive t;
    t.kind = torus;
    t.a = centre;
    t.ra = major;
    t.rb = minor;
    t.w = normalized(axis);
    complete_frame(t.w, t.u, t.v);
    return t;
  }
  /// The points within `half_thickness` of the rectangle centred at `centre` with half
  /// extents `half_u` along the unit vector `u` and `half_v` along `v` (orthogonal to u):
  /// a plate with rounded rims.
  static Primitive make_slab(const V3& centre, const V3& u, const V3& v, double half_u, double half_v,
                             double half_thickness)
  {
    if(!(half_u > 0 && half_v > 0 && half_thickness > 0))
      throw std::invalid_argument("slab: extents and thickness must be positive");
    if(!(norm(cross(normalized(u), normalized(v))) > 1e-6))
      throw std::invalid_argument("slab: u and v must not be parallel");
    Primitive s;
    s.kind = slab;
    s.a = centre;
    s.u = normalized(u);
    s.v = normalized(v - dot(v, s.u) * s.u);
    s.w = cross(s.u, s.v);
    s.half_u = half_u;
    s.half_v = half_v;
    s.ra = half_thickness;
    return s;
  }
  static Primitive make_sphere(const V3& centre, double radius)
  {
    if(!(radius > 0))
      throw std::invalid_argument("sphere: radius must be positive");
    Primitive s;
    s.kind = sphere;
    s.a = centre;
    s.ra = radius;
    complete_frame(V3{0, 0, 1}, s.u, s.v);
    s.w = V3{0, 0, 1};
    return s;
  }

  /// Exact signed distance (negative inside).
  double signed_distance(const V3& p) const
  {
    switch(kind) {
    case round_cone: {
      // In the half-plane (t along the axis, q from the axis) the shape is the hull of
      // two discs tangent to the flank line of outward normal (sin_a, cos_a). The
      // coordinate s along the flank, measured from the tangent point on disc a,
      // tells which feature is nearest: disc a (s < 0), the flank, or disc b.
      const V3 pa = p - a;
      const double t = dot(pa, w);
      const double q = norm(pa - t * w);
      const double s = t * cos_a - q * sin_a;
      if(s < 0)
        return norm(pa) - ra;
      if(s > length * cos_a)
        return norm(p - b) - rb;
      return t * sin_a + q * cos_a - ra;
    }
    case torus: {
      const V3 pc = p - a;
      const double h = dot(pc, w);
      const double rho = norm(pc - h * w);
      return std::sqrt((rho - ra) * (rho - ra) + h * h) - rb;
    }
    case slab:
      return norm(p - nearest_axis_point(p)) - ra;
    default:
      return norm(p - a) - ra;
    }
  }

  /// The point of the primitive's axis (segment, circle, centre) nearest to `p`.
  V3 nearest_axis_point(const V3& p) const
  {
    switch(kind) {
    case round_cone:
      return a + std::clamp(dot(p - a, w), 0.0, length) * w;
    case torus: {
      const V3 pc = p - a;
      const V3 radial = pc - dot(pc, w) * w;
      const double rho = norm(radial);
      // On the axis line every circle point is nearest; pick one deterministically.
      return a + ra * (rho > 1e-300 ? (1.0 / rho) * radial : u);
    }
    case slab: { // the plate's mid rectangle stands for its (2D) medial axis
      const V3 d = p - a;
      return a + std::clamp(dot(d, u), -half_u, half_u) * u + std::clamp(dot(d, v), -half_v, half_v) * v;
    }
    default:
      return a;
    }
  }

  CGAL::Bbox_3 bbox() const
  {
    auto ball = [](const V3& c, double r) {
      return CGAL::Bbox_3(c.x - r, c.y - r, c.z - r, c.x + r, c.y + r, c.z + r);
    };
    switch(kind) {
    case round_cone: // the hull of two balls has the bbox of their union
      return ball(a, ra) + ball(b, rb);
    case torus: {
      // The centre circle spans R*sqrt(1 - w_i^2) along coordinate axis i.
      const double ex = ra * std::sqrt(std::max(0.0, 1 - w.x * w.x)) + rb;
      const double ey = ra * std::sqrt(std::max(0.0, 1 - w.y * w.y)) + rb;
      const double ez = ra * std::sqrt(std::max(0.0, 1 - w.z * w.z)) + rb;
      return CGAL::Bbox_3(a.x - ex, a.y - ey, a.z - ez, a.x + ex, a.y + ey, a.z + ez);
    }
    case slab: {
      const double ex = half_u * std::abs(u.x) + half_v * std::abs(v.x) + ra;
      const double ey = half_u * std::abs(u.y) + half_v * std::abs(v.y) + ra;
      const double ez = half_u * std::abs(u.z) + half_v * std::abs(v.z) + ra;
      return CGAL::Bbox_3(a.x - ex, a.y - ey, a.z - ez, a.x + ex, a.y + ey, a.z + ez);
    }
    default:
      return ball(a, ra);
    }
  }

  /// Number of surface patches sampled separately (cone: cap a, flank, cap b; slab:
  /// faces, rims, corners).
  int patch_count() const { return kind == round_cone || kind == slab ? 3 : 1; }

  double patch_area(int patch) const
  {
    switch(kind) {
    case round_cone:
      if(patch == 0) // spherical cap below the tangent circle: height ra (1 + sin_a)
        return 2 * pi * ra * ra * (1 + sin_a);
      if(patch == 2)
        return 2 * pi * rb * rb * (1 - sin_a);
      // frustum: circle radii r cos_a, slant length L cos_a
      return pi * (ra + rb) * length * cos_a * cos_a;
    case torus:
      return 4 * pi * pi * ra * rb;
    case slab:
      if(patch == 0) // two faces
        return 8 * half_u * half_v;
      if(patch == 1) // half cylinders along the four edges
        return 4 * (half_u + half_v) * pi * ra;
      return 4 * pi * ra * ra; // four quarter balls at the corners
    default:
      return 4 * pi * ra * ra;
    }
  }

  /// Draws a point uniformly by area on one patch, with its outward unit normal.
  void sample_patch(int patch, Rng& rng, V3& point, V3& normal) const
  {
    const double phi = 2 * pi * rng.uniform();
    const V3 radial = std::cos(phi) * u + std::sin(phi) * v;
    auto on_ball = [&](const V3& c, double r, double z) { // z uniform => uniform on the zone
      normal = z * w + std::sqrt(std::max(0.0, 1 - z * z)) * radial;
      point = c + r * normal;
    };
    switch(kind) {
    case round_cone:
      if(patch == 0)
        on_ball(a, ra, rng.uniform(-1, sin_a));
      else if(patch == 2)
        on_ball(b, rb, rng.uniform(sin_a, 1));
      else {
        // Along the flank the circle radius grows linearly from ra cos_a to rb cos_a,
        // so the slant parameter has a linear density: invert its CDF (stable form).
        const double r0 = ra * cos_a, r1 = rb * cos_a, xi = rng.uniform();
        const double lambda = xi * (r0 + r1) / (r0 + std::sqrt(r0 * r0 + (r1 - r0) * xi * (r0 + r1)));
        normal = sin_a * w + cos_a * radial;
        point = a + lambda * (b - a) + (ra + lambda * (rb - ra)) * normal;
      }
      break;
    case torus: {
      // The area element is proportional to R + r cos(theta): rejection on theta.
      double theta;
      do
        theta = 2 * pi * rng.uniform();
      while(rng.uniform() * (ra + rb) > ra + rb * std::cos(theta));
      normal = std::cos(theta) * radial + std::sin(theta) * w;
      point = a + ra * radial + rb * normal;
      break;
    }
    case slab: {
      if(patch == 0) {
        normal = rng.uniform() < 0.5 ? w : -1.0 * w;
        point = a + rng.uniform(-half_u, half_u) * u + rng.uniform(-half_v, half_v) * v + ra * normal;
      } else if(patch == 1) {
        // An edge by its length, then a point on its outer half cylinder (uniform in angle).
        const double t = rng.uniform(0, 2 * (half_u + half_v));
        const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0, theta = rng.uniform(-pi / 2, pi / 2);
        V3 on_edge, out;
        if(t < 2 * half_u) { // an edge along u, at v = +-half_v
          on_edge = a + rng.uniform(-half_u, half_u) * u + (sign * half_v) * v;
          out = sign * v;
        } else {
          on_edge = a + (sign * half_u) * u + rng.uniform(-half_v, half_v) * v;
          out = sign * u;
        }
        normal = std::cos(theta) * out + std::sin(theta) * w;
        point = on_edge + ra * normal;
      } else {
        // A uniform direction picks its corner by the signs of its u and v components.
        normal = rng.unit_vector();
        const double su = dot(normal, u) < 0 ? -1.0 : 1.0, sv = dot(normal, v) < 0 ? -1.0 : 1.0;
        point = a + (su * half_u) * u + (sv * half_v) * v + ra * normal;
      }
      break;
    }
    default:
      on_ball(a, ra, rng.uniform(-1, 1));
    }
  }
};

/// A piece of the ground-truth skeleton before sampling: a polyline or a circular arc.
struct Axis_curve
{
  std::vector<V3> vertices; ///< polyline vertices (empty for an arc)
  V3 centre, axis, start;   ///< arc: `start` rotated about (centre, axis) by [0, angle]
  double angle = 0;
  double sheet_half_width = 0; ///< > 0: the mid-line of a plate this wide (see `Shape::add_slab()`)

  bool is_arc() const { return vertices.empty(); }
  V3 front() const { return is_arc() ? start : vertices.front(); }
  V3 back() const { return is_arc() ? rotate_about(start, centre, axis, angle) : vertices.back(); }
};

} // namespace internal

/// Topology counts of a curve skeleton.
struct Topology
{
  int end_points = 0; ///< vertices of degree 1
  int junctions = 0;  ///< vertices of degree >= 3 (a junction of k arms counts once)
  int cycles = 0;     ///< first Betti number
  int components = 0; ///< connected components
};
inline bool operator==(const Topology& a, const Topology& b)
{
  return a.end_points == b.end_points && a.junctions == b.junctions && a.cycles == b.cycles &&
         a.components == b.components;
}
inline bool operator!=(const Topology& a, const Topology& b) { return !(a == b); }
inline std::ostream& operator<<(std::ostream& os, const Topology& t)
{
  return os << "{ends " << t.end_points << ", junctions " << t.junctions << ", cycles " << t.cycles
            << ", components " << t.components << "}";
}

/// One ground-truth skeleton polyline, densely sampled.
struct Skeleton_polyline
{
  /// Consecutive points are joined; a closed polyline repeats its first point at the end.
  std::vector<Point_3> points;
  /// Local radius at each point: the depth -signed_distance() there, i.e. the radius of
  /// the largest primitive ball centred at the point. Exact away from junctions, a
  /// slight underestimate of the inscribed radius close to them.
  std::vector<double> radii;
  bool closed = false;
  /// 0 for a tube; for the mid-line of a plate (`Shape::add_slab()`), half the plate's
  /// width: a curve skeleton of a plate may run anywhere near that line.
  double sheet_half_width = 0;
};

/// A vertex of the ground-truth skeleton graph: where polylines end or meet.
struct Skeleton_node
{
  Point_3 point;
  int degree = 0; ///< 1: end point, 2: plain joint, >= 3: junction
};

/// A solid made of primitives with an analytic signed distance, and its known skeleton.
///
/// Build it with the `add_*` functions. Each primitive contributes its axis to the
/// ground-truth skeleton (a round cone its segment, a torus its centre circle, a sphere
/// its centre), and all but spheres also contribute an axis curve to the skeleton
/// graph. Curves must meet only at their end points; arms meeting at a junction must
/// therefore be separate curves starting at the same point.
class Shape
{
public:
  explicit Shape(std::string name = "", Topology expected = {}) : name_(std::move(name)), expected_(expected) {}

  const std::string& name() const { return name_; }
  /// The topology the shape was designed to have (see the shape functions).
  const Topology& expected_topology() const { return expected_; }
  void set_expected_topology(const Topology& t) { expected_ = t; }
  void set_name(const std::string& name) { name_ = name; }
  /// Whether the shape has a plate (`add_slab()`). The curve skeleton of a plate is a tree
  /// of medial curves whose end points and junctions depend on its outline, so only the
  /// components and cycles of such a shape are designed.
  bool has_sheets() const { return has_sheets_; }

  /// Adds a tapered capsule: the convex hull of the balls (a, ra) and (b, rb).
  /// Its medial axis is the segment ab, with a radius varying linearly from ra to rb.
  Shape& add_round_cone(const Point_3& a, const Point_3& b, double ra, double rb)
  {
    primitives_.push_back(internal::Primitive::make_round_cone(internal::to_v3(a), internal::to_v3(b), ra, rb));
    internal::Axis_curve curve;
    curve.vertices = {internal::to_v3(a), internal::to_v3(b)};
    curves_.push_back(curve);
    return *this;
  }

  /// Adds a tube along a polyline: one round cone per segment (radius `radii[i]` at
  /// `path[i]`) and one axis curve for the whole path. With `closed`, the last point
  /// is joined to the first.
  Shape& add_tube(const std::vector<Point_3>& path, const std::vector<double>& radii, bool closed = false)
  {
    if(path.size() < 2 || radii.size() != path.size())
      throw std::invalid_argument("add_tube: need >= 2 path points and one radius per point");
    internal::Axis_curve curve;
    const std::size_t n = path.size(), segments = closed ? n : n - 1;
    for(std::size_t i = 0; i < segments; ++i) {
      const std::size_t j = (i + 1) % n;
      primitives_.push_back(internal::Primitive::make_round_cone(internal::to_v3(path[i]), internal::to_v3(path[j]),
                                                                 radii[i], radii[j]));
    }
    for(const Point_3& p : path)
      curve.vertices.push_back(internal::to_v3(p));
    if(closed)
      curve.vertices.push_back(internal::to_v3(path.front()));
    curves_.push_back(curve);
    return *this;
  }

  /// Adds a torus (centre circle of radius `major` in the plane through `centre`
  /// orthogonal to `axis`, tube radius `minor`). With `with_axis_curve`, the whole centre
  /// circle becomes one closed axis curve; otherwise describe it with `add_axis_arc()`
  /// (needed when other curves attach to the circle).
  Shape& add_torus(const Point_3& centre, const Vector_3& axis, double major, double minor,
                   bool with_axis_curve = true)
  {
    primitives_.push_back(internal::Primitive::make_torus(internal::to_v3(centre), internal::to_v3(axis), major, minor));
    if(with_axis_curve) {
      const internal::Primitive& t = primitives_.back();
      add_axis_arc(centre, axis, internal::to_point(t.a + major * t.u), 2 * internal::pi);
    }
    return *this;
  }

  /// Adds a plate: the points within `half_thickness` of the rectangle centred at
  /// `centre` with half extents `half_u` along `u` and `half_v` along `v`. Its skeleton
  /// curve is given as the segment from `axis_from` to `axis_to` (usually the long
  /// mid-line, from where the plate is attached), with a coverage tolerance of half of
  /// the shorter half extent (see `Skeleton_polyline::sheet_half_width`).
  Shape& add_slab(const Point_3& centre, const Vector_3& u, const Vector_3& v, double half_u, double half_v,
                  double half_thickness, const Point_3& axis_from, const Point_3& axis_to)
  {
    primitives_.push_back(internal::Primitive::make_slab(internal::to_v3(centre), internal::to_v3(u),
                                                         internal::to_v3(v), half_u, half_v, half_thickness));
    internal::Axis_curve curve;
    curve.vertices = {internal::to_v3(axis_from), internal::to_v3(axis_to)};
    curve.sheet_half_width = std::min(half_u, half_v);
    curves_.push_back(curve);
    has_sheets_ = true;
    return *this;
  }

  /// Adds a ball. Its axis is its centre; it adds no axis curve, so place it on one
  /// (e.g. a knob at the end of a tube).
  Shape& add_sphere(const Point_3& centre, double radius)
  {
    primitives_.push_back(internal::Primitive::make_sphere(internal::to_v3(centre), radius));
    return *this;
  }

  /// Adds an axis curve: the arc swept by `start` rotating by `angle` (radians,
  /// right-handed) about the line through `centre` directed by `axis`.
  Shape& add_axis_arc(const Point_3& centre, const Vector_3& axis, const Point_3& start, double angle)
  {
    internal::Axis_curve curve;
    curve.centre = internal::to_v3(centre);
    curve.axis = internal::normalized(internal::to_v3(axis));
    curve.start = internal::to_v3(start);
    curve.angle = angle;
    curves_.push_back(curve);
    return *this;
  }

  /// Signed distance to the union: minimum over the primitives (negative inside).
  /// Exact outside; inside, a lower bound of the depth (exact away from overlaps).
  double signed_distance(const Point_3& p) const { return signed_distance(internal::to_v3(p)); }
  bool inside(const Point_3& p) const { return signed_distance(p) < 0; }

  CGAL::Bbox_3 bbox() const
  {
    CGAL::Bbox_3 box;
    for(const internal::Primitive& prim : primitives_)
      box += prim.bbox();
    return box;
  }
  double bbox_diagonal() const
  {
    const CGAL::Bbox_3 b = bbox();
    return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                     CGAL::square(b.zmax() - b.zmin()));
  }

  /// The point of the ground-truth skeleton nearest to `p` (exact, from the primitives' axes).
  Point_3 nearest_axis_point(const Point_3& p) const { return internal::to_point(nearest_axis_point(internal::to_v3(p))); }
  /// Distance from `p` to the ground-truth skeleton.
  double distance_to_axis(const Point_3& p) const
  {
    const internal::V3 q = internal::to_v3(p);
    return internal::norm(q - nearest_axis_point(q));
  }
  /// Local radius (depth, see `Skeleton_polyline::radii`) at the skeleton point nearest to `p`.
  double radius_at_nearest_axis_point(const Point_3& p) const
  {
    return -signed_distance(nearest_axis_point(internal::to_v3(p)));
  }

  /// The ground-truth skeleton as polylines sampled every `step` at most
  /// (default: 0.2 % of the bbox diagonal). Points of arcs lie exactly on the circle.
  std::vector<Skeleton_polyline> skeleton_polylines(double step = 0) const
  {
    if(!(step > 0))
      step = 0.002 * bbox_diagonal();
    std::vector<Skeleton_polyline> result;
    for(const internal::Axis_curve& curve : curves_) {
      std::vector<internal::V3> pts;
      if(curve.is_arc()) {
        const double radius = internal::norm(curve.start - curve.centre);
        const std::size_t k = std::max<std::size_t>(1, std::size_t(std::ceil(std::abs(curve.angle) * radius / step)));
        for(std::size_t i = 0; i <= k; ++i)
          pts.push_back(internal::rotate_about(curve.start, curve.centre, curve.axis, curve.angle * double(i) / double(k)));
      } else {
        pts.push_back(curve.vertices.front());
        for(std::size_t s = 0; s + 1 < curve.vertices.size(); ++s) {
          const internal::V3 &p = curve.vertices[s], &q = curve.vertices[s + 1];
          const std::size_t k = std::max<std::size_t>(1, std::size_t(std::ceil(internal::norm(q - p) / step)));
          for(std::size_t i = 1; i <= k; ++i)
            pts.push_back(i == k ? q : p + (double(i) / double(k)) * (q - p));
        }
      }
      Skeleton_polyline polyline;
      polyline.sheet_half_width = curve.sheet_half_width;
      polyline.closed = same_node(curve.front(), curve.back());
      if(polyline.closed)
        pts.back() = pts.front(); // exact repetition, as documented
      for(const internal::V3& p : pts) {
        polyline.points.push_back(internal::to_point(p));
        polyline.radii.push_back(-signed_distance(p));
      }
      result.push_back(std::move(polyline));
    }
    return result;
  }

  /// The vertices of the skeleton graph (curve end points, merged where they coincide).
  std::vector<Skeleton_node> skeleton_nodes() const
  {
    std::vector<Skeleton_node> nodes;
    const Graph g = graph();
    for(std::size_t i = 0; i < g.nodes.size(); ++i)
      nodes.push_back({internal::to_point(g.nodes[i]), g.degree[i]});
    return nodes;
  }

  /// Topology of the skeleton graph built from the axis curves. A consistent shape
  /// has `skeleton_topology() == expected_topology()`.
  Topology skeleton_topology() const
  {
    const Graph g = graph();
    Topology t;
    for(int d : g.degree) {
      t.end_points += d == 1;
      t.junctions += d >= 3;
    }
    t.components = g.components;
    t.cycles = int(curves_.size()) - int(g.nodes.size()) + g.components; // E - V + C
    return t;
  }

  /// The primitives, for the samplers.
  const std::vector<internal::Primitive>& primitives() const { return primitives_; }

private:
  struct Graph
  {
    std::vector<internal::V3> nodes;
    std::vector<int> degree;
    int components = 0;
  };

  double signed_distance(const internal::V3& p) const
  {
    double d = std::numeric_limits<double>::infinity();
    for(const internal::Primitive& prim : primitives_)
      d = std::min(d, prim.signed_distance(p));
    return d;
  }

  internal::V3 nearest_axis_point(const internal::V3& p) const
  {
    internal::V3 best;
    double best_d = std::numeric_limits<double>::infinity();
    for(const internal::Primitive& prim : primitives_) {
      const internal::V3 q = prim.nearest_axis_point(p);
      const double d = internal::norm(p - q);
      if(d < best_d) {
        best_d = d;
        best = q;
      }
    }
    return best;
  }

  bool same_node(const internal::V3& p, const internal::V3& q) const
  {
    return internal::norm(p - q) <= 1e-9 * std::max(1.0, bbox_diagonal());
  }

  /// Contracts every curve to an edge between its end nodes.
  Graph graph() const
  {
    Graph g;
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    auto node_of = [&](const internal::V3& p) {
      for(std::size_t i = 0; i < g.nodes.size(); ++i)
        if(same_node(g.nodes[i], p))
          return i;
      g.nodes.push_back(p);
      g.degree.push_back(0);
      return g.nodes.size() - 1;
    };
    for(const internal::Axis_curve& curve : curves_) {
      const std::size_t i = node_of(curve.front()), j = node_of(curve.back());
      ++g.degree[i];
      ++g.degree[j]; // a loop adds 2 to its node
      edges.emplace_back(i, j);
    }
    std::vector<std::size_t> parent(g.nodes.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&](std::size_t i) {
      while(parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    for(const auto& e : edges)
      parent[find(e.first)] = find(e.second);
    for(std::size_t i = 0; i < parent.size(); ++i)
      g.components += find(i) == i;
    return g;
  }

  std::string name_;
  Topology expected_;
  bool has_sheets_ = false;
  std::vector<internal::Primitive> primitives_;
  std::vector<internal::Axis_curve> curves_;
};

// ---------------------------------------------------------------------------------
// Shapes. Sizes are in arbitrary units, bbox diagonals between 1 and 3. The thinnest
// tube radius is >= 2.5 % of the bbox diagonal and tubes meet only at the designed
// junctions.

namespace internal {

/// `arms` directions spread over the unit sphere (Fibonacci lattice).
inline std::vector<V3> sphere_directions(int arms)
{
  std::vector<V3> dirs;
  const double golden_angle = pi * (3 - std::sqrt(5.0));
  for(int i = 0; i < arms; ++i) {
    const double z = 1 - (2 * i + 1) / double(arms);
    const double s = std::sqrt(1 - z * z);
    dirs.push_back({s * std::cos(golden_angle * i), s * std::sin(golden_angle * i), z});
  }
  return dirs;
}

inline void check_arms(int arms, const char* shape)
{
  // Beyond 16 arms, neighbouring directions get closer than ~45 degrees and the
  // tubes would stay merged over a large part of their length.
  if(arms < 3 || arms > 16)
    throw std::invalid_argument(std::string(shape) + ": the number of arms must be in [3, 16]");
}

inline std::string with_count(const std::string& name, int count, int default_count)
{
  return count == default_count ? name : name + "_" + std::to_string(count);
}

} // namespace internal

/// A single straight tapered capsule (radius 0.12 -> 0.07, length 1.1, oblique axis).
/// Topology: 2 ends, 0 junctions, 0 cycles, 1 component.
inline Shape capsule()
{
  Shape s("capsule", {2, 0, 0, 1});
  s.add_round_cone(Point_3(-0.5, -0.15, -0.1), Point_3(0.5, 0.15, 0.1), 0.12, 0.07);
  return s;
}

/// A letter Y in the plane z = 0: a stem of length 0.6 going down and two arms of
/// length 0.5 at +-45 degrees from vertical, tapered 0.085 -> 0.06.
/// Topology: 3 ends, 1 junction (degree 3), 0 cycles, 1 component.
inline Shape y_junction()
{
  Shape s("y_junction", {3, 1, 0, 1});
  const Point_3 o(0, 0, 0);
  const double c = 0.5 * std::sqrt(0.5);
  s.add_round_cone(o, Point_3(0, -0.6, 0), 0.085, 0.06);
  s.add_round_cone(o, Point_3(-c, c, 0), 0.085, 0.06);
  s.add_round_cone(o, Point_3(c, c, 0), 0.085, 0.06);
  return s;
}

/// `arms` arms of length 0.55 along directions spread over the sphere, tapered
/// 0.075 -> 0.055, all starting at the origin. `arms` in [3, 16].
/// Topology: `arms` ends, 1 junction (degree `arms`), 0 cycles, 1 component.
inline Shape star(int arms = 6)
{
  internal::check_arms(arms, "star");
  Shape s(internal::with_count("star", arms, 6), {arms, 1, 0, 1});
  for(const internal::V3& d : internal::sphere_directions(arms))
    s.add_round_cone(Point_3(0, 0, 0), internal::to_point(0.55 * d), 0.075, 0.055);
  return s;
}

/// A torus of major radius 0.5 and tube radius 0.12, its axis slightly tilted from z.
/// Topology: 0 ends, 0 junctions, 1 cycle, 1 component.
inline Shape torus()
{
  Shape s("torus", {0, 0, 1, 1});
  s.add_torus(Point_3(0, 0, 0), Vector_3(0.2, 0.1, 1), 0.5, 0.12);
  return s;
}

/// A tube of radius 0.07 along the lemniscate of Gerono x = 0.9 cos t,
/// y = 0.45 sin 2t in the plane z = 0: two loops crossing at right angles at the origin.
/// The skeleton is two loops attached at one vertex of degree 4 (a skeletoniser may
/// legitimately resolve the X crossing as two nearby degree-3 junctions).
/// Topology: 0 ends, 1 junction (degree 4), 2 cycles, 1 component.
inline Shape figure_eight()
{
  Shape s("figure_eight", {0, 1, 2, 1});
  const int segments = 80; // per loop
  for(int loop = 0; loop < 2; ++loop) {
    std::vector<Point_3> path;
    for(int i = 0; i <= segments; ++i) {
      const double t = internal::pi * (loop - 0.5 + double(i) / segments);
      // Both loops start and end exactly at the crossing point.
      path.push_back(i == 0 || i == segments ? Point_3(0, 0, 0)
                                             : Point_3(0.9 * std::cos(t), 0.45 * std::sin(2 * t), 0));
    }
    s.add_tube(path, std::vector<double>(path.size(), 0.07));
  }
  return s;
}

/// A ring (torus, major radius 0.5, tube 0.08) with a bar of the same radius along a
/// diameter: the skeleton is a theta graph, two T-junctions joined by three arcs.
/// Topology: 0 ends, 2 junctions (degree 3), 2 cycles, 1 component.
inline Shape theta()
{
  Shape s("theta", {0, 2, 2, 1});
  const Point_3 o(0, 0, 0), left(-0.5, 0, 0), right(0.5, 0, 0);
  const Vector_3 axis(0, 0, 1);
  s.add_torus(o, axis, 0.5, 0.08, false);
  s.add_axis_arc(o, axis, right, internal::pi);
  s.add_axis_arc(o, axis, left, internal::pi);
  s.add_round_cone(left, right, 0.08, 0.08);
  return s;
}

/// A humanoid in the plane z ~ 0, 2 units tall: torso (hip (0,0,0) to neck (0,0.6,0),
/// radius 0.12 -> 0.14), head (neck to (0,0.95,0), 0.06 -> 0.13), two arms from the neck
/// (0.075 -> 0.065) and two legs from the hip (0.09 -> 0.065).
/// Topology: 5 ends (head, hands, feet), 2 junctions (neck: degree 4, hip: degree 3),
/// 0 cycles, 1 component.
inline Shape stick_figure()
{
  Shape s("stick_figure", {5, 2, 0, 1});
  const Point_3 hip(0, 0, 0), neck(0, 0.6, 0);
  s.add_round_cone(hip, neck, 0.12, 0.14);
  s.add_round_cone(neck, Point_3(0, 0.95, 0), 0.06, 0.13);
  for(double side : {-1.0, 1.0}) {
    s.add_round_cone(neck, Point_3(side * 0.62, 0.42, 0.08), 0.075, 0.065);
    s.add_round_cone(hip, Point_3(side * 0.4, -0.85, 0.02), 0.09, 0.065);
  }
  return s;
}

/// A tapered tree: a trunk, two branches splitting in the x-y plane, each splitting
/// again in the plane containing z (all splits +-35 degrees, slightly asymmetric).
/// Topology: 5 ends (root, 4 tips), 3 junctions (degree 3), 0 cycles, 1 component.
inline Shape branching_tree()
{
  using internal::V3;
  Shape s("branching_tree", {5, 3, 0, 1});
  const double deg = internal::pi / 180;
  const V3 base{0, -0.6, 0}, top{0, 0, 0}, z{0, 0, 1};
  s.add_round_cone(internal::to_point(base), internal::to_point(top), 0.10, 0.085);
  const double lengths1[2] = {0.45, 0.40}, lengths2[2][2] = {{0.30, 0.27}, {0.28, 0.31}};
  for(int i = 0; i < 2; ++i) {
    const double a1 = (i == 0 ? -35 : 35) * deg;
    const V3 d1{-std::sin(a1), std::cos(a1), 0};
    const V3 fork = top + lengths1[i] * d1;
    s.add_round_cone(internal::to_point(top), internal::to_point(fork), 0.075, 0.065);
    for(int j = 0; j < 2; ++j) {
      const double a2 = (j == 0 ? -35 : 35) * deg;
      const V3 d2 = std::cos(a2) * d1 + std::sin(a2) * z;
      s.add_round_cone(internal::to_point(fork), internal::to_point(fork + lengths2[i][j] * d2), 0.06, 0.05);
    }
  }
  return s;
}

/// A tube of radius 0.06 along a helix of radius 0.35, pitch 0.3 and 2.5 turns about
/// the z axis, made of 100 short capsules.
/// Topology: 2 ends, 0 junctions, 0 cycles, 1 component.
inline Shape helix()
{
  Shape s("helix", {2, 0, 0, 1});
  const int segments = 100;
  const double turns = 2.5, pitch = 0.3;
  std::vector<Point_3> path;
  for(int i = 0; i <= segments; ++i) {
    const double angle = 2 * internal::pi * turns * i / segments;
    path.push_back(Point_3(0.35 * std::cos(angle), 0.35 * std::sin(angle), pitch * (angle / (2 * internal::pi) - turns / 2)));
  }
  s.add_tube(path, std::vector<double>(path.size(), 0.06));
  return s;
}

/// `arms` arms from the origin along directions spread over the sphere, with lengths
/// in [0.3, 0.55] and radii in [0.065, 0.085] (tapered to 85 % at the tip) that vary
/// from arm to arm. `arms` in [3, 16].
/// Topology: `arms` ends, 1 junction (degree `arms`), 0 cycles, 1 component.
inline Shape many_armed(int arms = 10)
{
  internal::check_arms(arms, "many_armed");
  Shape s(internal::with_count("many_armed", arms, 10), {arms, 1, 0, 1});
  const std::vector<internal::V3> dirs = internal::sphere_directions(arms);
  for(int i = 0; i < arms; ++i) {
    // Low-discrepancy sequences give well-spread, deterministic variety.
    const double f1 = std::fmod(0.2 + 0.618033988749895 * i, 1.0), f2 = std::fmod(0.7 + 0.754877666246693 * i, 1.0);
    const double length = 0.3 + 0.25 * f1, radius = 0.065 + 0.02 * f2;
    s.add_round_cone(Point_3(0, 0, 0), internal::to_point(length * dirs[std::size_t(i)]), radius, 0.85 * radius);
  }
  return s;
}

/// A bar of radius 0.07 from (-0.5,0,0) to (0.5,0,0) with a ball of radius 0.2
/// centred on each end: a skeleton with a strong radius change at its ends.
/// Topology: 2 ends, 0 junctions, 0 cycles, 1 component.
inline Shape dumbbell()
{
  Shape s("dumbbell", {2, 0, 0, 1});
  const Point_3 a(-0.5, 0, 0), b(0.5, 0, 0);
  s.add_round_cone(a, b, 0.07, 0.07);
  s.add_sphere(a, 0.2);
  s.add_sphere(b, 0.2);
  return s;
}

/// Two separate parts 0.3 apart: a torus (major radius 0.3, tube 0.08) and a tapered
/// capsule (0.08 -> 0.07).
/// Topology: 2 ends, 0 junctions, 1 cycle, 2 components.
inline Shape disjoint_pair()
{
  Shape s("disjoint_pair", {2, 0, 1, 2});
  s.add_torus(Point_3(-0.55, 0, 0), Vector_3(0, 0.3, 1), 0.3, 0.08);
  s.add_round_cone(Point_3(0.2, -0.4, 0), Point_3(0.6, 0.4, 0.1), 0.08, 0.07);
  return s;
}

/// All shapes with their default parameters, by name.
inline std::vector<std::pair<std::string, Shape>> all_shapes()
{
  std::vector<std::pair<std::string, Shape>> shapes;
  for(Shape s : {capsule(), y_junction(), star(), torus(), figure_eight(), theta(), stick_figure(),
                 branching_tree(), helix(), many_armed(), dumbbell(), disjoint_pair()})
    shapes.emplace_back(s.name(), s);
  return shapes;
}

/// The shape called `name` in `all_shapes()`; "star_N" and "many_armed_N" select the
/// arm count. Throws `std::invalid_argument` for an unknown name.
inline Shape shape_by_name(const std::string& name)
{
  for(const char* prefix : {"star_", "many_armed_"}) {
    const std::string p(prefix);
    if(name.size() > p.size() && name.compare(0, p.size(), p) == 0 &&
       name.find_first_not_of("0123456789", p.size()) == std::string::npos && name.size() - p.size() <= 3) {
      const int arms = std::stoi(name.substr(p.size()));
      return p == "star_" ? star(arms) : many_armed(arms);
    }
  }
  for(auto& entry : all_shapes())
    if(entry.first == name)
      return entry.second;
  throw std::invalid_argument("unknown shape '" + name + "'");
}

// ---------------------------------------------------------------------------------
// Sampling.

/// Degradations applied to a clean surface sample.
enum class Variant
{
  clean,    ///< uniform by area on the surface
  noise,    ///< clean, then Gaussian displacement of every coordinate
  outliers, ///< a fraction of the points replaced by uniform points in the enlarged bbox
  holes,    ///< no points in a few patches on one side (see `hole_side()`)
  uneven,   ///< density decreasing geometrically 10:1 along the longest bbox axis
  sparse    ///< clean with only a few points (2,000 by default)
};

inline const char* to_string(Variant v)
{
  switch(v) {
  case Variant::clean: return "clean";
  case Variant::noise: return "noise";
  case Variant::outliers: return "outliers";
  case Variant::holes: return "holes";
  case Variant::uneven: return "uneven";
  case Variant::sparse: return "sparse";
  }
  return "?";
}

inline std::vector<Variant> all_variants()
{
  return {Variant::clean, Variant::noise, Variant::outliers, Variant::holes, Variant::uneven, Variant::sparse};
}

/// The variant called `name`; throws `std::invalid_argument` for an unknown name.
inline Variant variant_by_name(const std::string& name)
{
  for(Variant v : all_variants())
    if(name == to_string(v))
      return v;
  throw std::invalid_argument("unknown variant '" + name + "'");
}

/// Parameters of the variants. Lengths are fractions of the shape's bbox diagonal.
struct Variant_options
{
  double noise_sigma = 0.01;        ///< noise: standard deviation per coordinate
  double outlier_fraction = 0.10;   ///< outliers: fraction of the n points
  double outlier_margin = 0.05;     ///< outliers: the bbox grows by this on every side
  std::size_t hole_count = 6;       ///< holes: number of patches
  double hole_radius_factor = 0.6;  ///< holes: patch radius / local tube radius
  double uneven_ratio = 10;         ///< uneven: density at the low end / at the high end
  std::size_t sparse_count = 2000;  ///< sparse: number of points (n is ignored)
  std::size_t uneven_count = 0;     ///< uneven: number of points when not 0 (n is then ignored)
};

/// A generated point cloud.
struct Sample
{
  std::vector<Point_3> points;
  /// Outward unit normal of the clean surface at each point's origin; a random unit
  /// vector for outliers.
  std::vector<Vector_3> normals;
  std::vector<bool> is_outlier;
};

namespace internal {

/// Draws points uniformly by area on the outer surface of a union of primitives:
/// area-weighted choice of a primitive patch, uniform point on it, rejected when
/// another primitive covers it.
class Surface_sampler
{
public:
  explicit Surface_sampler(const Shape& shape) : prims_(shape.primitives())
  {
    if(prims_.empty())
      throw std::invalid_argument("cannot sample a shape without primitives");
    const double diag = shape.bbox_diagonal();
    eps_ = 1e-10 * diag;
    double total = 0;
    for(std::size_t i = 0; i < prims_.size(); ++i)
      for(int k = 0; k < prims_[i].patch_count(); ++k) {
        total += prims_[i].patch_area(k);
        cumulative_.push_back(total);
        patches_.emplace_back(i, k);
      }
    // Only primitives with overlapping boxes can cover each other: this keeps the
    // rejection test short for shapes made of many small capsules.
    std::vector<CGAL::Bbox_3> boxes;
    for(const Primitive& p : prims_)
      boxes.push_back(p.bbox());
    // Nearest first: a covering neighbour is then found after few distance evaluations.
    auto centre = [&](std::size_t i) {
      return V3{(boxes[i].xmin() + boxes[i].xmax()) / 2, (boxes[i].ymin() + boxes[i].ymax()) / 2,
                (boxes[i].zmin() + boxes[i].zmax()) / 2};
    };
    neighbours_.resize(prims_.size());
    for(std::size_t i = 0; i < prims_.size(); ++i) {
      for(std::size_t j = 0; j < prims_.size(); ++j)
        if(i != j && CGAL::do_overlap(boxes[i], boxes[j]))
          neighbours_[i].push_back(j);
      std::stable_sort(neighbours_[i].begin(), neighbours_[i].end(), [&](std::size_t j, std::size_t k) {
        return norm(centre(j) - centre(i)) < norm(centre(k) - centre(i));
      });
    }
  }

  void draw(Rng& rng, V3& point, V3& normal) const
  {
    for(;;) {
      const double target = rng.uniform() * cumulative_.back();
      const std::size_t k = std::size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin());
      const auto& patch = patches_[std::min(k, patches_.size() - 1)];
      prims_[patch.first].sample_patch(patch.second, rng, point, normal);
      if(on_outer_surface(patch.first, point))
        return;
    }
  }

private:
  bool on_outer_surface(std::size_t i, const V3& p) const
  {
    for(std::size_t j : neighbours_[i]) {
      const double d = prims_[j].signed_distance(p);
      // Where surfaces coincide (equal balls at a joint), the lower index owns the
      // point, so that it is not sampled twice as densely.
      if(d < -eps_ || (j < i && d <= eps_))
        return false;
    }
    return true;
  }

  const std::vector<Primitive>& prims_;
  double eps_ = 0;
  std::vector<double> cumulative_;
  std::vector<std::pair<std::size_t, int>> patches_;
  std::vector<std::vector<std::size_t>> neighbours_;
};

} // namespace internal

/// The coordinate axis (0, 1, 2) of the largest bbox extent, along which the uneven
/// variant's density decreases (from the low end to the high end).
inline int uneven_axis(const Shape& shape)
{
  const CGAL::Bbox_3 b = shape.bbox();
  const double extent[3] = {b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()};
  return int(std::max_element(extent, extent + 3) - extent);
}

/// The unit coordinate vector whose side the holes variant carves: the axis of the
/// smallest bbox extent. Tubes lie across it, so each tube shows a face towards it
/// and a hole there is one-sided (a fixed +x would only hit the tips of an x-aligned
/// capsule).
inline Vector_3 hole_side(const Shape& shape)
{
  const CGAL::Bbox_3 b = shape.bbox();
  const double extent[3] = {b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()};
  const int axis = int(std::min_element(extent, extent + 3) - extent);
  return Vector_3(axis == 0, axis == 1, axis == 2);
}

/// Samples `n` points of `shape` degraded by `variant` (see `Variant_options` for the
/// parameters); deterministic for a seed. Every variant returns exactly `n` points,
/// except `sparse` (always `options.sparse_count`). `outliers` holds
/// round(fraction * n) outliers shuffled among the surface points; `holes` and
/// `uneven` reject surface points until `n` are kept. The clean, noise and outliers
/// variants share their surface points for a seed (noise displaces them, outliers
/// replace the last ones), so that their differences come from the degradation alone.
inline Sample make_sample(const Shape& shape, Variant variant, std::size_t n, std::uint64_t seed,
                          const Variant_options& options = {})
{
  using internal::V3;
  const internal::Surface_sampler sampler(shape);
  internal::Rng surface_rng(internal::mix_seed(seed, 0));
  internal::Rng variant_rng(internal::mix_seed(seed, 1 + std::uint64_t(variant)));
  const double diag = shape.bbox_diagonal();
  const CGAL::Bbox_3 box = shape.bbox();

  if(variant == Variant::sparse)
    n = options.sparse_count;
  if(variant == Variant::uneven && options.uneven_count)
    n = options.uneven_count;
  std::size_t outliers = 0;
  if(variant == Variant::outliers)
    outliers = std::min(n, std::size_t(std::llround(options.outlier_fraction * double(n))));

  // Holes: centres on the surface facing hole_side(), spread apart, radius from the
  // local tube. A patch only takes points facing roughly like its centre (within 60
  // degrees), so that near a junction it cannot bite into the wall of another arm.
  struct Hole
  {
    V3 centre, normal;
    double radius;
  };
  std::vector<Hole> holes;
  const V3 side = internal::to_v3(hole_side(shape));
  if(variant == Variant::holes)
    for(std::size_t attempt = 0; holes.size() < options.hole_count && attempt < 1000 * options.hole_count; ++attempt) {
      V3 c, nc;
      sampler.draw(variant_rng, c, nc);
      if(dot(nc, side) < 0.7) // within 45 degrees
        continue;
      const double r = options.hole_radius_factor * shape.radius_at_nearest_axis_point(internal::to_point(c));
      if(std::all_of(holes.begin(), holes.end(), [&](const Hole& h) { return norm(h.centre - c) > 2 * (r + h.radius); }))
        holes.push_back({c, nc, r});
    }
  auto in_hole = [&](const V3& p, const V3& nrm) {
    return std::any_of(holes.begin(), holes.end(),
                       [&](const Hole& h) { return norm(p - h.centre) < h.radius && dot(nrm, h.normal) > 0.5; });
  };

  // Uneven: keep probability ratio^-t, t in [0, 1] along the longest bbox axis (a
  // geometric decay: equal density ratios over equal lengths).
  const int axis = uneven_axis(shape);
  const double low = box.min(axis), extent = box.max(axis) - low;
  auto keep_probability = [&](const V3& p) {
    const double coordinate = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
    return std::pow(options.uneven_ratio, -(coordinate - low) / extent);
  };
  const double sigma = options.noise_sigma * diag;

  Sample sample;
  sample.points.reserve(n);
  sample.normals.reserve(n);
  while(sample.points.size() < n - outliers) {
    V3 p, nrm;
    sampler.draw(surface_rng, p, nrm);
    if(variant == Variant::holes && in_hole(p, nrm))
      continue;
    if(variant == Variant::uneven && variant_rng.uniform() >= keep_probability(p))
      continue;
    if(variant == Variant::noise) {
      const double dx = variant_rng.normal(), dy = variant_rng.normal(), dz = variant_rng.normal();
      p = p + sigma * V3{dx, dy, dz};
    }
    sample.points.push_back(internal::to_point(p));
    sample.normals.push_back(internal::to_vector(nrm));
  }
  sample.is_outlier.assign(sample.points.size(), false);

  if(outliers > 0) {
    const double m = options.outlier_margin * diag;
    for(std::size_t i = 0; i < outliers; ++i) {
      const double x = variant_rng.uniform(box.xmin() - m, box.xmax() + m);
      const double y = variant_rng.uniform(box.ymin() - m, box.ymax() + m);
      const double z = variant_rng.uniform(box.zmin() - m, box.zmax() + m);
      sample.points.push_back(Point_3(x, y, z));
      sample.normals.push_back(internal::to_vector(variant_rng.unit_vector()));
      sample.is_outlier.push_back(true);
    }
    // Fisher-Yates with our own index draw (std::shuffle's algorithm is unspecified).
    for(std::size_t i = sample.points.size(); i > 1; --i) {
      const std::size_t j = variant_rng.index(i);
      std::swap(sample.points[i - 1], sample.points[j]);
      std::swap(sample.normals[i - 1], sample.normals[j]);
      const bool flag = sample.is_outlier[i - 1];
      sample.is_outlier[i - 1] = sample.is_outlier[j];
      sample.is_outlier[j] = flag;
    }
  }
  return sample;
}

/// Writes one "x y z" line per point with 17 significant digits (exact round trip).
/// Throws `std::runtime_error` when the file cannot be written.
inline void write_xyz(const std::string& path, const std::vector<Point_3>& points)
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot open '" + path + "' for writing");
  out << std::setprecision(17);
  for(const Point_3& p : points)
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  out.close();
  if(!out)
    throw std::runtime_error("cannot write '" + path + "'");
}

/// Same, with the normal after each point ("x y z nx ny nz").
inline void write_xyz(const std::string& path, const std::vector<Point_3>& points, const std::vector<Vector_3>& normals)
{
  if(normals.size() != points.size())
    throw std::invalid_argument("write_xyz: one normal per point expected");
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot open '" + path + "' for writing");
  out << std::setprecision(17);
  for(std::size_t i = 0; i < points.size(); ++i)
    out << points[i].x() << ' ' << points[i].y() << ' ' << points[i].z() << ' ' << normals[i].x() << ' '
        << normals[i].y() << ' ' << normals[i].z() << '\n';
  out.close();
  if(!out)
    throw std::runtime_error("cannot write '" + path + "'");
}

} // namespace DF_L1_test

#endif // DF_L1_TEST_SUPPORT_SYNTHETIC_SHAPES_H
