// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_skeleton._df_l1_skeleton: the Python binding of the library (pybind11).
//
// It runs the stages exactly as the tool df_l1_skeleton does (the same class, the same
// order, the same parameters), times them with the tool's Stage_clock, and writes the
// skeleton, the segmentation and the --report JSON with the tool's writers
// (tools/report.h, include/CGAL/DF_L1_skeleton/IO/), so that its outputs are the tool's
// byte for byte (python/tests/test_module.py checks it). The pure Python part
// (python/df_l1_skeleton/__init__.py) checks the arrays and keyword arguments and
// documents the API; the computation releases the GIL.

#include "heap_settings.h"
#include "options.h"
#include "report.h"
#include "stage_clock.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/DF_L1_skeleton.h>
#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/DF_L1_skeleton/IO/write_file_atomically.h>
#include <CGAL/DF_L1_skeleton/IO/write_skeleton.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <boost/range/counting_range.hpp>

#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::DF_L1_skeletonization<Kernel> Skeletonization;
typedef CGAL::DF_L1::Skeleton_graph<Kernel> Graph;
typedef CGAL::DF_L1::Point_cloud<Kernel> Cloud;
namespace DF = CGAL::DF_L1;
namespace params = CGAL::parameters;

// The fields of the tool's Settings that df_l1_tool::report_json() reads.
struct Settings
{
  std::string input, output, stage = "final";
  long seed = 0;
  DF::Parameters parameters;
};

// Runs `f` with exactly `threads` threads, as the tool does with --threads (0: TBB's
// default, all cores).
template <class F>
auto in_arena(int threads, F&& f)
{
  if(threads <= 0)
    return f();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  tbb::task_arena arena(threads);
  return arena.execute(f);
}

// The input points: a numpy array of float32 or float64 of shape (N, 3), any strides
// (read in place, not copied), or a cloud read from a file. Only its creator and its
// destructor touch Python objects, both with the GIL held.
class Input_points
{
public:
  explicit Input_points(py::array array) : array_(std::move(array))
  {
    data_ = static_cast<const char*>(array_.data());
    size_ = std::size_t(array_.shape(0));
    row_stride_ = array_.strides(0);
    column_stride_ = array_.strides(1);
    single_ = array_.itemsize() == 4;
  }
  explicit Input_points(std::shared_ptr<const Cloud> cloud) : cloud_(std::move(cloud)) { size_ = cloud_->points.size(); }

  std::size_t size() const { return size_; }
  Point_3 operator[](std::size_t i) const
  {
    if(cloud_)
      return cloud_->points[i];
    const char* row = data_ + py::ssize_t(i) * row_stride_;
    return single_ ? Point_3(read<float>(row), read<float>(row + column_stride_), read<float>(row + 2 * column_stride_))
                   : Point_3(read<double>(row), read<double>(row + column_stride_), read<double>(row + 2 * column_stride_));
  }
  // The points as the tool holds them (for the segmentation writer).
  std::vector<Point_3> copy() const
  {
    if(cloud_)
      return cloud_->points;
    std::vector<Point_3> points;
    points.reserve(size_);
    for(std::size_t i = 0; i < size_; ++i)
      points.push_back((*this)[i]);
    return points;
  }

private:
  template <class T>
  static double read(const char* p)
  {
    T x;
    std::memcpy(&x, p, sizeof(T)); // the array may be unaligned
    return double(x);
  }

  py::array array_;
  std::shared_ptr<const Cloud> cloud_;
  const char* data_ = nullptr;
  std::size_t size_ = 0;
  py::ssize_t row_stride_ = 0, column_stride_ = 0;
  bool single_ = false;
};

// The input points as a CGAL property map over indices 0..N-1.
struct Input_point_map
{
  typedef std::size_t key_type;
  typedef Point_3 value_type;
  typedef Point_3 reference;
  typedef boost::readable_property_map_tag category;
  const Input_points* points = nullptr;
  friend Point_3 get(const Input_point_map& m, std::size_t i) { return (*m.points)[i]; }
};

auto index_range(const Input_points& points) { return boost::counting_range<std::size_t>(0, points.size()); }

// One skeletonization, run and reported as the tool runs and reports it.
struct Run
{
  Settings settings;
  int threads = 0;
  double max_memory = 0; // bytes; 0: the memory available at the start
  std::shared_ptr<const Input_points> points;
  df_l1_tool::Stage_clock clock{true};
  std::unique_ptr<Skeletonization> skeletonization;
  const DF::Voxel_grid<Kernel>* grid = nullptr;
  const DF::Distance_field<Kernel>* field = nullptr;
  const DF::Initial_skeleton<Kernel>* initial = nullptr;
  const DF::Contracted_samples<Kernel>* contracted = nullptr;
  const Graph* final_skeleton = nullptr;
  // the clock and output of the last write_skeleton(), for the report
  std::unique_ptr<df_l1_tool::Stage_clock> written_clock;
  std::string written_output;

