// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETONIZATION_H
#define CGAL_DF_L1_SKELETONIZATION_H

/// \file DF_L1_skeletonization.h
/// The `DF_L1_skeletonization` class, which runs the stages of the method one by one and
/// keeps every intermediate result.

#include <CGAL/DF_L1_skeleton/Contracted_samples.h>
#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/Initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/Parameters.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/assign_points_to_skeleton.h>
#include <CGAL/DF_L1_skeleton/build_skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/compute_distance_field.h>
#include <CGAL/DF_L1_skeleton/contract_samples.h>
#include <CGAL/DF_L1_skeleton/denoise_point_set.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/extract_initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/flag_sparse_outliers.h>
#include <CGAL/DF_L1_skeleton/internal/attach_fragments.h>
#include <CGAL/DF_L1_skeleton/internal/contractible_cycles.h>
#include <CGAL/DF_L1_skeleton/internal/density_cap.h>
#include <CGAL/DF_L1_skeleton/internal/memory_estimate.h>
#include <CGAL/DF_L1_skeleton/internal/normalization.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>
#include <CGAL/DF_L1_skeleton/internal/point_gap_cuts.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/internal/sampling_spacing.h>
#include <CGAL/DF_L1_skeleton/internal/spur_pruning.h>
#include <CGAL/DF_L1_skeleton/internal/twig_test.h>
#include <CGAL/DF_L1_skeleton/internal/uniform_grid.h>
#include <CGAL/DF_L1_skeleton/internal/vec3.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>
#include <CGAL/DF_L1_skeleton/remove_outlier_voxels.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>
#include <CGAL/DF_L1_skeleton/upsample_sparse_regions.h>
#include <CGAL/DF_L1_skeleton/voxelize_point_set.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <memory>
#include <optional>
#include <type_traits>
#include <string>
#include <vector>

