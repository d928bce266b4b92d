// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_TOPOLOGY_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_TOPOLOGY_H

#include <array>
#include <cstdlib>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// A 3x3x3 neighbourhood; cell (dx,dy,dz) in {-1,0,1}^3 has index (dz+1)*9+(dy+1)*3+(dx+1),
// the centre is cell 13.
typedef std::array<bool, 27> Neighbourhood;

inline int cell_offset_norm(int c) // number of non-zero offsets of cell c
{
  return std::abs(c % 3 - 1) + std::abs((c / 3) % 3 - 1) + std::abs(c / 9 - 1);
}

inline bool cells_adjacent(int a, int b, int max_norm)
{
  const int dx = std::abs(a % 3 - b % 3), dy = std::abs((a / 3) % 3 - (b / 3) % 3),
            dz = std::abs(a / 9 - b / 9);
  return dx <= 1 && dy <= 1 && dz <= 1 && dx + dy + dz >= 1 && dx + dy + dz <= max_norm;
}

// Number of components of the cells of `in` (centre excluded) that satisfy `member`, with
// adjacency of offset norm <= max_norm (1: 6-adjacency, 3: 26-adjacency). When
// `touching_centre_norm` > 0 only the components containing a cell at offset norm
// <= touching_centre_norm from the centre are counted.
template <class Member>
int count_components(const Member& member, int max_norm, int touching_centre_norm)
{
  std::array<int, 27> component;
  component.fill(-1);
  int count = 0;
  for(int seed = 0; seed < 27; ++seed)
  {
    if(seed == 13 || !member(seed) || component[seed] >= 0)
      continue;
    int stack[27], top = 0;
    stack[top++] = seed;
    component[seed] = seed;
    bool touches = touching_centre_norm == 0;
    while(top > 0)
    {
      const int c = stack[--top];
      touches = touches || cell_offset_norm(c) <= touching_centre_norm;
      for(int d = 0; d < 27; ++d)
        if(d != 13 && component[d] < 0 && member(d) && cells_adjacent(c, d, max_norm))
        {
          component[d] = seed;
          stack[top++] = d;
        }
    }
    count += touches;
  }
  return count;
}

// A voxel of a 26-connected object is simple (removable without changing the topology)
// iff its 26-neighbours in the object form one 26-component and the background
// 18-neighbours form one 6-component 6-adjacent to it (Bertrand and Malandain, 1994).
inline bool is_simple(const Neighbourhood& n)
{
  const int foreground = count_components([&](int c) { return n[c]; }, 3, 0);
  if(foreground != 1)
    return false;
  const int background =
    count_components([&](int c) { return !n[c] && cell_offset_norm(c) <= 2; }, 1, 1);
  return background == 1;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_TOPOLOGY_H
