// The command-line contract of df_l1_skeleton: exit status, one clear line on stderr
// naming the file, no output file on failure, outputs and report on success.
#include <catch2/catch.hpp>

#include "evaluation/synthetic_shapes.h"
#include "support/shared_data.h"

#include <CGAL/DF_L1_skeleton/Parameters.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

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

std::string quoted(const std::string& path) { return "\"" + path + "\""; }

std::string read_text(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// A clean synthetic shape of tools/evaluation/synthetic_shapes.h (what df_l1_generate writes).
std::string shape_input(const Scratch& scratch, const std::string& shape, std::size_t n)
{
  const std::string path = scratch.path(shape + ".xyz");
  DF_L1_test::write_xyz(path, DF_L1_test::make_sample(DF_L1_test::shape_by_name(shape), DF_L1_test::Variant::clean, n, 1).points);
  return path;
}

// Parses the report; throws (and fails the test) if it is not valid JSON.
boost::property_tree::ptree read_report(const std::string& path)
{
  boost::property_tree::ptree tree;
  std::ifstream in(path);
  boost::property_tree::read_json(in, tree);
  return tree;
}

// The vertex count and connected components of an .obj polyline file, checking that it
// has nothing but the header comment, `v x y z` and `l a b` lines with valid indices.
struct Obj_graph
{
  std::size_t vertices = 0, edges = 0, components = 0;
  bool well_formed = true;
};

Obj_graph read_obj_graph(const std::string& path)
{
  Obj_graph g;
  std::vector<std::pair<long, long>> edges;
  std::istringstream in(read_text(path));
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string tag;
    fields >> tag;
    if(tag == "v")
    {
      double x, y, z;
      g.well_formed = g.well_formed && bool(fields >> x >> y >> z);
      ++g.vertices;
    }
    else if(tag == "l")
    {
      long a = 0, b = 0;
      g.well_formed = g.well_formed && bool(fields >> a >> b);
      edges.emplace_back(a - 1, b - 1);
    }
    else if(tag != "#")
      g.well_formed = false;
  }
  g.edges = edges.size();
  std::vector<std::size_t> parent(g.vertices);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto find = [&](std::size_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  g.components = g.vertices;
  for(const auto& e : edges)
  {
    if(e.first < 0 || e.second < 0 || std::size_t(e.first) >= g.vertices || std::size_t(e.second) >= g.vertices)
    {
      g.well_formed = false;
      continue;
    }
    const std::size_t a = find(std::size_t(e.first)), b = find(std::size_t(e.second));
    if(a != b)
    {
      parent[a] = b;
      --g.components;
    }
  }
  return g;
}

std::size_t count_of(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size()))
    ++n;
  return n;
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
    {"one_point.xyz", "1 2 3\n", "a single point"},
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
                                 std::string("--max-memory 0"), std::string("--max-memory 4X"),
                                 std::string("--max-memory abc"),
                                 "\"" + input + "\" out.xyz", "\"" + input + "\" out.obj --stage voxels",
                                 "\"" + input + "\" out.obj --preview p.png"})
  {
    INFO(args);
    const Run r = run_tool(args, scratch);
    CHECK(r.status == 2);
    CHECK_FALSE(r.err.empty());
  }
}

TEST_CASE("tool: the memory guard refuses a run beyond --max-memory at once, naming what to lower", "[tool][memory]")
{
  const Scratch scratch;
  const std::string input = scratch.write("sphere.xyz", sphere_points(3000));
  const std::string output = scratch.path("out.ply");
  const Run refused = run_tool("\"" + input + "\" \"" + output + "\" --voxel-resolution 2048 --max-memory 2G", scratch);
  CHECK(refused.status == 1);
  CHECK(refused.err.find("lower voxel_resolution") != std::string::npos);
  CHECK(refused.err.find("max_memory") != std::string::npos);
  CHECK(refused.err.find("outlier_points...") == std::string::npos); // before any stage ran
  CHECK_FALSE(fs::exists(output));
  const Run ran = run_tool("\"" + input + "\" \"" + output + "\" --max-memory 1G --report \"" +
                             scratch.path("r.json") + "\" --samples 500", scratch);
  INFO(ran.err);
  REQUIRE(ran.status == 0);
  std::ifstream report(scratch.path("r.json"));
  std::stringstream json;
  json << report.rdbuf();
  CHECK(json.str().find("\"estimated_peak_memory_mib\"") != std::string::npos);
}

TEST_CASE("tool: the refined memory estimate stops a run before the initial skeleton when it exceeds --max-memory",
          "[tool][memory]")
{
  const Scratch scratch;
  const std::string input = scratch.write("sphere.xyz", sphere_points(3000));
  const std::string output = scratch.path("out.ply");
  const std::string report = scratch.path("r.json");
  const Run ran = run_tool("\"" + input + "\" \"" + output + "\" --stage initial --report \"" + report + "\"", scratch);
  INFO(ran.err);
  REQUIRE(ran.status == 0);
  const auto tree = read_report(report);
  const double refined = tree.get<double>("estimated_peak_memory_mib");
  const double initial = tree.get<double>("initial_estimated_peak_memory_mib");
  // a sphere at voxel resolution 100: 1.3 million voxels, of which the grid, the field,
  // their copies in input units and the initial skeleton's search hold 42 bytes each,
  // more than the 30 of the initial model
  REQUIRE(refined > initial);
  fs::remove(output);
  const long long limit = static_cast<long long>((initial + refined) / 2 * 1024 * 1024);
  const Run refused = run_tool("\"" + input + "\" \"" + output + "\" --max-memory " + std::to_string(limit), scratch);
  CHECK(refused.status == 1);
  CHECK(refused.err.find("initial skeleton") != std::string::npos);
  CHECK(refused.err.find("lower voxel_resolution") != std::string::npos);
  CHECK(refused.err.find("max_memory") != std::string::npos);
  CHECK_FALSE(fs::exists(output));
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
                           "\" --report \"" + scratch.path("r.json") + "\" --threads 1 --samples 500", scratch);
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
                         "\"skeleton_cycles\"", "\"peak_memory_mib\"", "\"projection_seconds\""})
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

