// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_DENOISE_POINT_SET_H
#define CGAL_DF_L1_SKELETON_DENOISE_POINT_SET_H

/// \file denoise_point_set.h
/// Stage 0b: the surface noise of the cloud, and points smoothed onto local quadrics.

#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// A quadric z = a x^2 + b xy + c y^2 + d x + e y + f fitted by least squares to the k
// nearest neighbours of a point, in the frame of their principal axes (z along the
// smallest one): jet fitting of order 2, as CGAL's jet_smooth_point_set() does. A plane
// would do for the noise but not for a thin part, whose curvature across a neighbourhood
// of 24 sparse samples looks like noise to a plane (measured: up to 0.7 voxel of
// deviation on 2,000-point samples, as much as 1 % noise on 20,000 points).
template <class Traits>
class Local_quadric_fitter
{
  typedef typename Traits::Point_3 Point_3;

public:
  struct Fit
  {
    Eigen::Vector3d projection; // the point moved onto the quadric, along the local normal
    double residual = 0;        // RMS distance of the neighbours to the quadric, along the normal
    bool valid = false;         // false when the neighbours are too few or degenerate
  };

  // The arrays of a fit, kept from one fit to the next: allocating them for every point
  // cost about a tenth of the denoising.
  struct Workspace
  {
    std::vector<std::pair<double, std::size_t>> nearest;
    std::vector<Eigen::Vector3d> q;
    Eigen::MatrixXd a;
    Eigen::VectorXd z, c, r; // c: the coefficients, r: the residuals
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  };

  // Calls f(q, fit to the k nearest neighbours of point(q)) for q = 0, ..., n - 1, in
  // blocks of 64 that share a workspace (in parallel with Parallel_tag).
  template <class ConcurrencyTag, class Point, class F>
  void for_each_fit(std::size_t n, unsigned int k, const Point& point, const F& f) const
  {
    const std::size_t block = 64;
    for_each_index<ConcurrencyTag>((n + block - 1) / block, [&](std::size_t b) {
      Workspace w;
      for(std::size_t q = b * block; q < (std::min)(n, (b + 1) * block); ++q)
        f(q, fit(point(q), k, w));
    }, 1);
  }

  // The number of neighbours is given to each fit, so that the noise estimate and the
  // smoothing share the grid (building it took 6 ms of sequential work on 35,000 points).
  explicit Local_quadric_fitter(const std::vector<Point_3>& points)
    : xyz_(to_xyz(points, CGAL::Identity_property_map<Point_3>())), grid_(xyz_, 0)
  {
  }

  std::size_t size() const { return xyz_.size(); }

  // The points in an order that keeps consecutive fits' searches in the same cells.
  const std::vector<std::size_t>& spatial_order() const { return grid_.indices_by_cell(); }

