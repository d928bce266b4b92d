// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_CONTRACTED_SAMPLES_H
#define CGAL_DF_L1_SKELETON_CONTRACTED_SAMPLES_H

/// \file Contracted_samples.h
/// The result of `contract_samples()`: the samples of the L1-median contraction, the
/// branches traced through them and the history of the iterations.

#include <CGAL/DF_L1_skeleton/Parameters.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// What a sample of the contraction has become.
enum class Sample_role : std::uint8_t
{
  FREE = 0,   ///< still moving (or left over when the contraction stopped)
  BRANCH = 1, ///< a branch or bridge point: frozen, joined to its neighbours by edges
  REMOVED = 2 ///< merged into a branch it came too close to
};

/// \ingroup PkgDFL1SkeletonRef
/// Statistics of one support-radius stage of the contraction.
struct Contraction_stage
{
  int iterations = 0;             ///< fixed-point iterations run in this stage
  double min_radius = 0;          ///< smallest support radius h of a free sample (input units)
  double mean_radius = 0;         ///< mean h of the free samples
  double max_radius = 0;          ///< largest h of a free sample
  std::size_t free_samples = 0;   ///< samples free at the start of the stage
  std::size_t branch_samples = 0; ///< branch points at the end of the stage
  double projection_seconds = 0;  ///< wall seconds of this stage's fixed-point iterations (Eq. 8), the parallel
                                  ///< projection step; the only field that varies from run to run
};

/// \ingroup PkgDFL1SkeletonRef
/// The samples of the contraction (paper, section 6) and the branches through them.
/// \tparam Traits a model of `Kernel`
template <class Traits>
struct Contracted_samples
{
  typedef typename Traits::Point_3 Point_3; ///< point type

  /// final positions; junction points created by bridges are appended after the samples
  std::vector<Point_3> points;
  /// the role of each point
  std::vector<Sample_role> roles;
  /// the support radius h of each point in the last stage it moved (input units)
  std::vector<double> support_radii;
  /// the branch and bridge edges, as pairs of indices into `points`
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  /// one entry per support-radius stage
  std::vector<Contraction_stage> stages;
  /// the positions of the samples after each iteration (the first entry is the initial
  /// pick, before any iteration)
  std::vector<std::vector<Point_3>> iterations;
  /// the initial support radius h0 (input units)
  double initial_support_radius = 0;
  /// the method that produced the samples
  Skeletonization_method method = Skeletonization_method::DISTANCE_FIELD_GUIDED;
};

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_CONTRACTED_SAMPLES_H
