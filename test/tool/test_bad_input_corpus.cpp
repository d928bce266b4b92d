// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The corpus of malformed and degenerate inputs of issue 21, run through the tool:
// every case documents its outcome (README.md, "Errors", lists them). A failing
// case must exit with 1 (bad input) or 2 (bad usage), print one line naming the
// file (and the line or vertex where it applies), and write no output; a case
// that succeeds must write its output, with no "nan" in it or on stderr. The files
// are generated here, in a temporary folder; the clouds are small and the voxel
// grid coarse (--voxel-resolution 16), so the whole corpus runs in a few seconds.

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

class Corpus_dir
{
public:
  Corpus_dir()
  {
    dir_ = fs::temp_directory_path() / ("df_l1_bad_input_corpus_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Corpus_dir()
  {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  Corpus_dir(const Corpus_dir&) = delete;
  Corpus_dir& operator=(const Corpus_dir&) = delete;
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

private:
  fs::path dir_;
};

std::string read_all(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string lower(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

struct Tool_run
{
  int status = -1;
  std::string err;
};

Tool_run run_tool(const std::string& arguments, const Corpus_dir& dir)
{
  const std::string err_file = dir.path("stderr.txt");
  const std::string command = std::string("\"") + DF_L1_TOOL_PATH + "\" " + arguments +
                              " --quiet > /dev/null 2> \"" + err_file + "\"";
  const int raw = std::system(command.c_str());
  Tool_run r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.err = read_all(err_file);
  return r;
}

// --- Content builders -------------------------------------------------------

/// n points on a sphere of radius `scale` centred at (offset, offset, offset),
/// "x y z" (or "x y z nx ny nz") lines ended by `eol`.
std::string sphere(int n, double scale = 1.0, double offset = 0.0, const std::string& eol = "\n",
                   bool normals = false)
{
  std::ostringstream s;
  s.precision(17);
  const double golden = 3.14159265358979 * (3 - std::sqrt(5.0));
  for(int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z);
    const double x = r * std::cos(golden * i), y = r * std::sin(golden * i);
    s << offset + scale * x << ' ' << offset + scale * y << ' ' << offset + scale * z;
    if(normals)
      s << ' ' << x << ' ' << y << ' ' << z;
    s << eol;
  }
  return s.str();
}

const int n_sphere = 300;

std::string ply_ascii_header(int n, const std::string& extra_props = "")
{
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(n) +
         "\nproperty float x\nproperty float y\nproperty float z\n" + extra_props + "end_header\n";
}

/// The sphere as binary PLY: `big` endian or little, doubles or floats, with an
/// optional face element (one triangle) stored before the vertices.
std::string binary_ply_sphere(bool big, bool doubles, bool face_first, int n = n_sphere)
{
  const std::string type = doubles ? "double" : "float";
  std::string s = std::string("ply\nformat binary_") + (big ? "big" : "little") + "_endian 1.0\n";
  if(face_first)
    s += "element face 1\nproperty list uchar int vertex_indices\n";
  s += "element vertex " + std::to_string(n) + "\nproperty " + type + " x\nproperty " + type +
       " y\nproperty " + type + " z\nend_header\n";
  const auto put = [&s, big](const void* p, std::size_t size) {
    char b[8];
    std::memcpy(b, p, size);
    const std::uint16_t one = 1;
    char first;
    std::memcpy(&first, &one, 1);
    if((first == 1) == big)
      std::reverse(b, b + size);
    s.append(b, size);
  };
  if(face_first) {
    s += '\x03';
    for(std::int32_t i = 0; i < 3; ++i)
      put(&i, 4);
  }
  std::istringstream text(sphere(n));
  double v;
  while(text >> v) {
    if(doubles) {
      put(&v, 8);
    } else {
      const float f = static_cast<float>(v);
      put(&f, 4);
    }
  }
  return s;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to)
{
  for(std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
    s.replace(p, from.size(), to);
  return s;
}

std::string points_text(int n, double (*f)(int, int))
{
  std::ostringstream s;
  for(int i = 0; i < n; ++i)
    s << f(i, 0) << ' ' << f(i, 1) << ' ' << f(i, 2) << '\n';
  return s.str();
}

// --- The corpus ---------------------------------------------------------------

enum class Kind { file, missing, directory };

struct Case
{
  std::string name;     // file name of the input
  std::string content;  // its bytes
  int status;           // 0 result, 1 bad input, 2 bad usage
  std::vector<std::string> expected; // fragments of the message (status 1 and 2)
  std::string output = "out.obj";
  std::string extra;    // more arguments
  Kind kind = Kind::file;
};

std::vector<Case> corpus()
{
  const std::string sph = sphere(n_sphere);
  const std::string bom = "\xEF\xBB\xBF";
  std::string nan_normals = sphere(n_sphere, 1.0, 0.0, "\n", true);
  nan_normals += "0 0 2 nan 0 1\n";
  std::string mixed = sphere(n_sphere, 1.0, 0.0, "\n", true) + sph;
  std::string counted = std::to_string(n_sphere) + "\n" + sph;
  std::string commented = "# scan\n\n" + replace_all(sph, "\n", "\t# c\n");
  const std::string three = "0 0 0\n1 0 0\n0 1 0\n";
  std::string all_equal;
  for(int i = 0; i < 50; ++i)
    all_equal += "1.5 -2 3\n";

  std::vector<Case> c = {
      // XYZ / PTS / TXT, malformed
      {"empty.xyz", "", 1, {"no points"}},
      {"comments_only.xyz", "# a\n# b\n", 1, {"no points"}},
      {"whitespace_only.xyz", std::string(1000, ' ') + "\n\t\n\r\n", 1, {"no points"}},
      {"bad_token.xyz", "0 0 0\n1 abc 2\n", 1, {"line 2", "expected a number, got 'abc'"}},
      {"comma_decimal.xyz", "0,5 1 2\n", 1, {"line 1", "the decimal mark must be '.'"}},
      {"nan.xyz", "0 0 0\n1 nan 2\n", 1, {"line 2", "coordinate is not finite: 'nan'"}},
      {"inf.xyz", "0 0 0\n1 2 -inf\n", 1, {"line 2", "coordinate is not finite: '-inf'"}},
      {"overflow.xyz", "0 0 0\n1e999 0 0\n", 1, {"line 2", "number out of the range of a double"}},
      {"short_line.xyz", "0 0 0\n1 2\n", 1, {"line 2", "expected at least 3 numbers (x y z), got 2"}},
      {"truncated.xyz", "0 0 0\n1 2 3\n4 5", 1, {"line 3", "got 2 numbers"}},
      {"nul_bytes.xyz", std::string(4096, '\0'), 1, {"line 1", "expected a number, got '\\x00"}},
      {"binary_garbage.xyz", "\x80\xfe\xff \x01\x02 \x7f\n", 1, {"line 1", "'\\x80\\xfe\\xff'"}},
      {"bad_normal.xyz", "0 0 0 0 0 1\n1 1 1 0 x 1\n", 1, {"line 2", "expected a number, got 'x'"}},
      {"cr_only_bad.xyz", "0 0 0\r1 2\r", 1, {"line 2", "got 2 numbers"}},
      {"ply_content.xyz", "ply\nformat ascii 1.0\n", 1, {"line 1", "expected a number, got 'ply'"}},
      // XYZ / PTS / TXT, accepted
      {"crlf.xyz", sphere(n_sphere, 1.0, 0.0, "\r\n"), 0, {}},
      {"cr_only.xyz", sphere(n_sphere, 1.0, 0.0, "\r"), 0, {}},
      {"bom.xyz", bom + sph, 0, {}},
      {"tabs_comments.xyz", replace_all(commented, " ", "\t"), 0, {}},
      {"counted.pts", counted, 0, {}},
      {"points.txt", sph, 0, {}},
      {"UPPER.XYZ", sph, 0, {}},
      {"nan_normal.xyz", nan_normals, 0, {}},
      {"mixed_widths.xyz", mixed, 0, {}},
      {"seven_columns.xyz", replace_all(sph, "\n", " 10 200 30 40\n"), 0, {}},
      // PLY, malformed
      {"empty.ply", "", 1, {"empty file (expected a PLY header)"}},
      {"not_ply.ply", "plx\nformat ascii 1.0\n", 1, {"line 1", "not a PLY file"}},
      {"no_format.ply", "ply\nelement vertex 1\nproperty float x\nend_header\n1\n", 1, {"no 'format' line"}},
      {"bad_format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", 1,
       {"line 2", "unknown PLY format 'binary_middle_endian'"}},
      {"bad_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n", 1,
       {"line 4", "unknown PLY type 'float128'"}},
      {"no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", 1,
       {"no 'end_header' line"}},
      {"no_vertex.ply", "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int v\nend_header\n", 1,
       {"no 'vertex' element"}},
      {"missing_z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
       1, {"no 'z' property"}},
      {"list_x.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar float x\nproperty float y\n"
                     "property float z\nend_header\n1 1 2 3\n", 1, {"vertex property 'x' is a list"}},
      {"two_vertex_elements.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
       "element vertex 1\nproperty float x\nend_header\n1 2 3\n1\n", 1, {"two 'vertex' elements"}},
      {"property_first.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", 1,
       {"line 3", "property declared before any element"}},
      {"zero_vertices.ply", ply_ascii_header(0), 1, {"no points (the header says 0 vertices)"}},
      {"few_values.ply", ply_ascii_header(2) + "1 2 3\n4 5\n", 1,
       {"vertex 2 of 2 (line 9)", "the line ends before property 'z'"}},
      {"many_values.ply", ply_ascii_header(2) + "1 2 3\n4 5 6 7\n", 1,
       {"vertex 2 of 2 (line 9)", "more values than the vertex properties"}},
      {"nan.ply", ply_ascii_header(2) + "1 2 3\n4 nan 6\n", 1, {"vertex 2 of 2 (line 9)", "not finite"}},
      {"lying_count.ply", ply_ascii_header(10) + "1 2 3\n4 5 6\n", 1,
       {"vertex 3 of 10", "header says 10 vertices but the file ends after 2"}},
      {"binary_truncated.ply", binary_ply_sphere(false, false, false).substr(0, 200), 1,
       {"vertex", "ends after"}},
      {"binary_huge_count.ply", replace_all(binary_ply_sphere(false, true, false, 2), "vertex 2", "vertex 1000000000000"), 1,
       {"vertex 3 of 1000000000000", "ends after 2"}},
      {"binary_negative_list.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty list char int l\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n\xfe", 1, {"vertex 1 of 1", "invalid count -2 for list 'l'"}},
      {"binary_inf.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n" + std::string("\x00\x00\x80\x7f\x00\x00\x00\x00\x00\x00\x00\x00", 12),
       1, {"vertex 1 of 1", "coordinate is not finite (inf)"}},
      // PLY, accepted
      {"ascii.ply", ply_ascii_header(n_sphere) + sph, 0, {}},
      {"crlf_header.ply", replace_all(ply_ascii_header(n_sphere), "\n", "\r\n") + sph, 0, {}},
      {"binary_le_double.ply", binary_ply_sphere(false, true, false), 0, {}},
      {"binary_be_float_face_first.ply", binary_ply_sphere(true, false, true), 0, {}},
      {"nan_normal.ply",
       ply_ascii_header(n_sphere + 1, "property float nx\nproperty float ny\nproperty float nz\n") +
           replace_all(sph, "\n", " 0 0 1\n") + "0 0 2 nan 0 1\n", 0, {}},
      // OFF, malformed
      {"empty.off", "", 1, {"empty file (expected an 'OFF' header line)"}},
      {"counts_no_keyword.off", "3 0 0\n0 0 0\n1 0 0\n0 1 0\n", 1, {"line 1", "counts line without its keyword"}},
      {"bad_keyword.off", "FOO\n1 0 0\n1 2 3\n", 1, {"line 1", "expected an OFF header keyword"}},
      {"binary.off", "OFF BINARY\n1 0 0\n", 1, {"line 1", "binary OFF is not supported"}},
      {"four_d.off", "4OFF\n1 0 0\n1 2 3 4\n", 1, {"line 1", "4D vertices"}},
      {"lying_count.off", "OFF\n10 0 0\n" + three, 1, {"header says 10 vertices but the file ends after 3"}},
      {"bad_count.off", "OFF\nabc 0 0\n", 1, {"line 2", "expected the vertex count"}},
      {"zero_vertices.off", "OFF\n0 0 0\n", 1, {"line 2", "no points (the header says 0 vertices)"}},
      {"short_vertex.off", "OFF\n3 0 0\n0 0 0\n1 0\n0 1 0\n", 1, {"vertex 2 of 3 (line 4)", "got 2 numbers"}},
      {"nan_vertex.off", "OFF\n3 0 0\nnan 0 0\n1 0 0\n0 1 0\n", 1, {"vertex 1 of 3 (line 3)", "not finite"}},
      {"noff_mixed.off", "NOFF\n2 0 0\n0 0 0 0 0 1\n1 1 1\n", 1,
       {"vertex 2 of 2 (line 4)", "expected 6 numbers (x y z nx ny nz)"}},
      {"headerless_widths.off", "0.5 0 0\n1 0 0 5\n", 1, {"line 2", "expected 3 numbers (x y z) as on line 1"}},
      {"noff_dimension_4.off", "nOFF 4\n1 0 0\n1 2 3 4\n", 1, {"line 1", "nOFF with dimension 4"}},
      // OFF, accepted
      {"sphere.off", "OFF\n" + std::to_string(n_sphere) + " 0 0\n" + sph + "3 0 1 2\n", 0, {}},
      {"normals.noff", "", 0, {}}, // filled below (needs the .off extension)
      {"headerless.off", sph, 0, {}},
      {"comments.off", "# made by hand\n\nOFF # keyword\n# counts next\n" + std::to_string(n_sphere) + " 0\n" +
                           commented, 0, {}},
      // Paths and names
      {"missing.xyz", "", 1, {"cannot open file: no such file"}, "out.obj", "", Kind::missing},
      {"folder.xyz", "", 1, {"cannot open file: it is a directory"}, "out.obj", "", Kind::directory},
      {"cloud.obj", "v 1 2 3\n", 1, {"unsupported file extension '.obj'"}},
      {"no_extension", sph, 1, {"unsupported file extension ''"}},
      // Usage
      {"usage_output.xyz", sph, 2, {"OUTPUT must end in .obj, .ply or .polylines.txt"}, "out.xyz"},
      {"usage_option.xyz", sph, 2, {"--no-such-option"}, "out.obj", "--no-such-option"},
      {"usage_resolution.xyz", sph, 2, {"voxel"}, "out.obj", "--voxel-resolution abc"},
      // Degenerate clouds, through the whole pipeline
      {"one_point.xyz", "1 2 3\n", 1, {"a single point"}},
      {"two_points.xyz", "0 0 0\n1 1 1\n", 1, {"no skeleton"}},
      {"three_points.xyz", three, 1, {"no skeleton", "plane"}},
      {"all_equal.xyz", all_equal, 1, {"coincide"}},
      {"collinear.xyz", points_text(200, [](int i, int) { return i * 0.01; }), 1, {"no skeleton"}},
      {"coplanar.xyz",
       points_text(400, [](int i, int a) { return a == 2 ? 0.0 : (a == 0 ? (i % 20) * 0.05 : (i / 20) * 0.05); }), 1,
       {"no skeleton", "plane"}},
      {"large_coordinates.xyz", sphere(n_sphere, 1e150), 0, {}},
      {"small_coordinates.xyz", sphere(n_sphere, 1e-150), 0, {}},
      // The skeletonization works on coordinates divided by the diagonal: any magnitude
      // a double holds gives the scaled skeleton, and what it cannot hold is named.
      {"huge_coordinates.xyz", sphere(n_sphere, 1e300), 0, {}},
      {"tiny_coordinates.xyz", sphere(n_sphere, 1e-300), 0, {}},
      {"extent_overflow.xyz", "-1e308 0 0\n1e308 0 0\n0 1e307 0\n0 0 1e307\n0 0 -1e307\n", 1,
       {"beyond the largest double", "cannot be represented"}},
      {"subnormal_extent.xyz", sphere(n_sphere, 1e-310), 1, {"smallest normal double", "cannot be represented"}},
      {"far_offset.xyz", sphere(n_sphere, 1.0, 1e15), 0, {}},
      {"duplicates.xyz", sph + sph, 0, {}},
      {"sphere.xyz", sph, 0, {}},
      {"sphere_ply_output.xyz", sph, 0, {}, "out.ply"},
      {"sphere_polylines.xyz", sph, 0, {}, "out.polylines.txt"},
  };
  for(Case& k : c)
    if(k.name == "normals.noff") {
      k.name = "normals.off";
      k.content = "NOFF\n" + std::to_string(n_sphere) + " 0 0\n" + sphere(n_sphere, 1.0, 0.0, "\n", true);
    }
  return c;
}

} // namespace

TEST_CASE("bad input corpus: each case gives its documented outcome through the tool", "[tool][corpus]")
{
  const Corpus_dir dir;
  const std::vector<Case> cases = corpus();
  CHECK(cases.size() >= 60);
  for(const Case& k : cases) {
    INFO("case " << k.name);
    const std::string input = dir.path(k.name);
    if(k.kind == Kind::file)
      std::ofstream(input, std::ios::binary).write(k.content.data(), static_cast<std::streamsize>(k.content.size()));
    else if(k.kind == Kind::directory)
      fs::create_directory(input);
    const std::string output = dir.path(k.name + "." + k.output);
    const Tool_run r = run_tool("\"" + input + "\" \"" + output + "\" --voxel-resolution 16 " + k.extra, dir);
    INFO("stderr: " << r.err);
    CHECK(r.status == k.status);
    for(const std::string& part : k.expected)
      CHECK(r.err.find(part) != std::string::npos);
    CHECK((lower(r.err).find("nan") == std::string::npos || k.name.find("nan") != std::string::npos));
    if(k.status == 0) {
      REQUIRE(fs::exists(output));
      const std::string out = read_all(output);
      CHECK(!out.empty());
      CHECK(lower(out).find("nan") == std::string::npos);
      CHECK(r.err.empty());
    } else {
      CHECK_FALSE(fs::exists(output));
      // One message line (the tool may end a progress line first).
      const std::string message = r.err.substr(r.err.find_first_not_of('\n') == std::string::npos
                                                   ? 0
                                                   : r.err.find_first_not_of('\n'));
      CHECK(std::count(message.begin(), message.end(), '\n') == 1);
      if(k.status == 1)
        CHECK(message.find(input) != std::string::npos);
    }
    std::error_code ec;
    fs::remove_all(input, ec);
    fs::remove(output, ec);
  }
}