  Fit fit(std::size_t i, unsigned int k, Workspace& w) const
  {
    Fit result;
    std::vector<std::pair<double, std::size_t>>& nearest = w.nearest; // the point itself first
    grid_.k_nearest(xyz_[i], k, [](std::size_t) { return true; }, nearest);
    std::vector<Eigen::Vector3d>& q = w.q;
    q.clear();
    for(const auto& neighbour : nearest)
      q.emplace_back(xyz_[neighbour.second][0], xyz_[neighbour.second][1], xyz_[neighbour.second][2]);
    const Eigen::Vector3d self(xyz_[i][0], xyz_[i][1], xyz_[i][2]);
    result.projection = self;
    const int m = int(q.size());
    if(m < 10) // well over the 6 coefficients, so that the residual measures the noise
      return result;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for(const Eigen::Vector3d& p : q)
      centre += p;
    centre /= m;
    // entry by entry: the outer products of Eigen went through the stack (a tenth of a fit)
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const Eigen::Vector3d& p : q)
    {
      const Eigen::Vector3d d = p - centre;
      for(int r = 0; r < 3; ++r)
        for(int s = 0; s < 3; ++s)
          covariance(r, s) += d[r] * d[s];
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    if(!(eigen.eigenvalues()[1] > 0))
      return result; // collinear neighbours: no surface to fit
    const Eigen::Matrix3d frame = eigen.eigenvectors(); // columns: normal, then the two tangents
    Eigen::MatrixXd& a = w.a;
    Eigen::VectorXd& z = w.z;
    a.resize(m, 6);
    z.resize(m);
    for(int j = 0; j < m; ++j)
    {
      const Eigen::Vector3d l = frame.transpose() * (q[j] - centre);
      a(j, 0) = l[1] * l[1];
      a(j, 1) = l[1] * l[2];
      a(j, 2) = l[2] * l[2];
      a(j, 3) = l[1];
      a(j, 4) = l[2];
      a(j, 5) = 1;
      z[j] = l[0];
    }
    Eigen::VectorXd& c = w.c;
    c = w.qr.compute(a).solve(z);
    if(!c.allFinite())
      return result;
    w.r.noalias() = a * c;
    w.r -= z;
    result.residual = std::sqrt(w.r.squaredNorm() / m);
    const Eigen::Vector3d l = frame.transpose() * (self - centre);
    const double on_quadric = c[0] * l[1] * l[1] + c[1] * l[1] * l[2] + c[2] * l[2] * l[2] + c[3] * l[1] + c[4] * l[2] + c[5];
    result.projection = self + (on_quadric - l[0]) * frame.col(0);
    result.valid = result.projection.allFinite();
    if(!result.valid)
      result.projection = self;
    return result;
  }

private:
  std::vector<std::array<double, 3>> xyz_;
  Uniform_grid grid_; // cells for k-nearest searches
};

template <class PointRange, class PointMap>
std::vector<typename boost::property_traits<PointMap>::value_type> copy_points(const PointRange& points,
                                                                               const PointMap& point_map)
{
  std::vector<typename boost::property_traits<PointMap>::value_type> xyz;
  for(const auto& value : points)
    xyz.push_back(get(point_map, value));
  return xyz;
}

// The noise estimate of estimate_surface_noise(), from a fitter of the points: the
// median residual of the fits to the k nearest neighbours.
template <class ConcurrencyTag, class Traits>
double surface_noise(const Local_quadric_fitter<Traits>& fitter, unsigned int k = 16, std::size_t fits = 2000)
{
  const std::size_t size = fitter.size();
  if(size < k)
    return 0;
  const std::size_t n = (std::min)(size, fits);
  std::vector<double> residual(n, -1);
  fitter.template for_each_fit<ConcurrencyTag>(n, k, [&](std::size_t s) { return s * size / n; },
                                                [&](std::size_t s, const auto& fit) {
                                                  if(fit.valid)
                                                    residual[s] = fit.residual;
                                                });
  residual.erase(std::remove(residual.begin(), residual.end(), -1.0), residual.end());
  if(residual.empty())
    return 0;
  std::nth_element(residual.begin(), residual.begin() + residual.size() / 2, residual.end());
  return residual[residual.size() / 2];
}

// How the residual of the fits grows from 10 to 40 neighbours: about 2 on a noisy
// surface (the noise is the same at both scales; a fit to fewer points follows more of
// it), 3.3 and more where the neighbourhoods span parts thinner than themselves (the
// twigs of a LiDAR crown, a sparse sample of thin limbs), whose residual is the parts'
// curvature and thickness, not noise. 0 when either residual is 0. The medians over
// 1,000 fits each keep the cost at a few milliseconds.
template <class ConcurrencyTag, class Traits>
double residual_growth(const Local_quadric_fitter<Traits>& fitter)
{
  const double fine = surface_noise<ConcurrencyTag>(fitter, 10, 1000), coarse = surface_noise<ConcurrencyTag>(fitter, 40, 1000);
  return fine > 0 && coarse > 0 ? coarse / fine : 0;
}

