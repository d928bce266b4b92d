// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_READ_POINT_CLOUD_H
#define CGAL_DF_L1_SKELETON_IO_READ_POINT_CLOUD_H

/// \file read_point_cloud.h
/// Robust readers for point clouds stored as XYZ/PTS/TXT, PLY or OFF files.
///
/// All readers share these rules:
/// - The input is parsed from memory: a regular file is mapped read-only (on
///   POSIX systems; read otherwise), a stream is read to its end first. Files
///   are opened read-only and never modified.
/// - Every failure throws `CGAL::DF_L1::Read_error` with a one-line message
///   that starts with the file name and, where it applies, names the line
///   (`"bunny.xyz: line 12: expected a number, got 'abc'"`) or the vertex
///   (`"scan.off: vertex 37 of 100 (line 39): ..."`). Lines and vertices are
///   numbered from 1.
/// - Counts announced by a header are never trusted for memory: reservations
///   are capped by what the remaining data can hold, and a count that exceeds
///   the data gives `"header says N vertices but the file ends after M"`.
/// - A coordinate that is NaN or infinite (or overflows a `double`) is an
///   error naming the line or vertex. Zero points is an error (`"no points"`).
/// - Normals are optional: if any normal component is NaN or infinite, all
///   normals of the file are dropped (`Point_cloud::normals` is empty) and the
///   points are still returned.
/// - Windows (CR LF) and old Mac (lone CR) line ends and a UTF-8 byte-order
///   mark are accepted in text data.
/// - A file that another process modifies while `read_point_cloud()` reads it
///   (its size or modification time differ at the end from when it was opened)
///   gives `"<file>: the file changed while it was being read (...)"`. A file
///   removed or replaced by a rename meanwhile is read as it was opened (POSIX).
///   A file *truncated* while it is mapped ends the process with SIGBUS, unless
///   the program handles that signal (the tool reports it; see `input_buffer.h`).

#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/IO/internal/input_buffer.h>
#include <CGAL/DF_L1_skeleton/IO/internal/read_off.h>
#include <CGAL/DF_L1_skeleton/IO/internal/read_ply.h>
#include <CGAL/DF_L1_skeleton/IO/internal/read_xyz.h>
#include <CGAL/DF_L1_skeleton/IO/internal/reader_messages.h>
#include <CGAL/DF_L1_skeleton/IO/internal/text_input.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// A point cloud as returned by the readers.
/// \tparam Kernel a CGAL kernel, e.g. `CGAL::Exact_predicates_inexact_constructions_kernel`
template <class Kernel>
struct Point_cloud
{
  /// the points, in file order
  std::vector<typename Kernel::Point_3> points;
  /// one normal per point, in the same order; empty when the file has no
  /// (usable) normals
  std::vector<typename Kernel::Vector_3> normals;
};

