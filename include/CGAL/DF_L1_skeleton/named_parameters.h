// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_NAMED_PARAMETERS_H
#define CGAL_DF_L1_SKELETON_NAMED_PARAMETERS_H

/// \file named_parameters.h
/// The package's own named parameters, next to CGAL's (`point_map`, `geom_traits`,
/// `random_seed`, `callback`...).
///
/// CGAL 5.5 offers no way for a package outside CGAL to add chainable member
/// functions to `CGAL::Named_function_parameters`, so each of our parameters is a
/// free function in `CGAL::parameters` with an optional last argument: the list
/// to extend. Both forms build ordinary CGAL named parameters:
/// \code
/// namespace params = CGAL::parameters;
/// auto np = params::voxel_resolution(64, params::point_map(pmap));
/// auto np2 = params::thinning_coefficient(0.8, params::voxel_resolution(64));
/// \endcode

#include <CGAL/DF_L1_skeleton/errors.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace CGAL {
namespace internal_np {
enum df_l1_voxel_resolution_t { df_l1_voxel_resolution };
enum df_l1_initial_voxel_size_t { df_l1_initial_voxel_size };
enum df_l1_exterior_propagation_t { df_l1_exterior_propagation };
enum df_l1_upsampling_t { df_l1_upsampling };
enum df_l1_upsampling_neighbors_t { df_l1_upsampling_neighbors };
enum df_l1_upsampling_radius_t { df_l1_upsampling_radius };
enum df_l1_thinning_coefficient_t { df_l1_thinning_coefficient };
enum df_l1_outlier_component_size_t { df_l1_outlier_component_size };
enum df_l1_spur_length_t { df_l1_spur_length };
enum df_l1_method_t { df_l1_method };
enum df_l1_repulsion_t { df_l1_repulsion };
enum df_l1_support_radius_t { df_l1_support_radius };
enum df_l1_support_radius_growth_t { df_l1_support_radius_growth };
enum df_l1_branch_directionality_t { df_l1_branch_directionality };
enum df_l1_contraction_stages_t { df_l1_contraction_stages };
enum df_l1_denoising_t { df_l1_denoising };
enum df_l1_denoising_neighbors_t { df_l1_denoising_neighbors };
enum df_l1_thin_parts_t { df_l1_thin_parts };
enum df_l1_occupied_depth_t { df_l1_occupied_depth };
enum df_l1_open_crotches_t { df_l1_open_crotches };
enum df_l1_surface_noise_t { df_l1_surface_noise };
} // namespace internal_np

namespace parameters {

#define CGAL_DF_L1_ADD_NAMED_PARAMETER(TAG, NAME)                                         \
  template <class K>                                                                      \
  Named_function_parameters<K, internal_np::TAG##_t> NAME(const K& k)                     \
  {                                                                                       \
    return Named_function_parameters<K, internal_np::TAG##_t>(k);                         \
  }                                                                                       \
  template <class K, class T, class Tag, class Base>                                      \
  Named_function_parameters<K, internal_np::TAG##_t, Named_function_parameters<T, Tag, Base>> \
  NAME(const K& k, const Named_function_parameters<T, Tag, Base>& np)                     \
  {                                                                                       \
    return Named_function_parameters<K, internal_np::TAG##_t,                             \
                                     Named_function_parameters<T, Tag, Base>>(k, np);     \
  }

/// \ingroup PkgDFL1SkeletonNamedParameters
/// V, the number of voxels along the longest side of the finest voxel grid (default 100).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_voxel_resolution, voxel_resolution)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// s0, the voxel size of the coarsest grid before it is rounded to a power-of-3
/// multiple of the finest voxel size (default: d_bb / 9).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_initial_voxel_size, initial_voxel_size)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// How many 26-neighbour steps the exterior label may spread through the empty
/// sub-voxels of a boundary voxel at each refinement level (default 1, the paper's rule).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_exterior_propagation, exterior_propagation_steps)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Whether sparse regions are upsampled before voxelization (default `true`).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_upsampling, upsampling)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// k, the number of neighbours that defines the local density k / r^3 (default 5).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_upsampling_neighbors, upsampling_neighbors)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// r, the radius of the density test (default 3 d_bb / cbrt(N)).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_upsampling_radius, upsampling_radius)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// c, the thinning coefficient of Eq. 2 (default 0.86).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_thinning_coefficient, thinning_coefficient)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Occupied voxel components without interior voxels and at most this many voxels are
/// outliers (default: derived from the grid, see `remove_outlier_voxels()`).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_outlier_component_size, outlier_component_size)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Terminal branches of the initial skeleton shorter than this many times the local
/// radius at their junction are pruned (default 1).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_spur_length, spur_length_ratio)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Whether the initial skeleton's curves enter the parts thinner than two voxels, that
/// have no skeleton voxel (default `true`; `DF_L1_skeletonization` turns it off for
/// smoothed noisy clouds, whose ragged shell cannot be told from a thin part).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_thin_parts, thin_parts)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Whether the initial skeleton measures depth in the occupied voxels (the distance to
/// the nearest unoccupied voxel, less one) instead of reading the distance field
/// (default `false`; `DF_L1_skeletonization` turns it on for smoothed noisy clouds, whose
/// boundary shell is several voxels thick and leaves thin limbs no interior voxel two
/// deep). `thin_parts` is then moot: the occupied voxels hold the thin parts.
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_occupied_depth, occupied_depth)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The noise of the sampled surface, in input units, as `estimate_surface_noise()` gives
/// it (default 0; `DF_L1_skeletonization` passes its estimate): the initial skeleton's
/// spur pruning takes a branch for hair when it rises less than twice that above the
/// rest, on top of its slack in voxels.
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_surface_noise, surface_noise)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Whether the voxelization opens the interior voxels that see the exterior along 10 or
/// more of the 26 grid directions: the crotches between close parts, narrower than the
/// sweeping balls (default `true`; `DF_L1_skeletonization` turns it off for smoothed
/// noisy clouds, whose ragged shell lets the lines into the surface layer).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_open_crotches, open_crotches)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The refinement method, a `CGAL::DF_L1::Skeletonization_method` (default
/// `DISTANCE_FIELD_GUIDED`; `L1_MEDIAL` switches the guidance off, as a baseline).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_method, skeletonization_method)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// u, the weight of the repulsion between samples in Eq. 8, in [0, 0.5) (default 0.35).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_repulsion, repulsion_coefficient)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// h0, the initial support radius of the contraction (default 2 d_bb / cbrt(N), the paper's).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_support_radius, initial_support_radius)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The growth ratio of the support radius between stages, h <- (1 + ratio) h (default 0.5).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_support_radius_growth, support_radius_growth)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The directionality sigma above which a sample may become a branch point (default 0.9).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_branch_directionality, branch_directionality)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The maximum number of support-radius stages of the contraction, in [1, 64] (default
/// 64: the contraction runs until its own stopping rule).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_contraction_stages, contraction_stages)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// When the points are smoothed before voxelization, a `CGAL::DF_L1::Denoising`
/// (default `AUTOMATIC`: when the estimated surface noise exceeds a fifth of a voxel).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_denoising, denoising)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// k, the number of nearest neighbours to which the local quadrics of the smoothing are
/// fitted (default 24).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_denoising_neighbors, denoising_neighbors)

