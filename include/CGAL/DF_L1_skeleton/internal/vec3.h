// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VEC3_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VEC3_H

/// \file vec3.h
/// The vector of three doubles in which the contraction and the skeleton graph compute,
/// whatever the kernel's number type, and its arithmetic. Not part of the public API.

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>

namespace CGAL {
namespace DF_L1 {
namespace internal {

typedef std::array<double, 3> Vec3;

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline Vec3 operator*(double s, const Vec3& a) { return {{s * a[0], s * a[1], s * a[2]}}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }
inline Vec3 normalized(const Vec3& a)
{
  const double n = norm(a);
  return n > 0 ? (1 / n) * a : Vec3{{0, 0, 0}};
}
template <class Point_3>
Vec3 to_vec3(const Point_3& p)
{
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VEC3_H
