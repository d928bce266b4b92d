// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_READER_MESSAGES_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_READER_MESSAGES_H

/// \file reader_messages.h
/// Error-message helpers shared by the point cloud readers: throwing
/// `Read_error` with the file name and location, quoting bad tokens, and the
/// wording of the messages used by several formats. Not part of the public API.

#include <CGAL/DF_L1_skeleton/errors.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace CGAL {
namespace DF_L1 {
namespace internal {
// A namespace of its own: the generic helper names here (fail, quote_token...)
// must not collide with other internal headers of the package.
namespace point_cloud_reader {

/// A token quoted for an error message: at most 40 characters, and control or
/// non-ASCII bytes escaped, so that garbage input still gives a one-line message.
inline std::string quote_token(std::string_view tok)
{
  constexpr std::size_t max_shown = 40;
  static const char hex[] = "0123456789abcdef";
  std::string out = "'";
  for(std::size_t i = 0; i < tok.size() && i < max_shown; ++i) {
    const unsigned char c = static_cast<unsigned char>(tok[i]);
    if(c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 0xf];
    }
  }
  if(tok.size() > max_shown)
    out += "...";
  out += "'";
  return out;
}

/// Throws `Read_error("<name>: <where>: <what>")`, or `"<name>: <what>"` when
/// `where` is empty.
[[noreturn]] inline void fail(const std::string& name, const std::string& where,
                              const std::string& what)
{
  if(where.empty())
    throw Read_error(name + ": " + what);
  throw Read_error(name + ": " + where + ": " + what);
}

/// A decoded binary value for a message ("-2", "inf", "0.5").
inline std::string format_value(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

/// The message for data that ends before the announced vertex count.
inline std::string truncated_vertices(std::uint64_t announced, std::uint64_t read)
{
  return "header says " + std::to_string(announced) + " vertices but the file ends after " +
         std::to_string(read);
}

inline std::string line_where(std::size_t line) { return "line " + std::to_string(line); }

/// "vertex 37 of 100 (line 39)"; `line == 0` (binary data) omits the line.
inline std::string vertex_where(std::size_t index, std::uint64_t count, std::size_t line)
{
  std::string s = "vertex " + std::to_string(index + 1) + " of " + std::to_string(count);
  if(line != 0)
    s += " (line " + std::to_string(line) + ")";
  return s;
}

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_READER_MESSAGES_H
