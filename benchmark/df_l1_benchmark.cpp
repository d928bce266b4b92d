// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_benchmark: seconds per stage, peak memory and skeleton quality of
// DF_L1_skeleton and of the skeletonizers a CGAL user would compare it with, on the same
// inputs. scripts/bench.sh runs the suite and writes benchmark/REPORT.md.
//
//   df_l1_benchmark run METHOD INPUT.xyz [options]   one result line on stdout
//   df_l1_benchmark report RESULTS.tsv OUT_DIR [--command TEXT] [--notes FILE]
//   df_l1_benchmark compare BASELINE.tsv RESULTS.tsv [--tolerance 0.25]
//
// METHOD: df_l1 (ours), l1 (our plain L1-medial mode), poisson_mcf (normals by
// jet_estimate_normals + mst_orient_normals, Poisson surface reconstruction, then CGAL's
// Mean_curvature_flow_skeletonization on the mesh) or mesh_mcf (MCF on a closed mesh of
// the synthetic shape's analytic signed distance: MCF's best case; INPUT is only used
// for the voxel size of the quality measure).

#include "bench_record.h"
#include "bench_report.h"
#include "heap_settings.h"

#include "evaluation/skeleton_quality.h"
#include "evaluation/synthetic_shapes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>
#include <CGAL/DF_L1_skeleton/skeleton_statistics.h>

#include <CGAL/Implicit_surface_3.h>
#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>
#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/make_surface_mesh.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>

#include <tbb/global_control.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef CGAL::Mean_curvature_flow_skeletonization<Mesh> Mcf;
namespace DF = CGAL::DF_L1;
namespace params = CGAL::parameters;
using DF_L1_bench::Record;

double peak_memory_mib()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
}

struct Options
{
  std::string method, input, shape, variant = "clean", label;
  int resolution = 100, samples = 1500, runs = 5;
  std::vector<int> threads = {2};
};

// Seconds of each stage over the runs, in the order the stages first ran, and the peak
// resident memory after each stage of the first run (the process peak so far: it
// only grows, so a stage's figure is the largest footprint up to its end).
class Stage_clock
{
public:
  template <class F>
  auto time(const std::string& stage, F&& f)
  {
    const auto start = std::chrono::steady_clock::now();
    struct Done
    {
      Stage_clock* clock;
      const std::string* stage;
      std::chrono::steady_clock::time_point start;
      ~Done() { clock->add(*stage, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()); }
    } done{this, &stage, start};
    return f();
  }
  void next_run()
  {
    ++run_;
    totals_.push_back(0);
  }
  void write(Record& r) const
  {
    for(const std::string& stage : order_)
    {
      const DF_L1_bench::Spread s = DF_L1_bench::spread(seconds_.at(stage));
      r.set("t." + stage, s.median).set("tmin." + stage, s.min).set("tmax." + stage, s.max);
    }
    const DF_L1_bench::Spread s = DF_L1_bench::spread(totals_);
    r.set("t.total", s.median).set("tmin.total", s.min).set("tmax.total", s.max);
    for(const std::string& stage : order_)
      r.set("mib." + stage, memory_.at(stage));
  }
  double median(const std::string& stage) const { return DF_L1_bench::spread(seconds_.at(stage)).median; }

private:
  void add(const std::string& stage, double seconds)
  {
    if(!seconds_.count(stage))
      order_.push_back(stage);
    seconds_[stage].push_back(seconds);
    totals_.back() += seconds;
    if(run_ == 1)
      memory_[stage] = peak_memory_mib();
  }
  int run_ = 0;
  std::vector<std::string> order_;
  std::map<std::string, std::vector<double>> seconds_;
  std::map<std::string, double> memory_;
  std::vector<double> totals_;
};

// Where a run writes its skeleton (the write is part of the pipeline's time).
std::string scratch_path(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("df_l1_benchmark_" + std::to_string(::getpid()) + "_" + name))
    .string();
}