  const Graph* skeleton() const { return final_skeleton ? final_skeleton : initial ? &initial->graph : nullptr; }

  // The stages of the tool's run_stages() (tools/df_l1_skeleton.cpp), in its order,
  // up to the writing. Called without the GIL.
  void compute()
  {
    in_arena(threads, [&] {
      compute_stages();
      return 0;
    });
  }

  // The tool's --report, for the clock given (the run's, or that of a write).
  std::string report(const df_l1_tool::Stage_clock& c, const std::string& output)
  {
    Settings s = settings;
    s.output = output;
    return in_arena(threads, [&] {
      return df_l1_tool::report_json(s, *skeletonization, *grid, field, initial, contracted, final_skeleton, c);
    });
  }

private:
  void compute_stages()
  {
    const Settings& s = settings;
    const std::string prefix = s.input.empty() ? "" : s.input + ": ";
    const double memory = max_memory > 0 ? max_memory : DF::internal::available_memory_bytes();
    skeletonization = std::make_unique<Skeletonization>(
      index_range(*points),
      params::voxel_resolution(s.parameters.voxel_resolution,
                               params::max_memory(memory, params::point_map(Input_point_map{points.get()}))));
    skeletonization->set_parameters(s.parameters);
    const auto stage = [&](const char* name, void (Skeletonization::*f)()) {
      clock.run(name, [&] {
        ((*skeletonization).*f)();
        return 0;
      });
    };
    stage("outlier_points", &Skeletonization::flag_outliers);
    stage("denoising", &Skeletonization::denoise);
    if(skeletonization->upsampling())
      stage("upsampling", &Skeletonization::upsample);
    stage("voxelization", &Skeletonization::voxelize);
    stage("outliers", &Skeletonization::remove_outlier_voxels);
    grid = &skeletonization->voxel_grid();
    if(s.stage != "voxels")
    {
      stage("distance", &Skeletonization::compute_distance_field);
      field = &skeletonization->distance_field();
    }
    if(s.stage == "initial" || s.stage == "final")
    {
      stage("initial", &Skeletonization::extract_initial_skeleton);
      initial = &skeletonization->initial_skeleton();
      if(boost::num_vertices(initial->graph) == 0)
        throw DF::Invalid_input(prefix + "no skeleton: the points enclose no volume at voxel resolution " +
                                std::to_string(skeletonization->voxel_resolution()) +
                                " (flat, linear or too sparse input; try --stage voxels to look at the voxels)");
    }
    if(s.stage == "final")
    {
      stage("contraction", &Skeletonization::contract_until_convergence);
      contracted = &skeletonization->contracted_samples();
      stage("skeleton", &Skeletonization::convert_to_skeleton);
      final_skeleton = &skeletonization->skeleton();
      if(boost::num_vertices(*final_skeleton) == 0)
        throw DF::Invalid_input(prefix + "no skeleton: the contraction of " +
                                std::to_string(df_l1_tool::contracted_count(*contracted)) +
                                " samples traced no branch (try --stage initial, or more --samples)");
    }
  }
};

// ---------------------------------------------------------------------------------------
// Conversions to numpy.

template <class T>
py::array_t<T> new_array(std::vector<py::ssize_t> shape)
{
  return py::array_t<T>(shape);
}

py::array_t<double> points_array(const std::vector<Point_3>& points)
{
  py::array_t<double> a = new_array<double>({py::ssize_t(points.size()), 3});
  auto m = a.mutable_unchecked<2>();
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    m(i, 0) = CGAL::to_double(points[i].x());
    m(i, 1) = CGAL::to_double(points[i].y());
    m(i, 2) = CGAL::to_double(points[i].z());
  }
  return a;
}

template <class T>
py::array_t<T> vector_array(const std::vector<T>& v)
{
  py::array_t<T> a = new_array<T>({py::ssize_t(v.size())});
  if(!v.empty())
    std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(T));
  return a;
}

py::array_t<bool> flags_array(const std::vector<bool>& v)
{
  py::array_t<bool> a = new_array<bool>({py::ssize_t(v.size())});
  auto m = a.mutable_unchecked<1>();
  for(std::size_t i = 0; i < v.size(); ++i)
    m(i) = v[i];
  return a;
}

