// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_quality: runs the library with its defaults on the procedural corpus
// (tools/evaluation/shape_corpus.h) under every degradation and on the real scans of
// ../shared/data, and writes the rows (TSV), previews (SVG) and the Markdown report.
// scripts/quality.sh runs it; see its header for the options.

#include "quality_table.h"
#include "evaluation/scan_variants.h"
#include "evaluation/shape_corpus.h"
#include "evaluation/skeleton_quality.h"

#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_svg_preview.h>
#include <CGAL/bounding_box.h>

#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace DF = CGAL::DF_L1;
using DF_L1_quality::Row;

struct Options
{
  std::string out_dir = "quality_out";
  std::vector<std::string> families = DF_L1_test::corpus_families();
  std::vector<std::string> degradations;
  int shapes = DF_L1_test::corpus_shapes_per_family;
  int first = 0;
  std::size_t points = 20000;
  int jobs = 2;
  int resolution = 100; // voxel_resolution of every run
  std::string previews = "failures"; // failures, all, none
  std::string scans_dir;
  std::string scan_filter;
  std::vector<std::string> scan_variants; // degradations of every scan besides the scan itself
  bool corpus = true;
  std::string results, previous, markdown, label, command = "scripts/quality.sh";
  std::string scan_sheet, failure_sheet;
  bool list = false;
  bool quiet = false;
};

std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, ','))
    if(!item.empty())
      out.push_back(item);
  return out;
}

void usage(std::ostream& os)
{
  os << "usage: df_l1_quality [--out DIR] [--families a,b] [--degradations a,b] [--shapes N] [--first K]\n"
        "         [--points N] [--jobs J] [--resolution V] [--previews failures|all|none] [--scans DIR|none] [--scan-filter NAME]\n"
        "         [--scan-variants a,b|none]\n"
        "         [--no-corpus] [--results FILE.tsv] [--previous FILE.tsv] [--markdown FILE.md] [--label TEXT]\n"
        "         [--command TEXT] [--scan-sheet PATH] [--failure-sheet PATH] [--list] [--quiet]\n";
}

/// The designed skeleton of a corpus shape as a graph, for the previews: its axis
/// curves, sampled every voxel, joined where they meet (so its ends are the designed tips).
DF::Skeleton_graph<K> designed_skeleton(const DF_L1_test::Shape& shape, double voxel)
{
  DF::Skeleton_graph<K> g;
  std::vector<std::pair<Point, std::size_t>> nodes; // curve ends already in g
  const double tolerance = 1e-6 * shape.bbox_diagonal();
  auto vertex_at = [&](const Point& p, double radius) {
    for(const auto& n : nodes)
      if(CGAL::squared_distance(n.first, p) <= tolerance * tolerance)
        return n.second;
    const std::size_t v = boost::add_vertex(g);
    g[v].point = p;
    g[v].radius = radius;
    nodes.emplace_back(p, v);
    return v;
  };
  for(const DF_L1_test::Skeleton_polyline& curve : shape.skeleton_polylines(voxel)) {
    const std::size_t n = curve.points.size();
    if(n < 2)
      continue;
    std::size_t previous = vertex_at(curve.points.front(), curve.radii.front());
    for(std::size_t i = 1; i < n; ++i) {
      std::size_t v;
      if(i + 1 == n)
        v = vertex_at(curve.points.back(), curve.radii.back());
      else {
        v = boost::add_vertex(g);
        g[v].point = curve.points[i];
        g[v].radius = curve.radii[i];
      }
      if(v != previous)
        boost::add_edge(previous, v, g);
      previous = v;
    }
  }
  return g;
}

/// The input points and the skeleton of a case, drawn for a human to look at; with
/// `designed`, a row of the designed skeleton first.
void write_preview(const std::string& path, const std::vector<Point>& points, const std::string& title,
                   CGAL::DF_L1_skeletonization<K, CGAL::Sequential_tag>& s,
                   const DF::Skeleton_graph<K>* designed = nullptr)
{
  std::vector<DF::Preview_panel<K>> rows;
  if(designed)
    rows.push_back({"designed", designed});
  rows.push_back({"final", &s.skeleton()});
  rows.push_back({"initial", &s.initial_skeleton().graph});
  DF::Preview_options opt;
  opt.title = title;
  DF::write_svg_preview<K>(path, points, rows, opt);
}

std::string counts(const DF_L1_test::Topology& t) { return DF_L1_test::compact(t); }

