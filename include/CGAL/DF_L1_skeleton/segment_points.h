// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_SEGMENT_POINTS_H
#define CGAL_DF_L1_SKELETON_SEGMENT_POINTS_H

/// \file segment_points.h
/// A segmentation of the input cloud by the skeleton: each point's vertex and branch.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/split_into_polylines.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/Iterator_range.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The skeleton vertex and branch of every input point (`segment_points()`).
struct Point_segmentation
{
  /// per input point, the skeleton vertex that stands for it; -1 for outliers
  std::vector<long> vertex;
  /// per input point, its branch: the index of a polyline of `split_into_polylines()`;
  /// -1 for outliers
  std::vector<long> branch;
  /// the number of branches
  std::size_t branches = 0;
};

/// \ingroup PkgDFL1SkeletonRef
/// Segments the input points by the skeleton: each non-outlier point gets the vertex
/// whose `points` list holds it and the branch (polyline between end points and
/// junctions, in the order of `split_into_polylines()`) of that vertex. A junction lies
/// on several branches; each of its points goes to the branch of the incident edge whose
/// other vertex is nearest to it, so that the points around a fork split along its arms.
///
/// \tparam PointRange a model of `ConstRange` with random-access iterators; its value
///         type is the key type of the point map
/// \param points the input points, as given to the skeletonization
/// \param skeleton a skeleton whose vertices' `points` lists index `points`
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<Traits::Point_3>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_input if a vertex lists a point index outside `points`
template <class PointRange, class Traits, class NamedParameters = parameters::Default_named_parameters>
Point_segmentation segment_points(const PointRange& points, const Skeleton_graph<Traits>& skeleton,
                                  const NamedParameters& np = parameters::default_values())
{
  const auto point_map = parameters::choose_parameter(parameters::get_parameter(np, internal_np::point_map),
                                                      CGAL::Identity_property_map<typename Traits::Point_3>());
  const std::size_t n = std::size_t(std::distance(points.begin(), points.end()));
  Point_segmentation result;
  result.vertex.assign(n, -1);
  result.branch.assign(n, -1);

  std::vector<std::vector<std::size_t>> polylines;
  split_into_polylines(skeleton, std::back_inserter(polylines));
  result.branches = polylines.size();
  // the branch of every edge, and of every vertex that lies on one branch only
  std::map<std::pair<std::size_t, std::size_t>, long> edge_branch;
  std::vector<long> vertex_branch(boost::num_vertices(skeleton), -1);
  for(std::size_t b = 0; b < polylines.size(); ++b)
  {
    const std::vector<std::size_t>& p = polylines[b];
    for(std::size_t k = 0; k < p.size(); ++k)
    {
      if(vertex_branch[p[k]] < 0 || boost::degree(p[k], skeleton) <= 2)
        vertex_branch[p[k]] = long(b);
      if(k + 1 < p.size())
        edge_branch[std::minmax(p[k], p[k + 1])] = long(b);
    }
  }

  const auto first = points.begin();
  for(std::size_t v = 0; v < boost::num_vertices(skeleton); ++v)
    for(std::size_t i : skeleton[v].points)
    {
      if(i >= n)
        throw Invalid_input("segment_points: vertex " + std::to_string(v) + " lists point " + std::to_string(i) + " of " +
                            std::to_string(n));
      result.vertex[i] = long(v);
      result.branch[i] = vertex_branch[v];
      if(boost::degree(v, skeleton) <= 2)
        continue;
      const auto p = get(point_map, *(first + i));
      double best = -1;
      for(auto e : CGAL::make_range(boost::out_edges(v, skeleton)))
      {
        const std::size_t w = boost::target(e, skeleton);
        const double d = CGAL::to_double(CGAL::squared_distance(p, skeleton[w].point));
        if(best < 0 || d < best)
        {
          best = d;
          result.branch[i] = edge_branch[std::minmax(v, w)];
        }
      }
    }
  return result;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_SEGMENT_POINTS_H