#undef CGAL_DF_L1_ADD_NAMED_PARAMETER

} // namespace parameters

namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The refinement method (named parameter `skeletonization_method`).
enum class Skeletonization_method
{
  /// the paper's method: samples attracted to the initial skeleton, never moving to a
  /// voxel of smaller distance value, adaptive support radius, inside-only bridges
  DISTANCE_FIELD_GUIDED,
  /// the plain L1-medial skeleton (Huang et al. 2013): the same engine with the guidance
  /// off and a global support radius growing by stages
  L1_MEDIAL
};

/// \ingroup PkgDFL1SkeletonRef
/// When the points are smoothed before voxelization (named parameter `denoising`).
enum class Denoising
{
  /// when `estimate_surface_noise()` exceeds a fifth of the finest voxel size
  AUTOMATIC,
  /// always
  ALWAYS,
  /// never
  NEVER
};

namespace internal {

// Each parameter has one default and one range, read here by the stage that uses it and
// by DF_L1_skeletonization; `stage` names the caller in the error message.

// V is read by several stages (upsampling spacing, voxelization).
template <class NamedParameters>
int voxel_resolution(const NamedParameters& np, const char* stage)
{
  const int V = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_voxel_resolution), 100);
  if(V < 3 || V > 2048)
    throw Invalid_input(std::string(stage) + ": voxel_resolution must be in [3, 2048], got " + std::to_string(V));
  return V;
}

inline double check_initial_voxel_size(double s0, const char* stage)
{
  if(!(s0 > 0) || !std::isfinite(s0))
    throw Invalid_input(std::string(stage) + ": initial_voxel_size must be positive and finite");
  return s0;
}

// s0, default d_bb / 9 (the paper).
template <class NamedParameters>
double initial_voxel_size(const NamedParameters& np, double diagonal, const char* stage)
{
  return check_initial_voxel_size(
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_initial_voxel_size), diagonal / 9), stage);
}

template <class NamedParameters>
int exterior_propagation_steps(const NamedParameters& np, const char* stage)
{
  const int steps = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_exterior_propagation), 1);
  if(steps < 1 || steps > 27)
    throw Invalid_input(std::string(stage) + ": exterior_propagation_steps must be in [1, 27]");
  return steps;
}

template <class NamedParameters>
int upsampling_neighbors(const NamedParameters& np, const char* stage)
{
  const int k = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_upsampling_neighbors), 5);
  if(k < 1 || k > 64)
    throw Invalid_input(std::string(stage) + ": upsampling_neighbors must be in [1, 64], got " + std::to_string(k));
  return k;
}

inline double check_upsampling_radius(double r, const char* stage)
{
  if(!(r > 0) || !std::isfinite(r))
    throw Invalid_input(std::string(stage) + ": upsampling_radius must be positive and finite");
  return r;
}

