// The benchmark's result records, report and regression comparison (benchmark/):
// the parts of scripts/bench.sh that compute figures from measurements. The
// measurements themselves are never asserted (no timed tests).
#include "../../benchmark/bench_report.h"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using DF_L1_bench::Record;

namespace {

std::string read_text(const std::string& path)
{
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Record timed(const std::string& label, const std::string& method, double total)
{
  Record r;
  r.set("label", label).set("method", method).set("shape", "stick_figure").set("variant", "clean");
  r.set("points", 35000.0).set("resolution", 100.0).set("samples_requested", 1500.0).set("threads", 2.0);
  r.set("runs", 5.0).set("t.read", 0.01).set("t.contraction", total - 0.01).set("t.total", total);
  r.set("tmin.total", 0.9 * total).set("tmax.total", 1.1 * total).set("peak_mib", 20.0);
  return r;
}

} // namespace

TEST_CASE("benchmark records: a line of key=value fields, read back as written", "[benchmark]")
{
  Record r;
  r.set("label", "points/1000").set("t.total", 0.125).set("label", "points/2000");
  CHECK(r.line() == "label=points/2000\tt.total=0.125");
  const Record back = Record::parse(r.line());
  CHECK(back.text("label") == "points/2000");
  CHECK(back.number("t.total") == 0.125);
  CHECK(std::isnan(back.number("missing")));
  CHECK_THROWS_AS(r.set("a\tb", 1.0), std::invalid_argument);
  CHECK_THROWS_AS(r.set("key", "two\tfields"), std::invalid_argument);
  const std::vector<double> runs = {0.0775081, 0.046198, 2.5};
  CHECK(DF_L1_bench::join_numbers(runs) == "0.0775081,0.046198,2.5");
  CHECK(DF_L1_bench::split_numbers(DF_L1_bench::join_numbers(runs)) == runs);
  CHECK(DF_L1_bench::split_numbers("0.5,fast").empty());
}

TEST_CASE("benchmark statistics: median, min and max; the log-log exponent", "[benchmark]")
{
  const DF_L1_bench::Spread odd = DF_L1_bench::spread({3, 1, 2, 10, 0.5});
  CHECK(odd.median == 2);
  CHECK(odd.min == 0.5);
  CHECK(odd.max == 10);
  CHECK(DF_L1_bench::spread({4, 1, 3, 2}).median == 2.5);
  std::vector<std::pair<double, double>> xy;
  for(double n : {1e4, 3e4, 1e5, 3e5, 1e6})
    xy.emplace_back(n, 3e-5 * std::pow(n, 1.1));
  CHECK(DF_L1_bench::report_internal::loglog_slope(xy) == Approx(1.1).epsilon(1e-9));
  CHECK(std::isnan(DF_L1_bench::report_internal::loglog_slope({{1e4, 1.0}})));
}

TEST_CASE("benchmark comparison: warns about stages more than 25 % slower only", "[benchmark]")
{
  std::vector<Record> baseline = {timed("quick/a", "df_l1", 1.0), timed("quick/b", "df_l1", 1.0)};
  std::vector<Record> now = {timed("quick/a", "df_l1", 1.4), timed("quick/b", "df_l1", 1.2)};
  std::ostringstream out;
  DF_L1_bench::compare(baseline, now, 0.25, out);
  const std::string text = out.str();
  INFO(text);
  CHECK(text.find("WARNING: quick/a contraction") != std::string::npos);
  CHECK(text.find("WARNING: quick/a total") != std::string::npos);
  CHECK(text.find("WARNING: quick/b") == std::string::npos); // +20 %
  CHECK(text.find("read") == std::string::npos);             // 10 ms stages are noise
  CHECK(text.find("2 more than 25 % slower") != std::string::npos);
}

TEST_CASE("benchmark report: targets checked against the figures, plots written", "[benchmark]")
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("df_l1_test_benchmark_report_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::vector<Record> records = {timed("headline/stick_figure-clean", "df_l1", 0.4),
                                 timed("headline/stick_figure-clean", "poisson_mcf", 6.0)};
  records[0].set("t.refinement", 0.35).set("topology_ok", 1.0).set("axis_ratio", 0.05).set("outside", 0.0);
  records[1].set("topology_ok", 0.0).set("axis_ratio", 0.1).set("outside", 0.0);
  for(double n : {1e5, 3e5, 1e6})
  {
    Record r = timed("points/" + std::to_string(int(n)), "df_l1", 1e-6 * std::pow(n, 1.2));
    r.set("points", n);
    records.push_back(r);
  }
  for(double t : {1.0, 2.0}) // the thread series: the projection step scales, the whole contraction less
  {
    Record r = timed("threads/" + std::to_string(int(t)), "df_l1", t == 1 ? 2.0 : 1.5);
    r.set("threads", t).set("t.contraction", t == 1 ? 1.0 : 0.7).set("projection_seconds", t == 1 ? 0.9 : 0.5);
    records.push_back(r);
  }
  // with the runs of each: the median of the ratios of alternating pairs (2, 1.75, 1.73),
  // not the ratio of the medians (1.0 / 0.52)
  for(double t : {1.0, 2.0})
  {
    Record r = timed("threads/" + std::to_string(int(t)) + "-300000", "df_l1", t == 1 ? 2.0 : 1.5);
    r.set("points", 300000.0).set("runs", 3.0).set("threads", t).set("t.contraction", t == 1 ? 1.0 : 0.7);
    r.set("projection_seconds", t == 1 ? 1.0 : 0.52).set("projection_runs", t == 1 ? "1,1.4,0.9" : "0.5,0.8,0.52");
    records.push_back(r);
  }
  DF_L1_bench::Report_options options;
  options.command = "scripts/bench.sh";
  DF_L1_bench::write_report(records, dir.string(), options);
  const std::string report = read_text((dir / "REPORT.md").string());
  INFO(report);
  CHECK(report.find("`scripts/bench.sh`") != std::string::npos);
  CHECK(report.find("| 35,000 points, whole pipeline < 0.5 s (slowest headline cloud) | 0.400 s | met |") !=
        std::string::npos);
  CHECK(report.find("refinement (contraction + graph) < 0.3 s | 0.350 s | **not met** |") != std::string::npos);
  CHECK(report.find(">= 5x faster than normals + Poisson + MCF (slowest ratio) | 15.0x | met |") != std::string::npos);
  CHECK(report.find("**1.20** from 100k to 1M points") != std::string::npos);
  CHECK(report.find("| 1000000 points < 10 s | 15.8 s | **not met** |") != std::string::npos);
  CHECK(report.find("N^1.20 | **not met** |") != std::string::npos);
  CHECK(report.find("35000 points (5 runs each): projection step (the fixed-point iterations) 1.80x faster on 2 threads,"
                     " contraction stage 1.43x,"
                     " whole pipeline 1.33x") != std::string::npos);
  CHECK(report.find("300000 points (3 runs each): projection step (the fixed-point iterations) 1.75x faster on 2"
                     " threads (median over the pairs of alternating runs; ratio of the medians 1.92x)") !=
        std::string::npos);
  CHECK(report.find("| projection step >= 1.7x faster on 2 threads than on 1 | 1.75x | met |") != std::string::npos);
  CHECK(std::filesystem::file_size(dir / "scaling_points.svg") > 500);
  std::filesystem::remove_all(dir);
}