Row run_corpus_case(const Options& o, const DF_L1_test::Shape& shape, const std::string& family, int index,
                    const DF_L1_test::Degradation& d)
{
  Row row;
  row.kind = "corpus";
  row.name = shape.name();
  row.family = family;
  row.degradation = d.name;
  row.expected = shape.has_sheets() ? "-/-/" + std::to_string(shape.expected_topology().cycles) + "/" +
                                        std::to_string(shape.expected_topology().components)
                                    : counts(shape.expected_topology());
  const DF_L1_test::Sample sample = DF_L1_test::corpus_sample(shape, index, d, o.points);
  row.points = sample.points.size();
  try {
    const auto start = std::chrono::steady_clock::now();
    CGAL::DF_L1_skeletonization<K, CGAL::Sequential_tag> s(sample.points, CGAL::parameters::voxel_resolution(o.resolution));
    const auto& g = s.skeleton();
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    DF_L1_test::Quality_options qo;
    qo.junction_merge_radius_fraction = 1.0;
    qo.merge_within_junction_zones = true;
    const double voxel = CGAL::to_double(s.distance_field().voxel_size);
    const DF_L1_test::Skeleton_quality q = DF_L1_test::measure_quality(shape, g, voxel, qo);
    row.got = counts(q.topology);
    row.initial = counts(DF_L1_test::measure_quality(shape, s.initial_skeleton().graph, voxel, qo).topology);
    std::vector<std::pair<double, bool>> tips;
    for(const DF_L1_test::Tip_recall& t : DF_L1_test::tip_recall(shape, g, voxel))
      tips.emplace_back(t.free_voxels, t.found);
    row.tips = DF_L1_quality::tip_counts(tips);
    row.ok = DF_L1_test::corpus_topology_matches(shape, q.topology, d.noisy);
    row.ratio = q.mean_axis_ratio;
    row.outside = q.outside_fraction;
    row.coverage = q.axis_coverage;
    if(o.previews == "all" || (o.previews == "failures" && !row.ok)) {
      const DF::Skeleton_graph<K> designed = designed_skeleton(shape, voxel);
      write_preview(o.out_dir + "/previews/" + row.name + "__" + d.name + ".svg", sample.points,
                    row.name + " " + d.name + ": got " + row.got + ", expected " + row.expected, s, &designed);
    }
  } catch(const std::exception& e) {
    row.error = e.what();
    row.ok = false;
  }
  return row;
}

// A real scan, or one of its degraded copies (scan_variants.h) when `variant` is not "-".
Row run_scan(const Options& o, const DF_L1_quality::Scan_expectation& e, const std::string& variant)
{
  Row row;
  row.kind = variant == "-" ? "scan" : "scan_variant";
  row.name = e.file;
  row.family = "scan";
  row.degradation = variant;
  row.expected = e.text();
  try {
    auto cloud = DF::read_point_cloud<K>(o.scans_dir + "/" + e.file);
    std::size_t scan_points = cloud.points.size();
    if(variant != "-") {
      std::vector<std::array<double, 3>> xyz;
      for(const Point& p : cloud.points)
        xyz.push_back({p.x(), p.y(), p.z()});
      xyz = DF_L1_test::degrade_scan(xyz, variant, DF_L1_test::scan_seed(e.file), scan_points);
      if(xyz.empty()) {
        row.error = "not applicable";
        row.got = "-";
        row.ok = true;
        return row;
      }
      cloud.points.clear();
      for(const auto& p : xyz)
        cloud.points.emplace_back(p[0], p[1], p[2]);
    }
    row.points = cloud.points.size();
    const auto start = std::chrono::steady_clock::now();
    CGAL::DF_L1_skeletonization<K, CGAL::Sequential_tag> s(cloud.points, CGAL::parameters::voxel_resolution(o.resolution));
    const auto& g = s.skeleton();
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const DF::Skeleton_statistics st = DF::skeleton_statistics(g);
    // Points near the skeleton: within 0.08 d_bb of an edge (or of an isolated vertex).
    std::vector<std::pair<DF_L1_test::internal::V3, DF_L1_test::internal::V3>> segments;
    auto v3 = [](const Point& p) { return DF_L1_test::internal::V3{p.x(), p.y(), p.z()}; };
    for(const auto& edge : CGAL::make_range(boost::edges(g)))
      segments.emplace_back(v3(g[boost::source(edge, g)].point), v3(g[boost::target(edge, g)].point));
    for(std::size_t v = 0; v < boost::num_vertices(g); ++v)
      if(boost::degree(v, g) == 0)
        segments.emplace_back(v3(g[v].point), v3(g[v].point));
    const double reach = 0.08 * s.bbox_diagonal();
    const DF_L1_test::quality_internal::Segment_grid grid(segments, reach);
    const std::vector<bool>& outlier = s.outlier_flags();
    std::size_t kept = 0, near = 0;
    for(std::size_t i = 0; i < scan_points; ++i) { // the added outliers are not the scan's
      if(outlier[i])
        continue;
      ++kept;
      near += grid.distance_within(v3(cloud.points[i]), reach) <= reach;
    }
    row.coverage = kept ? double(near) / double(kept) : 0;
    const auto describe = [](const DF::Skeleton_statistics& t) {
      return "components " + std::to_string(t.components) + ", cycles " + std::to_string(t.cycles) + ", ends " +
             std::to_string(t.end_points);
    };
    row.initial = describe(DF::skeleton_statistics(s.initial_skeleton().graph));
    row.got = describe(st);
    row.ok = int(st.components) == e.components && int(st.cycles) == e.cycles;
    if(e.endpoints >= 0)
      row.ok = row.ok && std::abs(int(st.end_points) - e.endpoints) <= e.endpoint_tolerance;
    if(e.min_points_near >= 0)
      row.ok = row.ok && row.coverage >= e.min_points_near;
    if(o.previews != "none") {
      std::ostringstream title;
      title << e.file << (variant == "-" ? "" : " " + variant) << ": " << row.got << " (expected " << row.expected << "), near " << DF_L1_quality::fixed(row.coverage, 3);
      if(variant == "-")
        write_preview(o.out_dir + "/scans/" + e.file + ".svg", cloud.points, title.str(), s);
      else if(o.previews == "all" || !row.ok)
        write_preview(o.out_dir + "/previews/scan_" + e.file + "__" + variant + ".svg", cloud.points, title.str(), s);
    }
  } catch(const std::exception& ex) {
    row.error = ex.what();
    row.ok = false;
  }
  return row;
}

} // namespace