TEST_CASE("tool: the default stage is final and writes one connected skeleton", "[tool][final]")
{
  const Scratch scratch;
  const std::string input = shape_input(scratch, "y_junction", 3000);
  const std::string output = scratch.path("default.obj"), report = scratch.path("default.json");
  const Run r = run_tool(quoted(input) + " " + quoted(output) + " --report " + quoted(report) + " --threads 1", scratch);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const Obj_graph g = read_obj_graph(output);
  CHECK(g.well_formed);
  CHECK(g.vertices >= 2);
  CHECK(g.edges >= 1);
  CHECK(g.components == 1);

  const auto tree = read_report(report);
  CHECK(tree.get<std::string>("parameters.stage") == "final");
  CHECK(tree.get<std::size_t>("counts.skeleton_vertices") == g.vertices);
  CHECK(tree.get<std::size_t>("counts.skeleton_edges") == g.edges);
  CHECK(tree.get<std::size_t>("counts.skeleton_components") == 1);
  // The library's defaults, as the report states them.
  CHECK(tree.get<std::string>("parameters.method") == "df_l1");
  CHECK(tree.get<std::size_t>("parameters.number_of_samples") == 1500);
  CHECK(tree.get<double>("parameters.repulsion_coefficient") == Approx(0.35));
  CHECK(tree.get<double>("parameters.support_radius_growth") == Approx(0.5));
  CHECK(tree.get<double>("parameters.branch_directionality") == Approx(0.9));
  CHECK(tree.get<int>("parameters.number_of_iterations") == 30);
  CHECK(tree.get<double>("parameters.initial_support_radius") > 0);

  // --stage final is the same run.
  const std::string explicit_output = scratch.path("final.obj");
  REQUIRE(run_tool(quoted(input) + " " + quoted(explicit_output) + " --stage final --threads 1", scratch).status == 0);
  CHECK(read_text(explicit_output) == read_text(output));
}

TEST_CASE("tool: the report of the final stage states the contraction", "[tool][final]")
{
  const Scratch scratch;
  const std::string input = shape_input(scratch, "y_junction", 3000);
  const double h0 = 0.15 * DF_L1_test::shape_by_name("y_junction").bbox_diagonal();
  std::ostringstream h0_text;
  h0_text << std::setprecision(17) << h0;
  const std::string output = scratch.path("skeleton.ply"), report = scratch.path("r.json");
  const Run r = run_tool(quoted(input) + " " + quoted(output) + " --report " + quoted(report) +
                         " --samples 400 --repulsion 0.3 --support-radius " + h0_text.str() +
                         " --support-growth 0.75 --branch-sigma 0.85 --iterations 12 --contraction-stages 3 --threads 1", scratch);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::string text = read_text(report);
  INFO(text);
  boost::property_tree::ptree tree;
  REQUIRE_NOTHROW(tree = read_report(report)); // valid JSON
  CHECK(text.find("nan") == std::string::npos);
  CHECK(text.find("null") == std::string::npos);

  // Every key of the earlier stages is still there.
  for(const char* key : {"input", "output", "version", "peak_memory_mib", "parameters.stage", "parameters.threads",
                         "parameters.seed", "parameters.bbox_diagonal", "parameters.upsampling",
                         "parameters.upsampling_neighbors", "parameters.upsampling_radius", "parameters.voxel_resolution",
                         "parameters.initial_voxel_size", "parameters.initial_voxel_size_used",
                         "parameters.refinement_levels", "parameters.voxel_size", "parameters.exterior_propagation_steps",
                         "parameters.outlier_component_size", "parameters.thinning_coefficient",
                         "parameters.thinning_parameters", "parameters.spur_length_ratio", "seconds.read",
                         "seconds.outlier_points", "seconds.upsampling", "seconds.voxelization", "seconds.outliers",
                         "seconds.distance", "seconds.initial", "seconds.write", "counts.input_points",
                         "counts.added_points", "counts.outlier_points", "counts.sparse_outlier_points",
                         "counts.outlier_clusters", "counts.shape_components", "counts.grid", "counts.boundary_voxels",
                         "counts.interior_voxels", "counts.exterior_voxels", "counts.outlier_voxels",
                         "counts.max_distance", "counts.skeleton_voxels", "counts.skeleton_vertices",
                         "counts.skeleton_edges", "counts.skeleton_components", "counts.skeleton_cycles",
                         "counts.skeleton_end_points", "counts.skeleton_junctions",
                         // and the new ones
                         "seconds.contraction", "seconds.skeleton", "counts.initial_skeleton_vertices",
                         "counts.initial_skeleton_edges", "counts.initial_skeleton_components",
                         "counts.initial_skeleton_cycles", "counts.initial_skeleton_end_points",
                         "counts.initial_skeleton_junctions", "counts.samples", "counts.branch_points",
                         "counts.iterations", "counts.contraction_stages"})
  {
    INFO(key);
    CHECK(bool(tree.get_child_optional(key)));
  }
  // The parameters given are the parameters used.
  CHECK(tree.get<std::string>("parameters.method") == "df_l1");
  CHECK(tree.get<std::size_t>("parameters.number_of_samples") == 400);
  CHECK(tree.get<double>("parameters.repulsion_coefficient") == Approx(0.3));
  CHECK(tree.get<double>("parameters.initial_support_radius") == Approx(h0));
  CHECK(tree.get<double>("parameters.support_radius_growth") == Approx(0.75));
  CHECK(tree.get<double>("parameters.branch_directionality") == Approx(0.85));
  CHECK(tree.get<int>("parameters.number_of_iterations") == 12);
  CHECK(tree.get<int>("parameters.contraction_stages") == 3);
  CHECK(tree.get_child("counts.contraction_stages").size() <= 3);

  const std::size_t samples = tree.get<std::size_t>("counts.samples");
  CHECK(samples > 0);
  CHECK(samples <= 400);
  CHECK(tree.get<std::size_t>("counts.branch_points") > 0);
  const auto& stages = tree.get_child("counts.contraction_stages");
  REQUIRE(!stages.empty());
  int iterations = 0;
  bool first = true;
  for(const auto& entry : stages)
  {
    const auto& stage = entry.second;
    CHECK(entry.first.empty()); // an array element
    const int it = stage.get<int>("iterations");
    CHECK(it >= 0);
    CHECK(it <= 12);
    iterations += it;
    const double lo = stage.get<double>("min_radius"), mean = stage.get<double>("mean_radius"),
                 hi = stage.get<double>("max_radius");
    CHECK(lo > 0);
    CHECK(lo <= mean * (1 + 1e-12));
    CHECK(mean <= hi * (1 + 1e-12));
    CHECK(stage.get<std::size_t>("free_samples") <= samples);
    CHECK(bool(stage.get_child_optional("branch_samples")));
    if(first)
      CHECK(lo == Approx(h0)); // every sample starts with h0
    first = false;
  }
  CHECK(tree.get<int>("counts.iterations") == iterations);
}