// A grid array indexed [i, j, k] (x, y, z): the library's linear order, i fastest, is
// numpy's Fortran order of shape (nx, ny, nz).
template <class T>
py::array_t<T, py::array::f_style> grid_array(const std::array<int, 3>& dims)
{
  return py::array_t<T, py::array::f_style>({py::ssize_t(dims[0]), py::ssize_t(dims[1]), py::ssize_t(dims[2])});
}

py::array_t<double> xyz_array(const Point_3& p)
{
  py::array_t<double> a = new_array<double>({3});
  auto m = a.mutable_unchecked<1>();
  m(0) = CGAL::to_double(p.x());
  m(1) = CGAL::to_double(p.y());
  m(2) = CGAL::to_double(p.z());
  return a;
}

void make_read_only(py::array& a) { a.attr("flags").attr("writeable") = false; }

// ---------------------------------------------------------------------------------------
// The Python classes.

// A skeleton graph with its arrays, and the run that made it when there is one (for the
// report and the writers).
class Skeleton
{
public:
  Skeleton(std::shared_ptr<const Graph> graph, std::shared_ptr<const Input_points> points, std::shared_ptr<Run> run)
    : graph_(std::move(graph)), points_(std::move(points)), run_(std::move(run))
  {
    const Graph& g = *graph_;
    const std::size_t n = boost::num_vertices(g);
    std::vector<Point_3> positions;
    std::vector<double> radii;
    for(std::size_t v = 0; v < n; ++v)
    {
      positions.push_back(g[v].point);
      radii.push_back(CGAL::to_double(g[v].radius));
    }
    vertices_ = points_array(positions);
    radii_ = vector_array(radii);
    py::array_t<std::int64_t> edges = new_array<std::int64_t>({py::ssize_t(boost::num_edges(g)), 2});
    auto m = edges.mutable_unchecked<2>();
    py::ssize_t e = 0;
    for(auto edge : CGAL::make_range(boost::edges(g)))
    {
      m(e, 0) = std::int64_t(boost::source(edge, g));
      m(e, 1) = std::int64_t(boost::target(edge, g));
      ++e;
    }
    edges_ = edges;
    for(py::array* a : {&vertices_, &radii_, &edges_})
      make_read_only(*a);
  }

  const Graph& graph() const { return *graph_; }
  const std::shared_ptr<Run>& run() const { return run_; }
  const std::shared_ptr<const Input_points>& points() const { return points_; }
  py::array vertices() const { return vertices_; }
  py::array edges() const { return edges_; }
  py::array radii() const { return radii_; }

  const DF::Point_segmentation& segmentation()
  {
    if(!segmentation_)
    {
      if(!points_)
        throw DF::Invalid_input("this skeleton has no input points to label");
      // under the GIL, which orders two threads asking at once (one pass over the points)
      segmentation_ = std::make_unique<DF::Point_segmentation>(
        DF::segment_points(index_range(*points_), *graph_, params::point_map(Input_point_map{points_.get()})));
    }
    return *segmentation_;
  }
  py::array point_labels()
  {
    py::array a = vector_array<std::int64_t>(std::vector<std::int64_t>(segmentation().vertex.begin(), segmentation().vertex.end()));
    make_read_only(a);
    return a;
  }
  py::array point_branches()
  {
    py::array a = vector_array<std::int64_t>(std::vector<std::int64_t>(segmentation().branch.begin(), segmentation().branch.end()));
    make_read_only(a);
    return a;
  }
  std::vector<std::vector<std::size_t>> branches() const
  {
    std::vector<std::vector<std::size_t>> polylines;
    DF::split_into_polylines(*graph_, std::back_inserter(polylines));
    return polylines;
  }
  py::list polylines() const
  {
    py::list result;
    for(const auto& line : DF::skeleton_polylines(*graph_))
      result.append(points_array(std::vector<Point_3>(line.begin(), line.end())));
    return result;
  }
  py::dict statistics() const
  {
    const DF::Skeleton_statistics s = DF::skeleton_statistics(*graph_);
    py::dict d;
    d["vertices"] = s.vertices;
    d["edges"] = s.edges;
    d["components"] = s.components;
    d["cycles"] = s.cycles;
    d["end_points"] = s.end_points;
    d["junctions"] = s.junctions;
    return d;
  }
  std::string report_json() const
  {
    if(!run_)
      throw DF::Invalid_input("this skeleton has no report: it was not made by skeletonize()");
    py::gil_scoped_release release;
    return run_->written_clock ? run_->report(*run_->written_clock, run_->written_output) : run_->report(run_->clock, "");
  }
  std::string repr() const
  {
    const DF::Skeleton_statistics s = DF::skeleton_statistics(*graph_);
    return "<df_l1_skeleton.Skeleton: " + std::to_string(s.vertices) + " vertices, " + std::to_string(s.edges) +
           " edges, " + std::to_string(s.components) + " components, " + std::to_string(s.cycles) + " cycles, " +
           std::to_string(s.end_points) + " end points, " + std::to_string(s.junctions) + " junctions>";
  }

private:
  std::shared_ptr<const Graph> graph_;
  std::shared_ptr<const Input_points> points_;
  std::shared_ptr<Run> run_;
  py::array vertices_, edges_, radii_;
  std::unique_ptr<DF::Point_segmentation> segmentation_;
};

