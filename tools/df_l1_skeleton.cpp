// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_skeleton: the command-line front end of the package.
// Exit status: 0 success, 1 bad input or failed output, 2 bad usage, 128 + the signal
// (130, 143) when stopped by SIGINT or SIGTERM.

#include "heap_settings.h"
#include "options.h"
#include "report.h"
#include "stage_clock.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/write_svg_preview.h>
#include <CGAL/DF_L1_skeleton/IO/write_file_atomically.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
namespace DF = CGAL::DF_L1;
namespace params = CGAL::parameters;
using df_l1_tool::Usage_error;

// The stages the tool can stop after, in pipeline order.
const char* const STAGES[] = {"voxels", "distance", "initial", "final"};

// Position of a stage in STAGES, -1 if unknown.
int stage_index(const std::string& stage)
{
  for(int i = 0; i < int(std::size(STAGES)); ++i)
    if(stage == STAGES[i])
      return i;
  return -1;
}

// Faults. A run stopped by SIGINT or SIGTERM leaves no file: the outputs are written
// to temporary files (write_file_atomically) that one Atomic_file_group renames
// together at the end, and the handler removes the temporary files, then exits with
// 128 + the signal. Only the main thread writes, so the handler runs there: a worker
// thread that gets the signal forwards it (else the main thread could create a file
// just after the removal). A signal that comes while the group renames waits for the
// renames (a few system calls): the outputs are then all new, the status still 130/143.
pthread_t main_thread;
volatile std::sig_atomic_t deferred_signal = 0;

void write_to_stderr(const char* text) { (void)!::write(2, text, std::strlen(text)); }

void on_stop_signal(int signal)
{
  if(!pthread_equal(pthread_self(), main_thread))
  {
    pthread_kill(main_thread, signal);
    return;
  }
  if(!DF::remove_unfinished_files())
  {
    deferred_signal = signal;
    return;
  }
  write_to_stderr(signal == SIGINT ? "\ndf_l1_skeleton: interrupted (SIGINT); no output written\n"
                                   : "\ndf_l1_skeleton: terminated (SIGTERM); no output written\n");
  ::_exit(128 + signal);
}

void handle_stop_signals()
{
  main_thread = pthread_self();
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART; // a deferred signal must not fail the renames
  for(const int signal : {SIGINT, SIGTERM})
    sigaction(signal, &action, nullptr);
}

// Ends the run if a signal came while the outputs were renamed.
void exit_on_deferred_signal()
{
  if(deferred_signal == 0)
    return;
  write_to_stderr(deferred_signal == SIGINT ? "\ndf_l1_skeleton: interrupted (SIGINT) after the outputs were written\n"
                                            : "\ndf_l1_skeleton: terminated (SIGTERM) after the outputs were written\n");
  ::_exit(128 + deferred_signal);
}

// The input is mapped while it is read: a file truncated meanwhile by another process
// raises SIGBUS on the first access past its new end. While it lives, this reports that
// (the message is made beforehand: a handler may not allocate) and exits with 1. Other
// changes are found by the reader itself (size and modification time).
char bus_error_message[8192];

void on_bus_error(int)
{
  write_to_stderr(bus_error_message);
  ::_exit(1);
}

class Changed_input_report
{
public:
  explicit Changed_input_report(const std::string& input)
  {
    const std::string message =
      "\ndf_l1_skeleton: " + input + ": the file changed while it was being read (truncated)\n";
    std::snprintf(bus_error_message, sizeof(bus_error_message), "%s", message.c_str());
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = on_bus_error;
    sigemptyset(&action.sa_mask);
    sigaction(SIGBUS, &action, &previous_);
  }
  ~Changed_input_report() { sigaction(SIGBUS, &previous_, nullptr); }
  Changed_input_report(const Changed_input_report&) = delete;
  Changed_input_report& operator=(const Changed_input_report&) = delete;

private:
  struct sigaction previous_;
};

struct Settings
{
  std::string input, output, report, preview, segmentation, stage = "final";
  bool preview_stages = false;
  int threads = 0; // 0: all cores
  double max_memory = 0; // bytes; 0: the memory available at the start
  long seed = 0;
  bool quiet = false;
  DF::Parameters parameters; // the library's, set from the options of parameter_table()
};

