// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_python_call_benchmark CLOUD REPETITIONS [heap]: the C++ side of the Python call's
// overhead (python/benchmark/call_overhead.py). Reads CLOUD once, then runs the stages
// as the tool and df_l1_skeleton.skeletonize() run them (the class, the tool's order,
// Stage_clock, the results mapped to input units), REPETITIONS times in this process,
// and prints the wall seconds of each run. With REPETITIONS 0, one run per line read
// on stdin, its seconds on a line of their own (to pair each C++ call with a Python
// call made at the same time, on a machine whose speed drifts). With `heap`, the tool's
// malloc settings (tools/heap_settings.h) first.

#include "heap_settings.h"
#include "stage_clock.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;
namespace DF = CGAL::DF_L1;
namespace params = CGAL::parameters;

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: df_l1_python_call_benchmark CLOUD REPETITIONS [heap]\n";
    return 2;
  }
  if(argc > 3 && std::string(argv[3]) == "heap")
    df_l1_tool::keep_large_buffers_on_heap();
  const auto cloud = DF::read_point_cloud<Kernel>(argv[1]);
  const int repetitions = std::atoi(argv[2]);
  const bool on_request = repetitions == 0;
  std::size_t vertices = 0;
  std::string line;
  for(int r = 0; on_request ? bool(std::getline(std::cin, line)) : r < repetitions; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    df_l1_tool::Stage_clock clock(true);
    const DF::Parameters parameters;
    Skeletonization s(cloud.points, params::voxel_resolution(parameters.voxel_resolution,
                                    params::max_memory(DF::internal::available_memory_bytes())));
    s.set_parameters(parameters);
    const auto stage = [&](const char* name, void (Skeletonization::*f)()) {
      clock.run(name, [&] {
        (s.*f)();
        return 0;
      });
    };
    stage("outlier_points", &Skeletonization::flag_outliers);
    stage("denoising", &Skeletonization::denoise);
    if(s.upsampling())
      stage("upsampling", &Skeletonization::upsample);
    stage("voxelization", &Skeletonization::voxelize);
    stage("outliers", &Skeletonization::remove_outlier_voxels);
    s.voxel_grid();
    stage("distance", &Skeletonization::compute_distance_field);
    s.distance_field();
    stage("initial", &Skeletonization::extract_initial_skeleton);
    s.initial_skeleton();
    stage("contraction", &Skeletonization::contract_until_convergence);
    s.contracted_samples();
    stage("skeleton", &Skeletonization::convert_to_skeleton);
    vertices = boost::num_vertices(s.skeleton());
    std::cout << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << (on_request || r + 1 == repetitions ? "\n" : " ") << std::flush;
  }
  std::cerr << "skeleton of " << vertices << " vertices\n";
  return 0;
}
