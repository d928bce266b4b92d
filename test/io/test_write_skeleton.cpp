// Tests of the output writers, the polyline split, the SVG preview and the
// atomic file writing.

#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/write_svg_preview.h>
#include <CGAL/DF_L1_skeleton/Skeleton_graph.h>
#include <CGAL/DF_L1_skeleton/errors.h>
#include <CGAL/DF_L1_skeleton/IO/write_file_atomically.h>
#include <CGAL/DF_L1_skeleton/split_into_polylines.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Graph = CGAL::DF_L1::Skeleton_graph<K>;
using Polyline = std::vector<std::size_t>;
namespace fs = std::filesystem;

// A fresh empty directory, removed with its content at the end of the test.
class Scratch_dir
{
public:
  Scratch_dir()
  {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("df_l1_write_test_" + std::to_string(CGAL::DF_L1::internal::current_process_id()) +
             "_" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~Scratch_dir()
  {
    std::error_code ec;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

  // Names of all entries, sorted.
  std::vector<std::string> entries() const
  {
    std::vector<std::string> names;
    for(const auto& e : fs::directory_iterator(path_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

private:
  fs::path path_;
};

Graph make_graph(const std::vector<Point>& points,
                 const std::vector<std::pair<std::size_t, std::size_t>>& edges)
{
  Graph g;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const auto v = add_vertex(g);
    g[v].point = points[i];
    g[v].radius = 0.5 + double(i);
  }
  for(const auto& e : edges)
    add_edge(e.first, e.second, g);
  return g;
}

// A graph whose vertex i sits at (i, 0, 0): positions do not matter for the split.
Graph make_topology(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& edges)
{
  std::vector<Point> pts;
  for(std::size_t i = 0; i < n; ++i)
    pts.emplace_back(double(i), 0., 0.);
  return make_graph(pts, edges);
}

std::vector<Polyline> split(const Graph& g)
{
  std::vector<Polyline> out;
  CGAL::DF_L1::split_into_polylines(g, std::back_inserter(out));
  return out;
}

// The checks every split must pass: each edge in exactly one polyline, inner
// vertices of degree 2, open ends of degree != 2, isolated vertices alone.
void check_split_invariants(const Graph& g, const std::vector<Polyline>& polylines)
{
  std::map<std::pair<std::size_t, std::size_t>, int> edge_count;
  for(auto e : boost::make_iterator_range(edges(g))) {
    const std::size_t a = source(e, g), b = target(e, g);
    ++edge_count[{std::min(a, b), std::max(a, b)}];
  }
  std::vector<int> isolated_seen(num_vertices(g), 0);
  for(const Polyline& pl : polylines) {
    REQUIRE(!pl.empty());
    if(pl.size() == 1) {
      CHECK(degree(pl[0], g) == 0);
      ++isolated_seen[pl[0]];
      continue;
    }
    for(std::size_t i = 0; i + 1 < pl.size(); ++i) {
      const std::size_t a = pl[i], b = pl[i + 1];
      --edge_count[{std::min(a, b), std::max(a, b)}];
    }
    for(std::size_t i = 1; i + 1 < pl.size(); ++i)
      CHECK(degree(pl[i], g) == 2);
    if(pl.front() != pl.back()) {
      CHECK(degree(pl.front(), g) != 2);
      CHECK(degree(pl.back(), g) != 2);
    }
  }
  for(const auto& ec : edge_count)
    CHECK(ec.second == 0); // each edge used exactly once
  for(std::size_t v = 0; v < num_vertices(g); ++v)
    CHECK(isolated_seen[v] == (degree(v, g) == 0 ? 1 : 0));
  // Ordered by first vertex.
  for(std::size_t i = 1; i < polylines.size(); ++i)
    CHECK(polylines[i - 1].front() <= polylines[i].front());
}

std::string read_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_text(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
  REQUIRE(out);
}

std::vector<std::string> lines_of(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line))
    lines.push_back(line);
  return lines;
}

std::vector<std::string> tokens_of(const std::string& line)
{
  std::vector<std::string> tokens;
  std::istringstream in(line);
  std::string t;
  while(in >> t)
    tokens.push_back(t);
  return tokens;
}

std::uint64_t bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

double parse_double(const std::string& s)
{
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  REQUIRE(end == s.c_str() + s.size());
  return x;
}

std::size_t count_of(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t pos = text.find(what); pos != std::string::npos;
      pos = text.find(what, pos + what.size()))
    ++n;
  return n;
}

const double not_a_number = std::numeric_limits<double>::quiet_NaN();

} // namespace

// ---------------------------------------------------------------------------
// split_into_polylines

TEST_CASE("split_into_polylines: a path is one polyline from its smaller end", "[io][polylines]")
{
  // 1 - 3 - 0 - 2
  const Graph g = make_topology(4, {{2, 0}, {0, 3}, {3, 1}});
  const auto pls = split(g);
  REQUIRE(pls == std::vector<Polyline>{{1, 3, 0, 2}});
  check_split_invariants(g, pls);
}

TEST_CASE("split_into_polylines: a Y gives three chains from the junction", "[io][polylines]")
{
  const Graph g = make_topology(6, {{0, 1}, {1, 2}, {0, 3}, {3, 4}, {5, 0}});
  const auto pls = split(g);
  REQUIRE(pls == std::vector<Polyline>{{0, 1, 2}, {0, 3, 4}, {0, 5}});
  check_split_invariants(g, pls);
}

TEST_CASE("split_into_polylines: a pure cycle is one closed polyline", "[io][polylines]")
{
  const Graph g = make_topology(4, {{2, 3}, {0, 1}, {3, 0}, {1, 2}});
  const auto pls = split(g);
  REQUIRE(pls == std::vector<Polyline>{{0, 1, 2, 3, 0}});
  check_split_invariants(g, pls);
}

TEST_CASE("split_into_polylines: a cycle with a tail", "[io][polylines]")
{
  // Triangle 0-1-2 and tail 2-3-4: the loop through junction 2 is closed.
  const Graph g = make_topology(5, {{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 4}});
  const auto pls = split(g);
  REQUIRE(pls == std::vector<Polyline>{{2, 0, 1, 2}, {2, 3, 4}});
  check_split_invariants(g, pls);
}

TEST_CASE("split_into_polylines: components, isolated vertices, cycles are ordered by first vertex",
          "[io][polylines]")
{
  // Isolated 0 and 6, cycle 3-5-7, path 1-2-4.
  const Graph g = make_topology(8, {{1, 2}, {2, 4}, {3, 5}, {5, 7}, {7, 3}});
  const auto pls = split(g);
  REQUIRE(pls == std::vector<Polyline>{{0}, {1, 2, 4}, {3, 5, 7, 3}, {6}});
  check_split_invariants(g, pls);
}

TEST_CASE("split_into_polylines: self-loops and parallel edges", "[io][polylines]")
{
  SECTION("self-loop at a junction")
  {
    const Graph g = make_topology(3, {{0, 1}, {1, 1}, {1, 2}});
    const auto pls = split(g);
    REQUIRE(pls == std::vector<Polyline>{{0, 1}, {1, 1}, {1, 2}});
    check_split_invariants(g, pls);
  }
  SECTION("a lone vertex with a self-loop is a closed polyline")
  {
    const Graph g = make_topology(1, {{0, 0}});
    REQUIRE(split(g) == std::vector<Polyline>{{0, 0}});
  }
  SECTION("two parallel edges form a 2-cycle")
  {
    const Graph g = make_topology(2, {{0, 1}, {1, 0}});
    const auto pls = split(g);
    REQUIRE(pls == std::vector<Polyline>{{0, 1, 0}});
    check_split_invariants(g, pls);
  }
  SECTION("a theta graph: three chains between two junctions")
  {
    const Graph g = make_topology(5, {{0, 2}, {2, 1}, {0, 3}, {3, 1}, {0, 4}, {4, 1}});
    const auto pls = split(g);
    REQUIRE(pls == std::vector<Polyline>{{0, 2, 1}, {0, 3, 1}, {0, 4, 1}});
    check_split_invariants(g, pls);
  }
}

TEST_CASE("split_into_polylines: invariants on random graphs", "[io][polylines]")
{
  std::mt19937 rng(12345);
  for(int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 1 + rng() % 30;
    std::vector<std::pair<std::size_t, std::size_t>> es;
    const std::size_t m = rng() % (2 * n);
    // Mostly chains so that degree-2 runs and cycles are common.
    for(std::size_t i = 0; i < m; ++i) {
      const std::size_t a = rng() % n;
      const std::size_t b = (rng() % 4 == 0) ? rng() % n : (a + 1) % n;
      es.emplace_back(a, b);
    }
    const Graph g = make_topology(n, es);
    INFO("trial " << trial);
    const auto pls = split(g);
    check_split_invariants(g, pls);
    REQUIRE(split(g) == pls); // deterministic
    // Canonical: the same graph with its edges stored in another order, some of
    // them reversed, splits the same way.
    std::shuffle(es.begin(), es.end(), rng);
    for(auto& e : es)
      if(rng() % 2 == 0)
        std::swap(e.first, e.second);
    REQUIRE(split(make_topology(n, es)) == pls);
  }
}

TEST_CASE("skeleton_polylines returns the vertex positions", "[io][polylines]")
{
  const Graph g = make_graph({Point(0, 0, 0), Point(1, 0, 0), Point(1, 2, 0)}, {{0, 1}, {1, 2}, {2, 0}});
  const std::vector<std::vector<Point>> pls = CGAL::DF_L1::skeleton_polylines(g);
  REQUIRE(pls.size() == 1);
  REQUIRE(pls[0] == std::vector<Point>{Point(0, 0, 0), Point(1, 0, 0), Point(1, 2, 0), Point(0, 0, 0)});
}

// ---------------------------------------------------------------------------
// Skeleton writers: content

TEST_CASE("write_skeleton_obj writes vertices, 1-based lines and the header", "[io][write]")
{
  Scratch_dir dir;
  const Graph g = make_graph({Point(0, 0, 0), Point(1.5, -2, 3.25), Point(0.1, 1e-300, -7)},
                             {{0, 1}, {1, 2}});
  const std::string path = dir.file("s.obj");
  CGAL::DF_L1::write_skeleton_obj(path, g);
  REQUIRE(lines_of(read_file(path)) ==
          std::vector<std::string>{"# DF_L1_skeleton: 3 vertices, 2 edges", "v 0 0 0",
                                   "v 1.5 -2 3.25", "v 0.1 1e-300 -7", "l 1 2", "l 2 3"});
  REQUIRE(dir.entries() == std::vector<std::string>{"s.obj"});
}

TEST_CASE("write_skeleton_ply writes an ASCII PLY with vertex and edge elements", "[io][write]")
{
  Scratch_dir dir;
  const Graph g = make_graph({Point(0, 0, 0), Point(1, 2, 3), Point(-1, 0.5, 2)}, {{0, 1}, {0, 2}});
  const std::string path = dir.file("s.ply");
  CGAL::DF_L1::write_skeleton_ply(path, g);
  const auto lines = lines_of(read_file(path));
  const std::vector<std::string> expected{
      "ply", "format ascii 1.0", "comment written by DF_L1_skeleton", "element vertex 3",
      "property double x", "property double y", "property double z", "property double radius",
      "element edge 2", "property int vertex1", "property int vertex2", "end_header",
      "0 0 0 0.5", "1 2 3 1.5", "-1 0.5 2 2.5", "0 1", "0 2"};
  REQUIRE(lines == expected);
}

TEST_CASE("write_skeleton_ply of an empty skeleton", "[io][write]")
{
  Scratch_dir dir;
  const std::string path = dir.file("empty.ply");
  CGAL::DF_L1::write_skeleton_ply(path, Graph());
  const std::string text = read_file(path);
  CHECK(text.find("element vertex 0\n") != std::string::npos);
  CHECK(text.find("element edge 0\n") != std::string::npos);
  CHECK(text.substr(text.size() - 11) == "end_header\n");
}

TEST_CASE("write_skeleton_polylines writes one line per polyline", "[io][write]")
{
  Scratch_dir dir;
  // Y with center 0, a separate triangle 4-5-6, an isolated vertex 7.
  const Graph g = make_graph({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
                              Point(5, 5, 5), Point(6, 5, 5), Point(5, 6, 5), Point(9, 9, 9)},
                             {{0, 1}, {0, 2}, {0, 3}, {4, 5}, {5, 6}, {6, 4}});
  const std::string path = dir.file("s.polylines.txt");
  CGAL::DF_L1::write_skeleton_polylines(path, g);
  REQUIRE(lines_of(read_file(path)) ==
          std::vector<std::string>{"2 0 0 0 1 0 0", "2 0 0 0 0 1 0", "2 0 0 0 0 0 1",
                                   "4 5 5 5 6 5 5 5 6 5 5 5 5", "1 9 9 9"});
}

TEST_CASE("written numbers read back exactly", "[io][write]")
{
  Scratch_dir dir;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(-1000., 1000.);
  std::vector<Point> pts{Point(0.1, 1. / 3., -2. / 3.), Point(1e-310, -1e308, 123456789.123456789),
                         Point(std::nextafter(1., 2.), std::nextafter(0., 1.), -0.)};
  for(int i = 0; i < 300; ++i)
    pts.emplace_back(uni(rng), uni(rng) * 1e-9, std::ldexp(uni(rng), int(rng() % 200) - 100));
  std::vector<std::pair<std::size_t, std::size_t>> es;
  for(std::size_t i = 0; i + 1 < pts.size(); ++i)
    es.emplace_back(i, i + 1);
  Graph g = make_graph(pts, es);
  for(std::size_t i = 0; i < pts.size(); ++i)
    g[i].radius = uni(rng) / 7.;

  auto check_xyz = [&](const std::vector<std::string>& t, std::size_t first, std::size_t v) {
    CHECK(bits(parse_double(t[first])) == bits(pts[v].x()));
    CHECK(bits(parse_double(t[first + 1])) == bits(pts[v].y()));
    CHECK(bits(parse_double(t[first + 2])) == bits(pts[v].z()));
  };

  SECTION("obj")
  {
    const std::string path = dir.file("r.obj");
    CGAL::DF_L1::write_skeleton_obj(path, g);
    const auto lines = lines_of(read_file(path));
    REQUIRE(lines.size() == 1 + pts.size() + es.size());
    for(std::size_t v = 0; v < pts.size(); ++v) {
      const auto t = tokens_of(lines[1 + v]);
      REQUIRE(t.size() == 4);
      REQUIRE(t[0] == "v");
      check_xyz(t, 1, v);
    }
  }
  SECTION("ply")
  {
    const std::string path = dir.file("r.ply");
    CGAL::DF_L1::write_skeleton_ply(path, g);
    const auto lines = lines_of(read_file(path));
    const std::size_t body = 12;
    REQUIRE(lines[body - 1] == "end_header");
    for(std::size_t v = 0; v < pts.size(); ++v) {
      const auto t = tokens_of(lines[body + v]);
      REQUIRE(t.size() == 4);
      check_xyz(t, 0, v);
      CHECK(bits(parse_double(t[3])) == bits(double(g[v].radius)));
    }
  }
  SECTION("polylines")
  {
    const std::string path = dir.file("r.polylines.txt");
    CGAL::DF_L1::write_skeleton_polylines(path, g);
    const auto lines = lines_of(read_file(path));
    REQUIRE(lines.size() == 1);
    const auto t = tokens_of(lines[0]);
    REQUIRE(t[0] == std::to_string(pts.size()));
    REQUIRE(t.size() == 1 + 3 * pts.size());
    for(std::size_t v = 0; v < pts.size(); ++v)
      check_xyz(t, 1 + 3 * v, v);
  }
}

TEST_CASE("write_skeleton dispatches on the extension", "[io][write]")
{
  Scratch_dir dir;
  const Graph g = make_topology(3, {{0, 1}, {1, 2}});

  CGAL::DF_L1::write_skeleton(dir.file("a.obj"), g);
  CHECK(read_file(dir.file("a.obj")).rfind("# DF_L1_skeleton: 3 vertices, 2 edges\n", 0) == 0);
  CGAL::DF_L1::write_skeleton(dir.file("b.PLY"), g);
  CHECK(read_file(dir.file("b.PLY")).rfind("ply\n", 0) == 0);
  CGAL::DF_L1::write_skeleton(dir.file("c.polylines.txt"), g);
  CHECK(read_file(dir.file("c.polylines.txt")) == "3 0 0 0 1 0 0 2 0 0\n");

  for(const char* bad : {"d.txt", "e.xyz", "f", "g.obj.bak", "h.off"}) {
    INFO(bad);
    CHECK_THROWS_AS(CGAL::DF_L1::write_skeleton(dir.file(bad), g), CGAL::DF_L1::Write_error);
    CHECK_THROWS_WITH(CGAL::DF_L1::write_skeleton(dir.file(bad), g),
                      Catch::Contains("unsupported output extension") && Catch::Contains(bad));
  }
  CHECK(dir.entries() == std::vector<std::string>{"a.obj", "b.PLY", "c.polylines.txt"});
}

// ---------------------------------------------------------------------------
// Atomic behaviour

TEST_CASE("writing into a missing directory throws and creates nothing", "[io][write][atomic]")
{
  Scratch_dir dir;
  const Graph g = make_topology(2, {{0, 1}});
  const std::string path = (dir.path() / "no_such_dir" / "s.obj").string();
  CHECK_THROWS_AS(CGAL::DF_L1::write_skeleton_obj(path, g), CGAL::DF_L1::Write_error);
  CHECK_THROWS_WITH(CGAL::DF_L1::write_skeleton_obj(path, g),
                    Catch::Contains(path) && Catch::Contains("does not exist"));
  CHECK_THROWS_AS(CGAL::DF_L1::write_skeleton_ply(path, g), CGAL::DF_L1::Write_error);
  CHECK_THROWS_AS(CGAL::DF_L1::write_svg_preview(path, std::vector<Point>{Point(0, 0, 0)}),
                  CGAL::DF_L1::Write_error);
  CHECK(dir.entries().empty());
}

TEST_CASE("a destination that is a directory is refused", "[io][write][atomic]")
{
  Scratch_dir dir;
  fs::create_directory(dir.path() / "d.obj");
  CHECK_THROWS_AS(CGAL::DF_L1::write_skeleton_obj(dir.file("d.obj"), make_topology(1, {})),
                  CGAL::DF_L1::Write_error);
  CHECK(dir.entries() == std::vector<std::string>{"d.obj"});
  CHECK_THROWS_AS(CGAL::DF_L1::write_skeleton_obj("", make_topology(1, {})),
                  CGAL::DF_L1::Write_error);
}

TEST_CASE("a non-finite coordinate leaves the existing destination untouched", "[io][write][atomic]")
{
  Scratch_dir dir;
  const Graph bad = make_graph({Point(0, 0, 0), Point(1, not_a_number, 0)}, {{0, 1}});
  Graph bad_radius = make_topology(2, {{0, 1}});
  bad_radius[1].radius = std::numeric_limits<double>::infinity();

  for(const std::string name : {"s.obj", "s.ply", "s.polylines.txt", "s.svg"}) {
    INFO(name);
    const std::string path = dir.file(name);
    write_text(path, "old content\n");
    if(name == "s.svg") {
      std::vector<CGAL::DF_L1::Preview_panel<K>> rows{{"bad", &bad}};
      CHECK_THROWS_AS(CGAL::DF_L1::write_svg_preview(path, std::vector<Point>{}, rows),
                      CGAL::DF_L1::Write_error);
      CHECK_THROWS_AS(CGAL::DF_L1::write_svg_preview(path, std::vector<Point>{Point(not_a_number, 0, 0)}),
                      CGAL::DF_L1::Write_error);
    } else {
      CHECK_THROWS_AS(CGAL::DF_L1::write_skeleton(path, bad), CGAL::DF_L1::Write_error);
      CHECK_THROWS_WITH(CGAL::DF_L1::write_skeleton(path, bad),
                        Catch::Contains("non-finite") && Catch::Contains("vertex 1"));
    }
    CHECK(read_file(path) == "old content\n");
  }
  // The radius is only written to PLY.
  const std::string ply = dir.file("s.ply");
  CHECK_THROWS_WITH(CGAL::DF_L1::write_skeleton_ply(ply, bad_radius), Catch::Contains("radius"));
  CHECK(read_file(ply) == "old content\n");
  CHECK_NOTHROW(CGAL::DF_L1::write_skeleton_obj(dir.file("s.obj"), bad_radius));

  CHECK(dir.entries() == std::vector<std::string>{"s.obj", "s.ply", "s.polylines.txt", "s.svg"});
}

TEST_CASE("write_file_atomically replaces whole files and cleans up", "[io][write][atomic]")
{
  Scratch_dir dir;
  const std::string path = dir.file("f.txt");
  using CGAL::DF_L1::write_file_atomically;

  SECTION("replaces an existing file and leaves no temporary")
  {
    write_text(path, "old\n");
    write_file_atomically(path, [](std::ostream& os) { os << "new " << 1.5 << '\n'; });
    CHECK(read_file(path) == "new 1.5\n");
    CHECK(dir.entries() == std::vector<std::string>{"f.txt"});
  }
  SECTION("an exception from the content writer propagates and changes nothing")
  {
    write_text(path, "old\n");
    CHECK_THROWS_AS(write_file_atomically(path,
                                          [](std::ostream& os) {
                                            os << "partial";
                                            throw std::logic_error("boom");
                                          }),
                    std::logic_error);
    CHECK(read_file(path) == "old\n");
    CHECK(dir.entries() == std::vector<std::string>{"f.txt"});
  }
  SECTION("a failing stream is reported and changes nothing")
  {
    write_text(path, "old\n");
    CHECK_THROWS_AS(
        write_file_atomically(path, [](std::ostream& os) { os.setstate(std::ios::badbit); }),
        CGAL::DF_L1::Write_error);
    CHECK(read_file(path) == "old\n");
    CHECK(dir.entries() == std::vector<std::string>{"f.txt"});
  }
  SECTION("a new file in a new place")
  {
    write_file_atomically(path, [](std::ostream& os) { os << "x"; }, true);
    CHECK(read_file(path) == "x");
    CHECK(dir.entries() == std::vector<std::string>{"f.txt"});
  }
}

#ifndef _WIN32
TEST_CASE("permission denied is reported", "[io][write][atomic]")
{
  Scratch_dir dir;
  const fs::path ro = dir.path() / "ro";
  fs::create_directory(ro);
  fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec, fs::perm_options::replace);
  {
    // Root ignores directory permissions: nothing to test then.
    std::ofstream probe(ro / "probe");
    if(probe) {
      probe.close();
      fs::remove(ro / "probe");
      fs::permissions(ro, fs::perms::owner_all, fs::perm_options::replace);
      WARN("directory permissions are not enforced (running as root?): test skipped");
      return;
    }
  }
  const std::string path = (ro / "s.obj").string();
  CHECK_THROWS_WITH(CGAL::DF_L1::write_skeleton_obj(path, make_topology(2, {{0, 1}})),
                    Catch::Contains(path) && Catch::Contains("ermission denied"));
  fs::permissions(ro, fs::perms::owner_all, fs::perm_options::replace);
  CHECK(fs::is_empty(ro));
}

