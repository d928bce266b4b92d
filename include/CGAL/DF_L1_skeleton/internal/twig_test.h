// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_TWIG_TEST_H
#define CGAL_DF_L1_SKELETON_INTERNAL_TWIG_TEST_H

#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/internal/vec3.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Whether the points surround a curve as the surface of a tube surrounds its axis: a
// twig, not a bump of a ragged surface (which has points on one side only). `curve` runs
// from the graph to the tip, with the local radius of each of its points. Each point of
// the curve looks at the points in a slab one voxel thick across the curve: within its
// radius plus 1.5 voxels, it counts the sectors (of 8 around the curve) that hold one of
// them at least a quarter voxel off the curve; out to twice that distance, whether the
// points are a tube (few lie beyond) or a sheet crossed by the curve (the ragged shell of
// a noisy part, which surrounds a curve through it as well). The curve is surrounded
// when, at more than half of its points, 6 sectors or more are held, at most a quarter as
// many points lie beyond as within, and those within lie `min_radius` or more from the
// curve on average (a tube thinner than the noise is a clump of it).
inline bool points_surround_curve(const std::vector<Vec3>& curve, const std::vector<double>& radius,
                                  const std::vector<Vec3>& xyz, const Uniform_grid& grid, double voxel, double min_radius)
{
  const std::size_t n = curve.size();
  const double pi = 3.14159265358979323846;
  std::size_t tested = 0, surrounded = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vec3 d = normalized(curve[i + 2 < n ? i + 2 : n - 1] - curve[i >= 2 ? i - 2 : 0]);
    if(!(dot(d, d) > 0.5))
      continue;
    // a frame across the curve
    const Vec3 helper = std::abs(d[0]) < 0.9 ? Vec3{{1, 0, 0}} : Vec3{{0, 1, 0}};
    const Vec3 u = normalized(cross(d, helper)), v = cross(d, u);
    const double inner = radius[i] + 1.5 * voxel, outer = 2 * inner;
    unsigned int sectors = 0;
    std::size_t near = 0, far = 0;
    double radial_sum = 0;
    grid.for_each_in_ball(curve[i], outer, [&](std::size_t j, double) {
      const Vec3 x = xyz[j] - curve[i];
      const double a = dot(x, d);
      if(std::abs(a) > 0.5 * voxel)
        return true;
      const double pu = dot(x, u), pv = dot(x, v), across = pu * pu + pv * pv;
      if(across > inner * inner)
      {
        ++far;
        return true;
      }
      ++near;
      radial_sum += std::sqrt(across);
      if(across >= 0.0625 * voxel * voxel)
        sectors |= 1u << (int(std::floor((std::atan2(pv, pu) + pi) / (2 * pi) * 8)) & 7);
      return true;
    });
    int held = 0;
    for(int s = 0; s < 8; ++s)
      held += (sectors >> s) & 1u;
    ++tested;
    surrounded += held >= 6 && 4 * far <= near && radial_sum >= min_radius * double(near);
  }
  return 2 * surrounded > tested;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_TWIG_TEST_H
