// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The readers under hostile input (issue 21): headers that announce absurd
// counts, list lengths and element sizes, giant lines, files of NUL bytes or of
// whitespace only (all generated here), the inputs the fuzzers once broke
// (test/io/fuzz_regressions/, replayed through the parsers), the exactness of
// the fast number path, and the equality of the file and stream readers.

#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/stat.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cloud = CGAL::DF_L1::Point_cloud<K>;
namespace fs = std::filesystem;
namespace reader = CGAL::DF_L1::internal::point_cloud_reader;
using Catch::Matchers::Contains;

class Temp_dir
{
public:
  Temp_dir()
  {
    static std::atomic<unsigned> counter{0};
    std::random_device rd;
    for(int attempt = 0; attempt < 100; ++attempt) {
      path_ = fs::temp_directory_path() /
              ("df_l1_hostile_" + std::to_string(rd()) + "_" + std::to_string(counter++));
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

  std::string path(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const
  {
    const fs::path p = path_ / name;
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    REQUIRE(out.good());
    return p.string();
  }

private:
  fs::path path_;
};

/// Peak resident memory of the process so far, in MB.
double peak_rss_mb()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// Requires a one-line Read_error naming the file and holding every part, and
/// the same error from the stream reader of the format.
void require_error(const std::string& path, std::initializer_list<std::string> parts)
{
  std::string msg = "<no Read_error thrown>";
  try {
    CGAL::DF_L1::read_point_cloud<K>(path);
  } catch(const CGAL::DF_L1::Read_error& e) {
    msg = e.what();
  }
  INFO("message: " << msg.substr(0, 300));
  CHECK_THAT(msg, Contains(path));
  CHECK(msg.find('\n') == std::string::npos);
  CHECK(msg.size() < 400);
  for(const std::string& part : parts)
    CHECK_THAT(msg, Contains(part));
}

std::string le_u32(std::uint32_t v)
{
  std::string s(4, '\0');
  for(int i = 0; i < 4; ++i)
    s[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
  return s;
}

std::string le_f32(float f)
{
  std::uint32_t v;
  std::memcpy(&v, &f, 4);
  return le_u32(v);
}

const std::string xyz_props = "property float x\nproperty float y\nproperty float z\n";

} // namespace

TEST_CASE("hostile: headers announcing absurd counts fail fast in bounded memory", "[io][read][hostile]")
{
  Temp_dir dir;
  const double rss_before = peak_rss_mb();
  const std::string point = le_f32(1) + le_f32(2) + le_f32(3);

  SECTION("PLY claiming 10^12 vertices in a small file, ASCII and binary")
  {
    std::string ascii = "ply\nformat ascii 1.0\nelement vertex 1000000000000\n" + xyz_props + "end_header\n";
    for(int i = 0; i < 40; ++i)
      ascii += "1 2 3\n";
    require_error(dir.write("many.ply", ascii), {"vertex 41 of 1000000000000", "ends after 40"});
    std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n" + xyz_props + "end_header\n";
    for(int i = 0; i < 40; ++i)
      binary += point;
    require_error(dir.write("manyb.ply", binary), {"vertex 41 of 1000000000000", "ends after 40"});
  }
  SECTION("PLY vertex count beyond 64 bits")
  {
    require_error(dir.write("over.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\n" +
                                            xyz_props + "end_header\n1 2 3\n"),
                  {"line 3", "invalid element count"});
    require_error(dir.write("neg.ply", "ply\nformat ascii 1.0\nelement vertex -5\n" + xyz_props +
                                           "end_header\n1 2 3\n"),
                  {"line 3", "invalid element count '-5'"});
  }
  SECTION("element counts whose size overflows 64 bits when multiplied by the record size")
  {
    // 2^61 records of 3 doubles (24 bytes): 24 * 2^61 wraps around to 2^63 + ... in 64 bits.
    require_error(dir.write("wrap.ply", "ply\nformat binary_little_endian 1.0\n"
                                        "element camera 2305843009213693952\n"
                                        "property double a\nproperty double b\nproperty double c\n"
                                        "element vertex 1\n" + xyz_props + "end_header\n" + point),
                  {"'camera' elements", "ends after 0"});
    // 2^62 + 1 vertices of 4 bytes: the product is 4 (mod 2^64).
    require_error(dir.write("wrapv.ply", "ply\nformat binary_little_endian 1.0\n"
                                         "element vertex 4611686018427387905\n"
                                         "property float x\nproperty float y\nproperty float z\n"
                                         "property float w\nend_header\n" + point + le_f32(0)),
                  {"vertex 2 of 4611686018427387905", "ends after 1"});
  }
  SECTION("ASCII list counts: 2^31, negative, beyond 64 bits")
  {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz_props +
                             "property list uchar int l\nend_header\n";
    require_error(dir.write("l31.ply", head + "1 2 3 2147483648 1 2\n"),
                  {"vertex 1 of 1 (line 9)", "the line ends inside list 'l'"});
    require_error(dir.write("lneg.ply", head + "1 2 3 -1 5\n"),
                  {"vertex 1 of 1 (line 9)", "invalid count '-1' for list 'l'"});
    require_error(dir.write("lbig.ply", head + "1 2 3 184467440737095516160 5\n"),
                  {"vertex 1 of 1 (line 9)", "invalid count"});
    // The same before the vertices, in a face element.
    require_error(dir.write("fneg.ply", "ply\nformat ascii 1.0\nelement face 1000000000\n"
                                        "property list uchar int v\nelement vertex 1\n" +
                                            xyz_props + "end_header\n3 0 0 0\n"),
                  {"1000000000 'face' elements", "ends after 1"});
  }
  SECTION("binary list counts: 2^31, negative, NaN, fractional, huge float")
  {
    const std::string head = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n" + xyz_props;
    require_error(dir.write("b31.ply", head + "property list uint int l\nend_header\n" + point +
                                           le_u32(2147483648u) + le_u32(7)),
                  {"vertex 1 of 1", "ends after 0"});
    require_error(dir.write("bneg.ply", head + "property list int int l\nend_header\n" + point +
                                            le_u32(0xffffffffu)),
                  {"vertex 1 of 1", "invalid count -1 for list 'l'"});
    require_error(dir.write("bnan.ply", head + "property list float int l\nend_header\n" + point +
                                            le_f32(std::nanf(""))),
                  {"vertex 1 of 1", "invalid count nan for list 'l'"});
    require_error(dir.write("bfrac.ply", head + "property list float int l\nend_header\n" + point +
                                             le_f32(1.5f)),
                  {"vertex 1 of 1", "invalid count 1.5 for list 'l'"});
    require_error(dir.write("bhuge.ply", head + "property list float int l\nend_header\n" + point +
                                             le_f32(3e38f)),
                  {"vertex 1 of 1", "invalid count"});
  }
  SECTION("OFF claiming 10^15 vertices, or counts beyond 64 bits")
  {
    require_error(dir.write("many.off", "OFF\n1000000000000000 0 0\n1 2 3\n4 5 6\n"),
                  {"header says 1000000000000000 vertices but the file ends after 2"});
    require_error(dir.write("over.off", "OFF\n99999999999999999999999 0 0\n1 2 3\n"),
                  {"line 2", "expected the vertex count"});
    require_error(dir.write("neg.off", "OFF\n-3 0 0\n1 2 3\n"), {"line 2", "expected the vertex count"});
  }
  SECTION("a pts count line of 10^15 is not trusted")
  {
    const Cloud pc = CGAL::DF_L1::read_point_cloud<K>(dir.write("count.pts", "1000000000000000\n1 2 3\n"));
    CHECK(pc.points.size() == 1);
  }
  // Every case above holds a few hundred bytes: none may cost more than a few MB.
  CHECK(peak_rss_mb() - rss_before < 64.0);
}

TEST_CASE("hostile: NUL bytes, whitespace only and giant lines", "[io][read][hostile]")
{
  Temp_dir dir;
  SECTION("a file of NUL bytes")
  {
    const std::string nul(1 << 20, '\0');
    require_error(dir.write("nul.xyz", nul), {"line 1", "expected a number, got '\\x00\\x00"});
    require_error(dir.write("nul.ply", nul), {"line 1", "not a PLY file"});
    require_error(dir.write("nul.off", nul), {"line 1", "expected an OFF header keyword"});
  }
  SECTION("a file of whitespace only")
  {
    std::string blank;
    for(int i = 0; i < 100000; ++i)
      blank += " \t \r\n\n\f\v";
    require_error(dir.write("blank.xyz", blank), {"no points"});
    require_error(dir.write("blank.ply", blank), {"not a PLY file"});
    require_error(dir.write("blank.off", blank), {"empty file"});
  }
  SECTION("a 100 MB line without a newline")
  {
    // Written by chunks, so that the test itself never holds 100 MB.
    const auto write_giant = [&dir](const std::string& name, const std::string& head) {
      const std::string path = dir.write(name, head);
      std::ofstream out(path, std::ios::binary | std::ios::app);
      const std::string chunk(1u << 20, '7');
      for(int i = 0; i < 100; ++i)
        out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
      out.close();
      REQUIRE(out.good());
      return path;
    };
    const std::string xyz = write_giant("giant.xyz", "");
    const std::string xyz3 = write_giant("giant3.xyz", "1 2 ");
    const std::string off = write_giant("giant.off", "OFF\n1 0 0\n");
    const std::string ply = write_giant("giant.ply", "ply\nformat ascii 1.0\ncomment ");
    const double rss_before = peak_rss_mb();
    require_error(xyz, {"line 1", "number out of the range of a double: '7777"});
    require_error(xyz3, {"line 1", "number out of the range of a double: '7777"});
    require_error(off, {"vertex 1 of 1 (line 3)", "number out of the range"});
    require_error(ply, {"no 'end_header' line"});
    // The file is mapped, never copied: at most its 100 MB are resident at once.
    CHECK(peak_rss_mb() - rss_before < 150.0);
  }
}

TEST_CASE("hostile: the inputs the fuzzers found are refused or read cleanly", "[io][read][hostile][fuzz]")
{
  const fs::path root = fs::path(DF_L1_SOURCE_DIR) / "test" / "io" / "fuzz_regressions";
  std::size_t replayed = 0;
  for(const char* format : {"xyz", "ply", "off"}) {
    const fs::path folder = root / format;
    if(!fs::is_directory(folder))
      continue;
    for(const fs::directory_entry& entry : fs::directory_iterator(folder)) {
      if(!entry.is_regular_file() || entry.path().extension() == ".md")
        continue;
      INFO(entry.path().string());
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      Cloud pc;
      bool refused = false;
      try {
        if(std::string(format) == "xyz")
          reader::parse_xyz(data, "regression", pc);
        else if(std::string(format) == "ply")
          reader::parse_ply(data, "regression", pc);
        else
          reader::parse_off(data, "regression", pc);
      } catch(const CGAL::DF_L1::Read_error& e) {
        refused = true;
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
      }
      if(!refused) {
        REQUIRE(!pc.points.empty());
        CHECK((pc.normals.empty() || pc.normals.size() == pc.points.size()));
        for(const auto& p : pc.points)
          CHECK((std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())));
      }
      ++replayed;
    }
  }
  SUCCEED("replayed " << replayed << " fuzzer findings");
}

TEST_CASE("hostile: the fast number path gives the values of the general path, bit for bit", "[io][read][numbers]")
{
  // Edge tokens: subnormals, the extremes, halfway cases, long digit strings,
  // underflow and overflow, signs and forms the fast path leaves to the general one.
  std::vector<std::string> tokens = {
      "0", "-0", "0.0", "-0.0", ".5", "5.", "-.5", "+1", "+.5", "1e5", "1E5", "1e+5", "1e-5",
      "4.9406564584124654e-324", "5e-324", "3e-324", "2.4703282292062328e-324", "2e-324",
      "2.2250738585072011e-308", "2.2250738585072014e-308", "1.7976931348623157e308",
      "1.7976931348623158e308", "0.1", "0.30000000000000004", "9007199254740993",
      "9007199254740992.5", "2.00000000000000011102230246251565404236316680908203125",
      "1.00000000000000011102230246251565404236316680908203125", "1e23", "8.5e-323",
      "123456789012345678901234567890", "0.000000000000000000000000000001234567890123456789",
      "0e999999999", "1e-400", "-1e-400", "7.2057594037927933e16", "1.5e-45", "3.4028234663852886e38",
      "00000000000000000000000001.5", "1.0000000000000000000000000000000000000000000000001",
      "-2.5E-3", "6.02214076e23", "1.602176634e-19"};
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-320, 308);
  std::uniform_int_distribution<int> digits(1, 25);
  std::uniform_int_distribution<std::uint64_t> bits;
  char text[64];
  for(int i = 0; i < 30000; ++i) {
    switch(i % 4) {
    case 0: // shortest round trip of an arbitrary double
    {
      double d;
      const std::uint64_t b = bits(rng);
      std::memcpy(&d, &b, 8);
      if(!std::isfinite(d))
        d = 1.0;
      std::snprintf(text, sizeof text, "%.17g", d);
      break;
    }
    case 1: // a point of a scan
      std::snprintf(text, sizeof text, "%.*f", digits(rng) % 10, unit(rng) * 1000.0);
      break;
    case 2: // many digits, any exponent
      std::snprintf(text, sizeof text, "%.*e", digits(rng), unit(rng) * std::pow(10.0, exponent(rng) % 300));
      break;
    default: // digits beyond what a double holds
      std::snprintf(text, sizeof text, "%.25f", unit(rng));
    }
    tokens.push_back(text);
  }
  // Three tokens per line, after a first line that keeps the fast path on.
  std::string data = "0 0 0\n";
  std::size_t lines = 0;
  for(std::size_t i = 0; i + 2 < tokens.size(); i += 3, ++lines)
    data += tokens[i] + (i % 2 ? "\t" : " ") + tokens[i + 1] + " " + tokens[i + 2] + "\n";
  Cloud pc;
  reader::parse_xyz(data, "tokens", pc);
  REQUIRE(pc.points.size() == lines + 1);
  std::size_t compared_with_strtod = 0;
  for(std::size_t l = 0; l < lines; ++l) {
    const double got[3] = {pc.points[l + 1].x(), pc.points[l + 1].y(), pc.points[l + 1].z()};
    for(std::size_t j = 0; j < 3; ++j) {
      const std::string& tok = tokens[3 * l + j];
      INFO("token " << tok);
      double general = 0;
      REQUIRE(reader::parse_double(tok, general) == reader::Number_status::ok);
      CHECK(std::memcmp(&general, &got[j], 8) == 0);
      errno = 0;
      const double c = std::strtod(tok.c_str(), nullptr);
      if(errno == 0) {
        CHECK(std::memcmp(&c, &got[j], 8) == 0);
        ++compared_with_strtod;
      }
    }
  }
  CHECK(compared_with_strtod > 3 * lines * 9 / 10);
  // The OFF reader takes the same path.
  Cloud off;
  reader::parse_off("OFF\n" + std::to_string(lines + 1) + " 0 0\n" + data, "tokens.off", off);
  REQUIRE(off.points.size() == pc.points.size());
  for(std::size_t i = 0; i < off.points.size(); ++i)
    CHECK(off.points[i] == pc.points[i]);
}

TEST_CASE("hostile: the file and stream readers agree", "[io][read]")
{
  // 20 MB: beyond the 16 MB where the point count is estimated, and past two
  // drops of the mapped pages (every 8 MB).
  Temp_dir dir;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  std::string xyz;
  char line[96];
  for(int i = 0; i < 500000; ++i) {
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g 0 0 1\n", u(rng), u(rng), u(rng));
    xyz += line;
  }
  const std::string path = dir.write("agree.xyz", xyz);
  const Cloud from_file = CGAL::DF_L1::read_point_cloud<K>(path);
  std::ifstream in(path, std::ios::binary);
  const Cloud from_stream = CGAL::DF_L1::read_xyz_point_cloud<K>(in, path);
  std::istringstream text(xyz); // not a file
  const Cloud from_string = CGAL::DF_L1::read_xyz_point_cloud<K>(text, "s");
  REQUIRE(xyz.size() > (std::size_t(18) << 20));
  REQUIRE(from_file.points.size() == 500000);
  CHECK(from_file.points == from_stream.points);
  CHECK(from_file.points == from_string.points);
  CHECK(from_file.normals.size() == 500000);
  CHECK(from_file.normals == from_stream.normals);
}

TEST_CASE("hostile: a FIFO is read as a stream, an empty file gives no points", "[io][read]")
{
  Temp_dir dir;
  const std::string fifo = dir.path("pipe.xyz");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::thread writer([&fifo] {
    std::ofstream out(fifo, std::ios::binary);
    for(int i = 0; i < 20000; ++i)
      out << i << " 0.5 -1\n";
  });
  const Cloud pc = CGAL::DF_L1::read_point_cloud<K>(fifo);
  writer.join();
  REQUIRE(pc.points.size() == 20000);
  CHECK(pc.points.back().x() == 19999);
  require_error(dir.write("empty.xyz", ""), {"no points"});
  require_error(dir.write("empty.ply", ""), {"empty file"});
}

TEST_CASE("hostile: line ends are found the same across the search windows", "[io][read]")
{
  // Long stretches without '\r' (beyond the 64 KiB search window), lone CRs, CR LF
  // and LF, split by Line_reader and by the plain rule.
  std::mt19937 rng(11);
  std::string data;
  while(data.size() < 600000) {
    const int kind = static_cast<int>(rng() % 6);
    if(kind == 0)
      data += std::string(1000 + rng() % 150000, 'a') + "\n";
    else if(kind == 1)
      data += "\r";
    else if(kind == 2)
      data += "\r\n";
    else if(kind == 3)
      data += "xy\r\r\n";
    else
      data += std::string(rng() % 70, 'b') + (rng() % 2 ? "\n" : "\r");
  }
  data += "tail";
  std::vector<std::string> expected;
  {
    std::string current;
    for(std::size_t i = 0; i < data.size(); ++i) {
      const char c = data[i];
      if(c == '\n' || c == '\r') {
        if(c == '\r' && i + 1 < data.size() && data[i + 1] == '\n')
          ++i;
        expected.push_back(current);
        current.clear();
      } else {
        current += c;
      }
    }
    if(!current.empty())
      expected.push_back(current);
  }
  reader::Line_reader lines(data, 0, 1, true);
  std::vector<std::string> got;
  for(std::string_view line; lines.next(line);)
    got.emplace_back(line);
  REQUIRE(got.size() == expected.size());
  CHECK(got == expected);
}
