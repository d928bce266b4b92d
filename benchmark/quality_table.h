// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef DF_L1_BENCHMARK_QUALITY_TABLE_H
#define DF_L1_BENCHMARK_QUALITY_TABLE_H

/// \file quality_table.h
/// The rows of the quality evaluation (df_l1_quality), their tab-separated file, the
/// expectations of the real scans, and the Markdown report that sets a run beside the
/// previous one.

#include <CGAL/DF_L1_skeleton/IO/write_file_atomically.h>
#include "evaluation/scan_variants.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace DF_L1_quality {

/// One evaluated case: a corpus shape under a degradation, or a real scan.
struct Row
{
  std::string kind;        ///< "corpus" or "scan"
  std::string name;        ///< shape name (family_index) or file name
  std::string family;      ///< corpus family; "scan" for scans
  std::string degradation; ///< corpus degradation; "-" for scans
  std::string expected;    ///< corpus: ends/junctions/cycles/components; scan: the expectation
  std::string got;         ///< the same counts of the skeleton
  bool ok = false;         ///< topology (and, for scans, the near share) as expected
  double ratio = 0;        ///< corpus: mean distance to the true axis / local radius
  double outside = 0;      ///< corpus: share of the skeleton length outside the solid
  double coverage = 0;     ///< corpus: share of the true axis passed near; scan: share of points near
  double seconds = 0;      ///< the skeletonization
  std::size_t points = 0;  ///< input points
  std::string error;       ///< what was thrown, if anything (the case then fails)
  std::string initial;     ///< the counts of the initial skeleton (as `got`), for diagnosis
  /// corpus: the designed end points found / designed, by how far their limb stands apart
  /// (`tip_recall()`), one "found/designed" per class of `tip_classes()`, space-separated
  std::string tips;
};

/// The classes of designed end points by the free length of their limb, in voxels.
inline const std::vector<std::pair<double, std::string>>& tip_classes()
{
  static const std::vector<std::pair<double, std::string>> classes{
    {2, "under 2 voxels"}, {4, "2 to 4"}, {6, "4 to 6"}, {std::numeric_limits<double>::infinity(), "6 or more"}};
  return classes;
}

/// `Row::tips` of the tip recalls `t` (pairs of free length in voxels, found).
inline std::string tip_counts(const std::vector<std::pair<double, bool>>& t)
{
  std::vector<std::size_t> found(tip_classes().size(), 0), designed(tip_classes().size(), 0);
  for(const auto& tip : t)
    for(std::size_t c = 0; c < tip_classes().size(); ++c)
      if(tip.first < tip_classes()[c].first) {
        ++designed[c];
        found[c] += tip.second;
        break;
      }
  std::string s;
  for(std::size_t c = 0; c < designed.size(); ++c)
    s += (c ? " " : "") + std::to_string(found[c]) + "/" + std::to_string(designed[c]);
  return s;
}

inline std::string clean_field(std::string s)
{
  std::replace(s.begin(), s.end(), '\t', ' ');
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  return s.empty() ? "-" : s;
}

inline void write_rows(const std::string& path, const std::vector<Row>& rows)
{
  CGAL::DF_L1::write_file_atomically(path, [&](std::ostream& out) {
    out << "kind\tname\tfamily\tdegradation\texpected\tgot\tok\tratio\toutside\tcoverage\tseconds\tpoints\terror\tinitial\ttips\n";
    char num[160];
    for(const Row& r : rows) {
      std::snprintf(num, sizeof num, "%.4f\t%.5f\t%.4f\t%.3f\t%zu", r.ratio, r.outside, r.coverage, r.seconds, r.points);
      out << clean_field(r.kind) << '\t' << clean_field(r.name) << '\t' << clean_field(r.family) << '\t'
          << clean_field(r.degradation) << '\t' << clean_field(r.expected) << '\t' << clean_field(r.got) << '\t'
          << (r.ok ? 1 : 0) << '\t' << num << '\t' << clean_field(r.error) << '\t' << clean_field(r.initial) << '\t'
          << clean_field(r.tips) << '\n';
    }
  });
}

