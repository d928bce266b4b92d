// Computes the initial skeleton of a point cloud and writes it as OBJ.
// usage: initial_skeleton INPUT [OUTPUT.obj]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>
#include <CGAL/DF_L1_skeleton/compute_distance_field.h>
#include <CGAL/DF_L1_skeleton/extract_initial_skeleton.h>
#include <CGAL/DF_L1_skeleton/remove_outlier_voxels.h>
#include <CGAL/DF_L1_skeleton/upsample_sparse_regions.h>
#include <CGAL/DF_L1_skeleton/voxelize_point_set.h>

#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
namespace DF = CGAL::DF_L1;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [OUTPUT.obj]\n";
    return 2;
  }
  try
  {
    std::vector<Kernel::Point_3> points = DF::read_point_cloud<Kernel>(argv[1]).points;
    std::vector<Kernel::Point_3> added;
    DF::upsample_sparse_regions(points, std::back_inserter(added));
    points.insert(points.end(), added.begin(), added.end());

    // points -> voxel grid -> distance field -> initial skeleton
    const DF::Voxel_grid<Kernel> grid =
      DF::remove_outlier_voxels(DF::voxelize_point_set(points, CGAL::parameters::voxel_resolution(100)));
    const DF::Distance_field<Kernel> field = DF::compute_distance_field(grid);
    const DF::Initial_skeleton<Kernel> skeleton = DF::extract_initial_skeleton(field);

    DF::write_skeleton(argc > 2 ? argv[2] : "initial_skeleton.obj", skeleton.graph);
    std::cout << skeleton.points.size() << " skeleton voxels, " << boost::num_vertices(skeleton.graph)
              << " graph vertices\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
