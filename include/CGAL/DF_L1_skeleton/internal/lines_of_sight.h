// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_INTERNAL_LINES_OF_SIGHT_H
#define CGAL_DF_L1_SKELETON_INTERNAL_LINES_OF_SIGHT_H

#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/internal/curve_thinning.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_components.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_topology.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {

// For every voxel v with `open[v]` (the others get 0), the set of the 26 grid directions
// (bit d for the direction of cell d of the 3x3x3 neighbourhood, see voxel_topology.h)
// along which the straight line of voxels from v reaches an exterior voxel (or leaves
// the grid) before a voxel of `blocker`, passing only `open` voxels. A
// diagonal step is blocked when a voxel that it passes between is a blocker, so that a
// line does not slip through a 26-connected shell.
template <class Traits>
std::vector<std::uint32_t> exterior_lines_of_sight(const Grid_geometry<Traits>& g, const std::vector<std::uint8_t>& labels,
                                                  const std::vector<char>& open, const std::vector<char>& blocker)
{
  const std::uint8_t E = std::uint8_t(Voxel_label::EXTERIOR);
  const int nx = g.dims[0], ny = g.dims[1], nz = g.dims[2];
  const std::size_t n = labels.size();
  std::vector<std::size_t> voxels;
  for(std::size_t v = 0; v < n; ++v)
    if(open[v])
      voxels.push_back(v);
  std::vector<std::uint32_t> count(n, 0);
  std::vector<char> sees(n, 0); // along the current direction
  for(int d = 0; d < 27; ++d)
  {
    if(d == 13)
      continue;
    const int dx = d % 3 - 1, dy = d / 3 % 3 - 1, dz = d / 9 - 1;
    const long offset = dx + long(dy) * nx + long(dz) * nx * ny;
    // The voxels a diagonal step passes between: the partial steps.
    std::array<long, 6> between{};
    int between_count = 0;
    for(int s = 1; s < 7; ++s)
    {
      const int sx = (s & 1) ? dx : 0, sy = (s & 2) ? dy : 0, sz = (s & 4) ? dz : 0;
      if((sx == 0 && sy == 0 && sz == 0) || (sx == dx && sy == dy && sz == dz))
        continue;
      const long o = sx + long(sy) * nx + long(sz) * nx * ny;
      bool seen = false;
      for(int b = 0; b < between_count; ++b)
        seen = seen || between[std::size_t(b)] == o;
      if(!seen)
        between[std::size_t(between_count++)] = o;
    }
    // v + d before v: in decreasing index order when the step increases the index.
    auto visit = [&](std::size_t v) {
      const std::array<int, 3> c = g.coordinates(v);
      const int a = c[0] + dx, b = c[1] + dy, e = c[2] + dz;
      bool result;
      if(a < 0 || b < 0 || e < 0 || a >= nx || b >= ny || e >= nz)
        result = true;
      else
      {
        const std::size_t w = std::size_t(long(v) + offset);
        bool blocked = blocker[w] != 0;
        for(int s = 0; s < between_count && !blocked; ++s)
          blocked = blocker[std::size_t(long(v) + between[std::size_t(s)])] != 0;
        result = !blocked && (labels[w] == E || (open[w] && sees[w]));
      }
      sees[v] = result;
      if(result)
        count[v] |= std::uint32_t(1) << d;
    };
    if(offset > 0)
      for(std::size_t i = voxels.size(); i-- > 0;)
        visit(voxels[i]);
    else
      for(std::size_t v : voxels)
        visit(v);
  }
  return count;
}

// The `open` voxels whose 26-connected region of open voxels touches at most one
// 26-connected piece of `shell`. A bridge of such voxels between two parts closes a loop
// through empty space, as the surface joins the parts already; one between pieces of
// the shell that nothing else joins (the sparse twigs of a scanned crown) holds the
// shape together.
template <class Traits>
std::vector<char> within_one_shell_piece(const Grid_geometry<Traits>& g, const std::vector<char>& open,
                                         const std::vector<char>& shell)
{
  int pieces = 0;
  const std::vector<int> piece = label_26_components(g, [&](std::size_t v) { return shell[v] != 0; }, pieces);
  std::vector<char> result(open.size(), 0);
  for_each_26_component(g, [&](std::size_t v) { return open[v] != 0; }, [&](const std::vector<std::size_t>& c) {
    int touched = -1;
    bool several = false;
    for(std::size_t v : c)
      for_each_neighbour_26(g, v, [&](std::size_t w) {
        if(piece[w] < 0)
          return;
        several = several || (touched >= 0 && piece[w] != touched);
        touched = piece[w];
      });
    if(!several)
      for(std::size_t v : c)
        result[v] = 1;
  });
  return result;
}