// The tool's own options, then one per library parameter (made from
// DF::parameter_table(), under its canonical name and its earlier spellings).
std::vector<df_l1_tool::Option> option_table(Settings& s, bool& help, bool& version)
{
  using df_l1_tool::parse_integer;
  std::vector<df_l1_tool::Option> table{
    {"stage", "STAGE", "final", "stop after this stage: voxels, distance, initial or final",
     [&](const std::string& v) {
       if(stage_index(v) < 0)
         throw Usage_error("--stage must be voxels, distance, initial or final, got '" + v + "'");
       s.stage = v;
     }},
    {"report", "FILE.json", "none", "write the parameters used, timings and counts as JSON",
     [&](const std::string& v) { s.report = v; }},
    {"preview", "FILE.svg", "none", "write front, side and top views of the points and the skeleton",
     [&](const std::string& v) { s.preview = v; }},
    {"segmentation", "FILE.ply", "none",
     "with --stage initial or final: write every input point with the index of its skeleton vertex and of its branch "
     "(-1 for outliers)",
     [&](const std::string& v) { s.segmentation = v; }},
    {"preview-stages", "", "off", "with --stage final: add rows with the contracted samples, the initial skeleton, the distance field and the voxels to the preview",
     [&](const std::string&) { s.preview_stages = true; }},
    {"threads", "N", "all cores", "number of threads (exactly N, even beyond the cores; the outputs do not depend on it)",
     [&](const std::string& v) { s.threads = int(parse_integer("threads", v, 1, 1024)); }},
    {"max-memory", "SIZE", "available memory",
     "refuse a run whose estimated peak memory exceeds SIZE (such as 512M or 4G), naming the parameter to lower",
     [&](const std::string& v) { s.max_memory = df_l1_tool::parse_bytes("max-memory", v); }},
    {"seed", "S", "0", "random seed, written to the report (the stages are deterministic and draw no random numbers)",
     [&](const std::string& v) { s.seed = parse_integer("seed", v, 0, 2147483647L); }},
    {"quiet", "", "off", "no progress on stderr", [&](const std::string&) { s.quiet = true; }},
  };
  for(const DF::Parameter_info& info : DF::parameter_table())
  {
    const std::string name = info.name;
    std::string help = info.help;
    if(info.kind == DF::Parameter_kind::INTEGER || info.kind == DF::Parameter_kind::REAL)
    {
      const std::string range = info.range_text();
      if(range != "(0, inf)" && range != "[0, inf)")
        help += ", in " + range;
    }
    std::string also;
    for(const DF::Option_alias& alias : info.aliases)
      if(alias.option)
        also += std::string(also.empty() ? "" : ", ") + "--" + alias.option + (alias.value ? "" : std::string(" ") + info.argument);
    if(!also.empty())
      help += "; also " + also;
    const auto set = [&s, name](const std::string& option, const std::string& value) {
      try
      {
        DF::set_parameter(s.parameters, name, value);
      }
      catch(const DF::Invalid_input& e)
      {
        throw Usage_error("--" + option + ": " + e.what());
      }
    };
    const std::string option = info.option();
    table.push_back({option, info.argument, info.default_text, help, [set, option](const std::string& v) { set(option, v); }});
    for(const DF::Option_alias& alias : info.aliases)
      if(alias.option)
      {
        const std::string old = alias.option;
        const std::string fixed = alias.value ? alias.value : "";
        table.push_back({old, alias.value ? "" : info.argument, "", "",
                         [set, old, fixed](const std::string& v) { set(old, fixed.empty() ? v : fixed); }});
      }
  }
  table.push_back({"help", "", "", "show this help", [&](const std::string&) { help = true; }});
  table.push_back({"version", "", "", "show the version", [&](const std::string&) { version = true; }});
  return table;
}

