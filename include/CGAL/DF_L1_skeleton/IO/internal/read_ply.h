// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_PLY_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_PLY_H

/// \file read_ply.h
/// The parser of PLY files (ASCII, binary little and big endian) behind
/// `read_ply_point_cloud()` and `read_point_cloud()`: the header, then the
/// vertex element; other elements are skipped.
/// It works on the whole file held in memory and appends to the `points` and
/// `normals` vectors of a `Cloud` (in practice `CGAL::DF_L1::Point_cloud<Kernel>`),
/// whose value types are constructible from three `double`s. Filling the
/// caller's vectors directly, rather than an intermediate array, halves the
/// memory touched. Not part of the public API.

#include <CGAL/DF_L1_skeleton/IO/internal/parse_numbers.h>
#include <CGAL/DF_L1_skeleton/IO/internal/reader_messages.h>
#include <CGAL/DF_L1_skeleton/IO/internal/text_input.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {
namespace point_cloud_reader {

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline bool ply_type_from_name(std::string_view s, Ply_type& t)
{
  struct Entry { const char* name; Ply_type type; };
  static const Entry table[] = {
    {"char", Ply_type::int8},       {"int8", Ply_type::int8},
    {"uchar", Ply_type::uint8},     {"uint8", Ply_type::uint8},
    {"short", Ply_type::int16},     {"int16", Ply_type::int16},
    {"ushort", Ply_type::uint16},   {"uint16", Ply_type::uint16},
    {"int", Ply_type::int32},       {"int32", Ply_type::int32},
    {"uint", Ply_type::uint32},     {"uint32", Ply_type::uint32},
    {"float", Ply_type::float32},   {"float32", Ply_type::float32},
    {"double", Ply_type::float64},  {"float64", Ply_type::float64}};
  for(const Entry& e : table)
    if(s == e.name) {
      t = e.type;
      return true;
    }
  return false;
}

inline std::size_t ply_type_size(Ply_type t)
{
  switch(t) {
  case Ply_type::int8: case Ply_type::uint8: return 1;
  case Ply_type::int16: case Ply_type::uint16: return 2;
  case Ply_type::int32: case Ply_type::uint32: case Ply_type::float32: return 4;
  case Ply_type::float64: return 8;
  }
  return 0;
}

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::float32;       // the item type for a list
  bool is_list = false;
  Ply_type count_type = Ply_type::uint8;   // lists only
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
};

enum class Ply_format { ascii, binary_little_endian, binary_big_endian };

struct Ply_header
{
  Ply_format format = Ply_format::ascii;
  std::vector<Ply_element> elements;
  std::size_t data_offset = 0;     // first byte after the "end_header" line
  std::size_t next_line = 0;       // number of the first line after the header
};

inline Ply_header parse_ply_header(std::string_view buf, const std::string& name)
{
  Ply_header h;
  Line_reader lines(buf, skip_bom(buf), 1, false);
  std::string_view line;
  if(!lines.next(line))
    fail(name, "", "empty file (expected a PLY header)");
  {
    Line_tokens<2> t(line);
    if(t.size != 1 || t.tok[0] != "ply")
      fail(name, line_where(1), "not a PLY file (the first line must be 'ply')");
  }
  bool has_format = false;
  while(lines.next(line)) {
    const std::string where = line_where(lines.line_number());
    Token_reader reader(line);
    std::string_view keyword;
    if(!reader.next(keyword))
      continue; // tolerate blank header lines
    if(keyword == "comment" || keyword == "obj_info")
      continue;
    std::vector<std::string_view> args;
    for(std::string_view tok; reader.next(tok);)
      args.push_back(tok);

    if(keyword == "end_header") {
      if(!has_format)
        fail(name, "", "the PLY header has no 'format' line");
      h.data_offset = lines.position();
      h.next_line = lines.line_number() + 1;
      return h;
    }
    if(keyword == "format") {
      if(args.empty())
        fail(name, where, "the format line names no format");
      if(args[0] == "ascii")
        h.format = Ply_format::ascii;
      else if(args[0] == "binary_little_endian")
        h.format = Ply_format::binary_little_endian;
      else if(args[0] == "binary_big_endian")
        h.format = Ply_format::binary_big_endian;
      else
        fail(name, where, "unknown PLY format " + quote_token(args[0]) +
                              " (expected ascii, binary_little_endian or binary_big_endian)");
      has_format = true;
    } else if(keyword == "element") {
      if(args.size() != 2)
        fail(name, where, "expected 'element <name> <count>'");
      Ply_element e;
      e.name = std::string(args[0]);
      if(!parse_count(args[1], e.count))
        fail(name, where, "invalid element count " + quote_token(args[1]));
      h.elements.push_back(std::move(e));
    } else if(keyword == "property") {
      if(h.elements.empty())
        fail(name, where, "property declared before any element");
      Ply_property p;
      if(!args.empty() && args[0] == "list") {
        if(args.size() != 4)
          fail(name, where, "expected 'property list <count type> <item type> <name>'");
        if(!ply_type_from_name(args[1], p.count_type))
          fail(name, where, "unknown PLY type " + quote_token(args[1]));
        if(!ply_type_from_name(args[2], p.type))
          fail(name, where, "unknown PLY type " + quote_token(args[2]));
        p.is_list = true;
        p.name = std::string(args[3]);
      } else {
        if(args.size() != 2)
          fail(name, where, "expected 'property <type> <name>'");
        if(!ply_type_from_name(args[0], p.type))
          fail(name, where, "unknown PLY type " + quote_token(args[0]));
        p.name = std::string(args[1]);
      }
      h.elements.back().properties.push_back(std::move(p));
    } else {
      fail(name, where, "unexpected " + quote_token(keyword) +
                            " in the PLY header (is the 'end_header' line missing?)");
    }
  }
  fail(name, "", "the PLY header has no 'end_header' line");
}

