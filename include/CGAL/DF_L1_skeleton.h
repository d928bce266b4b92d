// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_H
#define CGAL_DF_L1_SKELETON_H

/// \file DF_L1_skeleton.h
/// The umbrella header of the package: the class `DF_L1_skeletonization`, the free
/// function `extract_df_l1_skeleton()`, the parameters and every stage function. The
/// readers and writers are in `DF_L1_skeleton/IO/`.

#include <CGAL/DF_L1_skeletonization.h>
#include <CGAL/extract_df_l1_skeleton.h>

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
#include <CGAL/DF_L1_skeleton/named_parameters.h>
#include <CGAL/DF_L1_skeleton/remove_outlier_voxels.h>
#include <CGAL/DF_L1_skeleton/segment_points.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>
#include <CGAL/DF_L1_skeleton/split_into_polylines.h>
#include <CGAL/DF_L1_skeleton/upsample_sparse_regions.h>
#include <CGAL/DF_L1_skeleton/voxelize_point_set.h>

#endif // CGAL_DF_L1_SKELETON_H