// The points smoothed as denoise_point_set() does, from a fitter of these points.
template <class ConcurrencyTag, class Traits>
std::vector<typename Traits::Point_3> smoothed_points(const Local_quadric_fitter<Traits>& fitter,
                                                      const std::vector<typename Traits::Point_3>& points,
                                                      unsigned int k)
{
  typedef typename Traits::Point_3 Point_3;
  std::vector<Point_3> smoothed = points;
  if(points.size() < 10)
    return smoothed;
  const std::vector<std::size_t>& order = fitter.spatial_order();
  fitter.template for_each_fit<ConcurrencyTag>(points.size(), k, [&](std::size_t q) { return order[q]; },
                                                [&](std::size_t q, const auto& fit) {
                                                  if(fit.valid)
                                                    smoothed[order[q]] = Point_3(fit.projection[0], fit.projection[1], fit.projection[2]);
                                                });
  return smoothed;
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Estimates the noise of the sampled surface: the median, over up to 2,000 points taken
/// at a regular stride, of the RMS distance of their 16 nearest neighbours to the
/// quadric fitted to them (along its normal). A clean sample of a smooth surface gives
/// nearly 0 however sparse, because the quadric follows the curvature: at most 0.09 voxel
/// (V = 100) on our synthetic shapes, clean, sparse (2,000 points), with holes, uneven or
/// with outliers, and 0.01 to 0.04 voxel on the camel, woman, fertility and tree scans.
/// Noise gives a fraction of its RMS, as the fit follows part of it (0.40 to 0.75 voxel
/// for the 1 % noise of our tests, about 1 voxel on the noisy dinosaur and bunny scans).
/// More neighbours would see more of the noise but also the curvature of thin sparse
/// parts (24 neighbours: 0.31 voxel on the sparse helix).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \param points the points (outliers removed: they are no surface)
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of
///       the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the noise estimate, in input units (0 for fewer than 16 points)
/// \throws Invalid_input if a point is not finite
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange,
          class NamedParameters = parameters::Default_named_parameters>
double estimate_surface_noise(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Traits;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  internal::checked_bbox(points, point_map, "noise estimate");
  const auto xyz = internal::copy_points(points, point_map);
  return internal::surface_noise<ConcurrencyTag>(internal::Local_quadric_fitter<Traits>(xyz));
}

/// \ingroup PkgDFL1SkeletonRef
/// Moves every point onto the quadric fitted to its k nearest neighbours, along the
/// local normal (jet smoothing of order 2; the positions are read from the input, so
/// the result does not depend on the order or the threads).
///
/// The paper pre-filters noisy clouds with LOP. Noise of 1 % of the bounding-box
/// diagonal is more than a voxel at V = 100: the boundary shell gets several voxels
/// thick, parts thinner than the noise lose their interior and the thinning grows spurs
/// into the ragged shell. One pass of this smoothing brings the points about a third
/// closer to the surface and raised the noisy cases with the designed topology from 5 to
/// 10 of 12 in our tests (20,000 points, 12 shapes); on clean clouds it is not needed,
/// and it rounds the thin parts of sparse ones, so `DF_L1_skeletonization` applies it
/// only when `estimate_surface_noise()` finds noise (named parameter `denoising`).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \param points the points (outliers removed)
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of
///       the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{denoising_neighbors}
///     \cgalParamDescription{k, the neighbours of the quadric fitted at each point}
///     \cgalParamType{`int`, in [6, 256]}
///     \cgalParamDefault{24}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the smoothed points, in the order of `points`
/// \throws Invalid_input if a point is not finite or `denoising_neighbors` is out of range
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange,
          class NamedParameters = parameters::Default_named_parameters>
std::vector<typename Point_set_processing_3_np_helper<const PointRange, NamedParameters>::Geom_traits::Point_3>
denoise_point_set(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Traits;
  typedef typename Traits::Point_3 Point_3;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  const unsigned int k = internal::denoising_neighbors(np, "denoising");
  internal::checked_bbox(points, point_map, "denoising");
  const std::vector<Point_3> xyz = internal::copy_points(points, point_map);
  if(xyz.size() < 10)
    return xyz;
  return internal::smoothed_points<ConcurrencyTag>(internal::Local_quadric_fitter<Traits>(xyz), xyz, k);
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_DENOISE_POINT_SET_H