/// Roles of the vertex properties the reader keeps.
enum Ply_role : int { role_none = -1, role_x, role_y, role_z, role_nx, role_ny, role_nz };

inline std::vector<int> ply_vertex_roles(const Ply_element& vertex, const std::string& name,
                                         bool& has_normals)
{
  static const char* const role_names[] = {"x", "y", "z", "nx", "ny", "nz"};
  std::vector<int> roles(vertex.properties.size(), role_none);
  bool found[6] = {false, false, false, false, false, false};
  for(std::size_t i = 0; i < vertex.properties.size(); ++i) {
    for(int r = 0; r < 6; ++r) {
      if(vertex.properties[i].name != role_names[r] || found[r])
        continue; // a duplicate name: the first one wins
      if(vertex.properties[i].is_list)
        fail(name, "", std::string("vertex property '") + role_names[r] + "' is a list");
      roles[i] = r;
      found[r] = true;
    }
  }
  for(int r = 0; r < 3; ++r)
    if(!found[r])
      fail(name, "", std::string("the vertex element has no '") + role_names[r] + "' property");
  has_normals = found[role_nx] && found[role_ny] && found[role_nz];
  if(!has_normals)
    for(int& r : roles)
      if(r >= role_nx)
        r = role_none; // an incomplete normal is ignored
  return roles;
}