/// The rows of a file written by `write_rows()`; none when it does not exist.
inline std::vector<Row> read_rows(const std::string& path)
{
  std::vector<Row> rows;
  std::ifstream in(path);
  if(!in)
    return rows;
  std::string line;
  std::getline(in, line); // header
  while(std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string field;
    while(std::getline(ss, field, '\t'))
      f.push_back(field);
    if(f.size() < 12)
      continue;
    Row r;
    r.kind = f[0];
    r.name = f[1];
    r.family = f[2];
    r.degradation = f[3];
    r.expected = f[4];
    r.got = f[5];
    r.ok = f[6] == "1";
    r.ratio = std::stod(f[7]);
    r.outside = std::stod(f[8]);
    r.coverage = std::stod(f[9]);
    r.seconds = std::stod(f[10]);
    r.points = std::size_t(std::stoull(f[11]));
    r.error = f.size() > 12 && f[12] != "-" ? f[12] : "";
    r.initial = f.size() > 13 && f[13] != "-" ? f[13] : "";
    r.tips = f.size() > 14 && f[14] != "-" ? f[14] : "";
    rows.push_back(r);
  }
  return rows;
}

/// What a real scan's skeleton must have (../shared/data/expected_topology.json).
struct Scan_expectation
{
  std::string file;
  int components = -1, cycles = -1, endpoints = -1, endpoint_tolerance = 0;
  double min_points_near = -1;

  std::string text() const
  {
    std::string s = "components " + std::to_string(components) + ", cycles " + std::to_string(cycles);
    if(endpoints >= 0)
      s += ", ends " + std::to_string(endpoints) + "+-" + std::to_string(endpoint_tolerance);
    if(min_points_near >= 0) {
      char b[40];
      std::snprintf(b, sizeof b, ", near >= %.2f", min_points_near);
      s += b;
    }
    return s;
  }
};

/// Reads the flat JSON object of objects of numbers that expected_topology.json is
/// (keys starting with '_' are comments). Throws `std::runtime_error` on anything else.
inline std::vector<Scan_expectation> read_expectations(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    return {};
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string s = buffer.str();
  std::size_t i = 0;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(path + ": " + what + " at offset " + std::to_string(i));
  };
  auto skip = [&] {
    while(i < s.size() && std::isspace(static_cast<unsigned char>(s[i])))
      ++i;
  };
  auto expect = [&](char c) {
    skip();
    if(i >= s.size() || s[i] != c)
      fail(std::string("expected '") + c + "'");
    ++i;
  };
  auto string = [&] {
    expect('"');
    std::string out;
    while(i < s.size() && s[i] != '"') {
      if(s[i] == '\\' && i + 1 < s.size())
        ++i;
      out += s[i++];
    }
    expect('"');
    return out;
  };
  auto number = [&] {
    skip();
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(s.substr(i, 40), &used);
    } catch(const std::exception&) {
      fail("expected a number");
    }
    i += used;
    return v;
  };
  std::vector<Scan_expectation> result;
  expect('{');
  skip();
  while(i < s.size() && s[i] != '}') {
    const std::string key = string();
    expect(':');
    skip();
    if(s[i] == '"') {
      string();
    } else {
      Scan_expectation e;
      e.file = key;
      expect('{');
      skip();
      while(i < s.size() && s[i] != '}') {
        const std::string field = string();
        expect(':');
        const double v = number();
        if(field == "components")
          e.components = int(v);
        else if(field == "cycles")
          e.cycles = int(v);
        else if(field == "endpoints")
          e.endpoints = int(v);
        else if(field == "endpoint_tolerance")
          e.endpoint_tolerance = int(v);
        else if(field == "min_points_near_skeleton")
          e.min_points_near = v;
        else
          fail("unknown field '" + field + "'");
        skip();
        if(s[i] == ',')
          ++i;
        skip();
      }
      expect('}');
      if(e.components < 0 || e.cycles < 0)
        fail("'" + key + "' needs components and cycles");
      if(key.empty() || key[0] != '_')
        result.push_back(e);
    }
    skip();
    if(i < s.size() && s[i] == ',')
      ++i;
    skip();
  }
  return result;
}

