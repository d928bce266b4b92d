// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_NAMED_PARAMETERS_H
#define CGAL_DF_L1_SKELETON_NAMED_PARAMETERS_H

/// \file named_parameters.h
/// The package's own named parameters, next to CGAL's (`point_map`, `geom_traits`,
/// `number_of_samples`, `number_of_iterations`). Their defaults and ranges are those of
/// `CGAL::DF_L1::parameter_table()`; each tag is `df_l1_` followed by the parameter's name.
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

#include <CGAL/DF_L1_skeleton/Parameters.h>
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
enum df_l1_support_points_t { df_l1_support_points };
enum df_l1_initial_voxel_size_t { df_l1_initial_voxel_size };
enum df_l1_exterior_propagation_steps_t { df_l1_exterior_propagation_steps };
enum df_l1_upsampling_t { df_l1_upsampling };
enum df_l1_upsampling_neighbors_t { df_l1_upsampling_neighbors };
enum df_l1_upsampling_radius_t { df_l1_upsampling_radius };
enum df_l1_thinning_coefficient_t { df_l1_thinning_coefficient };
enum df_l1_outlier_component_size_t { df_l1_outlier_component_size };
enum df_l1_spur_length_ratio_t { df_l1_spur_length_ratio };
enum df_l1_skeletonization_method_t { df_l1_skeletonization_method };
enum df_l1_repulsion_coefficient_t { df_l1_repulsion_coefficient };
enum df_l1_initial_support_radius_t { df_l1_initial_support_radius };
enum df_l1_support_radius_growth_t { df_l1_support_radius_growth };
enum df_l1_branch_directionality_t { df_l1_branch_directionality };
enum df_l1_contraction_stages_t { df_l1_contraction_stages };
enum df_l1_denoising_t { df_l1_denoising };
enum df_l1_denoising_neighbors_t { df_l1_denoising_neighbors };
enum df_l1_thin_parts_t { df_l1_thin_parts };
enum df_l1_occupied_depth_t { df_l1_occupied_depth };
enum df_l1_open_crotches_t { df_l1_open_crotches };
enum df_l1_local_shell_bands_t { df_l1_local_shell_bands };
enum df_l1_surface_noise_t { df_l1_surface_noise };
enum df_l1_max_memory_t { df_l1_max_memory };
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
/// How many face-neighbour steps the exterior label may spread through the empty
/// sub-voxels of a boundary voxel at each refinement level (default 1, the paper's rule).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_exterior_propagation_steps, exterior_propagation_steps)
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
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_spur_length_ratio, spur_length_ratio)
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
/// The points a distance field was computed from, passed with `std::cref()`, as evidence
/// for the initial skeleton's terminal branches: one whose tip has points well outside the
/// rest of the skeleton is not pruned (default: none; `DF_L1_skeletonization` passes the
/// points it analyses). See `extract_initial_skeleton()`.
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_support_points, support_points)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The noise of the sampled surface, in input units, as `estimate_surface_noise()` gives
/// it (default 0; `DF_L1_skeletonization` passes its estimate): the initial skeleton's
/// spur pruning takes a branch for hair when it rises less than twice that above the
/// rest, on top of its slack in voxels.
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_surface_noise, surface_noise)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The most memory, in bytes, that `DF_L1_skeletonization` may use: the estimate of its
/// peak (`DF_L1_skeletonization::estimated_peak_memory()`) beyond it throws
/// `DF_L1::Invalid_input` naming the parameter to lower, in the constructor, before the
/// voxelization, and with the estimate refined from the voxels before the initial
/// skeleton's thinning and graph repairs (default: the memory available when the object
/// is constructed, `MemAvailable` on Linux; no limit elsewhere).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_max_memory, max_memory)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Whether the voxelization opens the interior voxels that see the exterior along 10 or
/// more of the 26 grid directions: the crotches between close parts, narrower than the
/// sweeping balls (default `true`; `DF_L1_skeletonization` turns it off for smoothed
/// noisy clouds, whose ragged shell lets the lines into the surface layer).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_open_crotches, open_crotches)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// Whether the voxelization's shell (the boundary voxels dilated to close the gaps
/// between samples, which the parity vote and the lines of sight cross) takes its width
/// from the local sampling spacing at each boundary voxel rather than from the median
/// spacing of the cloud (default `true`; `DF_L1_skeletonization` turns it off for
/// smoothed noisy clouds, whose scattered residual points would thicken it).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_local_shell_bands, local_shell_bands)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// The refinement method, a `CGAL::DF_L1::Skeletonization_method` (default
/// `DISTANCE_FIELD_GUIDED`; `L1_MEDIAL` switches the guidance off, as a baseline).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_skeletonization_method, skeletonization_method)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// u, the weight of the repulsion between samples in Eq. 8, in [0, 0.5) (default 0.35).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_repulsion_coefficient, repulsion_coefficient)
/// \ingroup PkgDFL1SkeletonNamedParameters
/// h0, the initial support radius of the contraction (default 2 d_bb / cbrt(N), the paper's).
CGAL_DF_L1_ADD_NAMED_PARAMETER(df_l1_initial_support_radius, initial_support_radius)
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

