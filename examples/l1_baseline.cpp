// The plain L1-medial skeleton (Huang et al. 2013) beside the distance-field guided
// method, on the same cloud and the same parameters otherwise: what the guidance adds.
// usage: l1_baseline INPUT
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/extract_df_l1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <chrono>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
namespace DF = CGAL::DF_L1;

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
    for(const DF::Skeletonization_method method :
        {DF::Skeletonization_method::DISTANCE_FIELD_GUIDED, DF::Skeletonization_method::L1_MEDIAL})
    {
      const auto start = std::chrono::steady_clock::now();
      DF::Skeleton_graph<Kernel> skeleton;
      CGAL::extract_df_l1_skeleton(points, skeleton, CGAL::parameters::skeletonization_method(method));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const DF::Skeleton_statistics s = DF::skeleton_statistics(skeleton);
      std::cout << (method == DF::Skeletonization_method::L1_MEDIAL ? "plain L1-medial:       " : "distance-field guided: ")
                << s.vertices << " vertices, " << s.end_points << " end points, " << s.junctions << " junctions, "
                << s.cycles << " cycles, " << s.components << " component(s), " << seconds << " s\n";
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
