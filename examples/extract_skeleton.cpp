// The one-call free function: reads a point cloud, computes its curve skeleton with the
// default parameters and writes it as OBJ.
// usage: extract_skeleton INPUT [OUTPUT.obj]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/extract_df_l1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::DF_L1::Skeleton_graph<Kernel> Skeleton;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [OUTPUT.obj]\n";
    return 2;
  }
  try
  {
    const std::vector<Kernel::Point_3> points = CGAL::DF_L1::read_point_cloud<Kernel>(argv[1]).points;
    Skeleton skeleton;
    CGAL::extract_df_l1_skeleton(points, skeleton);

    const CGAL::DF_L1::Skeleton_statistics s = CGAL::DF_L1::skeleton_statistics(skeleton);
    std::cout << points.size() << " points: skeleton of " << s.vertices << " vertices, " << s.edges << " edges, "
              << s.end_points << " end points, " << s.junctions << " junctions, " << s.cycles << " cycles, "
              << s.components << " component(s)\n";
    CGAL::DF_L1::write_skeleton(argc > 2 ? argv[2] : "skeleton.obj", skeleton);
  }
  catch(const std::exception& e) // Invalid_input, Read_error, Write_error
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