// A cloud read from a file, with the tool's clock holding its "read" time.
struct Point_cloud_handle
{
  std::shared_ptr<const Cloud> cloud;
  std::string path;
  df_l1_tool::Stage_clock clock{true};
  py::array points, normals;
};

// Checks parameters given as (name, text) pairs into a DF::Parameters.
DF::Parameters parameters_from(const std::vector<std::pair<std::string, std::string>>& given)
{
  DF::Parameters p;
  for(const auto& [name, text] : given)
    DF::set_parameter(p, name, text);
  return p;
}

std::shared_ptr<Run> make_run(const std::string& stage, int threads, long seed, double max_memory,
                              const std::vector<std::pair<std::string, std::string>>& given)
{
  if(stage != "initial" && stage != "final")
    throw DF::Invalid_input("stage must be 'initial' or 'final', got '" + stage + "'");
  if(threads < 0 || threads > 1024)
    throw DF::Invalid_input("threads must be in [1, 1024] (or None for all cores), got " + std::to_string(threads));
  if(seed < 0 || seed > 2147483647L)
    throw DF::Invalid_input("seed must be in [0, 2147483647], got " + std::to_string(seed));
  if(max_memory < 0)
    throw DF::Invalid_input("max_memory must be a positive number of bytes");
  auto run = std::make_shared<Run>();
  run->settings.stage = stage;
  run->settings.seed = seed;
  run->settings.parameters = parameters_from(given);
  run->threads = threads;
  run->max_memory = max_memory;
  return run;
}

Skeleton finish(std::shared_ptr<Run> run)
{
  {
    py::gil_scoped_release release;
    run->compute();
  }
  const Graph* g = run->skeleton();
  std::shared_ptr<const Graph> graph(run, g); // aliasing: the graph lives in the run
  return Skeleton(graph, run->points, run);
}

Skeleton skeletonize_array(py::array points, const std::string& stage, int threads, long seed, double max_memory,
                           const std::vector<std::pair<std::string, std::string>>& given)
{
  auto run = make_run(stage, threads, seed, max_memory, given);
  run->points = std::make_shared<const Input_points>(std::move(points));
  return finish(run);
}

Skeleton skeletonize_cloud(const Point_cloud_handle& cloud, const std::string& stage, int threads, long seed,
                           double max_memory, const std::vector<std::pair<std::string, std::string>>& given)
{
  auto run = make_run(stage, threads, seed, max_memory, given);
  run->points = std::make_shared<const Input_points>(cloud.cloud);
  run->settings.input = cloud.path;
  run->clock = cloud.clock; // the "read" stage comes first, as in the tool's report
  return finish(run);
}

Point_cloud_handle read_point_cloud(const std::string& path)
{
  Point_cloud_handle h;
  h.path = path;
  {
    py::gil_scoped_release release;
    h.cloud = h.clock.run("read", [&] { return std::make_shared<const Cloud>(DF::read_point_cloud<Kernel>(path)); });
  }
  // numpy views of the cloud's vectors (Point_3 and Vector_3 of Epick are three doubles)
  static_assert(sizeof(Point_3) == 3 * sizeof(double) && sizeof(Kernel::Vector_3) == 3 * sizeof(double));
  py::capsule owner(new std::shared_ptr<const Cloud>(h.cloud),
                    [](void* p) { delete static_cast<std::shared_ptr<const Cloud>*>(p); });
  h.points = py::array_t<double>({py::ssize_t(h.cloud->points.size()), py::ssize_t(3)},
                                 reinterpret_cast<const double*>(h.cloud->points.data()), owner);
  make_read_only(h.points);
  if(!h.cloud->normals.empty())
  {
    h.normals = py::array_t<double>({py::ssize_t(h.cloud->normals.size()), py::ssize_t(3)},
                                    reinterpret_cast<const double*>(h.cloud->normals.data()), owner);
    make_read_only(h.normals);
  }
  return h;
}

