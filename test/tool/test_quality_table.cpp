// The quality evaluation's bookkeeping (benchmark/quality_table.h): the rows file, the
// scans' expectations, and the report that sets a run beside the previous one.
#include "../../benchmark/quality_table.h"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using DF_L1_quality::Row;

namespace {

std::string temp_path(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("df_l1_quality_test_" + std::to_string(::getpid()) + "_" + name)).string();
}

Row corpus_row(const std::string& name, const std::string& family, const std::string& degradation, bool ok, double coverage)
{
  Row r;
  r.kind = "corpus";
  r.name = name;
  r.family = family;
  r.degradation = degradation;
  r.expected = "3/1/0/1";
  r.got = ok ? "3/1/0/1" : "2/0/0/1";
  r.ok = ok;
  r.ratio = 0.1;
  r.outside = 0.002;
  r.coverage = coverage;
  r.seconds = 0.25;
  r.points = 20000;
  return r;
}

} // namespace

TEST_CASE("quality rows: a written file reads back, tabs and newlines in messages cleaned", "[quality]")
{
  std::vector<Row> rows{corpus_row("trees_1", "trees", "clean", true, 0.97), corpus_row("trees_1", "trees", "holes", false, 0.5)};
  rows[1].error = "bad\tthing\nhappened";
  rows[0].tips = DF_L1_quality::tip_counts({{0.5, false}, {1.5, true}, {3, true}, {7, true}, {30, false}});
  CHECK(rows[0].tips == "1/2 1/1 0/0 1/2");
  const std::string path = temp_path("rows.tsv");
  DF_L1_quality::write_rows(path, rows);
  const std::vector<Row> back = DF_L1_quality::read_rows(path);
  REQUIRE(back.size() == 2);
  CHECK(back[0].name == "trees_1");
  CHECK(back[0].ok);
  CHECK(!back[1].ok);
  CHECK(back[1].degradation == "holes");
  CHECK(back[1].coverage == Approx(0.5));
  CHECK(back[1].error == "bad thing happened");
  CHECK(back[0].error.empty());
  CHECK(back[0].tips == "1/2 1/1 0/0 1/2");
  CHECK(back[1].tips.empty());
  CHECK(DF_L1_quality::read_rows(temp_path("absent.tsv")).empty());
  std::filesystem::remove(path);
}

TEST_CASE("quality expectations: the flat JSON of the shared scans", "[quality]")
{
  const std::string path = temp_path("expected.json");
  {
    std::ofstream out(path);
    out << "{\n \"_about\": \"comment, ignored\",\n \"a.off\": {\n  \"components\": 1,\n  \"cycles\": 4\n },\n"
           " \"b.xyz\": {\"components\": 1, \"cycles\": 0, \"endpoint_tolerance\": 1, \"endpoints\": 6},\n"
           " \"c.ply\": {\"components\": 2, \"cycles\": 0, \"min_points_near_skeleton\": 0.95}\n}\n";
  }
  const auto e = DF_L1_quality::read_expectations(path);
  REQUIRE(e.size() == 3);
  CHECK(e[0].file == "a.off");
  CHECK(e[0].cycles == 4);
  CHECK(e[0].endpoints == -1);
  CHECK(e[1].endpoints == 6);
  CHECK(e[1].endpoint_tolerance == 1);
  CHECK(e[2].components == 2);
  CHECK(e[2].min_points_near == Approx(0.95));
  CHECK(e[1].text() == "components 1, cycles 0, ends 6+-1");
  {
    std::ofstream out(path);
    out << "{ \"a.off\": [1, 2] }";
  }
  CHECK_THROWS_AS(DF_L1_quality::read_expectations(path), std::runtime_error);
  std::filesystem::remove(path);
}

TEST_CASE("quality report: shares per family and degradation, the previous run beside, gains and losses", "[quality]")
{
  std::vector<Row> previous{corpus_row("trees_1", "trees", "clean", false, 0.6), corpus_row("trees_1", "trees", "holes", true, 0.9),
                            corpus_row("loops_1", "loops", "clean", true, 0.95), corpus_row("loops_1", "loops", "holes", true, 0.95)};
  previous[0].tips = "1/4 0/0 0/0 2/2";
  std::vector<Row> now = previous;
  now[0].tips = "3/4 0/0 0/0 2/2";
  now[1].tips = "0/0 1/2 0/0 0/0";
  now[0].ok = true; // gained
  now[0].got = "3/1/0/1";
  now[1].ok = false; // lost
  now[1].got = "2/0/0/1";
  Row scan;
  scan.kind = "scan";
  scan.name = "horse.off";
  scan.family = "scan";
  scan.degradation = "-";
  scan.expected = "components 1, cycles 0";
  scan.got = "components 1, cycles 2, ends 5";
  now.push_back(scan);
  // the scan thinned to 2,000 points: failed before, passes now
  Row thinned = scan;
  thinned.kind = "scan_variant";
  thinned.degradation = "sparse_2000";
  thinned.got = "components 3, cycles 0, ends 11";
  previous.push_back(thinned);
  thinned.got = "components 1, cycles 0, ends 6";
  thinned.ok = true;
  now.push_back(thinned);
  DF_L1_quality::Report_context ctx;
  ctx.command = "scripts/quality.sh";
  ctx.families = {"trees", "loops"};
  ctx.degradations = {"clean", "holes"};
  const std::string md = DF_L1_quality::markdown_report(now, previous, ctx);
  // 3 of 4 corpus cases pass now, as before
  CHECK(md.find("| corpus cases with the designed topology | 3 / 4 (75 %) | 3 / 4 (75 %) |") != std::string::npos);
  // trees: 50 % now in both columns, the previous shares in parentheses where they differ
  CHECK(md.find("| trees | 100 (0) | 0 (100) | 50 |") != std::string::npos);
  CHECK(md.find("| loops | 100 | 100 | 100 |") != std::string::npos);
  CHECK(md.find("Gained 2, lost 1.") != std::string::npos);
  CHECK(md.find("Lost: trees_1 holes (2/0/0/1, expected 3/1/0/1)") != std::string::npos);
  CHECK(md.find("| horse.off |") != std::string::npos);
  CHECK(md.find("| degraded real scans meeting the scan's expectation | 1 / 1 | 0 / 1 |") != std::string::npos);
  CHECK(md.find("| file | sparse_2000 |") != std::string::npos);
  CHECK(md.find("| horse.off | ok (**components 3, cycles 0, ends 11**) |") != std::string::npos);
  CHECK(md.find("horse.off sparse_2000") != std::string::npos); // among the gains
  // tips found by class: clean 3 of 4 now (1 before), holes 1 of 2 (none designed before)
  CHECK(md.find("| clean | 75 (25) of 4 | - | - | 100 of 2 |") != std::string::npos);
  CHECK(md.find("| holes | - | 50 of 2 | - | - |") != std::string::npos);
  CHECK(md.find("**not met**") != std::string::npos); // 75 % < 95 %
  CHECK(DF_L1_quality::beside("50", "50") == "50");
  CHECK(DF_L1_quality::beside("50", "") == "50");
  CHECK(DF_L1_quality::beside("50", "40") == "50 (40)");
}
