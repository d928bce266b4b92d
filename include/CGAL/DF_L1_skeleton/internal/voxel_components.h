// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_COMPONENTS_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_COMPONENTS_H

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// Calls `f` on the linear index of each of the 6 face neighbours of voxel v in the grid.
template <class Traits, class F>
void for_each_face_neighbour(const Grid_geometry<Traits>& g, std::size_t v, const F& f)
{
  const std::array<int, 3> c = g.coordinates(v);
  for(int n = 0; n < 6; ++n)
  {
    const int i = c[0] + (n == 0) - (n == 1), j = c[1] + (n == 2) - (n == 3), k = c[2] + (n == 4) - (n == 5);
    if(g.contains(i, j, k))
      f(g.index(i, j, k));
  }
}

// Whether `pred` holds at one of the 6 face neighbours of voxel v.
template <class Traits, class Pred>
bool has_face_neighbour(const Grid_geometry<Traits>& g, std::size_t v, const Pred& pred)
{
  bool found = false;
  for_each_face_neighbour(g, v, [&](std::size_t w) { found = found || pred(w); });
  return found;
}

// Calls `f(w, step)` on the linear index w of each of the 26 neighbours of voxel v in
// the grid and the length of the step to it, in voxels (1, sqrt 2 or sqrt 3).
template <class Traits, class F>
void for_each_neighbour_26_step(const Grid_geometry<Traits>& g, std::size_t v, const F& f)
{
  static const double lengths[4] = {0.0, 1.0, std::sqrt(2.0), std::sqrt(3.0)};
  const std::array<int, 3> c = g.coordinates(v);
  for(int dk = -1; dk <= 1; ++dk)
    for(int dj = -1; dj <= 1; ++dj)
      for(int di = -1; di <= 1; ++di)
        if((di != 0 || dj != 0 || dk != 0) && g.contains(c[0] + di, c[1] + dj, c[2] + dk))
          f(g.index(c[0] + di, c[1] + dj, c[2] + dk), lengths[di * di + dj * dj + dk * dk]);
}

// Calls `f` on the linear index of each of the 26 neighbours of voxel v in the grid.
template <class Traits, class F>
void for_each_neighbour_26(const Grid_geometry<Traits>& g, std::size_t v, const F& f)
{
  for_each_neighbour_26_step(g, v, [&](std::size_t w, double) { f(w); });
}

// The connected components of the voxels where `in_set(v)` holds, for the adjacency of
// `for_each_neighbour(g, v, visit)`, each passed to `f` (a vector of linear indices), in
// the order of their lowest index.
template <class Traits, class Neighbours, class InSet, class F>
void for_each_component(const Grid_geometry<Traits>& g, const Neighbours& for_each_neighbour, const InSet& in_set,
                        const F& f)
{
  std::vector<char> seen(g.size(), 0);
  std::vector<std::size_t> component, stack;
  for(std::size_t s = 0; s < g.size(); ++s)
  {
    if(seen[s] || !in_set(s))
      continue;
    component.clear();
    stack.assign(1, s);
    seen[s] = 1;
    while(!stack.empty())
    {
      const std::size_t v = stack.back();
      stack.pop_back();
      component.push_back(v);
      for_each_neighbour(g, v, [&](std::size_t w) {
        if(!seen[w] && in_set(w))
        {
          seen[w] = 1;
          stack.push_back(w);
        }
      });
    }
    f(component);
  }
}

// 6-connected regions of the voxels where `in_set` holds, each passed to `f`.
template <class Traits, class InSet, class F>
void for_each_region(const Grid_geometry<Traits>& g, const InSet& in_set, const F& f)
{
  for_each_component(g, [](const Grid_geometry<Traits>& grid, std::size_t v, const auto& visit) {
    for_each_face_neighbour(grid, v, visit);
  }, in_set, f);
}

// 26-connected components of the voxels where `in_set` holds, each passed to `f`.
template <class Traits, class InSet, class F>
void for_each_26_component(const Grid_geometry<Traits>& g, const InSet& in_set, const F& f)
{
  for_each_component(g, [](const Grid_geometry<Traits>& grid, std::size_t v, const auto& visit) {
    for_each_neighbour_26(grid, v, visit);
  }, in_set, f);
}

// The number of its 26-connected component (in the order of their lowest index) for
// every voxel where `in_set` holds, -1 elsewhere; `count` receives the number of them.
template <class Traits, class InSet>
std::vector<int> label_26_components(const Grid_geometry<Traits>& g, const InSet& in_set, int& count)
{
  std::vector<int> label(g.size(), -1);
  count = 0;
  for_each_26_component(g, in_set, [&](const std::vector<std::size_t>& component) {
    for(std::size_t v : component)
      label[v] = count;
    ++count;
  });
  return label;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_COMPONENTS_H
