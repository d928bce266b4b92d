// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_WRITE_SKELETON_H
#define CGAL_DF_L1_SKELETON_IO_WRITE_SKELETON_H

/// \file write_skeleton.h
/// Writers for skeleton graphs (OBJ, PLY, CGAL polylines) and for point sets
/// with per-point properties (PLY). All of them write atomically: on failure
/// the destination is left untouched and a `Write_error` is thrown.

#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/IO/write_file_atomically.h>
#include <CGAL/DF_L1_skeleton/split_into_polylines.h>

#include <CGAL/number_utils.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <iterator>
#include <locale>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// A named per-point scalar property for `write_point_ply()`.
struct Ply_point_property
{
  /// the PLY property name (no white space; not `x`, `y` or `z`)
  std::string name;
  /// written as PLY `int` when true (values must then be integers in the `int`
  /// range), as `double` otherwise
  bool is_integer = false;
  /// one value per point, in the order of the point range
  std::vector<double> values;
};

namespace internal {

/// Appends the shortest decimal text that reads back as exactly `x`.
inline void append_double(std::string& s, double x)
{
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), x);
  s.append(buf, r.ptr);
#else
  // 17 significant digits always round-trip a double; the classic locale keeps
  // the decimal point a '.'.
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << std::setprecision(17) << x;
  s += os.str();
#endif
}

inline void append_integer(std::string& s, long long i) { s += std::to_string(i); }

/// Buffers text and hands it to the stream in large blocks: formatting a line
/// at a time into a string is much faster than `operator<<` on each number.
class Text_buffer
{
public:
  explicit Text_buffer(std::ostream& os) : os_(os) { buf_.reserve(1 << 16); }
  ~Text_buffer() = default;

  Text_buffer& operator<<(const std::string& t) { buf_ += t; return spill(); }
  Text_buffer& operator<<(const char* t) { buf_ += t; return spill(); }
  Text_buffer& operator<<(char c) { buf_ += c; return spill(); }
  Text_buffer& real(double x) { append_double(buf_, x); return spill(); }
  Text_buffer& integer(long long i) { append_integer(buf_, i); return spill(); }