TEST_CASE("tool: --method l1 runs the plain L1-medial contraction", "[tool][final]")
{
  const Scratch scratch;
  const std::string input = shape_input(scratch, "y_junction", 3000);
  for(const std::string method : {"df_l1", "l1"})
  {
    INFO(method);
    const std::string output = scratch.path(method + ".obj"), report = scratch.path(method + ".json");
    const Run r = run_tool(quoted(input) + " " + quoted(output) + " --method " + method + " --samples 400 --report " +
                           quoted(report) + " --threads 1", scratch);
    INFO(r.err);
    REQUIRE(r.status == 0);
    const Obj_graph g = read_obj_graph(output);
    CHECK(g.well_formed);
    CHECK(g.vertices >= 2);
    const auto tree = read_report(report);
    CHECK(tree.get<std::string>("parameters.method") == method);
    const auto& stages = tree.get_child("counts.contraction_stages");
    REQUIRE(!stages.empty());
    if(method == "l1") // without the guidance all samples share the support radius
      for(const auto& entry : stages)
        CHECK(entry.second.get<double>("min_radius") == Approx(entry.second.get<double>("max_radius")));
  }
}

TEST_CASE("tool: --denoise smooths noisy clouds by default and as told", "[tool][denoising]")
{
  const Scratch scratch;
  const std::string noisy = scratch.path("noisy.xyz"), clean = shape_input(scratch, "capsule", 4000);
  DF_L1_test::write_xyz(noisy, DF_L1_test::make_sample(DF_L1_test::shape_by_name("capsule"), DF_L1_test::Variant::noise, 4000, 1).points);
  const struct
  {
    std::string input, mode;
    bool denoised;
  } cases[] = {{noisy, "", true}, {clean, "", false}, {noisy, "off", false}, {clean, "on", true}, {clean, "auto", false}};
  for(const auto& c : cases)
  {
    INFO(c.input << " --denoise " << c.mode);
    const std::string report = scratch.path("r.json");
    const Run r = run_tool(quoted(c.input) + " " + quoted(scratch.path("s.obj")) + " --stage initial --report " + quoted(report) +
                           (c.mode.empty() ? "" : " --denoise " + c.mode) + " --denoising-neighbors 20", scratch);
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto tree = read_report(report);
    CHECK(tree.get<std::string>("parameters.denoising") == (c.mode.empty() ? "auto" : c.mode));
    CHECK(tree.get<int>("parameters.denoising_neighbors") == 20);
    CHECK(tree.get<bool>("counts.denoised") == c.denoised);
    CHECK(tree.get<double>("counts.surface_noise") >= 0);
    CHECK(tree.get<double>("counts.residual_growth") >= 0);
    CHECK(tree.get<double>("seconds.denoising") >= 0);
  }
  for(const std::string bad : {"--denoise yes", "--denoise", "--denoising-neighbors 5", "--denoising-neighbors 257"})
  {
    INFO(bad);
    const Run r = run_tool(quoted(clean) + " " + quoted(scratch.path("bad.obj")) + " " + bad, scratch);
    CHECK(r.status == 2);
    CHECK(r.err.find(bad.substr(0, bad.find(' '))) != std::string::npos);
    CHECK_FALSE(fs::exists(scratch.path("bad.obj")));
  }
}