bool has_suffix(std::string s, const std::string& suffix)
{
  for(char& c : s)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The tool's write step: the skeleton, the segmentation and the report, each to a
// temporary file, renamed together at the end (none is left on failure).
void write_skeleton(const std::string& path, Skeleton& skeleton, const std::string& segmentation,
                    const std::string& report)
{
  if(!has_suffix(path, ".obj") && !has_suffix(path, ".ply") && !has_suffix(path, ".polylines.txt"))
    throw DF::Invalid_input("the skeleton's file must end in .obj, .ply or .polylines.txt, got '" + path + "'");
  if(!segmentation.empty() && !has_suffix(segmentation, ".ply"))
    throw DF::Invalid_input("segmentation expects a .ply file, got '" + segmentation + "'");
  if(!report.empty() && !has_suffix(report, ".json"))
    throw DF::Invalid_input("report expects a .json file, got '" + report + "'");
  const std::shared_ptr<Run>& run = skeleton.run();
  if(!report.empty() && !run)
    throw DF::Invalid_input("this skeleton has no report: it was not made by skeletonize()");
  if(!segmentation.empty() && !skeleton.points())
    throw DF::Invalid_input("this skeleton has no input points to label");
  auto clock = std::make_unique<df_l1_tool::Stage_clock>(run ? run->clock : df_l1_tool::Stage_clock(true));
  {
  py::gil_scoped_release release;
  DF::Atomic_file_group outputs;
  clock->run("write", [&] {
    DF::write_skeleton(path, skeleton.graph());
    if(!segmentation.empty())
    {
      const std::vector<Point_3> points = skeleton.points()->copy();
      const DF::Point_segmentation segments = DF::segment_points(points, skeleton.graph());
      DF::Ply_point_property vertex{"vertex", true, {}}, branch{"branch", true, {}};
      vertex.values.assign(segments.vertex.begin(), segments.vertex.end());
      branch.values.assign(segments.branch.begin(), segments.branch.end());
      DF::write_point_ply(segmentation, points, {vertex, branch});
    }
    return 0;
  });
  if(!report.empty())
  {
    const std::string text = run->report(*clock, path);
    DF::write_file_atomically(report, [&](std::ostream& os) { os << text << "\n"; });
  }
  outputs.commit();
  }
  if(run) // with the GIL: the report of the skeleton reads these
  {
    run->written_clock = std::move(clock);
    run->written_output = path;
  }
}

// ---------------------------------------------------------------------------------------
// The stage-by-stage class.

class Stagewise
{
public:
  Stagewise(py::array points, int threads, double max_memory, const std::vector<std::pair<std::string, std::string>>& given)
    : points_(std::make_shared<const Input_points>(std::move(points))), threads_(threads)
  {
    if(threads < 0 || threads > 1024)
      throw DF::Invalid_input("threads must be in [1, 1024] (or None for all cores), got " + std::to_string(threads));
    const DF::Parameters p = parameters_from(given);
    py::gil_scoped_release release;
    const double memory = max_memory > 0 ? max_memory : DF::internal::available_memory_bytes();
    skeletonization_ = std::make_unique<Skeletonization>(
      index_range(*points_),
      params::voxel_resolution(p.voxel_resolution, params::max_memory(memory, params::point_map(Input_point_map{points_.get()}))));
    skeletonization_->set_parameters(p);
  }

  // Runs a member of the class without the GIL, in the arena of `threads`.
  // One call at a time: the GIL is released first, then the object locked.
  template <class F>
  auto call(F f)
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    return in_arena(threads_, [&] { return f(*skeletonization_); });
  }
  const std::shared_ptr<const Input_points>& points() const { return points_; }

  void set(const std::string& name, const std::string& text)
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    DF::Parameters p = skeletonization_->parameters();
    DF::set_parameter(p, name, text);
    skeletonization_->set_parameters(p);
  }

private:
  std::shared_ptr<const Input_points> points_;
  int threads_ = 0;
  std::unique_ptr<Skeletonization> skeletonization_;
  std::mutex mutex_;
};

