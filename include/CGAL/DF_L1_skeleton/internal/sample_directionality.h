// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_SAMPLE_DIRECTIONALITY_H
#define CGAL_DF_L1_SKELETON_INTERNAL_SAMPLE_DIRECTIONALITY_H

#include <CGAL/DF_L1_skeleton/internal/l1_median_iteration.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// How line-like the samples around each sample are: sigma = lambda_max / (l1 + l2 + l3)
// of their theta-weighted covariance within the sample's support radius (1/3 for a
// blob, 1 on a line), and the principal direction. Then sigma is smoothed over the 6
// nearest samples that are not removed, as in the L1-medial method, so that one noisy
// sample neither starts nor stops a branch. A sample with fewer than 3 neighbours gets
// sigma = 0.95 (L1-medial's rule: isolated samples are on thin parts).
struct Directionality
{
  std::vector<double> sigma;      // smoothed
  std::vector<Vec3> direction;    // unit principal direction
};

template <class ConcurrencyTag>
Directionality compute_directionality(const std::vector<Vec3>& samples, const std::vector<char>& active,
                                      const std::vector<double>& radius, const Uniform_grid& grid)
{
  const std::size_t m = samples.size();
  Directionality d;
  std::vector<double> raw(m, 0);
  d.sigma.assign(m, 0);
  d.direction.assign(m, Vec3{{1, 0, 0}});
  for_each_index<ConcurrencyTag>(m, [&](std::size_t i) {
    if(!active[i])
      return;
    const double h = radius[i], inv = 4 / (h * h);
    double total = 0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    int count = 0;
    grid.for_each_in_ball(samples[i], h, [&](std::size_t j, double d2) {
      if(!active[j])
        return true;
      const double w = std::exp(-d2 * inv);
      const Eigen::Vector3d p(samples[j][0] - samples[i][0], samples[j][1] - samples[i][1], samples[j][2] - samples[i][2]);
      const Eigen::Vector3d wp = w * p;
      total += w;
      mean += wp;
      // entry by entry: Eigen's 3x3 outer product went through the stack at each sample
      for(int r = 0; r < 3; ++r)
        for(int c = 0; c < 3; ++c)
          second(r, c) += wp[r] * p[c];
      ++count;
      return true;
    });
    if(count < 4) // the sample itself and fewer than 3 others
    {
      raw[i] = 0.95;
      return;
    }
    mean /= total;
    const Eigen::Matrix3d covariance = second / total - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    const Eigen::Vector3d l = solver.eigenvalues().cwiseMax(0.0);
    const double sum = l.sum();
    raw[i] = sum > 0 ? l(2) / sum : 1.0 / 3;
    const Eigen::Vector3d e = solver.eigenvectors().col(2);
    d.direction[i] = normalized(Vec3{{e(0), e(1), e(2)}});
  });
  for_each_range<ConcurrencyTag>(m, [&](std::size_t begin, std::size_t end) {
    std::vector<std::pair<double, std::size_t>> near; // shared by the searches of the range
    for(std::size_t i = begin; i < end; ++i)
    {
      if(!active[i])
        continue;
      // the 6 nearest within the support radius (a k-nearest search: once the radii have
      // grown, the ball holds most of the samples)
      grid.k_nearest(samples[i], 6, [&](std::size_t j) { return active[j] && j != i; }, near);
      const double r2 = radius[i] * radius[i];
      while(!near.empty() && near.back().first > r2)
        near.pop_back();
      double s = raw[i];
      for(const auto& neighbour : near)
        s += raw[neighbour.second];
      d.sigma[i] = s / double(near.size() + 1);
    }
  });
  return d;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_SAMPLE_DIRECTIONALITY_H
