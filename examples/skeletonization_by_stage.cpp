// The class stage by stage, as a researcher uses it: each stage's result is looked at
// before the next one runs, and a parameter changed between two stages discards only
// what depends on it.
// usage: skeletonization_by_stage INPUT
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/DF_L1_skeletonization.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;
namespace DF = CGAL::DF_L1;

void print_graph(const char* name, const DF::Skeleton_graph<Kernel>& g)
{
  const DF::Skeleton_statistics s = DF::skeleton_statistics(g);
  std::cout << name << ": " << s.vertices << " vertices, " << s.end_points << " end points, " << s.junctions
            << " junctions, " << s.cycles << " cycles\n";
}

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT\n";
    return 2;
  }
  try
  {
    const std::vector<Kernel::Point_3> points = DF::read_point_cloud<Kernel>(argv[1]).points;
    Skeletonization skeletonization(points, CGAL::parameters::voxel_resolution(100));

    skeletonization.denoise();
    std::cout << "noise " << skeletonization.surface_noise() << " (" << (skeletonization.denoised() ? "" : "not ")
              << "smoothed), " << skeletonization.number_of_sparse_outliers() << " scattered outliers\n";

    skeletonization.remove_outlier_voxels();
    const DF::Voxel_grid<Kernel>& grid = skeletonization.voxel_grid();
    std::cout << "voxels " << grid.dims[0] << " x " << grid.dims[1] << " x " << grid.dims[2] << " of size "
              << grid.voxel_size << ": " << grid.count(DF::Voxel_label::BOUNDARY) << " boundary, "
              << grid.count(DF::Voxel_label::INTERIOR) << " interior\n";

    skeletonization.compute_distance_field();
    const DF::Distance_field<Kernel>& field = skeletonization.distance_field();
    std::cout << "largest distance to the boundary " << field.maximum() * field.voxel_size << "\n";

    skeletonization.extract_initial_skeleton();
    print_graph("initial skeleton", skeletonization.initial_skeleton().graph);

    skeletonization.contract_until_convergence();
    const DF::Contracted_samples<Kernel>& samples = skeletonization.contracted_samples();
    std::cout << "contraction: " << samples.stages.size() << " support-radius stages, "
              << samples.points.size() << " samples\n";

    skeletonization.convert_to_skeleton();
    print_graph("final skeleton", skeletonization.skeleton());

    // A coarser thinning: the voxels and the distance field are kept, the initial
    // skeleton and what follows it are recomputed.
    skeletonization.set_thinning_coefficient(1.2);
    print_graph("final skeleton, c = 1.2", skeletonization.skeleton());
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