namespace CGAL {

/// \ingroup PkgDFL1SkeletonRef
/// Computes the curve skeleton of a point cloud with the distance-field guided
/// L1-median method, one stage at a time, like `CGAL::Mean_curvature_flow_skeletonization`.
///
/// The data flows one way: points, outlier flags and upsampling, voxel grid, distance
/// field, initial skeleton. Each stage function runs the stages before it if they have
/// not run yet, so a researcher can stop after any of them and look at its result, and
/// a user can call the last one alone. Every length parameter left unset derives from
/// the input (the diagonal d_bb of its bounding box, or the voxel size), so a scaled
/// cloud gives a scaled result; the getters return the values actually used.
///
/// Scale: the stages run on the points moved to the centre of their bounding box,
/// divided by its diagonal and rounded to multiples of 2^-32 (2.3e-10 of the diagonal,
/// far below any scanner's precision); every result and length is mapped back to input
/// units by the getters. A cloud of coordinates of the order of 1e300 or 1e-300 thus gives
/// the same skeleton, scaled, as one of the order of 1: equal within a relative 1e-9 for
/// any factor, bit for bit for a power of two. A cloud whose extent exceeds the largest
/// `double`, or is below the smallest normal `double` (2.2e-308), is refused.
///
/// Numbers: the points are kept in the kernel's type; the voxel grid's origin and voxel
/// size are the kernel's `FT`; everything else (distance field, thinning, contraction,
/// skeleton positions before they are stored as `Point_3`) is computed in `double`. With
/// `Epick` and `Simple_cartesian<double>` the results are identical; with exact
/// constructions or `float` a grid boundary may fall on the other side of a point, which
/// can move a vertex by up to a voxel (tested in `test/pipeline/test_genericity.cpp`).
///
/// \tparam Traits a model of `Kernel`
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`, honoured by every stage; results do not
///         depend on the number of threads
template <class Traits, class ConcurrencyTag = CGAL::Parallel_if_available_tag>
class DF_L1_skeletonization
{
public:
  /// \name Types
  /// @{
  typedef typename Traits::Point_3 Point;                   ///< point type
  typedef DF_L1::Skeleton_graph<Traits> Skeleton;           ///< the skeleton, a `boost::adjacency_list`
  typedef DF_L1::Voxel_grid<Traits> Voxel_grid;             ///< labelled voxels
  typedef DF_L1::Distance_field<Traits> Distance_field;     ///< distance of every voxel
  typedef DF_L1::Initial_skeleton<Traits> Initial_skeleton; ///< skeleton voxels and their graph
  typedef DF_L1::Contracted_samples<Traits> Contracted_samples; ///< samples, branches and iterations of the contraction
  typedef DF_L1::Sample_contraction<Traits, ConcurrencyTag> Sample_contraction; ///< the contraction, stage by stage
  /// @}

  /// Copies the points and reads the parameters.
  ///
  /// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
  /// \param points the input points; normals are not needed
  /// \param np an optional sequence of named parameters: `point_map` (as for
  ///        `voxelize_point_set()`) and every parameter of `DF_L1::Parameters`, whose
  ///        type, range, default and meaning \ref parameters lists (the stage functions
  ///        document them too). The initial skeleton's `thin_parts`, `occupied_depth` and
  ///        `surface_noise` are set by the class: `thin_parts` on exactly when the cloud
  ///        was not smoothed (`denoised()`), `occupied_depth` on exactly when it was,
  ///        `surface_noise` to `surface_noise()`
  /// \throws DF_L1::Invalid_input if the range is empty, holds a non-finite coordinate,
  ///         all its points coincide or lie on a plane (within a quarter of a voxel, RMS),
  ///         their extent exceeds the largest `double`, a parameter is out of range, or
  ///         `estimated_peak_memory()` exceeds `max_memory` (the message names the
  ///         parameter to lower)
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
  explicit DF_L1_skeletonization(const PointRange& points, const NamedParameters& np = parameters::default_values())
  {
    typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
    const auto point_map = NP_helper::get_const_point_map(points, np);
    const CGAL::Bbox_3 input_box = DF_L1::internal::checked_bbox(points, point_map, stage_name, true);
    normalization_ = DF_L1::internal::Normalization(input_box, stage_name);
    if(!(DF_L1::internal::longest_side(input_box) > 0))
    {
      const std::size_t n = DF_L1::internal::range_size(points, point_map);
      throw DF_L1::Invalid_input(std::string(stage_name) +
                                 (n == 1 ? std::string(": a single point")
                                         : ": all " + std::to_string(n) + " points coincide") +
                                 "; there is no shape to skeletonize");
    }
    points_.reserve(DF_L1::internal::range_size(points, point_map));
    for(const auto& p : points)
      points_.push_back(normalization_.to_internal(get(point_map, p)));
    const CGAL::Bbox_3 box = DF_L1::internal::checked_bbox(points_, CGAL::Identity_property_map<Point>(), stage_name);
    diagonal_ = DF_L1::internal::diagonal(box);
    longest_side_ = DF_L1::internal::longest_side(box);
    box_min_ = {{box.xmin(), box.ymin(), box.zmin()}};
    extent_ = {{box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}};
    thickness_ = rms_distance_to_best_plane(points_);
    parameters_ = DF_L1::internal::resolve_parameters(np, stage_name);
    set_max_memory(parameters::choose_parameter(parameters::get_parameter(np, internal_np::df_l1_max_memory),
                                                DF_L1::internal::available_memory_bytes()));
    check_volume(parameters_.voxel_resolution);
    DF_L1::internal::check_memory(initial_memory_estimate(), max_memory_, parameters_.voxel_resolution, stage_name);
  }

  /// \name Stages
  /// Each runs the stages before it when they have not run yet, and does nothing when
  /// it has already run.
  /// @{

  /// Flags the scattered outliers (`flag_sparse_outliers()`). In a cloud denser than its
  /// voxels can show (at least twice as many points as it occupies cells of a third of
  /// the finest voxel, in a lattice of at most 4 cells per point), the test runs on a
  /// uniform sample of about two points per occupied cell, and a point outside the sample
  /// is an outlier unless an unflagged point of the sample lies within twice that point's
  /// distance to its 6th neighbour in the sample (\ref design_density_cap).
  void flag_outliers()
  {
    if(!sparse_outliers_.empty())
      return;
    const DF_L1::internal::Cell_lattice lattice = density_lattice();
    if(lattice.size() > 0)
    {
      const std::size_t occupied = DF_L1::internal::occupied_cells(lattice, points_.size(), point_coordinates()).count;
      if(double(occupied) <= dense_share * double(points_.size()))
        sparse_outliers_ = DF_L1::internal::sampled_sparse_outliers<ConcurrencyTag>(
          points_, lattice, (std::max)(std::size_t(1), points_.size() / (2 * occupied)));
    }
    if(sparse_outliers_.empty())
      sparse_outliers_ = DF_L1::flag_sparse_outliers<ConcurrencyTag>(points_);
    sparse_outlier_count_ = 0;
    for(bool b : sparse_outliers_)
      sparse_outlier_count_ += b;
  }

  /// Estimates the surface noise of the kept points (`estimate_surface_noise()`) and,
  /// as the `denoising` parameter says, smooths them (`denoise_point_set()`): by default
  /// when the noise exceeds a fifth of the finest voxel size (measured: at most 0.09
  /// voxel on clean, sparse, holed or uneven samples, at least 0.40 with 1 % noise) and
  /// the residual of the local fits grows less than 3 times from 10 to 40 neighbours
  /// (`residual_growth()`): noise is the same at both scales (a growth of 2 to 2.7 on the
  /// noisy scans and samples we measured), while the twigs of a LiDAR crown or a sparse
  /// sample of thin limbs look noisy only to neighbourhoods wider than they are (3.3 to
  /// 6), and smoothing would erase them. The later stages use the smoothed positions;
  /// the input points, their indices and the outlier flags stay.
  void denoise()
  {
    if(denoise_checked_)
      return;
    flag_outliers();
    // A cloud denser than its voxels can show (see flag_outliers()) is analysed through
    // representatives: the first non-outlier point of each such cell in input order. Every
    // occupied cell keeps one, so the voxels are marked much as with all the points; a
    // point left out shares its cell with its representative and takes its voxel
    // outlier flag, its smoothed position and its skeleton vertex. The stages from here to the
    // contraction then cost as much at 10 million points as at the few hundred thousand
    // that the voxels can tell apart (`number_of_analysed_points()`).
    const DF_L1::internal::Cell_lattice lattice = density_lattice();
    if(lattice.size() > 0)
      density_cap_ = DF_L1::internal::Density_cap(lattice, points_.size(), point_coordinates(),
                                                  [this](std::size_t i) { return !sparse_outliers_[i]; }, dense_share);
    kept_points_.clear();
    for(std::size_t i = 0; i < points_.size(); ++i)
      if(!sparse_outliers_[i] && density_cap_.is_representative(i))
        kept_points_.push_back(points_[i]);
    // one fitter, and so one grid, for the noise estimate and the smoothing (the points
    // were checked by flag_outliers())
    const DF_L1::internal::Local_quadric_fitter<Traits> fitter(kept_points_);
    surface_noise_ = DF_L1::internal::surface_noise<ConcurrencyTag>(fitter);
    const double finest_voxel = longest_side_ / parameters_.voxel_resolution;
    const bool noisy = parameters_.denoising == DF_L1::Denoising::AUTOMATIC && surface_noise_ > 0.2 * finest_voxel;
    residual_growth_ = noisy ? DF_L1::internal::residual_growth<ConcurrencyTag>(fitter) : 0.0;
    denoised_ = parameters_.denoising == DF_L1::Denoising::ALWAYS || (noisy && residual_growth_ < 3);
    if(denoised_)
      kept_points_ = DF_L1::internal::smoothed_points<ConcurrencyTag>(fitter, kept_points_, unsigned(parameters_.denoising_neighbors));
    denoise_checked_ = true;
  }

  /// Adds points in the sparse regions of the kept points (`upsample_sparse_regions()`),
  /// unless upsampling is off.
  void upsample()
  {
    if(upsampled_)
      return;
    denoise();
    if(parameters_.upsampling)
    {
      DF_L1::upsample_sparse_regions<ConcurrencyTag>(
        kept_points_, std::back_inserter(added_points_),
        parameters::upsampling_neighbors(parameters_.upsampling_neighbors,
        parameters::upsampling_radius(internal_upsampling_radius(),
        parameters::voxel_resolution(parameters_.voxel_resolution))));
    }
    upsampled_ = true;
  }

  /// Voxelizes the kept and added points (`voxelize_point_set()`), without opening the
  /// crotches (`open_crotches`) or a shell from the local spacing (`local_shell_bands`)
  /// in the clouds it smoothed.
  void voxelize()
  {
    if(raw_grid_)
      return;
    DF_L1::internal::check_memory(initial_memory_estimate(), max_memory_, parameters_.voxel_resolution, "voxelization");
    upsample();
    raw_grid_ = std::make_unique<Voxel_grid>(DF_L1::voxelize_point_set<ConcurrencyTag>(
      kept_and_added_points(), parameters::voxel_resolution(parameters_.voxel_resolution,
           parameters::initial_voxel_size(internal_initial_voxel_size(),
           parameters::exterior_propagation_steps(parameters_.exterior_propagation_steps,
           parameters::open_crotches(!denoised_,
           parameters::local_shell_bands(!denoised_)))))));
  }

  /// Removes the outlier voxels (`remove_outlier_voxels()`) and flags their points.
  void remove_outlier_voxels()
  {
    if(grid_)
      return;
    voxelize();
    grid_ = std::make_unique<Voxel_grid>(DF_L1::remove_outlier_voxels(
      *raw_grid_, parameters::outlier_component_size(resolved_outlier_component_size()), &outlier_voxel_statistics_));
    // A point left out by the density cap goes with its representative: its own voxel may
    // have been marked by no representative.
    if(density_cap_.active())
    {
      const std::vector<Point> analysed = analysed_input_points();
      const std::vector<bool> flags = voxel_outlier_flags(analysed, denoised_ ? &kept_points_ : nullptr);
      const std::vector<char> owner_flag = for_each_left_out<char>(0, [&](std::size_t i) {
        return char(flags[owner_position(i)]);
      });
      outliers_.assign(points_.size(), false);
      for(std::size_t i = 0, r = 0; i < points_.size(); ++i)
        outliers_[i] = density_cap_.is_representative(i) ? flags[r++] : owner_flag[i] != 0;
    }
    else if(denoised_)
    {
      const std::vector<Point> smoothed = smoothed_input_points();
      outliers_ = voxel_outlier_flags(points_, &smoothed);
    }
    else
      outliers_ = voxel_outlier_flags(points_, nullptr);
    outlier_count_ = 0;
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      outliers_[i] = outliers_[i] || sparse_outliers_[i];
      outlier_count_ += outliers_[i];
    }
  }

  /// Computes the distance field of the voxels (`compute_distance_field()`).
  void compute_distance_field()
  {
    if(field_)
      return;
    remove_outlier_voxels();
    field_ = std::make_unique<Distance_field>(DF_L1::compute_distance_field<ConcurrencyTag>(*grid_));
  }

  /// Extracts the initial skeleton (`extract_initial_skeleton()`), cuts its cycles where
  /// they cross a gap between two parts that the points show and the voxels did not
  /// (parts 1 or 2 voxels apart) and those around holes narrower than the sampling
  /// spacing (\ref design_initial_skeleton), and assigns every non-outlier input point to its
  /// nearest vertex of the graph (a point left out by the density cap, to that of its
  /// representative: `flag_outliers()`).
  ///
  /// The memory estimate is refined from the distance field (`estimated_peak_memory()`)
  /// and checked against `max_memory` before the thinning, and again before the graph
  /// repairs (joining pieces, adding missing branches) when they run.
  /// \throws DF_L1::Invalid_input if the refined estimate exceeds `max_memory` (the
  ///         message names the parameter to lower); the stages before it keep their results
  void extract_initial_skeleton()
  {
    if(initial_)
      return;
    compute_distance_field();
    refine_memory_estimate(false, "initial skeleton");
    // The analysed points are the evidence for the terminal branches of the spur pruning
    // (named parameter `support_points`), except in the clouds it smoothed, whose residual
    // scatter would keep hair, and show the gaps cut below: their grid is built when one
    // of the two needs it.
    const double voxel = CGAL::to_double(field_->voxel_size);
    std::vector<std::array<double, 3>> xyz;
    std::optional<DF_L1::internal::Uniform_grid> grid;
    auto point_grid = [&]() -> const DF_L1::internal::Uniform_grid& {
      if(!grid)
      {
        xyz = DF_L1::internal::to_xyz(kept_points_, CGAL::Identity_property_map<Point>());
        grid.emplace(xyz, 2 * voxel);
      }
      return *grid;
    };
    const DF_L1::internal::Point_support support =
      denoised_ ? DF_L1::internal::Point_support() : DF_L1::internal::Point_support{&xyz, &point_grid()};
    initial_ = std::make_unique<Initial_skeleton>(DF_L1::internal::extract_initial_skeleton<ConcurrencyTag>(
      *field_, parameters::thinning_coefficient(parameters_.thinning_coefficient,
               parameters::spur_length_ratio(parameters_.spur_length_ratio, parameters::thin_parts(!denoised_, parameters::occupied_depth(denoised_,
               parameters::surface_noise(surface_noise_))))),
      [this] { refine_memory_estimate(true, "initial skeleton (graph repairs)"); }, support));
    // The cycles through gaps between parts that the voxels could not separate are cut
    // where the points show the gap (`internal::cut_point_gaps()`). Then the cycles
    // around holes narrower than the sampling resolves: those whose disk lies in the
    // solid closed by the sampling spacing (`internal::cut_contractible_cycles()`, which
    // the thinning ran with a one-voxel closing), the pores between the samples of a
    // sparse plate. The stubs that a cut leaves go through the spur pruning again.
    if(DF_L1::skeleton_statistics(initial_->graph).cycles > 0)
    {
      const DF_L1::internal::Uniform_grid& points = point_grid();
      const double spacing = DF_L1::internal::median_kth_neighbour_distance(xyz, 6, voxel / 2, points);
      if(DF_L1::internal::cut_point_gaps(initial_->graph, xyz, points, voxel, spacing) > 0)
        DF_L1::internal::prune_spurs(initial_->graph, parameters_.spur_length_ratio, voxel, surface_noise_, support);
      const double closing = sampling_closing * spacing / voxel;
      if(closing > DF_L1::internal::one_voxel_closing && DF_L1::skeleton_statistics(initial_->graph).cycles > 0 &&
         DF_L1::internal::cut_contractible_cycles(initial_->graph, *field_, field_->labels, closing) > 0)
        DF_L1::internal::prune_spurs(initial_->graph, parameters_.spur_length_ratio, voxel, surface_noise_, support);
    }
    if(denoised_)
      add_missing_twigs(xyz, point_grid(), voxel);
    assign_points(initial_->graph);
  }

  /// Runs one support-radius stage of the contraction of samples of the kept and added
  /// points onto the skeleton (`Sample_contraction::contract()`): the L1-median iterations
  /// of Eq. 8 for the free samples, then the tracing of branches and bridges. The first
  /// call picks the samples first. Returns `false`, running nothing, once the contraction
  /// has converged. `contracted_samples()` shows the samples after the stages run so far.
  bool contract()
  {
    start_contraction();
    const bool ran = contraction_->contract();
    if(ran || !contracted_)
      take_contracted_samples();
    return ran;
  }

  /// Runs the stages of the contraction until it converges (`contract_samples()`).
  void contract_until_convergence()
  {
    start_contraction();
    bool ran = false;
    while(contraction_->contract()) // the samples are copied out once, at the end
      ran = true;
    if(ran || !contracted_)
      take_contracted_samples();
  }

  /// Builds the final skeleton from the contracted samples (`build_skeleton_graph()`),
  /// assigns every non-outlier input point to its nearest vertex (a point left out by the
  /// density cap, to that of its representative), and attaches by one edge
  /// each piece whose points span at most a third of another piece's extent and come
  /// nearer to it than their own extent (a fragment whose connection the scan missed).
  void convert_to_skeleton()
  {
    if(skeleton_)
      return;
    contract_until_convergence();
    skeleton_ = std::make_unique<Skeleton>(DF_L1::build_skeleton_graph(*contracted_, *field_, *initial_));
    assign_points(*skeleton_);
    // A piece much smaller than another and near it is a fragment of it whose connection
    // the scan missed (`internal::attach_fragments()`).
    if(DF_L1::skeleton_statistics(*skeleton_).components > 1)
      DF_L1::internal::attach_fragments(
        *skeleton_, DF_L1::internal::to_xyz(denoised_ ? smoothed_input_points() : points_, CGAL::Identity_property_map<Point>()));
  }

  /// Runs every stage that has not run and copies the final skeleton into `skeleton`.
  void operator()(Skeleton& skeleton)
  {
    skeleton = this->skeleton();
  }
  /// @}

  /// \name Results
  /// Each runs the stages it needs.
  /// @{
  /// the input points, in input order, as the stages see them: mapped back from their
  /// frame, within 2.3e-10 of the bounding box diagonal of the given points
  const std::vector<Point>& input_points() const { return in_input_units(input_points_, points_); }
  /// the number of input points
  std::size_t number_of_input_points() const { return points_.size(); }
  /// one flag per input point: scattered outliers and points of outlier voxels (or of no
  /// voxel; a smoothed cloud's points are located at their smoothed positions)
  const std::vector<bool>& outlier_flags() { remove_outlier_voxels(); return outliers_; }
  /// number of input points flagged as outliers
  std::size_t number_of_outliers() { remove_outlier_voxels(); return outlier_count_; }
  /// number of input points flagged by `flag_sparse_outliers()` alone
  std::size_t number_of_sparse_outliers() { flag_outliers(); return sparse_outlier_count_; }
  /// the number of input points that the stages from the smoothing to the contraction
  /// analyse: those not flagged as scattered outliers, or their representatives in a
  /// cloud denser than its voxels can show (`denoise()`)
  std::size_t number_of_analysed_points()
  {
    denoise();
    return kept_points_.size();
  }
  /// the estimated noise of the surface, input units (`estimate_surface_noise()`)
  double surface_noise() { denoise(); return normalization_.to_input(surface_noise_); }
  /// how the noise estimate grows from 10 to 40 neighbours per fit; the points are
  /// smoothed automatically only below 3 (see `denoise()`). Measured only when the
  /// smoothing is automatic and the noise estimate exceeds its threshold; 0 otherwise.
  double residual_growth() { denoise(); return residual_growth_; }
  /// whether the points were smoothed before voxelization
  bool denoised() { denoise(); return denoised_; }
  /// the points that are not scattered outliers, in input order, at the positions the
  /// later stages use (smoothed when `denoised()`); in a cloud denser than its voxels, only
  /// the representatives (`number_of_analysed_points()`)
  const std::vector<Point>& kept_points() { denoise(); return in_input_units(kept_points_in_input_units_, kept_points_); }
  /// the points added in sparse regions
  const std::vector<Point>& added_points() { upsample(); return in_input_units(added_points_in_input_units_, added_points_); }
  /// the voxels after outlier removal
  const Voxel_grid& voxel_grid() { remove_outlier_voxels(); return in_input_units(grid_in_input_units_, *grid_); }
  /// what the outlier voxel removal found
  const DF_L1::Outlier_voxel_statistics& outlier_voxel_statistics() { remove_outlier_voxels(); return outlier_voxel_statistics_; }
  /// the distance field
  const Distance_field& distance_field() { compute_distance_field(); return in_input_units(field_in_input_units_, *field_); }
  /// the initial skeleton: the skeleton voxels S and a curve graph through them
  const Initial_skeleton& initial_skeleton() { extract_initial_skeleton(); return in_input_units(initial_in_input_units_, *initial_); }
  /// the contracted samples, their branches, and the samples after every iteration: as
  /// the stages run by `contract()` left them, or all stages when the contraction has not
  /// started
  const Contracted_samples& contracted_samples()
  {
    if(!contracted_)
      contract_until_convergence();
    return in_input_units(contracted_in_input_units_, *contracted_);
  }
  /// the final skeleton
  const Skeleton& skeleton() { convert_to_skeleton(); return in_input_units(skeleton_in_input_units_, *skeleton_); }
  /// @}

  /// \name Parameters
  /// The getters return the values the stages use: the derived defaults are resolved
  /// (which runs the stages they derive from). Each setter checks its value (throwing
  /// `DF_L1::Invalid_input` out of range, as the constructor does) and discards the
  /// results of the stages that depend on it; the next stage function recomputes them.
  /// @{
  double bbox_diagonal() const { return normalization_.to_input(diagonal_); } ///< d_bb
  /// the parameters as given (derived lengths left empty when they were not set)
  const DF_L1::Parameters& parameters() const { return parameters_; }
  /// sets every parameter at once, discarding the results from the first stage whose
  /// parameters changed
  void set_parameters(const DF_L1::Parameters& p)
  {
    DF_L1::check_parameters(p, stage_name);
    check_volume(p.voxel_resolution);
    int first = number_of_stages;
    for(const DF_L1::Parameter_info& info : DF_L1::parameter_table())
    {
      const bool given_before = info.given == nullptr || info.given(parameters_);
      const bool given_after = info.given == nullptr || info.given(p);
      if(given_before != given_after || (given_after && info.read(parameters_) != info.read(p)))
        first = (std::min)(first, stage_index(info.stage));
    }
    parameters_ = p;
    discard_from(first);
  }

  DF_L1::Denoising denoising() const { return parameters_.denoising; } ///< when the points are smoothed
  void set_denoising(DF_L1::Denoising d) { set([&](DF_L1::Parameters& p) { p.denoising = d; }); } ///< \sa `denoising()`
  unsigned int denoising_neighbors() const { return unsigned(parameters_.denoising_neighbors); } ///< k of the local quadrics
  void set_denoising_neighbors(int k) { set([&](DF_L1::Parameters& p) { p.denoising_neighbors = k; }); } ///< \sa `denoising_neighbors()`
  bool upsampling() const { return parameters_.upsampling; } ///< whether sparse regions are upsampled
  void set_upsampling(bool on) { set([&](DF_L1::Parameters& p) { p.upsampling = on; }); } ///< \sa `upsampling()`
  int upsampling_neighbors() const { return parameters_.upsampling_neighbors; } ///< k of the density test
  void set_upsampling_neighbors(int k) { set([&](DF_L1::Parameters& p) { p.upsampling_neighbors = k; }); } ///< \sa `upsampling_neighbors()`
  /// r of the density test (input units; default 3 d_bb / cbrt(N), N the input points, or
  /// the analysed points of a cloud denser than its voxels once `denoise()` has run)
  double upsampling_radius() const { return normalization_.to_input(internal_upsampling_radius()); }
  void set_upsampling_radius(double r) { set([&](DF_L1::Parameters& p) { p.upsampling_radius = r; }); } ///< \sa `upsampling_radius()`
  int voxel_resolution() const { return parameters_.voxel_resolution; } ///< V
  /// the best estimate so far of the peak memory of the whole skeletonization, in bytes
  /// (\ref memory): until the initial skeleton starts, `initial_estimated_peak_memory()`;
  /// from then on, the estimate refined from the distance field (the voxels of the grid as
  /// built, its interior voxels, whether the cloud was smoothed), and once the initial
  /// skeleton knows it, whether its graph repairs run. Changing a parameter of a stage
  /// up to the initial skeleton goes back to the initial estimate.
  double estimated_peak_memory() const { return memory_estimate().bytes(); }
  /// the estimate of the peak memory from the parameters and the number of points
  /// alone, in bytes, as the constructor checks it: linear in the points and in the
  /// voxels of the finest grid (their coefficients measured on the tool, which holds a
  /// copy of the points too; \ref memory)
  double initial_estimated_peak_memory() const { return initial_memory_estimate().bytes(); }
  /// the limit of `estimated_peak_memory()`, in bytes (`max_memory`)
  double max_memory() const { return max_memory_; }
  /// Sets the limit of `estimated_peak_memory()` checked before the voxelization and
  /// the initial skeleton.
  /// \throws DF_L1::Invalid_input if `bytes` is not > 0
  void set_max_memory(double bytes)
  {
    if(!(bytes > 0))
      throw DF_L1::Invalid_input("skeletonization: max_memory must be a positive number of bytes");
    max_memory_ = bytes;
  }
  void set_voxel_resolution(int V) { set([&](DF_L1::Parameters& p) { p.voxel_resolution = V; }); } ///< \sa `voxel_resolution()`
  /// s0, the size of the coarsest voxels before rounding (input units; default d_bb / 9)
  double initial_voxel_size() const { return normalization_.to_input(internal_initial_voxel_size()); }
  void set_initial_voxel_size(double s0) { set([&](DF_L1::Parameters& p) { p.initial_voxel_size = s0; }); } ///< \sa `initial_voxel_size()`
  int exterior_propagation_steps() const { return parameters_.exterior_propagation_steps; } ///< exterior steps per level
  /// \sa `exterior_propagation_steps()`
  void set_exterior_propagation_steps(int n) { set([&](DF_L1::Parameters& p) { p.exterior_propagation_steps = n; }); }
  /// the largest extent of a removable outlier cluster, in voxels (default max(3, V'/10),
  /// V' the longest side of the grid, known once the voxels exist)
  int outlier_component_size() { voxelize(); return resolved_outlier_component_size(); }
  /// \sa `outlier_component_size()`
  void set_outlier_component_size(int voxels) { set([&](DF_L1::Parameters& p) { p.outlier_component_size = voxels; }); }
  double thinning_coefficient() const { return parameters_.thinning_coefficient; } ///< c of Eq. 2
  void set_thinning_coefficient(double c) { set([&](DF_L1::Parameters& p) { p.thinning_coefficient = c; }); } ///< \sa `thinning_coefficient()`
  double spur_length_ratio() const { return parameters_.spur_length_ratio; } ///< spur pruning of the initial graph
  void set_spur_length_ratio(double x) { set([&](DF_L1::Parameters& p) { p.spur_length_ratio = x; }); } ///< \sa `spur_length_ratio()`
  DF_L1::Skeletonization_method skeletonization_method() const { return parameters_.skeletonization_method; } ///< refinement method
  /// \sa `skeletonization_method()`
  void set_skeletonization_method(DF_L1::Skeletonization_method m) { set([&](DF_L1::Parameters& p) { p.skeletonization_method = m; }); }
  std::size_t number_of_samples() const { return parameters_.number_of_samples; } ///< M requested (at most the points are used)
  void set_number_of_samples(std::size_t m) { set([&](DF_L1::Parameters& p) { p.number_of_samples = m; }); } ///< \sa `number_of_samples()`
  double repulsion_coefficient() const { return parameters_.repulsion_coefficient; } ///< u of Eq. 8
  void set_repulsion_coefficient(double u) { set([&](DF_L1::Parameters& p) { p.repulsion_coefficient = u; }); } ///< \sa `repulsion_coefficient()`
  /// h0, the initial support radius (input units; default 2 d_bb / cbrt(N), N the kept
  /// and added points, known once upsampled)
  double initial_support_radius() { upsample(); return normalization_.to_input(internal_initial_support_radius()); }
  void set_initial_support_radius(double h) { set([&](DF_L1::Parameters& p) { p.initial_support_radius = h; }); } ///< \sa `initial_support_radius()`
  double support_radius_growth() const { return parameters_.support_radius_growth; } ///< growth ratio of h between stages
  void set_support_radius_growth(double r) { set([&](DF_L1::Parameters& p) { p.support_radius_growth = r; }); } ///< \sa `support_radius_growth()`
  double branch_directionality() const { return parameters_.branch_directionality; } ///< sigma threshold of branch points
  void set_branch_directionality(double s) { set([&](DF_L1::Parameters& p) { p.branch_directionality = s; }); } ///< \sa `branch_directionality()`
  int number_of_iterations() const { return parameters_.number_of_iterations; } ///< maximum iterations per stage
  void set_number_of_iterations(int n) { set([&](DF_L1::Parameters& p) { p.number_of_iterations = n; }); } ///< \sa `number_of_iterations()`
  int contraction_stages() const { return parameters_.contraction_stages; } ///< maximum support-radius stages
  void set_contraction_stages(int n) { set([&](DF_L1::Parameters& p) { p.contraction_stages = n; }); } ///< \sa `contraction_stages()`
  /// @}

private:
  static constexpr const char* stage_name = "skeletonization"; // in error messages

  // The stage functions in pipeline order, as `DF_L1::Parameter_info::stage` names them.
  static constexpr int number_of_stages = 9;
  static int stage_index(const char* stage)
  {
    static const char* const stages[number_of_stages] = {"flag_outliers", "denoise", "upsample", "voxelize",
                                                         "remove_outlier_voxels", "compute_distance_field",
                                                         "extract_initial_skeleton", "contract", "convert_to_skeleton"};
    for(int i = 0; i < number_of_stages; ++i)
      if(std::string(stage) == stages[i])
        return i;
    return 0;
  }

  // Picks the samples, once per contraction.
  void start_contraction()
  {
    if(contraction_)
      return;
    extract_initial_skeleton();
    contraction_ = std::make_unique<Sample_contraction>(
      kept_and_added_points(), *field_, *initial_,
      parameters::skeletonization_method(parameters_.skeletonization_method,
      parameters::repulsion_coefficient(parameters_.repulsion_coefficient,
      parameters::initial_support_radius(internal_initial_support_radius(),
      parameters::support_radius_growth(parameters_.support_radius_growth,
      parameters::branch_directionality(parameters_.branch_directionality,
      parameters::contraction_stages(parameters_.contraction_stages,
      parameters::number_of_iterations(parameters_.number_of_iterations)
        .number_of_samples(parameters_.number_of_samples))))))));
  }

  // The samples as the contraction left them; the skeleton built from older ones goes.
  void take_contracted_samples()
  {
    contracted_ = std::make_unique<Contracted_samples>(contraction_->result());
    contracted_in_input_units_.reset();
    skeleton_.reset();
    skeleton_in_input_units_.reset();
  }

  // Changes a copy of the parameters and sets it.
  template <class Change>
  void set(Change change)
  {
    DF_L1::Parameters p = parameters_;
    change(p);
    set_parameters(p);
  }

  // Discards the results of the stage `first` (in the order of stage_index()) and after.
  void discard_from(int first)
  {
    if(first <= 0)
    {
      sparse_outliers_.clear();
      sparse_outlier_count_ = 0;
    }
    if(first <= 1)
    {
      denoise_checked_ = denoised_ = false;
      density_cap_ = DF_L1::internal::Density_cap();
      surface_noise_ = residual_growth_ = 0;
      kept_points_.clear();
      kept_points_in_input_units_.reset();
    }
    if(first <= 2)
    {
      upsampled_ = false;
      added_points_.clear();
      added_points_in_input_units_.reset();
    }
    if(first <= 3)
      raw_grid_.reset();
    if(first <= 4)
    {
      grid_.reset();
      grid_in_input_units_.reset();
      outliers_.clear();
      outlier_count_ = 0;
    }
    if(first <= 5)
    {
      field_.reset();
      field_in_input_units_.reset();
    }
    if(first <= 6)
    {
      refined_memory_.reset();
      initial_.reset();
      initial_in_input_units_.reset();
    }
    if(first <= 7)
    {
      contraction_.reset();
      contracted_.reset();
      contracted_in_input_units_.reset();
    }
    if(first <= 8)
    {
      skeleton_.reset();
      skeleton_in_input_units_.reset();
    }
  }

  // The RMS distance of the points to their best-fitting plane (the smallest standard
  // deviation of their covariance).
  static double rms_distance_to_best_plane(const std::vector<Point>& points)
  {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for(const Point& p : points)
      mean += Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    mean /= double(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const Point& p : points)
    {
      const Eigen::Vector3d d = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())) - mean;
      covariance += d * d.transpose();
    }
    covariance /= double(points.size());
    return std::sqrt((std::max)(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvalues()(0)));
  }

  // Points on a plane (or a line) enclose no volume, yet the voxels between their samples
  // can look enclosed and give a meaningless skeleton: refuse them with a clear message.
  void check_volume(int voxel_resolution) const
  {
    if(thickness_ < 0.25 * (longest_side_ / voxel_resolution))
      throw DF_L1::Invalid_input("no skeleton: the " + std::to_string(points_.size()) +
                                 " points lie on a plane (RMS distance to it under a quarter of a voxel); they enclose no volume");
  }

  // The length parameters in the frame of the stages: as set, or derived from d_bb.
  double internal_upsampling_radius() const
  {
    return parameters_.upsampling_radius ? normalization_.to_internal(*parameters_.upsampling_radius)
                                         : DF_L1::internal::default_upsampling_radius(
                                             diagonal_, density_cap_.active() ? kept_points_.size() : points_.size());
  }
  // the constructor's estimate, from the parameters and the number of points
  DF_L1::internal::Memory_estimate initial_memory_estimate() const
  {
    return DF_L1::internal::initial_memory_estimate(
      double(points_.size()), DF_L1::internal::finest_voxel_count(extent_, parameters_.voxel_resolution));
  }
  // the best estimate so far
  DF_L1::internal::Memory_estimate memory_estimate() const
  {
    return refined_memory_ ? *refined_memory_ : initial_memory_estimate();
  }
  // Refines the estimate from the distance field, with or without the graph repairs of
  // the initial skeleton, and checks it.
  void refine_memory_estimate(bool repairs, const char* stage)
  {
    DF_L1::internal::Voxel_stage_counts counts;
    counts.points = double(points_.size());
    if(density_cap_.active())
      counts.analysed_points = double(kept_points_.size());
    counts.added_points = double(added_points_.size());
    counts.voxels = double(field_->size());
    counts.interior_voxels =
      double(std::count(field_->labels.begin(), field_->labels.end(), DF_L1::Voxel_label::INTERIOR));
    counts.grid_copy = grid_in_input_units_ != nullptr;
    counts.field_copy = field_in_input_units_ != nullptr;
    counts.denoised = denoised_;
    counts.repair = repairs;
    refined_memory_ = std::make_unique<DF_L1::internal::Memory_estimate>(DF_L1::internal::refined_memory_estimate(counts));
    DF_L1::internal::check_memory(*refined_memory_, max_memory_, parameters_.voxel_resolution, stage);
  }

  double internal_initial_voxel_size() const
  {
    return parameters_.initial_voxel_size ? normalization_.to_internal(*parameters_.initial_voxel_size)
                                          : DF_L1::internal::default_initial_voxel_size(diagonal_);
  }
  // h0 as set, or derived from the number of kept and added points (once upsampled)
  double internal_initial_support_radius() const
  {
    return parameters_.initial_support_radius
             ? normalization_.to_internal(*parameters_.initial_support_radius)
             : DF_L1::internal::default_initial_support_radius(diagonal_, kept_points_.size() + added_points_.size());
  }

  // A result of the stages in input units, mapped on the first request.
  template <class Result>
  const Result& in_input_units(std::unique_ptr<Result>& cache, const Result& result) const
  {
    if(!cache)
      cache = std::make_unique<Result>(normalization_.to_input(result));
    return *cache;
  }

  // the outlier size as set, or derived from the grid (once voxelized)
  int resolved_outlier_component_size() const
  {
    return parameters_.outlier_component_size ? *parameters_.outlier_component_size
                                              : DF_L1::internal::default_outlier_component_size(raw_grid_->dims);
  }

  // the input points, each non-outlier at its smoothed position (input order); a point
  // left out by the density cap at its owner's (within a cell diagonal: its own offset
  // would carry its noise, which the owner's smoothing did not see)
  std::vector<Point> smoothed_input_points() const
  {
    std::vector<Point> result = points_;
    std::size_t kept = 0;
    for(std::size_t i = 0; i < points_.size(); ++i)
      if(!sparse_outliers_[i] && density_cap_.is_representative(i))
        result[i] = kept_points_[kept++];
    if(density_cap_.active())
    {
      for(std::size_t i = 0; i < points_.size(); ++i)
      {
        if(sparse_outliers_[i] || density_cap_.is_representative(i))
          continue;
        result[i] = result[owner_of(i)];
      }
    }
    return result;
  }

  // The flags of the voxel test (`flag_outlier_points()`) of the input points `raw`.
  // The voxels of a smoothed cloud hold the smoothed positions, `smoothed` (one per raw
  // point); the noisy ones lie about the noise off that shell (judged there, half of a
  // noisy scan's points fell in empty voxels). A point that the smoothing moved by more
  // than 4 times the estimated noise (the fits' residual, which underestimates the noise
  // by about a fifth: some 3 sigma) was no noise of the surface but an outlier drawn
  // onto it.
  std::vector<bool> voxel_outlier_flags(const std::vector<Point>& raw, const std::vector<Point>* smoothed) const
  {
    if(!smoothed)
      return DF_L1::flag_outlier_points(raw, *grid_);
    std::vector<bool> flags = DF_L1::flag_outlier_points(*smoothed, *grid_);
    const double reach = 4 * surface_noise_;
    for(std::size_t i = 0; i < raw.size(); ++i)
      flags[i] = flags[i] || CGAL::to_double(CGAL::squared_distance(raw[i], (*smoothed)[i])) > reach * reach;
    return flags;
  }

  // the input points of the representatives of the density cap, in their order
  std::vector<Point> analysed_input_points() const
  {
    std::vector<Point> analysed;
    analysed.reserve(density_cap_.representatives().size());
    for(std::size_t i : density_cap_.representatives())
      analysed.push_back(points_[i]);
    return analysed;
  }

  // Assigns every non-outlier input point to its nearest vertex of `g`
  // (`assign_points_to_skeleton()`); through the density cap, the representatives, and
  // each point left out to the vertex of its representative.
  void assign_points(Skeleton& g) const
  {
    if(!density_cap_.active())
    {
      DF_L1::assign_points_to_skeleton<ConcurrencyTag>(points_, outliers_, g);
      return;
    }
    const std::vector<std::size_t>& representatives = density_cap_.representatives();
    std::vector<bool> analysed_outliers;
    analysed_outliers.reserve(representatives.size());
    for(std::size_t i : representatives)
      analysed_outliers.push_back(outliers_[i]);
    DF_L1::assign_points_to_skeleton<ConcurrencyTag>(analysed_input_points(), analysed_outliers, g);
    const std::size_t none = std::size_t(-1);
    std::vector<std::size_t> vertex_of(representatives.size(), none);
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
    {
      for(std::size_t r : g[v].points)
        vertex_of[r] = v;
      g[v].points.clear();
    }
    // the vertex of each point (in parallel), then the lists in point order
    const std::vector<std::size_t> vertex = for_each_left_out<std::size_t>(none, [&](std::size_t i) {
      return outliers_[i] ? none : vertex_of[owner_position(i)];
    });
    std::vector<std::size_t> count(boost::num_vertices(g), 0);
    for(std::size_t i = 0, r = 0; i < points_.size(); ++i)
    {
      const std::size_t v = density_cap_.is_representative(i) ? vertex_of[r++] : vertex[i];
      if(v != none)
        ++count[v];
    }
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
      g[v].points.reserve(count[v]);
    for(std::size_t i = 0, r = 0; i < points_.size(); ++i)
    {
      const std::size_t v = density_cap_.is_representative(i) ? vertex_of[r++] : vertex[i];
      if(v != none)
        g[v].points.push_back(i);
    }
  }

  // f(i) for every input point i left out by the density cap, in parallel, `other` for
  // the rest: one value per input point
  template <class T, class F>
  std::vector<T> for_each_left_out(T other, const F& f) const
  {
    static_assert(!std::is_same<T, bool>::value, "the values are written in parallel: not std::vector<bool>");
    std::vector<T> result(points_.size(), other);
    DF_L1::internal::for_each_range<ConcurrencyTag>(points_.size(), [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        if(!density_cap_.is_representative(i) && !sparse_outliers_[i])
          result[i] = f(i);
    }, 1 << 14);
    return result;
  }

  // A cloud is dense when it holds at least 1 / dense_share points per occupied cell of
  // a third of the finest voxel (the paper's 3 x 3 x 3 subdivision), in a lattice of at
  // most max_cells_per_point cells per point (beyond, the cloud is sparser than its
  // cells anyway, and their array would cost more than the points).
  static constexpr double dense_share = 0.5;
  // The closing of the cycle test after the gap cuts, in sampling spacings (the median
  // distance to the 6th neighbour): the holes narrower than about three samples.
  static constexpr double sampling_closing = 1.0;
  // The missing twigs of a smoothed cloud reach beyond the balls of the graph by 4 voxels
  // plus twice the noise estimate (a bump of the noise reaches about that far), and are
  // thicker than 2.5 noise estimates (about one deviation of the noise, which the fits
  // underestimate: estimate_surface_noise()).
  static constexpr double twig_reach_per_noise = 2.0, twig_radius_per_noise = 2.5;

  // The twigs that the thinning of a smoothed cloud lost: their flat, ragged tips are
  // eaten with the shell (\ref design_initial_skeleton). Branches through the occupied
  // voxels to the thin parts that reach beyond the balls of the graph
  // (`add_missing_branches()`), each kept only where the points around the part of it
  // beyond the balls form a tube apart from the rest, thicker than the noise could fake
  // (`points_surround_curve()`); the stub left where a curve had stopped short of the
  // new tip goes with the spur pruning.
  void add_missing_twigs(const std::vector<std::array<double, 3>>& xyz, const DF_L1::internal::Uniform_grid& points,
                         double voxel)
  {
    refine_memory_estimate(true, "initial skeleton (graph repairs)");
    const std::vector<float> depth = DF_L1::internal::occupied_depth(*field_);
    const std::vector<char> candidates = std::move(DF_L1::internal::thin_parts(*field_, 2.0, 4.0).voxels);
    if(std::find(candidates.begin(), candidates.end(), 1) == candidates.end())
      return;
    auto surrounded = [&](const std::vector<std::size_t>& path, std::size_t beyond) {
      std::vector<DF_L1::internal::Vec3> curve;
      std::vector<double> radius;
      for(std::size_t i = beyond; i < path.size(); ++i)
      {
        curve.push_back(DF_L1::internal::to_vec3(field_->center(path[i])));
        radius.push_back((std::max)(0.5, double(depth[path[i]]) - 0.5) * voxel);
      }
      return DF_L1::internal::points_surround_curve(curve, radius, xyz, points, voxel,
                                                    twig_radius_per_noise * surface_noise_);
    };
    if(DF_L1::internal::add_missing_branches(initial_->graph, *field_, depth, candidates,
                                             4.0 + twig_reach_per_noise * surface_noise_ / voxel, 1.0, 1.3, surrounded) > 0)
      DF_L1::internal::prune_spurs(initial_->graph, parameters_.spur_length_ratio, voxel, surface_noise_,
                                   DF_L1::internal::Point_support());
  }

  static constexpr double max_cells_per_point = 4;
  // the cells of the density cap; empty (size() 0) when there would be too many
  DF_L1::internal::Cell_lattice density_lattice() const
  {
    const DF_L1::internal::Cell_lattice lattice(box_min_, extent_, longest_side_ / (3.0 * parameters_.voxel_resolution));
    return lattice.cells() <= max_cells_per_point * double(points_.size()) ? lattice : DF_L1::internal::Cell_lattice();
  }
  // the coordinates of the input point i
  auto point_coordinates() const
  {
    return [this](std::size_t i) { return DF_L1::internal::to_vec3(points_[i]); };
  }

  // the position in density_cap_.representatives() of the representative that stands
  // for the input point i, left out by the density cap
  std::size_t owner_position(std::size_t i) const { return density_cap_.owner(DF_L1::internal::to_vec3(points_[i])); }
  // the input index of that representative
  std::size_t owner_of(std::size_t i) const { return density_cap_.representatives()[owner_position(i)]; }

  // the points the grid and the contraction are built from
  std::vector<Point> kept_and_added_points() const
  {
    std::vector<Point> all = kept_points_;
    all.insert(all.end(), added_points_.begin(), added_points_.end());
    return all;
  }

  // The stages' frame, and the results they keep in it (input points included).
  DF_L1::internal::Normalization normalization_;
  std::vector<Point> points_;
  double diagonal_ = 0, longest_side_ = 0; // of the points' bounding box
  double thickness_ = 0;                   // rms_distance_to_best_plane() of the points
  std::array<double, 3> box_min_ = {{0, 0, 0}}, extent_ = {{0, 0, 0}}; // of the bounding box of the points
  double max_memory_ = 0;
  std::unique_ptr<DF_L1::internal::Memory_estimate> refined_memory_; // from the distance field, once known
  DF_L1::Parameters parameters_;

  DF_L1::internal::Density_cap density_cap_; // the points the stages analyse
  std::vector<bool> sparse_outliers_, outliers_;
  std::size_t sparse_outlier_count_ = 0, outlier_count_ = 0;
  bool denoise_checked_ = false, denoised_ = false;
  double surface_noise_ = 0, residual_growth_ = 0;
  std::vector<Point> kept_points_; // the analysed points (not scattered outliers), smoothed when denoised
  bool upsampled_ = false;
  std::vector<Point> added_points_;
  std::unique_ptr<Voxel_grid> raw_grid_, grid_;
  DF_L1::Outlier_voxel_statistics outlier_voxel_statistics_;
  std::unique_ptr<Distance_field> field_;
  std::unique_ptr<Initial_skeleton> initial_;
  std::unique_ptr<Sample_contraction> contraction_; // the contraction in progress
  std::unique_ptr<Contracted_samples> contracted_;  // its samples after the last stage run
  std::unique_ptr<Skeleton> skeleton_;

  // The results in input units, as the getters return them (filled on request).
  mutable std::unique_ptr<std::vector<Point>> input_points_;
  std::unique_ptr<std::vector<Point>> kept_points_in_input_units_, added_points_in_input_units_;
  std::unique_ptr<Voxel_grid> grid_in_input_units_;
  std::unique_ptr<Distance_field> field_in_input_units_;
  std::unique_ptr<Initial_skeleton> initial_in_input_units_;
  std::unique_ptr<Contracted_samples> contracted_in_input_units_;
  std::unique_ptr<Skeleton> skeleton_in_input_units_;
};

} // namespace CGAL

#endif // CGAL_DF_L1_SKELETONIZATION_H
