// The command-line contract of df_l1_skeleton: exit status, one clear line on stderr
// naming the file, no output file on failure, outputs and report on success.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

struct Run
{
  int status = -1;
  std::string err;
};

class Scratch
{
public:
  Scratch()
  {
    dir_ = fs::temp_directory_path() / ("df_l1_tool_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  ~Scratch() { std::error_code ec; fs::remove_all(dir_, ec); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const
  {
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }

private:
  fs::path dir_;
};

Run run_tool(const std::string& arguments, const Scratch& scratch)
{
  const std::string err_file = scratch.path("stderr.txt");
  const std::string command = std::string("\"") + DF_L1_TOOL_PATH + "\" " + arguments + " --quiet > /dev/null 2> \"" + err_file + "\"";
  const int raw = std::system(command.c_str());
  Run r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err_file);
  std::stringstream ss;
  ss << in.rdbuf();
  r.err = ss.str();
  return r;
}

std::string points_text(int n, double (*f)(int, int))
{
  std::ostringstream s;
  for(int i = 0; i < n; ++i)
    s << f(i, 0) << ' ' << f(i, 1) << ' ' << f(i, 2) << '\n';
  return s.str();
}

// A sampled sphere shell: a small, valid input.
std::string sphere_points(int n)
{
  std::ostringstream s;
  const double golden = 3.14159265358979 * (3 - std::sqrt(5.0));
  for(int i = 0; i < n; ++i)
  {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z);
    s << r * std::cos(golden * i) << ' ' << r * std::sin(golden * i) << ' ' << z << '\n';
  }
  return s.str();
}

} // namespace

TEST_CASE("tool: malformed inputs give exit status 1, one line naming the file, and no output", "[tool]")
{
  const Scratch scratch;
  const struct
  {
    const char* name;
    std::string content;
    const char* expected; // a fragment of the message
  } cases[] = {
    {"empty.xyz", "", "no points"},
    {"text.xyz", "0 0 0\n1 abc 2\n", "line 2"},
    {"nan.xyz", "0 0 0\n1 nan 2\n", "line 2"},
    {"inf.xyz", "0 0 0\n1 2 inf\n", "line 2"},
    {"short_line.xyz", "0 0 0\n1 2\n", "line 2"},
    {"lying.off", "OFF\n5 0 0\n0 0 0\n1 1 1\n", "5"},
    {"truncated.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 10\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n\x01\x02\x03",
     "vertex"},
    {"no_header_end.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "end_header"},
    {"one_point.xyz", "1 2 3\n", "coincide"},
    {"all_equal.xyz", "1 2 3\n1 2 3\n1 2 3\n1 2 3\n", "coincide"},
    {"collinear.xyz", points_text(200, [](int i, int) { return i * 0.01; }), "no skeleton"},
    {"coplanar.xyz", points_text(400, [](int i, int a) { return a == 2 ? 0.0 : (a == 0 ? (i % 20) * 0.05 : (i / 20) * 0.05); }),
     "no skeleton"},
    {"unknown.abc", "0 0 0\n", "extension"},
  };
  for(const auto& c : cases)
  {
    INFO(c.name);
    const std::string input = scratch.write(c.name, c.content);
    const std::string output = scratch.path("out.obj");
    const Run r = run_tool("\"" + input + "\" \"" + output + "\"", scratch);
    CHECK(r.status == 1);
    CHECK(r.err.find(c.name) != std::string::npos);
    CHECK(r.err.find(c.expected) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') <= 2); // one message line (after a progress newline)
    CHECK_FALSE(fs::exists(output));
  }
  {
    const Run r = run_tool("\"" + scratch.path("does_not_exist.xyz") + "\" \"" + scratch.path("out.obj") + "\"", scratch);
    CHECK(r.status == 1);
    CHECK(r.err.find("does_not_exist.xyz") != std::string::npos);
  }
}

TEST_CASE("tool: bad usage gives exit status 2", "[tool]")
{
  const Scratch scratch;
  const std::string input = scratch.write("sphere.xyz", sphere_points(3000));
  for(const std::string& args : {std::string("--no-such-option"), std::string("--voxel-resolution 2"),
                                 std::string("--voxel-resolution abc"), std::string("--stage bogus"),
                                 std::string("--threads"), std::string("a b c"),
                                 "\"" + input + "\" out.xyz", "\"" + input + "\" out.obj --stage voxels",
                                 "\"" + input + "\" out.obj --preview p.png"})
  {
    INFO(args);
    const Run r = run_tool(args, scratch);
    CHECK(r.status == 2);
    CHECK_FALSE(r.err.empty());
  }
}

TEST_CASE("tool: a valid input gives the skeleton, the preview and a complete report", "[tool]")
{
  const Scratch scratch;
  const std::string input = scratch.write("sphere.xyz", sphere_points(4000));
  const std::string before = [&] { std::ifstream f(input); std::stringstream s; s << f.rdbuf(); return s.str(); }();
  for(const std::string ext : {".obj", ".ply", ".polylines.txt"})
  {
    const std::string output = scratch.path("skeleton" + ext);
    const Run r = run_tool("\"" + input + "\" \"" + output + "\" --preview \"" + scratch.path("p.svg") +
                           "\" --report \"" + scratch.path("r.json") + "\" --threads 1", scratch);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(fs::file_size(output) > 0);
    CHECK(fs::file_size(scratch.path("p.svg")) > 0);
  }
  std::ifstream report(scratch.path("r.json"));
  std::stringstream json;
  json << report.rdbuf();
  for(const char* key : {"\"voxel_resolution\": 100", "\"bbox_diagonal\"", "\"voxel_size\"", "\"upsampling_radius\"",
                         "\"thinning_parameters\"", "\"voxelization\"", "\"distance\"", "\"initial\"",
                         "\"input_points\": 4000", "\"added_points\"", "\"outlier_points\"", "\"interior_voxels\"",
                         "\"skeleton_vertices\"", "\"skeleton_edges\"", "\"skeleton_components\"",
                         "\"skeleton_cycles\"", "\"peak_memory_mib\""})
  {
    INFO(key);
    CHECK(json.str().find(key) != std::string::npos);
  }
  CHECK(json.str().find("nan") == std::string::npos);
  const std::string after = [&] { std::ifstream f(input); std::stringstream s; s << f.rdbuf(); return s.str(); }();
  CHECK(before == after); // inputs are never modified
}

TEST_CASE("tool: --stage voxels and distance write labelled voxel centres", "[tool]")
{
  const Scratch scratch;
  const std::string input = scratch.write("sphere.xyz", sphere_points(4000));
  for(const std::string stage : {"voxels", "distance"})
  {
    const std::string output = scratch.path(stage + ".ply");
    const Run r = run_tool("\"" + input + "\" \"" + output + "\" --stage " + stage, scratch);
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::ifstream f(output);
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    CHECK(text.find("property int label") != std::string::npos);
    CHECK(text.find("property double distance") != std::string::npos);
  }
}

TEST_CASE("tool: an unwritable output fails cleanly and leaves no file", "[tool]")
{
  const Scratch scratch;
  const std::string input = scratch.write("sphere.xyz", sphere_points(3000));
  const Run r = run_tool("\"" + input + "\" \"" + scratch.path("no/such/dir/out.obj") + "\"", scratch);
  CHECK(r.status == 1);
  CHECK(r.err.find("out.obj") != std::string::npos);
}
