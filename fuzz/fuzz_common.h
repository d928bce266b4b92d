// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the libFuzzer targets of the point cloud readers: a minimal cloud
// type (the parsers are templates, so no CGAL kernel is needed, which keeps the
// sanitized build small) and the checks of a successful parse.

#ifndef DF_L1_FUZZ_COMMON_H
#define DF_L1_FUZZ_COMMON_H

#include <CGAL/DF_L1_skeleton/errors.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace df_l1_fuzz {

struct Triple
{
  double x, y, z;
  Triple(double a, double b, double c) : x(a), y(b), z(c) {}
};

struct Cloud
{
  std::vector<Triple> points;
  std::vector<Triple> normals;
};

[[noreturn]] inline void invariant_broken(const char* what)
{
  std::fprintf(stderr, "invariant broken after a successful parse: %s\n", what);
  std::abort(); // libFuzzer saves the input as a crash
}

inline bool finite(const Triple& t)
{
  return std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z);
}

/// What every successful parse must give: at least one point, finite
/// coordinates, and normals that are absent or one per point (and finite).
inline void check_cloud(const Cloud& pc)
{
  if(pc.points.empty())
    invariant_broken("no points");
  for(const Triple& p : pc.points)
    if(!finite(p))
      invariant_broken("a coordinate is not finite");
  if(!pc.normals.empty() && pc.normals.size() != pc.points.size())
    invariant_broken("normals count differs from the points count");
  for(const Triple& n : pc.normals)
    if(!finite(n))
      invariant_broken("a normal is not finite");
}

/// Runs `parse(buffer, name, cloud)` on the fuzz input: a Read_error is a
/// valid outcome, as is a cloud meeting `check_cloud`; anything else (another
/// exception, a crash, a sanitizer report, a hang) is a bug.
template <class Parse>
int run(const std::uint8_t* data, std::size_t size, const Parse& parse)
{
  const std::string_view buffer(reinterpret_cast<const char*>(data), size);
  Cloud pc;
  try {
    parse(buffer, std::string("fuzz-input"), pc);
  } catch(const CGAL::DF_L1::Read_error& e) {
    // Messages must stay one line, whatever the input holds.
    const std::string_view what(e.what());
    if(what.find('\n') != std::string_view::npos || what.find('\r') != std::string_view::npos)
      invariant_broken("a Read_error message spans several lines");
    return 0;
  }
  check_cloud(pc);
  return 0;
}

} // namespace df_l1_fuzz

#endif // DF_L1_FUZZ_COMMON_H
