// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_POINT_CLOUD_IMPL_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_POINT_CLOUD_IMPL_H

/// \file read_point_cloud_impl.h
/// The parsers behind `read_point_cloud.h`. Each one works on the whole file
/// held in memory (one read, no per-token stream extraction) and appends to the
/// `points` and `normals` vectors of a `Cloud` (in practice
/// `CGAL::DF_L1::Point_cloud<Kernel>`), whose value types are constructible from
/// three `double`s. Filling the caller's vectors directly, rather than an
/// intermediate array, halves the memory touched. Not part of the public API.

#include <CGAL/DF_L1_skeleton/errors.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

// libstdc++ >= 11, MSVC >= 19.24 and recent libc++ have a floating-point
// std::from_chars (locale-independent and fast); otherwise fall back to strtod.
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L && \
    !defined(CGAL_DF_L1_NO_FLOAT_FROM_CHARS)
#  define CGAL_DF_L1_HAS_FLOAT_FROM_CHARS 1
#endif

namespace CGAL {
namespace DF_L1 {
namespace internal {
// A namespace of its own: the generic helper names here (fail, Line_reader...)
// must not collide with other internal headers of the package.
namespace point_cloud_reader {

/// Appends a point or vector made of `c` to `v`.
template <class Vector>
void append(Vector& v, const std::array<double, 3>& c)
{
  v.emplace_back(c[0], c[1], c[2]);
}

// ---------------------------------------------------------------------------
// Error messages
// ---------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------
// Input
// ---------------------------------------------------------------------------

/// Reads everything left in `in`. `size_hint` (e.g. the file size) only
/// pre-sizes the buffer; it is capped so that a wrong hint cannot cost memory.
inline std::string read_stream(std::istream& in, const std::string& name,
                               std::uint64_t size_hint = 0)
{
  if(!in)
    fail(name, "", "cannot read (the stream is not in a good state)");
  constexpr std::size_t chunk = std::size_t(1) << 16;
  std::string data;
  // + chunk: the last read asks for a full chunk past the expected end.
  data.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(size_hint, std::uint64_t(1) << 30)) +
               chunk);
  for(;;) {
    const std::size_t old_size = data.size();
    data.resize(old_size + chunk);
    in.read(&data[old_size], static_cast<std::streamsize>(chunk));
    const std::streamsize got = in.gcount();
    data.resize(old_size + static_cast<std::size_t>(got));
    if(!in)
      break;
  }
  if(in.bad())
    fail(name, "", "read error");
  return data;
}

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
class Line_reader
{
public:
  Line_reader(std::string_view buffer, std::size_t start, std::size_t first_line_number,
              bool lone_cr_ends_line)
    : buf_(buffer), pos_(start), next_line_(first_line_number), lone_cr_(lone_cr_ends_line)
  {}

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
      const void* cr = std::memchr(begin, '\r', len);
      if(cr != nullptr) { // the line ends at a lone "\r"
        len = static_cast<std::size_t>(static_cast<const char*>(cr) - begin);
        consumed = len + 1;
      }
    }
    line = std::string_view(begin, len);
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
  const char* newline_ = nullptr; // next '\n' at or after pos_, or the end
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

/// An upper bound on the number of points the text from `start` on can hold,
/// to size reservations: one per line, and no more than one per 6 bytes (the
/// shortest point line is "1 2 3\n"), so blank lines cannot inflate it.
inline std::size_t max_text_points(std::string_view buf, std::size_t start)
{
  if(start >= buf.size())
    return 0;
  const std::size_t lines =
      static_cast<std::size_t>(std::count(buf.begin() + static_cast<std::ptrdiff_t>(start),
                                          buf.end(), '\n')) + 1;
  return std::min(lines, (buf.size() - start + 1) / 6 + 1);
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

// ---------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------

enum class Number_status { ok, not_a_number, out_of_range };

/// For a decimal number out of the range of `double`: whether it overflows
/// (rather than underflows). Such numbers are beyond 1e308 or below 1e-307, so
/// the position of the first significant digit decides without ambiguity.
inline bool decimal_overflows(const char* first, const char* last)
{
  const char* p = first;
  if(p != last && (*p == '+' || *p == '-'))
    ++p;
  long long magnitude = 0; // decimal exponent of the leading significant digit, plus one
  bool significant = false;
  for(; p != last && *p >= '0' && *p <= '9'; ++p) {
    if(*p != '0')
      significant = true;
    if(significant)
      ++magnitude;
  }
  if(p != last && *p == '.') {
    for(++p; p != last && *p >= '0' && *p <= '9'; ++p) {
      if(significant)
        continue;
      if(*p == '0')
        --magnitude;
      else
        significant = true;
    }
  }
  long long exponent = 0;
  if(p != last && (*p == 'e' || *p == 'E')) {
    ++p;
    bool negative = false;
    if(p != last && (*p == '+' || *p == '-'))
      negative = (*p++ == '-');
    for(; p != last && *p >= '0' && *p <= '9'; ++p)
      exponent = std::min(exponent * 10 + (*p - '0'), 1000000000LL); // saturate
    if(negative)
      exponent = -exponent;
  }
  return magnitude + exponent > 0;
}

/// Parses a whole token as a `double` ("nan" and "inf" are accepted here and
/// rejected by the callers' finiteness checks, which give a better message).
/// Underflow gives a signed zero; overflow gives `out_of_range`.
inline Number_status parse_double(std::string_view tok, double& value)
{
  const char* first = tok.data();
  const char* const last = first + tok.size();
  if(first != last && *first == '+') { // from_chars rejects an explicit '+'
    ++first;
    if(first != last && (*first == '+' || *first == '-'))
      return Number_status::not_a_number;
  }
  if(first == last)
    return Number_status::not_a_number;
#ifdef CGAL_DF_L1_HAS_FLOAT_FROM_CHARS
  const std::from_chars_result r = std::from_chars(first, last, value, std::chars_format::general);
  if(r.ptr != last || r.ec == std::errc::invalid_argument)
    return Number_status::not_a_number;
  if(r.ec == std::errc::result_out_of_range) {
    if(decimal_overflows(first, last))
      return Number_status::out_of_range;
    value = (*first == '-') ? -0.0 : 0.0;
  }
  return Number_status::ok;
#else
  // strtod needs a terminated string; it also accepts hexadecimal floats,
  // which is harmless. It follows the C locale, the default of C++ programs.
  const std::string copy(first, last);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(copy.c_str(), &end);
  if(end != copy.c_str() + copy.size())
    return Number_status::not_a_number;
  if(errno == ERANGE && std::isinf(value))
    return Number_status::out_of_range;
  return Number_status::ok;
#endif
}

/// Parses a non-negative decimal integer (an optional '+', digits only).
inline bool parse_count(std::string_view tok, std::uint64_t& value)
{
  std::size_t i = (!tok.empty() && tok[0] == '+') ? 1 : 0;
  if(i == tok.size())
    return false;
  value = 0;
  for(; i < tok.size(); ++i) {
    const char c = tok[i];
    if(c < '0' || c > '9')
      return false;
    const std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
    if(value > (std::numeric_limits<std::uint64_t>::max() - digit) / 10)
      return false;
    value = value * 10 + digit;
  }
  return true;
}

inline bool is_number(std::string_view tok)
{
  double unused;
  return parse_double(tok, unused) != Number_status::not_a_number;
}

/// The message for a token that `parse_double` did not accept.
inline std::string number_error(std::string_view tok, Number_status status)
{
  if(status == Number_status::out_of_range)
    return "number out of the range of a double: " + quote_token(tok);
  std::string msg = "expected a number, got " + quote_token(tok);
  if(tok.find(',') != std::string_view::npos)
    msg += " (values must be separated by spaces or tabs, and the decimal mark must be '.')";
  return msg;
}

/// Parses three coordinate tokens; throws if one is not a finite number.
/// `where()` builds the location only when needed: building it for every
/// point would cost an allocation per point.
template <class Where>
std::array<double, 3> parse_coordinates(const std::string_view* tok, const std::string& name,
                                        const Where& where)
{
  std::array<double, 3> c;
  for(std::size_t i = 0; i < 3; ++i) {
    const Number_status st = parse_double(tok[i], c[i]);
    if(st != Number_status::ok)
      fail(name, where(), number_error(tok[i], st));
    if(!std::isfinite(c[i]))
      fail(name, where(), "coordinate is not finite: " + quote_token(tok[i]));
  }
  return c;
}

/// Parses three normal tokens. Returns the status of the first bad token and
/// its index in `bad`; a non-finite value is reported through `finite`.
inline Number_status parse_normal(const std::string_view* tok, std::array<double, 3>& n,
                                  bool& finite, std::size_t& bad)
{
  finite = true;
  for(std::size_t i = 0; i < 3; ++i) {
    const Number_status st = parse_double(tok[i], n[i]);
    if(st != Number_status::ok) {
      bad = i;
      return st;
    }
    if(!std::isfinite(n[i]))
      finite = false;
  }
  return Number_status::ok;
}

/// Error for a point line with fewer than 3 tokens: names the first
/// non-numeric token if there is one, else the missing columns.
[[noreturn]] inline void fail_short_line(const std::string_view* tok, std::size_t size,
                                         const std::string& name, const std::string& where,
                                         const char* expected)
{
  for(std::size_t i = 0; i < size; ++i) {
    double unused;
    const Number_status st = parse_double(tok[i], unused);
    if(st != Number_status::ok)
      fail(name, where, number_error(tok[i], st));
  }
  fail(name, where, std::string("expected ") + expected + ", got " + std::to_string(size) +
                        (size == 1 ? " number" : " numbers"));
}

// ---------------------------------------------------------------------------
// XYZ / PTS / TXT
// ---------------------------------------------------------------------------

template <class Cloud>
void parse_xyz(std::string_view buf, const std::string& name, Cloud& out)
{
  const std::size_t start = skip_bom(buf);
  out.points.reserve(max_text_points(buf, start));
  Line_reader lines(buf, start, 1, true);

  bool first_content_line = true;
  bool six_columns_everywhere = true; // normals are kept only while this holds
  bool normals_finite = true;
  std::string deferred_error; // a bad normal token, fatal only if normals are kept

  std::string_view line;
  while(lines.next(line)) {
    const Line_tokens<7> t(strip_comment(line));
    if(t.size == 0)
      continue;
    std::uint64_t unused_count;
    if(first_content_line && t.size == 1 && parse_count(t.tok[0], unused_count)) {
      // The count line of .pts files. The count is not trusted: the points read are the truth.
      first_content_line = false;
      continue;
    }
    first_content_line = false;

    const auto where = [&lines] { return line_where(lines.line_number()); };
    if(t.size < 3)
      fail_short_line(t.tok.data(), t.size, name, where(), "at least 3 numbers (x y z)");
    append(out.points, parse_coordinates(t.tok.data(), name, where));

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
      out.normals.reserve(out.points.capacity());
    append(out.normals, n);
  }

  if(out.points.empty())
    fail(name, "", "no points");
  if(six_columns_everywhere && !deferred_error.empty())
    fail(name, "", deferred_error);
  if(!six_columns_everywhere || !normals_finite)
    out.normals.clear();
}

// ---------------------------------------------------------------------------
// OFF
// ---------------------------------------------------------------------------

/// Appends the point of an OFF vertex line (its first three tokens) and, with
/// `with_normal`, the normal of the next three; a bad number is an error at `where()`,
/// a non-finite normal clears `normals_finite`.
template <class Cloud, class Where>
void append_off_vertex(Cloud& out, const std::string_view* tok, bool with_normal, bool& normals_finite,
                       const std::string& name, const Where& where)
{
  append(out.points, parse_coordinates(tok, name, where));
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
  out.points.reserve(max_text_points(buf, lines.position()) + 1);
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
        out.normals.reserve(out.points.capacity());
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

template <class Cloud>
void parse_off(std::string_view buf, const std::string& name, Cloud& out)
{
  const std::size_t start = skip_bom(buf);
  Line_reader lines(buf, start, 1, true);
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

  out.points.reserve(capped_reserve(n, max_text_points(buf, lines.position())));
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
    const Line_tokens<6> t(line);
    if(t.size < 3)
      fail_short_line(t.tok.data(), t.size, name, where(), "at least 3 numbers (x y z)");
    if(has_normals && i == 0) {
      first_vertex_line = lines.line_number();
      read_normals = t.size != 3;
      if(read_normals)
        out.normals.reserve(out.points.capacity());
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
    append_off_vertex(out, t.tok.data(), read_normals, normals_finite, name, where);
  }
  // Faces and anything after them are not read.
  if(!normals_finite)
    out.normals.clear();
}

// ---------------------------------------------------------------------------
// PLY
// ---------------------------------------------------------------------------

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
                      Cloud& out)
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
  out.points.reserve(capped_reserve(v.count, c.remaining() / std::max<std::uint64_t>(min_size, 1)));
  if(has_normals)
    out.normals.reserve(out.points.capacity());
  bool normals_finite = true;

  for(std::uint64_t i = 0; i < v.count; ++i) {
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
                     Cloud& out)
{
  // One element instance per line, as every writer does; this lets a line with
  // too many or too few values be reported instead of shifting all that follows.
  Line_reader lines(buf, h.data_offset, h.next_line, true);
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
  out.points.reserve(capped_reserve(v.count, max_text_points(buf, lines.position())));
  if(has_normals)
    out.normals.reserve(out.points.capacity());
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

template <class Cloud>
void parse_ply(std::string_view buf, const std::string& name, Cloud& out)
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
    parse_ply_ascii(buf, h, vertex_index, roles, has_normals, name, out);
  else
    parse_ply_binary(buf, h, vertex_index, roles, has_normals, name, out);
}

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_READ_POINT_CLOUD_IMPL_H
