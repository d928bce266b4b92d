// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_TEXT_INPUT_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_TEXT_INPUT_H

/// \file text_input.h
/// The text side shared by the point cloud readers: iterating over the lines
/// and tokens of an input held in memory (`Input_buffer`; the parsers work on
/// the buffer, with no per-token stream extraction), and the helpers that keep
/// reservations within what the data can hold. Not part of the public API.

#include <CGAL/DF_L1_skeleton/IO/internal/input_buffer.h>
#include <CGAL/DF_L1_skeleton/IO/internal/reader_messages.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <string>
#include <string_view>

namespace CGAL {
namespace DF_L1 {
namespace internal {
// A namespace of its own: the generic helper names here (Line_reader, skip_bom...)
// must not collide with other internal headers of the package.
namespace point_cloud_reader {

// ---------------------------------------------------------------------------
// Lines and tokens
// ---------------------------------------------------------------------------

/// Whitespace inside a line ('\n' never occurs there).
inline bool is_blank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Iterates over the lines of a buffer, counting them from 1. A line ends at
/// "\n", "\r\n", or (when `lone_cr_ends_line`) a lone "\r" as written by old Mac
/// tools. The PLY header disables the latter: binary data may follow
/// "end_header\r" only through a "\n".
/// With `input` (whose view must be `buffer`), the pages of a mapped file are
/// dropped every few MB behind the current line.
class Line_reader
{
public:
  Line_reader(std::string_view buffer, std::size_t start, std::size_t first_line_number,
              bool lone_cr_ends_line, const Input_buffer* input = nullptr)
    : buf_(buffer), pos_(start), next_line_(first_line_number), lone_cr_(lone_cr_ends_line),
      input_(input), next_drop_(start + drop_interval)
  {}

  /// Bytes parsed between two calls of `Input_buffer::drop_pages_before()`.
  static constexpr std::size_t drop_interval = std::size_t(8) << 20;

  /// Gets the next line, without its end-of-line characters.
  bool next(std::string_view& line)
  {
    if(pos_ >= buf_.size())
      return false;
    const char* const begin = buf_.data() + pos_;
    const char* const end = buf_.data() + buf_.size();
    // memchr is much faster than a byte loop on large files. The next "\n" is
    // remembered: in a file of lone-"\r" lines it serves many lines.
    if(newline_ == nullptr || newline_ < begin) {
      newline_ = static_cast<const char*>(std::memchr(begin, '\n', static_cast<std::size_t>(end - begin)));
      if(newline_ == nullptr)
        newline_ = end;
    }
    const char* const p = newline_;
    std::size_t len = static_cast<std::size_t>(p - begin);
    std::size_t consumed = len + (p != end ? 1 : 0);
    if(len > 0 && begin[len - 1] == '\r')
      --len; // "\r\n"
    if(lone_cr_) {
      // The next '\r' is searched for by windows of 64 KiB and remembered: a
      // file without any costs a search per window rather than one per line,
      // and no search runs far ahead of the parser through a mapped file.
      // Invariant: no '\r' in [begin, next_cr_) when next_cr_ >= begin.
      const char* const line_end = begin + len;
      while(next_cr_ < begin || (!next_cr_is_cr_ && next_cr_ < line_end)) {
        const char* const from = std::max(next_cr_, begin);
        const char* const window_end = from + std::min<std::size_t>(static_cast<std::size_t>(end - from), cr_window);
        const void* cr = std::memchr(from, '\r', static_cast<std::size_t>(window_end - from));
        next_cr_ = cr != nullptr ? static_cast<const char*>(cr) : window_end;
        next_cr_is_cr_ = cr != nullptr;
      }
      if(next_cr_is_cr_ && next_cr_ < line_end) { // the line ends at a lone "\r"
        len = static_cast<std::size_t>(next_cr_ - begin);
        consumed = len + 1;
      }
    }
    line = std::string_view(begin, len);
    if(input_ != nullptr && pos_ >= next_drop_) {
      input_->drop_pages_before(pos_);
      next_drop_ = pos_ + drop_interval;
    }
    pos_ += consumed;
    current_line_ = next_line_++;
    return true;
  }

  /// Number of the line last returned by `next()`.
  std::size_t line_number() const { return current_line_; }
  /// Offset of the first byte after the line last returned.
  std::size_t position() const { return pos_; }

private:
  std::string_view buf_;
  std::size_t pos_;
  std::size_t next_line_;
  std::size_t current_line_ = 0;
  bool lone_cr_;
  const Input_buffer* input_;
  std::size_t next_drop_;
  const char* newline_ = nullptr; // next '\n' at or after pos_, or the end
  static constexpr std::size_t cr_window = std::size_t(1) << 16;
  const char* next_cr_ = buf_.data() + pos_; // see next()
  bool next_cr_is_cr_ = false;
};

/// Whitespace-separated tokens of one line.
class Token_reader
{
public:
  explicit Token_reader(std::string_view line) : s_(line) {}