void print_help(const std::vector<df_l1_tool::Option>& table)
{
  std::cout << "usage: df_l1_skeleton [INPUT] [OUTPUT] [options]\n\n"
               "Extracts the curve skeleton of a point cloud (distance-field guided L1-median).\n"
               "Stages: voxels < distance < initial (voxel thinning) < final (L1-median contraction\n"
               "of samples onto the skeleton, then the skeleton graph); --stage stops after one.\n\n"
               "INPUT   .xyz .pts .txt (x y z [nx ny nz ...]), .ply (ascii or binary), .off;\n"
               "        default: the bundled example " DF_L1_DEFAULT_INPUT "\n"
               "OUTPUT  by extension: .obj (v/l lines), .ply (vertex x y z radius, edge),\n"
               "        .polylines.txt (one 'n x1 y1 z1 ...' line per branch); default skeleton.obj;\n"
               "        the final skeleton, or the initial one with --stage initial.\n"
               "        With --stage voxels or distance: a .ply of the voxel centres with their\n"
               "        label (0 exterior, 1 boundary, 2 interior, 3 outlier; exterior voxels are\n"
               "        omitted) and distance (input units; -1 when not computed); default voxels.ply.\n\n"
               "options:\n";
  for(const df_l1_tool::Option& o : table)
  {
    if(o.help.empty()) // an earlier spelling, listed with its option
      continue;
    std::string left = "  --" + o.name + (o.argument.empty() ? "" : " " + o.argument);
    left.resize((std::max)(left.size() + 1, std::size_t(36)), ' ');
    std::cout << left << o.help;
    if(!o.default_text.empty())
      std::cout << " (default: " << o.default_text << ")";
    std::cout << "\n";
  }
  std::cout << "\nThe --report JSON has parameters (the values used, derived ones resolved), seconds per\n"
               "stage and counts; with --stage final also the contraction's parameters and its\n"
               "per-stage support radii (counts.contraction_stages).\n"
               "\nExit status: 0 success, 1 bad input or output, 2 bad usage, 130/143 stopped by\n"
               "SIGINT/SIGTERM (no output is left: the outputs appear together at the end).\n";
}

