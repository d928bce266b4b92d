// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_H
#define CGAL_DF_L1_SKELETON_H

/// \file DF_L1_skeleton.h
/// The public entry of the package: the `DF_L1_skeletonization` class, which runs the
/// stages of the method one by one and keeps every intermediate result.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/assign_points_to_skeleton.h>
#include <CGAL/DF_L1_skeleton/build_skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/contract_samples.h>
#include <CGAL/DF_L1_skeleton/denoise_point_set.h>
#include <CGAL/DF_L1_skeleton/distance_field.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/extract_initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/internal/point_gap_cuts.h>
#include <CGAL/DF_L1_skeleton/flag_sparse_outliers.h>
#include <CGAL/DF_L1_skeleton/internal/point_range.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>
#include <CGAL/DF_L1_skeleton/remove_outlier_voxels.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>
#include <CGAL/DF_L1_skeleton/upsample_sparse_regions.h>
#include <CGAL/DF_L1_skeleton/voxelize_point_set.h>

#include <CGAL/Named_function_parameters.h>

#include <Eigen/Dense>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cmath>
#include <iterator>
#include <memory>
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
/// \tparam Traits a model of `Kernel`
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`; results do not depend on the number of threads
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
  /// @}

  /// Copies the points and reads the parameters.
  ///
  /// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
  /// \param points the input points; normals are not needed
  /// \param np an optional sequence of named parameters among `point_map` and the
  ///        parameters of the stages: `denoising`, `denoising_neighbors`,
  ///        `voxel_resolution`, `initial_voxel_size`,
  ///        `exterior_propagation_steps`, `upsampling`, `upsampling_neighbors`,
  ///        `upsampling_radius`, `outlier_component_size`, `thinning_coefficient`,
  ///        `spur_length_ratio`, `skeletonization_method`, `number_of_samples`,
  ///        `repulsion_coefficient`, `initial_support_radius`, `support_radius_growth`,
  ///        `branch_directionality`, `number_of_iterations`, `contraction_stages` (see `voxelize_point_set()`,
  ///        `denoise_point_set()`, `upsample_sparse_regions()`, `remove_outlier_voxels()`,
  ///        `extract_initial_skeleton()` and `contract_samples()` for their meaning and
  ///        defaults); the initial skeleton's `thin_parts`, `occupied_depth` and
  ///        `surface_noise` are set by the class: `thin_parts` on exactly when the cloud
  ///        was not smoothed (`denoised()`), `occupied_depth` on exactly when it was,
  ///        `surface_noise` to `surface_noise()`
  /// \throws DF_L1::Invalid_input if the range is empty, holds a non-finite coordinate,
  ///         all its points coincide or lie on a plane (within a quarter of a voxel, RMS),
  ///         or a parameter is out of range
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
  explicit DF_L1_skeletonization(const PointRange& points, const NamedParameters& np = parameters::default_values())
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    typedef Point_set_processing_3_np_helper<const PointRange, NamedParameters> NP_helper;
    const auto point_map = NP_helper::get_const_point_map(points, np);
    for(const auto& p : points)
      points_.push_back(get(point_map, p));
    const CGAL::Bbox_3 box = DF_L1::internal::checked_bbox(points_, CGAL::Identity_property_map<Point>(), stage_name);
    if(!(DF_L1::internal::longest_side(box) > 0))
      throw DF_L1::Invalid_input(std::string(stage_name) + ": all " + std::to_string(points_.size()) +
                                 " points coincide; there is no shape to skeletonize");
    diagonal_ = DF_L1::internal::diagonal(box);

    voxel_resolution_ = DF_L1::internal::voxel_resolution(np, stage_name);
    check_volume(DF_L1::internal::longest_side(box) / voxel_resolution_);
    initial_voxel_size_ = DF_L1::internal::initial_voxel_size(np, diagonal_, stage_name);
    exterior_propagation_steps_ = DF_L1::internal::exterior_propagation_steps(np, stage_name);
    denoising_ = DF_L1::internal::denoising(np);
    denoising_neighbors_ = DF_L1::internal::denoising_neighbors(np, stage_name);
    upsampling_ = choose_parameter(get_parameter(np, internal_np::df_l1_upsampling), true);
    upsampling_neighbors_ = DF_L1::internal::upsampling_neighbors(np, stage_name);
    upsampling_radius_ = DF_L1::internal::upsampling_radius(np, diagonal_, points_.size(), stage_name);
    // The default of the outlier size derives from the grid, known after voxelization.
    outlier_component_size_set_ =
      !parameters::is_default_parameter<NamedParameters, internal_np::df_l1_outlier_component_size_t>::value;
    if(outlier_component_size_set_)
      outlier_component_size_ = DF_L1::internal::check_outlier_component_size(
        choose_parameter(get_parameter(np, internal_np::df_l1_outlier_component_size), 0), stage_name);
    thinning_coefficient_ = DF_L1::internal::thinning_coefficient(np, stage_name);
    spur_length_ratio_ = DF_L1::internal::spur_length_ratio(np, stage_name);
    method_ = DF_L1::internal::skeletonization_method(np);
    number_of_samples_ = parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_samples), std::size_t(1500));
    DF_L1::internal::number_of_samples(np, points_.size(), stage_name); // range check
    repulsion_coefficient_ = DF_L1::internal::repulsion_coefficient(np, stage_name);
    initial_support_radius_set_ =
      !parameters::is_default_parameter<NamedParameters, internal_np::df_l1_support_radius_t>::value;
    if(initial_support_radius_set_)
      initial_support_radius_ = DF_L1::internal::check_initial_support_radius(
        choose_parameter(get_parameter(np, internal_np::df_l1_support_radius), 1.0), stage_name);
    support_radius_growth_ = DF_L1::internal::support_radius_growth(np, stage_name);
    branch_directionality_ = DF_L1::internal::branch_directionality(np, stage_name);
    iterations_per_stage_ = DF_L1::internal::iterations_per_stage(np, stage_name);
    contraction_stages_ = DF_L1::internal::contraction_stages(np, stage_name);
  }

  /// \name Stages
  /// Each runs the stages before it when they have not run yet, and does nothing when
  /// it has already run.
  /// @{

  /// Flags the scattered outliers (`flag_sparse_outliers()`).
  void flag_outliers()
  {
    if(!sparse_outliers_.empty())
      return;
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
    kept_points_.clear();
    for(std::size_t i = 0; i < points_.size(); ++i)
      if(!sparse_outliers_[i])
        kept_points_.push_back(points_[i]);
    // one fitter, and so one grid, for the noise estimate and the smoothing (the points
    // were checked by flag_outliers())
    const DF_L1::internal::Local_quadric_fitter<Traits> fitter(kept_points_);
    surface_noise_ = DF_L1::internal::surface_noise<ConcurrencyTag>(fitter);
    const double finest_voxel = DF_L1::internal::longest_side(
      CGAL::bbox_3(points_.begin(), points_.end())) / voxel_resolution_;
    const bool noisy = denoising_ == DF_L1::Denoising::AUTOMATIC && surface_noise_ > 0.2 * finest_voxel;
    residual_growth_ = noisy ? DF_L1::internal::residual_growth<ConcurrencyTag>(fitter) : 0.0;
    denoised_ = denoising_ == DF_L1::Denoising::ALWAYS || (noisy && residual_growth_ < 3);
    if(denoised_)
      kept_points_ = DF_L1::internal::smoothed_points<ConcurrencyTag>(fitter, kept_points_, denoising_neighbors_);
    denoise_checked_ = true;
  }

  /// Adds points in the sparse regions of the kept points (`upsample_sparse_regions()`),
  /// unless upsampling is off.
  void upsample()
  {
    if(upsampled_)
      return;
    denoise();
    if(upsampling_)
    {
      DF_L1::upsample_sparse_regions<ConcurrencyTag>(
        kept_points_, std::back_inserter(added_points_),
        parameters::upsampling_neighbors(upsampling_neighbors_,
        parameters::upsampling_radius(upsampling_radius_,
        parameters::voxel_resolution(voxel_resolution_))));
    }
    upsampled_ = true;
  }

  /// Voxelizes the kept and added points (`voxelize_point_set()`), without opening the
  /// crotches (`open_crotches`) in the clouds it smoothed.
  void voxelize()
  {
    if(raw_grid_)
      return;
    upsample();
    raw_grid_ = std::make_unique<Voxel_grid>(DF_L1::voxelize_point_set<ConcurrencyTag>(
      kept_and_added_points(), parameters::voxel_resolution(voxel_resolution_,
           parameters::initial_voxel_size(initial_voxel_size_,
           parameters::exterior_propagation_steps(exterior_propagation_steps_,
           parameters::open_crotches(!denoised_))))));
  }

  /// Removes the outlier voxels (`remove_outlier_voxels()`) and flags their points.
  void remove_outlier_voxels()
  {
    if(grid_)
      return;
    voxelize();
    if(!outlier_component_size_set_)
      outlier_component_size_ =
        DF_L1::internal::outlier_component_size(parameters::default_values(), raw_grid_->dims, stage_name);
    grid_ = std::make_unique<Voxel_grid>(DF_L1::remove_outlier_voxels(
      *raw_grid_, parameters::outlier_component_size(outlier_component_size_), &outlier_voxel_statistics_));
    outliers_ = DF_L1::flag_outlier_points(points_, *grid_);
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
  /// (parts 1 or 2 voxels apart), and assigns every non-outlier input point to its
  /// nearest vertex of the graph.
  void extract_initial_skeleton()
  {
    if(initial_)
      return;
    compute_distance_field();
    initial_ = std::make_unique<Initial_skeleton>(DF_L1::extract_initial_skeleton(
      *field_, parameters::thinning_coefficient(thinning_coefficient_,
               parameters::spur_length_ratio(spur_length_ratio_, parameters::thin_parts(!denoised_, parameters::occupied_depth(denoised_,
               parameters::surface_noise(surface_noise_)))))));
    // The cycles through gaps between parts that the voxels could not separate are cut
    // where the points show the gap (`internal::cut_point_gaps()`); the stubs that are
    // left go through the spur pruning again.
    if(DF_L1::skeleton_statistics(initial_->graph).cycles > 0)
    {
      const std::vector<std::array<double, 3>> xyz =
        DF_L1::internal::to_xyz(kept_points_, CGAL::Identity_property_map<Point>());
      const double voxel = CGAL::to_double(field_->voxel_size);
      const DF_L1::internal::Uniform_grid grid(xyz, 2 * voxel);
      const double spacing = DF_L1::internal::median_kth_neighbour_distance(xyz, 6, voxel / 2, grid);
      if(DF_L1::internal::cut_point_gaps(initial_->graph, xyz, grid, voxel, spacing) > 0)
        DF_L1::internal::prune_spurs(initial_->graph, spur_length_ratio_, voxel, surface_noise_);
    }
    DF_L1::assign_points_to_skeleton<ConcurrencyTag>(points_, outliers_, initial_->graph);
  }

  /// Contracts samples of the kept and added points onto the skeleton
  /// (`contract_samples()`), tracing branches and bridges between stages.
  void contract()
  {
    if(contracted_)
      return;
    extract_initial_skeleton();
    const std::vector<Point> all = kept_and_added_points();
    contracted_ = std::make_unique<Contracted_samples>(DF_L1::contract_samples<ConcurrencyTag>(
      all, *field_, *initial_,
      parameters::skeletonization_method(method_,
      parameters::repulsion_coefficient(repulsion_coefficient_,
      parameters::initial_support_radius(resolved_initial_support_radius(),
      parameters::support_radius_growth(support_radius_growth_,
      parameters::branch_directionality(branch_directionality_,
      parameters::contraction_stages(contraction_stages_,
      parameters::number_of_iterations(iterations_per_stage_).number_of_samples(number_of_samples_)))))))));
  }

  /// Builds the final skeleton from the contracted samples (`build_skeleton_graph()`)
  /// and assigns every non-outlier input point to its nearest vertex.
  void convert_to_skeleton()
  {
    if(skeleton_)
      return;
    contract();
    skeleton_ = std::make_unique<Skeleton>(DF_L1::build_skeleton_graph(*contracted_, *field_, *initial_));
    DF_L1::assign_points_to_skeleton<ConcurrencyTag>(points_, outliers_, *skeleton_);
  }

  /// Runs every stage that has not run and copies the final skeleton into `skeleton`.
  void operator()(Skeleton& skeleton)
  {
    convert_to_skeleton();
    skeleton = *skeleton_;
  }
  /// @}

  /// \name Results
  /// Each runs the stages it needs.
  /// @{
  const std::vector<Point>& input_points() const { return points_; } ///< the input points, in input order
  /// one flag per input point: scattered outliers and points of outlier voxels
  const std::vector<bool>& outlier_flags() { remove_outlier_voxels(); return outliers_; }
  /// number of input points flagged as outliers
  std::size_t number_of_outliers() { remove_outlier_voxels(); return outlier_count_; }
  /// number of input points flagged by `flag_sparse_outliers()` alone
  std::size_t number_of_sparse_outliers() { flag_outliers(); return sparse_outlier_count_; }
  /// the estimated noise of the surface, input units (`estimate_surface_noise()`)
  double surface_noise() { denoise(); return surface_noise_; }
  /// how the noise estimate grows from 10 to 40 neighbours per fit; the points are
  /// smoothed automatically only below 3 (see `denoise()`). Measured only when the
  /// smoothing is automatic and the noise estimate exceeds its threshold; 0 otherwise.
  double residual_growth() { denoise(); return residual_growth_; }
  /// whether the points were smoothed before voxelization
  bool denoised() { denoise(); return denoised_; }
  /// the points that are not scattered outliers, in input order, at the positions the
  /// later stages use (smoothed when `denoised()`)
  const std::vector<Point>& kept_points() { denoise(); return kept_points_; }
  /// the points added in sparse regions
  const std::vector<Point>& added_points() { upsample(); return added_points_; }
  /// the voxels after outlier removal
  const Voxel_grid& voxel_grid() { remove_outlier_voxels(); return *grid_; }
  /// what the outlier voxel removal found
  const DF_L1::Outlier_voxel_statistics& outlier_voxel_statistics() { remove_outlier_voxels(); return outlier_voxel_statistics_; }
  /// the distance field
  const Distance_field& distance_field() { compute_distance_field(); return *field_; }
  /// the initial skeleton: the skeleton voxels S and a curve graph through them
  const Initial_skeleton& initial_skeleton() { extract_initial_skeleton(); return *initial_; }
  /// the contracted samples, their branches, and the samples after every iteration
  const Contracted_samples& contracted_samples() { contract(); return *contracted_; }
  /// the final skeleton
  const Skeleton& skeleton() { convert_to_skeleton(); return *skeleton_; }
  /// @}

  /// \name Parameters in use
  /// Derived defaults are resolved: these are the values the stages use.
  /// @{
  double bbox_diagonal() const { return diagonal_; }                      ///< d_bb
  int voxel_resolution() const { return voxel_resolution_; }              ///< V
  double initial_voxel_size() const { return initial_voxel_size_; }       ///< s0 before rounding
  int exterior_propagation_steps() const { return exterior_propagation_steps_; } ///< exterior steps per level
  DF_L1::Denoising denoising() const { return denoising_; } ///< when the points are smoothed
  unsigned int denoising_neighbors() const { return denoising_neighbors_; } ///< k of the local quadrics
  bool upsampling() const { return upsampling_; } ///< whether sparse regions are upsampled
  int upsampling_neighbors() const { return upsampling_neighbors_; } ///< k of the density test
  double upsampling_radius() const { return upsampling_radius_; } ///< r of the density test
  /// the largest extent of a removable outlier cluster, in voxels (derived from the grid
  /// once the voxels exist)
  int outlier_component_size() { remove_outlier_voxels(); return outlier_component_size_; }
  double thinning_coefficient() const { return thinning_coefficient_; } ///< c of Eq. 2
  double spur_length_ratio() const { return spur_length_ratio_; } ///< spur pruning of the initial graph
  DF_L1::Skeletonization_method skeletonization_method() const { return method_; } ///< refinement method
  std::size_t number_of_samples() const { return number_of_samples_; } ///< M requested (at most the points are used)
  double repulsion_coefficient() const { return repulsion_coefficient_; } ///< u of Eq. 8
  /// h0, the initial support radius (input units; derived from the kept and added points
  /// once they are known)
  double initial_support_radius() { upsample(); return resolved_initial_support_radius(); }
  double support_radius_growth() const { return support_radius_growth_; } ///< growth ratio of h between stages
  double branch_directionality() const { return branch_directionality_; } ///< sigma threshold of branch points
  int number_of_iterations() const { return iterations_per_stage_; } ///< maximum iterations per stage
  int contraction_stages() const { return contraction_stages_; } ///< maximum support-radius stages
  /// @}

  /// \name Setting derived parameters
  /// Each discards the results of the stages that depend on the parameter.
  /// @{

  /// sets s0, the size of the coarsest voxels before rounding (input units)
  void set_initial_voxel_size(double s0)
  {
    initial_voxel_size_ = DF_L1::internal::check_initial_voxel_size(s0, stage_name);
    discard_from_voxelization();
  }
  /// sets r, the radius of the density test of the upsampling (input units)
  void set_upsampling_radius(double r)
  {
    upsampling_radius_ = DF_L1::internal::check_upsampling_radius(r, stage_name);
    upsampled_ = false;
    added_points_.clear();
    discard_from_voxelization();
  }
  /// sets h0, the initial support radius of the contraction (input units)
  void set_initial_support_radius(double h)
  {
    initial_support_radius_ = DF_L1::internal::check_initial_support_radius(h, stage_name);
    initial_support_radius_set_ = true;
    contracted_.reset();
    skeleton_.reset();
  }
  /// sets the largest extent of a removable outlier cluster, in voxels
  void set_outlier_component_size(int voxels)
  {
    outlier_component_size_ = DF_L1::internal::check_outlier_component_size(voxels, stage_name);
    outlier_component_size_set_ = true;
    grid_.reset();
    field_.reset();
    initial_.reset();
    contracted_.reset();
    skeleton_.reset();
  }
  /// @}

private:
  static constexpr const char* stage_name = "skeletonization"; // in error messages

  void discard_from_voxelization()
  {
    raw_grid_.reset();
    grid_.reset();
    field_.reset();
    initial_.reset();
    contracted_.reset();
    skeleton_.reset();
  }

  // Points on a plane (or a line) enclose no volume, yet the voxels between their samples
  // can look enclosed and give a meaningless skeleton: refuse them with a clear message.
  void check_volume(double voxel_size) const
  {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for(const Point& p : points_)
      mean += Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    mean /= double(points_.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const Point& p : points_)
    {
      const Eigen::Vector3d d = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())) - mean;
      covariance += d * d.transpose();
    }
    covariance /= double(points_.size());
    const double thickness = std::sqrt((std::max)(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvalues()(0)));
    if(thickness < 0.25 * voxel_size)
      throw DF_L1::Invalid_input("no skeleton: the " + std::to_string(points_.size()) +
                                 " points lie on a plane (RMS distance to it under a quarter of a voxel); they enclose no volume");
  }

  // h0 as set, or derived from the number of kept and added points (once upsampled)
  double resolved_initial_support_radius() const
  {
    if(initial_support_radius_set_)
      return initial_support_radius_;
    return DF_L1::internal::initial_support_radius(parameters::default_values(), diagonal_,
                                                   kept_points_.size() + added_points_.size(), stage_name);
  }

  // the points the grid and the contraction are built from
  std::vector<Point> kept_and_added_points() const
  {
    std::vector<Point> all = kept_points_;
    all.insert(all.end(), added_points_.begin(), added_points_.end());
    return all;
  }

  std::vector<Point> points_;
  double diagonal_ = 0;
  int voxel_resolution_ = 100;
  double initial_voxel_size_ = 0;
  int exterior_propagation_steps_ = 1;
  DF_L1::Denoising denoising_ = DF_L1::Denoising::AUTOMATIC;
  unsigned int denoising_neighbors_ = 24;
  bool upsampling_ = true;
  int upsampling_neighbors_ = 5;
  double upsampling_radius_ = 0;
  int outlier_component_size_ = 0;
  bool outlier_component_size_set_ = false; // otherwise derived from the grid
  double thinning_coefficient_ = 0.86;
  double spur_length_ratio_ = 1;
  DF_L1::Skeletonization_method method_ = DF_L1::Skeletonization_method::DISTANCE_FIELD_GUIDED;
  std::size_t number_of_samples_ = 1500;
  double repulsion_coefficient_ = 0.35;
  double initial_support_radius_ = 0;
  bool initial_support_radius_set_ = false; // otherwise derived from the kept and added points
  double support_radius_growth_ = 0.5;
  double branch_directionality_ = 0.9;
  int iterations_per_stage_ = 30;
  int contraction_stages_ = 64;

  std::vector<bool> sparse_outliers_, outliers_;
  std::size_t sparse_outlier_count_ = 0, outlier_count_ = 0;
  bool denoise_checked_ = false, denoised_ = false;
  double surface_noise_ = 0, residual_growth_ = 0;
  std::vector<Point> kept_points_; // the points that are not scattered outliers, smoothed when denoised
  bool upsampled_ = false;
  std::vector<Point> added_points_;
  std::unique_ptr<Voxel_grid> raw_grid_, grid_;
  DF_L1::Outlier_voxel_statistics outlier_voxel_statistics_;
  std::unique_ptr<Distance_field> field_;
  std::unique_ptr<Initial_skeleton> initial_;
  std::unique_ptr<Contracted_samples> contracted_;
  std::unique_ptr<Skeleton> skeleton_;
};

/// \ingroup PkgDFL1SkeletonRef
/// Computes the curve skeleton of a point cloud with the distance-field guided
/// L1-median method in one call: `DF_L1_skeletonization` run to the end.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`; the result does not depend on the threads
/// \tparam PointRange a model of `ConstRange`; its value type is the key type of the point map
/// \tparam Skeleton `CGAL::DF_L1::Skeleton_graph<Traits>`, with `Traits` the kernel of the
///         point map's value type (or the one given by `geom_traits`)
/// \param points the input points
/// \param skeleton receives the skeleton: each vertex has its point, its local radius and
///        the indices of the input points it stands for (every non-outlier point belongs
///        to exactly one vertex)
/// \param np optional named parameters, those of the `DF_L1_skeletonization` constructor
/// \throws DF_L1::Invalid_input on bad input or parameters
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange, class Traits,
          class NamedParameters = parameters::Default_named_parameters>
void extract_df_l1_skeleton(const PointRange& points, DF_L1::Skeleton_graph<Traits>& skeleton,
                            const NamedParameters& np = parameters::default_values())
{
  DF_L1_skeletonization<Traits, ConcurrencyTag> skeletonization(points, np);
  skeletonization(skeleton);
}

} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_H