TEST_CASE("writing through a symbolic link replaces its target", "[io][write][atomic]")
{
  Scratch_dir dir;
  write_text(dir.file("target.obj"), "old\n");
  fs::create_symlink("target.obj", dir.path() / "link.obj");
  CGAL::DF_L1::write_skeleton_obj(dir.file("link.obj"), make_topology(1, {}));
  CHECK(fs::is_symlink(dir.path() / "link.obj"));
  CHECK(read_file(dir.file("target.obj")).rfind("# DF_L1_skeleton: 1 vertices", 0) == 0);
  CHECK(dir.entries() == std::vector<std::string>{"link.obj", "target.obj"});
}
#endif

// ---------------------------------------------------------------------------
// write_point_ply

TEST_CASE("write_point_ply writes named int and double properties", "[io][write]")
{
  Scratch_dir dir;
  const std::vector<Point> pts{Point(0, 0, 0), Point(0.5, 1, -1), Point(1e-3, 2, 3)};
  const std::string path = dir.file("v.ply");
  CGAL::DF_L1::write_point_ply(path, pts,
                               {{"label", true, {0, -1, 42}}, {"distance", false, {0.25, 1. / 3., 7}}});
  REQUIRE(lines_of(read_file(path)) ==
          std::vector<std::string>{"ply", "format ascii 1.0", "comment written by DF_L1_skeleton",
                                   "element vertex 3", "property double x", "property double y",
                                   "property double z", "property int label",
                                   "property double distance", "end_header", "0 0 0 0 0.25",
                                   "0.5 1 -1 -1 0.3333333333333333", "0.001 2 3 42 7"});

  SECTION("pair overload writes doubles")
  {
    const std::vector<std::pair<std::string, std::vector<double>>> props{{"d", {1, 2, 3.5}}};
    CGAL::DF_L1::write_point_ply(path, pts, props);
    const auto lines = lines_of(read_file(path));
    CHECK(lines[7] == "property double d");
    CHECK(lines.back() == "0.001 2 3 3.5");
  }
  SECTION("no properties")
  {
    CGAL::DF_L1::write_point_ply(path, pts);
    CHECK(lines_of(read_file(path)).back() == "0.001 2 3");
  }
  SECTION("invalid properties are refused before writing")
  {
    using P = CGAL::DF_L1::Ply_point_property;
    const std::string before = read_file(path);
    const std::vector<std::pair<std::vector<P>, std::string>> bad{
        {{P{"label", true, {0, 1}}}, "2 values for 3 points"},
        {{P{"label", true, {0, 1.5, 2}}}, "not an integer"},
        {{P{"label", true, {0, 1e10, 2}}}, "not an integer"},
        {{P{"distance", false, {0, not_a_number, 2}}}, "not finite"},
        {{P{"x", false, {0, 1, 2}}}, "used twice"},
        {{P{"a", false, {0, 1, 2}}, P{"a", true, {0, 1, 2}}}, "used twice"},
        {{P{"my label", true, {0, 1, 2}}}, "white space"},
        {{P{"", true, {0, 1, 2}}}, "empty name"}};
    for(const auto& b : bad) {
      INFO(b.second);
      CHECK_THROWS_WITH(CGAL::DF_L1::write_point_ply(path, pts, b.first), Catch::Contains(b.second));
    }
    const std::vector<Point> nan_pts{Point(0, 0, not_a_number)};
    CHECK_THROWS_AS(CGAL::DF_L1::write_point_ply(path, nan_pts), CGAL::DF_L1::Write_error);
    CHECK(read_file(path) == before);
    CHECK(dir.entries() == std::vector<std::string>{"v.ply"});
  }
}