TEST_CASE("tool: bad values of the contraction options give exit status 2 and a message", "[tool][final]")
{
  const Scratch scratch;
  const std::string input = scratch.write("sphere.xyz", sphere_points(500));
  const std::string output = scratch.path("out.obj");
  const struct
  {
    std::string arguments, option; // the option the message must name
  } cases[] = {
    {"--method bogus", "--method"},           {"--method", "--method"},
    {"--samples 0", "--samples"},             {"--samples -5", "--samples"},
    {"--samples 1.5", "--samples"},           {"--samples abc", "--samples"},
    {"--repulsion 0.5", "--repulsion"},       {"--repulsion -0.01", "--repulsion"},
    {"--repulsion x", "--repulsion"},         {"--support-radius 0", "--support-radius"},
    {"--support-radius -1", "--support-radius"}, {"--support-radius nan", "--support-radius"},
    {"--support-growth 0", "--support-growth"}, {"--support-growth 4.5", "--support-growth"},
    {"--branch-sigma 0.3", "--branch-sigma"}, {"--branch-sigma 1", "--branch-sigma"},
    {"--iterations 0", "--iterations"},       {"--iterations 10001", "--iterations"},
    {"--iterations 2.5", "--iterations"},     {"--preview-stages", "--preview-stages"},
    {"--contraction-stages 0", "--contraction-stages"}, {"--contraction-stages 65", "--contraction-stages"},
    {"--stage initial --preview " + quoted(scratch.path("p.svg")) + " --preview-stages", "--preview-stages"},
    {"--stage fin", "--stage"},
  };
  for(const auto& c : cases)
  {
    INFO(c.arguments);
    const Run r = run_tool(quoted(input) + " " + quoted(output) + " " + c.arguments, scratch);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(c.option) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(output));
  }
}

TEST_CASE("tool: --preview-stages adds a row per earlier stage; voxel stages draw slices", "[tool][final]")
{
  const Scratch scratch;
  const std::string input = shape_input(scratch, "y_junction", 3000);
  const std::string output = scratch.path("out.obj");
  const auto preview = [&](const std::string& name, const std::string& arguments) {
    const std::string svg = scratch.path(name);
    const std::string out = arguments.find("--stage voxels") != std::string::npos ||
                                    arguments.find("--stage distance") != std::string::npos
                              ? scratch.path("voxels.ply")
                              : output;
    const Run r = run_tool(quoted(input) + " " + quoted(out) + " --samples 400 --threads 1 --preview " + quoted(svg) +
                           " " + arguments, scratch);
    INFO(r.err);
    REQUIRE(r.status == 0);
    return read_text(svg);
  };
  // The rows in this order, the result first.
  const std::vector<std::string> titles{">final skeleton", ">contracted samples", ">initial skeleton",
                                        ">distance field", ">voxels"};
  const std::string all = preview("all.svg", "--preview-stages");
  CHECK(count_of(all, "class=\"row-title\"") == 5);
  std::size_t previous = 0;
  for(const std::string& title : titles)
  {
    INFO(title);
    const std::size_t at = all.find(title);
    REQUIRE(at != std::string::npos);
    CHECK(at > previous);
    previous = at;
  }
  // Slices of both voxel rows; the distance field is shaded, the voxels are not.
  CHECK(count_of(all, "slice") >= 6);
  CHECK(all.find("#bd0026") != std::string::npos); // the deepest shade
  CHECK(all.find("#6baed6") != std::string::npos); // interior voxels

  const std::string final_only = preview("final.svg", "");
  CHECK(count_of(final_only, "class=\"row-title\"") == 1);
  CHECK(final_only.find(">final skeleton") != std::string::npos);
  CHECK(final_only.find(">initial skeleton") == std::string::npos);

  const std::string initial_only = preview("initial.svg", "--stage initial");
  CHECK(count_of(initial_only, "class=\"row-title\"") == 1);
  CHECK(initial_only.find(">initial skeleton") != std::string::npos);
  CHECK(initial_only.find(">final skeleton") == std::string::npos);

  const std::string distance = preview("distance.svg", "--stage distance");
  CHECK(count_of(distance, "class=\"row-title\"") == 1);
  CHECK(distance.find(">distance field") != std::string::npos);
  CHECK(distance.find("#bd0026") != std::string::npos);

  const std::string voxels = preview("voxels.svg", "--stage voxels");
  CHECK(count_of(voxels, "class=\"row-title\"") == 1);
  CHECK(voxels.find(">voxels") != std::string::npos);
  CHECK(voxels.find("#6baed6") != std::string::npos);
  CHECK(voxels.find("#6e6e6e") != std::string::npos); // boundary voxels
  CHECK(voxels.find("#bd0026") == std::string::npos);
}