namespace internal {
namespace point_cloud_reader {

/// The file name's extension in lower case, including the dot ("" if none).
inline std::string lower_case_extension(const std::string& filename)
{
  const std::string base = std::filesystem::path(filename).filename().string();
  const std::size_t dot = base.rfind('.');
  if(dot == std::string::npos)
    return std::string();
  std::string ext = base.substr(dot);
  for(char& c : ext)
    if(c >= 'A' && c <= 'Z')
      c = static_cast<char>(c - 'A' + 'a');
  return ext;
}

/// The content of a file, opened read-only: mapped when it is a regular file
/// (see input_buffer.h), else read from the descriptor (a FIFO, say), or as a
/// stream where there is no POSIX `open`.
inline Input_buffer read_file(const std::string& filename)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(filename, ec);
  if(st.type() == fs::file_type::not_found)
    fail(filename, "", "cannot open file: no such file");
  if(st.type() == fs::file_type::directory)
    fail(filename, "", "cannot open file: it is a directory");
  Input_buffer content;
  int open_errno = 0;
  if(read_with_descriptor(filename, content, open_errno))
    return content;
  errno = 0;
  std::ifstream in(filename, std::ios::in | std::ios::binary);
  if(!in.is_open()) {
    const int err = open_errno != 0 ? open_errno : errno;
    fail(filename, "", std::string("cannot open file") +
                           (err != 0 ? std::string(": ") + std::strerror(err) : std::string()));
  }
  return read_stream(in, filename);
}

} // namespace point_cloud_reader
} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Reads a point cloud in the XYZ family of formats (`.xyz`, `.pts`, `.txt`):
/// one point per line, `x y z` optionally followed by more columns.
///
/// - Blank lines and `#` comments (whole lines, or the end of a line) are skipped.
/// - If the first non-comment line holds exactly one non-negative integer, it is
///   the point count that some scanners write at the top of `.pts` files; it is
///   ignored (the points actually present are read, whatever it says).
/// - Values are separated by spaces or tabs; the decimal mark is `.`.
/// - A line with fewer than 3 values, or a first, second or third value that is
///   not a finite number, is an error naming the line. Columns after the third
///   are not checked unless they are read as normals.
/// - **Normals rule:** columns 4 to 6 are read as `nx ny nz` if and only if
///   every point line of the file has exactly 6 columns. A file with 4, 5 or 7+
///   columns on any line (e.g. `x y z intensity r g b` from laser scanners), or
///   with lines of different widths, yields points only. When normals are read,
///   a non-numeric value among them is an error naming the line; a NaN or
///   infinite one drops all normals.
///
/// \tparam Kernel a CGAL kernel providing `Point_3` and `Vector_3`
/// \param in the stream to read to its end (open it in binary mode to keep
///        line ends intact; text mode works too)
/// \param name_for_messages how the input is named in error messages,
///        typically the file name
/// \returns the points, and normals if the file has them
/// \throws Read_error if the stream cannot be read or the content is invalid
template <class Kernel>
Point_cloud<Kernel> read_xyz_point_cloud(std::istream& in, const std::string& name_for_messages)
{
  namespace reader = internal::point_cloud_reader;
  const reader::Input_buffer data = reader::read_stream(in, name_for_messages);
  Point_cloud<Kernel> pc;
  reader::parse_xyz(data.view(), name_for_messages, pc, &data);
  return pc;
}

/// \ingroup PkgDFL1SkeletonRef
/// Reads the vertices of a PLY file (ASCII, binary little endian or binary big
/// endian) as a point cloud.
///
/// - The `vertex` element must have scalar `x`, `y` and `z` properties; `nx`,
///   `ny`, `nz` are read as normals when all three are present. The properties
///   may come in any order and have any PLY type (`char`/`int8`, `uchar`/`uint8`,
///   `short`/`int16`, `ushort`/`uint16`, `int`/`int32`, `uint`/`uint32`,
///   `float`/`float32`, `double`/`float64`); other properties, lists included,
///   are skipped.
/// - Other elements (faces, edges...) are skipped; those stored before the
///   vertices are walked through (list lengths included), those after are not read.
/// - `comment` and `obj_info` lines are ignored; header lines may end in CR LF.
/// - In ASCII data each element instance must be on its own line, as all
///   writers do; a vertex line with too few or too many values is an error.
/// - A missing `end_header` or `format` line, an unknown format or type, a
///   missing `x`/`y`/`z` property and data shorter than the header announces
///   (the message names the vertex) are errors.
///
/// \tparam Kernel a CGAL kernel providing `Point_3` and `Vector_3`
/// \param in the stream to read to its end; it must be opened in binary mode
///        for binary PLY
/// \param name_for_messages how the input is named in error messages
/// \returns the points, and normals if the vertices have `nx ny nz`
/// \throws Read_error if the stream cannot be read or the content is invalid
template <class Kernel>
Point_cloud<Kernel> read_ply_point_cloud(std::istream& in, const std::string& name_for_messages)
{
  namespace reader = internal::point_cloud_reader;
  const reader::Input_buffer data = reader::read_stream(in, name_for_messages);
  Point_cloud<Kernel> pc;
  reader::parse_ply(data.view(), name_for_messages, pc, &data);
  return pc;
}

