// The parameter record: one table of defaults and ranges, read by the named parameters,
// the class's getters and setters, and the text form the tool uses.
#include "evaluation/synthetic_shapes.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/Parameters.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace DF = CGAL::DF_L1;
namespace params = CGAL::parameters;
using DF_L1_test::Point_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;

namespace {

// A value inside the range of `info` other than its default (nothing for the derived
// defaults' emptiness), as text.
std::string other_value(const DF::Parameter_info& info, const DF::Parameters& defaults)
{
  if(info.kind == DF::Parameter_kind::CHOICE || info.kind == DF::Parameter_kind::BOOLEAN)
    return info.choices[info.read(defaults) == 0 ? 1 : 0];
  const double lower = info.lower_open ? info.lower + (info.kind == DF::Parameter_kind::INTEGER ? 1 : 1e-3) : info.lower;
  double x = std::isinf(info.upper) ? lower + 7 : (lower + info.upper) / 2;
  if(info.kind == DF::Parameter_kind::INTEGER)
    x = std::floor(x);
  if(info.given == nullptr && x == info.read(defaults))
    x = lower;
  return std::to_string(x);
}

} // namespace

TEST_CASE("parameters: every row of the table is consistent", "[parameters]")
{
  const DF::Parameters defaults;
  std::set<std::string> names, options;
  for(const DF::Parameter_info& info : DF::parameter_table())
  {
    INFO(info.name);
    CHECK(names.insert(info.name).second);
    CHECK(options.insert(info.option()).second);
    for(const DF::Option_alias& alias : info.aliases)
      if(alias.option)
        CHECK(options.insert(alias.option).second);
    CHECK(std::string(info.help).size() > 10);
    CHECK(std::string(info.default_text).size() > 0);
    CHECK(&DF::parameter_info(info.name) == &info);
    if(info.given)
    {
      CHECK_FALSE(info.given(defaults)); // derived from the input
      CHECK(DF::parameter_text(defaults, info.name).empty());
    }
    else
    {
      // the documented default is the record's
      CHECK(DF::parameter_text(defaults, info.name) == info.default_text);
      if(info.kind == DF::Parameter_kind::INTEGER || info.kind == DF::Parameter_kind::REAL)
        CHECK(info.in_range(info.read(defaults)));
    }
    // the text form round-trips, and a value out of range leaves the record unchanged
    DF::Parameters p;
    const std::string value = other_value(info, defaults);
    DF::set_parameter(p, info.name, value);
    CHECK(DF::parameter_text(p, info.name) != DF::parameter_text(defaults, info.name));
    DF::Parameters q;
    DF::set_parameter(q, info.name, DF::parameter_text(p, info.name));
    CHECK(DF::parameter_text(q, info.name) == DF::parameter_text(p, info.name));
    const DF::Parameters before = p;
    if(info.kind == DF::Parameter_kind::INTEGER || info.kind == DF::Parameter_kind::REAL)
    {
      for(const double bad : {info.lower - 1, info.lower_open ? info.lower : info.lower - 0.5, info.upper + 1})
      {
        if(std::isinf(bad))
          continue;
        CHECK_THROWS_WITH(DF::set_parameter(p, info.name, std::to_string(bad)), Catch::Contains(info.name));
      }
      CHECK_THROWS_AS(DF::set_parameter(p, info.name, "nan"), DF::Invalid_input);
      CHECK_THROWS_AS(DF::set_parameter(p, info.name, "1x"), DF::Invalid_input);
      if(info.kind == DF::Parameter_kind::INTEGER)
        CHECK_THROWS_AS(DF::set_parameter(p, info.name, "2.5"), DF::Invalid_input);
    }
    else
      CHECK_THROWS_WITH(DF::set_parameter(p, info.name, "bogus"), Catch::Contains(info.choices[0]));
    CHECK(DF::parameter_text(p, info.name) == DF::parameter_text(before, info.name));
  }
  CHECK_THROWS_AS(DF::parameter_info("no_such_parameter"), DF::Invalid_input);
  CHECK_NOTHROW(DF::check_parameters(defaults));
  DF::Parameters bad;
  bad.repulsion_coefficient = 0.5;
  CHECK_THROWS_WITH(DF::check_parameters(bad, "here"), Catch::Contains("here: repulsion_coefficient"));
  bad = DF::Parameters();
  bad.initial_support_radius = std::nan("");
  CHECK_THROWS_AS(DF::check_parameters(bad), DF::Invalid_input);
}

