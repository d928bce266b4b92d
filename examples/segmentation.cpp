// From the skeleton to the cloud: the skeleton split into polylines (one per branch,
// between end points and junctions), and the cloud segmented by it: every input point
// with its skeleton vertex and its branch, written as a PLY with one label per point.
// usage: segmentation INPUT [SEGMENTS.ply] [BRANCHES.polylines.txt]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/extract_df_l1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>
#include <CGAL/DF_L1_skeleton/segment_points.h>
#include <CGAL/DF_L1_skeleton/split_into_polylines.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
namespace DF = CGAL::DF_L1;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [SEGMENTS.ply] [BRANCHES.polylines.txt]\n";
    return 2;
  }
  try
  {
    const std::vector<Kernel::Point_3> points = DF::read_point_cloud<Kernel>(argv[1]).points;
    DF::Skeleton_graph<Kernel> skeleton;
    CGAL::extract_df_l1_skeleton(points, skeleton);

    // branches as point sequences
    const std::vector<std::vector<Kernel::Point_3>> branches = DF::skeleton_polylines(skeleton);
    for(std::size_t b = 0; b < branches.size(); ++b)
      std::cout << "branch " << b << ": " << branches[b].size() << " vertices, from " << branches[b].front() << " to "
                << branches[b].back() << "\n";
    DF::write_skeleton(argc > 3 ? argv[3] : "branches.polylines.txt", skeleton);

    // the cloud segmented by branch
    const DF::Point_segmentation segments = DF::segment_points(points, skeleton);
    std::vector<std::size_t> size(segments.branches, 0);
    std::size_t outliers = 0;
    DF::Ply_point_property vertex{"vertex", true, {}}, branch{"branch", true, {}};
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      vertex.values.push_back(double(segments.vertex[i]));
      branch.values.push_back(double(segments.branch[i]));
      if(segments.branch[i] < 0)
        ++outliers;
      else
        ++size[std::size_t(segments.branch[i])];
    }
    for(std::size_t b = 0; b < size.size(); ++b)
      std::cout << "branch " << b << ": " << size[b] << " points\n";
    std::cout << outliers << " outliers\n";
    DF::write_point_ply(argc > 2 ? argv[2] : "segments.ply", points, {vertex, branch});
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
