// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_WRITE_SVG_PREVIEW_H
#define CGAL_DF_L1_SKELETON_IO_WRITE_SVG_PREVIEW_H

/// \file write_svg_preview.h
/// A quick-look picture of a point cloud and its skeleton(s): a self-contained
/// SVG file with three orthographic views per row, viewable in any browser.

#include <CGAL/DF_L1_skeleton/Distance_field.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/Voxel_grid.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/IO/write_file_atomically.h>

#include <CGAL/number_utils.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// Options of `write_svg_preview()`.
struct Preview_options
{
  /// at most this many input points are drawn (a deterministic, evenly strided
  /// subset); 0 draws none
  std::size_t max_points = 6000;
  /// size in pixels of the largest extent of the bounding box in each view
  double view_size = 360.;
  /// space in pixels around and between the views
  double margin = 24.;
  /// radius in pixels of the point dots
  double point_radius = 1.1;
  /// shade points by depth (far points lighter), drawn far to near
  bool depth_shading = true;
  /// optional line at the top of the picture
  std::string title;
};

/// \ingroup PkgDFL1SkeletonRef
/// One row of `write_svg_preview()`: a title and what is drawn over the points, in this
/// order: a slice of voxels, points of a stage (such as the contracted samples), the
/// skeleton.
/// \tparam Traits a model of `Kernel`
template <class Traits>
struct Preview_panel
{
  /// text shown above the row, followed by the vertex and edge counts
  std::string title;
  /// the skeleton to draw; `nullptr` draws none
  const Skeleton_graph<Traits>* skeleton = nullptr;
  /// a voxel grid to draw: in each view, the slice across the view direction that holds
  /// the most interior voxels, boundary voxels grey, interior voxels blue, outlier
  /// voxels red; `nullptr` draws none
  const Voxel_grid<Traits>* voxels = nullptr;
  /// a distance field to draw as `voxels` does, the interior voxels shaded from light
  /// (shallow) to dark red (deepest); drawn instead of `voxels` when both are given
  const Distance_field<Traits>* distance_field = nullptr;
  /// points to draw as small dark blue dots (such as the contracted samples); `nullptr`
  /// draws none
  const std::vector<typename Traits::Point_3>* stage_points = nullptr;
};

