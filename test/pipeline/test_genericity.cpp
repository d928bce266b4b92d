// Genericity: the same cloud through other kernels, a CGAL::Point_set_3 and a user's own
// point type with a property map gives the same skeleton. The stages compute in double,
// except the grid's origin and voxel size, which are the kernel's numbers: with exact
// constructions or floats a voxel boundary can fall on the other side of a point, which
// moves a vertex by up to a voxel but not the topology.
#include "evaluation/synthetic_shapes.h"

#include <CGAL/DF_L1_skeleton.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/property_map/property_map.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace DF = CGAL::DF_L1;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

namespace {

struct Summary
{
  DF::Skeleton_statistics counts;
  std::vector<std::array<double, 3>> positions;
  std::vector<std::size_t> owners; // vertex of each input point
};

template <class Graph>
Summary summary_of(const Graph& g, std::size_t n)
{
  Summary s;
  s.counts = DF::skeleton_statistics(g);
  s.owners.assign(n, std::size_t(-1));
  for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
  {
    s.positions.push_back({CGAL::to_double(g[v].point.x()), CGAL::to_double(g[v].point.y()), CGAL::to_double(g[v].point.z())});
    for(std::size_t i : g[v].points)
      s.owners[i] = v;
  }
  return s;
}

template <class Kernel>
Summary with_kernel(const std::vector<Epick::Point_3>& points)
{
  std::vector<typename Kernel::Point_3> converted;
  for(const auto& p : points)
    converted.emplace_back(p.x(), p.y(), p.z());
  DF::Skeleton_graph<Kernel> skeleton;
  CGAL::extract_df_l1_skeleton<CGAL::Sequential_tag>(converted, skeleton, CGAL::parameters::number_of_samples(600));
  return summary_of(skeleton, points.size());
}

// the largest distance between corresponding vertices, or infinity when the graphs differ
double difference(const Summary& a, const Summary& b)
{
  if(a.positions.size() != b.positions.size() || a.counts.edges != b.counts.edges)
    return HUGE_VAL;
  double d = 0;
  for(std::size_t v = 0; v < a.positions.size(); ++v)
    for(int k = 0; k < 3; ++k)
      d = (std::max)(d, std::abs(a.positions[v][k] - b.positions[v][k]));
  return d;
}

struct User_point
{
  float where[3];
  int label;
};

struct User_point_map
{
  typedef User_point key_type;
  typedef Epick::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  friend value_type get(const User_point_map&, const User_point& p) { return value_type(p.where[0], p.where[1], p.where[2]); }
};

} // namespace

TEST_CASE("genericity: kernels, Point_set_3 and a user's point type give the same skeleton", "[genericity]")
{
  // float coordinates, so that every kernel holds the very same input
  std::vector<Epick::Point_3> points;
  for(const auto& p : DF_L1_test::make_sample(DF_L1_test::shape_by_name("y_junction"), DF_L1_test::Variant::clean, 4000, 3).points)
    points.emplace_back(float(p.x()), float(p.y()), float(p.z()));
  const Summary reference = with_kernel<Epick>(points);
  REQUIRE(reference.counts.end_points == 3);
  REQUIRE(reference.counts.junctions >= 1);

  // the same numbers in double: identical
  CHECK(difference(with_kernel<CGAL::Simple_cartesian<double>>(points), reference) == 0);
  // exact constructions and float: the same topology, vertices within a voxel
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  const double voxel = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}) / 100;
  for(const Summary& other : {with_kernel<CGAL::Exact_predicates_exact_constructions_kernel>(points),
                              with_kernel<CGAL::Simple_cartesian<float>>(points)})
  {
    CHECK(other.counts.end_points == reference.counts.end_points);
    CHECK(other.counts.junctions == reference.counts.junctions);
    CHECK(other.counts.cycles == reference.counts.cycles);
    CHECK(other.counts.components == reference.counts.components);
    if(other.positions.size() == reference.positions.size())
      CHECK(difference(other, reference) < voxel);
    else
      CHECK(std::abs(other.counts.length - reference.counts.length) < 0.02 * reference.counts.length);
  }

  // CGAL::Point_set_3 through its point map
  CGAL::Point_set_3<Epick::Point_3> point_set;
  for(const auto& p : points)
    point_set.insert(p);
  DF::Skeleton_graph<Epick> from_set;
  CGAL::extract_df_l1_skeleton<CGAL::Sequential_tag>(point_set, from_set,
                                                      CGAL::parameters::point_map(point_set.point_map()).number_of_samples(600));
  const Summary set_summary = summary_of(from_set, points.size());
  CHECK(difference(set_summary, reference) == 0);
  CHECK(set_summary.owners == reference.owners);

  // a user's struct with a property map, also through the stage functions that take one
  std::vector<User_point> user;
  for(std::size_t i = 0; i < points.size(); ++i)
    user.push_back({{float(points[i].x()), float(points[i].y()), float(points[i].z())}, int(i)});
  DF::Skeleton_graph<Epick> from_user;
  CGAL::extract_df_l1_skeleton<CGAL::Sequential_tag>(user, from_user,
                                                      CGAL::parameters::point_map(User_point_map()).number_of_samples(600));
  const Summary user_summary = summary_of(from_user, points.size());
  CHECK(difference(user_summary, reference) == 0);
  CHECK(user_summary.owners == reference.owners);

  DF::Skeleton_graph<Epick> reassigned = from_user;
  DF::assign_points_to_skeleton<CGAL::Sequential_tag>(user, std::vector<bool>(), reassigned,
                                                      CGAL::parameters::point_map(User_point_map()));
  std::size_t assigned = 0;
  for(std::size_t v = 0; v < boost::num_vertices(reassigned); ++v)
    assigned += reassigned[v].points.size();
  CHECK(assigned == user.size()); // every point, outliers included, belongs to a vertex

  // the stage functions with a point map: the contraction of the user's points
  CGAL::DF_L1_skeletonization<Epick, CGAL::Sequential_tag> stages(points, CGAL::parameters::number_of_samples(600));
  const auto direct = DF::contract_samples<CGAL::Sequential_tag>(
    user, stages.distance_field(), stages.initial_skeleton(), CGAL::parameters::point_map(User_point_map()).number_of_samples(300));
  const auto plain = DF::contract_samples<CGAL::Sequential_tag>(
    points, stages.distance_field(), stages.initial_skeleton(), CGAL::parameters::number_of_samples(300));
  CHECK(direct.points == plain.points);
}