/// Decodes one binary value; `swap` when the file's byte order is not the host's.
inline double ply_decode(const char* p, Ply_type t, bool swap)
{
  unsigned char b[8];
  const std::size_t n = ply_type_size(t);
  for(std::size_t i = 0; i < n; ++i)
    b[i] = static_cast<unsigned char>(swap ? p[n - 1 - i] : p[i]);
  switch(t) {
  case Ply_type::int8:    { std::int8_t v;   std::memcpy(&v, b, 1); return v; }
  case Ply_type::uint8:   { std::uint8_t v;  std::memcpy(&v, b, 1); return v; }
  case Ply_type::int16:   { std::int16_t v;  std::memcpy(&v, b, 2); return v; }
  case Ply_type::uint16:  { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
  case Ply_type::int32:   { std::int32_t v;  std::memcpy(&v, b, 4); return v; }
  case Ply_type::uint32:  { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
  case Ply_type::float32: { float v;         std::memcpy(&v, b, 4); return static_cast<double>(v); }
  case Ply_type::float64: { double v;        std::memcpy(&v, b, 8); return v; }
  }
  return 0;
}

inline bool host_is_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// Walks binary element instances with bounds checks. `where` describes the
/// instance in error messages.
class Ply_binary_cursor
{
public:
  Ply_binary_cursor(std::string_view buf, std::size_t pos, bool swap)
    : buf_(buf), pos_(pos), swap_(swap) {}

  std::size_t remaining() const { return buf_.size() - pos_; }
  std::size_t position() const { return pos_; }
  bool swap() const { return swap_; }

  /// Advances by `n` bytes if there are that many.
  bool skip(std::uint64_t n)
  {
    if(n > remaining())
      return false;
    pos_ += static_cast<std::size_t>(n);
    return true;
  }

  bool read(Ply_type t, double& v)
  {
    const std::size_t n = ply_type_size(t);
    if(n > remaining())
      return false;
    v = ply_decode(buf_.data() + pos_, t, swap_);
    pos_ += n;
    return true;
  }

private:
  std::string_view buf_;
  std::size_t pos_;
  bool swap_;
};

/// Result of walking one binary element instance.
enum class Ply_walk { ok, truncated, bad_list_count };

/// Walks one binary element instance, storing the values of properties whose
/// role is not `role_none` into `values` (roles may be null for "keep none").
inline Ply_walk ply_walk_binary(Ply_binary_cursor& c, const Ply_element& e, const int* roles,
                                double* values, std::string* bad_list)
{
  for(std::size_t i = 0; i < e.properties.size(); ++i) {
    const Ply_property& p = e.properties[i];
    if(!p.is_list) {
      if(roles != nullptr && roles[i] != role_none) {
        if(!c.read(p.type, values[roles[i]]))
          return Ply_walk::truncated;
      } else if(!c.skip(ply_type_size(p.type))) {
        return Ply_walk::truncated;
      }
      continue;
    }
    double count;
    if(!c.read(p.count_type, count))
      return Ply_walk::truncated;
    // Counts of float type are odd but legal; they must still be whole and >= 0.
    if(!(count >= 0) || count != std::floor(count) || count > 9.0e15) {
      if(bad_list != nullptr)
        *bad_list = "invalid count " + format_value(count) + " for list '" + p.name + "'";
      return Ply_walk::bad_list_count;
    }
    const std::uint64_t n = static_cast<std::uint64_t>(count);
    const std::uint64_t item = ply_type_size(p.type);
    if(n > c.remaining() / item || !c.skip(n * item))
      return Ply_walk::truncated;
  }
  return Ply_walk::ok;
}

// The tail shared by the binary and ASCII PLY parsers; coordinates are already checked.
template <class Cloud>
void append_ply_vertex(Cloud& out, const double (&values)[6], bool has_normals, bool& normals_finite)
{
  out.points.emplace_back(values[0], values[1], values[2]);
  if(has_normals) {
    normals_finite = normals_finite && std::isfinite(values[3]) && std::isfinite(values[4]) &&
                     std::isfinite(values[5]);
    out.normals.emplace_back(values[3], values[4], values[5]);
  }
}

template <class Cloud>
void parse_ply_binary(std::string_view buf, const Ply_header& h, std::size_t vertex_index,
                      const std::vector<int>& roles, bool has_normals, const std::string& name,
                      Cloud& out, const Input_buffer* input)
{
  const bool file_little = h.format == Ply_format::binary_little_endian;
  Ply_binary_cursor c(buf, h.data_offset, file_little != host_is_little_endian());

  // Skip the elements stored before the vertices.
  for(std::size_t k = 0; k < vertex_index; ++k) {
    const Ply_element& e = h.elements[k];
    bool has_list = false;
    std::uint64_t stride = 0;
    for(const Ply_property& p : e.properties) {
      has_list = has_list || p.is_list;
      stride += ply_type_size(p.type);
    }
    if(!has_list) { // fixed size: one bounds-checked jump
      if(stride != 0 && e.count > c.remaining() / stride)
        fail(name, "",
             "header says " + std::to_string(e.count) + " '" + e.name +
                 "' elements but the file ends after " + std::to_string(c.remaining() / stride));
      c.skip(stride * e.count);
      continue;
    }
    // Each instance consumes at least one byte (a list count), so a lying
    // count stops at the end of the data.
    for(std::uint64_t i = 0; i < e.count; ++i) {
      std::string bad_list;
      const Ply_walk w = ply_walk_binary(c, e, nullptr, nullptr, &bad_list);
      if(w == Ply_walk::truncated)
        fail(name, "",
             "header says " + std::to_string(e.count) + " '" + e.name +
                 "' elements but the file ends after " + std::to_string(i));
      if(w == Ply_walk::bad_list_count)
        fail(name, "'" + e.name + "' element " + std::to_string(i + 1) + " of " +
                       std::to_string(e.count), bad_list);
    }
  }

  const Ply_element& v = h.elements[vertex_index];
  std::uint64_t min_size = 0;
  for(const Ply_property& p : v.properties)
    min_size += ply_type_size(p.is_list ? p.count_type : p.type);
  reserve_elements(out.points, capped_reserve(v.count, c.remaining() / std::max<std::uint64_t>(min_size, 1)));
  if(has_normals)
    reserve_elements(out.normals, out.points.capacity());
  bool normals_finite = true;

  std::size_t next_drop = c.position() + Line_reader::drop_interval;
  for(std::uint64_t i = 0; i < v.count; ++i) {
    if(input != nullptr && c.position() >= next_drop) {
      input->drop_pages_before(c.position());
      next_drop = c.position() + Line_reader::drop_interval;
    }
    double values[6] = {0, 0, 0, 0, 0, 0};
    std::string bad_list;
    const Ply_walk w = ply_walk_binary(c, v, roles.data(), values, &bad_list);
    const auto where = [&] { return vertex_where(static_cast<std::size_t>(i), v.count, 0); };
    if(w == Ply_walk::truncated)
      fail(name, where(), truncated_vertices(v.count, i));
    if(w == Ply_walk::bad_list_count)
      fail(name, where(), bad_list);
    for(int r = 0; r < 3; ++r)
      if(!std::isfinite(values[r]))
        fail(name, where(), "coordinate is not finite (" + format_value(values[r]) + ")");
    append_ply_vertex(out, values, has_normals, normals_finite);
  }
  if(!normals_finite)
    out.normals.clear();
}

template <class Cloud>
void parse_ply_ascii(std::string_view buf, const Ply_header& h, std::size_t vertex_index,
                     const std::vector<int>& roles, bool has_normals, const std::string& name,
                     Cloud& out, const Input_buffer* input)
{
  // One element instance per line, as every writer does; this lets a line with
  // too many or too few values be reported instead of shifting all that follows.
  Line_reader lines(buf, h.data_offset, h.next_line, true, input);
  auto next_nonblank = [&](std::string_view& line) {
    while(lines.next(line))
      for(char ch : line)
        if(!is_blank(ch))
          return true;
    return false;
  };

  std::string_view line;
  for(std::size_t k = 0; k < vertex_index; ++k) { // elements before the vertices
    const Ply_element& e = h.elements[k];
    for(std::uint64_t i = 0; i < e.count; ++i)
      if(!next_nonblank(line))
        fail(name, "",
             "header says " + std::to_string(e.count) + " '" + e.name +
                 "' elements but the file ends after " + std::to_string(i));
  }

  const Ply_element& v = h.elements[vertex_index];
  reserve_elements(out.points, capped_reserve(v.count, text_points_bound(buf, lines.position())));
  if(has_normals)
    reserve_elements(out.normals, out.points.capacity());
  bool normals_finite = true;

  for(std::uint64_t i = 0; i < v.count; ++i) {
    if(!next_nonblank(line))
      fail(name, vertex_where(static_cast<std::size_t>(i), v.count, 0),
           truncated_vertices(v.count, i));
    const auto where = [&] {
      return vertex_where(static_cast<std::size_t>(i), v.count, lines.line_number());
    };
    Token_reader reader(line);
    std::string_view tok;
    double values[6] = {0, 0, 0, 0, 0, 0};
    std::string_view tokens[6];
    for(std::size_t j = 0; j < v.properties.size(); ++j) {
      const Ply_property& p = v.properties[j];
      if(!reader.next(tok))
        fail(name, where(), "the line ends before property '" + p.name + "'");
      if(!p.is_list) {
        if(roles[j] != role_none) {
          const Number_status st = parse_double(tok, values[roles[j]]);
          if(st != Number_status::ok)
            fail(name, where(), number_error(tok, st));
          tokens[roles[j]] = tok;
        }
        continue;
      }
      std::uint64_t n = 0;
      if(!parse_count(tok, n))
        fail(name, where(), "invalid count " + quote_token(tok) + " for list '" + p.name + "'");
      for(std::uint64_t m = 0; m < n; ++m)
        if(!reader.next(tok))
          fail(name, where(), "the line ends inside list '" + p.name + "'");
    }
    if(reader.next(tok))
      fail(name, where(), "more values than the vertex properties of the header, starting at " +
                            quote_token(tok));
    for(int r = 0; r < 3; ++r)
      if(!std::isfinite(values[r]))
        fail(name, where(), "coordinate is not finite: " + quote_token(tokens[r]));
    append_ply_vertex(out, values, has_normals, normals_finite);
  }
  if(!normals_finite)
    out.normals.clear();
}

/// Parses `buf`; `input`, when given, is the buffer `buf` views (its pages are
/// dropped as parsing advances).
template <class Cloud>
void parse_ply(std::string_view buf, const std::string& name, Cloud& out,
               const Input_buffer* input = nullptr)
{
  const Ply_header h = parse_ply_header(buf, name);
  std::size_t vertex_index = h.elements.size();
  for(std::size_t k = 0; k < h.elements.size(); ++k) {
    if(h.elements[k].name != "vertex")
      continue;
    if(vertex_index != h.elements.size())
      fail(name, "", "the PLY header declares two 'vertex' elements");
    vertex_index = k;
  }
  if(vertex_index == h.elements.size())
    fail(name, "", "the PLY header declares no 'vertex' element");
  bool has_normals = false;
  const std::vector<int> roles = ply_vertex_roles(h.elements[vertex_index], name, has_normals);
  if(h.elements[vertex_index].count == 0)
    fail(name, "", "no points (the header says 0 vertices)");
  if(h.format == Ply_format::ascii)
    parse_ply_ascii(buf, h, vertex_index, roles, has_normals, name, out, input);
  else
    parse_ply_binary(buf, h, vertex_index, roles, has_normals, name, out, input);
}

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_PLY_H