TEST_CASE("tool: --stage initial still writes the initial skeleton in the same formats", "[tool][final]")
{
  const Scratch scratch;
  const std::string input = shape_input(scratch, "y_junction", 3000);
  const std::string report = scratch.path("initial.json");
  REQUIRE(run_tool(quoted(input) + " " + quoted(scratch.path("initial.obj")) + " --stage initial --report " +
                   quoted(report), scratch).status == 0);
  REQUIRE(run_tool(quoted(input) + " " + quoted(scratch.path("initial.ply")) + " --stage initial", scratch).status == 0);
  REQUIRE(run_tool(quoted(input) + " " + quoted(scratch.path("initial.polylines.txt")) + " --stage initial", scratch).status == 0);

  const Obj_graph g = read_obj_graph(scratch.path("initial.obj"));
  CHECK(g.well_formed);
  const std::string obj = read_text(scratch.path("initial.obj"));
  CHECK(obj.rfind("# DF_L1_skeleton: " + std::to_string(g.vertices) + " vertices, " + std::to_string(g.edges) + " edges\n", 0) == 0);
  const std::string ply = read_text(scratch.path("initial.ply"));
  CHECK(ply.rfind("ply\nformat ascii 1.0\ncomment written by DF_L1_skeleton\nelement vertex " + std::to_string(g.vertices) +
                  "\nproperty double x\nproperty double y\nproperty double z\nproperty double radius\nelement edge " +
                  std::to_string(g.edges) + "\nproperty int vertex1\nproperty int vertex2\nend_header\n", 0) == 0);
  const std::string polylines = read_text(scratch.path("initial.polylines.txt"));
  CHECK(!polylines.empty());
  CHECK(std::isdigit(static_cast<unsigned char>(polylines[0])));

  // The report is the one of the initial stage: no key of the contraction.
  const std::string text = read_text(report);
  INFO(text);
  const auto tree = read_report(report);
  CHECK(tree.get<std::string>("parameters.stage") == "initial");
  CHECK(tree.get<std::size_t>("counts.skeleton_vertices") == g.vertices);
  for(const char* key : {"parameters.method", "parameters.number_of_samples", "seconds.contraction", "seconds.skeleton",
                         "counts.samples", "counts.contraction_stages", "counts.initial_skeleton_vertices"})
  {
    INFO(key);
    CHECK_FALSE(bool(tree.get_child_optional(key)));
  }

  // It is the initial skeleton of the final stage.
  const std::string final_report = scratch.path("final.json");
  REQUIRE(run_tool(quoted(input) + " " + quoted(scratch.path("final.obj")) + " --samples 400 --report " +
                   quoted(final_report), scratch).status == 0);
  const auto final_tree = read_report(final_report);
  CHECK(final_tree.get<std::size_t>("counts.initial_skeleton_vertices") == g.vertices);
  CHECK(final_tree.get<std::size_t>("counts.initial_skeleton_edges") == g.edges);
  CHECK(final_tree.get<std::size_t>("counts.skeleton_voxels") == tree.get<std::size_t>("counts.skeleton_voxels"));
}

TEST_CASE("tool: --help lists the stages and the contraction options", "[tool][final]")
{
  const Scratch scratch;
  const std::string out = scratch.path("help.txt");
  const int raw = std::system(("\"" + std::string(DF_L1_TOOL_PATH) + "\" --help > " + quoted(out)).c_str());
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 0);
  const std::string help = read_text(out);
  for(const char* text : {"voxels, distance, initial or final (default: final)", "--method", "--samples", "--repulsion",
                          "--support-radius", "--support-growth", "--branch-sigma", "--iterations", "--preview-stages",
                          "--denoise", "--denoising-neighbors", "--contraction-stages"})
  {
    INFO(text);
    CHECK(help.find(text) != std::string::npos);
  }
}

TEST_CASE("tool: every library parameter has an option, and the earlier spellings still work", "[tool][parameters]")
{
  const Scratch scratch;
  // --help lists each parameter of the library's table under its canonical name
  const std::string help_file = scratch.path("help.txt");
  REQUIRE(std::system(("\"" + std::string(DF_L1_TOOL_PATH) + "\" --help > " + quoted(help_file)).c_str()) == 0);
  const std::string help = read_text(help_file);
  for(const CGAL::DF_L1::Parameter_info& info : CGAL::DF_L1::parameter_table())
  {
    INFO(info.name);
    CHECK(help.find("--" + info.option() + " ") != std::string::npos);
    CHECK(help.find("(default: " + std::string(info.default_text) + ")") != std::string::npos);
  }
  // old and canonical spellings give the same skeleton and the same report parameters
  const std::string input = shape_input(scratch, "y_junction", 3000);
  const struct
  {
    std::string old_spelling, canonical;
  } cases[] = {
    {"--repulsion 0.3 --samples 400 --iterations 20", "--repulsion-coefficient 0.3 --number-of-samples=400 --number-of-iterations 20"},
    {"--support-growth 0.6 --branch-sigma 0.85 --support-radius 0.08",
     "--support-radius-growth 0.6 --branch-directionality 0.85 --initial-support-radius 0.08"},
    {"--no-upsampling --method l1 --denoise off", "--upsampling off --skeletonization-method l1 --denoising off"},
  };
  for(const auto& c : cases)
  {
    INFO(c.old_spelling);
    const std::string a = scratch.path("a.ply"), b = scratch.path("b.ply");
    const Run ra = run_tool(quoted(input) + " " + quoted(a) + " --threads 1 --report " + quoted(scratch.path("a.json")) + " " + c.old_spelling, scratch);
    const Run rb = run_tool(quoted(input) + " " + quoted(b) + " --threads 1 --report " + quoted(scratch.path("b.json")) + " " + c.canonical, scratch);
    INFO(ra.err << rb.err);
    REQUIRE(ra.status == 0);
    REQUIRE(rb.status == 0);
    CHECK(read_text(a) == read_text(b));
    CHECK(read_report(scratch.path("a.json")).get_child("parameters") == read_report(scratch.path("b.json")).get_child("parameters"));
  }
  // a value out of range names the option as typed, and the library's range
  for(const std::string bad : {"--repulsion-coefficient 0.7", "--number-of-samples 0", "--upsampling maybe", "--denoising loud"})
  {
    INFO(bad);
    const Run r = run_tool(quoted(input) + " " + quoted(scratch.path("bad.obj")) + " " + bad, scratch);
    CHECK(r.status == 2);
    CHECK(r.err.find(bad.substr(0, bad.find(' '))) != std::string::npos);
    CHECK_FALSE(fs::exists(scratch.path("bad.obj")));
  }
}

