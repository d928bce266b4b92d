// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_PARAMETERS_H
#define CGAL_DF_L1_SKELETON_PARAMETERS_H

/// \file Parameters.h
/// The parameters of the method in one record, and the table that gives each its
/// default, range, documentation and command-line option. The named parameters, the
/// class `DF_L1_skeletonization`, the stage functions and the tool all read their
/// defaults and ranges from here.

#include <CGAL/DF_L1_skeleton/errors.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace DF_L1 {

/// \ingroup PkgDFL1SkeletonRef
/// The refinement method (parameter `skeletonization_method`).
enum class Skeletonization_method
{
  /// the paper's method: samples attracted to the initial skeleton, never moving to a
  /// voxel of smaller distance value, adaptive support radius, inside-only bridges
  DISTANCE_FIELD_GUIDED,
  /// the plain L1-medial skeleton (Huang et al. 2013): the same engine with the guidance
  /// off and a global support radius growing by stages
  L1_MEDIAL
};

/// \ingroup PkgDFL1SkeletonRef
/// When the points are smoothed before voxelization (parameter `denoising`).
enum class Denoising
{
  /// when `estimate_surface_noise()` exceeds a fifth of the finest voxel size
  AUTOMATIC,
  /// always
  ALWAYS,
  /// never
  NEVER
};

/// \ingroup PkgDFL1SkeletonRef
/// The parameters of `DF_L1_skeletonization`, in the order of the stages that use them.
/// A default-constructed record holds the defaults; the length parameters left empty
/// derive from the input when the stages run (their getters in `DF_L1_skeletonization`
/// return the values used). `parameter_table()` documents every field and its range.
struct Parameters
{
  Denoising denoising = Denoising::AUTOMATIC;        ///< when the points are smoothed
  int denoising_neighbors = 24;                      ///< k of the local quadrics of the smoothing
  bool upsampling = true;                            ///< whether sparse regions are upsampled
  int upsampling_neighbors = 5;                      ///< k of the density k / r^3
  std::optional<double> upsampling_radius;           ///< r of the density test; default 3 d_bb / cbrt(N)
  int voxel_resolution = 100;                        ///< V, voxels along the longest side
  std::optional<double> initial_voxel_size;          ///< s0; default d_bb / 9
  int exterior_propagation_steps = 1;                ///< exterior steps per refinement level
  std::optional<int> outlier_component_size;         ///< in voxels; default max(3, V / 10)
  double thinning_coefficient = 0.86;                ///< c of Eq. 2
  double spur_length_ratio = 1;                      ///< spur pruning of the initial skeleton
  Skeletonization_method skeletonization_method = Skeletonization_method::DISTANCE_FIELD_GUIDED; ///< refinement
  std::size_t number_of_samples = 1500;              ///< M, samples contracted (at most the points)
  double repulsion_coefficient = 0.35;               ///< u of Eq. 8
  std::optional<double> initial_support_radius;      ///< h0; default 2 d_bb / cbrt(N)
  double support_radius_growth = 0.5;                ///< h <- (1 + growth) h between stages
  double branch_directionality = 0.9;                ///< sigma above which a sample may be a branch point
  int number_of_iterations = 30;                     ///< maximum iterations per support-radius stage
  int contraction_stages = 64;                       ///< maximum support-radius stages
};

/// \ingroup PkgDFL1SkeletonRef
/// How a parameter's value is written in text (`set_parameter()`, the tool's options).
enum class Parameter_kind
{
  INTEGER, ///< a whole number in the range
  REAL,    ///< a finite number in the range
  BOOLEAN, ///< `on` or `off` (also `true`/`false`, `1`/`0`)
  CHOICE   ///< one of the spellings in `Parameter_info::choices`
};

/// \ingroup PkgDFL1SkeletonRef
/// An earlier spelling of a command-line option, still accepted.
struct Option_alias
{
  const char* option = nullptr; ///< without the leading `--`
  const char* value = nullptr;  ///< for a flag without argument, the value it stands for
};