// The longest side of the points' bounding box over V: the finest voxel of our grid,
// used as the unit of every method's quality tolerances.
double voxel_size_of(const std::vector<Point_3>& points, int resolution)
{
  const CGAL::Bbox_3 b = CGAL::bbox_3(points.begin(), points.end());
  return (std::max)({b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin()}) / resolution;
}

template <class Graph>
void write_quality(Record& r, const Options& o, const Graph& g, double voxel_size)
{
  const DF::Skeleton_statistics st = DF::skeleton_statistics(g);
  r.set("vertices", double(st.vertices)).set("components", double(st.components)).set("cycles", double(st.cycles));
  r.set("ends", double(st.end_points)).set("junctions", double(st.junctions));
  if(o.shape.empty())
    return;
  const DF_L1_test::Shape shape = DF_L1_test::shape_by_name(o.shape);
  const DF_L1_test::Skeleton_quality q = DF_L1_test::measure_quality(shape, g, voxel_size);
  const bool noisy = DF_L1_test::variant_by_name(o.variant) != DF_L1_test::Variant::clean;
  r.set("topology_ok", DF_L1_test::topology_matches(shape.expected_topology(), q.topology, noisy) ? 1.0 : 0.0);
  r.set("axis_ratio", q.mean_axis_ratio).set("outside", q.outside_fraction).set("coverage", q.axis_coverage);
}

template <class Graph>
void write_obj(const std::string& path, const Graph& g)
{
  std::ofstream out(path);
  out.precision(17);
  for(auto v : CGAL::make_range(boost::vertices(g)))
    out << "v " << g[v].point << "\n";
  for(auto e : CGAL::make_range(boost::edges(g)))
    out << "l " << boost::source(e, g) + 1 << " " << boost::target(e, g) + 1 << "\n";
  if(!out)
    throw std::runtime_error("cannot write " + path);
}

// The runs of our method on one input and one number of threads, made one at a time, so
// that runs on different numbers of threads can alternate (in one process, the memory
// figures of the later ones include the peaks of the earlier ones).
class Our_runs
{
public:
  explicit Our_runs(const Options& o) : o_(o), output_(scratch_path("skeleton.obj")) {}

  void run_once(bool last)
  {
    typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;
    const DF::Skeletonization_method method =
      o_.method == "l1" ? DF::Skeletonization_method::L1_MEDIAL : DF::Skeletonization_method::DISTANCE_FIELD_GUIDED;
    clock_.next_run();
    const auto cloud = clock_.time("read", [&] { return DF::read_point_cloud<Kernel>(o_.input); });
    Skeletonization s(cloud.points,
                      params::skeletonization_method(
                        method, params::voxel_resolution(o_.resolution, params::number_of_samples(std::size_t(o_.samples)))));
    const auto stage = [&](const char* name, void (Skeletonization::*f)()) {
      clock_.time(name, [&] {
        (s.*f)();
        return 0;
      });
    };
    stage("outlier_points", &Skeletonization::flag_outliers);
    stage("denoising", &Skeletonization::denoise);
    stage("upsampling", &Skeletonization::upsample);
    stage("voxelization", &Skeletonization::voxelize);
    stage("outlier_voxels", &Skeletonization::remove_outlier_voxels);
    stage("distance", &Skeletonization::compute_distance_field);
    stage("initial", &Skeletonization::extract_initial_skeleton);
    stage("contraction", &Skeletonization::contract_until_convergence);
    projection_.push_back(0);
    for(const auto& st : s.contracted_samples().stages)
      projection_.back() += st.projection_seconds;
    stage("skeleton", &Skeletonization::convert_to_skeleton);
    clock_.time("write", [&] {
      DF::write_skeleton(output_, s.skeleton());
      return 0;
    });
    if(last)
    {
      r_.set("points", double(cloud.points.size()));
      int iterations = 0;
      for(const auto& st : s.contracted_samples().stages)
        iterations += st.iterations;
      r_.set("samples", double(s.contracted_samples().points.size())).set("iterations", double(iterations));
      r_.set("contraction_stages", double(s.contracted_samples().stages.size()));
      r_.set("denoised", s.denoised() ? 1.0 : 0.0);
      write_quality(r_, o_, s.skeleton(), CGAL::to_double(s.distance_field().voxel_size));
    }
  }