TEST_CASE("tool: --segmentation labels every input point with its vertex and branch", "[tool][segmentation]")
{
  const Scratch scratch;
  const std::string input = shape_input(scratch, "y_junction", 3000);
  const std::string segments = scratch.path("segments.ply"), skeleton = scratch.path("s.polylines.txt");
  const Run r = run_tool(quoted(input) + " " + quoted(skeleton) + " --threads 1 --segmentation " + quoted(segments), scratch);
  INFO(r.err);
  REQUIRE(r.status == 0);
  std::istringstream in(read_text(segments));
  std::string line;
  std::size_t declared = 0;
  while(std::getline(in, line) && line != "end_header")
    if(line.rfind("element vertex ", 0) == 0)
      declared = std::stoul(line.substr(15));
  CHECK(declared == 3000);
  // one polyline per branch in the skeleton file; every branch label names one of them
  std::size_t branches = 0;
  {
    std::istringstream polylines(read_text(skeleton));
    while(std::getline(polylines, line))
      branches += !line.empty();
  }
  REQUIRE(branches == 3); // a Y: three branches from the junction
  std::vector<std::size_t> per_branch(branches, 0);
  std::size_t rows = 0, labelled = 0;
  double x, y, z;
  long vertex, branch;
  while(in >> x >> y >> z >> vertex >> branch)
  {
    ++rows;
    CHECK((vertex < 0) == (branch < 0));
    if(branch >= 0)
    {
      REQUIRE(std::size_t(branch) < branches);
      ++per_branch[std::size_t(branch)];
      ++labelled;
    }
  }
  CHECK(rows == 3000);
  CHECK(labelled > 2700); // a clean sample: few outliers
  for(std::size_t b = 0; b < branches; ++b)
    CHECK(per_branch[b] > 300); // each arm holds its share of the points
  // only with a skeleton, and only to a PLY file
  for(const std::string bad : {"--stage voxels --segmentation " + quoted(scratch.path("x.ply")),
                               "--segmentation " + quoted(scratch.path("x.txt"))})
  {
    INFO(bad);
    const Run b = run_tool(quoted(input) + " " + quoted(scratch.path(bad.find("voxels") != std::string::npos ? "v.ply" : "o.obj")) +
                           " " + bad, scratch);
    CHECK(b.status == 2);
    CHECK(b.err.find("--segmentation") != std::string::npos);
  }
}

namespace {

// The report without what may vary between runs: the seconds, the peak memory and the
// number of threads. The rest is compared byte for byte (the tree keeps the numbers'
// text as written).
std::string deterministic_report(const std::string& path)
{
  boost::property_tree::ptree tree = read_report(path);
  tree.erase("seconds");
  tree.erase("peak_memory_mib");
  tree.get_child("parameters").erase("threads");
  if(auto stages = tree.get_child_optional("counts.contraction_stages"))
    for(auto& stage : *stages)
      stage.second.erase("projection_seconds");
  std::ostringstream text;
  boost::property_tree::write_json(text, tree);
  return text.str();
}

} // namespace