bool has_suffix(std::string s, const std::string& suffix)
{
  for(char& c : s)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void write_voxels(const std::string& path, const DF::Voxel_grid<Kernel>& grid,
                  const DF::Distance_field<Kernel>* field)
{
  std::vector<Point_3> centres;
  DF::Ply_point_property label{"label", true, {}}, distance{"distance", false, {}};
  for(std::size_t v = 0; v < grid.size(); ++v)
    if(grid.labels[v] != DF::Voxel_label::EXTERIOR)
    {
      centres.push_back(grid.center(v));
      label.values.push_back(double(int(grid.labels[v])));
      distance.values.push_back(field ? CGAL::to_double(field->distance(v)) : -1.0);
    }
  DF::write_point_ply(path, centres, {label, distance});
}

int run_stages(const Settings& s)
{
  df_l1_tool::Stage_clock clock(s.quiet);
  const double max_memory = s.max_memory > 0 ? s.max_memory : DF::internal::available_memory_bytes();
  const auto cloud = clock.run("read", [&] {
    const Changed_input_report changed_input(s.input);
    return DF::read_point_cloud<Kernel>(s.input);
  });
  const std::vector<Point_3>& points = cloud.points;

  // The library resolves the derived defaults; the report states what it used. The
  // resolution goes to the constructor, whose test of flat input depends on it.
  typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;
  Skeletonization skeletonization(points, params::voxel_resolution(s.parameters.voxel_resolution,
                                           params::max_memory(max_memory)));
  skeletonization.set_parameters(s.parameters);
  const auto stage = [&](const char* name, void (Skeletonization::*f)()) {
    clock.run(name, [&] {
      (skeletonization.*f)();
      return 0;
    });
  };
  // Scattered outliers go before voxelization; the voxel test catches the clusters.
  stage("outlier_points", &Skeletonization::flag_outliers);
  stage("denoising", &Skeletonization::denoise);
  if(skeletonization.upsampling())
    stage("upsampling", &Skeletonization::upsample);
  stage("voxelization", &Skeletonization::voxelize);
  stage("outliers", &Skeletonization::remove_outlier_voxels);
  const DF::Voxel_grid<Kernel>& grid = skeletonization.voxel_grid();
  const DF::Distance_field<Kernel>* field = nullptr;
  if(s.stage != "voxels")
  {
    stage("distance", &Skeletonization::compute_distance_field);
    field = &skeletonization.distance_field();
  }
  const int last_stage = stage_index(s.stage);
  const DF::Initial_skeleton<Kernel>* initial = nullptr;
  if(last_stage >= stage_index("initial"))
  {
    stage("initial", &Skeletonization::extract_initial_skeleton);
    initial = &skeletonization.initial_skeleton();
    if(boost::num_vertices(initial->graph) == 0)
      throw DF::Invalid_input(s.input + ": no skeleton: the points enclose no volume at voxel resolution " +
                              std::to_string(skeletonization.voxel_resolution()) +
                              " (flat, linear or too sparse input; try --stage voxels to look at the voxels)");
  }
  const DF::Contracted_samples<Kernel>* contracted = nullptr;
  const DF::Skeleton_graph<Kernel>* final_skeleton = nullptr;
  if(last_stage >= stage_index("final"))
  {
    stage("contraction", &Skeletonization::contract_until_convergence);
    contracted = &skeletonization.contracted_samples();
    stage("skeleton", &Skeletonization::convert_to_skeleton);
    final_skeleton = &skeletonization.skeleton();
    if(boost::num_vertices(*final_skeleton) == 0)
      throw DF::Invalid_input(s.input + ": no skeleton: the contraction of " +
                              std::to_string(df_l1_tool::contracted_count(*contracted)) +
                              " samples traced no branch (try --stage initial, or more --samples)");
  }
  // The skeleton written: the last one computed.
  const DF::Skeleton_graph<Kernel>* skeleton = final_skeleton ? final_skeleton : initial ? &initial->graph : nullptr;

  // Every output waits in its temporary file until all are written (see on_stop_signal).
  DF::Atomic_file_group outputs;
  clock.run("write", [&] {
    if(skeleton)
      DF::write_skeleton(s.output, *skeleton);
    else
      write_voxels(s.output, grid, field);
    if(!s.segmentation.empty())
    {
      const DF::Point_segmentation segments = DF::segment_points(points, *skeleton);
      DF::Ply_point_property vertex{"vertex", true, {}}, branch{"branch", true, {}};
      vertex.values.assign(segments.vertex.begin(), segments.vertex.end());
      branch.values.assign(segments.branch.begin(), segments.branch.end());
      DF::write_point_ply(s.segmentation, points, {vertex, branch});
    }
    if(!s.preview.empty())
    {
      std::vector<DF::Preview_panel<Kernel>> rows;
      std::vector<Point_3> kept_samples;
      if(final_skeleton)
        rows.push_back({"final skeleton (" + DF::parameter_text(s.parameters, "skeletonization_method") + ")", final_skeleton});
      if(contracted && s.preview_stages)
      {
        for(std::size_t i = 0; i < contracted->points.size(); ++i)
          if(contracted->roles[i] != DF::Sample_role::REMOVED)
            kept_samples.push_back(contracted->points[i]);
        DF::Preview_panel<Kernel> panel;
        panel.title = "contracted samples";
        panel.stage_points = &kept_samples;
        rows.push_back(panel);
      }
      if(initial && (!final_skeleton || s.preview_stages))
        rows.push_back({"initial skeleton", &initial->graph});
      if(field && (!initial || s.preview_stages))
      {
        DF::Preview_panel<Kernel> panel;
        panel.title = "distance field";
        panel.distance_field = field;
        rows.push_back(panel);
      }
      if(!field || s.preview_stages)
      {
        DF::Preview_panel<Kernel> panel;
        panel.title = "voxels";
        panel.voxels = &grid;
        rows.push_back(panel);
      }
      DF::Preview_options options;
      options.title = s.input;
      if(rows.empty())
        DF::write_svg_preview(s.preview, points, options);
      else
        DF::write_svg_preview(s.preview, points, rows, options);
    }
    return 0;
  });

  if(!s.report.empty())
  {
    const std::string report =
      df_l1_tool::report_json(s, skeletonization, grid, field, initial, contracted, final_skeleton, clock);
    DF::write_file_atomically(s.report, [&](std::ostream& os) { os << report << "\n"; });
  }
  outputs.commit();
  exit_on_deferred_signal();
  if(!s.quiet)
    std::cerr << "df_l1_skeleton: wrote " << s.output << (s.preview.empty() ? "" : " and " + s.preview)
              << (s.segmentation.empty() ? "" : " and " + s.segmentation)
              << (s.report.empty() ? "" : " and " + s.report) << "\n";
  return 0;
}

// Runs the whole computation with exactly `--threads` threads. An explicit arena has
// that many slots even beyond the core count (global_control alone only lowers the
// limit), and the global limit lets that many threads join it; the report states the
// arena's concurrency. The outputs do not depend on the number (test [threads]).
int run(const Settings& s)
{
  if(s.threads <= 0)
    return run_stages(s);
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(s.threads));
  tbb::task_arena arena(s.threads);
  return arena.execute([&] { return run_stages(s); });
}

} // namespace

