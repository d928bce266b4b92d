// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H
#define CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H

/// \file extract_initial_skeleton.h
/// Stage 4 (paper, section 5): multi-scale parameter-controlled thinning.

#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/Initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/box_sum.h>
#include <CGAL/DF_L1_skeleton/internal/contractible_cycles.h>
#include <CGAL/DF_L1_skeleton/internal/curve_thinning.h>
#include <CGAL/DF_L1_skeleton/internal/join_pieces.h>
#include <CGAL/DF_L1_skeleton/internal/missing_branches.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/ridge_voxels.h>
#include <CGAL/DF_L1_skeleton/internal/spur_pruning.h>
#include <CGAL/DF_L1_skeleton/internal/thinning_volume.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_curve_graph.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_morphology.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <numeric>
#include <array>
#include <cmath>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Extracts the initial skeleton from a distance field by multi-scale
/// parameter-controlled thinning (paper, section 5, Eq. 1-2).
///
/// For every interior voxel p and the 26, 124 and 342 neighbours around it, MNT_k(p) is
/// their mean distance (box sums: 8 reads per voxel and scale). p is a skeleton voxel
/// when, at all three scales, it stands above that mean by more than
/// TP_k = c |mean over the interior of (DT - MNT_k)|, at least two voxels deep. The paper
/// writes the threshold without the magnitude, which is negative on a concave field.
///
/// The skeleton voxels S form a band a few voxels thick, broken where noise flattens the
/// ridge; `Initial_skeleton::graph` is a curve through it with the topology of the shape
/// (our addition): the interior is thinned to curves in the order of depth without
/// changing its topology, with ends only where a branch is capped; parts thinner than two
/// voxels join through their occupied voxels (`thin_parts`); hair is pruned by what its
/// balls add to the shape; cycles around holes narrower than the grid resolves are cut,
/// pieces of one solid joined, and thin limbs that the thinning ate get their branch back.
/// The rules and their measurements: \ref design_initial_skeleton.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: the thin-part search runs beside the ridge
///         extraction on a second thread when parallel; the result is the same
/// \tparam Traits a model of `Kernel`
/// \param field the distance field returned by `compute_distance_field()`
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{thinning_coefficient}
///     \cgalParamDescription{c of Eq. 2: larger keeps fewer skeleton voxels}
///     \cgalParamType{`double`, in (0, 10]}
///     \cgalParamDefault{0.86}
///   \cgalParamNEnd
///   \cgalParamNBegin{spur_length_ratio}
///     \cgalParamDescription{terminal branches shorter than this times the local radius at their
///       junction (plus one voxel) are pruned}
///     \cgalParamType{`double`, >= 0}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{thin_parts}
///     \cgalParamDescription{whether the curves run into the parts thinner than two voxels;
///       `DF_L1_skeletonization` turns it off for clouds it smoothed, whose ragged boundary shell cannot
///       be told from a thin part; moot with `occupied_depth`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{occupied_depth}
///     \cgalParamDescription{whether depth is measured in the occupied voxels (the distance to the
///       nearest unoccupied voxel less one) instead of read from the distance field;
///       `DF_L1_skeletonization` turns it on for the clouds it smoothed}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{support_points}
///     \cgalParamDescription{the points the field was computed from, in its frame, passed with
///       `std::cref()`: a terminal branch whose tip has points more than 3 voxels (plus twice the
///       surface noise) outside the balls of the rest of the skeleton is kept, although those balls
///       cover its own to within the pruning's slack (the cap of a short twig beside its parent);
///       `DF_L1_skeletonization` passes the points it analyses}
///     \cgalParamType{a `std::reference_wrapper` to a range of `Traits::Point_3`}
///     \cgalParamDefault{none: the pruning reads the field alone}
///   \cgalParamNEnd
///   \cgalParamNBegin{surface_noise}
///     \cgalParamDescription{the noise of the sampled surface, in input units (`estimate_surface_noise()`):
///       the cover test of the spur pruning grows its slack by twice it; `DF_L1_skeletonization` passes
///       its estimate}
///     \cgalParamType{`double`, >= 0}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the skeleton voxels and the graph; both are empty when the field has no
///          interior voxel two voxels deep and no thin object (a flat or linear point set, or one too
///          sparse to enclose a volume); the graph alone may hold curves when only thin objects have
///          them
/// \throws Invalid_input if a parameter is out of range
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class Traits,
          class NamedParameters = parameters::Default_named_parameters>