// The headline clouds of scripts/bench.sh (35,000 points, seed 7) and every scan of the
// shared data folder, run with 1, 2, 3, 4 and 8 threads (8 oversubscribes a 2-core
// machine: the tool runs in an arena of exactly --threads slots); the skeleton, the
// report, the segmentation and the preview must not change. About 75 s on 2 cores;
// without the shared data folder only the bench clouds run (the ctest entry then reads
// as skipped). A cloud denser than its voxels (150,000 noisy points at V = 30) takes the
// sampled outlier test and the density cap.
TEST_CASE("tool: the same skeleton and report, byte for byte, for 1, 2, 3, 4 and 8 threads",
          "[tool][threads][shared_data]")
{
  const Scratch scratch;
  std::vector<std::string> inputs;
  const std::string dense = scratch.path("stick_figure-noise-dense.xyz");
  DF_L1_test::write_xyz(dense, DF_L1_test::make_sample(DF_L1_test::shape_by_name("stick_figure"),
                                                       DF_L1_test::Variant::noise, 150000, 7).points);
  inputs.push_back(dense);
  for(const char* headline : {"stick_figure:clean", "torus:clean", "branching_tree:clean", "many_armed:clean",
                              "stick_figure:noise"})
  {
    const std::string name = headline, shape = name.substr(0, name.find(':')), variant = name.substr(name.find(':') + 1);
    const std::string path = scratch.path(shape + "-" + variant + ".xyz");
    DF_L1_test::write_xyz(path, DF_L1_test::make_sample(DF_L1_test::shape_by_name(shape),
                                                        DF_L1_test::variant_by_name(variant), 35000, 7).points);
    inputs.push_back(path);
  }
  const std::string data = DF_L1_test::shared_data_folder();
  if(!data.empty())
  {
    std::vector<std::string> scans;
    for(const auto& entry : fs::directory_iterator(data))
    {
      const std::string ext = entry.path().extension().string();
      if(entry.is_regular_file() && (ext == ".xyz" || ext == ".ply" || ext == ".off"))
        scans.push_back(entry.path().string());
    }
    std::sort(scans.begin(), scans.end());
    CHECK(scans.size() >= 16);
    inputs.insert(inputs.end(), scans.begin(), scans.end());
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string skeleton = scratch.path("skeleton.ply"), report = scratch.path("report.json"),
                    segments = scratch.path("segments.ply"), preview = scratch.path("preview.svg");
  for(const std::string& input : inputs)
  {
    INFO(input);
    std::vector<std::string> reference;
    for(const int threads : {1, 2, 3, 4, 8})
    {
      INFO(threads << " threads");
      const Run r = run_tool(quoted(input) + " " + quoted(skeleton) + " --report " + quoted(report) + " --segmentation " +
                               quoted(segments) + " --preview " + quoted(preview) + " --threads " + std::to_string(threads) +
                               (input == dense ? " --voxel-resolution 30" : ""),
                             scratch);
      INFO(r.err);
      REQUIRE(r.status == 0);
      CHECK(read_report(report).get<int>("parameters.threads") == threads);
      if(input == dense)
        CHECK(read_report(report).get<double>("counts.analysed_points") < 50000);
      const std::vector<std::string> outputs{read_text(skeleton), deterministic_report(report), read_text(segments),
                                             read_text(preview)};
      if(threads == 1)
        reference = outputs;
      // One by one, so that a failure says which.
      CHECK(outputs[0] == reference[0]);
      CHECK(outputs[1] == reference[1]);
      CHECK(outputs[2] == reference[2]);
      CHECK(outputs[3] == reference[3]);
    }
  }
  WARN(inputs.size() << " inputs x 5 thread counts in "
                     << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s");
}

namespace {

// A run of the tool as a child process whose stderr the test reads as it comes, to act
// at a given moment of the run (a signal, a change of the input).
class Child_run
{
public:
  // `in_child` runs in the child before exec (limits, signal dispositions).
  Child_run(const std::vector<std::string>& arguments, void (*in_child)() = nullptr)
  {
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    pid_ = ::fork();
    REQUIRE(pid_ >= 0);
    if(pid_ == 0)
    {
      ::dup2(fds[1], 2);
      ::close(fds[0]);
      ::close(fds[1]);
      if(in_child)
        in_child();
      std::vector<char*> argv{const_cast<char*>(DF_L1_TOOL_PATH)};
      for(const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(DF_L1_TOOL_PATH, argv.data());
      std::_Exit(127);
    }
    ::close(fds[1]);
    err_fd_ = fds[0];
  }
  ~Child_run()
  {
    if(pid_ > 0 && !reaped_)
    {
      ::kill(pid_, SIGKILL);
      wait();
    }
    if(err_fd_ >= 0)
      ::close(err_fd_);
  }
  // Reads stderr until `text` appears (true) or the child closes it (false).
  bool wait_for(const std::string& text)
  {
    char buffer[4096];
    while(err_.find(text) == std::string::npos)
    {
      const ssize_t n = ::read(err_fd_, buffer, sizeof(buffer));
      if(n <= 0)
        return false;
      err_.append(buffer, std::size_t(n));
    }
    return true;
  }
  void signal(int s) { ::kill(pid_, s); }
  bool running()
  {
    if(!reaped_ && ::waitpid(pid_, &raw_status_, WNOHANG) == pid_)
      reaped_ = true;
    return !reaped_;
  }
  // The exit status (-1 if killed by a signal), after the rest of stderr.
  int wait()
  {
    wait_for("\x01never\x01");
    if(!reaped_)
      ::waitpid(pid_, &raw_status_, 0);
    reaped_ = true;
    status_ = WIFEXITED(raw_status_) ? WEXITSTATUS(raw_status_) : -1;
    return status_;
  }
  const std::string& err() const { return err_; }

private:
  pid_t pid_ = -1;
  int err_fd_ = -1;
  int raw_status_ = 0, status_ = -1;
  bool reaped_ = false;
  std::string err_;
};

std::vector<std::string> entries(const std::string& folder)
{
  std::vector<std::string> names;
  for(const auto& e : fs::directory_iterator(folder))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A folder holding only a cloud large enough for the run to last a few seconds.
std::string big_input(const Scratch& scratch, const std::string& folder, std::size_t n)
{
  fs::create_directories(scratch.path(folder));
  const std::string path = scratch.path(folder + "/input.xyz");
  DF_L1_test::write_xyz(path, DF_L1_test::make_sample(DF_L1_test::shape_by_name("stick_figure"),
                                                      DF_L1_test::Variant::clean, n, 7).points);
  return path;
}

} // namespace

TEST_CASE("tool: SIGINT and SIGTERM exit with 130 and 143 and leave no file", "[tool][faults][signals]")
{
  const Scratch scratch;
  const std::string input = big_input(scratch, "signals", 600000), folder = scratch.path("signals");
  const std::vector<std::string> arguments{input, folder + "/skeleton.ply", "--segmentation", folder + "/segments.ply",
                                           "--report", folder + "/report.json", "--preview", folder + "/preview.svg"};
  const struct
  {
    int signal;
    const char* when; // a stage's progress, or the temporary file to wait for
    bool file;
  } cases[] = {
    {SIGINT, "contraction...", false},   // computing: no file yet
    {SIGTERM, ".skeleton.ply.tmp", true}, // the first output being written
    {SIGINT, ".segments.ply.tmp", true},  // the second, the first waiting for the commit
  };
  for(const auto& c : cases)
  {
    INFO(c.when << ", signal " << c.signal);
    Child_run run(arguments);
    if(!c.file)
      REQUIRE(run.wait_for(c.when));
    else
    {
      REQUIRE(run.wait_for("write..."));
      bool seen = false;
      while(!seen && run.running())
        for(const std::string& name : entries(folder))
          seen = seen || name.rfind(c.when, 0) == 0;
      REQUIRE(seen);
    }
    run.signal(c.signal);
    const int status = run.wait();
    INFO(run.err());
    CHECK(status == 128 + c.signal);
    CHECK(run.err().find(c.signal == SIGINT ? "interrupted (SIGINT)" : "terminated (SIGTERM)") != std::string::npos);
    CHECK(entries(folder) == std::vector<std::string>{"input.xyz"});
  }
}

TEST_CASE("tool: a full disk names the file and the reason, and leaves no file", "[tool][faults]")
{
  const Scratch scratch;
  const std::string input = shape_input(scratch, "y_junction", 3000);
  const std::string folder = scratch.path("disk");
  fs::create_directories(folder);
  // A file-size limit makes write() fail with EFBIG, as a full disk with ENOSPC; the
  // skeleton fits, the segmentation (3000 points) does not, and neither is left.
  Child_run limited({input, folder + "/skeleton.ply", "--segmentation", folder + "/segments.ply", "--quiet"}, [] {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{32 * 1024, 32 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  });
  CHECK(limited.wait() == 1);
  CHECK(limited.err().find("cannot write '" + folder + "/segments.ply': writing failed: File too large") != std::string::npos);
  CHECK(entries(folder).empty());

  // /dev/full, through a link named as an output (the device is written in place).
  if(!fs::exists("/dev/full"))
    return;
  fs::create_symlink("/dev/full", folder + "/full.ply");
  fs::create_symlink("/dev/full", folder + "/full.json");
  for(const std::vector<std::string>& arguments :
      {std::vector<std::string>{input, folder + "/full.ply", "--quiet"},
       std::vector<std::string>{input, folder + "/skeleton.ply", "--report", folder + "/full.json", "--quiet"}})
  {
    Child_run run(arguments);
    CHECK(run.wait() == 1);
    INFO(run.err());
    CHECK(run.err().find("/full.") != std::string::npos);
    CHECK(run.err().find("No space left on device") != std::string::npos);
    CHECK(entries(folder) == std::vector<std::string>{"full.json", "full.ply"});
    CHECK(fs::is_character_file("/dev/full"));
  }
}

TEST_CASE("tool: an input truncated or changed while it is read is reported", "[tool][faults]")
{
  const Scratch scratch;
  const std::string original = big_input(scratch, "original", 600000), folder = scratch.path("changed");
  fs::create_directories(folder);
  const std::string input = folder + "/input.xyz";
  const std::uintmax_t size = fs::file_size(original);
  // The change must come while the tool parses (about 0.1 s): right after it says
  // "read...". A change that comes too early or too late is tried again.
  const struct
  {
    const char* change;
    const char* message;
  } cases[] = {{"truncated", "the file changed while it was being read (truncated)"},
               {"appended", "the file changed while it was being read (it had "}};
  for(const auto& c : cases)
  {
    INFO(c.change);
    bool hit = false;
    for(int attempt = 0; attempt < 8 && !hit; ++attempt)
    {
      fs::copy_file(original, input, fs::copy_options::overwrite_existing);
      Child_run run({input, folder + "/skeleton.ply", "--stage", "voxels"});
      REQUIRE(run.wait_for("read..."));
      if(std::string(c.change) == "truncated")
        fs::resize_file(input, size / 3);
      else
        std::ofstream(input, std::ios::app) << "1 2 3\n";
      const int status = run.wait();
      INFO(run.err());
      hit = status == 1 && run.err().find(input + ": " + c.message) != std::string::npos;
      if(status != 0)
        CHECK(entries(folder) == std::vector<std::string>{"input.xyz"});
      fs::remove(folder + "/skeleton.ply");
    }
    if(!hit)
      WARN("skipped: the change of the input never came while the tool read it");
  }
}