// ---------------------------------------------------------------------------
// SVG preview

namespace {

// Points on three cylinders along the arms of a Y, and the Y skeleton.
std::vector<Point> cylinder_points(std::size_t n)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0., 1.);
  const double pi = std::acos(-1.);
  const std::array<std::array<double, 3>, 3> dirs{
      {{{0., 0., -1.}}, {{0.8, 0., 0.6}}, {{-0.8, 0.3, 0.52}}}};
  std::vector<Point> pts;
  for(std::size_t i = 0; i < n; ++i) {
    const auto& d = dirs[i % 3];
    // An orthonormal frame around d.
    std::array<double, 3> a{{d[1] * 0. - d[2] * 1., d[2] * 0. - d[0] * 0., d[0] * 1. - d[1] * 0.}};
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for(double& c : a) c /= la;
    const std::array<double, 3> b{{d[1] * a[2] - d[2] * a[1], d[2] * a[0] - d[0] * a[2],
                                   d[0] * a[1] - d[1] * a[0]}};
    const double t = 2. * u(rng), phi = 2. * pi * u(rng), r = 0.3;
    pts.emplace_back(t * d[0] + r * (std::cos(phi) * a[0] + std::sin(phi) * b[0]),
                     t * d[1] + r * (std::cos(phi) * a[1] + std::sin(phi) * b[1]),
                     t * d[2] + r * (std::cos(phi) * a[2] + std::sin(phi) * b[2]));
  }
  return pts;
}