Initial_skeleton<Traits> extract_initial_skeleton(const Distance_field<Traits>& field,
                                                  const NamedParameters& np = parameters::default_values());

namespace internal {

// extract_initial_skeleton(), calling `before_repairs()` once before the graph repairs
// (joining pieces, adding missing branches) when one of them will run: each allocates
// 32 bytes per voxel of the grid, and whether they run is known only here.
// DF_L1_skeletonization checks its memory estimate there.
template <class ConcurrencyTag, class Traits, class NamedParameters, class BeforeRepairs>
Initial_skeleton<Traits> extract_initial_skeleton(const Distance_field<Traits>& field, const NamedParameters& np,
                                                  const BeforeRepairs& before_repairs,
                                                  const Point_support& support = Point_support())
{
  const double c = internal::thinning_coefficient(np, "initial skeleton");
  const double spur_ratio = internal::spur_length_ratio(np, "initial skeleton");
  const double noise = internal::surface_noise(np, "initial skeleton");
  const bool in_occupied = parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_occupied_depth), false);
  // The occupied solid already holds the thin parts.
  const bool with_thin_parts =
    !in_occupied && parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_thin_parts), true);

  const double ridge_end_ratio = 0.5, thin_end_ratio = 0.6;
  Initial_skeleton<Traits> result;
  // The depth that the ridge test and the thinning read: the distance field, or the
  // depth in the occupied voxels less their outer layer (about the field where the
  // boundary shell is one voxel thick).
  std::vector<float> occupied_values;
  if(in_occupied)
  {
    occupied_values = internal::occupied_depth(field);
    for(float& d : occupied_values)
      d = (std::max)(0.f, d - 1);
  }
  const std::vector<float>& values = in_occupied ? occupied_values : field.values;
  // Three independent reads of the field: the ridge voxels, the solid to thin and the
  // thin parts; the thin parts (most of the time of this stage) run beside the other two.
  std::vector<char> in, curves;
  internal::Thin_parts thin;
  bool has_interior = false;
  internal::run_both<ConcurrencyTag>(
    [&] {
      has_interior = internal::ridge_voxels(field, values, c, result, in);
      if(has_interior)
        curves = internal::shape_volume(field);
    },
    [&] {
      if(with_thin_parts)
        thin = internal::thin_parts(field, 2.0, 4.0);
    });
  const bool has_thin = with_thin_parts && std::find(thin.voxels.begin(), thin.voxels.end(), 1) != thin.voxels.end();
  if(!has_interior && !has_thin)
    return result;
  if(!has_interior) // thin objects alone: no ridge voxel, no thick solid
  {
    in.assign(field.size(), 0);
    curves.assign(field.size(), 0);
  }
  if(in_occupied)
    for(std::size_t v = 0; v < field.size(); ++v)
      curves[v] = curves[v] || values[v] > 0;
  // The thinning order uses the depth above (the distance field, or the depth in the
  // occupied voxels with `occupied_depth`), and in and around the thin parts (where it
  // is 0 or 1) the distance to the nearest unoccupied voxel minus one (about the field
  // plus the boundary layer elsewhere): their curves then follow their middle.
  std::vector<float> depth = values;
  if(with_thin_parts)
  {
    for(std::size_t v = 0; v < field.size(); ++v)
      if(thin.solid[v])
      {
        curves[v] = 1;
        depth[v] = (std::max)(depth[v], thin.depth[v] - 1);
      }
  }
  // A ridge voxel may end a curve when it is half as deep as the deepest voxel within
  // twice its depth; a voxel of a thin part, or with `occupied_depth` any voxel below the
  // outer layer, when its radius is 0.6 times the largest there: the thin limbs of a
  // smoothed cloud have few ridge voxels, and their curves would stop short of the tips.
  // Those depths are the occupied ones less one, half a voxel short of the radius; the
  // occupied voxels less than two deep are read voxel by voxel, as the thin parts. The
  // hair this lets through on ragged sides is pruned by the cover test of `prune_spurs`.
  std::vector<signed char> deep_end(field.size(), -1); // memo of is_deep_end
  const internal::Block_maximum maxima(field, depth);
  internal::thin_to_curves(field, depth, curves, [&](std::size_t v) {
    const bool in_thin_part = with_thin_parts && thin.voxels[v];
    const bool thin_end = in_thin_part || (in_occupied && values[v] > 0);
    if(!in[v] && !thin_end)
      return false;
    if(deep_end[v] < 0)
      deep_end[v] = internal::is_deep_end(field, depth, maxima, v, in[v] ? ridge_end_ratio : thin_end_ratio,
                                          in_thin_part || (in_occupied && values[v] < 2), in_occupied ? 0.5 : 0.0);
    return bool(deep_end[v]);
  });
  std::vector<std::size_t> curve_voxels;
  for(std::size_t v = 0; v < curves.size(); ++v)
    if(curves[v])
      curve_voxels.push_back(v);
  result.graph = internal::voxel_curve_graph<Traits>(field, curve_voxels);
  const double voxel = CGAL::to_double(field.voxel_size);
  for(std::size_t d = 0; d < curve_voxels.size(); ++d)
  {
    const std::size_t v = curve_voxels[d];
    // In a thin part the field is 0 or 1; its radius is the distance to the nearest
    // unoccupied voxel, less the half voxel to the surface inside the boundary voxel.
    const double thin_radius = with_thin_parts && thin.solid[v] ? (thin.depth[v] - 0.5) * voxel : 0.0;
    const double occupied_radius = in_occupied ? values[v] * voxel : 0.0;
    result.graph[d].radius = (std::max)({CGAL::to_double(field.distance(v)), thin_radius, occupied_radius});
  }
  internal::prune_spurs(result.graph, spur_ratio, voxel, noise, support);
  if(skeleton_statistics(result.graph).cycles > 0 && internal::cut_contractible_cycles(result.graph, field, field.labels) > 0)
    internal::prune_spurs(result.graph, spur_ratio, voxel, noise, support);
  // Pieces within one component of the occupied voxels are joined; the depth of the
  // thin parts is the same transform when it was computed.
  const bool join = skeleton_statistics(result.graph).components > 1;
  if(join || has_thin)
    before_repairs();
  if(join)
    internal::join_pieces_within_shape(result.graph, field,
                                       thin.depth.empty() ? internal::occupied_depth(field) : thin.depth);
  // The thin limbs that the thinning ate from their flat tips get their branches back.
  // A twig 1.75 voxels in radius holds voxels sqrt(2) deep along its axis: only the
  // layer of depth 1 is surface.
  if(has_thin)
    internal::add_missing_branches(result.graph, field, thin.depth, thin.voxels, 4.0 + 2 * noise / voxel, 1.0, 1.3);
  return result;
}

} // namespace internal

template <class ConcurrencyTag, class Traits, class NamedParameters>
Initial_skeleton<Traits> extract_initial_skeleton(const Distance_field<Traits>& field, const NamedParameters& np)
{
  const auto& points = parameters::get_parameter_reference(np, internal_np::df_l1_support_points);
  if constexpr(std::is_same_v<std::decay_t<decltype(points)>, internal_np::Param_not_found>)
    return internal::extract_initial_skeleton<ConcurrencyTag>(field, np, [] {});
  else
  {
    const std::vector<std::array<double, 3>> xyz =
      internal::to_xyz(points, CGAL::Identity_property_map<typename Traits::Point_3>());
    const internal::Uniform_grid grid(xyz, 2 * CGAL::to_double(field.voxel_size));
    return internal::extract_initial_skeleton<ConcurrencyTag>(field, np, [] {}, internal::Point_support{&xyz, &grid});
  }
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H
