// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_ASSIGN_POINTS_TO_SKELETON_H
#define CGAL_DF_L1_SKELETON_ASSIGN_POINTS_TO_SKELETON_H

/// \file assign_points_to_skeleton.h
/// Fills `Skeleton_vertex::points`: which input points each skeleton vertex stands for.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/parallel_for.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Assigns every input point that is not an outlier to its nearest skeleton vertex
/// (between vertices at exactly the same distance, the one the kd-tree search meets
/// first: the tree is built from the vertices in index order, so the choice is the same
/// on every run), replacing the vertices' `points` lists. Each
/// non-outlier point then belongs to exactly one vertex. The nearest vertices are found
/// in parallel and the lists filled in point order, so the result does not depend on the
/// number of threads.
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PointRange a model of `ConstRange` with random-access iterators; its value
///         type is the key type of the point map
/// \param points the input points
/// \param is_outlier one flag per point (may be empty: no outliers)
/// \param skeleton the skeleton whose `points` members are filled
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `Traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<Traits::Point_3>`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_input if `is_outlier` is neither empty nor of the size of `points`
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class PointRange, class Traits,
          class NamedParameters = parameters::Default_named_parameters>
void assign_points_to_skeleton(const PointRange& points, const std::vector<bool>& is_outlier,
                               Skeleton_graph<Traits>& skeleton, const NamedParameters& np = parameters::default_values())
{
  const auto point_map = parameters::choose_parameter(parameters::get_parameter(np, internal_np::point_map),
                                                      CGAL::Identity_property_map<typename Traits::Point_3>());
  typedef typename Traits::Point_3 Point_3;
  typedef CGAL::Search_traits_3<Traits> Base_traits;
  typedef std::vector<Point_3> Vertex_points;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Vertex_point_map; // read-only
  typedef CGAL::Search_traits_adapter<std::size_t, Vertex_point_map, Base_traits> Search_traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Search_traits> Search;
  typedef typename Search::Tree Tree;
  typedef typename Search::Distance Distance;

  const std::size_t n = std::size_t(std::distance(points.begin(), points.end()));
  if(!is_outlier.empty() && is_outlier.size() != n)
    throw Invalid_input("assign_points_to_skeleton: one outlier flag per point expected");
  const std::size_t nv = boost::num_vertices(skeleton);
  for(std::size_t v = 0; v < nv; ++v)
    skeleton[v].points.clear();
  if(nv == 0)
    return;

  Vertex_points vertex_points(nv);
  for(std::size_t v = 0; v < nv; ++v)
    vertex_points[v] = skeleton[v].point;
  const Vertex_point_map vpm(&vertex_points[0]);
  std::vector<std::size_t> ids(nv);
  for(std::size_t v = 0; v < nv; ++v)
    ids[v] = v;
  Tree tree(ids.begin(), ids.end(), typename Tree::Splitter(), Search_traits(vpm));
  tree.build();
  const Distance distance(vpm);
  std::vector<std::size_t> nearest_vertex(n);
  const auto first = points.begin();
  internal::for_each_index<ConcurrencyTag>(n, [&](std::size_t i) {
    if(is_outlier.empty() || !is_outlier[i])
    {
      Search search(tree, get(point_map, *(first + i)), 1, 0, true, distance);
      nearest_vertex[i] = search.begin()->first;
    }
  }, 4096);
  for(std::size_t i = 0; i < n; ++i)
    if(is_outlier.empty() || !is_outlier[i])
      skeleton[nearest_vertex[i]].points.push_back(i);
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_ASSIGN_POINTS_TO_SKELETON_H