TEST_CASE("parameters: named parameters, the record and the getters agree", "[parameters][class]")
{
  const std::vector<Point_3> points =
    DF_L1_test::make_sample(DF_L1_test::shape_by_name("capsule"), DF_L1_test::Variant::clean, 3000, 1).points;
  // every parameter given a value other than its default, by name in the text form
  DF::Parameters expected;
  for(const DF::Parameter_info& info : DF::parameter_table())
    DF::set_parameter(expected, info.name, other_value(info, DF::Parameters()));
  const Skeletonization s(
    points,
    params::denoising(expected.denoising,
    params::denoising_neighbors(expected.denoising_neighbors,
    params::upsampling(expected.upsampling,
    params::upsampling_neighbors(expected.upsampling_neighbors,
    params::upsampling_radius(*expected.upsampling_radius,
    params::voxel_resolution(expected.voxel_resolution,
    params::initial_voxel_size(*expected.initial_voxel_size,
    params::exterior_propagation_steps(expected.exterior_propagation_steps,
    params::outlier_component_size(*expected.outlier_component_size,
    params::thinning_coefficient(expected.thinning_coefficient,
    params::spur_length_ratio(expected.spur_length_ratio,
    params::skeletonization_method(expected.skeletonization_method,
    params::repulsion_coefficient(expected.repulsion_coefficient,
    params::initial_support_radius(*expected.initial_support_radius,
    params::support_radius_growth(expected.support_radius_growth,
    params::branch_directionality(expected.branch_directionality,
    params::contraction_stages(expected.contraction_stages,
    params::number_of_iterations(expected.number_of_iterations).number_of_samples(expected.number_of_samples)))))))))))))))))));
  for(const DF::Parameter_info& info : DF::parameter_table())
  {
    INFO(info.name);
    CHECK(DF::parameter_text(s.parameters(), info.name) == DF::parameter_text(expected, info.name));
  }
  CHECK(s.voxel_resolution() == expected.voxel_resolution);
  CHECK(s.repulsion_coefficient() == expected.repulsion_coefficient);
  CHECK(s.initial_voxel_size() == *expected.initial_voxel_size);
  CHECK(s.upsampling_radius() == *expected.upsampling_radius);
  CHECK(s.skeletonization_method() == expected.skeletonization_method);
  CHECK(s.number_of_samples() == expected.number_of_samples);
  // out of range through the named parameters: the constructor names the parameter
  CHECK_THROWS_WITH(Skeletonization(points, params::branch_directionality(0.2)), Catch::Contains("branch_directionality"));
  CHECK_THROWS_WITH(Skeletonization(points, params::number_of_iterations(0)), Catch::Contains("number_of_iterations"));
}

TEST_CASE("parameters: a setter discards exactly the stages that read the parameter", "[parameters][class]")
{
  const std::vector<Point_3> points =
    DF_L1_test::make_sample(DF_L1_test::shape_by_name("y_junction"), DF_L1_test::Variant::clean, 4000, 2).points;
  Skeletonization s(points, params::number_of_samples(300));
  const auto* field = &s.distance_field();
  const std::size_t vertices = boost::num_vertices(s.skeleton());
  REQUIRE(vertices > 0);
  const std::size_t initial_vertices = boost::num_vertices(s.initial_skeleton().graph);

  // a contraction parameter: the distance field and the initial skeleton stay
  const auto* initial = &s.initial_skeleton();
  s.set_repulsion_coefficient(0.3);
  CHECK(&s.distance_field() == field);
  CHECK(&s.initial_skeleton() == initial);
  CHECK(boost::num_vertices(s.skeleton()) > 0);
  s.set_repulsion_coefficient(0.35);
  CHECK(boost::num_vertices(s.skeleton()) == vertices); // the same parameters give the same skeleton

  // setting a value equal to the current one discards nothing
  s.set_parameters(s.parameters());
  CHECK(&s.distance_field() == field);

  // a thinning parameter: a new initial skeleton on the same distance field
  s.set_thinning_coefficient(0.5);
  CHECK(&s.distance_field() == field);
  CHECK(s.thinning_coefficient() == 0.5);
  s.set_thinning_coefficient(0.86);
  CHECK(boost::num_vertices(s.initial_skeleton().graph) == initial_vertices);

  // the resolution: everything from the smoothing test on
  s.set_voxel_resolution(60);
  CHECK(s.voxel_resolution() == 60);
  CHECK(s.voxel_grid().dims[0] <= 62 + 8);
  CHECK(boost::num_vertices(s.skeleton()) > 0);

  // a value out of range leaves the parameters and the results as they were
  const auto* grid = &s.voxel_grid();
  CHECK_THROWS_AS(s.set_voxel_resolution(1), DF::Invalid_input);
  CHECK_THROWS_AS(s.set_support_radius_growth(0), DF::Invalid_input);
  CHECK_THROWS_AS(s.set_denoising_neighbors(300), DF::Invalid_input);
  CHECK(s.voxel_resolution() == 60);
  CHECK(s.support_radius_growth() == 0.5);
  CHECK(&s.voxel_grid() == grid);

  // a derived default comes back when the record leaves it empty
  s.set_initial_support_radius(0.05);
  CHECK(s.initial_support_radius() == 0.05);
  DF::Parameters p = s.parameters();
  p.initial_support_radius.reset();
  s.set_parameters(p);
  CHECK(s.initial_support_radius() == Approx(2 * s.bbox_diagonal() / std::cbrt(double(s.kept_points().size() + s.added_points().size()))));
}
