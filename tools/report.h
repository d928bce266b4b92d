// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The --report JSON of df_l1_skeleton: the parameters used, the seconds per stage, the counts
// and the peak memory. Other programs read it: keys, their order and the formatting are a
// contract.
#ifndef DF_L1_TOOLS_REPORT_H
#define DF_L1_TOOLS_REPORT_H

#include "json_object.h"
#include "stage_clock.h"

#include <CGAL/DF_L1_skeleton.h>

#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <string>

namespace df_l1_tool {

// The number of samples contracted (junction points of bridges come on top of them).
template <class Kernel>
std::size_t contracted_count(const CGAL::DF_L1::Contracted_samples<Kernel>& c)
{
  return c.iterations.empty() ? 0 : c.iterations.front().size();
}

// The report of a run that stopped after the stages whose results are given: `field`,
// `initial`, `contracted` and `final_skeleton` are null for the stages that did not run.
// `s` is the tool's settings (input, output, stage, threads, seed, parameters). The
// skeletonization is not const: some of its getters run the stages they read from.
template <class Settings, class Kernel, class ConcurrencyTag>
std::string report_json(const Settings& s, CGAL::DF_L1_skeletonization<Kernel, ConcurrencyTag>& skeletonization,
                        const CGAL::DF_L1::Voxel_grid<Kernel>& grid, const CGAL::DF_L1::Distance_field<Kernel>* field,
                        const CGAL::DF_L1::Initial_skeleton<Kernel>* initial,
                        const CGAL::DF_L1::Contracted_samples<Kernel>* contracted,
                        const CGAL::DF_L1::Skeleton_graph<Kernel>* final_skeleton, const Stage_clock& clock)
{
  namespace DF = CGAL::DF_L1;
  const double voxel_size = CGAL::to_double(grid.voxel_size);
  Json_object parameters;
  parameters.text("stage", s.stage)
    .number("threads", double(tbb::this_task_arena::max_concurrency())) // of the arena the run is in
    .number("seed", double(s.seed))
    .number("bbox_diagonal", skeletonization.bbox_diagonal())
    .text("denoising", DF::parameter_text(s.parameters, "denoising"))
    .number("denoising_neighbors", skeletonization.denoising_neighbors())
    .boolean("upsampling", skeletonization.upsampling())
    .number("upsampling_neighbors", skeletonization.upsampling_neighbors())
    .number("upsampling_radius", skeletonization.upsampling_radius())
    .number("voxel_resolution", skeletonization.voxel_resolution())
    .number("initial_voxel_size", skeletonization.initial_voxel_size())
    .number("initial_voxel_size_used", grid.levels.front().voxel_size)
    .number("refinement_levels", double(grid.levels.size() - 1))
    .number("voxel_size", voxel_size)
    .number("exterior_propagation_steps", skeletonization.exterior_propagation_steps())
    .number("outlier_component_size", skeletonization.outlier_component_size());
  if(initial)
    parameters.number("thinning_coefficient", skeletonization.thinning_coefficient())
      .raw("thinning_parameters", "[" + std::to_string(initial->thinning_parameters[0] * voxel_size) + ", " +
                                   std::to_string(initial->thinning_parameters[1] * voxel_size) + ", " +
                                   std::to_string(initial->thinning_parameters[2] * voxel_size) + "]")
      .number("spur_length_ratio", skeletonization.spur_length_ratio());
  if(contracted)
    parameters.text("method", DF::parameter_text(s.parameters, "skeletonization_method"))
      .number("number_of_samples", double(skeletonization.number_of_samples()))
      .number("repulsion_coefficient", skeletonization.repulsion_coefficient())
      .number("initial_support_radius", skeletonization.initial_support_radius())
      .number("support_radius_growth", skeletonization.support_radius_growth())
      .number("branch_directionality", skeletonization.branch_directionality())
      .number("number_of_iterations", skeletonization.number_of_iterations())
      .number("contraction_stages", skeletonization.contraction_stages());
  Json_object counts;
  counts.number("input_points", double(skeletonization.number_of_input_points()))
    .number("analysed_points", double(skeletonization.number_of_analysed_points()))
    .number("added_points", double(skeletonization.added_points().size()))
    .number("outlier_points", double(skeletonization.number_of_outliers()))
    .number("sparse_outlier_points", double(skeletonization.number_of_sparse_outliers()))
    .number("surface_noise", skeletonization.surface_noise())
    .number("residual_growth", skeletonization.residual_growth())
    .boolean("denoised", skeletonization.denoised())
    .number("outlier_clusters", double(skeletonization.outlier_voxel_statistics().components_removed))
    .number("shape_components", double(skeletonization.outlier_voxel_statistics().components_kept))
    .raw("grid", "[" + std::to_string(grid.dims[0]) + ", " + std::to_string(grid.dims[1]) + ", " +
                   std::to_string(grid.dims[2]) + "]")
    .number("boundary_voxels", double(grid.count(DF::Voxel_label::BOUNDARY)))
    .number("interior_voxels", double(grid.count(DF::Voxel_label::INTERIOR)))
    .number("exterior_voxels", double(grid.count(DF::Voxel_label::EXTERIOR)))
    .number("outlier_voxels", double(grid.count(DF::Voxel_label::OUTLIER)));
  if(field)
    counts.number("max_distance", CGAL::to_double(field->voxel_size) * field->maximum());
  // skeleton_*: the skeleton written (the final one with --stage final);
  // initial_skeleton_*: the initial one, when the final one was written.
  const auto skeleton_counts = [&](const std::string& prefix, const DF::Skeleton_graph<Kernel>& g) {
    const DF::Skeleton_statistics st = DF::skeleton_statistics(g);
    counts.number(prefix + "vertices", double(st.vertices))
      .number(prefix + "edges", double(st.edges))
      .number(prefix + "components", double(st.components))
      .number(prefix + "cycles", double(st.cycles))
      .number(prefix + "end_points", double(st.end_points))
      .number(prefix + "junctions", double(st.junctions));
  };
  if(initial)
  {
    counts.number("skeleton_voxels", double(initial->points.size()));
    skeleton_counts("skeleton_", final_skeleton ? *final_skeleton : initial->graph);
  }
  if(contracted)
  {
    skeleton_counts("initial_skeleton_", initial->graph);
    std::string stages = "[";
    for(std::size_t i = 0; i < contracted->stages.size(); ++i)
    {
      const DF::Contraction_stage& st = contracted->stages[i];
      Json_object o;
      o.number("iterations", st.iterations)
        .number("min_radius", st.min_radius)
        .number("mean_radius", st.mean_radius)
        .number("max_radius", st.max_radius)
        .number("free_samples", double(st.free_samples))
        .number("branch_samples", double(st.branch_samples))
        .number("projection_seconds", st.projection_seconds);
      stages += (i ? ",\n      " : "\n      ") + o.inline_str();
    }
    stages += contracted->stages.empty() ? "]" : "\n    ]";
    int iterations = 0;
    for(const DF::Contraction_stage& st : contracted->stages)
      iterations += st.iterations;
    counts.number("samples", double(contracted_count(*contracted)))
      .number("branch_points",
              double(std::count(contracted->roles.begin(), contracted->roles.end(), DF::Sample_role::BRANCH)))
      .number("iterations", iterations)
      .raw("contraction_stages", stages);
  }
  Json_object report;
  // DF_L1_VERSION: set by the tool's CMake target, like the version --version prints.
  report.text("input", s.input).text("output", s.output).text("version", DF_L1_VERSION)
    .object("parameters", parameters).object("seconds", clock.times()).object("counts", counts)
    .number("peak_memory_mib", peak_memory_mib())
    .number("estimated_peak_memory_mib", skeletonization.estimated_peak_memory() / (1024.0 * 1024.0))
    .number("initial_estimated_peak_memory_mib", skeletonization.initial_estimated_peak_memory() / (1024.0 * 1024.0));
  return report.str();
}

} // namespace df_l1_tool

#endif // DF_L1_TOOLS_REPORT_H