Graph y_skeleton()
{
  return make_graph({Point(0, 0, 0), Point(0, 0, -1), Point(0, 0, -2), Point(0.8, 0, 0.6),
                     Point(1.6, 0, 1.2), Point(-0.8, 0.3, 0.52), Point(-1.6, 0.6, 1.04)},
                    {{0, 1}, {1, 2}, {0, 3}, {3, 4}, {0, 5}, {5, 6}});
}

bool has_rsvg_convert()
{
#ifdef _WIN32
  return false;
#else
  return std::system("command -v rsvg-convert >/dev/null 2>&1") == 0;
#endif
}

} // namespace

TEST_CASE("write_svg_preview writes a labelled three-view picture", "[io][svg]")
{
  Scratch_dir dir;
  const std::vector<Point> pts = cylinder_points(20000);
  const Graph y = y_skeleton();
  Graph y_short = y;
  remove_edge(5, 6, y_short);

  const std::string path = dir.file("preview.svg");
  std::vector<CGAL::DF_L1::Preview_panel<K>> rows{{"initial <skeleton> & more", &y},
                                                  {"final", &y_short}};
  CGAL::DF_L1::Preview_options opt;
  opt.title = "three cylinders";
  CGAL::DF_L1::write_svg_preview(path, pts, rows, opt);

  const std::string svg = read_file(path);
  CHECK(svg.rfind("<svg", 0) == 0);
  CHECK(svg.size() >= 7);
  CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
  CHECK(svg.size() < 2000000);
  CHECK(count_of(svg, "class=\"view-label\"") == 6);
  CHECK(count_of(svg, ">front (x right, z up)<") == 2);
  CHECK(count_of(svg, ">side (y right, z up)<") == 2);
  CHECK(count_of(svg, ">top (x right, y up)<") == 2);
  CHECK(svg.find("initial &lt;skeleton&gt; &amp; more") != std::string::npos);
  CHECK(svg.find("7 vertices, 6 edges") != std::string::npos);
  CHECK(svg.find("7 vertices, 5 edges") != std::string::npos);
  CHECK(svg.find("6000 of 20000 points shown") != std::string::npos);
  CHECK(svg.find("nan") == std::string::npos);
  // 6000 dots per view: each dot is one "M x y" subpath of a point path.
  CHECK(count_of(svg, "h0") == 6000 * 3 * 2);
  CHECK(dir.entries() == std::vector<std::string>{"preview.svg"});

  SECTION("deterministic")
  {
    CGAL::DF_L1::write_svg_preview(dir.file("again.svg"), pts, rows, opt);
    CHECK(read_file(dir.file("again.svg")) == svg);
  }
  SECTION("renders with rsvg-convert")
  {
    if(!has_rsvg_convert()) {
      WARN("rsvg-convert not found: rendering not checked");
      return;
    }
    const std::string png = dir.file("preview.png");
    const std::string cmd = "rsvg-convert -o '" + png + "' '" + path + "' 2>'" +
                            dir.file("rsvg.err") + "'";
    INFO(cmd);
    REQUIRE(std::system(cmd.c_str()) == 0);
    const std::string data = read_file(png);
    REQUIRE(data.size() > 1000);
    CHECK(data.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  }
}

TEST_CASE("write_svg_preview without skeleton rows", "[io][svg]")
{
  Scratch_dir dir;
  const std::vector<Point> pts = cylinder_points(500);

  SECTION("points-only overload")
  {
    CGAL::DF_L1::write_svg_preview(dir.file("p.svg"), pts);
    const std::string svg = read_file(dir.file("p.svg"));
    CHECK(svg.rfind("<svg", 0) == 0);
    CHECK(count_of(svg, "class=\"view-label\"") == 3);
    CHECK(count_of(svg, "h0") == 500 * 3);
    CHECK(svg.find("<circle") == std::string::npos);
  }
  SECTION("empty rows")
  {
    CGAL::DF_L1::write_svg_preview(dir.file("p.svg"), pts,
                                   std::vector<CGAL::DF_L1::Preview_panel<K>>());
    CHECK(count_of(read_file(dir.file("p.svg")), "class=\"view-label\"") == 3);
  }
  SECTION("a row without skeleton, and degenerate inputs")
  {
    std::vector<CGAL::DF_L1::Preview_panel<K>> rows{{"just points", nullptr}};
    CGAL::DF_L1::write_svg_preview(dir.file("p.svg"), pts, rows);
    CHECK(read_file(dir.file("p.svg")).find("just points") != std::string::npos);
    // No points at all, a single point, a flat point set.
    CGAL::DF_L1::write_svg_preview(dir.file("e.svg"), std::vector<Point>{});
    CGAL::DF_L1::write_svg_preview(dir.file("o.svg"), std::vector<Point>{Point(1, 2, 3)});
    CGAL::DF_L1::write_svg_preview(dir.file("f.svg"),
                                   std::vector<Point>{Point(0, 0, 0), Point(1, 1, 0), Point(2, 0, 0)});
    for(const char* f : {"e.svg", "o.svg", "f.svg"}) {
      const std::string svg = read_file(dir.file(f));
      CHECK(svg.rfind("<svg", 0) == 0);
      CHECK(svg.find("nan") == std::string::npos);
      CHECK(count_of(svg, "class=\"view-label\"") == 3);
    }
  }
}

TEST_CASE("write_file_atomically: remove_unfinished_files() removes the file being written", "[io][write][atomic][faults]")
{
  Scratch_dir dir;
  const std::string path = dir.file("f.txt");
  using CGAL::DF_L1::write_file_atomically;
  // What a signal handler sees in the middle of a write: the temporary file, registered.
  std::vector<std::string> during;
  CHECK_THROWS_WITH(write_file_atomically(path,
                                          [&](std::ostream& os) {
                                            os << "partial" << std::flush;
                                            during = dir.entries();
                                            CHECK(CGAL::DF_L1::remove_unfinished_files());
                                          }),
                    Catch::Contains("f.txt"));
  REQUIRE(during.size() == 1);
  CHECK(during[0].rfind(".f.txt.tmp.", 0) == 0);
  CHECK(dir.entries().empty());
  // Once the file is complete, nothing is registered any more.
  write_file_atomically(path, [](std::ostream& os) { os << "whole\n"; });
  CHECK(CGAL::DF_L1::remove_unfinished_files());
  CHECK(read_file(path) == "whole\n");
}

TEST_CASE("Atomic_file_group: the files of a group appear together at its commit", "[io][write][atomic][faults]")
{
  Scratch_dir dir;
  using CGAL::DF_L1::write_file_atomically;
  const std::string a = dir.file("a.txt"), b = dir.file("b.txt");
  SECTION("commit renames them all")
  {
    write_text(a, "old a\n");
    CGAL::DF_L1::Atomic_file_group group;
    write_file_atomically(a, [](std::ostream& os) { os << "new a\n"; });
    write_file_atomically(b, [](std::ostream& os) { os << "new b\n"; });
    CHECK(group.size() == 2);
    CHECK(read_file(a) == "old a\n");
    CHECK_FALSE(fs::exists(b));
    CHECK(dir.entries().size() == 3); // a.txt and two temporary files
    group.commit();
    CHECK(group.size() == 0);
    CHECK(read_file(a) == "new a\n");
    CHECK(read_file(b) == "new b\n");
    CHECK(dir.entries() == std::vector<std::string>{"a.txt", "b.txt"});
  }
  SECTION("a group left without commit (an exception) changes nothing")
  {
    write_text(a, "old a\n");
    CHECK_THROWS_AS(([&] {
                      CGAL::DF_L1::Atomic_file_group group;
                      write_file_atomically(a, [](std::ostream& os) { os << "new a\n"; });
                      write_file_atomically(b, [](std::ostream&) { throw std::runtime_error("boom"); });
                      group.commit();
                    }()),
                    std::runtime_error);
    CHECK(read_file(a) == "old a\n");
    CHECK(dir.entries() == std::vector<std::string>{"a.txt"});
  }
  SECTION("a signal handler removes the files waiting for the commit")
  {
    CGAL::DF_L1::Atomic_file_group group;
    write_file_atomically(a, [](std::ostream& os) { os << "new a\n"; });
    write_file_atomically(b, [](std::ostream& os) { os << "new b\n"; });
    CHECK(CGAL::DF_L1::remove_unfinished_files());
    CHECK(dir.entries().empty());
    CHECK_THROWS_AS(group.commit(), CGAL::DF_L1::Write_error);
    CHECK(dir.entries().empty());
  }
  SECTION("groups do not nest")
  {
    CGAL::DF_L1::Atomic_file_group group;
    CHECK_THROWS_AS(CGAL::DF_L1::Atomic_file_group(), std::logic_error);
  }
}

TEST_CASE("write_file_atomically: a full disk names the file and the reason, and leaves no file", "[io][write][atomic][faults]")
{
  Scratch_dir dir;
  using CGAL::DF_L1::write_file_atomically;
  const auto megabyte = [](std::ostream& os) {
    for(int i = 0; i < 100000; ++i)
      os << "line " << i << '\n';
  };
  // A file-size limit makes write() fail with EFBIG, as a full disk fails with ENOSPC.
  // In a child process, which reports by its exit status: 0 the expected error.
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if(child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};
    int status = 1;
    if(::setrlimit(RLIMIT_FSIZE, &limit) == 0) {
      try {
        write_file_atomically(dir.file("big.txt"), megabyte);
        status = 2;
      } catch(const CGAL::DF_L1::Write_error& e) {
        const std::string what = e.what();
        status = what.find("big.txt") != std::string::npos && what.find("File too large") != std::string::npos ? 0 : 3;
      }
    }
    std::_Exit(status);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(dir.entries().empty());

  // A device is written in place (a rename would replace it): /dev/full is a full disk.
  if(fs::exists("/dev/full") && fs::exists("/dev/null")) {
    const std::string full = dir.file("full.txt");
    fs::create_symlink("/dev/full", full);
    CHECK_THROWS_WITH(write_file_atomically(full, megabyte),
                      Catch::Contains("full.txt") && Catch::Contains("No space left on device"));
    CHECK(fs::is_character_file("/dev/full"));
    CHECK_NOTHROW(write_file_atomically("/dev/null", megabyte));
    CHECK(fs::is_character_file("/dev/null"));
    CHECK(dir.entries() == std::vector<std::string>{"full.txt"});
  }
}