// The value a getter of the class returns for a parameter, as Python sees it.
py::object parameter_value(Stagewise& w, const std::string& name)
{
  const DF::Parameter_info& info = DF::parameter_info(name);
  if(name == "upsampling_radius")
    return py::float_(w.call([](Skeletonization& x) { return x.upsampling_radius(); }));
  if(name == "initial_voxel_size")
    return py::float_(w.call([](Skeletonization& x) { return x.initial_voxel_size(); }));
  if(name == "outlier_component_size")
    return py::int_(w.call([](Skeletonization& x) { return x.outlier_component_size(); }));
  if(name == "initial_support_radius")
    return py::float_(w.call([](Skeletonization& x) { return x.initial_support_radius(); }));
  const double x = info.read(w.call([](Skeletonization& x) { return x.parameters(); }));
  switch(info.kind)
  {
  case DF::Parameter_kind::INTEGER: return py::int_(static_cast<long long>(x));
  case DF::Parameter_kind::REAL: return py::float_(x);
  case DF::Parameter_kind::BOOLEAN: return py::bool_(x != 0);
  default: return py::str(info.choices[std::size_t(x)]);
  }
}

py::object skeleton_of(Stagewise& w, const Graph& g)
{
  return py::cast(Skeleton(std::make_shared<const Graph>(g), w.points(), nullptr));
}

} // namespace