  bool next(std::string_view& tok)
  {
    while(pos_ < s_.size() && is_blank(s_[pos_]))
      ++pos_;
    if(pos_ == s_.size())
      return false;
    const std::size_t start = pos_;
    while(pos_ < s_.size() && !is_blank(s_[pos_]))
      ++pos_;
    tok = s_.substr(start, pos_ - start);
    return true;
  }

private:
  std::string_view s_;
  std::size_t pos_ = 0;
};

/// The first `max_tokens` tokens of a line; `size == max_tokens` means "that many
/// or more". Enough to tell 3, 6 and 7+ columns apart without scanning further.
template <std::size_t max_tokens>
struct Line_tokens
{
  std::array<std::string_view, max_tokens> tok;
  std::size_t size = 0;

  Line_tokens() = default;
  explicit Line_tokens(std::string_view line)
  {
    Token_reader reader(line);
    while(size < max_tokens && reader.next(tok[size]))
      ++size;
  }
};

/// The line up to a '#' comment; used by the text formats whose numbers never
/// contain '#'.
inline std::string_view strip_comment(std::string_view line)
{
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// Offset of the first byte after a UTF-8 byte-order mark, as some Windows
/// editors write at the start of text files.
inline std::size_t skip_bom(std::string_view buf)
{
  return (buf.size() >= 3 && buf.compare(0, 3, "\xEF\xBB\xBF") == 0) ? 3 : 0;
}

/// The number of points to reserve for the text from `start` on: one per line,
/// and no more than one per 6 bytes (the shortest point line is "1 2 3\n"), so
/// blank lines cannot inflate it. Beyond 16 MB the lines are not all counted
/// (that pass would bring every page of a mapped file into memory at once): the
/// count of the first 4 MB is extrapolated with a 2 % margin, and the vectors
/// grow as usual should the rest of the file have shorter lines.
inline std::size_t max_text_points(std::string_view buf, std::size_t start)
{
  if(start >= buf.size())
    return 0;
  const std::size_t bytes = buf.size() - start;
  const std::size_t bound = (bytes + 1) / 6 + 1;
  constexpr std::size_t exact_limit = std::size_t(16) << 20;
  constexpr std::size_t sample = std::size_t(4) << 20;
  const char* const first = buf.data() + start;
  if(bytes <= exact_limit)
    return std::min(static_cast<std::size_t>(std::count(first, first + bytes, '\n')) + 1, bound);
  const double lines_per_byte =
      static_cast<double>(std::count(first, first + sample, '\n')) / static_cast<double>(sample);
  const double estimate = lines_per_byte * static_cast<double>(bytes) * 1.02 + 1024.0;
  return std::min(static_cast<std::size_t>(estimate), bound);
}

/// Reserves `n` elements in `v`, on huge pages where the system has them
/// (filling 240 MB of points otherwise costs 60000 page faults).
template <class Vector>
void reserve_elements(Vector& v, std::size_t n)
{
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(typename Vector::value_type));
}

/// The most points the text from `start` on can hold: one per 6 bytes (the
/// shortest point line is "1 2 3\n"). Caps a count announced by a header, which
/// is then reserved exactly when it is honest.
inline std::size_t text_points_bound(std::string_view buf, std::size_t start)
{
  return start >= buf.size() ? 0 : (buf.size() - start + 1) / 6 + 1;
}

/// Capacity to reserve for a count announced by a header: never more than the
/// remaining data can hold, so that a lying header costs no memory.
inline std::size_t capped_reserve(std::uint64_t announced, std::uint64_t possible)
{
  return static_cast<std::size_t>(std::min(announced, possible));
}

inline bool ascii_iequals(std::string_view a, std::string_view b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i) {
    const char ca = (a[i] >= 'a' && a[i] <= 'z') ? char(a[i] - 'a' + 'A') : a[i];
    const char cb = (b[i] >= 'a' && b[i] <= 'z') ? char(b[i] - 'a' + 'A') : b[i];
    if(ca != cb)
      return false;
  }
  return true;
}

/// Position of `needle` in `hay`, ignoring ASCII case.
inline std::size_t ascii_ifind(std::string_view hay, std::string_view needle)
{
  if(needle.size() > hay.size())
    return std::string_view::npos;
  for(std::size_t i = 0; i + needle.size() <= hay.size(); ++i)
    if(ascii_iequals(hay.substr(i, needle.size()), needle))
      return i;
  return std::string_view::npos;
}

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_TEXT_INPUT_H