// r of the density test, default 3 d_bb / cbrt(N) for N points.
template <class NamedParameters>
double upsampling_radius(const NamedParameters& np, double diagonal, std::size_t n, const char* stage)
{
  return check_upsampling_radius(
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_upsampling_radius),
                                 3 * diagonal / std::cbrt(double(n))),
    stage);
}

inline int check_outlier_component_size(int voxels, const char* stage)
{
  if(voxels < 0)
    throw Invalid_input(std::string(stage) + ": outlier_component_size must not be negative");
  return voxels;
}

// Default max(3, V/10), V the longest side of the grid in voxels.
template <class NamedParameters>
int outlier_component_size(const NamedParameters& np, const std::array<int, 3>& dims, const char* stage)
{
  const int longest = (std::max)({dims[0], dims[1], dims[2]});
  return check_outlier_component_size(
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_outlier_component_size),
                                 (std::max)(3, longest / 10)),
    stage);
}

template <class NamedParameters>
double thinning_coefficient(const NamedParameters& np, const char* stage)
{
  const double c = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_thinning_coefficient), 0.86);
  if(!(c > 0 && c <= 10))
    throw Invalid_input(std::string(stage) + ": thinning_coefficient must be in (0, 10]");
  return c;
}

inline double non_negative(double value, const char* name, const char* stage)
{
  if(!(value >= 0) || !std::isfinite(value))
    throw Invalid_input(std::string(stage) + ": " + name + " must be a non-negative number");
  return value;
}

template <class NamedParameters>
double spur_length_ratio(const NamedParameters& np, const char* stage)
{
  return non_negative(parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_spur_length), 1.0),
                      "spur_length_ratio", stage);
}

template <class NamedParameters>
double surface_noise(const NamedParameters& np, const char* stage)
{
  return non_negative(parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_surface_noise), 0.0),
                      "surface_noise", stage);
}

template <class NamedParameters>
Skeletonization_method skeletonization_method(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_method),
                                      Skeletonization_method::DISTANCE_FIELD_GUIDED);
}

template <class NamedParameters>
Denoising denoising(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_denoising), Denoising::AUTOMATIC);
}

template <class NamedParameters>
unsigned int denoising_neighbors(const NamedParameters& np, const char* stage)
{
  const int k = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_denoising_neighbors), 24);
  if(k < 6 || k > 256)
    throw Invalid_input(std::string(stage) + ": denoising_neighbors must be in [6, 256], got " + std::to_string(k));
  return unsigned(k);
}

// M, default 1500 (the paper's timings) but never more than the points.
template <class NamedParameters>
std::size_t number_of_samples(const NamedParameters& np, std::size_t points, const char* stage)
{
  const std::size_t m = parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_samples),
                                                     std::size_t(1500));
  if(m < 1)
    throw Invalid_input(std::string(stage) + ": number_of_samples must be at least 1");
  return (std::min)(m, points);
}

template <class NamedParameters>
double repulsion_coefficient(const NamedParameters& np, const char* stage)
{
  const double u = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_repulsion), 0.35);
  if(!(u >= 0 && u < 0.5))
    throw Invalid_input(std::string(stage) + ": repulsion_coefficient must be in [0, 0.5)");
  return u;
}

inline double check_initial_support_radius(double h, const char* stage)
{
  if(!(h > 0) || !std::isfinite(h))
    throw Invalid_input(std::string(stage) + ": initial_support_radius must be positive and finite");
  return h;
}

// h0 = 2 d_bb / cbrt(N) (the paper).
template <class NamedParameters>
double initial_support_radius(const NamedParameters& np, double diagonal, std::size_t n, const char* stage)
{
  return check_initial_support_radius(
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_support_radius),
                                 2 * diagonal / std::cbrt(double((std::max)(n, std::size_t(1))))),
    stage);
}

template <class NamedParameters>
double support_radius_growth(const NamedParameters& np, const char* stage)
{
  const double r = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_support_radius_growth), 0.5);
  if(!(r > 0 && r <= 4))
    throw Invalid_input(std::string(stage) + ": support_radius_growth must be in (0, 4]");
  return r;
}

template <class NamedParameters>
double branch_directionality(const NamedParameters& np, const char* stage)
{
  const double s = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_branch_directionality), 0.9);
  if(!(s > 1.0 / 3 && s < 1))
    throw Invalid_input(std::string(stage) + ": branch_directionality must be in (1/3, 1)");
  return s;
}

template <class NamedParameters>
int contraction_stages(const NamedParameters& np, const char* stage)
{
  const int n = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_contraction_stages), 64);
  if(n < 1 || n > 64)
    throw Invalid_input(std::string(stage) + ": contraction_stages must be in [1, 64]");
  return n;
}

// Maximum number of iterations of one support-radius stage (CGAL's number_of_iterations).
template <class NamedParameters>
int iterations_per_stage(const NamedParameters& np, const char* stage)
{
  const int n = parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_iterations), 30);
  if(n < 1 || n > 10000)
    throw Invalid_input(std::string(stage) + ": number_of_iterations must be in [1, 10000]");
  return n;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_NAMED_PARAMETERS_H