  Record result()
  {
    std::remove(output_.c_str());
    r_.set("t.refinement", clock_.median("contraction") + clock_.median("skeleton"));
    r_.set("projection_seconds", DF_L1_bench::spread(projection_).median);
    // every run's, in run order: runs on different numbers of threads alternate, so the
    // report can pair them
    r_.set("projection_runs", DF_L1_bench::join_numbers(projection_));
    clock_.write(r_);
    return r_;
  }

private:
  const Options& o_;
  std::string output_;
  Stage_clock clock_;
  Record r_;
  std::vector<double> projection_; // seconds of the projection step (inside the contraction), per run
};

Record run_ours(const Options& o)
{
  Our_runs runs(o);
  for(int run = 0; run < o.runs; ++run)
    runs.run_once(run + 1 == o.runs);
  return runs.result();
}

Record run_poisson_mcf(const Options& o)
{
  typedef std::pair<Point_3, Vector_3> Point_with_normal;
  typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
  typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;
  const std::string output = scratch_path("mcf.obj");
  Stage_clock clock;
  Record r;
  for(int run = 0; run < o.runs; ++run)
  {
    clock.next_run();
    const auto cloud = clock.time("read", [&] { return DF::read_point_cloud<Kernel>(o.input); });
    std::vector<Point_with_normal> points;
    points.reserve(cloud.points.size());
    for(const Point_3& p : cloud.points)
      points.emplace_back(p, Vector_3(0, 0, 0));
    const auto np = params::point_map(Point_map()).normal_map(Normal_map());
    // The neighbourhood sizes of CGAL's Poisson reconstruction example.
    clock.time("normals", [&] {
      CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(points, 18, np);
      return 0;
    });
    clock.time("orientation", [&] {
      points.erase(CGAL::mst_orient_normals(points, 18, np), points.end());
      return 0;
    });
    Mesh mesh;
    const bool reconstructed = clock.time("poisson", [&] {
      const double spacing = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(points, 6, np);
      return CGAL::poisson_surface_reconstruction_delaunay(points.begin(), points.end(), Point_map(), Normal_map(),
                                                            mesh, spacing);
    });
    if(!reconstructed || mesh.number_of_faces() == 0)
      throw std::runtime_error("Poisson reconstruction failed on " + o.input);
    Mcf::Skeleton skeleton;
    clock.time("mcf", [&] {
      CGAL::extract_mean_curvature_flow_skeleton(mesh, skeleton);
      return 0;
    });
    clock.time("write", [&] {
      write_obj(output, skeleton);
      return 0;
    });
    if(run + 1 == o.runs)
    {
      r.set("points", double(cloud.points.size())).set("oriented_points", double(points.size()));
      r.set("mesh_vertices", double(mesh.number_of_vertices())).set("mesh_closed", CGAL::is_closed(mesh) ? 1.0 : 0.0);
      write_quality(r, o, skeleton, voxel_size_of(cloud.points, o.resolution));
    }
  }
  std::remove(output.c_str());
  clock.write(r);
  return r;
}