namespace internal {

using Svg_point = std::array<double, 3>;

/// One orthographic view: which coordinates go right and up, and which one
/// grows towards the viewer (for the painter's order of the points).
struct Svg_view
{
  const char* label;
  int right, up, depth;
  bool depth_towards_viewer;
};

// Right-handed: in the front view the viewer looks along +y, in the side view
// along -x, in the top view along -z.
inline const std::array<Svg_view, 3>& svg_views()
{
  static const std::array<Svg_view, 3> views{{{"front (x right, z up)", 0, 2, 1, false},
                                               {"side (y right, z up)", 1, 2, 0, true},
                                               {"top (x right, y up)", 0, 1, 2, true}}};
  return views;
}

/// A square of a voxel slice, by its lower corner in the coordinates that go right
/// and up in its view, and the index of its colour in `svg_cell_colours()`.
struct Svg_cell
{
  double right, up;
  std::size_t colour;
};

/// Boundary, interior, outlier, then the shades of depth from shallow to deep.
inline const std::array<const char*, 9>& svg_cell_colours()
{
  static const std::array<const char*, 9> colours{{"#6e6e6e", "#6baed6", "#d62728", "#ffffb2", "#fed976",
                                                    "#feb24c", "#fd8d3c", "#f03b20", "#bd0026"}};
  return colours;
}

/// A row reduced to plain arrays, so that the drawing code is not a template.
struct Svg_row
{
  std::string title;
  bool has_skeleton = false;
  std::vector<Svg_point> vertices;
  std::vector<std::size_t> degrees;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<Svg_point> stage_points;
  double cell_size = 0;
  std::array<std::vector<Svg_cell>, 3> cells; // per view
  std::string slice_note;                    // where the slices are, for the title
};

/// Appends `x` rounded to one decimal, locale-independently: pixel coordinates
/// need no more, and it keeps the file small.
inline void append_fixed1(std::string& s, double x)
{
  long long t = std::llround(x * 10.);
  if(t < 0) {
    s += '-';
    t = -t;
  }
  s += std::to_string(t / 10);
  if(t % 10 != 0) {
    s += '.';
    s += static_cast<char>('0' + t % 10);
  }
}

inline std::string xml_escape(const std::string& in)
{
  std::string out;
  for(char c : in) {
    switch(c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default:
        // Control characters are not allowed in XML 1.0 text.
        if(static_cast<unsigned char>(c) >= 0x20 || c == '\t')
          out += c;
    }
  }
  return out;
}

template <class Point>
Svg_point svg_point(const std::string& path, const Point& p, const char* what, std::size_t i)
{
  const Svg_point q{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
    throw Write_error("cannot write '" + path + "': " + what + " " + std::to_string(i) +
                      " has a non-finite coordinate");
  return q;
}

/// Fills `row.cells`: per view, the slice across its depth axis with the most interior
/// voxels. `values` (may be null) shades the interior voxels by depth.
template <class Traits>
void svg_slices(Svg_row& row, const Grid_geometry<Traits>& grid, const std::vector<Voxel_label>& labels,
                const std::vector<float>* values)
{
  const auto& views = svg_views();
  float deepest = 0;
  if(values)
    for(float x : *values)
      deepest = (std::max)(deepest, x);
  row.cell_size = CGAL::to_double(grid.voxel_size);
  const double origin[3] = {CGAL::to_double(grid.origin.x()), CGAL::to_double(grid.origin.y()),
                            CGAL::to_double(grid.origin.z())};
  const char* axis_names = "xyz";
  for(int k = 0; k < 3; ++k) {
    const int d = views[k].depth;
    std::vector<std::size_t> interior(std::size_t(grid.dims[d]), 0);
    for(std::size_t v = 0; v < labels.size(); ++v)
      if(labels[v] == Voxel_label::INTERIOR)
        ++interior[std::size_t(grid.coordinates(v)[d])];
    const int slice = int(std::max_element(interior.begin(), interior.end()) - interior.begin());
    for(std::size_t v = 0; v < labels.size(); ++v) {
      const std::array<int, 3> c = grid.coordinates(v);
      if(c[d] != slice || labels[v] == Voxel_label::EXTERIOR)
        continue;
      std::size_t colour = std::size_t(labels[v]) - 1; // boundary, interior, outlier
      if(values && labels[v] == Voxel_label::INTERIOR && deepest > 0)
        colour = 3 + (std::min)(std::size_t(5), std::size_t(6 * (*values)[v] / deepest));
      row.cells[std::size_t(k)].push_back({origin[views[k].right] + c[views[k].right] * row.cell_size,
                                           origin[views[k].up] + c[views[k].up] * row.cell_size, colour});
    }
    row.slice_note += (k ? ", " : "") + std::string(1, axis_names[d]) + " slice " + std::to_string(slice);
  }
}

template <class Traits>
Svg_row svg_row(const std::string& path, const Preview_panel<Traits>& panel)
{
  Svg_row row;
  row.title = panel.title;
  if(panel.distance_field)
    svg_slices(row, *panel.distance_field, panel.distance_field->labels, &panel.distance_field->values);
  else if(panel.voxels)
    svg_slices(row, *panel.voxels, panel.voxels->labels, nullptr);
  if(panel.stage_points)
    for(std::size_t i = 0; i < panel.stage_points->size(); ++i)
      row.stage_points.push_back(svg_point(path, (*panel.stage_points)[i], "point", i));
  if(panel.skeleton == nullptr)
    return row;
  const Skeleton_graph<Traits>& g = *panel.skeleton;
  row.has_skeleton = true;
  for(std::size_t v = 0; v < num_vertices(g); ++v) {
    row.vertices.push_back(svg_point(path, g[v].point, "skeleton vertex", v));
    row.degrees.push_back(static_cast<std::size_t>(degree(v, g)));
  }
  for(auto e : boost::make_iterator_range(edges(g)))
    row.edges.emplace_back(static_cast<std::size_t>(source(e, g)),
                           static_cast<std::size_t>(target(e, g)));
  return row;
}

/// Grows the box [lo, hi] to hold p.
inline void extend_box(Svg_point& lo, Svg_point& hi, const Svg_point& p)
{
  for(int a = 0; a < 3; ++a) {
    lo[a] = std::min(lo[a], p[a]);
    hi[a] = std::max(hi[a], p[a]);
  }
}

/// The input points as drawn: the strided subset shown and the bounding box of all of
/// them, so that a cloud of millions of points is never copied whole.
struct Svg_cloud
{
  std::vector<Svg_point> shown;
  std::size_t total = 0;
  Svg_point lo{{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                std::numeric_limits<double>::max()}};
  Svg_point hi{{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                -std::numeric_limits<double>::max()}};
};

/// Checks every point and keeps the deterministic, evenly strided subset of at most
/// `max_points` of them.
template <class PointRange>
Svg_cloud svg_cloud(const std::string& path, const PointRange& points, std::size_t max_points)
{
  Svg_cloud cloud;
  cloud.total = static_cast<std::size_t>(std::distance(std::begin(points), std::end(points)));
  const std::size_t shown = std::min(cloud.total, max_points);
  cloud.shown.reserve(shown);
  const auto strided = [&](std::size_t k) {
    return static_cast<std::size_t>(static_cast<unsigned long long>(k) * cloud.total / shown);
  };
  std::size_t i = 0;
  for(const auto& p : points) {
    const Svg_point q = svg_point(path, p, "point", i);
    extend_box(cloud.lo, cloud.hi, q);
    if(cloud.shown.size() < shown && strided(cloud.shown.size()) == i)
      cloud.shown.push_back(q);
    ++i;
  }
  return cloud;
}

inline void write_svg(std::ostream& os, const Svg_cloud& cloud,
                      const std::vector<Svg_row>& rows, const Preview_options& opt)
{
  const std::vector<Svg_point>& pts = cloud.shown;
  const std::size_t n = cloud.total;

  // One bounding box for everything, so that all views and rows share a scale.
  Svg_point lo = cloud.lo, hi = cloud.hi;
  for(const Svg_row& r : rows) {
    for(const Svg_point& p : r.vertices) extend_box(lo, hi, p);
    for(const Svg_point& p : r.stage_points) extend_box(lo, hi, p);
  }
  if(lo[0] > hi[0]) { // nothing at all
    lo = {{0., 0., 0.}};
    hi = {{1., 1., 1.}};
  }
  double largest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if(!(largest > 0.))
    largest = 1.;
  const double view_size = opt.view_size > 1. ? opt.view_size : 360.;
  const double scale = view_size / largest;
  // Flat directions still get a visible strip.
  std::array<double, 3> ext;
  for(int i = 0; i < 3; ++i)
    ext[i] = std::max((hi[i] - lo[i]) * scale, 8.);
  const double pad = 6.; // keeps dots and markers on the bbox border inside the frame
  const double margin = std::max(opt.margin, 4.);
  const double title_h = 22., label_h = 18.;

  const auto& views = svg_views();
  std::array<double, 3> view_x; // left of each view frame
  double x = margin;
  for(int k = 0; k < 3; ++k) {
    view_x[k] = x;
    x += ext[views[k].right] + 2 * pad + margin;
  }
  const double width = x;
  double frame_h = 0;
  for(const Svg_view& v : views)
    frame_h = std::max(frame_h, ext[v.up] + 2 * pad);
  const double row_h = title_h + label_h + frame_h + margin;
  const double header_h = opt.title.empty() ? 0. : title_h + 4.;
  const std::size_t num_rows = rows.empty() ? 1 : rows.size();
  const double height = margin + header_h + row_h * double(num_rows);

  std::string s;
  s.reserve(64 + pts.size() * 3 * num_rows * 14);
  auto num = [&s](double v) { append_fixed1(s, v); };

  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"";
  num(width);
  s += "\" height=\"";
  num(height);
  s += "\" viewBox=\"0 0 ";
  num(width);
  s += ' ';
  num(height);
  s += "\" font-family=\"sans-serif\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if(!opt.title.empty()) {
    s += "<text x=\"";
    num(margin);
    s += "\" y=\"";
    num(margin + 14.);
    s += "\" font-size=\"16\" font-weight=\"bold\">" + xml_escape(opt.title) + "</text>\n";
  }

  // Point shades, far to near; a single shade when depth shading is off.
  const std::vector<const char*> shades = opt.depth_shading
      ? std::vector<const char*>{"#dcdcdc", "#c8c8c8", "#b4b4b4", "#a0a0a0"}
      : std::vector<const char*>{"#bdbdbd"};

  for(std::size_t r = 0; r < num_rows; ++r) {
    const Svg_row* row = rows.empty() ? nullptr : &rows[r];
    const double top = margin + header_h + row_h * double(r);

    std::string title = row ? row->title : std::string("points");
    if(row && row->has_skeleton)
      title += " \xE2\x80\x94 " + std::to_string(row->vertices.size()) + " vertices, " +
               std::to_string(row->edges.size()) + " edges";
    if(row && !row->slice_note.empty())
      title += " \xE2\x80\x94 " + row->slice_note;
    if(row && !row->stage_points.empty())
      title += " \xE2\x80\x94 " + std::to_string(row->stage_points.size()) + " points";
    title += " (" + std::to_string(pts.size()) + " of " + std::to_string(n) + " points shown)";
    s += "<text class=\"row-title\" x=\"";
    num(margin);
    s += "\" y=\"";
    num(top + 15.);
    s += "\" font-size=\"14\" font-weight=\"bold\">" + xml_escape(title) + "</text>\n";

    for(int k = 0; k < 3; ++k) {
      const Svg_view& v = views[k];
      const double fx = view_x[k], fy = top + title_h + label_h;
      const double fw = ext[v.right] + 2 * pad, fh = ext[v.up] + 2 * pad;
      // Maps a 3D point into this view; the up axis points down in SVG.
      // Flat directions are centred in their strip.
      const double cx = fx + pad + 0.5 * (ext[v.right] - (hi[v.right] - lo[v.right]) * scale);
      const double cy = fy + pad + 0.5 * (ext[v.up] + (hi[v.up] - lo[v.up]) * scale);
      auto px = [&](const Svg_point& p) { return cx + (p[v.right] - lo[v.right]) * scale; };
      auto py = [&](const Svg_point& p) { return cy - (p[v.up] - lo[v.up]) * scale; };

      s += "<g class=\"view\">\n<text class=\"view-label\" x=\"";
      num(fx);
      s += "\" y=\"";
      num(fy - 5.);
      s += "\" font-size=\"12\" fill=\"#333\">";
      s += v.label;
      s += "</text>\n<rect x=\"";
      num(fx);
      s += "\" y=\"";
      num(fy);
      s += "\" width=\"";
      num(fw);
      s += "\" height=\"";
      num(fh);
      s += "\" fill=\"none\" stroke=\"#888\" stroke-width=\"0.5\"/>\n";

      // Points: zero-length round-capped subpaths are dots, far fewer bytes
      // than one <circle> each. Binned by depth and drawn far to near.
      if(!pts.empty()) {
        const std::size_t bins = shades.size();
        const double dlo = lo[v.depth], dext = hi[v.depth] - lo[v.depth];
        std::vector<std::vector<std::size_t>> by_bin(bins);
        for(std::size_t i = 0; i < pts.size(); ++i) {
          double t = dext > 0. ? (pts[i][v.depth] - dlo) / dext : 0.5;
          if(!v.depth_towards_viewer)
            t = 1. - t;
          const std::size_t b = std::min(bins - 1, static_cast<std::size_t>(t * double(bins)));
          by_bin[b].push_back(i);
        }
        for(std::size_t b = 0; b < bins; ++b) {
          if(by_bin[b].empty())
            continue;
          s += "<path fill=\"none\" stroke=\"";
          s += shades[b];
          s += "\" stroke-width=\"";
          num(2. * std::max(opt.point_radius, 0.1));
          s += "\" stroke-linecap=\"round\" d=\"";
          for(std::size_t i : by_bin[b]) {
            s += 'M';
            num(px(pts[i]));
            s += ' ';
            num(py(pts[i]));
            s += "h0";
          }
          s += "\"/>\n";
        }
      }

      // Voxel slice: one path per colour of squares, over the points.
      if(row && !row->cells[std::size_t(k)].empty()) {
        const double side = row->cell_size * scale;
        const auto& colours = svg_cell_colours();
        for(std::size_t colour = 0; colour < colours.size(); ++colour) {
          bool open = false;
          for(const Svg_cell& cell : row->cells[std::size_t(k)]) {
            if(cell.colour != colour)
              continue;
            if(!open) {
              s += "<path fill=\"";
              s += colours[colour];
              s += "\" fill-opacity=\"0.85\" d=\"";
              open = true;
            }
            Svg_point corner{{0., 0., 0.}};
            corner[v.right] = cell.right;
            corner[v.up] = cell.up;
            s += 'M';
            num(px(corner));
            s += ' ';
            num(py(corner) - side);
            s += 'h';
            num(side);
            s += 'v';
            num(side);
            s += 'h';
            num(-side);
            s += 'z';
          }
          if(open)
            s += "\"/>\n";
        }
      }

      if(row && !row->stage_points.empty()) {
        s += "<path fill=\"none\" stroke=\"#08306b\" stroke-width=\"2\" stroke-linecap=\"round\" d=\"";
        for(const Svg_point& p : row->stage_points) {
          s += 'M';
          num(px(p));
          s += ' ';
          num(py(p));
          s += "h0";
        }
        s += "\"/>\n";
      }

      if(row && row->has_skeleton) {
        if(!row->edges.empty()) {
          s += "<path fill=\"none\" stroke=\"#a01010\" stroke-width=\"1.5\" "
               "stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"";
          for(const auto& e : row->edges) {
            s += 'M';
            num(px(row->vertices[e.first]));
            s += ' ';
            num(py(row->vertices[e.first]));
            s += 'L';
            num(px(row->vertices[e.second]));
            s += ' ';
            num(py(row->vertices[e.second]));
          }
          s += "\"/>\n";
        }
        // End points (degree 0 or 1) blue, junctions black.
        for(std::size_t i = 0; i < row->vertices.size(); ++i) {
          if(row->degrees[i] == 2)
            continue;
          s += "<circle cx=\"";
          num(px(row->vertices[i]));
          s += "\" cy=\"";
          num(py(row->vertices[i]));
          s += row->degrees[i] <= 1 ? "\" r=\"2.5\" fill=\"#1f4fd0\"/>\n"
                                    : "\" r=\"3\" fill=\"black\"/>\n";
        }
      }
      s += "</g>\n";
    }
  }
  s += "</svg>\n";
  os.write(s.data(), static_cast<std::streamsize>(s.size()));
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Writes a self-contained SVG picture of a point set and one or more
/// skeletons of it. Each row shows three orthographic views side by side,
/// each labelled: front (x right, z up), side (y right, z up) and top
/// (x right, y up). All views of all rows share one scale, fitted to the
/// bounding box of the points and the skeletons, and keep the aspect ratio.
///
/// In each view the points (at most `opt.max_points`, a deterministic evenly
/// strided subset) are drawn as grey dots, shaded by depth, then the skeleton
/// edges as dark red lines and the vertices of degree other than 2 as dots:
/// blue for end points (and isolated vertices), black for junctions. Each row
/// has a title line: the row's title, its vertex and edge counts and the number
/// of points shown. An empty `rows` gives one row of points only.
///
/// \tparam Traits a model of `Kernel`
/// \tparam PointRange a range of points with `x()`, `y()`, `z()` convertible
///         with `CGAL::to_double()` (such as a range of `Traits::Point_3`)
/// \param path the output file, replaced atomically
/// \param points the input points
/// \param rows the rows, from top to bottom
/// \param opt the drawing options
/// \throws Write_error if a point or a skeleton vertex has a non-finite
///         coordinate (nothing is written then) or if the file cannot be written.
template <class Traits, class PointRange>
void write_svg_preview(const std::string& path, const PointRange& points,
                       const std::vector<Preview_panel<Traits>>& rows,
                       const Preview_options& opt = Preview_options())
{
  const internal::Svg_cloud cloud = internal::svg_cloud(path, points, opt.max_points);
  std::vector<internal::Svg_row> svg_rows;
  for(const Preview_panel<Traits>& panel : rows)
    svg_rows.push_back(internal::svg_row(path, panel));
  write_file_atomically(
      path, [&](std::ostream& os) { internal::write_svg(os, cloud, svg_rows, opt); });
}

/// \ingroup PkgDFL1SkeletonRef
/// Writes a self-contained SVG picture of a point set alone: one row of the
/// three views of `write_svg_preview()` above.
///
/// \tparam PointRange as above
/// \param path the output file, replaced atomically
/// \param points the input points
/// \param opt the drawing options
/// \throws Write_error as above
template <class PointRange>
void write_svg_preview(const std::string& path, const PointRange& points,
                       const Preview_options& opt = Preview_options())
{
  const internal::Svg_cloud cloud = internal::svg_cloud(path, points, opt.max_points);
  write_file_atomically(path, [&](std::ostream& os) {
    internal::write_svg(os, cloud, std::vector<internal::Svg_row>(), opt);
  });
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_WRITE_SVG_PREVIEW_H
