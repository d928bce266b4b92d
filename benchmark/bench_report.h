// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// benchmark/REPORT.md from the result lines of df_l1_benchmark: the machine, the
// targets of the speed issue checked against the figures, tables per series and SVG
// plots (drawn here, no plotting package needed); and the regression comparison of
// scripts/bench.sh --quick.
#ifndef DF_L1_BENCHMARK_BENCH_REPORT_H
#define DF_L1_BENCHMARK_BENCH_REPORT_H

#include "bench_record.h"

#include <CGAL/version.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iterator>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace DF_L1_bench {

struct Report_options
{
  std::string command; ///< the command that produced the results, quoted in the report
  std::string notes;   ///< a Markdown file appended verbatim (profile and optimisation log)
};

namespace report_internal {

inline std::string fixed(double x, int digits)
{
  if(std::isnan(x))
    return "-";
  std::ostringstream os;
  os << std::fixed << std::setprecision(digits) << x;
  return os.str();
}

// Seconds with 3 significant figures at least 0.001.
inline std::string seconds(double x)
{
  if(std::isnan(x))
    return "-";
  return fixed(x, x < 1 ? 3 : x < 10 ? 2 : 1);
}

inline std::string seconds_spread(const Record& r, const std::string& stage)
{
  if(!r.has("t." + stage))
    return "-";
  return seconds(r.number("t." + stage)) + " (" + seconds(r.number("tmin." + stage)) + "-" +
         seconds(r.number("tmax." + stage)) + ")";
}

inline bool starts_with(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

inline std::vector<Record> series(const std::vector<Record>& all, const std::string& prefix)
{
  std::vector<Record> out;
  for(const Record& r : all)
    if(starts_with(r.text("label"), prefix))
      out.push_back(r);
  return out;
}

inline std::string first_line_of(const std::string& path, const std::string& key)
{
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
    if(starts_with(line, key))
    {
      const std::size_t colon = line.find(':');
      std::string v = colon == std::string::npos ? line : line.substr(colon + 1);
      v.erase(0, v.find_first_not_of(" \t"));
      return v;
    }
  return "unknown";
}

// Least-squares slope of log(y) against log(x).
inline double loglog_slope(const std::vector<std::pair<double, double>>& xy)
{
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for(const auto& p : xy)
  {
    if(!(p.first > 0 && p.second > 0))
      continue;
    const double x = std::log(p.first), y = std::log(p.second);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  if(n < 2 || n * sxx - sx * sx <= 0)
    return std::nan("");
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

struct Plot_series
{
  std::string name, colour;
  std::vector<double> x, y, ymin, ymax;
};

// A log-log plot with decade grid lines, error bars from ymin to ymax.
inline void write_loglog_svg(const std::string& path, const std::string& title, const std::string& xlabel,
                             const std::string& ylabel, const std::vector<Plot_series>& series)
{
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for(const Plot_series& s : series)
    for(std::size_t i = 0; i < s.x.size(); ++i)
    {
      x0 = (std::min)(x0, s.x[i]);
      x1 = (std::max)(x1, s.x[i]);
      y0 = (std::min)(y0, (std::min)(s.y[i], s.ymin[i]));
      y1 = (std::max)(y1, (std::max)(s.y[i], s.ymax[i]));
    }
  if(!(x0 > 0 && y0 > 0))
    return;
  const double lx0 = std::floor(std::log10(x0)), lx1 = std::ceil(std::log10(x1) + 1e-9);
  const double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1) + 1e-9);
  const double W = 640, H = 400, left = 70, right = 160, top = 40, bottom = 50;
  const auto px = [&](double x) { return left + (std::log10(x) - lx0) / (lx1 - lx0) * (W - left - right); };
  const auto py = [&](double y) { return H - bottom - (std::log10(y) - ly0) / (ly1 - ly0) * (H - top - bottom); };
  std::ofstream out(path);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << title << "</text>\n";
  for(double e = lx0; e <= lx1 + 1e-9; ++e)
    for(int m = 1; m < 10; ++m)
    {
      const double x = m * std::pow(10.0, e);
      if(std::log10(x) > lx1 + 1e-9)
        break;
      out << "<line x1=\"" << px(x) << "\" y1=\"" << top << "\" x2=\"" << px(x) << "\" y2=\"" << H - bottom
          << "\" stroke=\"" << (m == 1 ? "#bbb" : "#eee") << "\"/>\n";
      if(m == 1)
        out << "<text x=\"" << px(x) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\">" << x << "</text>\n";
    }
  for(double e = ly0; e <= ly1 + 1e-9; ++e)
    for(int m = 1; m < 10; ++m)
    {
      const double y = m * std::pow(10.0, e);
      if(std::log10(y) > ly1 + 1e-9)
        break;
      out << "<line x1=\"" << left << "\" y1=\"" << py(y) << "\" x2=\"" << W - right << "\" y2=\"" << py(y)
          << "\" stroke=\"" << (m == 1 ? "#bbb" : "#eee") << "\"/>\n";
      if(m == 1)
        out << "<text x=\"" << left - 6 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\">" << y << "</text>\n";
    }
  out << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\">" << xlabel
      << "</text>\n<text transform=\"translate(16," << (top + H - bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << ylabel << "</text>\n";
  for(std::size_t k = 0; k < series.size(); ++k)
  {
    const Plot_series& s = series[k];
    out << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"2\" points=\"";
    for(std::size_t i = 0; i < s.x.size(); ++i)
      out << px(s.x[i]) << "," << py(s.y[i]) << " ";
    out << "\"/>\n";
    for(std::size_t i = 0; i < s.x.size(); ++i)
      out << "<line x1=\"" << px(s.x[i]) << "\" y1=\"" << py(s.ymin[i]) << "\" x2=\"" << px(s.x[i]) << "\" y2=\""
          << py(s.ymax[i]) << "\" stroke=\"" << s.colour << "\"/>\n<circle cx=\"" << px(s.x[i]) << "\" cy=\""
          << py(s.y[i]) << "\" r=\"3\" fill=\"" << s.colour << "\"/>\n";
    out << "<line x1=\"" << W - right + 12 << "\" y1=\"" << top + 10 + 18 * k << "\" x2=\"" << W - right + 32
        << "\" y2=\"" << top + 10 + 18 * k << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\"/>\n<text x=\""
        << W - right + 36 << "\" y=\"" << top + 14 + 18 * k << "\">" << s.name << "</text>\n";
  }
  out << "</svg>\n";
}

inline const char* colour(std::size_t k)
{
  static const char* c[] = {"#c0392b", "#2471a3", "#27ae60", "#8e44ad", "#d68910", "#17202a", "#7f8c8d", "#e67e22"};
  return c[k % 8];
}

// The stages of a record, in the order they ran.
inline std::vector<std::string> stages_of(const Record& r)
{
  std::vector<std::string> s;
  for(const auto& f : r.fields())
    if(starts_with(f.first, "t.") && f.first != "t.total" && f.first != "t.refinement")
      s.push_back(f.first.substr(2));
  return s;
}

inline std::string quality_cells(const Record& r)
{
  if(!r.has("topology_ok"))
    return "- | - | - | -";
  return std::string(r.number("topology_ok") > 0 ? "yes" : "**no**") + " | " + fixed(r.number("axis_ratio"), 3) +
         " | " + fixed(r.number("outside"), 4) + " | " + fixed(r.number("coverage"), 3);
}

inline std::string topology_cell(const Record& r)
{
  return fixed(r.number("components"), 0) + "/" + fixed(r.number("cycles"), 0) + "/" + fixed(r.number("ends"), 0) +
         "/" + fixed(r.number("junctions"), 0);
}

// A table of stage seconds: one row per record, one column per stage.
inline void stage_table(std::ostream& os, const std::vector<Record>& rows, const std::string& first_column,
                        const std::function<std::string(const Record&)>& first_cell)
{
  if(rows.empty())
    return;
  const std::vector<std::string> stages = stages_of(rows.front());
  os << "| " << first_column;
  for(const std::string& s : stages)
    os << " | " << s;
  os << " | total | peak MiB |\n|---";
  for(std::size_t i = 0; i <= stages.size() + 1; ++i)
    os << "|---";
  os << "|\n";
  for(const Record& r : rows)
  {
    os << "| " << first_cell(r);
    for(const std::string& s : stages)
      os << " | " << seconds(r.number("t." + s));
    os << " | " << seconds_spread(r, "total") << " | " << fixed(r.number("peak_mib"), 0) << " |\n";
  }
  os << "\n";
}

inline std::string method_name(const std::string& m)
{
  if(m == "df_l1")
    return "DF_L1 (ours)";
  if(m == "l1")
    return "plain L1-medial (ours, `l1`)";
  if(m == "poisson_mcf")
    return "normals + Poisson + MCF";
  if(m == "mesh_mcf")
    return "MCF on an exact mesh";
  return m;
}

inline std::string case_of(const Record& r)
{
  const std::string label = r.text("label");
  const std::size_t slash = label.find('/');
  return slash == std::string::npos ? label : label.substr(slash + 1);
}

} // namespace report_internal

/// Writes OUT_DIR/REPORT.md and its SVG plots.
inline void write_report(const std::vector<Record>& all, const std::string& out_dir, const Report_options& options)
{
  using namespace report_internal;
  std::filesystem::create_directories(out_dir);
  std::ostringstream md;
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  md << "# DF_L1_skeleton benchmark report\n\n"
     << "Generated by `scripts/bench.sh` on " << date << "; do not edit by hand (the profile notes at the end come"
     << " from `benchmark/profile_notes.md`).\n\n"
     << "## Machine\n\n"
     << "- CPU: " << first_line_of("/proc/cpuinfo", "model name") << ", " << std::thread::hardware_concurrency()
     << " hardware threads\n- memory: " << first_line_of("/proc/meminfo", "MemTotal") << "\n- compiler: "
#ifdef __VERSION__
     << "g++ " << __VERSION__
#endif
     << ", CGAL " << CGAL_VERSION_STR << ", Release build\n";
  if(!options.command.empty())
    md << "- command: `" << options.command << "`\n";
  md << "\nTimes are wall seconds, the median over the runs with (min-max); a run goes from reading the"
        " input file to writing the skeleton. Peak MiB is the process's peak resident memory. Quality is"
        " measured against the shape's true skeleton as in the tests: *topology* (the designed numbers of"
        " components, cycles, ends and junctions), *ratio* (mean distance to the true axis over the local"
        " radius), *outside* (fraction of the skeleton's length outside the shape), *coverage* (fraction of"
        " the true axis the skeleton passes near).\n\n";

  // Headline: every method on the same 35,000-point clouds.
  const std::vector<Record> headline = series(all, "headline/");
  std::map<std::string, std::map<std::string, Record>> by_case; // case -> method -> record
  std::vector<std::string> cases;
  for(const Record& r : headline)
  {
    const std::string c = case_of(r);
    if(!by_case.count(c))
      cases.push_back(c);
    by_case[c][r.text("method")] = r;
  }
  std::vector<std::string> target_lines;
  if(!headline.empty())
  {
    md << "## Headline: the same clouds, every method\n\n"
       << headline.front().number("points") << " points per cloud, V = " << headline.front().number("resolution")
       << ", M = " << headline.front().number("samples_requested") << " samples, "
       << headline.front().number("threads") << " threads, " << headline.front().number("runs") << " runs.\n\n"
       << "| cloud | method | seconds | vs Poisson+MCF | peak MiB | topology | ratio | outside | coverage |"
          " components/cycles/ends/junctions |\n|---|---|---|---|---|---|---|---|---|---|\n";
    const char* methods[] = {"df_l1", "l1", "poisson_mcf", "mesh_mcf"};
    double worst_total = 0, worst_refinement = 0, worst_speedup = 1e300;
    bool quality_at_least = true;
    for(const std::string& c : cases)
      for(const char* m : methods)
      {
        if(!by_case[c].count(m))
          continue;
        const Record& r = by_case[c][m];
        std::string versus = "-";
        if(by_case[c].count("poisson_mcf") && std::string(m) != "poisson_mcf")
        {
          const double ratio = by_case[c]["poisson_mcf"].number("t.total") / r.number("t.total");
          versus = fixed(ratio, ratio < 10 ? 1 : 0) + "x faster";
          if(std::string(m) == "df_l1")
            worst_speedup = (std::min)(worst_speedup, ratio);
        }
        if(std::string(m) == "df_l1")
        {
          worst_total = (std::max)(worst_total, r.number("t.total"));
          worst_refinement = (std::max)(worst_refinement, r.number("t.refinement"));
          if(by_case[c].count("poisson_mcf"))
          {
            const Record& p = by_case[c]["poisson_mcf"];
            quality_at_least = quality_at_least && r.number("topology_ok") >= p.number("topology_ok") &&
                               r.number("axis_ratio") <= p.number("axis_ratio") + 1e-9 &&
                               r.number("outside") <= p.number("outside") + 1e-9;
          }
        }
        md << "| " << c << " | " << method_name(m) << " | " << seconds_spread(r, "total") << " | " << versus << " | "
           << fixed(r.number("peak_mib"), 0) << " | " << quality_cells(r) << " | " << topology_cell(r) << " |\n";
      }
    md << "\n";
    const auto target = [&](const std::string& what, const std::string& measured, bool met) {
      target_lines.push_back("| " + what + " | " + measured + " | " + (met ? "met" : "**not met**") + " |");
    };
    target("35,000 points, whole pipeline < 0.5 s (slowest headline cloud)", seconds(worst_total) + " s",
           worst_total < 0.5);
    target("35,000 points, refinement (contraction + graph) < 0.3 s", seconds(worst_refinement) + " s",
           worst_refinement < 0.3);
    if(worst_speedup < 1e300)
    {
      target(">= 5x faster than normals + Poisson + MCF (slowest ratio)", fixed(worst_speedup, 1) + "x",
             worst_speedup >= 5);
      target("quality at least as good as Poisson + MCF (topology, ratio, outside, every cloud)",
             quality_at_least ? "yes" : "no", quality_at_least);
    }

    md << "### Seconds per stage\n\n";
    for(const char* m : methods)
    {
      std::vector<Record> rows;
      for(const std::string& c : cases)
        if(by_case[c].count(m))
          rows.push_back(by_case[c][m]);
      if(rows.empty())
        continue;
      md << method_name(m) << ":\n\n";
      stage_table(md, rows, "cloud", case_of);
    }
  }

  // Scaling in the number of points.
  const std::vector<Record> points = series(all, "points/");
  if(!points.empty())
  {
    md << "## Scaling with the number of points\n\n" << points.front().text("shape") << ", "
       << points.front().text("variant") << ", V = " << points.front().number("resolution") << ", M = "
       << points.front().number("samples_requested") << ", " << points.front().number("threads") << " threads.\n\n";
    const std::string variant = points.front().text("variant");
    stage_table(md, points, "points", [&](const Record& r) {
      return fixed(r.number("points"), 0) + (r.text("variant") == variant ? "" : " (" + r.text("variant") + ")");
    });
    // the plot and the fits: the rows of the first variant (the others are single checks)
    std::vector<Record> same;
    for(const Record& r : points)
      if(r.text("variant") == variant)
        same.push_back(r);
    std::vector<std::pair<double, double>> xy, xy_large, xy_huge;
    Plot_series total{"total", colour(0)};
    std::vector<Plot_series> plot;
    for(const Record& r : same)
    {
      xy.emplace_back(r.number("points"), r.number("t.total"));
      if(r.number("points") >= 1e5 && r.number("points") <= 1e6)
        xy_large.emplace_back(r.number("points"), r.number("t.total"));
      if(r.number("points") >= 1e6)
        xy_huge.emplace_back(r.number("points"), r.number("t.total"));
      total.x.push_back(r.number("points"));
      total.y.push_back(r.number("t.total"));
      total.ymin.push_back(r.number("tmin.total"));
      total.ymax.push_back(r.number("tmax.total"));
    }
    plot.push_back(total);
    const std::vector<std::string> stages = stages_of(same.front());
    for(const std::string& s : stages)
    {
      if(!(same.back().number("t." + s) > 0.05 * same.back().number("t.total")))
        continue; // only the stages that matter at the largest size
      Plot_series p{s, colour(plot.size())};
      for(const Record& r : same)
      {
        p.x.push_back(r.number("points"));
        p.y.push_back((std::max)(1e-4, r.number("t." + s)));
        p.ymin.push_back((std::max)(1e-4, r.number("tmin." + s)));
        p.ymax.push_back((std::max)(1e-4, r.number("tmax." + s)));
      }
      plot.push_back(p);
    }
    write_loglog_svg(out_dir + "/scaling_points.svg", "seconds against input points", "input points", "seconds",
                     plot);
    const double slope = loglog_slope(xy), slope_large = loglog_slope(xy_large), slope_huge = loglog_slope(xy_huge);
    md << "![seconds against points](scaling_points.svg)\n\nFitted exponent of the total time against the number"
          " of points (least squares in log-log, " << variant << " rows): **"
       << fixed(slope, 2) << "** over the whole series, **" << fixed(slope_large, 2) << "** from 100k to 1M points"
       << (std::isnan(slope_huge) ? std::string() : ", **" + fixed(slope_huge, 2) + "** from 1M points on") << ".\n\n";
    // issue 5: a million points in under 10 s and 2 GiB; issue 21: ten million in under
    // 10 s and 1.5 GiB, whatever the variant
    for(const Record& r : points)
    {
      const double n = r.number("points");
      const bool million = n >= 9e5 && n <= 1.1e6, ten_million = n >= 9e6;
      if(!million && !ten_million)
        continue;
      const std::string name = fixed(n, 0) + " points" + (r.text("variant") == variant ? "" : " (" + r.text("variant") + ")");
      const double mib = ten_million ? 1536 : 2048;
      target_lines.push_back("| " + name + " < 10 s | " + seconds(r.number("t.total")) + " s | " +
                             (r.number("t.total") < 10 ? "met" : "**not met**") + " |");
      target_lines.push_back("| " + name + " < " + (ten_million ? "1.5" : "2") + " GiB peak | " +
                             fixed(r.number("peak_mib"), 0) + " MiB | " +
                             (r.number("peak_mib") < mib ? "met" : "**not met**") + " |");
    }
    if(!std::isnan(slope_large))
      target_lines.push_back("| time grows at most like N^1.15 from 100k to 1M points | N^" + fixed(slope_large, 2) +
                             " | " + (slope_large <= 1.15 ? "met" : "**not met**") + " |");
    if(!std::isnan(slope_huge))
      target_lines.push_back("| time grows at most like N^1.1 from 1M to 10M points | N^" + fixed(slope_huge, 2) +
                             " | " + (slope_huge <= 1.1 ? "met" : "**not met**") + " |");
  }

  const auto simple_series = [&](const std::string& prefix, const std::string& title, const std::string& column,
                                 const std::string& key) {
    const std::vector<Record> rows = series(all, prefix);
    if(rows.empty())
      return;
    md << "## " << title << "\n\n" << rows.front().text("shape") << ", " << rows.front().text("variant") << ", "
       << rows.front().number("points") << " points.\n\n";
    stage_table(md, rows, column, [&](const Record& r) { return fixed(r.number(key), 0); });
    md << "| " << column << " | samples | iterations | topology | ratio | outside | coverage |\n|---|---|---|---|---|---|---|\n";
    for(const Record& r : rows)
      md << "| " << fixed(r.number(key), 0) << " | " << fixed(r.number("samples"), 0) << " | "
         << fixed(r.number("iterations"), 0) << " | " << quality_cells(r) << " |\n";
    md << "\n";
  };
  simple_series("resolution/", "Voxel resolution V", "V", "resolution");
  simple_series("samples/", "Number of samples M", "M", "samples_requested");

  const std::vector<Record> threads = series(all, "threads/");
  if(!threads.empty())
  {
    md << "## Threads\n\nThe projection step (the contraction) is the parallel stage; the outlier, smoothing"
          " and distance stages are parallel too.\n\n";
    stage_table(md, threads, "threads, points",
                [](const Record& r) { return fixed(r.number("threads"), 0) + ", " + fixed(r.number("points"), 0); });
    std::map<double, std::map<double, Record>> by_points;
    for(const Record& r : threads)
      by_points[r.number("points")][r.number("threads")] = r;
    double worst = 1e300;
    for(auto& p : by_points)
      if(p.second.count(1) && p.second.count(2))
      {
        // the projection step alone when the results have it (older results: the contraction)
        const char* key = p.second[1].has("projection_seconds") && p.second[2].has("projection_seconds") ? "projection_seconds" : "t.contraction";
        const double of_medians = p.second[1].number(key) / p.second[2].number(key);
        // The runs alternate (1, 2, 1, 2, ...): the median of the ratios of the pairs
        // follows the machine's drift less than the ratio of the medians.
        const std::vector<double> one = split_numbers(p.second[1].text("projection_runs"));
        const std::vector<double> two = split_numbers(p.second[2].text("projection_runs"));
        const bool paired = !one.empty() && one.size() == two.size();
        double speedup = of_medians;
        if(paired)
        {
          std::vector<double> ratios;
          for(std::size_t i = 0; i < one.size(); ++i)
            ratios.push_back(one[i] / two[i]);
          speedup = spread(ratios).median;
        }
        md << "- " << fixed(p.first, 0) << " points (" << fixed(p.second[1].number("runs"), 0)
           << " runs each): projection step (the fixed-point iterations) " << fixed(speedup, 2) << "x faster on 2 threads";
        if(paired)
          md << " (median over the pairs of alternating runs; ratio of the medians " << fixed(of_medians, 2) << "x)";
        md << ", contraction stage "
           << fixed(p.second[1].number("t.contraction") / p.second[2].number("t.contraction"), 2) << "x, whole pipeline "
           << fixed(p.second[1].number("t.total") / p.second[2].number("t.total"), 2) << "x.\n";
        worst = (std::min)(worst, speedup);
      }
    md << "\n";
    if(worst < 1e300)
      target_lines.push_back("| projection step >= 1.7x faster on 2 threads than on 1 | " + fixed(worst, 2) + "x | " +
                             (worst >= 1.7 ? "met" : "**not met**") + " |");
  }

  const std::vector<Record> scans = series(all, "scan/");
  if(!scans.empty())
  {
    md << "## Real scans (`../shared/data`)\n\n| scan | method | points | seconds | peak MiB |"
          " components/cycles/ends/junctions |\n|---|---|---|---|---|---|\n";
    for(const Record& r : scans)
      md << "| " << r.text("input") << " | " << method_name(r.text("method")) << " | " << fixed(r.number("points"), 0)
         << " | " << seconds_spread(r, "total") << " | " << fixed(r.number("peak_mib"), 0) << " | " << topology_cell(r)
         << " |\n";
    md << "\n";
  }

  std::ostringstream head;
  if(!target_lines.empty())
  {
    head << "## Targets (issues 5 and 21)\n\n| target | measured | |\n|---|---|---|\n";
    for(const std::string& l : target_lines)
      head << l << "\n";
    head << "\n";
  }
  std::string text = md.str();
  const std::size_t at = text.find("## Headline");
  text.insert(at == std::string::npos ? text.size() : at, head.str());
  if(!options.notes.empty())
  {
    std::ifstream notes(options.notes);
    if(notes)
      text += std::string(std::istreambuf_iterator<char>(notes), std::istreambuf_iterator<char>());
  }
  std::ofstream(out_dir + "/REPORT.md") << text;
}

/// Prints, for every label and stage present in both, the stages that got more than
/// `tolerance` slower than the baseline (and those that got faster, for the record).
/// Stages under 10 ms are ignored: their noise is larger than any change.
inline void compare(const std::vector<Record>& baseline, const std::vector<Record>& now, double tolerance,
                    std::ostream& os)
{
  using namespace report_internal;
  std::size_t slower = 0, compared = 0;
  for(const Record& r : now)
    for(const Record& b : baseline)
    {
      if(b.text("label") != r.text("label") || b.text("method") != r.text("method"))
        continue;
      for(const auto& f : r.fields())
      {
        if(!starts_with(f.first, "t.") || !b.has(f.first))
          continue;
        const double was = b.number(f.first), is = r.number(f.first);
        if(!(was >= 0.01 || is >= 0.01))
          continue;
        ++compared;
        const double change = is / (std::max)(was, 1e-9) - 1;
        if(change > tolerance)
        {
          ++slower;
          os << "WARNING: " << r.text("label") << " " << f.first.substr(2) << ": " << seconds(is) << " s, was "
             << seconds(was) << " s (+" << fixed(100 * change, 0) << " %)\n";
        }
        else if(change < -tolerance)
          os << "faster: " << r.text("label") << " " << f.first.substr(2) << ": " << seconds(is) << " s, was "
             << seconds(was) << " s (" << fixed(100 * change, 0) << " %)\n";
      }
    }
  os << compared << " stage times compared with the baseline, " << slower << " more than "
     << fixed(100 * tolerance, 0) << " % slower\n";
}

} // namespace DF_L1_bench

#endif // DF_L1_BENCHMARK_BENCH_REPORT_H
