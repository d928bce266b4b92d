// A CGAL::Point_set_3, read with CGAL's own reader, skeletonized through its point map.
// usage: point_set_3 INPUT.xyz|.ply|.off
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/extract_df_l1_skeleton.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3> Point_set;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT\n";
    return 2;
  }
  Point_set point_set;
  if(!CGAL::IO::read_point_set(argv[1], point_set))
  {
    std::cerr << argv[1] << ": cannot read the point set\n";
    return 1;
  }
  try
  {
    CGAL::DF_L1::Skeleton_graph<Kernel> skeleton;
    CGAL::extract_df_l1_skeleton(point_set, skeleton, CGAL::parameters::point_map(point_set.point_map()));
    const CGAL::DF_L1::Skeleton_statistics s = CGAL::DF_L1::skeleton_statistics(skeleton);
    std::cout << point_set.size() << " points: " << s.vertices << " vertices, " << s.end_points << " end points, "
              << s.junctions << " junctions, total length " << s.length << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
