// A user's own point type: the points stay in the user's structure and a property map
// tells the library where their positions are. The skeleton's vertices list the indices
// of the input points they stand for, so the user's data (here an id) follows along.
// usage: custom_point_type INPUT
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/extract_df_l1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>

#include <boost/property_map/property_map.hpp>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;

struct Scan_point
{
  double xyz[3];
  int scanner_id;
};

// A readable property map from a Scan_point to its position.
struct Scan_point_map
{
  typedef Scan_point key_type;
  typedef Kernel::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  friend value_type get(const Scan_point_map&, const Scan_point& p) { return value_type(p.xyz[0], p.xyz[1], p.xyz[2]); }
};

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT\n";
    return 2;
  }
  try
  {
    std::vector<Scan_point> scan;
    int id = 0;
    for(const Kernel::Point_3& p : CGAL::DF_L1::read_point_cloud<Kernel>(argv[1]).points)
      scan.push_back({{p.x(), p.y(), p.z()}, id++ % 4});

    CGAL::DF_L1::Skeleton_graph<Kernel> skeleton;
    CGAL::extract_df_l1_skeleton(scan, skeleton, CGAL::parameters::point_map(Scan_point_map()));

    // the scanners that saw the points of each of the first vertices
    for(std::size_t v = 0; v < boost::num_vertices(skeleton) && v < 5; ++v)
    {
      int seen[4] = {0, 0, 0, 0};
      for(std::size_t i : skeleton[v].points)
        ++seen[scan[i].scanner_id];
      std::cout << "vertex " << v << " at " << skeleton[v].point << ", radius " << skeleton[v].radius << ": points from scanners "
                << seen[0] << " " << seen[1] << " " << seen[2] << " " << seen[3] << "\n";
    }
    std::cout << boost::num_vertices(skeleton) << " vertices\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