PYBIND11_MODULE(_df_l1_skeleton, m)
{
  m.doc() = "The compiled part of df_l1_skeleton (use the package df_l1_skeleton, which documents the API).";

  static py::exception<DF::Read_error> read_error(m, "ReadError", PyExc_ValueError);
  static py::exception<DF::Write_error> write_error(m, "WriteError", PyExc_OSError);
  read_error.doc() = "A point cloud file that cannot be opened or parsed; the message names the file and the line or vertex.";
  write_error.doc() = "An output that cannot be written completely; the destination is then left as it was.";
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const DF::Invalid_input& e)
    {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
    catch(const DF::Read_error& e)
    {
      read_error(e.what());
    }
    catch(const DF::Write_error& e)
    {
      write_error(e.what());
    }
  });

  m.attr("__version__") = DF_L1_VERSION;

  m.def("parameter_table", [] {
    py::list rows;
    const DF::Parameters defaults;
    for(const DF::Parameter_info& info : DF::parameter_table())
    {
      py::dict d;
      d["name"] = info.name;
      d["stage"] = info.stage;
      const char* kinds[] = {"integer", "real", "boolean", "choice"};
      d["kind"] = kinds[int(info.kind)];
      d["range"] = info.range_text();
      py::list choices;
      for(const char* c : info.choices)
        if(c)
          choices.append(c);
      d["choices"] = choices;
      d["default_text"] = info.default_text;
      d["help"] = info.help;
      const std::string text = DF::parameter_text(defaults, info.name);
      py::object value = py::none();
      if(!text.empty())
      {
        const double x = info.read(defaults);
        switch(info.kind)
        {
        case DF::Parameter_kind::INTEGER: value = py::int_(static_cast<long long>(x)); break;
        case DF::Parameter_kind::REAL: value = py::float_(x); break;
        case DF::Parameter_kind::BOOLEAN: value = py::bool_(x != 0); break;
        default: value = py::str(text);
        }
      }
      d["default"] = value;
      rows.append(d);
    }
    return rows;
  }, "The library's parameter table (CGAL::DF_L1::parameter_table()): one dict per parameter.");

  m.def("_parse_bytes", [](const std::string& text) {
    try
    {
      return df_l1_tool::parse_bytes("max-memory", text);
    }
    catch(const df_l1_tool::Usage_error& e)
    {
      throw DF::Invalid_input(std::string(e.what()).substr(2)); // without the option's "--"
    }
  }, py::arg("text"));
  m.def("_check_parameters", [](const std::vector<std::pair<std::string, std::string>>& given) { parameters_from(given); },
        py::arg("parameters"));
  m.def("keep_large_buffers_on_heap", &df_l1_tool::keep_large_buffers_on_heap,
        "Keeps large buffers on the heap for reuse (glibc mallopt), as the tool does; a process setting.");

  py::class_<Point_cloud_handle>(m, "PointCloud", "A point cloud read by read_point_cloud().")
    .def_readonly("points", &Point_cloud_handle::points, "(N, 3) float64 array of the points, in file order (read-only)")
    .def_property_readonly("normals", [](const Point_cloud_handle& h) -> py::object {
      return h.normals ? py::object(h.normals) : py::none();
    }, "(N, 3) float64 array of the normals, or None when the file has none (or a non-finite one)")
    .def_readonly("path", &Point_cloud_handle::path, "the file it was read from")
    .def("__len__", [](const Point_cloud_handle& h) { return h.cloud->points.size(); })
    .def("__array__", [](const Point_cloud_handle& h, py::object dtype) {
      return dtype.is_none() ? py::object(h.points) : h.points.attr("astype")(dtype);
    }, py::arg("dtype") = py::none())
    .def("__repr__", [](const Point_cloud_handle& h) {
      return "<df_l1_skeleton.PointCloud '" + h.path + "': " + std::to_string(h.cloud->points.size()) + " points" +
             (h.normals ? ", normals>" : ">");
    });

  py::class_<Skeleton>(m, "Skeleton", "A curve skeleton: a graph of vertices with positions and radii.")
    .def_property_readonly("vertices", &Skeleton::vertices, "(V, 3) float64 array of the vertex positions")
    .def_property_readonly("edges", &Skeleton::edges, "(E, 2) int64 array of the edges (vertex indices), in the order of the writers")
    .def_property_readonly("radii", &Skeleton::radii, "(V,) float64 array: the local radius of the shape at each vertex")
    .def_property_readonly("point_labels", &Skeleton::point_labels,
                           "(N,) int64 array: the skeleton vertex of each input point, -1 for outliers")
    .def_property_readonly("point_branches", &Skeleton::point_branches,
                           "(N,) int64 array: the branch (index into branches) of each input point, -1 for outliers")
    .def_property_readonly("branches", &Skeleton::branches,
                           "the branches: lists of vertex indices between end points and junctions (closed ones repeat their first vertex)")
    .def("polylines", &Skeleton::polylines, "The branches as (k, 3) float64 arrays of positions.")
    .def_property_readonly("statistics", &Skeleton::statistics,
                           "dict of vertices, edges, components, cycles, end_points, junctions")
    .def("_report_json", &Skeleton::report_json)
    .def("__repr__", &Skeleton::repr);

  m.def("_read_point_cloud", &read_point_cloud, py::arg("path"));
  m.def("_skeletonize_array", &skeletonize_array, py::arg("points"), py::arg("stage"), py::arg("threads"),
        py::arg("seed"), py::arg("max_memory"), py::arg("parameters"));
  m.def("_skeletonize_cloud", &skeletonize_cloud, py::arg("cloud"), py::arg("stage"), py::arg("threads"),
        py::arg("seed"), py::arg("max_memory"), py::arg("parameters"));
  m.def("_write_skeleton", &write_skeleton, py::arg("path"), py::arg("skeleton"), py::arg("segmentation"),
        py::arg("report"));

  // The stage-by-stage class; the Python class Skeletonization wraps it.
  py::class_<Stagewise> w(m, "_Skeletonization");
  w.def(py::init<py::array, int, double, const std::vector<std::pair<std::string, std::string>>&>(), py::arg("points"),
        py::arg("threads"), py::arg("max_memory"), py::arg("parameters"));
  const auto stage = [&w](const char* name, void (Skeletonization::*f)(), const char* doc) {
    w.def(name, [f](Stagewise& self) { self.call([f](Skeletonization& s) { (s.*f)(); return 0; }); }, doc);
  };
  stage("flag_outliers", &Skeletonization::flag_outliers, "Flags the scattered outliers.");
  stage("denoise", &Skeletonization::denoise, "Estimates the surface noise and, as `denoising` says, smooths the points.");
  stage("upsample", &Skeletonization::upsample, "Adds points in the sparse regions, unless `upsampling` is off.");
  stage("voxelize", &Skeletonization::voxelize, "Voxelizes the kept and added points.");
  stage("remove_outlier_voxels", &Skeletonization::remove_outlier_voxels, "Removes the outlier voxels and flags their points.");
  stage("compute_distance_field", &Skeletonization::compute_distance_field, "Computes the distance field of the voxels.");
  stage("extract_initial_skeleton", &Skeletonization::extract_initial_skeleton, "Extracts the initial skeleton (voxel thinning).");
  stage("contract_until_convergence", &Skeletonization::contract_until_convergence, "Runs the contraction until it converges.");
  stage("convert_to_skeleton", &Skeletonization::convert_to_skeleton, "Builds the final skeleton from the contracted samples.");
  w.def("contract", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.contract(); }); },
        "Runs one support-radius stage of the contraction; False, running nothing, once it has converged.");
  w.def("get_parameter", &parameter_value, py::arg("name"));
  w.def("set_parameter", &Stagewise::set, py::arg("name"), py::arg("text"));
  w.def_property_readonly("number_of_input_points", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.number_of_input_points(); }); });
  w.def_property_readonly("bbox_diagonal", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.bbox_diagonal(); }); });
  w.def_property_readonly("estimated_peak_memory", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.estimated_peak_memory(); }); });
  w.def_property_readonly("max_memory", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.max_memory(); }); });
  w.def_property_readonly("surface_noise", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.surface_noise(); }); });
  w.def_property_readonly("residual_growth", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.residual_growth(); }); });
  w.def_property_readonly("denoised", [](Stagewise& self) { return self.call([](Skeletonization& s) { return s.denoised(); }); });
  w.def_property_readonly("number_of_sparse_outliers", [](Stagewise& self) {
    return self.call([](Skeletonization& s) { return s.number_of_sparse_outliers(); });
  });
  w.def_property_readonly("number_of_analysed_points", [](Stagewise& self) {
    return self.call([](Skeletonization& s) { return s.number_of_analysed_points(); });
  });
  w.def_property_readonly("number_of_outliers", [](Stagewise& self) {
    return self.call([](Skeletonization& s) { return s.number_of_outliers(); });
  });
  w.def("outlier_flags", [](Stagewise& self) {
    return flags_array(*self.call([](Skeletonization& s) { return &s.outlier_flags(); }));
  });
  w.def("kept_points", [](Stagewise& self) {
    return points_array(*self.call([](Skeletonization& s) { return &s.kept_points(); }));
  });
  w.def("added_points", [](Stagewise& self) {
    return points_array(*self.call([](Skeletonization& s) { return &s.added_points(); }));
  });
  w.def("voxel_grid", [](Stagewise& self) {
    const DF::Voxel_grid<Kernel>& g = *self.call([](Skeletonization& s) { return &s.voxel_grid(); });
    auto labels = grid_array<std::uint8_t>(g.dims);
    std::memcpy(labels.mutable_data(), g.labels.data(), g.labels.size());
    py::dict d;
    d["origin"] = xyz_array(g.origin);
    d["voxel_size"] = CGAL::to_double(g.voxel_size);
    d["labels"] = labels;
    return d;
  });
  w.def("distance_field", [](Stagewise& self) {
    const DF::Distance_field<Kernel>& f = *self.call([](Skeletonization& s) { return &s.distance_field(); });
    auto distances = grid_array<double>(f.dims);
    double* out = distances.mutable_data();
    const double size = CGAL::to_double(f.voxel_size);
    for(std::size_t v = 0; v < f.values.size(); ++v)
      out[v] = double(f.values[v]) * size;
    py::dict d;
    d["origin"] = xyz_array(f.origin);
    d["voxel_size"] = size;
    d["distances"] = distances;
    return d;
  });
  w.def("initial_skeleton", [](Stagewise& self) {
    const DF::Initial_skeleton<Kernel>& i = *self.call([](Skeletonization& s) { return &s.initial_skeleton(); });
    py::dict d;
    d["skeleton"] = skeleton_of(self, i.graph);
    d["skeleton_voxels"] = points_array(i.points);
    d["thinning_parameters"] = py::make_tuple(i.thinning_parameters[0], i.thinning_parameters[1], i.thinning_parameters[2]);
    return d;
  });
  w.def("contracted_samples", [](Stagewise& self) {
    const DF::Contracted_samples<Kernel>& c = *self.call([](Skeletonization& s) { return &s.contracted_samples(); });
    std::vector<std::uint8_t> roles;
    for(DF::Sample_role r : c.roles)
      roles.push_back(std::uint8_t(r));
    py::array_t<std::int64_t> edges = new_array<std::int64_t>({py::ssize_t(c.edges.size()), 2});
    auto m = edges.mutable_unchecked<2>();
    for(std::size_t e = 0; e < c.edges.size(); ++e)
    {
      m(e, 0) = std::int64_t(c.edges[e].first);
      m(e, 1) = std::int64_t(c.edges[e].second);
    }
    py::dict d;
    d["points"] = points_array(c.points);
    d["roles"] = vector_array(roles);
    d["support_radii"] = vector_array(c.support_radii);
    d["edges"] = edges;
    d["initial_support_radius"] = c.initial_support_radius;
    py::list stages;
    for(const DF::Contraction_stage& st : c.stages)
    {
      py::dict s;
      s["iterations"] = st.iterations;
      s["min_radius"] = st.min_radius;
      s["mean_radius"] = st.mean_radius;
      s["max_radius"] = st.max_radius;
      s["free_samples"] = st.free_samples;
      s["branch_samples"] = st.branch_samples;
      s["projection_seconds"] = st.projection_seconds;
      stages.append(s);
    }
    d["stages"] = stages;
    return d;
  });
  w.def("skeleton", [](Stagewise& self) {
    const Graph& g = *self.call([](Skeletonization& s) { return &s.skeleton(); });
    return skeleton_of(self, g);
  });
}