/// Aggregates over a set of rows.
struct Summary
{
  std::size_t cases = 0, passes = 0, measured = 0;
  double ratio = 0, outside = 0, coverage = 0, min_coverage = 1;
  double share() const { return cases ? double(passes) / double(cases) : 0; }
};

template <class Pred>
Summary summarize(const std::vector<Row>& rows, Pred pred)
{
  Summary s;
  for(const Row& r : rows) {
    if(!pred(r))
      continue;
    ++s.cases;
    s.passes += r.ok;
    if(r.error.empty()) {
      ++s.measured;
      s.ratio += r.ratio;
      s.outside += r.outside;
      s.coverage += r.coverage;
      s.min_coverage = std::min(s.min_coverage, r.coverage);
    }
  }
  if(s.measured) {
    s.ratio /= double(s.measured);
    s.outside /= double(s.measured);
    s.coverage /= double(s.measured);
  } else
    s.min_coverage = 0;
  return s;
}

inline std::string percent(const Summary& s, int digits = 0)
{
  if(!s.cases)
    return "-";
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, 100 * s.share());
  return b;
}

inline std::string fixed(double v, int digits)
{
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

/// "now (previous)" when there is a previous figure that differs, else "now".
inline std::string beside(const std::string& now, const std::string& prev)
{
  return prev.empty() || prev == "-" || prev == now ? now : now + " (" + prev + ")";
}

/// Everything the Markdown report needs besides the rows.
struct Report_context
{
  std::string command;                 ///< how to reproduce
  std::string label;                   ///< e.g. the commit
  std::vector<std::string> families;   ///< table order
  std::vector<std::string> degradations;
  std::string scan_sheet;              ///< relative path of the scans' contact sheet, or ""
  std::string failure_sheet;           ///< where the failures' previews are (not committed)
  std::map<std::string, std::string> scan_previews; ///< file -> relative preview path
};

inline std::string markdown_report(const std::vector<Row>& rows, const std::vector<Row>& previous, const Report_context& ctx)
{
  std::ostringstream md;
  auto corpus = [](const Row& r) { return r.kind == "corpus"; };
  const Summary all = summarize(rows, corpus), prev_all = summarize(previous, corpus);
  const bool has_prev = prev_all.cases > 0;
  auto prev_of = [&](const Summary& s) { return has_prev && s.cases ? percent(s) : std::string(); };

  md << "# Skeleton quality on unseen shapes and real scans\n\n";
  md << "Written by `" << ctx.command << "`";
  if(!ctx.label.empty())
    md << " at " << ctx.label;
  md << ". Figures in parentheses are the previous run's (the committed `benchmark/quality_results.tsv` before this one), "
        "shown where they differ. Every case runs the library with its defaults (V = 100, M = 1500).\n\n";

  md << "## Headline\n\n";
  std::size_t scans = 0, scans_ok = 0, prev_scans = 0, prev_scans_ok = 0;
  for(const Row& r : rows)
    if(r.kind == "scan") {
      ++scans;
      scans_ok += r.ok;
    }
  for(const Row& r : previous)
    if(r.kind == "scan") {
      ++prev_scans;
      prev_scans_ok += r.ok;
    }
  md << "| | now | previous |\n|---|---|---|\n";
  md << "| corpus cases with the designed topology | " << all.passes << " / " << all.cases << " (" << percent(all) << " %) | "
     << (has_prev ? std::to_string(prev_all.passes) + " / " + std::to_string(prev_all.cases) + " (" + percent(prev_all) + " %)" : "-")
     << " |\n";
  md << "| mean axis ratio | " << fixed(all.ratio, 3) << " | " << (has_prev ? fixed(prev_all.ratio, 3) : "-") << " |\n";
  md << "| mean outside fraction | " << fixed(all.outside, 4) << " | " << (has_prev ? fixed(prev_all.outside, 4) : "-") << " |\n";
  md << "| mean coverage | " << fixed(all.coverage, 3) << " | " << (has_prev ? fixed(prev_all.coverage, 3) : "-") << " |\n";
  md << "| real scans meeting their expectation | " << scans_ok << " / " << scans << " | "
     << (prev_scans ? std::to_string(prev_scans_ok) + " / " + std::to_string(prev_scans) : "-") << " |\n";
  {
    std::size_t n = 0, ok = 0, prev_n = 0, prev_ok = 0;
    for(const Row& r : rows)
      if(r.kind == "scan_variant" && r.got != "-") {
        ++n;
        ok += r.ok;
      }
    for(const Row& r : previous)
      if(r.kind == "scan_variant" && r.got != "-") {
        ++prev_n;
        prev_ok += r.ok;
      }
    if(n)
      md << "| degraded real scans meeting the scan's expectation | " << ok << " / " << n << " | "
         << (prev_n ? std::to_string(prev_ok) + " / " + std::to_string(prev_n) : "-") << " |\n";
  }
  md << "\n";

  // Targets of issue 19.
  double worst_family = 1, worst_degradation = 1;
  std::string worst_family_name, worst_degradation_name;
  for(const std::string& f : ctx.families) {
    const Summary s = summarize(rows, [&](const Row& r) { return corpus(r) && r.family == f; });
    if(s.cases && s.share() < worst_family) {
      worst_family = s.share();
      worst_family_name = f;
    }
  }
  for(const std::string& d : ctx.degradations) {
    const Summary s = summarize(rows, [&](const Row& r) { return corpus(r) && r.degradation == d; });
    if(s.cases && s.share() < worst_degradation) {
      worst_degradation = s.share();
      worst_degradation_name = d;
    }
  }
  auto met = [](bool b) { return b ? "met" : "**not met**"; };
  md << "Targets: designed topology on >= 95 % of all cases: " << percent(all, 1) << " %, " << met(all.share() >= 0.95)
     << "; >= 90 % in every family: lowest " << fixed(100 * worst_family, 1) << " % (" << worst_family_name << "), "
     << met(worst_family >= 0.9) << "; >= 90 % in every degradation: lowest " << fixed(100 * worst_degradation, 1) << " % ("
     << worst_degradation_name << "), " << met(worst_degradation >= 0.9) << "; mean axis ratio <= 0.25: "
     << met(all.ratio <= 0.25) << "; outside fraction <= 1 %: " << met(all.outside <= 0.01)
     << "; coverage >= 0.95: " << met(all.coverage >= 0.95) << "; every real scan: " << met(scans_ok == scans && scans > 0)
     << ".\n\n";

  md << "## Designed topology, % of cases, per family and degradation\n\n";
  md << "Topology: components and cycles; junctions (junction vertices joined by a path shorter than the true local radius, "
        "or lying in the zone of the same designed junction, where its parts are not yet 2 voxels apart, count once) and "
        "end points (+-1 under noise) except on shapes with plates.\n\n";
  md << "| family |";
  for(const std::string& d : ctx.degradations)
    md << ' ' << d << " |";
  md << " all |\n|---|";
  for(std::size_t i = 0; i <= ctx.degradations.size(); ++i)
    md << "---|";
  md << '\n';
  for(std::size_t fi = 0; fi <= ctx.families.size(); ++fi) {
    const bool total = fi == ctx.families.size();
    const std::string f = total ? "all" : ctx.families[fi];
    md << "| " << (total ? "**all**" : f) << " |";
    for(std::size_t di = 0; di <= ctx.degradations.size(); ++di) {
      const bool dall = di == ctx.degradations.size();
      auto pred = [&](const Row& r) {
        return corpus(r) && (total || r.family == f) && (dall || r.degradation == ctx.degradations[di]);
      };
      md << ' ' << beside(percent(summarize(rows, pred)), prev_of(summarize(previous, pred))) << " |";
    }
    md << '\n';
  }

  auto metric_table = [&](const std::string& what, const std::vector<std::string>& keys, bool by_family) {
    md << "\n## Geometry per " << what << "\n\n";
    md << "| " << what << " | cases | axis ratio | outside | coverage | min coverage | mean seconds |\n|---|---|---|---|---|---|---|\n";
    for(const std::string& k : keys) {
      auto pred = [&](const Row& r) { return corpus(r) && (by_family ? r.family == k : r.degradation == k); };
      const Summary s = summarize(rows, pred), p = summarize(previous, pred);
      double seconds = 0;
      for(const Row& r : rows)
        if(pred(r))
          seconds += r.seconds;
      const bool hp = p.measured > 0;
      md << "| " << k << " | " << s.cases << " | " << beside(fixed(s.ratio, 3), hp ? fixed(p.ratio, 3) : "") << " | "
         << beside(fixed(s.outside, 4), hp ? fixed(p.outside, 4) : "") << " | "
         << beside(fixed(s.coverage, 3), hp ? fixed(p.coverage, 3) : "") << " | "
         << beside(fixed(s.min_coverage, 3), hp ? fixed(p.min_coverage, 3) : "") << " | "
         << fixed(s.cases ? seconds / double(s.cases) : 0, 3) << " |\n";
    }
  };
  metric_table("family", ctx.families, true);
  metric_table("degradation", ctx.degradations, false);

  // Designed end points found, by how far their limb stands apart from the other parts.
  // found / designed of the class `c` of tip_classes(), under `degradation` ("": all)
  auto tip_tally = [&](const std::vector<Row>& from, const std::string& degradation, std::size_t c) {
    std::pair<std::size_t, std::size_t> t{0, 0};
    for(const Row& r : from) {
      if(!corpus(r) || (!degradation.empty() && r.degradation != degradation) || r.tips.empty())
        continue;
      std::istringstream in(r.tips);
      std::string field;
      for(std::size_t k = 0; in >> field; ++k)
        if(k == c) {
          const std::size_t slash = field.find('/');
          t.first += std::stoul(field.substr(0, slash));
          t.second += std::stoul(field.substr(slash + 1));
        }
    }
    return t;
  };
  auto tip_percent = [](const std::pair<std::size_t, std::size_t>& t) {
    char b[32];
    std::snprintf(b, sizeof b, "%.0f", 100.0 * double(t.first) / double(t.second));
    return std::string(b);
  };
  md << "\n## Designed end points found, by how far their limb stands apart\n\n";
  md << "Per designed end point (shapes without plates): found when the skeleton has an end point within "
        "max(3 voxels, 3 radii) of it; classed by the length of its limb's axis, from the tip back, along which its "
        "surface keeps at least a voxel from every other part (`tip_recall()` in tools/evaluation/skeleton_quality.h). "
        "A tip of the first class is fused with a neighbour to near its end. % found of the designed tips, all families.\n\n";
  md << "| degradation |";
  for(const auto& c : tip_classes())
    md << ' ' << c.second << " |";
  md << "\n|---|";
  for(std::size_t c = 0; c < tip_classes().size(); ++c)
    md << "---|";
  md << '\n';
  for(std::size_t di = 0; di <= ctx.degradations.size(); ++di) {
    const std::string d = di < ctx.degradations.size() ? ctx.degradations[di] : "";
    md << "| " << (d.empty() ? "**all**" : d) << " |";
    for(std::size_t c = 0; c < tip_classes().size(); ++c) {
      const auto now = tip_tally(rows, d, c), before = tip_tally(previous, d, c);
      if(!now.second)
        md << " - |";
      else
        md << ' ' << beside(tip_percent(now), before.second ? tip_percent(before) : "") << " of " << now.second << " |";
    }
    md << '\n';
  }

  md << "\n## Real scans (`../shared/data`)\n\n";
  md << "Near: the share of the points not flagged as outliers that lie within 0.08 d_bb of the skeleton.\n\n";
  md << "| file | points | expected | got | near | seconds | ok | previous |\n|---|---|---|---|---|---|---|---|\n";
  for(const Row& r : rows) {
    if(r.kind != "scan")
      continue;
    std::string prev = "-";
    for(const Row& p : previous)
      if(p.kind == "scan" && p.name == r.name)
        prev = std::string(p.ok ? "ok" : "fail") + " (" + p.got + ")";
    md << "| " << r.name << " | " << r.points << " | " << r.expected << " | "
       << (r.error.empty() ? r.got : "error: " + r.error) << " | " << fixed(r.coverage, 3) << " | " << fixed(r.seconds, 2)
       << " | " << (r.ok ? "ok" : "**fail**") << " | " << prev << " |\n";
  }
  if(!ctx.scan_sheet.empty())
    md << "\nPreviews (final skeleton over the points, front/side/top; the initial skeleton below it):\n\n![scans]("
       << ctx.scan_sheet << ")\n";

  // The degraded copies of the scans (scan_variants.h), one column per variant.
  std::vector<std::string> variants;
  for(const Row& r : rows)
    if(r.kind == "scan_variant" && std::find(variants.begin(), variants.end(), r.degradation) == variants.end())
      variants.push_back(r.degradation);
  if(!variants.empty()) {
    md << "\n## Degraded real scans\n\n";
    md << "Each scan of the table above, degraded, against the same expectation:";
    for(const DF_L1_test::Scan_variant& v : DF_L1_test::scan_variants())
      if(std::find(variants.begin(), variants.end(), v.name) != variants.end())
        md << " " << v.name << ": " << v.description << ";";
    md << " the near share counts the scan's own points. A cell gives what failed and, in parentheses, the "
          "previous run's result where it differs.\n\n| file |";
    for(const std::string& v : variants)
      md << ' ' << v << " |";
    md << "\n|---|";
    for(std::size_t i = 0; i < variants.size(); ++i)
      md << "---|";
    md << '\n';
    auto cell = [](const Row& r) {
      if(r.got == "-")
        return std::string("-");
      if(!r.error.empty())
        return std::string("**error**");
      return r.ok ? std::string("ok") : "**" + r.got + "**";
    };
    for(const Row& r : rows) {
      if(r.kind != "scan")
        continue;
      md << "| " << r.name << " |";
      for(const std::string& v : variants) {
        std::string text = "-";
        for(const Row& x : rows)
          if(x.kind == "scan_variant" && x.name == r.name && x.degradation == v) {
            text = cell(x);
            for(const Row& p : previous)
              if(p.kind == "scan_variant" && p.name == r.name && p.degradation == v && cell(p) != text)
                text += " (" + cell(p) + ")";
          }
        md << ' ' << text << " |";
      }
      md << '\n';
    }
  }

  // Gains and losses case by case.
  if(has_prev) {
    std::map<std::string, bool> before;
    for(const Row& p : previous)
      before[p.kind + "/" + p.name + "/" + p.degradation] = p.ok;
    std::vector<std::string> gained, lost;
    for(const Row& r : rows) {
      const auto it = before.find(r.kind + "/" + r.name + "/" + r.degradation);
      if(it == before.end())
        continue;
      if(r.ok && !it->second)
        gained.push_back(r.name + " " + r.degradation);
      if(!r.ok && it->second)
        lost.push_back(r.name + " " + r.degradation + " (" + r.got + ", expected " + r.expected + ")");
    }
    md << "\n## Changes since the previous run\n\n";
    md << "Gained " << gained.size() << ", lost " << lost.size() << ".\n";
    auto list = [&](const char* title, const std::vector<std::string>& v) {
      if(v.empty())
        return;
      md << "\n" << title << ":";
      for(std::size_t i = 0; i < v.size() && i < 80; ++i)
        md << (i ? ", " : " ") << v[i];
      if(v.size() > 80)
        md << ", ... (" << v.size() - 80 << " more)";
      md << "\n";
    };
    list("Gained", gained);
    list("Lost", lost);
  }
  if(!ctx.failure_sheet.empty())
    md << "\nPreviews of the failed corpus cases (not committed): `" << ctx.failure_sheet << "`.\n";
  return md.str();
}

} // namespace DF_L1_quality

#endif // DF_L1_BENCHMARK_QUALITY_TABLE_H
