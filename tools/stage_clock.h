// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What df_l1_skeleton measures of its run: the time of each stage (shown as progress on
// stderr and kept for the report) and the peak memory.
#ifndef DF_L1_TOOLS_STAGE_CLOCK_H
#define DF_L1_TOOLS_STAGE_CLOCK_H

#include "json_object.h"

#include <sys/resource.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <string>

namespace df_l1_tool {

// Runs the stages, timing each one under its name.
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
  // Seconds per stage, in the order the stages ran.
  const Json_object& times() const { return times_; }

private:
  bool quiet_;
  Json_object times_;
};

// The peak resident memory of the process so far, in MiB.
inline double peak_memory_mib()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}

} // namespace df_l1_tool

#endif // DF_L1_TOOLS_STAGE_CLOCK_H