Record run_mesh_mcf(const Options& o)
{
  if(o.shape.empty())
    throw std::invalid_argument("mesh_mcf needs --shape");
  const DF_L1_test::Shape shape = DF_L1_test::shape_by_name(o.shape);
  const double voxel = voxel_size_of(DF::read_point_cloud<Kernel>(o.input).points, o.resolution);
  typedef CGAL::Surface_mesh_default_triangulation_3 Tr;
  typedef Tr::Geom_traits GT;
  typedef CGAL::Complex_2_in_triangulation_3<Tr> C2t3;
  const auto distance = [&shape](const GT::Point_3& p) { return GT::FT(shape.signed_distance(Point_3(p.x(), p.y(), p.z()))); };
  typedef CGAL::Implicit_surface_3<GT, decltype(distance)> Surface;
  // The mesher needs a point inside (the function negative) at the sphere's centre.
  const Point_3 inner = shape.skeleton_polylines().front().points.front();
  const double diagonal = shape.bbox_diagonal();
  Stage_clock clock;
  Record r;
  for(int run = 0; run < o.runs; ++run)
  {
    clock.next_run();
    Mesh mesh;
    clock.time("meshing", [&] {
      Tr tr;
      C2t3 c2t3(tr);
      const Surface surface(distance, GT::Sphere_3(GT::Point_3(inner.x(), inner.y(), inner.z()), 4 * diagonal * diagonal),
                            1e-6);
      // Facets of about a voxel, within a tenth of a voxel of the surface.
      CGAL::Surface_mesh_default_criteria_3<Tr> criteria(25, voxel, 0.1 * voxel);
      CGAL::make_surface_mesh(c2t3, surface, criteria, CGAL::Manifold_tag());
      CGAL::facets_in_complex_2_to_triangle_mesh(c2t3, mesh);
      return 0;
    });
    Mcf::Skeleton skeleton;
    clock.time("mcf", [&] {
      CGAL::extract_mean_curvature_flow_skeleton(mesh, skeleton);
      return 0;
    });
    if(run + 1 == o.runs)
    {
      r.set("mesh_vertices", double(mesh.number_of_vertices())).set("mesh_closed", CGAL::is_closed(mesh) ? 1.0 : 0.0);
      write_quality(r, o, skeleton, voxel);
    }
  }
  clock.write(r);
  return r;
}

// Prints the result line of one method and one number of threads.
void print_line(const Options& o, int threads, const Record& m)
{
  std::string label = o.label.empty() ? std::string("-") : o.label;
  const std::size_t at = label.find("{threads}");
  if(at != std::string::npos)
    label.replace(at, 9, std::to_string(threads));
  Record r;
  r.set("label", label).set("method", o.method);
  r.set("input", std::filesystem::path(o.input).filename().string());
  r.set("shape", o.shape.empty() ? std::string("-") : o.shape).set("variant", o.variant);
  r.set("resolution", double(o.resolution)).set("samples_requested", double(o.samples));
  r.set("threads", double(threads)).set("runs", double(o.runs));
  for(const auto& f : m.fields())
    r.set(f.first, f.second);
  r.set("peak_mib", peak_memory_mib());
  std::cout << r.line() << std::endl;
}

int run(const Options& o)
{
  if(o.threads.size() > 1)
  {
    // Our method on several numbers of threads: the runs alternate (1, 2, 1, 2, ...) so
    // that the ratios between them do not follow the drift of the machine's speed.
    if(o.method != "df_l1" && o.method != "l1")
      throw std::invalid_argument("several numbers of threads: df_l1 or l1 only");
    std::vector<std::unique_ptr<Our_runs>> runs;
    for(std::size_t t = 0; t < o.threads.size(); ++t)
      runs.push_back(std::make_unique<Our_runs>(o));
    for(int run = 0; run < o.runs; ++run)
      for(std::size_t t = 0; t < o.threads.size(); ++t)
      {
        const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads[t]));
        runs[t]->run_once(run + 1 == o.runs);
      }
    for(std::size_t t = 0; t < o.threads.size(); ++t)
      print_line(o, o.threads[t], runs[t]->result());
    return 0;
  }
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads[0]));
  Record m;
  if(o.method == "df_l1" || o.method == "l1")
    m = run_ours(o);
  else if(o.method == "poisson_mcf")
    m = run_poisson_mcf(o);
  else if(o.method == "mesh_mcf")
    m = run_mesh_mcf(o);
  else
    throw std::invalid_argument("unknown method '" + o.method + "' (df_l1, l1, poisson_mcf, mesh_mcf)");
  print_line(o, o.threads[0], m);
  return 0;
}