/// \ingroup PkgDFL1SkeletonRef
/// One row of `parameter_table()`.
struct Parameter_info
{
  const char* name;          ///< the field of `Parameters`, the named parameter and the getter
  const char* stage;         ///< the first stage function of `DF_L1_skeletonization` that reads it
  Parameter_kind kind;       ///< how the value is written
  double lower;              ///< lower bound of INTEGER and REAL values
  double upper;              ///< upper bound of INTEGER and REAL values
  bool lower_open;           ///< whether the range excludes its lower bound
  bool upper_open;           ///< whether the range excludes its upper bound
  std::array<const char*, 3> choices; ///< CHOICE: the spelling of each enumerator, in order
  const char* default_text;  ///< the default, as the documentation states it
  const char* argument;      ///< the tool's name for the value (`V`, `K`...)
  const char* help;          ///< one line of documentation
  std::array<Option_alias, 2> aliases; ///< earlier spellings of the tool's option
  double (*read)(const Parameters&);   ///< the value as a number (CHOICE and BOOLEAN: index of the choice)
  void (*write)(Parameters&, double);  ///< sets the value from a checked number
  /// for a parameter whose default derives from the input: whether it was given
  /// (`read` is then meaningful); null for the others
  bool (*given)(const Parameters&) = nullptr;

  /// the tool's option: the name with `-` for `_`
  std::string option() const
  {
    std::string o = name;
    for(char& c : o)
      if(c == '_')
        c = '-';
    return o;
  }
  /// the range as text: `[3, 2048]`, `(0, inf)`
  std::string range_text() const
  {
    std::ostringstream s;
    s << (lower_open ? "(" : "[") << number_text(lower) << ", " << number_text(upper) << (upper_open ? ")" : "]");
    return s.str();
  }
  /// whether `x` lies in the range (and is whole for INTEGER)
  bool in_range(double x) const
  {
    if(!std::isfinite(x))
      return false;
    if(kind == Parameter_kind::INTEGER && x != std::floor(x))
      return false;
    return (lower_open ? x > lower : x >= lower) && (upper_open ? x < upper : x <= upper);
  }

private:
  static std::string number_text(double x)
  {
    if(std::isinf(x))
      return x > 0 ? "inf" : "-inf";
    if(std::abs(x - 1.0 / 3) < 1e-15)
      return "1/3";
    std::ostringstream s;
    if(x == std::floor(x) && std::abs(x) < 1e15)
      s << static_cast<long long>(x);
    else
      s << x;
    return s.str();
  }
};

