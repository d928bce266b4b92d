// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_OFF_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_OFF_H

/// \file read_off.h
/// The parser of ASCII OFF files (with or without the `N` prefix, and
/// headerless vertex lists) behind `read_off_point_cloud()` and
/// `read_point_cloud()`; only the vertices are read.
/// It works on the whole file held in memory and appends to the `points` and
/// `normals` vectors of a `Cloud` (in practice `CGAL::DF_L1::Point_cloud<Kernel>`),
/// whose value types are constructible from three `double`s. Filling the
/// caller's vectors directly, rather than an intermediate array, halves the
/// memory touched. Not part of the public API.

#include <CGAL/DF_L1_skeleton/IO/internal/parse_numbers.h>
#include <CGAL/DF_L1_skeleton/IO/internal/reader_messages.h>
#include <CGAL/DF_L1_skeleton/IO/internal/text_input.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace DF_L1 {
namespace internal {
namespace point_cloud_reader {

/// Appends the point of an OFF vertex line (its first three tokens) and, with
/// `with_normal`, the normal of the next three; a bad number is an error at `where()`,
/// a non-finite normal clears `normals_finite`.
/// `parsed`, when not null, holds the point already parsed by `fast_coordinates()`.
template <class Cloud, class Where>
void append_off_vertex(Cloud& out, const std::string_view* tok, bool with_normal, bool& normals_finite,
                       const std::string& name, const Where& where,
                       const std::array<double, 3>* parsed = nullptr)
{
  append(out.points, parsed != nullptr ? *parsed : parse_coordinates(tok, name, where));
  if(!with_normal)
    return;
  std::array<double, 3> nv;
  bool finite;
  std::size_t bad = 0;
  const Number_status st = parse_normal(tok + 3, nv, finite, bad);
  if(st != Number_status::ok)
    fail(name, where(), number_error(tok[3 + bad], st));
  normals_finite = normals_finite && finite;
  append(out.normals, nv);
}

/// Next line holding something other than blanks and '#' comments.
inline bool next_content_line(Line_reader& lines, std::string_view& content)
{
  std::string_view line;
  while(lines.next(line)) {
    content = strip_comment(line);
    for(char c : content)
      if(!is_blank(c))
        return true;
  }
  return false;
}

/// Whether a first content line is made of 1 to 3 non-negative integers only,
/// i.e. reads as the counts line `V [F [E]]` of a header whose keyword is missing.
inline bool looks_like_counts_line(std::string_view line)
{
  const Line_tokens<4> t(line);
  if(t.size == 0 || t.size > 3)
    return false;
  for(std::size_t i = 0; i < t.size; ++i) {
    std::uint64_t unused;
    if(!parse_count(t.tok[i], unused))
      return false;
  }
  return true;
}

/// A headerless OFF file: no keyword and no counts line, every content line is
/// a vertex `x y z` or `x y z nx ny nz`, with the same width on every line (the
/// first vertex line sets it). `line` is the first content line, already read.
template <class Cloud>
void parse_headerless_off(std::string_view buf, Line_reader& lines, std::string_view line,
                          const std::string& name, Cloud& out)
{
  reserve_elements(out.points, max_text_points(buf, lines.position()) + 1);
  std::size_t columns = 0; // 3 or 6, from the first line
  std::size_t first_line = 0;
  bool normals_finite = true;
  do {
    const auto where = [&lines] { return line_where(lines.line_number()); };
    const Line_tokens<7> t(line);
    if(columns == 0) {
      if(t.size != 3 && t.size != 6) {
        if(t.size < 3)
          fail_short_line(t.tok.data(), t.size, name, where(),
                          "3 or 6 numbers (x y z or x y z nx ny nz) on each line of a "
                          "headerless OFF file");
        fail(name, where(),
             std::string("expected 3 or 6 numbers (x y z or x y z nx ny nz) on each line of a "
                         "headerless OFF file, got ") +
                 (t.size == 7 ? "7 or more" : std::to_string(t.size)));
      }
      columns = t.size;
      first_line = lines.line_number();
      if(columns == 6)
        reserve_elements(out.normals, out.points.capacity());
    } else if(t.size != columns) {
      if(t.size < 3)
        for(std::size_t i = 0; i < t.size; ++i) { // a non-number says more than the count
          double unused;
          const Number_status st = parse_double(t.tok[i], unused);
          if(st != Number_status::ok)
            fail(name, where(), number_error(t.tok[i], st));
        }
      fail(name, where(),
           "expected " + std::to_string(columns) +
               (columns == 6 ? " numbers (x y z nx ny nz)" : " numbers (x y z)") +
               " as on line " + std::to_string(first_line) +
               ", the first line of this headerless OFF file, got " +
               (t.size == 7 ? std::string("7 or more") : std::to_string(t.size)));
    }
    append_off_vertex(out, t.tok.data(), columns == 6, normals_finite, name, where);
  } while(next_content_line(lines, line));
  if(!normals_finite)
    out.normals.clear();
}

/// Parses `buf`; `input`, when given, is the buffer `buf` views (its pages are
/// dropped as parsing advances).
template <class Cloud>
void parse_off(std::string_view buf, const std::string& name, Cloud& out,
               const Input_buffer* input = nullptr)
{
  const std::size_t start = skip_bom(buf);
  Line_reader lines(buf, start, 1, true, input);
  std::string_view line;
  if(!next_content_line(lines, line))
    fail(name, "", "empty file (expected an 'OFF' header line)");

  // No keyword: a first token that is a number starts a headerless list of
  // vertex lines, unless the line reads as a counts line (1 to 3 non-negative
  // integers): then the keyword is missing and the file is refused, as a counts
  // line cannot be told from a vertex line with certainty.
  {
    const Line_tokens<1> first(line);
    if(is_number(first.tok[0])) {
      if(looks_like_counts_line(line))
        fail(name, line_where(lines.line_number()),
             "expected an OFF header keyword ('OFF', 'NOFF', 'COFF'...), got " +
                 quote_token(first.tok[0]) +
                 " (this line of integers reads as a counts line without its keyword; a "
                 "headerless OFF file must start with a vertex line)");
      parse_headerless_off(buf, lines, line, name, out);
      return;
    }
  }

  // Keyword: [ST][C][N][4][n]OFF plus any suffix ("NOFF_SK"...), then optionally
  // BINARY and the counts on the same line.
  std::vector<std::string_view> header;
  {
    Token_reader reader(line);
    std::string_view tok;
    while(reader.next(tok))
      header.push_back(tok);
  }
  const std::string_view keyword = header.front();
  const std::size_t off_pos = ascii_ifind(keyword, "OFF");
  if(off_pos == std::string_view::npos)
    fail(name, line_where(lines.line_number()),
         "expected an OFF header keyword ('OFF', 'NOFF', 'COFF'...), got " + quote_token(keyword));
  const std::string_view prefix = keyword.substr(0, off_pos);
  const bool has_normals = prefix.find('N') != std::string_view::npos;
  const bool has_dimension = prefix.find('n') != std::string_view::npos;
  if(prefix.find('4') != std::string_view::npos)
    fail(name, line_where(lines.line_number()),
         "4D vertices (" + quote_token(keyword) + ") are not supported");
  bool binary = ascii_ifind(keyword.substr(off_pos + 3), "BINARY") != std::string_view::npos;
  header.erase(header.begin());
  for(auto it = header.begin(); it != header.end();) {
    if(ascii_iequals(*it, "BINARY")) {
      binary = true;
      it = header.erase(it);
    } else {
      ++it;
    }
  }
  if(binary)
    fail(name, line_where(lines.line_number()),
         "binary OFF is not supported (convert the file to ASCII OFF)");

  auto next_header_line = [&](const char* what) {
    if(!next_content_line(lines, line))
      fail(name, "", std::string("the file ends before the ") + what);
    Token_reader reader(line);
    std::string_view tok;
    while(reader.next(tok))
      header.push_back(tok);
  };

  if(has_dimension) { // nOFF: the dimension comes first
    if(header.empty())
      next_header_line("dimension of the nOFF header");
    std::uint64_t dim = 0;
    if(!parse_count(header.front(), dim))
      fail(name, line_where(lines.line_number()),
           "expected the dimension of the nOFF header, got " + quote_token(header.front()));
    if(dim != 3)
      fail(name, line_where(lines.line_number()),
           "nOFF with dimension " + std::to_string(dim) + " is not supported (only 3)");
    header.erase(header.begin());
  }
  if(header.empty())
    next_header_line("vertex count line");
  const std::string counts_where = line_where(lines.line_number());

  // Counts: "V F E" as specified, but "V F" and "V" occur in the wild.
  if(header.size() > 3)
    fail(name, counts_where,
         "expected the counts 'vertices faces edges', got " + std::to_string(header.size()) +
             " values");
  static const char* const count_names[] = {"vertex count", "face count", "edge count"};
  std::uint64_t counts[3] = {0, 0, 0};
  for(std::size_t i = 0; i < header.size(); ++i)
    if(!parse_count(header[i], counts[i]))
      fail(name, counts_where,
           std::string("expected the ") + count_names[i] + " (a non-negative integer), got " +
               quote_token(header[i]));
  const std::uint64_t n = counts[0];
  if(n == 0)
    fail(name, counts_where, "no points (the header says 0 vertices)");

  reserve_elements(out.points, capped_reserve(n, text_points_bound(buf, lines.position())));
  bool normals_finite = true;
  // With an N keyword, the first vertex line decides: 6 or more values give the
  // normals, required on every vertex line; exactly 3 (x y z) mean the writer
  // put the N without the normals, and every vertex line must then have 3.
  bool read_normals = has_normals;
  std::size_t first_vertex_line = 0;

  for(std::uint64_t i = 0; i < n; ++i) {
    if(!next_content_line(lines, line))
      fail(name, "", truncated_vertices(n, i));
    const auto where = [&] {
      return vertex_where(static_cast<std::size_t>(i), n, lines.line_number());
    };
    Line_tokens<6> t;
    std::array<double, 3> c;
    const bool fast = fast_coordinates(line, c, t);
    if(!fast)
      t = Line_tokens<6>(line);
    if(t.size < 3)
      fail_short_line(t.tok.data(), t.size, name, where(), "at least 3 numbers (x y z)");
    if(has_normals && i == 0) {
      first_vertex_line = lines.line_number();
      read_normals = t.size != 3;
      if(read_normals)
        reserve_elements(out.normals, out.points.capacity());
    }
    if(read_normals && t.size < 6)
      fail(name, where(),
           "expected 6 numbers (x y z nx ny nz) since the keyword is " + quote_token(keyword) +
               ", got " + std::to_string(t.size));
    if(has_normals && !read_normals && t.size != 3)
      fail(name, where(),
           "expected 3 numbers (x y z) as on line " + std::to_string(first_vertex_line) +
               ", the first vertex line (the keyword " + quote_token(keyword) +
               " announces normals but that line has none), got " +
               (t.size == 6 ? std::string("6 or more") : std::to_string(t.size)));
    append_off_vertex(out, t.tok.data(), read_normals, normals_finite, name, where,
                      fast ? &c : nullptr);
  }
  // Faces and anything after them are not read.
  if(!normals_finite)
    out.normals.clear();
}

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_OFF_H
