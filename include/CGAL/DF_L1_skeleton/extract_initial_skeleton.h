// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H
#define CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H

/// \file extract_initial_skeleton.h
/// Stage 4 (paper, section 5): multi-scale parameter-controlled thinning.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/distance_field.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/internal/box_sum.h>
#include <CGAL/DF_L1_skeleton/internal/voxel_topology.h>
#include <CGAL/DF_L1_skeleton/named_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The initial skeleton: the skeleton voxels and a thin graph through them.
/// \tparam Traits a model of `Kernel`
template <class Traits>
struct Initial_skeleton
{
  /// S: the centres of all skeleton voxels (the attractors of the refinement)
  std::vector<typename Traits::Point_3> points;
  /// the linear grid index of each point of `points`
  std::vector<std::size_t> voxels;
  /// a curve graph through a subset of the skeleton voxels: 26-connected, one voxel
  /// thick, with the spurs shorter than the local radius pruned
  Skeleton_graph<Traits> graph;
  /// TP1, TP2, TP3 of Eq. 2, in voxel units
  std::array<double, 3> thinning_parameters = {{0, 0, 0}};
};

namespace internal {

// Morphological closing (26-neighbour dilation, then erosion) of the voxel set, kept
// inside the interior. The ridge band S is full of one-voxel pits and tunnels where the
// discrete field dips; thinning preserves topology, so it would keep every one of them
// as a small loop. Closing fills them and leaves the loops of the shape (a handle spans
// many voxels) alone.
template <class Traits>
void close_voxel_set(const Distance_field<Traits>& df, std::vector<char>& in)
{
  const auto dilate = [&](const std::vector<char>& from, bool value) {
    // value = 1: dilation of the 1s; value = 0: dilation of the 0s (erosion of the 1s).
    std::vector<char> to = from;
    for(int k = 0; k < df.dims[2]; ++k)
      for(int j = 0; j < df.dims[1]; ++j)
        for(int i = 0; i < df.dims[0]; ++i)
        {
          const std::size_t v = df.index(i, j, k);
          if(bool(from[v]) == value)
            continue;
          for(int cell = 0; cell < 27; ++cell)
          {
            const int a = i + cell % 3 - 1, b = j + (cell / 3) % 3 - 1, c = k + cell / 9 - 1;
            if(df.contains(a, b, c) && bool(from[df.index(a, b, c)]) == value)
            {
              to[v] = value;
              break;
            }
          }
        }
    return to;
  };
  std::vector<char> closed = dilate(dilate(in, true), false);
  for(std::size_t v = 0; v < in.size(); ++v)
    in[v] = (in[v] || closed[v]) && df.values[v] > 0;
}

// Topology-preserving thinning of the voxel set `in` (flags on the grid): simple voxels
// that are not curve ends are removed, those nearest the boundary first, so that what
// remains follows the ridge of the distance field.
template <class Traits>
void thin_voxel_set(const Distance_field<Traits>& df, std::vector<char>& in, std::vector<std::size_t> voxels)
{
  std::sort(voxels.begin(), voxels.end(), [&](std::size_t a, std::size_t b) {
    return df.values[a] != df.values[b] ? df.values[a] < df.values[b] : a < b;
  });
  const auto neighbourhood = [&](std::size_t v, int& count) {
    Neighbourhood n;
    const std::array<int, 3> c = df.coordinates(v);
    count = 0;
    for(int cell = 0; cell < 27; ++cell)
    {
      const int i = c[0] + cell % 3 - 1, j = c[1] + (cell / 3) % 3 - 1, k = c[2] + cell / 9 - 1;
      n[cell] = cell != 13 && df.contains(i, j, k) && in[df.index(i, j, k)];
      count += n[cell];
    }
    return n;
  };
  for(bool changed = true; changed;)
  {
    changed = false;
    std::size_t kept = 0;
    for(std::size_t v : voxels)
    {
      int count = 0;
      const Neighbourhood n = neighbourhood(v, count);
      if(count >= 2 && is_simple(n))
      {
        in[v] = 0;
        changed = true;
      }
      else
        voxels[kept++] = v;
    }
    voxels.resize(kept);
  }
}

// Graph of the 26-adjacent voxels, without the diagonal edges that a shorter two-edge
// path already spans (they would make triangles at every staircase step).
template <class Traits>
Skeleton_graph<Traits> voxel_curve_graph(const Distance_field<Traits>& df, const std::vector<char>& in)
{
  Skeleton_graph<Traits> g;
  // Vertices are added in voxel order, so the graph is the same on every run.
  std::vector<std::size_t> voxels;
  for(std::size_t v = 0; v < in.size(); ++v)
    if(in[v])
    {
      const std::size_t d = boost::add_vertex(g);
      voxels.push_back(v);
      g[d].point = df.center(v);
      g[d].radius = df.distance(v);
    }
  const auto vertex_of = [&](std::size_t v) {
    return std::size_t(std::lower_bound(voxels.begin(), voxels.end(), v) - voxels.begin());
  };
  for(std::size_t d = 0; d < voxels.size(); ++d)
  {
    const std::size_t v = voxels[d];
    const std::array<int, 3> c = df.coordinates(v);
    for(int cell = 14; cell < 27; ++cell) // half of the neighbourhood: each edge once
    {
      const int dx = cell % 3 - 1, dy = (cell / 3) % 3 - 1, dz = cell / 9 - 1;
      const int i = c[0] + dx, j = c[1] + dy, k = c[2] + dz;
      if(!df.contains(i, j, k) || !in[df.index(i, j, k)])
        continue;
      const int norm = dx * dx + dy * dy + dz * dz;
      bool spanned = false;
      for(int other = 0; other < 27 && !spanned && norm > 1; ++other)
      {
        const int ex = other % 3 - 1, ey = (other / 3) % 3 - 1, ez = other / 9 - 1;
        const int fx = dx - ex, fy = dy - ey, fz = dz - ez; // from w to the neighbour
        if(other == 13 || std::abs(fx) > 1 || std::abs(fy) > 1 || std::abs(fz) > 1)
          continue;
        const int wi = c[0] + ex, wj = c[1] + ey, wk = c[2] + ez;
        spanned = df.contains(wi, wj, wk) && in[df.index(wi, wj, wk)] &&
                  ex * ex + ey * ey + ez * ez < norm && fx * fx + fy * fy + fz * fz < norm;
      }
      if(!spanned)
        boost::add_edge(d, vertex_of(df.index(i, j, k)), g);
    }
  }
  return g;
}

// Removes, repeatedly, the terminal branches shorter than `ratio` times the local
// radius at their junction: the hair that thinning grows on bumps of the surface.
template <class Traits>
void prune_spurs(Skeleton_graph<Traits>& g, double ratio, double voxel_size)
{
  typedef typename boost::graph_traits<Skeleton_graph<Traits>>::vertex_descriptor vertex;
  for(bool changed = true; changed;)
  {
    changed = false;
    std::vector<char> doomed(boost::num_vertices(g), 0);
    for(vertex end = 0; end < boost::num_vertices(g); ++end)
    {
      if(boost::degree(end, g) != 1)
        continue;
      std::vector<vertex> chain(1, end);
      double length = 0;
      vertex previous = end, current = *boost::adjacent_vertices(end, g).first;
      while(boost::degree(current, g) == 2)
      {
        length += std::sqrt(CGAL::to_double(CGAL::squared_distance(g[previous].point, g[current].point)));
        chain.push_back(current);
        auto next = boost::adjacent_vertices(current, g).first;
        const vertex n = *next == previous ? *(++next) : *next;
        previous = current;
        current = n;
      }
      if(boost::degree(current, g) < 3)
      {
        // An isolated curve: noise of the field near the surface unless it is longer
        // than the local radius (a separate part of the shape).
        double max_radius = 0;
        for(vertex v : chain)
          max_radius = (std::max)(max_radius, CGAL::to_double(g[v].radius));
        if(boost::degree(current, g) == 1)
          length += std::sqrt(CGAL::to_double(CGAL::squared_distance(g[previous].point, g[current].point)));
        if(boost::degree(current, g) == 1 && length < max_radius)
        {
          chain.push_back(current);
          for(vertex v : chain)
            doomed[v] = 1;
        }
        continue;
      }
      length += std::sqrt(CGAL::to_double(CGAL::squared_distance(g[previous].point, g[current].point)));
      if(length < ratio * CGAL::to_double(g[current].radius) + voxel_size)
        for(vertex v : chain)
          doomed[v] = 1;
    }
    // Remove the doomed vertices, from the last so that indices stay valid (vecS).
    for(vertex v = 0; v < boost::num_vertices(g); ++v)
      if(boost::degree(v, g) == 0 && g[v].radius > 0 && 2 * voxel_size > CGAL::to_double(g[v].radius))
        doomed[v] = 1; // a lone voxel near the surface
    for(vertex v = boost::num_vertices(g); v-- > 0;)
      if(doomed[v])
      {
        boost::clear_vertex(v, g);
        boost::remove_vertex(v, g);
        changed = true;
      }
  }
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Extracts the initial skeleton from a distance field by multi-scale
/// parameter-controlled thinning (paper, section 5, Eq. 1-2).
///
/// For every interior voxel p and for the 3x3x3, 5x5x5 and 7x7x7 cubes around it,
/// MNT_k(p) is the mean distance of the 26, 124 and 342 neighbours (computed with a
/// summed-volume table, so each scale costs 8 reads per voxel). A voxel is a skeleton
/// voxel when, at all three scales, MNT_k(p) < DT(p) - TP_k: it stands above the mean of
/// its neighbourhood by more than TP_k. The paper writes TP_k = c (mean MNT_k - mean DT)
/// over the voxels of the model; since the distance field is concave on average that
/// difference is negative, and a negative threshold would accept the flat slopes of the
/// field. We read it as the magnitude, TP_k = c |mean over interior voxels of
/// (DT - MNT_k)|, the threshold of Gagvani and Silver that the paper builds on, with
/// c = 0.86.
///
/// The skeleton voxels S form a band a few voxels thick. `Initial_skeleton::graph` is
/// a curve through them: topology-preserving thinning (simple voxels that are not curve
/// ends are removed, lowest distance first), a 26-adjacency graph without redundant
/// diagonals, and pruning of the terminal branches shorter than `spur_length_ratio`
/// times the local radius at their junction (plus one voxel). Loops of S (the handle of
/// a torus) are kept.
///
/// \tparam Traits a model of `Kernel`
/// \param field the distance field returned by `compute_distance_field()`
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{thinning_coefficient}
///     \cgalParamDescription{c of Eq. 2, in (0, 10]}
///     \cgalParamDefault{0.86}
///   \cgalParamNEnd
///   \cgalParamNBegin{spur_length_ratio}
///     \cgalParamDescription{terminal branches shorter than this times the local radius are pruned; >= 0}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// Skeleton voxels lie at least two voxels deep: the interior voxels one voxel deep are
/// what a flat, linear or noisy sheet of points encloses between its samples.
///
/// \returns the skeleton voxels and the graph; both are empty when the field has no
///          interior voxel two voxels deep (a flat or linear point set, or one too sparse to enclose a volume)
template <class Traits, class NamedParameters = parameters::Default_named_parameters>
Initial_skeleton<Traits> extract_initial_skeleton(const Distance_field<Traits>& field,
                                                  const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double c = choose_parameter(get_parameter(np, internal_np::df_l1_thinning_coefficient), 0.86);
  if(!(c > 0 && c <= 10))
    throw Invalid_input("initial skeleton: thinning_coefficient must be in (0, 10]");
  const double spur_ratio = choose_parameter(get_parameter(np, internal_np::df_l1_spur_length), 1.0);
  if(!(spur_ratio >= 0) || !std::isfinite(spur_ratio))
    throw Invalid_input("initial skeleton: spur_length_ratio must be a non-negative number");

  Initial_skeleton<Traits> result;
  const internal::Box_sum sums(field.values, field.dims);
  const int radii[3] = {1, 2, 3};
  const double counts[3] = {26, 124, 342};

  // Mean of DT - MNT_k over the interior voxels, for the three thresholds.
  double mean_gap[3] = {0, 0, 0};
  std::size_t interior = 0;
  for(int k = 0; k < field.dims[2]; ++k)
    for(int j = 0; j < field.dims[1]; ++j)
      for(int i = 0; i < field.dims[0]; ++i)
      {
        const float dt = field.values[field.index(i, j, k)];
        if(dt <= 0)
          continue;
        ++interior;
        for(int s = 0; s < 3; ++s)
          mean_gap[s] += dt - (sums.cube(i, j, k, radii[s]) - dt) / counts[s];
      }
  if(interior == 0)
    return result;
  for(int s = 0; s < 3; ++s)
    result.thinning_parameters[s] = c * std::abs(mean_gap[s] / double(interior));

  std::vector<char> in(field.size(), 0);
  for(int k = 0; k < field.dims[2]; ++k)
    for(int j = 0; j < field.dims[1]; ++j)
      for(int i = 0; i < field.dims[0]; ++i)
      {
        const std::size_t v = field.index(i, j, k);
        const float dt = field.values[v];
        // One voxel deep is what a flat, linear or noisy sheet of points encloses
        // between its samples: no volume, no skeleton.
        if(dt < 2)
          continue;
        bool ridge = true;
        for(int s = 0; s < 3 && ridge; ++s)
          ridge = (sums.cube(i, j, k, radii[s]) - dt) / counts[s] < dt - result.thinning_parameters[s];
        if(ridge)
        {
          in[v] = 1;
          result.voxels.push_back(v);
          result.points.push_back(field.center(v));
        }
      }

  internal::close_voxel_set(field, in);
  std::vector<std::size_t> band;
  for(std::size_t v = 0; v < in.size(); ++v)
    if(in[v])
      band.push_back(v);
  internal::thin_voxel_set(field, in, band);
  result.graph = internal::voxel_curve_graph(field, in);
  internal::prune_spurs(result.graph, spur_ratio, CGAL::to_double(field.voxel_size));
  return result;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_EXTRACT_INITIAL_SKELETON_H
