// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_skeleton: the command-line front end of the package.
// Exit status: 0 success, 1 bad input or failed output, 2 bad usage.

#include "heap_settings.h"
#include "options.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/write_svg_preview.h>
#include <CGAL/DF_L1_skeleton/IO/write_file_atomically.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <tbb/global_control.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
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

struct Settings
{
  std::string input, output, report, preview, stage = "final";
  bool preview_stages = false;
  int threads = 0; // 0: all cores
  long seed = 0;
  bool quiet = false;
  DF::Parameters parameters; // the library's, set from the options of parameter_table()
};

double peak_memory_mib()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}

// A JSON object written in insertion order, numbers with round-trip precision.
class Json_object
{
public:
  Json_object& number(const std::string& key, double x)
  {
    std::ostringstream s;
    if(std::isfinite(x))
      s << std::setprecision(15) << x;
    else
      s << "null";
    return raw(key, s.str());
  }
  Json_object& text(const std::string& key, const std::string& value)
  {
    std::string quoted = "\"";
    for(char c : value)
    {
      if(c == '"' || c == '\\')
        quoted += '\\';
      if(static_cast<unsigned char>(c) < 0x20)
        c = ' ';
      quoted += c;
    }
    return raw(key, quoted + "\"");
  }
  Json_object& boolean(const std::string& key, bool b) { return raw(key, b ? "true" : "false"); }
  Json_object& object(const std::string& key, const Json_object& o) { return raw(key, o.str("  ")); }
  Json_object& raw(const std::string& key, const std::string& value)
  {
    entries_.emplace_back(key, value);
    return *this;
  }
  // On one line: {"a": 1, "b": 2}.
  std::string inline_str() const
  {
    std::string s = "{";
    for(std::size_t i = 0; i < entries_.size(); ++i)
      s += (i ? ", \"" : "\"") + entries_[i].first + "\": " + entries_[i].second;
    return s + "}";
  }
  std::string str(const std::string& indent = "") const
  {
    std::string s = "{";
    for(std::size_t i = 0; i < entries_.size(); ++i)
      s += (i ? ",\n" : "\n") + indent + "  \"" + entries_[i].first + "\": " + entries_[i].second;
    return s + "\n" + indent + "}";
  }

private:
  std::vector<std::pair<std::string, std::string>> entries_;
};

class Stage_clock
{
public:
  explicit Stage_clock(bool quiet) : quiet_(quiet) {}
  template <class F>
  auto run(const std::string& name, F&& f)
  {
    if(!quiet_)
      std::cerr << "df_l1_skeleton: " << name << "..." << std::flush;
    const auto start = std::chrono::steady_clock::now();
    auto result = f();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    times_.number(name, seconds);
    if(!quiet_)
      std::cerr << " " << std::fixed << std::setprecision(3) << seconds << " s\n" << std::defaultfloat;
    return result;
  }
  const Json_object& times() const { return times_; }

private:
  bool quiet_;
  Json_object times_;
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
    {"preview-stages", "", "off", "with --stage final: add a row with the initial skeleton to the preview",
     [&](const std::string&) { s.preview_stages = true; }},
    {"threads", "N", "all cores", "number of threads",
     [&](const std::string& v) { s.threads = int(parse_integer("threads", v, 1, 1024)); }},
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
               "\nExit status: 0 success, 1 bad input or output, 2 bad usage.\n";
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

// The number of samples contracted (junction points of bridges come on top of them).
std::size_t contracted_count(const DF::Contracted_samples<Kernel>& c)
{
  return c.iterations.empty() ? 0 : c.iterations.front().size();
}

int run(const Settings& s)
{
  std::unique_ptr<tbb::global_control> thread_limit;
  if(s.threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                         std::size_t(s.threads));
  Stage_clock clock(s.quiet);
  const auto cloud = clock.run("read", [&] { return DF::read_point_cloud<Kernel>(s.input); });
  const std::vector<Point_3>& points = cloud.points;

  // The library resolves the derived defaults; the report states what it used. The
  // resolution goes to the constructor, whose test of flat input depends on it.
  typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;
  Skeletonization skeletonization(points, params::voxel_resolution(s.parameters.voxel_resolution));
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
    stage("contraction", &Skeletonization::contract);
    contracted = &skeletonization.contracted_samples();
    stage("skeleton", &Skeletonization::convert_to_skeleton);
    final_skeleton = &skeletonization.skeleton();
    if(boost::num_vertices(*final_skeleton) == 0)
      throw DF::Invalid_input(s.input + ": no skeleton: the contraction of " + std::to_string(contracted_count(*contracted)) +
                              " samples traced no branch (try --stage initial, or more --samples)");
  }
  // The skeleton written: the last one computed.
  const DF::Skeleton_graph<Kernel>* skeleton = final_skeleton ? final_skeleton : initial ? &initial->graph : nullptr;