/// \ingroup PkgDFL1SkeletonRef
/// Reads the vertices of an ASCII OFF file as a point cloud.
///
/// - The first token must contain `OFF` (or be a number, see headerless files
///   below); the letters before it are the usual
///   Geomview prefixes (`ST`, `C`, `N`, `n`), and any suffix is accepted
///   (`OFF`, `NOFF`, `COFF`, `NCOFF`, `CNOFF`, `NOFF_SK`...). `nOFF` is
///   accepted with dimension 3 only; `4OFF` and binary OFF (`OFF BINARY`) are
///   rejected as not supported.
/// - The counts may follow the keyword on the same line or come on the next
///   line, as `V F E`, `V F` or just `V`. Only `V` is used: faces are not read.
/// - Blank lines and `#` comments are skipped.
/// - Each of the `V` following lines starts with `x y z`. When the keyword has
///   the `N` prefix, the number of values on the first vertex line decides:
///   with 6 or more, the next three values are the normal and must be present
///   on every vertex line (a shorter line is an error); with exactly 3, the
///   file has no normals despite its keyword (some writers put `NOFF` on plain
///   `x y z` files), and every one of the `V` vertex lines must then have
///   exactly 3 values (any other width is an error naming the vertex and the
///   line). Further values (colours, texture coordinates) are ignored.
/// - A file with fewer vertex lines than announced is an error:
///   `"header says V vertices but the file ends after M"`.
/// - **Headerless files:** when the first token is a number (no keyword), the
///   file has no header and no counts: every content line is a vertex,
///   `x y z` or `x y z nx ny nz`, and the first line's width (3 or 6) must be
///   that of every line; any other width, on the first line or on a later one
///   (a face line, say), is an error naming the line. All the lines of the
///   file are read. A first line of 1 to 3 non-negative integers only (such as
///   `3 0 0`) reads as the counts line of a header whose keyword is missing and
///   is an error: such a line cannot be told from a vertex with certainty.
///
/// \tparam Kernel a CGAL kernel providing `Point_3` and `Vector_3`
/// \param in the stream to read to its end
/// \param name_for_messages how the input is named in error messages
/// \returns the points, and normals when the vertex lines have them
///          (`N`-prefixed keyword with 6 values, or headerless with 6 columns)
/// \throws Read_error if the stream cannot be read or the content is invalid
template <class Kernel>
Point_cloud<Kernel> read_off_point_cloud(std::istream& in, const std::string& name_for_messages)
{
  namespace reader = internal::point_cloud_reader;
  const reader::Input_buffer data = reader::read_stream(in, name_for_messages);
  Point_cloud<Kernel> pc;
  reader::parse_off(data.view(), name_for_messages, pc, &data);
  return pc;
}

/// \ingroup PkgDFL1SkeletonRef
/// Reads a point cloud file, choosing the format from the file name's
/// extension, in any letter case: `.xyz`, `.pts`, `.txt` (see
/// `read_xyz_point_cloud()`), `.ply` (see `read_ply_point_cloud()`) and `.off`
/// (see `read_off_point_cloud()`). The file is opened read-only.
///
/// \tparam Kernel a CGAL kernel providing `Point_3` and `Vector_3`
/// \param filename path of the file to read
/// \returns the points, and normals if the file has usable ones
/// \throws Read_error if the extension is not one of the above, the path does
///         not name a readable file (`"<file>: cannot open file..."`), or the
///         content is invalid
template <class Kernel>
Point_cloud<Kernel> read_point_cloud(const std::string& filename)
{
  namespace reader = internal::point_cloud_reader;
  const std::string ext = reader::lower_case_extension(filename);
  const bool is_xyz = ext == ".xyz" || ext == ".pts" || ext == ".txt";
  if(!is_xyz && ext != ".ply" && ext != ".off")
    reader::fail(filename, "",
                 "unsupported file extension " + reader::quote_token(ext) +
                     " (expected .xyz, .pts, .txt, .ply or .off)");
  const reader::Input_buffer data = reader::read_file(filename);
  Point_cloud<Kernel> pc;
  try {
    if(is_xyz)
      reader::parse_xyz(data.view(), filename, pc, &data);
    else if(ext == ".ply")
      reader::parse_ply(data.view(), filename, pc, &data);
    else
      reader::parse_off(data.view(), filename, pc, &data);
  } catch(const Read_error&) {
    data.check_unchanged(filename); // a change, rather than the error it caused
    throw;
  }
  data.check_unchanged(filename);
  return pc;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_READ_POINT_CLOUD_H