int main(int argc, char** argv)
{
  df_l1_tool::keep_large_buffers_on_heap();
  Settings settings;
  bool help = false, version = false;
  try
  {
    const auto table = option_table(settings, help, version);
    const std::vector<std::string> positional = df_l1_tool::parse_options(argc, argv, table);
    if(help)
    {
      print_help(table);
      return 0;
    }
    if(version)
    {
      std::cout << "df_l1_skeleton " DF_L1_VERSION "\n";
      return 0;
    }
    if(positional.size() > 2)
      throw Usage_error("too many arguments (expected [INPUT] [OUTPUT])");
    settings.input = positional.size() > 0 ? positional[0] : DF_L1_DEFAULT_INPUT;
    const bool voxel_stage = stage_index(settings.stage) < stage_index("initial");
    settings.output = positional.size() > 1 ? positional[1] : (voxel_stage ? "voxels.ply" : "skeleton.obj");
    if(voxel_stage && !has_suffix(settings.output, ".ply"))
      throw Usage_error("--stage " + settings.stage + " writes voxels: OUTPUT must end in .ply");
    if(!voxel_stage && !has_suffix(settings.output, ".obj") && !has_suffix(settings.output, ".ply") &&
       !has_suffix(settings.output, ".polylines.txt"))
      throw Usage_error("OUTPUT must end in .obj, .ply or .polylines.txt, got '" + settings.output + "'");
    if(!settings.preview.empty() && !has_suffix(settings.preview, ".svg"))
      throw Usage_error("--preview expects a .svg file");
    if(!settings.report.empty() && !has_suffix(settings.report, ".json"))
      throw Usage_error("--report expects a .json file");
    if(!settings.segmentation.empty() && !has_suffix(settings.segmentation, ".ply"))
      throw Usage_error("--segmentation expects a .ply file");
    if(!settings.segmentation.empty() && voxel_stage)
      throw Usage_error("--segmentation needs --stage initial or final (it labels the points by skeleton vertex and branch)");
    if(settings.preview_stages && settings.preview.empty())
      throw Usage_error("--preview-stages needs --preview FILE.svg");
    if(settings.preview_stages && settings.stage != "final")
      throw Usage_error("--preview-stages needs --stage final (it adds the earlier stages under the final skeleton)");
  }
  catch(const Usage_error& e)
  {
    std::cerr << "df_l1_skeleton: " << e.what() << "\n";
    return 2;
  }
  handle_stop_signals();
  try
  {
    return run(settings);
  }
  catch(const CGAL::DF_L1::Invalid_input& e)
  {
    const std::string what = e.what();
    // Library messages name the stage; the file name makes them actionable.
    std::cerr << "\ndf_l1_skeleton: " << (what.compare(0, settings.input.size(), settings.input) == 0 ? "" : settings.input + ": ")
              << what << "\n";
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "\ndf_l1_skeleton: " << settings.input << ": out of memory (try a lower --voxel-resolution"
              << (settings.stage == "final" ? " or --samples" : "") << ")\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "\ndf_l1_skeleton: " << e.what() << "\n";
  }
  return 1;
}