namespace internal {

// The stage functions read their parameters here: the default is the one of
// `Parameters`, the range that of `parameter_table()`; `stage` names the caller in the
// error message.

template <class Tag, class NamedParameters, class T>
T parameter_or(const NamedParameters& np, Tag tag, const T& default_value)
{
  return parameters::choose_parameter(parameters::get_parameter(np, tag), default_value);
}

template <class T>
T checked(const char* name, T value, const char* stage)
{
  checked_parameter(name, double(value), stage);
  return value;
}

template <class NamedParameters>
int voxel_resolution(const NamedParameters& np, const char* stage)
{
  return checked("voxel_resolution", parameter_or(np, internal_np::df_l1_voxel_resolution, Parameters().voxel_resolution), stage);
}

// s0 = d_bb / 9 (the paper).
inline double default_initial_voxel_size(double diagonal) { return diagonal / 9; }

template <class NamedParameters>
double initial_voxel_size(const NamedParameters& np, double diagonal, const char* stage)
{
  return checked("initial_voxel_size",
                 parameter_or(np, internal_np::df_l1_initial_voxel_size, default_initial_voxel_size(diagonal)), stage);
}

template <class NamedParameters>
int exterior_propagation_steps(const NamedParameters& np, const char* stage)
{
  return checked("exterior_propagation_steps",
                 parameter_or(np, internal_np::df_l1_exterior_propagation_steps, Parameters().exterior_propagation_steps), stage);
}

template <class NamedParameters>
int upsampling_neighbors(const NamedParameters& np, const char* stage)
{
  return checked("upsampling_neighbors", parameter_or(np, internal_np::df_l1_upsampling_neighbors, Parameters().upsampling_neighbors),
                 stage);
}

// r of the density test, 3 d_bb / cbrt(N) for N points.
inline double default_upsampling_radius(double diagonal, std::size_t n) { return 3 * diagonal / std::cbrt(double(n)); }

template <class NamedParameters>
double upsampling_radius(const NamedParameters& np, double diagonal, std::size_t n, const char* stage)
{
  return checked("upsampling_radius",
                 parameter_or(np, internal_np::df_l1_upsampling_radius, default_upsampling_radius(diagonal, n)), stage);
}

// Default max(3, V/10), V the longest side of the grid in voxels.
inline int default_outlier_component_size(const std::array<int, 3>& dims)
{
  return (std::max)(3, (std::max)({dims[0], dims[1], dims[2]}) / 10);
}

template <class NamedParameters>
int outlier_component_size(const NamedParameters& np, const std::array<int, 3>& dims, const char* stage)
{
  return checked("outlier_component_size",
                 parameter_or(np, internal_np::df_l1_outlier_component_size, default_outlier_component_size(dims)), stage);
}

template <class NamedParameters>
double thinning_coefficient(const NamedParameters& np, const char* stage)
{
  return checked("thinning_coefficient", parameter_or(np, internal_np::df_l1_thinning_coefficient, Parameters().thinning_coefficient),
                 stage);
}

template <class NamedParameters>
double spur_length_ratio(const NamedParameters& np, const char* stage)
{
  return checked("spur_length_ratio", parameter_or(np, internal_np::df_l1_spur_length_ratio, Parameters().spur_length_ratio), stage);
}

// Not a user parameter (the class passes its estimate), so not in the table.
template <class NamedParameters>
double surface_noise(const NamedParameters& np, const char* stage)
{
  const double noise = parameter_or(np, internal_np::df_l1_surface_noise, 0.0);
  if(!(noise >= 0) || !std::isfinite(noise))
    throw Invalid_input(std::string(stage) + ": surface_noise must be a non-negative number");
  return noise;
}

template <class NamedParameters>
Skeletonization_method skeletonization_method(const NamedParameters& np)
{
  return parameter_or(np, internal_np::df_l1_skeletonization_method, Parameters().skeletonization_method);
}

template <class NamedParameters>
Denoising denoising(const NamedParameters& np)
{
  return parameter_or(np, internal_np::df_l1_denoising, Parameters().denoising);
}

template <class NamedParameters>
bool upsampling(const NamedParameters& np)
{
  return parameter_or(np, internal_np::df_l1_upsampling, Parameters().upsampling);
}

template <class NamedParameters>
unsigned int denoising_neighbors(const NamedParameters& np, const char* stage)
{
  return unsigned(
    checked("denoising_neighbors", parameter_or(np, internal_np::df_l1_denoising_neighbors, Parameters().denoising_neighbors), stage));
}

// M as requested (the stages use at most the points).
template <class NamedParameters>
std::size_t requested_samples(const NamedParameters& np, const char* stage)
{
  return checked("number_of_samples", parameter_or(np, internal_np::number_of_samples, Parameters().number_of_samples), stage);
}

// M, default 1500 (the paper's timings) but never more than the points.
template <class NamedParameters>
std::size_t number_of_samples(const NamedParameters& np, std::size_t points, const char* stage)
{
  return (std::min)(requested_samples(np, stage), points);
}

template <class NamedParameters>
double repulsion_coefficient(const NamedParameters& np, const char* stage)
{
  return checked("repulsion_coefficient",
                 parameter_or(np, internal_np::df_l1_repulsion_coefficient, Parameters().repulsion_coefficient), stage);
}

// h0 = 2 d_bb / cbrt(N) (the paper).
inline double default_initial_support_radius(double diagonal, std::size_t n)
{
  return 2 * diagonal / std::cbrt(double((std::max)(n, std::size_t(1))));
}

template <class NamedParameters>
double initial_support_radius(const NamedParameters& np, double diagonal, std::size_t n, const char* stage)
{
  return checked("initial_support_radius",
                 parameter_or(np, internal_np::df_l1_initial_support_radius, default_initial_support_radius(diagonal, n)), stage);
}

template <class NamedParameters>
double support_radius_growth(const NamedParameters& np, const char* stage)
{
  return checked("support_radius_growth",
                 parameter_or(np, internal_np::df_l1_support_radius_growth, Parameters().support_radius_growth), stage);
}

template <class NamedParameters>
double branch_directionality(const NamedParameters& np, const char* stage)
{
  return checked("branch_directionality",
                 parameter_or(np, internal_np::df_l1_branch_directionality, Parameters().branch_directionality), stage);
}

template <class NamedParameters>
int contraction_stages(const NamedParameters& np, const char* stage)
{
  return checked("contraction_stages", parameter_or(np, internal_np::df_l1_contraction_stages, Parameters().contraction_stages),
                 stage);
}

// Maximum number of iterations of one support-radius stage (CGAL's number_of_iterations).
template <class NamedParameters>
int iterations_per_stage(const NamedParameters& np, const char* stage)
{
  return checked("number_of_iterations", parameter_or(np, internal_np::number_of_iterations, Parameters().number_of_iterations),
                 stage);
}

// The user parameters of `np`, every one checked; the length parameters not given stay
// empty (derived from the input when the stages run).
template <class NamedParameters>
Parameters resolve_parameters(const NamedParameters& np, const char* stage)
{
  Parameters p;
  p.denoising = denoising(np);
  p.denoising_neighbors = int(denoising_neighbors(np, stage));
  p.upsampling = upsampling(np);
  p.upsampling_neighbors = upsampling_neighbors(np, stage);
  if(!parameters::is_default_parameter<NamedParameters, internal_np::df_l1_upsampling_radius_t>::value)
    p.upsampling_radius = upsampling_radius(np, 1, 1, stage);
  p.voxel_resolution = voxel_resolution(np, stage);
  if(!parameters::is_default_parameter<NamedParameters, internal_np::df_l1_initial_voxel_size_t>::value)
    p.initial_voxel_size = initial_voxel_size(np, 1, stage);
  p.exterior_propagation_steps = exterior_propagation_steps(np, stage);
  if(!parameters::is_default_parameter<NamedParameters, internal_np::df_l1_outlier_component_size_t>::value)
    p.outlier_component_size = outlier_component_size(np, {0, 0, 0}, stage);
  p.thinning_coefficient = thinning_coefficient(np, stage);
  p.spur_length_ratio = spur_length_ratio(np, stage);
  p.skeletonization_method = skeletonization_method(np);
  p.number_of_samples = requested_samples(np, stage);
  p.repulsion_coefficient = repulsion_coefficient(np, stage);
  if(!parameters::is_default_parameter<NamedParameters, internal_np::df_l1_initial_support_radius_t>::value)
    p.initial_support_radius = initial_support_radius(np, 1, 1, stage);
  p.support_radius_growth = support_radius_growth(np, stage);
  p.branch_directionality = branch_directionality(np, stage);
  p.number_of_iterations = iterations_per_stage(np, stage);
  p.contraction_stages = contraction_stages(np, stage);
  return p;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_NAMED_PARAMETERS_H
