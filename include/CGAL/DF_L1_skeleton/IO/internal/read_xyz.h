// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_XYZ_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_XYZ_H

/// \file read_xyz.h
/// The parser of the XYZ family of formats (`.xyz`, `.pts`, `.txt`) behind
/// `read_xyz_point_cloud()` and `read_point_cloud()`.
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

namespace CGAL {
namespace DF_L1 {
namespace internal {
namespace point_cloud_reader {

/// Parses `buf`; `input`, when given, is the buffer `buf` views (its pages are
/// dropped as parsing advances).
template <class Cloud>
void parse_xyz(std::string_view buf, const std::string& name, Cloud& out,
               const Input_buffer* input = nullptr)
{
  const std::size_t start = skip_bom(buf);
  reserve_elements(out.points, max_text_points(buf, start));
  Line_reader lines(buf, start, 1, true, input);

  bool first_content_line = true;
  bool six_columns_everywhere = true; // normals are kept only while this holds
  bool normals_finite = true;
  std::string deferred_error; // a bad normal token, fatal only if normals are kept

  std::string_view line;
  while(lines.next(line)) {
    const auto where = [&lines] { return line_where(lines.line_number()); };
    Line_tokens<7> t;
    std::array<double, 3> c;
    if(first_content_line || !fast_coordinates(line, c, t)) {
      t = Line_tokens<7>(strip_comment(line));
      if(t.size == 0)
        continue;
      std::uint64_t unused_count;
      if(first_content_line && t.size == 1 && parse_count(t.tok[0], unused_count)) {
        // The count line of .pts files. The count is not trusted: the points read are the truth.
        first_content_line = false;
        continue;
      }
      first_content_line = false;
      if(t.size < 3)
        fail_short_line(t.tok.data(), t.size, name, where(), "at least 3 numbers (x y z)");
      c = parse_coordinates(t.tok.data(), name, where);
    }
    append(out.points, c);

    if(!six_columns_everywhere)
      continue;
    if(t.size != 6) {
      six_columns_everywhere = false;
      out.normals.clear();
      out.normals.shrink_to_fit();
      continue;
    }
    std::array<double, 3> n;
    bool finite;
    std::size_t bad = 0;
    const Number_status st = parse_normal(t.tok.data() + 3, n, finite, bad);
    if(st != Number_status::ok) {
      if(deferred_error.empty())
        deferred_error = where() + ": " + number_error(t.tok[3 + bad], st);
      continue;
    }
    normals_finite = normals_finite && finite;
    if(out.normals.empty())
      reserve_elements(out.normals, out.points.capacity());
    append(out.normals, n);
  }

  if(out.points.empty())
    fail(name, "", "no points");
  if(six_columns_everywhere && !deferred_error.empty())
    fail(name, "", deferred_error);
  if(!six_columns_everywhere || !normals_finite)
    out.normals.clear();
}

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_XYZ_H
