// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_TOPOLOGY_H
#define CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_TOPOLOGY_H

#include <array>
#include <cstdint>
#include <cstdlib>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// A 3x3x3 neighbourhood as a bit mask: bit (dz+1)*9+(dy+1)*3+(dx+1) is the cell at offset
// (dx,dy,dz) in {-1,0,1}^3; the centre is bit 13 and is ignored.
typedef std::uint32_t Neighbourhood;

inline int cell_offset_norm(int c) // number of non-zero offsets of cell c
{
  return std::abs(c % 3 - 1) + std::abs((c / 3) % 3 - 1) + std::abs(c / 9 - 1);
}

// For every cell, the mask of the cells adjacent to it (centre excluded) with offset norm
// <= max_norm: 1 gives 6-adjacency, 3 gives 26-adjacency.
template <int max_norm>
const std::array<Neighbourhood, 27>& adjacency_masks()
{
  static const std::array<Neighbourhood, 27> masks = [] {
    std::array<Neighbourhood, 27> m{};
    for(int a = 0; a < 27; ++a)
      for(int b = 0; b < 27; ++b)
      {
        const int dx = std::abs(a % 3 - b % 3), dy = std::abs((a / 3) % 3 - (b / 3) % 3),
                  dz = std::abs(a / 9 - b / 9);
        if(b != 13 && dx <= 1 && dy <= 1 && dz <= 1 && dx + dy + dz >= 1 && dx + dy + dz <= max_norm)
          m[a] |= Neighbourhood(1) << b;
      }
    return m;
  }();
  return masks;
}

inline Neighbourhood cells_up_to_norm(int norm)
{
  Neighbourhood m = 0;
  for(int c = 0; c < 27; ++c)
    if(c != 13 && cell_offset_norm(c) <= norm)
      m |= Neighbourhood(1) << c;
  return m;
}

inline int lowest_bit(Neighbourhood m) // m != 0
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctz(m);
#else
  int b = 0;
  for(; !(m & 1u); m >>= 1)
    ++b;
  return b;
#endif
}

inline int bit_count(Neighbourhood m)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_popcount(m);
#else
  int count = 0;
  for(; m; m &= m - 1)
    ++count;
  return count;
#endif
}

// Number of connected components of the cells of `members` for the adjacency `adjacency`;
// only components that meet `touching` are counted.
inline int count_components(Neighbourhood members, const std::array<Neighbourhood, 27>& adjacency,
                            Neighbourhood touching)
{
  int count = 0;
  while(members)
  {
    Neighbourhood component = Neighbourhood(1) << lowest_bit(members), frontier = component;
    while(frontier)
    {
      Neighbourhood next = 0;
      for(Neighbourhood f = frontier; f; f &= f - 1)
        next |= adjacency[lowest_bit(f)];
      frontier = next & members & ~component;
      component |= frontier;
    }
    members &= ~component;
    count += (component & touching) != 0;
  }
  return count;
}

// Whether removing the voxel leaves the background 18-neighbours one 6-component
// 6-adjacent to it: it neither opens a tunnel nor a cavity into the exterior, while it
// may split the object locally (break a bridge).
inline bool opens_no_tunnel(Neighbourhood n)
{
  static const Neighbourhood n18 = cells_up_to_norm(2), n6 = cells_up_to_norm(1);
  return count_components(~n & n18, adjacency_masks<1>(), n6) == 1;
}

// A voxel of a 26-connected object is simple (removable without changing the topology)
// iff its 26-neighbours in the object form one 26-component and the background
// 18-neighbours have one 6-component 6-adjacent to it (Bertrand and Malandain, 1994).
inline bool is_simple(Neighbourhood n)
{
  static const Neighbourhood all = cells_up_to_norm(3);
  n &= all;
  return count_components(n, adjacency_masks<3>(), all) == 1 && opens_no_tunnel(n);
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_VOXEL_TOPOLOGY_H