  clock.run("write", [&] {
    if(skeleton)
      DF::write_skeleton(s.output, *skeleton);
    else
      write_voxels(s.output, grid, field);
    if(!s.preview.empty())
    {
      std::vector<DF::Preview_panel<Kernel>> rows;
      if(final_skeleton)
        rows.push_back({"final skeleton (" + DF::parameter_text(s.parameters, "skeletonization_method") + ")", final_skeleton});
      if(initial && (!final_skeleton || s.preview_stages))
        rows.push_back({"initial skeleton", &initial->graph});
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
    const double voxel_size = CGAL::to_double(grid.voxel_size);
    Json_object parameters;
    parameters.text("stage", s.stage)
      .number("threads", s.threads > 0 ? s.threads : double(tbb::this_task_arena::max_concurrency()))
      .number("seed", double(s.seed))
      .number("bbox_diagonal", skeletonization.bbox_diagonal())
      .text("denoising", DF::parameter_text(s.parameters, "denoising"))
      .number("denoising_neighbors", skeletonization.denoising_neighbors())
      .boolean("upsampling", skeletonization.upsampling())
      .number("upsampling_neighbors", skeletonization.upsampling_neighbors())
      .number("upsampling_radius", skeletonization.upsampling_radius())
      .number("voxel_resolution", skeletonization.voxel_resolution())
      .number("initial_voxel_size", skeletonization.initial_voxel_size())
      .number("initial_voxel_size_used", grid.levels.front().voxel_size)
      .number("refinement_levels", double(grid.levels.size() - 1))
      .number("voxel_size", voxel_size)
      .number("exterior_propagation_steps", skeletonization.exterior_propagation_steps())
      .number("outlier_component_size", skeletonization.outlier_component_size());
    if(initial)
      parameters.number("thinning_coefficient", skeletonization.thinning_coefficient())
        .raw("thinning_parameters", "[" + std::to_string(initial->thinning_parameters[0] * voxel_size) + ", " +
                                     std::to_string(initial->thinning_parameters[1] * voxel_size) + ", " +
                                     std::to_string(initial->thinning_parameters[2] * voxel_size) + "]")
        .number("spur_length_ratio", skeletonization.spur_length_ratio());
    if(contracted)
      parameters.text("method", DF::parameter_text(s.parameters, "skeletonization_method"))
        .number("number_of_samples", double(skeletonization.number_of_samples()))
        .number("repulsion_coefficient", skeletonization.repulsion_coefficient())
        .number("initial_support_radius", skeletonization.initial_support_radius())
        .number("support_radius_growth", skeletonization.support_radius_growth())
        .number("branch_directionality", skeletonization.branch_directionality())
        .number("number_of_iterations", skeletonization.number_of_iterations())
        .number("contraction_stages", skeletonization.contraction_stages());
    Json_object counts;
    counts.number("input_points", double(points.size()))
      .number("added_points", double(skeletonization.added_points().size()))
      .number("outlier_points", double(skeletonization.number_of_outliers()))
      .number("sparse_outlier_points", double(skeletonization.number_of_sparse_outliers()))
      .number("surface_noise", skeletonization.surface_noise())
      .number("residual_growth", skeletonization.residual_growth())
      .boolean("denoised", skeletonization.denoised())
      .number("outlier_clusters", double(skeletonization.outlier_voxel_statistics().components_removed))
      .number("shape_components", double(skeletonization.outlier_voxel_statistics().components_kept))
      .raw("grid", "[" + std::to_string(grid.dims[0]) + ", " + std::to_string(grid.dims[1]) + ", " +
                     std::to_string(grid.dims[2]) + "]")
      .number("boundary_voxels", double(grid.count(DF::Voxel_label::BOUNDARY)))
      .number("interior_voxels", double(grid.count(DF::Voxel_label::INTERIOR)))
      .number("exterior_voxels", double(grid.count(DF::Voxel_label::EXTERIOR)))
      .number("outlier_voxels", double(grid.count(DF::Voxel_label::OUTLIER)));
    if(field)
      counts.number("max_distance", CGAL::to_double(field->voxel_size) * field->maximum());
    // skeleton_*: the skeleton written (the final one with --stage final);
    // initial_skeleton_*: the initial one, when the final one was written.
    const auto skeleton_counts = [&](const std::string& prefix, const DF::Skeleton_graph<Kernel>& g) {
      const DF::Skeleton_statistics st = DF::skeleton_statistics(g);
      counts.number(prefix + "vertices", double(st.vertices))
        .number(prefix + "edges", double(st.edges))
        .number(prefix + "components", double(st.components))
        .number(prefix + "cycles", double(st.cycles))
        .number(prefix + "end_points", double(st.end_points))
        .number(prefix + "junctions", double(st.junctions));
    };
    if(initial)
    {
      counts.number("skeleton_voxels", double(initial->points.size()));
      skeleton_counts("skeleton_", *skeleton);
    }
    if(contracted)
    {
      skeleton_counts("initial_skeleton_", initial->graph);
      std::string stages = "[";
      for(std::size_t i = 0; i < contracted->stages.size(); ++i)
      {
        const DF::Contraction_stage& st = contracted->stages[i];
        Json_object o;
        o.number("iterations", st.iterations)
          .number("min_radius", st.min_radius)
          .number("mean_radius", st.mean_radius)
          .number("max_radius", st.max_radius)
          .number("free_samples", double(st.free_samples))
          .number("branch_samples", double(st.branch_samples))
          .number("projection_seconds", st.projection_seconds);
        stages += (i ? ",\n      " : "\n      ") + o.inline_str();
      }
      stages += contracted->stages.empty() ? "]" : "\n    ]";
      int iterations = 0;
      for(const DF::Contraction_stage& st : contracted->stages)
        iterations += st.iterations;
      counts.number("samples", double(contracted_count(*contracted)))
        .number("branch_points",
                double(std::count(contracted->roles.begin(), contracted->roles.end(), DF::Sample_role::BRANCH)))
        .number("iterations", iterations)
        .raw("contraction_stages", stages);
    }
    Json_object report;
    report.text("input", s.input).text("output", s.output).text("version", DF_L1_VERSION)
      .object("parameters", parameters).object("seconds", clock.times()).object("counts", counts)
      .number("peak_memory_mib", peak_memory_mib());
    DF::write_file_atomically(s.report, [&](std::ostream& os) { os << report.str() << "\n"; });
  }
  if(!s.quiet)
    std::cerr << "df_l1_skeleton: wrote " << s.output << (s.preview.empty() ? "" : " and " + s.preview)
              << (s.report.empty() ? "" : " and " + s.report) << "\n";
  return 0;
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
    if(settings.preview_stages && settings.preview.empty())
      throw Usage_error("--preview-stages needs --preview FILE.svg");
    if(settings.preview_stages && settings.stage != "final")
      throw Usage_error("--preview-stages needs --stage final (it adds the initial skeleton under the final one)");
  }
  catch(const Usage_error& e)
  {
    std::cerr << "df_l1_skeleton: " << e.what() << "\n";
    return 2;
  }
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