// The interior voxels that see the exterior along at least `min_directions` of the 26
// grid directions, among them `min_pairs` pairs of opposite ones, become exterior,
// unless `keep` holds them or opening them would change the topology of the solid
// (boundary and interior voxels) otherwise than by breaking a bridge of interior voxels
// between parts that the shell joins already (within_one_shell_piece()): such a bridge
// across the pocket between the twigs of two branches of a tree closed a loop. A voxel
// between two parts sees out on opposite sides; one inside a part behind a hole of the
// scan sees out through the hole alone. The lines stop at the voxels of `blocker`: the
// boundary voxels dilated so that the gaps between the samples of a sparse cloud are
// closed (boundary_shell() of voxelize_point_set.h). No interior voxel may lie on the
// outer layer of the grid. Returns the number opened.
template <class Traits>
std::size_t open_lines_of_sight(const Grid_geometry<Traits>& g, std::vector<std::uint8_t>& labels,
                                const std::vector<char>& keep, const std::vector<char>& blocker, int min_directions,
                                int min_pairs)
{
  const std::uint8_t I = std::uint8_t(Voxel_label::INTERIOR), E = std::uint8_t(Voxel_label::EXTERIOR);
  const std::size_t n = labels.size();
  std::vector<char> open(n);
  bool any = false;
  for(std::size_t v = 0; v < n; ++v)
  {
    open[v] = labels[v] == I && !blocker[v];
    any = any || open[v];
  }
  if(!any)
    return 0;
  const std::vector<std::uint32_t> seen = exterior_lines_of_sight(g, labels, open, blocker);
  // per voxel: the directions that see out, and the pairs of opposite ones that both do
  std::vector<std::uint8_t> count(n, 0);
  for(std::size_t v = 0; v < n; ++v)
  {
    if(!seen[v])
      continue;
    int pairs = 0;
    for(int d = 0; d < 13; ++d)
      pairs += ((seen[v] >> d) & 1) && ((seen[v] >> (26 - d)) & 1);
    count[v] = pairs >= min_pairs ? std::uint8_t(bit_count(seen[v])) : 0;
  }
  // Opened one at a time, most exposed first, and only while the solid keeps its
  // topology, but for the bridges above: a line through a hole of the scan may see out
  // from inside a part, and opening there would pierce it.
  std::vector<std::size_t> candidates;
  for(std::size_t v = 0; v < n; ++v)
    if(open[v] && !keep[v] && count[v] >= min_directions)
      candidates.push_back(v);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](std::size_t a, std::size_t b) { return count[a] > count[b]; });
  std::vector<char> may_split; // computed when a bridge first asks to break: most grids have none
  std::vector<std::uint8_t> solid(n);
  for(std::size_t v = 0; v < n; ++v)
    solid[v] = labels[v] != E;
  const std::array<std::ptrdiff_t, 27> offsets = neighbourhood_offsets(g);
  // A voxel that would change the topology now may not once its neighbours are open:
  // passes over the remaining candidates until none opens.
  std::size_t opened = 0;
  for(int pass = 0; pass < 100; ++pass)
  {
    std::size_t before = opened;
    for(std::size_t& v : candidates)
    {
      if(v == std::size_t(-1))
        continue;
      const Neighbourhood around = neighbourhood_in(solid, 1, v, offsets);
      if(!is_simple(around))
      {
        if(!opens_no_tunnel(around))
          continue;
        if(may_split.empty())
          may_split = within_one_shell_piece(g, open, blocker);
        if(!may_split[v])
          continue;
      }
      labels[v] = E;
      solid[v] = 0;
      v = std::size_t(-1);
      ++opened;
    }
    if(opened == before)
      break;
  }
  return opened;
}

} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_INTERNAL_LINES_OF_SIGHT_H