namespace internal {
constexpr double unbounded = HUGE_VAL;

template <class T>
double optional_value(const std::optional<T>& v)
{
  return v ? double(*v) : 0.0;
}
} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Every parameter of `Parameters`, in the order of the stages that use them: its
/// default, range, documentation and command-line spelling. The tool's options and its
/// `--help` are made from this table.
inline const std::vector<Parameter_info>& parameter_table()
{
  using K = Parameter_kind;
  const double inf = internal::unbounded;
  static const std::vector<Parameter_info> table{
    {"denoising", "denoise", K::CHOICE, 0, 2, false, false, {"auto", "on", "off"}, "auto", "MODE",
     "smooth the points onto local quadrics before voxelization: auto (when the estimated noise exceeds a fifth of a voxel), on or off",
     {{{"denoise", nullptr}, {}}},
     [](const Parameters& p) { return double(int(p.denoising)); },
     [](Parameters& p, double x) { p.denoising = Denoising(int(x)); }},
    {"denoising_neighbors", "denoise", K::INTEGER, 6, 256, false, false, {}, "24", "K",
     "neighbours of the local quadrics of the smoothing (the noise estimate uses 16)", {},
     [](const Parameters& p) { return double(p.denoising_neighbors); },
     [](Parameters& p, double x) { p.denoising_neighbors = int(x); }},
    {"upsampling", "upsample", K::BOOLEAN, 0, 1, false, false, {"off", "on"}, "on", "on|off",
     "upsample the sparse regions before voxelization", {{{"no-upsampling", "off"}, {}}},
     [](const Parameters& p) { return p.upsampling ? 1.0 : 0.0; },
     [](Parameters& p, double x) { p.upsampling = x != 0; }},
    {"upsampling_neighbors", "upsample", K::INTEGER, 1, 64, false, false, {}, "5", "K",
     "k of the density k/r^3 of the sparse-region test", {},
     [](const Parameters& p) { return double(p.upsampling_neighbors); },
     [](Parameters& p, double x) { p.upsampling_neighbors = int(x); }},
    {"upsampling_radius", "upsample", K::REAL, 0, inf, true, true, {}, "3*d_bb/cbrt(N)", "R",
     "r of the sparse-region test (input units)", {},
     [](const Parameters& p) { return internal::optional_value(p.upsampling_radius); },
     [](Parameters& p, double x) { p.upsampling_radius = x; },
     [](const Parameters& p) { return p.upsampling_radius.has_value(); }},
    {"voxel_resolution", "flag_outliers", K::INTEGER, 3, 2048, false, false, {}, "100", "V",
     "voxels along the longest side of the bounding box", {},
     [](const Parameters& p) { return double(p.voxel_resolution); },
     [](Parameters& p, double x) { p.voxel_resolution = int(x); }},
    {"initial_voxel_size", "voxelize", K::REAL, 0, inf, true, true, {}, "d_bb/9", "S0",
     "size of the coarsest voxels (input units), rounded down to a power-of-3 multiple of the finest", {},
     [](const Parameters& p) { return internal::optional_value(p.initial_voxel_size); },
     [](Parameters& p, double x) { p.initial_voxel_size = x; },
     [](const Parameters& p) { return p.initial_voxel_size.has_value(); }},
    {"exterior_propagation_steps", "voxelize", K::INTEGER, 1, 27, false, false, {}, "1", "N",
     "face-neighbour steps of the exterior through the empty sub-voxels per refinement level", {},
     [](const Parameters& p) { return double(p.exterior_propagation_steps); },
     [](Parameters& p, double x) { p.exterior_propagation_steps = int(x); }},
    {"outlier_component_size", "remove_outlier_voxels", K::INTEGER, 0, 1 << 20, false, false, {}, "max(3, V/10)", "N",
     "largest extent in voxels of a removable outlier cluster", {},
     [](const Parameters& p) { return internal::optional_value(p.outlier_component_size); },
     [](Parameters& p, double x) { p.outlier_component_size = int(x); },
     [](const Parameters& p) { return p.outlier_component_size.has_value(); }},
    {"thinning_coefficient", "extract_initial_skeleton", K::REAL, 0, 10, true, false, {}, "0.86", "C",
     "c of the thinning thresholds TP_k", {},
     [](const Parameters& p) { return p.thinning_coefficient; },
     [](Parameters& p, double x) { p.thinning_coefficient = x; }},
    {"spur_length_ratio", "extract_initial_skeleton", K::REAL, 0, inf, false, true, {}, "1", "X",
     "prune initial-skeleton spurs shorter than X times the local radius", {},
     [](const Parameters& p) { return p.spur_length_ratio; },
     [](Parameters& p, double x) { p.spur_length_ratio = x; }},
    {"skeletonization_method", "contract", K::CHOICE, 0, 1, false, false, {"df_l1", "l1"}, "df_l1", "METHOD",
     "refinement: df_l1 (distance-field guided) or l1 (plain L1-medial skeleton)", {{{"method", nullptr}, {}}},
     [](const Parameters& p) { return double(int(p.skeletonization_method)); },
     [](Parameters& p, double x) { p.skeletonization_method = Skeletonization_method(int(x)); }},
    {"number_of_samples", "contract", K::INTEGER, 1, 1e8, false, false, {}, "1500", "M",
     "samples contracted (at most the points)", {{{"samples", nullptr}, {}}},
     [](const Parameters& p) { return double(p.number_of_samples); },
     [](Parameters& p, double x) { p.number_of_samples = std::size_t(x); }},
    {"repulsion_coefficient", "contract", K::REAL, 0, 0.5, false, true, {}, "0.35", "U",
     "u, weight of the repulsion between samples", {{{"repulsion", nullptr}, {}}},
     [](const Parameters& p) { return p.repulsion_coefficient; },
     [](Parameters& p, double x) { p.repulsion_coefficient = x; }},
    {"initial_support_radius", "contract", K::REAL, 0, inf, true, true, {}, "2*d_bb/cbrt(N)", "H0",
     "h0, initial support radius of the contraction (input units)", {{{"support-radius", nullptr}, {}}},
     [](const Parameters& p) { return internal::optional_value(p.initial_support_radius); },
     [](Parameters& p, double x) { p.initial_support_radius = x; },
     [](const Parameters& p) { return p.initial_support_radius.has_value(); }},
    {"support_radius_growth", "contract", K::REAL, 0, 4, true, false, {}, "0.5", "R",
     "growth of the support radius between stages, h <- (1+R) h", {{{"support-growth", nullptr}, {}}},
     [](const Parameters& p) { return p.support_radius_growth; },
     [](Parameters& p, double x) { p.support_radius_growth = x; }},
    {"branch_directionality", "contract", K::REAL, 1.0 / 3, 1, true, true, {}, "0.9", "S",
     "directionality sigma above which a sample may become a branch point", {{{"branch-sigma", nullptr}, {}}},
     [](const Parameters& p) { return p.branch_directionality; },
     [](Parameters& p, double x) { p.branch_directionality = x; }},
    {"number_of_iterations", "contract", K::INTEGER, 1, 10000, false, false, {}, "30", "N",
     "maximum iterations per support-radius stage of the contraction", {{{"iterations", nullptr}, {}}},
     [](const Parameters& p) { return double(p.number_of_iterations); },
     [](Parameters& p, double x) { p.number_of_iterations = int(x); }},
    {"contraction_stages", "contract", K::INTEGER, 1, 64, false, false, {}, "64", "N",
     "maximum support-radius stages of the contraction", {},
     [](const Parameters& p) { return double(p.contraction_stages); },
     [](Parameters& p, double x) { p.contraction_stages = int(x); }},
  };
  return table;
}