  /// Must be called at the end; the stream state tells whether it worked.
  void flush()
  {
    os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

private:
  Text_buffer& spill()
  {
    if(buf_.size() >= (1u << 16))
      flush();
    return *this;
  }

  std::ostream& os_;
  std::string buf_;
};

/// The skeleton in plain arrays, checked to be finite before anything is written.
struct Skeleton_arrays
{
  std::vector<std::array<double, 3>> points;
  std::vector<double> radii;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
};

template <class Traits>
Skeleton_arrays skeleton_arrays(const std::string& path, const Skeleton_graph<Traits>& g,
                                bool check_radius)
{
  Skeleton_arrays a;
  const std::size_t n = num_vertices(g);
  a.points.reserve(n);
  a.radii.reserve(n);
  for(std::size_t v = 0; v < n; ++v) {
    const auto& p = g[v].point;
    const std::array<double, 3> xyz{{CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                     CGAL::to_double(p.z())}};
    if(!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
      throw Write_error("cannot write '" + path + "': skeleton vertex " + std::to_string(v) +
                        " has a non-finite coordinate");
    const double r = CGAL::to_double(g[v].radius);
    if(check_radius && !std::isfinite(r))
      throw Write_error("cannot write '" + path + "': skeleton vertex " + std::to_string(v) +
                        " has a non-finite radius");
    a.points.push_back(xyz);
    a.radii.push_back(r);
  }
  a.edges.reserve(num_edges(g));
  for(auto e : boost::make_iterator_range(edges(g)))
    a.edges.emplace_back(static_cast<std::size_t>(source(e, g)),
                         static_cast<std::size_t>(target(e, g)));
  return a;
}

inline void check_ply_int_range(const std::string& path, std::size_t count, const char* what)
{
  if(count > static_cast<std::size_t>(INT_MAX))
    throw Write_error("cannot write '" + path + "': too many " + what +
                      " for PLY int indices (" + std::to_string(count) + ")");
}

inline std::string lower_case(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

inline bool ends_with(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

inline void check_ply_properties(const std::string& path, std::size_t num_points,
                                 const std::vector<Ply_point_property>& properties)
{
  std::set<std::string> names{"x", "y", "z"};
  for(const Ply_point_property& prop : properties) {
    const std::string where = "cannot write '" + path + "': property '" + prop.name + "'";
    if(prop.name.empty())
      throw Write_error("cannot write '" + path + "': a property has an empty name");
    for(char c : prop.name)
      if(std::isspace(static_cast<unsigned char>(c)) || std::iscntrl(static_cast<unsigned char>(c)))
        throw Write_error(where + ": the name contains white space or control characters");
    if(!names.insert(prop.name).second)
      throw Write_error(where + ": the name is used twice (or is x, y or z)");
    if(prop.values.size() != num_points)
      throw Write_error(where + " has " + std::to_string(prop.values.size()) +
                        " values for " + std::to_string(num_points) + " points");
    for(std::size_t i = 0; i < prop.values.size(); ++i) {
      const double x = prop.values[i];
      if(!std::isfinite(x))
        throw Write_error(where + ": value " + std::to_string(i) + " is not finite");
      if(prop.is_integer && (x != std::floor(x) || x < double(INT_MIN) || x > double(INT_MAX)))
        throw Write_error(where + ": value " + std::to_string(i) +
                          " is not an integer in the PLY int range");
    }
  }
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Writes a skeleton as a Wavefront OBJ file: a comment line
/// `# DF_L1_skeleton: N vertices, M edges`, then one `v x y z` line per vertex
/// and one `l a b` line per edge (1-based vertex numbers, vertex `i` of the
/// graph being number `i+1`). Coordinates are written with the shortest text
/// that reads back as the same double.
///
/// \tparam Traits a model of `Kernel`
/// \param path the output file, replaced atomically
/// \param skeleton the skeleton
/// \throws Write_error if a vertex has a non-finite coordinate (nothing is
///         written then) or if the file cannot be written.
template <class Traits>
void write_skeleton_obj(const std::string& path, const Skeleton_graph<Traits>& skeleton)
{
  const internal::Skeleton_arrays a = internal::skeleton_arrays(path, skeleton, false);
  write_file_atomically(path, [&](std::ostream& os) {
    internal::Text_buffer out(os);
    out << "# DF_L1_skeleton: " << std::to_string(a.points.size()) << " vertices, "
        << std::to_string(a.edges.size()) << " edges\n";
    for(const auto& p : a.points) {
      out << "v ";
      out.real(p[0]) << ' ';
      out.real(p[1]) << ' ';
      out.real(p[2]) << '\n';
    }
    for(const auto& e : a.edges) {
      out << "l ";
      out.integer(static_cast<long long>(e.first) + 1) << ' ';
      out.integer(static_cast<long long>(e.second) + 1) << '\n';
    }
    out.flush();
  });
}

/// \ingroup PkgDFL1SkeletonRef
/// Writes a skeleton as an ASCII PLY file with an element `vertex` (properties
/// `double x`, `double y`, `double z`, `double radius`) and an element `edge`
/// (properties `int vertex1`, `int vertex2`, 0-based vertex indices).
///
/// \tparam Traits a model of `Kernel`
/// \param path the output file, replaced atomically
/// \param skeleton the skeleton
/// \throws Write_error if a vertex has a non-finite coordinate or radius
///         (nothing is written then) or if the file cannot be written.
template <class Traits>
void write_skeleton_ply(const std::string& path, const Skeleton_graph<Traits>& skeleton)
{
  const internal::Skeleton_arrays a = internal::skeleton_arrays(path, skeleton, true);
  internal::check_ply_int_range(path, a.points.size(), "vertices");
  write_file_atomically(path, [&](std::ostream& os) {
    internal::Text_buffer out(os);
    out << "ply\nformat ascii 1.0\ncomment written by DF_L1_skeleton\n";
    out << "element vertex " << std::to_string(a.points.size()) << '\n';
    out << "property double x\nproperty double y\nproperty double z\nproperty double radius\n";
    out << "element edge " << std::to_string(a.edges.size()) << '\n';
    out << "property int vertex1\nproperty int vertex2\nend_header\n";
    for(std::size_t i = 0; i < a.points.size(); ++i) {
      out.real(a.points[i][0]) << ' ';
      out.real(a.points[i][1]) << ' ';
      out.real(a.points[i][2]) << ' ';
      out.real(a.radii[i]) << '\n';
    }
    for(const auto& e : a.edges) {
      out.integer(static_cast<long long>(e.first)) << ' ';
      out.integer(static_cast<long long>(e.second)) << '\n';
    }
    out.flush();
  });
}

/// \ingroup PkgDFL1SkeletonRef
/// Writes a skeleton in CGAL's polylines text format: one line per polyline of
/// `split_into_polylines()`, `n x1 y1 z1 ... xn yn zn`. Closed polylines repeat
/// their first point at the end; an isolated vertex gives a line with `n = 1`.
///
/// \tparam Traits a model of `Kernel`
/// \param path the output file, replaced atomically
/// \param skeleton the skeleton
/// \throws Write_error if a vertex has a non-finite coordinate (nothing is
///         written then) or if the file cannot be written.
template <class Traits>
void write_skeleton_polylines(const std::string& path, const Skeleton_graph<Traits>& skeleton)
{
  const internal::Skeleton_arrays a = internal::skeleton_arrays(path, skeleton, false);
  std::vector<std::vector<std::size_t>> polylines;
  split_into_polylines(skeleton, std::back_inserter(polylines));
  write_file_atomically(path, [&](std::ostream& os) {
    internal::Text_buffer out(os);
    for(const auto& pl : polylines) {
      out.integer(static_cast<long long>(pl.size()));
      for(std::size_t v : pl) {
        out << ' ';
        out.real(a.points[v][0]) << ' ';
        out.real(a.points[v][1]) << ' ';
        out.real(a.points[v][2]);
      }
      out << '\n';
    }
    out.flush();
  });
}

/// \ingroup PkgDFL1SkeletonRef
/// Writes a skeleton in the format given by the extension of `path`
/// (case-insensitive): `.obj` (`write_skeleton_obj()`), `.ply`
/// (`write_skeleton_ply()`) or `.polylines.txt` (`write_skeleton_polylines()`).
///
/// \tparam Traits a model of `Kernel`
/// \param path the output file, replaced atomically
/// \param skeleton the skeleton
/// \throws Write_error for any other extension (a plain `.txt` included), and
///         as the writer called.
template <class Traits>
void write_skeleton(const std::string& path, const Skeleton_graph<Traits>& skeleton)
{
  const std::string name = internal::lower_case(path);
  // ".polylines.txt" is a double extension: it must be tested on the whole name.
  if(internal::ends_with(name, ".polylines.txt"))
    write_skeleton_polylines(path, skeleton);
  else if(internal::ends_with(name, ".obj"))
    write_skeleton_obj(path, skeleton);
  else if(internal::ends_with(name, ".ply"))
    write_skeleton_ply(path, skeleton);
  else
    throw Write_error("cannot write '" + path +
                      "': unsupported output extension (use .obj, .ply or .polylines.txt)");
}

/// \ingroup PkgDFL1SkeletonRef
/// Writes points with named per-point scalar properties as an ASCII PLY file:
/// an element `vertex` with properties `double x`, `double y`, `double z`,
/// then one property per entry of `properties`, in order, typed `int` or
/// `double` as each entry says. Used, for instance, to dump voxel centres with
/// an `int label` and a `double distance`.
///
/// \tparam PointRange a range of points with `x()`, `y()`, `z()` convertible
///         with `CGAL::to_double()` (such as a range of `Point_3`)
/// \param path the output file, replaced atomically
/// \param points the points
/// \param properties the per-point properties, each with one value per point
/// \throws Write_error if a coordinate or a property value is not finite, an
///         integer property has a non-integer value, a property has the wrong
///         number of values or an invalid or repeated name (nothing is written
///         then), or if the file cannot be written.
template <class PointRange>
void write_point_ply(const std::string& path, const PointRange& points,
                     const std::vector<Ply_point_property>& properties = {})
{
  std::vector<std::array<double, 3>> xyz;
  for(const auto& p : points) {
    const std::array<double, 3> c{{CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                   CGAL::to_double(p.z())}};
    if(!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
      throw Write_error("cannot write '" + path + "': point " + std::to_string(xyz.size()) +
                        " has a non-finite coordinate");
    xyz.push_back(c);
  }
  internal::check_ply_properties(path, xyz.size(), properties);

  write_file_atomically(path, [&](std::ostream& os) {
    internal::Text_buffer out(os);
    out << "ply\nformat ascii 1.0\ncomment written by DF_L1_skeleton\n";
    out << "element vertex " << std::to_string(xyz.size()) << '\n';
    out << "property double x\nproperty double y\nproperty double z\n";
    for(const Ply_point_property& prop : properties)
      out << "property " << (prop.is_integer ? "int " : "double ") << prop.name << '\n';
    out << "end_header\n";
    for(std::size_t i = 0; i < xyz.size(); ++i) {
      out.real(xyz[i][0]) << ' ';
      out.real(xyz[i][1]) << ' ';
      out.real(xyz[i][2]);
      for(const Ply_point_property& prop : properties) {
        out << ' ';
        if(prop.is_integer)
          out.integer(static_cast<long long>(prop.values[i]));
        else
          out.real(prop.values[i]);
      }
      out << '\n';
    }
    out.flush();
  });
}

/// \ingroup PkgDFL1SkeletonRef
/// Same as above with `double` properties given as (name, values) pairs.
///
/// \tparam PointRange as above
/// \param path the output file, replaced atomically
/// \param points the points
/// \param scalar_properties the per-point properties, all written as `double`
/// \throws Write_error as above
template <class PointRange>
void write_point_ply(const std::string& path, const PointRange& points,
                     const std::vector<std::pair<std::string, std::vector<double>>>& scalar_properties)
{
  std::vector<Ply_point_property> properties;
  properties.reserve(scalar_properties.size());
  for(const auto& sp : scalar_properties)
    properties.push_back(Ply_point_property{sp.first, false, sp.second});
  write_point_ply(path, points, properties);
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_WRITE_SKELETON_H
