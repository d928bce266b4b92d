// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_PARSE_NUMBERS_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_PARSE_NUMBERS_H

/// \file parse_numbers.h
/// Number parsing for the text formats of the point cloud readers: exact,
/// locale-independent `double` and count parsing, coordinate and normal
/// triples, and the messages for tokens that are not numbers. Not part of the
/// public API.

#include <CGAL/DF_L1_skeleton/IO/internal/reader_messages.h>
#include <CGAL/DF_L1_skeleton/IO/internal/text_input.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

// libstdc++ >= 11, MSVC >= 19.24 and recent libc++ have a floating-point
// std::from_chars (locale-independent and fast); otherwise fall back to strtod.
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L && \
    !defined(CGAL_DF_L1_NO_FLOAT_FROM_CHARS)
#  define CGAL_DF_L1_HAS_FLOAT_FROM_CHARS 1
#endif

namespace CGAL {
namespace DF_L1 {
namespace internal {
// A namespace of its own: the generic helper names here (append, parse_double...)
// must not collide with other internal headers of the package.
namespace point_cloud_reader {

/// Appends a point or vector made of `c` to `v`.
template <class Vector>
void append(Vector& v, const std::array<double, 3>& c)
{
  v.emplace_back(c[0], c[1], c[2]);
}

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

/// The fast path of the text formats, for a line of finite numbers separated
/// by spaces and tabs: parses the first three tokens of `line` as coordinates
/// straight from the buffer (no tokenizing pass) and fills `t` with the tokens
/// of the whole line as `Line_tokens(strip_comment(line))` would. Returns false
/// on anything else (a '+' sign, a comment or a '\r' among the first three
/// tokens, a bad or non-finite number, fewer than three tokens...): the caller
/// then takes the general path, which gives the same values or the error.
/// The values are those of `parse_double`: `std::from_chars` on the same
/// characters, since a token here ends at a space, a tab or the line's end.
template <std::size_t max_tokens>
bool fast_coordinates(std::string_view line, std::array<double, 3>& c, Line_tokens<max_tokens>& t)
{
#ifdef CGAL_DF_L1_HAS_FLOAT_FROM_CHARS
  static_assert(max_tokens > 3, "the line's width is counted past the coordinates");
  const char* p = line.data();
  const char* const end = p + line.size();
  for(std::size_t i = 0; i < 3; ++i) {
    while(p != end && (*p == ' ' || *p == '\t'))
      ++p;
    if(p == end || *p == '+')
      return false;
    const std::from_chars_result r = std::from_chars(p, end, c[i], std::chars_format::general);
    if(r.ec != std::errc() || (r.ptr != end && *r.ptr != ' ' && *r.ptr != '\t') || !std::isfinite(c[i]))
      return false;
    t.tok[i] = std::string_view(p, static_cast<std::size_t>(r.ptr - p));
    p = r.ptr;
  }
  // The rest of the line, up to a comment, gives the other columns.
  t.size = 3;
  Token_reader rest(strip_comment(std::string_view(p, static_cast<std::size_t>(end - p))));
  while(t.size < max_tokens && rest.next(t.tok[t.size]))
    ++t.size;
  return true;
#else
  (void)line;
  (void)c;
  (void)t;
  return false;
#endif
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

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_PARSE_NUMBERS_H