int main(int argc, char* argv[])
{
  Options o;
  for(const auto& d : DF_L1_test::corpus_degradations())
    o.degradations.push_back(d.name);
  for(const auto& v : DF_L1_test::scan_variants())
    o.scan_variants.push_back(v.name);
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        std::cerr << "df_l1_quality: " << a << " needs a value\n";
        usage(std::cerr);
        std::exit(2);
      }
      return argv[++i];
    };
    if(a == "--out") o.out_dir = value();
    else if(a == "--families") o.families = split(value());
    else if(a == "--degradations") o.degradations = split(value());
    else if(a == "--shapes") o.shapes = std::stoi(value());
    else if(a == "--first") o.first = std::stoi(value());
    else if(a == "--points") o.points = std::size_t(std::stoull(value()));
    else if(a == "--jobs") o.jobs = std::max(1, std::stoi(value()));
    else if(a == "--resolution") o.resolution = std::stoi(value());
    else if(a == "--previews") o.previews = value();
    else if(a == "--scans") o.scans_dir = value();
    else if(a == "--scan-filter") o.scan_filter = value();
    else if(a == "--scan-variants") {
      const std::string v = value();
      o.scan_variants = v == "none" ? std::vector<std::string>() : split(v);
      for(const std::string& name : o.scan_variants)
        if(std::none_of(DF_L1_test::scan_variants().begin(), DF_L1_test::scan_variants().end(),
                        [&](const DF_L1_test::Scan_variant& known) { return known.name == name; })) {
          std::cerr << "df_l1_quality: unknown scan variant " << name << "\n";
          return 2;
        }
    }
    else if(a == "--no-corpus") o.corpus = false;
    else if(a == "--results") o.results = value();
    else if(a == "--previous") o.previous = value();
    else if(a == "--markdown") o.markdown = value();
    else if(a == "--label") o.label = value();
    else if(a == "--command") o.command = value();
    else if(a == "--scan-sheet") o.scan_sheet = value();
    else if(a == "--failure-sheet") o.failure_sheet = value();
    else if(a == "--list") o.list = true;
    else if(a == "--quiet") o.quiet = true;
    else if(a == "--help" || a == "-h") {
      usage(std::cout);
      return 0;
    } else {
      std::cerr << "df_l1_quality: unknown option " << a << "\n";
      usage(std::cerr);
      return 2;
    }
  }
  std::vector<DF_L1_test::Degradation> degradations;
  for(const auto& name : o.degradations) {
    try {
      degradations.push_back(DF_L1_test::corpus_degradation(name));
    } catch(const std::invalid_argument&) {
      std::cerr << "df_l1_quality: unknown degradation " << name << "\n";
      return 2;
    }
  }

  // The shapes, built once.
  struct Case
  {
    std::size_t shape;
    std::size_t degradation;
  };
  std::vector<std::pair<std::string, DF_L1_test::Shape>> shapes;
  std::vector<int> shape_index;
  if(o.corpus)
    for(const std::string& f : o.families)
      for(int i = o.first; i < o.first + o.shapes; ++i) {
        shapes.emplace_back(f, DF_L1_test::corpus_shape(f, i));
        shape_index.push_back(i);
      }
  if(o.list) {
    for(const auto& s : shapes)
      std::cout << s.second.name() << '\t' << DF_L1_test::compact(s.second.expected_topology()) << '\t'
                << (s.second.has_sheets() ? "sheets" : "-") << '\t' << s.second.primitives().size() << " parts\t"
                << "voxel " << DF_L1_test::default_voxel_size(s.second) << '\n';
    return 0;
  }
  std::filesystem::create_directories(o.out_dir + "/previews");
  std::filesystem::create_directories(o.out_dir + "/scans");

  std::vector<Case> cases;
  for(std::size_t d = 0; d < degradations.size(); ++d)
    for(std::size_t s = 0; s < shapes.size(); ++s)
      cases.push_back({s, d});
  std::vector<DF_L1_quality::Scan_expectation> expectations;
  if(!o.scans_dir.empty() && o.scans_dir != "none") {
    try {
      expectations = DF_L1_quality::read_expectations(o.scans_dir + "/expected_topology.json");
    } catch(const std::exception& e) {
      std::cerr << "df_l1_quality: " << e.what() << "\n";
      return 1;
    }
    if(!o.scan_filter.empty())
      expectations.erase(std::remove_if(expectations.begin(), expectations.end(),
                                        [&](const auto& e) { return e.file.find(o.scan_filter) == std::string::npos; }),
                         expectations.end());
    if(expectations.empty())
      std::cerr << "df_l1_quality: no scan expectations in " << o.scans_dir << " (skipped)\n";
  }

  // Jobs run cases side by side, each on one thread (the results do not depend on it).
  // Every scan as it is, then every scan in each variant.
  std::vector<std::string> scan_runs{"-"};
  scan_runs.insert(scan_runs.end(), o.scan_variants.begin(), o.scan_variants.end());
  const std::size_t total = cases.size() + expectations.size() * scan_runs.size();
  std::vector<Row> rows(total);
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex print;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&] {
    tbb::task_arena arena(1);
    arena.execute([&] {
      for(;;) {
        const std::size_t k = next++;
        if(k >= total)
          return;
        Row r;
        if(k < cases.size()) {
          const Case& c = cases[k];
          r = run_corpus_case(o, shapes[c.shape].second, shapes[c.shape].first, shape_index[c.shape], degradations[c.degradation]);
        } else
        {
          const std::size_t j = k - cases.size();
          r = run_scan(o, expectations[j % expectations.size()], scan_runs[j / expectations.size()]);
        }
        rows[k] = r;
        const std::size_t finished = ++done;
        if(!o.quiet) {
          std::lock_guard<std::mutex> lock(print);
          std::cerr << '[' << finished << '/' << total << "] " << r.name << ' ' << r.degradation << ": "
                    << (r.ok ? "ok" : "FAIL") << ' ' << (r.error.empty() ? r.got : r.error) << " (expected " << r.expected
                    << ")\n";
        }
      }
    });
  };
  std::vector<std::thread> threads;
  for(int j = 0; j < o.jobs; ++j)
    threads.emplace_back(worker);
  for(std::thread& t : threads)
    t.join();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::vector<Row> previous = o.previous.empty() ? std::vector<Row>() : DF_L1_quality::read_rows(o.previous);
  if(!o.results.empty())
    DF_L1_quality::write_rows(o.results, rows);
  DF_L1_quality::Report_context ctx;
  ctx.command = o.command;
  ctx.label = o.label;
  ctx.families = o.families;
  ctx.degradations = o.degradations;
  ctx.scan_sheet = o.scan_sheet;
  ctx.failure_sheet = o.failure_sheet;
  const std::string md = DF_L1_quality::markdown_report(rows, previous, ctx);
  if(!o.markdown.empty())
    CGAL::DF_L1::write_file_atomically(o.markdown, [&](std::ostream& out) { out << md; });
  auto corpus = [](const Row& r) { return r.kind == "corpus"; };
  const DF_L1_quality::Summary all = DF_L1_quality::summarize(rows, corpus);
  std::size_t scans_ok = 0;
  for(const Row& r : rows)
    scans_ok += r.kind == "scan" && r.ok;
  std::cout << "corpus: " << all.passes << "/" << all.cases << " designed topology, ratio " << DF_L1_quality::fixed(all.ratio, 3)
            << ", outside " << DF_L1_quality::fixed(all.outside, 4) << ", coverage " << DF_L1_quality::fixed(all.coverage, 3)
            << "; scans: " << scans_ok << "/" << expectations.size() << "; " << DF_L1_quality::fixed(seconds, 1) << " s\n";
  return 0;
}
