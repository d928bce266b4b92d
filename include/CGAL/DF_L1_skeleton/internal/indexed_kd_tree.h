// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_INDEXED_KD_TREE_H
#define CGAL_DF_L1_SKELETON_INTERNAL_INDEXED_KD_TREE_H

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// CGAL's kd-tree over the indices of a vector of points, built once: neighbour searches
// report indices, so per-point results go straight into arrays. The points must outlive
// the tree; const searches may run in parallel.
template <class Traits>
class Indexed_kd_tree
{
public:
  typedef typename Traits::Point_3 Point_3;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Traits>> Search_traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Search_traits> K_neighbor_search;
  typedef typename K_neighbor_search::Tree Tree;
  typedef typename K_neighbor_search::Distance Distance;

  explicit Indexed_kd_tree(const std::vector<Point_3>& points)
    : map_(points.data()), indices_(points.size()), distance_(map_)
  {
    for(std::size_t i = 0; i < indices_.size(); ++i)
      indices_[i] = i;
    tree_ = std::make_unique<Tree>(indices_.begin(), indices_.end(), typename Tree::Splitter(), Search_traits(map_));
    tree_->build();
  }

  const Tree& tree() const { return *tree_; }
  const Distance& distance() const { return distance_; }
  const Point_map& point_map() const { return map_; }
  /// 0, 1, ..., n - 1
  const std::vector<std::size_t>& indices() const { return indices_; }
  /// 0, 1, ..., n - 1 in the order of a Hilbert curve through the points: searches made
  /// in this order visit the same tree nodes one after the other (the input order of a
  /// scan or a generator is often random in space)
  std::vector<std::size_t> hilbert_order() const
  {
    std::vector<std::size_t> order = indices_;
    CGAL::hilbert_sort(order.begin(), order.end(), CGAL::Spatial_sort_traits_adapter_3<Traits, Point_map>(map_),
                       CGAL::Hilbert_sort_median_policy());
    return order;
  }

private:
  Point_map map_;
  std::vector<std::size_t> indices_;
  Distance distance_;
  std::unique_ptr<Tree> tree_;
};

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_INDEXED_KD_TREE_H
