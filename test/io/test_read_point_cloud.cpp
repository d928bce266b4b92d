// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of the point-cloud readers (IO/read_point_cloud.h): every format's
// happy paths, the in-the-wild header variants, and malformed inputs, which
// must all give a one-line Read_error naming the file and the line or vertex.

#include "support/shared_data.h"

#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cloud = CGAL::DF_L1::Point_cloud<K>;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;

/// A fresh directory under the system temp directory, removed at scope exit.
class Temp_dir
{
public:
  Temp_dir()
  {
    static std::atomic<unsigned> counter{0};
    std::random_device rd;
    for(int attempt = 0; attempt < 100; ++attempt) {
      path_ = fs::temp_directory_path() /
              ("df_l1_read_test_" + std::to_string(rd()) + "_" + std::to_string(counter++));
      std::error_code ec;
      if(fs::create_directory(path_, ec))
        return;
    }
    FAIL("cannot create a temporary directory");
  }
  ~Temp_dir()
  {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  Temp_dir(const Temp_dir&) = delete;
  Temp_dir& operator=(const Temp_dir&) = delete;

  /// Writes `content` byte for byte to `name` in the directory; returns its path.
  std::string write(const std::string& name, const std::string& content) const
  {
    const fs::path p = path_ / name;
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    REQUIRE(out.good());
    return p.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

private:
  fs::path path_;
};

std::string file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Reads `path`, checking that the file is left byte-for-byte unchanged.
Cloud read_unmodified(const std::string& path)
{
  const std::string before = file_bytes(path);
  const auto time_before = fs::last_write_time(path);
  Cloud pc = CGAL::DF_L1::read_point_cloud<K>(path);
  CHECK(fs::file_size(path) == before.size());
  CHECK(file_bytes(path) == before);
  CHECK(fs::last_write_time(path) == time_before);
  return pc;
}

std::string read_error_message(const std::string& path)
{
  try {
    CGAL::DF_L1::read_point_cloud<K>(path);
  } catch(const CGAL::DF_L1::Read_error& e) {
    return e.what();
  }
  return "<no Read_error thrown>";
}

/// Requires a Read_error whose one-line message holds the file name and
/// every one of `parts`; also checks the file is not modified.
void require_read_error(const std::string& path, std::initializer_list<std::string> parts = {})
{
  const bool exists = fs::is_regular_file(path);
  const std::string before = exists ? file_bytes(path) : std::string();
  REQUIRE_THROWS_AS(CGAL::DF_L1::read_point_cloud<K>(path), CGAL::DF_L1::Read_error);
  const std::string msg = read_error_message(path);
  INFO("message: " << msg);
  CHECK_THAT(msg, Contains(path));
  CHECK(msg.find('\n') == std::string::npos);
  CHECK(msg.find('\r') == std::string::npos);
  for(const std::string& part : parts)
    CHECK_THAT(msg, Contains(part));
  if(exists)
    CHECK(file_bytes(path) == before);
}

void check_point(const K::Point_3& p, double x, double y, double z)
{
  CHECK(p.x() == x);
  CHECK(p.y() == y);
  CHECK(p.z() == z);
}

void check_vector(const K::Vector_3& v, double x, double y, double z)
{
  CHECK(v.x() == x);
  CHECK(v.y() == y);
  CHECK(v.z() == z);
}

/// Builds binary PLY payloads in either byte order.
class Binary_writer
{
public:
  explicit Binary_writer(bool big_endian) : big_(big_endian) {}

  template <class T>
  Binary_writer& put(T value)
  {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    const std::uint16_t one = 1;
    char first;
    std::memcpy(&first, &one, 1);
    const bool host_little = first == 1;
    if(host_little == big_)
      std::reverse(b, b + sizeof(T));
    bytes_.append(b, sizeof(T));
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

private:
  bool big_;
  std::string bytes_;
};

} // namespace

// ===========================================================================
// XYZ / PTS / TXT
// ===========================================================================

TEST_CASE("xyz: points with comments, blank lines, CRLF, tabs and signs", "[io][read][xyz]")
{
  Temp_dir dir;
  const std::string path = dir.write("a.xyz",
                                     "# a comment\r\n"
                                     "\r\n"
                                     "1 2 3\r\n"
                                     "   \t  \r\n"
                                     "-1.5\t+2.25e1   3e-2  # trailing comment\r\n"
                                     "  .5 5. -0\r\n");
  const Cloud pc = read_unmodified(path);
  REQUIRE(pc.points.size() == 3);
  CHECK(pc.normals.empty());
  check_point(pc.points[0], 1, 2, 3);
  check_point(pc.points[1], -1.5, 22.5, 0.03);
  check_point(pc.points[2], 0.5, 5, 0);
}

TEST_CASE("xyz: six columns everywhere give normals", "[io][read][xyz]")
{
  Temp_dir dir;
  const std::string path = dir.write("n.xyz", "0 0 0 0 0 1\n1 0 0 0 1 0\n\n0 1 0 1 0 0\n");
  const Cloud pc = read_unmodified(path);
  REQUIRE(pc.points.size() == 3);
  REQUIRE(pc.normals.size() == 3);
  check_point(pc.points[1], 1, 0, 0);
  check_vector(pc.normals[0], 0, 0, 1);
  check_vector(pc.normals[2], 1, 0, 0);
}

TEST_CASE("xyz: normals rule for other column counts", "[io][read][xyz]")
{
  Temp_dir dir;
  SECTION("4 and 5 columns: points only")
  {
    const Cloud pc = read_unmodified(dir.write("a.xyz", "1 2 3 4\n5 6 7 8 9\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
    check_point(pc.points[1], 5, 6, 7);
  }
  SECTION("7 columns (x y z intensity r g b): points only")
  {
    const Cloud pc = read_unmodified(dir.write("a.txt", "1 2 3 -500 255 128 0\n4 5 6 -20 1 2 3\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
  }
  SECTION("mixed widths: points only")
  {
    const Cloud pc = read_unmodified(dir.write("a.xyz", "0 0 0 0 0 1\n1 1 1\n2 2 2 0 1 0\n"));
    REQUIRE(pc.points.size() == 3);
    CHECK(pc.normals.empty());
  }
  SECTION("extra non-numeric columns are ignored when not read as normals")
  {
    const Cloud pc = read_unmodified(dir.write("a.xyz", "1 2 3 label\n4 5 6 other x y z w\n"));
    REQUIRE(pc.points.size() == 2);
    check_point(pc.points[1], 4, 5, 6);
  }
  SECTION("a non-numeric normal in a six-column file is an error naming the line")
  {
    require_read_error(dir.write("a.xyz", "0 0 0 0 0 1\n1 1 1 0 zz 0\n"), {"line 2", "'zz'"});
  }
  SECTION("non-numeric sixth column is fine once a line is not six columns wide")
  {
    const Cloud pc = read_unmodified(dir.write("a.xyz", "0 0 0 a b c\n1 1 1\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
  }
  SECTION("NaN normals drop all normals, points are kept")
  {
    const Cloud pc = read_unmodified(dir.write("a.xyz", "0 0 0 0 0 1\n1 1 1 nan 0 0\n2 2 2 0 inf 0\n"));
    REQUIRE(pc.points.size() == 3);
    CHECK(pc.normals.empty());
  }
}

TEST_CASE("xyz: pts count line", "[io][read][xyz]")
{
  Temp_dir dir;
  SECTION("correct count")
  {
    const Cloud pc = read_unmodified(dir.write("a.pts", "2\n1 2 3\n4 5 6\n"));
    REQUIRE(pc.points.size() == 2);
    check_point(pc.points[0], 1, 2, 3);
  }
  SECTION("lying count: the actual points are read")
  {
    CHECK(read_unmodified(dir.write("b.pts", "100\n1 2 3\n4 5 6\n7 8 9\n")).points.size() == 3);
    CHECK(read_unmodified(dir.write("c.pts", "# header\n1\n1 2 3\n4 5 6\n")).points.size() == 2);
  }
  SECTION("a one-integer line after the first content line is an error")
  {
    require_read_error(dir.write("d.pts", "1 2 3\n5\n4 5 6\n"), {"line 2", "at least 3 numbers"});
  }
  SECTION("a first line with a single non-integer is an error")
  {
    require_read_error(dir.write("e.xyz", "1.5\n1 2 3\n"), {"line 1"});
    require_read_error(dir.write("f.xyz", "-3\n1 2 3\n"), {"line 1"});
  }
}

TEST_CASE("xyz: extensions are case-insensitive; line end and BOM variants", "[io][read][xyz]")
{
  Temp_dir dir;
  CHECK(read_unmodified(dir.write("UP.XYZ", "1 2 3\n")).points.size() == 1);
  CHECK(read_unmodified(dir.write("up.Pts", "1 2 3\n")).points.size() == 1);
  CHECK(read_unmodified(dir.write("up.TXT", "1 2 3\n")).points.size() == 1);
  // old Mac line ends
  const Cloud cr = read_unmodified(dir.write("cr.xyz", "1 2 3\r4 5 6\r7 8 9"));
  REQUIRE(cr.points.size() == 3);
  check_point(cr.points[2], 7, 8, 9);
  // UTF-8 byte-order mark, no final line end
  const Cloud bom = read_unmodified(dir.write("bom.xyz", "\xEF\xBB\xBF" "1 2 3\n4 5 6"));
  REQUIRE(bom.points.size() == 2);
  check_point(bom.points[0], 1, 2, 3);
}

TEST_CASE("xyz: malformed inputs", "[io][read][xyz][errors]")
{
  Temp_dir dir;
  require_read_error(dir.write("empty.xyz", ""), {"no points"});
  require_read_error(dir.write("comments.xyz", "# nothing\n\n   \n"), {"no points"});
  require_read_error(dir.write("countonly.pts", "12\n"), {"no points"});
  require_read_error(dir.write("two.xyz", "1 2 3\n\n1 2\n"), {"line 3", "got 2 numbers"});
  require_read_error(dir.write("text.xyz", "1 2 3\nabc 2 3\n"), {"line 2", "expected a number", "'abc'"});
  require_read_error(dir.write("suffix.xyz", "1 2 3\n1 2.0abc 3\n"), {"line 2", "'2.0abc'"});
  require_read_error(dir.write("nan.xyz", "1 2 3\n4 5 6\n\n\nnan 1 2\n"), {"line 5", "not finite"});
  require_read_error(dir.write("inf.xyz", "1 2 -inf\n"), {"line 1", "not finite"});
  require_read_error(dir.write("big.xyz", "1 2 3\n1 1e999 3\n"), {"line 2", "out of the range"});
  require_read_error(dir.write("csv.xyz", "1.5,2.5,3.5\n"), {"line 1", "'1.5,2.5,3.5'"});
  require_read_error(dir.write("short.xyz", "abc\n"), {"line 1", "'abc'"});
  require_read_error(dir.write("plus.xyz", "+-1 2 3\n"), {"line 1", "'+-1'"});
  require_read_error(dir.write("crlf.xyz", "1 2 3\r\n4 x 6\r\n"), {"line 2", "'x'"});
  // binary garbage: the message stays one line with the bytes escaped
  require_read_error(dir.write("garbage.xyz", std::string("\x01\x02\n\xff\x00\x7f 1 2\n", 11)),
                     {"line 1"});
  // underflow is not an error: the value becomes zero
  const Cloud tiny = read_unmodified(dir.write("tiny.xyz", "1e-400 -1e-400 1e-310\n"));
  REQUIRE(tiny.points.size() == 1);
  check_point(tiny.points[0], 0, 0, 1e-310);
}

TEST_CASE("xyz: stream interface names the input as told", "[io][read][xyz]")
{
  std::istringstream good("1 2 3 0 0 1\n");
  const Cloud pc = CGAL::DF_L1::read_xyz_point_cloud<K>(good, "from-memory");
  REQUIRE(pc.points.size() == 1);
  CHECK(pc.normals.size() == 1);

  std::istringstream bad("1 2 3\n1 2 oops\n");
  try {
    CGAL::DF_L1::read_xyz_point_cloud<K>(bad, "from-memory");
    FAIL("no Read_error");
  } catch(const CGAL::DF_L1::Read_error& e) {
    CHECK_THAT(std::string(e.what()), Contains("from-memory: line 2:") && Contains("'oops'"));
  }
}

// ===========================================================================
// OFF
// ===========================================================================

TEST_CASE("off: happy paths", "[io][read][off]")
{
  Temp_dir dir;
  SECTION("counts on their own line, faces are not read")
  {
    const Cloud pc = read_unmodified(dir.write("a.off",
                                               "OFF\n# comment\n3 1 0\n\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    REQUIRE(pc.points.size() == 3);
    CHECK(pc.normals.empty());
    check_point(pc.points[1], 1, 0, 0);
  }
  SECTION("counts on the keyword line, CRLF")
  {
    const Cloud pc = read_unmodified(dir.write("b.off", "OFF 2 0 0\r\n1 2 3\r\n4 5 6\r\n"));
    REQUIRE(pc.points.size() == 2);
    check_point(pc.points[1], 4, 5, 6);
  }
  SECTION("NOFF gives normals")
  {
    const Cloud pc = read_unmodified(dir.write("c.off", "NOFF\n2 0 0\n1 2 3 0 0 1\n4 5 6 0 1 0\n"));
    REQUIRE(pc.points.size() == 2);
    REQUIRE(pc.normals.size() == 2);
    check_vector(pc.normals[1], 0, 1, 0);
  }
  SECTION("original NOFF_SK header of camel")
  {
    const Cloud pc = read_unmodified(dir.write("camel.off", "NOFF_SK\n2 0 0\n1 2 3 0 0 1\n4 5 6 0 1 0\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.size() == 2);
  }
  SECTION("two-number counts line 'N 0' of fertility and woman")
  {
    const Cloud pc = read_unmodified(dir.write("fert.off", "NOFF\n3 0\n1 2 3 0 0 1\n4\t5\t6 0\t1 0\n7 8 9 1 0 0\n"));
    REQUIRE(pc.points.size() == 3);
    REQUIRE(pc.normals.size() == 3);
    check_point(pc.points[1], 4, 5, 6);
  }
  SECTION("a single count")
  {
    CHECK(read_unmodified(dir.write("d.off", "OFF\n1\n1 2 3\n")).points.size() == 1);
  }
  SECTION("colour variants: colours ignored, normals when N")
  {
    const Cloud coff = read_unmodified(dir.write("e.off", "COFF\n1 0 0\n1 2 3 255 0 0 255\n"));
    REQUIRE(coff.points.size() == 1);
    CHECK(coff.normals.empty());
    const Cloud ncoff = read_unmodified(dir.write("f.off", "NCOFF\n1 0 0\n1 2 3 0 0 1 255 0 0 255\n"));
    REQUIRE(ncoff.normals.size() == 1);
    check_vector(ncoff.normals[0], 0, 0, 1);
    const Cloud cnoff = read_unmodified(dir.write("g.off", "CNOFF 1 0 0\n1 2 3 0 1 0 0.5 0.5 0.5 1\n"));
    REQUIRE(cnoff.normals.size() == 1);
    check_vector(cnoff.normals[0], 0, 1, 0);
    const Cloud stoff = read_unmodified(dir.write("h.off", "STOFF\n1 0 0\n1 2 3 0.5 0.25\n"));
    CHECK(stoff.normals.empty());
  }
  SECTION("nOFF with dimension 3")
  {
    const Cloud pc = read_unmodified(dir.write("i.off", "nOFF\n3\n2 0 0\n1 2 3\n4 5 6\n"));
    REQUIRE(pc.points.size() == 2);
    const Cloud pc2 = read_unmodified(dir.write("j.off", "nOFF 3 2 0 0\n1 2 3\n4 5 6\n"));
    REQUIRE(pc2.points.size() == 2);
  }
  SECTION("NaN normals are dropped")
  {
    const Cloud pc = read_unmodified(dir.write("k.off", "NOFF\n2 0 0\n1 2 3 0 0 1\n4 5 6 nan nan nan\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
  }
  SECTION("upper-case extension")
  {
    CHECK(read_unmodified(dir.write("UP.OFF", "OFF\n1 0 0\n1 2 3\n")).points.size() == 1);
  }
}

TEST_CASE("off: malformed inputs", "[io][read][off][errors]")
{
  Temp_dir dir;
  require_read_error(dir.write("empty.off", ""), {"empty file"});
  require_read_error(dir.write("blank.off", "\n  \n# only comments\n"), {"empty file"});
  require_read_error(dir.write("nokw.off", "3 0 0\n1 2 3\n"), {"line 1", "OFF"});
  require_read_error(dir.write("headeronly.off", "OFF\n"), {"vertex count"});
  require_read_error(dir.write("countsonly.off", "OFF\n3 0 0\n"),
                     {"header says 3 vertices but the file ends after 0"});
  require_read_error(dir.write("lie.off", "OFF\n10 0 0\n1 2 3\n4 5 6\n7 8 9\n"),
                     {"header says 10 vertices but the file ends after 3"});
  require_read_error(dir.write("absurd.off", "OFF\n1000000000000 0 0\n1 2 3\n"),
                     {"header says 1000000000000 vertices but the file ends after 1"});
  require_read_error(dir.write("overflow.off", "OFF\n99999999999999999999999 0 0\n1 2 3\n"),
                     {"line 2", "vertex count"});
  require_read_error(dir.write("negative.off", "OFF\n-3 0 0\n1 2 3\n"), {"line 2", "'-3'"});
  require_read_error(dir.write("textcount.off", "OFF\nabc 0 0\n1 2 3\n"), {"line 2", "'abc'"});
  require_read_error(dir.write("badfaces.off", "OFF\n1 x 0\n1 2 3\n"), {"line 2", "face count"});
  require_read_error(dir.write("toomany.off", "OFF\n1 2 3 4\n1 2 3\n"), {"line 2", "counts"});
  require_read_error(dir.write("novertex.off", "OFF\n1.5 2.5 3.5\n"), {"line 2", "vertex count"});
  require_read_error(dir.write("zero.off", "OFF\n0 0 0\n"), {"no points"});
  require_read_error(dir.write("nan.off", "OFF\n3 0 0\n1 2 3\nnan 5 6\n7 8 9\n"),
                     {"vertex 2 of 3", "line 4", "not finite"});
  require_read_error(dir.write("inf.off", "OFF\n# c\n3 0 0\n1 2 3\n4 5 6\n\n7 8 inf\n"),
                     {"vertex 3 of 3", "line 7", "not finite"});
  require_read_error(dir.write("text.off", "OFF\n2 0 0\n1 2 3\n4 five 6\n"),
                     {"vertex 2 of 2", "line 4", "'five'"});
  require_read_error(dir.write("short.off", "OFF\n2 0 0\n1 2 3\n4 5\n"),
                     {"vertex 2 of 2", "got 2 numbers"});
  require_read_error(dir.write("nshort.off", "NOFF\n2 0 0\n1 2 3 0 0 1\n4 5 6\n"),
                     {"vertex 2 of 2", "nx ny nz"});
  require_read_error(dir.write("nbad.off", "NOFF\n1 0 0\n1 2 3 0 q 1\n"), {"vertex 1 of 1", "'q'"});
  require_read_error(dir.write("binary.off", std::string("OFF BINARY\n\0\0\0\1\0\0\0\0", 19)),
                     {"binary OFF is not supported"});
  require_read_error(dir.write("4d.off", "4OFF\n1 0 0\n1 2 3 1\n"), {"not supported"});
  require_read_error(dir.write("5d.off", "nOFF\n5\n1 0 0\n1 2 3 4 5\n"), {"dimension 5"});
}

TEST_CASE("off: headerless files, six columns give normals", "[io][read][off]")
{
  Temp_dir dir;
  SECTION("x y z nx ny nz on every line, like fertility_headerless.off")
  {
    const Cloud pc = read_unmodified(dir.write("h6.off",
                                               "0.8 -0.11 -0.009 0.92572 -0.37630 0.03801\n"
                                               "0.79 -0.1119 -0.0046 0 0 1\n"
                                               "\n# a comment\n"
                                               "1 2 3 0 1 0\n"));
    REQUIRE(pc.points.size() == 3);
    REQUIRE(pc.normals.size() == 3);
    check_point(pc.points[0], 0.8, -0.11, -0.009);
    check_point(pc.points[2], 1, 2, 3);
    check_vector(pc.normals[1], 0, 0, 1);
    check_vector(pc.normals[2], 0, 1, 0);
  }
  SECTION("a first line of six integers is a vertex, not a counts line; CRLF")
  {
    const Cloud pc = read_unmodified(dir.write("h6int.off", "0 0 0 0 0 1\r\n-1 2 3 1 0 0\r\n"));
    REQUIRE(pc.points.size() == 2);
    REQUIRE(pc.normals.size() == 2);
    check_point(pc.points[1], -1, 2, 3);
    check_vector(pc.normals[0], 0, 0, 1);
  }
  SECTION("NaN normals drop all normals, points are kept")
  {
    const Cloud pc = read_unmodified(dir.write("h6nan.off", "0.5 0 0 0 0 1\n1 1 1 nan 0 0\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
  }
}

TEST_CASE("off: headerless files, three columns give points only", "[io][read][off]")
{
  Temp_dir dir;
  const Cloud pc = read_unmodified(dir.write("h3.off",
                                             "\xEF\xBB\xBF" "0.5 -1.25 2\n"
                                             "3 4 5\n"
                                             "  6\t7 8.5e-1  # trailing comment\n"));
  REQUIRE(pc.points.size() == 3);
  CHECK(pc.normals.empty());
  check_point(pc.points[0], 0.5, -1.25, 2);
  check_point(pc.points[1], 3, 4, 5);
  check_point(pc.points[2], 6, 7, 0.85);
}

TEST_CASE("off: NOFF header with 3-number vertex lines gives points only", "[io][read][off]")
{
  Temp_dir dir;
  SECTION("'NOFF' and an 'N 0' counts line, like misaligned_scan.off")
  {
    const Cloud pc = read_unmodified(dir.write("m.off", "NOFF\n3 0\n1 2 3\n4 5 6\n\n7 8 9\n"));
    REQUIRE(pc.points.size() == 3);
    CHECK(pc.normals.empty());
    check_point(pc.points[2], 7, 8, 9);
  }
  SECTION("other N keywords, counts on the keyword line")
  {
    const Cloud pc = read_unmodified(dir.write("m2.off", "CNOFF 2 0 0\n1 2 3\n4 5 6\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
    CHECK(read_unmodified(dir.write("m3.off", "NOFF_SK\n1 0 0\n1 2 3\n")).normals.empty());
  }
  SECTION("faces after the vertices are still not read")
  {
    const Cloud pc = read_unmodified(dir.write("m4.off", "NOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    REQUIRE(pc.points.size() == 3);
    CHECK(pc.normals.empty());
  }
  SECTION("the vertex count is honoured")
  {
    require_read_error(dir.write("m5.off", "NOFF\n4 0\n1 2 3\n4 5 6\n7 8 9\n"),
                       {"header says 4 vertices but the file ends after 3"});
    require_read_error(dir.write("m6.off", "NOFF\n1000000000000 0\n1 2 3\n"),
                       {"header says 1000000000000 vertices but the file ends after 1"});
  }
  SECTION("a vertex line of another width is an error naming the vertex and line")
  {
    require_read_error(dir.write("m7.off", "NOFF\n3 0\n1 2 3\n4 5 6 0 0 1\n7 8 9\n"),
                       {"vertex 2 of 3", "line 4", "expected 3 numbers", "line 3", "'NOFF'"});
    require_read_error(dir.write("m8.off", "NOFF\n3 0\n1 2 3\n4 5 6\n7 8 9 1\n"),
                       {"vertex 3 of 3", "line 5", "got 4"});
    require_read_error(dir.write("m9.off", "NOFF\n2 0\n1 2 3\n4 5\n"),
                       {"vertex 2 of 2", "line 4", "got 2 numbers"});
  }
}

TEST_CASE("off: headerless files with inconsistent or bad lines are errors", "[io][read][off][errors]")
{
  Temp_dir dir;
  require_read_error(dir.write("mix63.off", "0.5 0 0 0 0 1\n1 1 1 0 1 0\n2 2 2\n"),
                     {"line 3", "expected 6 numbers", "line 1", "headerless", "got 3"});
  require_read_error(dir.write("mix36.off", "0.5 0 0\n\n# c\n1 1 1 0 1 0\n"),
                     {"line 4", "expected 3 numbers", "line 1", "got 6"});
  // faces cannot follow: without counts they would be taken for vertices
  require_read_error(dir.write("faces.off", "0.5 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                     {"line 4", "got 4"});
  require_read_error(dir.write("four.off", "0.5 0 0 7\n1 0 0 7\n"), {"line 1", "3 or 6 numbers", "got 4"});
  require_read_error(dir.write("seven.off", "0.5 0 0 0 0 1 9\n"), {"line 1", "3 or 6 numbers"});
  require_read_error(dir.write("two.off", "0.5 1.5\n1 2 3\n"), {"line 1", "got 2 numbers"});
  require_read_error(dir.write("short.off", "0.5 0 0\n1 x\n"), {"line 2", "'x'"});
  require_read_error(dir.write("text.off", "0.5 0 0\n1 two 3\n"), {"line 2", "'two'"});
  require_read_error(dir.write("nan.off", "0.5 0 0\n1 nan 3\n"), {"line 2", "not finite"});
  require_read_error(dir.write("nbad.off", "0.5 0 0 0 0 1\n1 2 3 0 q 1\n"), {"line 2", "'q'"});
  // a first line of 1 to 3 non-negative integers is a counts line without its keyword
  require_read_error(dir.write("counts3.off", "15002 0 0\n0.5 0 0\n"), {"line 1", "OFF", "counts line"});
  require_read_error(dir.write("counts2.off", "15002 0\n0.5 0 0\n"), {"line 1", "OFF"});
  require_read_error(dir.write("counts1.off", "# c\n2\n0.5 0 0\n1 1 1\n"), {"line 2", "OFF"});
}

TEST_CASE("read_point_cloud: the shared headerless and misaligned OFF files load", "[io][read][data][shared_data]")
{
  const std::string dir = DF_L1_test::shared_data_folder();
  if(dir.empty())
    return;
  struct Expected
  {
    const char* file;
    std::size_t points;
    bool normals;
  };
  const Expected expected[] = {{"fertility_headerless.off", 4832, true},
                               {"misaligned_scan.off", 15002, false}};
  for(const Expected& e : expected) {
    const std::string path = (fs::path(dir) / e.file).string();
    INFO(path);
    if(DF_L1_test::shared_data_file(e.file).empty())
      continue;
    const Cloud pc = read_unmodified(path);
    CHECK(pc.points.size() == e.points);
    CHECK(pc.normals.size() == (e.normals ? e.points : 0));
  }
}

// ===========================================================================
// PLY
// ===========================================================================

TEST_CASE("ply ascii: happy paths", "[io][read][ply]")
{
  Temp_dir dir;
  SECTION("normals, extra properties, face element after the vertices")
  {
    const Cloud pc = read_unmodified(dir.write("a.ply",
                                               "ply\n"
                                               "format ascii 1.0\n"
                                               "comment made by hand\n"
                                               "obj_info some info\n"
                                               "element vertex 3\n"
                                               "property float nx\n"
                                               "property double z\n"
                                               "property uchar red\n"
                                               "property float y\n"
                                               "property float ny\n"
                                               "property float x\n"
                                               "property float nz\n"
                                               "element face 1\n"
                                               "property list uchar int vertex_indices\n"
                                               "end_header\n"
                                               "0 3 255 2 0 1 1\n"
                                               "1 6 0 5 0 4 0\n"
                                               "0 9 12 8 1 7 0\n"
                                               "3 0 1 2\n"));
    REQUIRE(pc.points.size() == 3);
    REQUIRE(pc.normals.size() == 3);
    check_point(pc.points[0], 1, 2, 3);
    check_point(pc.points[2], 7, 8, 9);
    check_vector(pc.normals[0], 0, 0, 1);
    check_vector(pc.normals[1], 1, 0, 0);
  }
  SECTION("face element before the vertices, vertex list property, CRLF, int types")
  {
    const Cloud pc = read_unmodified(dir.write("b.ply",
                                               "ply\r\n"
                                               "format ascii 1.0\r\n"
                                               "element face 2\r\n"
                                               "property list uchar int vertex_indices\r\n"
                                               "element vertex 2\r\n"
                                               "property int32 x\r\n"
                                               "property list uint8 float32 weights\r\n"
                                               "property short y\r\n"
                                               "property float64 z\r\n"
                                               "element edge 1\r\n"
                                               "property int vertex1\r\n"
                                               "property int vertex2\r\n"
                                               "end_header\r\n"
                                               "3 0 1 2\r\n"
                                               "4 0 1 2 3\r\n"
                                               "1 2 0.5 0.5 -2 3.5\r\n"
                                               "-4 0 5 6.25\r\n"
                                               "0 1\r\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
    check_point(pc.points[0], 1, -2, 3.5);
    check_point(pc.points[1], -4, 5, 6.25);
  }
  SECTION("incomplete normals are ignored")
  {
    const Cloud pc = read_unmodified(dir.write("c.ply",
                                               "ply\nformat ascii 1.0\nelement vertex 1\n"
                                               "property float x\nproperty float y\nproperty float z\n"
                                               "property float nx\nproperty float ny\nend_header\n"
                                               "1 2 3 0 1\n"));
    REQUIRE(pc.points.size() == 1);
    CHECK(pc.normals.empty());
  }
  SECTION("NaN normals are dropped")
  {
    const Cloud pc = read_unmodified(dir.write("d.ply",
                                               "ply\nformat ascii 1.0\nelement vertex 2\n"
                                               "property float x\nproperty float y\nproperty float z\n"
                                               "property float nx\nproperty float ny\nproperty float nz\n"
                                               "end_header\n1 2 3 0 0 1\n4 5 6 nan 0 0\n"));
    REQUIRE(pc.points.size() == 2);
    CHECK(pc.normals.empty());
  }
  SECTION("upper-case extension")
  {
    CHECK(read_unmodified(dir.write("UP.PLY", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                              "property float x\nproperty float y\nproperty float z\n"
                                              "end_header\n1 2 3\n"))
              .points.size() == 1);
  }
}

namespace {

/// A binary PLY file: faces (with lists) and a fixed-size element before the
/// vertices, vertices with mixed types, a list and normals in a scrambled order,
/// and edges after them.
std::string binary_ply(bool big_endian, bool use_double, std::size_t cut_bytes = 0)
{
  const char* real = use_double ? "double" : "float";
  std::string header = std::string("ply\n") +
                       "format " + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                       " 1.0\n"
                       "comment binary test\n"
                       "element camera 1\n"
                       "property float focal\n"
                       "property uchar id\n"
                       "element face 2\n"
                       "property list uchar int vertex_indices\n"
                       "property uchar flags\n"
                       "element vertex 3\n"
                       "property " + real + " z\n"
                       "property uchar red\n"
                       "property " + real + " x\n"
                       "property list int16 uint32 neighbours\n"
                       "property " + real + " nz\n"
                       "property " + real + " y\n"
                       "property " + real + " nx\n"
                       "property int8 label\n"
                       "property " + real + " ny\n"
                       "element edge 1\n"
                       "property list uchar int vertex_indices\n"
                       "end_header\n";
  Binary_writer w(big_endian);
  w.put(35.0f).put(std::uint8_t(7));                                 // camera
  w.put(std::uint8_t(3)).put(std::int32_t(0)).put(std::int32_t(1)).put(std::int32_t(2));
  w.put(std::uint8_t(1));                                            // face 1
  w.put(std::uint8_t(0)).put(std::uint8_t(9));                       // face 2: empty list
  const double coords[3][6] = {{1, 2, 3, 0, 0, 1}, {-4.5, 5.25, -6, 0, 1, 0}, {7, 8, 9e3, 1, 0, 0}};
  for(int i = 0; i < 3; ++i) {
    const double* c = coords[i];
    auto real_put = [&](double v) {
      if(use_double)
        w.put(v);
      else
        w.put(static_cast<float>(v));
    };
    real_put(c[2]);                                                  // z
    w.put(std::uint8_t(200));                                        // red
    real_put(c[0]);                                                  // x
    w.put(std::int16_t(i));                                          // neighbours: i items
    for(int k = 0; k < i; ++k)
      w.put(std::uint32_t(k));
    real_put(c[5]);                                                  // nz
    real_put(c[1]);                                                  // y
    real_put(c[3]);                                                  // nx
    w.put(std::int8_t(-1));                                          // label
    real_put(c[4]);                                                  // ny
  }
  w.put(std::uint8_t(2)).put(std::int32_t(0)).put(std::int32_t(1)); // edge
  std::string data = header + w.bytes();
  data.resize(data.size() - std::min(cut_bytes, w.bytes().size()));
  return data;
}

void check_binary_cloud(const Cloud& pc)
{
  REQUIRE(pc.points.size() == 3);
  REQUIRE(pc.normals.size() == 3);
  check_point(pc.points[0], 1, 2, 3);
  check_point(pc.points[1], -4.5, 5.25, -6);
  check_point(pc.points[2], 7, 8, 9e3);
  check_vector(pc.normals[0], 0, 0, 1);
  check_vector(pc.normals[1], 0, 1, 0);
  check_vector(pc.normals[2], 1, 0, 0);
}

} // namespace

TEST_CASE("ply binary: both byte orders, float and double", "[io][read][ply]")
{
  Temp_dir dir;
  for(bool big : {false, true})
    for(bool dbl : {false, true}) {
      INFO("big endian " << big << ", double " << dbl);
      check_binary_cloud(read_unmodified(dir.write("b.ply", binary_ply(big, dbl))));
    }
}

TEST_CASE("ply binary: every property type and a CRLF header", "[io][read][ply]")
{
  Temp_dir dir;
  for(bool big : {false, true}) {
    Binary_writer w(big);
    w.put(std::int8_t(-3)).put(std::uint8_t(250)).put(std::int16_t(-300));
    w.put(std::uint16_t(60000)).put(std::int32_t(-70000)).put(std::uint32_t(4000000000u));
    w.put(std::int8_t(1)).put(std::uint8_t(2)).put(std::int16_t(3));
    w.put(std::uint16_t(4)).put(std::int32_t(5)).put(std::uint32_t(6));
    const std::string header = std::string("ply\r\nformat ") +
                               (big ? "binary_big_endian" : "binary_little_endian") +
                               " 1.0\r\n"
                               "element vertex 2\r\n"
                               "property char x\r\nproperty uchar y\r\nproperty short z\r\n"
                               "property ushort a\r\nproperty int b\r\nproperty uint c\r\n"
                               "end_header\r\n";
    // The same file read with x y z on the other columns.
    const std::string header2 = std::string("ply\nformat ") +
                                (big ? "binary_big_endian" : "binary_little_endian") +
                                " 1.0\n"
                                "element vertex 2\n"
                                "property int8 a\nproperty uint8 b\nproperty int16 c\n"
                                "property uint16 x\nproperty int32 y\nproperty uint32 z\n"
                                "end_header\n";
    const Cloud pc = read_unmodified(dir.write("t.ply", header + w.bytes()));
    REQUIRE(pc.points.size() == 2);
    check_point(pc.points[0], -3, 250, -300);
    check_point(pc.points[1], 1, 2, 3);
    const Cloud pc2 = read_unmodified(dir.write("t2.ply", header2 + w.bytes()));
    REQUIRE(pc2.points.size() == 2);
    check_point(pc2.points[0], 60000, -70000, 4000000000.0);
    check_point(pc2.points[1], 4, 5, 6);
  }
}

TEST_CASE("ply: malformed inputs", "[io][read][ply][errors]")
{
  Temp_dir dir;
  const std::string xyz_props = "property float x\nproperty float y\nproperty float z\n";
  const std::string ascii_head = "ply\nformat ascii 1.0\nelement vertex 3\n" + xyz_props + "end_header\n";

  require_read_error(dir.write("empty.ply", ""), {"empty file"});
  require_read_error(dir.write("magic.ply", "plyx\nformat ascii 1.0\n"), {"line 1", "not a PLY file"});
  require_read_error(dir.write("headeronly.ply", ascii_head),
                     {"vertex 1 of 3", "header says 3 vertices", "ends after 0"});
  require_read_error(dir.write("truncascii.ply", ascii_head + "1 2 3\n4 5 6\n"),
                     {"vertex 3 of 3", "ends after 2"});
  require_read_error(dir.write("nan.ply", ascii_head + "1 2 3\n4 nan 6\n7 8 9\n"),
                     {"vertex 2 of 3", "line 9", "not finite"});
  require_read_error(dir.write("text.ply", ascii_head + "1 2 3\n4 5 6\n7 8 nine\n"),
                     {"vertex 3 of 3", "line 10", "'nine'"});
  require_read_error(dir.write("fewvalues.ply", ascii_head + "1 2 3\n4 5\n7 8 9\n"),
                     {"vertex 2 of 3", "line 9", "'z'"});
  require_read_error(dir.write("morevalues.ply", ascii_head + "1 2 3 4\n4 5 6\n7 8 9\n"),
                     {"vertex 1 of 3", "line 8", "more values"});
  require_read_error(dir.write("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props),
                     {"end_header"});
  require_read_error(dir.write("noend2.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props +
                                                 "1 2 3\n"),
                     {"line 7", "end_header"});
  require_read_error(dir.write("noformat.ply", "ply\nelement vertex 1\n" + xyz_props + "end_header\n1 2 3\n"),
                     {"format"});
  require_read_error(dir.write("badformat.ply", "ply\nformat binary_middle_endian 1.0\nelement vertex 1\n" +
                                                    xyz_props + "end_header\n1 2 3\n"),
                     {"line 2", "binary_middle_endian"});
  require_read_error(dir.write("emptyformat.ply", "ply\nformat\nelement vertex 1\n" + xyz_props +
                                                      "end_header\n1 2 3\n"),
                     {"line 2", "format"});
  require_read_error(dir.write("badtype.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                              "property float16 x\nproperty float y\nproperty float z\n"
                                              "end_header\n1 2 3\n"),
                     {"line 4", "unknown PLY type", "'float16'"});
  require_read_error(dir.write("badlisttype.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props +
                                                      "property list uchar bogus l\nend_header\n1 2 3 0\n"),
                     {"line 7", "'bogus'"});
  require_read_error(dir.write("nox.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                          "property float y\nproperty float z\nend_header\n1 2\n"),
                     {"no 'x' property"});
  require_read_error(dir.write("listx.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                            "property list uchar float x\nproperty float y\n"
                                            "property float z\nend_header\n1 1 2 3\n"),
                     {"'x'", "list"});
  require_read_error(dir.write("novertex.ply", "ply\nformat ascii 1.0\nelement point 1\n" + xyz_props +
                                                   "end_header\n1 2 3\n"),
                     {"no 'vertex' element"});
  require_read_error(dir.write("zero.ply", "ply\nformat ascii 1.0\nelement vertex 0\n" + xyz_props +
                                               "end_header\n"),
                     {"no points"});
  require_read_error(dir.write("propfirst.ply", "ply\nformat ascii 1.0\nproperty float x\n"
                                                "element vertex 1\nend_header\n"),
                     {"line 3", "before any element"});
  require_read_error(dir.write("badcount.ply", "ply\nformat ascii 1.0\nelement vertex -1\n" + xyz_props +
                                                   "end_header\n"),
                     {"line 3", "'-1'"});
  require_read_error(dir.write("absurdascii.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000000\n" +
                                                      xyz_props + "end_header\n1 2 3\n"),
                     {"vertex 2 of 1000000000000", "ends after 1"});
  require_read_error(dir.write("asciifaces.ply", "ply\nformat ascii 1.0\nelement face 5\n"
                                                 "property list uchar int vertex_indices\n"
                                                 "element vertex 1\n" + xyz_props +
                                                 "end_header\n3 0 1 2\n"),
                     {"'face' elements", "ends after 1"});
  require_read_error(dir.write("asciilist.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props +
                                                    "property list uchar int l\nend_header\n1 2 3 4 1 2\n"),
                     {"vertex 1 of 1", "list 'l'"});
}

TEST_CASE("ply binary: malformed inputs", "[io][read][ply][errors]")
{
  Temp_dir dir;
  // With floats, vertex i (from 0) takes 6 * 4 + 1 + 2 + 1 + 4 * i bytes
  // (28, 32, 36) and the trailing edge 9 bytes.
  SECTION("truncated in the middle of vertex 3")
  {
    for(bool big : {false, true})
      require_read_error(dir.write("trunc.ply", binary_ply(big, false, 9 + 20)),
                         {"vertex 3 of 3", "ends after 2"});
  }
  SECTION("truncated before the vertices")
  {
    require_read_error(dir.write("trunc0.ply", binary_ply(false, false, 9 + 28 + 32 + 36)),
                       {"vertex 1 of 3", "ends after 0"});
  }
  SECTION("truncated inside the faces before the vertices")
  {
    const std::string full = binary_ply(false, false);
    const std::size_t header_size = full.find("end_header\n") + 11;
    require_read_error(dir.write("truncface.ply", full.substr(0, header_size + 5 + 10)),
                       {"'face' elements", "ends after 0"});
    require_read_error(dir.write("trunccam.ply", full.substr(0, header_size + 3)),
                       {"'camera' elements", "ends after 0"});
  }
  SECTION("truncated in the edges after the vertices is fine")
  {
    check_binary_cloud(read_unmodified(dir.write("trunc_edge.ply", binary_ply(false, true, 4))));
  }
  SECTION("absurd vertex count")
  {
    Binary_writer w(false);
    w.put(1.0f).put(2.0f).put(3.0f);
    require_read_error(dir.write("absurd.ply", "ply\nformat binary_little_endian 1.0\n"
                                               "element vertex 1000000000000\n"
                                               "property float x\nproperty float y\nproperty float z\n"
                                               "end_header\n" + w.bytes()),
                       {"vertex 2 of 1000000000000", "ends after 1"});
    require_read_error(dir.write("absurdface.ply", "ply\nformat binary_little_endian 1.0\n"
                                                   "element face 999999999999999999\n"
                                                   "property list uchar int vertex_indices\n"
                                                   "element vertex 1\n"
                                                   "property float x\nproperty float y\nproperty float z\n"
                                                   "end_header\n" + w.bytes()),
                       {"999999999999999999 'face' elements"});
    require_read_error(dir.write("absurdfixed.ply", "ply\nformat binary_little_endian 1.0\n"
                                                    "element camera 18446744073709551615\n"
                                                    "property double a\n"
                                                    "element vertex 1\n"
                                                    "property float x\nproperty float y\nproperty float z\n"
                                                    "end_header\n" + w.bytes()),
                       {"'camera' elements", "ends after 1"});
  }
  SECTION("non-finite coordinate names the vertex")
  {
    Binary_writer w(true);
    w.put(1.0).put(2.0).put(3.0).put(4.0).put(std::numeric_limits<double>::infinity()).put(6.0);
    require_read_error(dir.write("inf.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 2\n"
                                            "property double x\nproperty double y\nproperty double z\n"
                                            "end_header\n" + w.bytes()),
                       {"vertex 2 of 2", "not finite"});
  }
  SECTION("negative list count")
  {
    Binary_writer w(false);
    w.put(1.0f).put(2.0f).put(3.0f).put(std::int8_t(-2));
    require_read_error(dir.write("neglist.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                                                "property float x\nproperty float y\nproperty float z\n"
                                                "property list char int l\n"
                                                "end_header\n" + w.bytes()),
                       {"vertex 1 of 1", "list 'l'"});
  }
  SECTION("huge list count")
  {
    Binary_writer w(false);
    w.put(std::uint32_t(4000000000u)).put(1.0f).put(2.0f).put(3.0f);
    require_read_error(dir.write("hugelist.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                                                 "property list uint double l\n"
                                                 "property float x\nproperty float y\nproperty float z\n"
                                                 "end_header\n" + w.bytes()),
                       {"vertex 1 of 1", "ends after 0"});
  }
}

// ===========================================================================
// Files and dispatch
// ===========================================================================

TEST_CASE("read_point_cloud: bad paths and extensions", "[io][read][errors]")
{
  Temp_dir dir;
  require_read_error(dir.write("a.obj", "v 1 2 3\n"), {"unsupported file extension", "'.obj'"});
  require_read_error(dir.write("noextension", "1 2 3\n"), {"unsupported file extension"});
  require_read_error(dir.path("missing.xyz"), {"cannot open file"});
  require_read_error(dir.path("missing.ply"), {"cannot open file"});
  require_read_error(dir.path("no/such/dir/x.off"), {"cannot open file"});
  fs::create_directory(dir.path("folder.xyz"));
  require_read_error(dir.path("folder.xyz"), {"cannot open file", "directory"});
  CHECK(fs::is_directory(dir.path("folder.xyz")));
  // A PLY file with the wrong extension is parsed as what the extension says.
  require_read_error(dir.write("ply_as.off", "ply\nformat ascii 1.0\n"), {"line 1", "OFF"});
}

TEST_CASE("read_point_cloud: a large OFF loads whole", "[io][read][off]")
{
  Temp_dir dir;
  std::string content = "OFF\n110000 0 0\n";
  content.reserve(110000 * 30);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  char line[96];
  for(int i = 0; i < 110000; ++i) {
    std::snprintf(line, sizeof line, "%.6f %.6f %.6f\n", u(rng), u(rng), u(rng));
    content += line;
  }
  const std::string path = dir.write("big.off", content);
  const Cloud pc = CGAL::DF_L1::read_point_cloud<K>(path);
  // Speed is measured in benchmark/, never asserted here.
  REQUIRE(pc.points.size() == 110000);
  CHECK(pc.points.back() != pc.points.front());
}

TEST_CASE("read_point_cloud: the shared real data sets load", "[io][read][data][shared_data]")
{
  const std::string dir = DF_L1_test::shared_data_folder();
  if(dir.empty())
    return;
  struct Expected
  {
    const char* file;
    std::size_t points;
    bool normals;
  };
  const Expected expected[] = {{"camel_scan.off", 17036, true},
                               {"fertility_partial_scan.off", 9471, true},
                               {"woman_scan.off", 11798, true},
                               {"tree_scan.off", 110423, false},
                               {"dinopet_noisy.xyz", 3916, true},
                               {"bunny_noisy.ply", 6964, false}};
  for(const Expected& e : expected) {
    const std::string path = (fs::path(dir) / e.file).string();
    INFO(path);
    if(DF_L1_test::shared_data_file(e.file).empty())
      continue;
    const Cloud pc = read_unmodified(path);
    CHECK(pc.points.size() == e.points);
    CHECK(pc.normals.size() == (e.normals ? e.points : 0));
  }
}

TEST_CASE("read_point_cloud: a file changed while it is read is an error; a removed one is not", "[io][read][faults]")
{
  namespace reader = CGAL::DF_L1::internal::point_cloud_reader;
  const Temp_dir dir;
  std::string content;
  for(int i = 0; i < 1000; ++i)
    content += std::to_string(i) + " 1 2\n";
  const auto changed = [](const reader::Input_buffer& data, const std::string& path) {
    try {
      data.check_unchanged(path);
    } catch(const CGAL::DF_L1::Read_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // What happens between the mapping and the end of the parsing.
  SECTION("grown")
  {
    const std::string path = dir.write("grown.xyz", content);
    const reader::Input_buffer data = reader::read_file(path);
    std::ofstream(path, std::ios::app) << "5 5 5\n";
    CHECK_THAT(changed(data, path), Contains(path + ": the file changed while it was being read") &&
                                        Contains(std::to_string(content.size()) + " bytes"));
  }
  SECTION("rewritten in place, same size")
  {
    const std::string path = dir.write("rewritten.xyz", content);
    const reader::Input_buffer data = reader::read_file(path);
    {
      std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(0);
      f << '9';
    }
    // a later modification time, whatever the clock's granularity
    const auto later = fs::last_write_time(path) + std::chrono::seconds(2);
    fs::last_write_time(path, later);
    CHECK_THAT(changed(data, path), Contains("the file changed while it was being read (it was modified"));
  }
  SECTION("removed or replaced: the mapping still reads the file opened")
  {
    const std::string path = dir.write("removed.xyz", content);
    const reader::Input_buffer data = reader::read_file(path);
    fs::remove(path);
    CHECK(changed(data, path).empty());
    const std::string other = dir.write("other.xyz", "1 2 3\n");
    const std::string replaced = dir.write("replaced.xyz", content);
    const reader::Input_buffer data2 = reader::read_file(replaced);
    fs::rename(other, replaced);
    CHECK(changed(data2, replaced).empty());
    CHECK(data2.view() == content);
  }
  SECTION("unchanged")
  {
    const std::string path = dir.write("same.xyz", content);
    CHECK(CGAL::DF_L1::read_point_cloud<K>(path).points.size() == 1000);
  }
}