void usage(std::ostream& os)
{
  os << "usage: df_l1_benchmark run METHOD INPUT [--shape NAME] [--variant NAME] [--resolution V]\n"
        "                          [--samples M] [--threads T[,T...]] [--runs R] [--label TEXT]\n"
        "       df_l1_benchmark report RESULTS.tsv OUT_DIR [--command TEXT] [--notes FILE]\n"
        "       df_l1_benchmark compare BASELINE.tsv RESULTS.tsv [--tolerance FRACTION]\n"
        "METHOD: df_l1 | l1 | poisson_mcf | mesh_mcf. `run` prints one line of tab-separated\n"
        "key=value fields: t.STAGE (median seconds), tmin./tmax. (over the runs), mib.STAGE\n"
        "(peak resident MiB at the end of the stage, first run), counts and quality.\n"
        "Several numbers of threads (df_l1, l1): one line each, their runs alternating;\n"
        "'{threads}' in the label is replaced by the number.\n";
}

} // namespace

int main(int argc, char** argv)
{
  df_l1_tool::keep_large_buffers_on_heap(); // as the tool does, so that the figures are the tool's
  try
  {
    std::vector<std::string> a(argv + 1, argv + argc);
    if(a.empty() || a[0] == "--help" || a[0] == "-h")
    {
      usage(a.empty() ? std::cerr : std::cout);
      return a.empty() ? 2 : 0;
    }
    const auto value = [&](std::size_t& i) -> const std::string& {
      if(i + 1 >= a.size())
        throw std::invalid_argument(a[i] + " needs a value");
      return a[++i];
    };
    if(a[0] == "run" && a.size() >= 3)
    {
      Options o;
      o.method = a[1];
      o.input = a[2];
      for(std::size_t i = 3; i < a.size(); ++i)
      {
        const std::string& k = a[i];
        if(k == "--shape") o.shape = value(i);
        else if(k == "--variant") o.variant = value(i);
        else if(k == "--label") o.label = value(i);
        else if(k == "--resolution") o.resolution = std::stoi(value(i));
        else if(k == "--samples") o.samples = std::stoi(value(i));
        else if(k == "--threads")
        {
          o.threads.clear();
          std::stringstream list(value(i));
          for(std::string t; std::getline(list, t, ',');)
            o.threads.push_back(std::stoi(t));
        }
        else if(k == "--runs") o.runs = std::stoi(value(i));
        else throw std::invalid_argument("unknown option " + k);
      }
      if(o.runs < 1 || o.threads.empty() || *std::min_element(o.threads.begin(), o.threads.end()) < 1)
        throw std::invalid_argument("--runs and --threads must be at least 1");
      return run(o);
    }
    if(a[0] == "report" && a.size() >= 3)
    {
      DF_L1_bench::Report_options o;
      for(std::size_t i = 3; i < a.size(); ++i)
      {
        if(a[i] == "--command") o.command = value(i);
        else if(a[i] == "--notes") o.notes = value(i);
        else throw std::invalid_argument("unknown option " + a[i]);
      }
      DF_L1_bench::write_report(DF_L1_bench::read_records(a[1]), a[2], o);
      return 0;
    }
    if(a[0] == "compare" && a.size() >= 3)
    {
      double tolerance = 0.25;
      for(std::size_t i = 3; i < a.size(); ++i)
      {
        if(a[i] == "--tolerance") tolerance = std::stod(value(i));
        else throw std::invalid_argument("unknown option " + a[i]);
      }
      DF_L1_bench::compare(DF_L1_bench::read_records(a[1]), DF_L1_bench::read_records(a[2]), tolerance, std::cout);
      return 0;
    }
    usage(std::cerr);
    return 2;
  }
  catch(const std::exception& e)
  {
    std::cerr << "df_l1_benchmark: " << e.what() << "\n";
    return 1;
  }
}