/// \ingroup PkgDFL1SkeletonRef
/// The row of `parameter_table()` named `name`.
/// \throws Invalid_input if no parameter has this name
inline const Parameter_info& parameter_info(const std::string& name)
{
  for(const Parameter_info& info : parameter_table())
    if(name == info.name)
      return info;
  throw Invalid_input("unknown parameter '" + name + "'");
}

namespace internal {

// `x` if it lies in the range of `name`; otherwise an Invalid_input that names the
// stage (when not null), the parameter, its range and the value.
inline double checked_parameter(const char* name, double x, const char* stage)
{
  const Parameter_info& info = parameter_info(name);
  if(!info.in_range(x))
  {
    std::ostringstream s;
    if(stage)
      s << stage << ": ";
    s << name << " must be "
      << (info.kind == Parameter_kind::INTEGER ? "an integer in " : "a number in ") << info.range_text() << ", got " << x;
    throw Invalid_input(s.str());
  }
  return x;
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Checks every value of `p` against its range.
/// \throws Invalid_input naming the first parameter out of range and `stage`
inline void check_parameters(const Parameters& p, const char* stage = "parameters")
{
  for(const Parameter_info& info : parameter_table())
  {
    if((info.given == nullptr || info.given(p)) && info.kind != Parameter_kind::CHOICE &&
       info.kind != Parameter_kind::BOOLEAN)
      internal::checked_parameter(info.name, info.read(p), stage);
  }
}

/// \ingroup PkgDFL1SkeletonRef
/// Sets the parameter `name` of `p` from its text (a number, `on`/`off`, or one of its
/// choices), as the tool's options and scripting bindings give it.
/// \throws Invalid_input when the name is unknown, the text is not a value of the
///         parameter's kind or the value is out of range; `p` is then unchanged
inline void set_parameter(Parameters& p, const std::string& name, const std::string& text)
{
  const Parameter_info& info = parameter_info(name);
  double x = 0;
  if(info.kind == Parameter_kind::CHOICE || info.kind == Parameter_kind::BOOLEAN)
  {
    const std::array<const char*, 6> booleans{"off", "on", "false", "true", "0", "1"};
    int found = -1;
    for(int i = 0; i < 3; ++i)
      if(info.choices[std::size_t(i)] && text == info.choices[std::size_t(i)])
        found = i;
    if(info.kind == Parameter_kind::BOOLEAN)
      for(int i = 0; i < 6; ++i)
        if(text == booleans[std::size_t(i)])
          found = i % 2;
    if(found < 0)
    {
      std::string allowed;
      for(const char* c : info.choices)
        if(c)
          allowed += std::string(allowed.empty() ? "" : ", ") + c;
      throw Invalid_input(std::string(name) + " must be one of " + allowed + ", got '" + text + "'");
    }
    x = found;
  }
  else
  {
    char* end = nullptr;
    errno = 0;
    x = std::strtod(text.c_str(), &end);
    if(text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
      throw Invalid_input(std::string(name) + " expects " +
                          (info.kind == Parameter_kind::INTEGER ? "an integer" : "a number") + ", got '" + text + "'");
    internal::checked_parameter(info.name, x, nullptr);
  }
  info.write(p, x);
}

/// \ingroup PkgDFL1SkeletonRef
/// The value of the parameter `name` of `p` as `set_parameter()` reads it back (empty
/// when it derives from the input and was not given).
inline std::string parameter_text(const Parameters& p, const std::string& name)
{
  const Parameter_info& info = parameter_info(name);
  if(info.given && !info.given(p))
    return {};
  const double x = info.read(p);
  if(info.kind == Parameter_kind::CHOICE || info.kind == Parameter_kind::BOOLEAN)
    return info.choices[std::size_t(x)];
  // the shortest text that reads back as the same double
  std::string text;
  for(int digits = 6; digits <= 17; ++digits)
  {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    text = s.str();
    if(std::strtod(text.c_str(), nullptr) == x)
      break;
  }
  return text;
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_PARAMETERS_H
