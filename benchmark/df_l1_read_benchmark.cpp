// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reading speed of the point cloud readers (doc/fuzzing.md has the figures):
//
//   df_l1_read_benchmark convert IN.xyz PREFIX   writes PREFIX.ply (ASCII, the same
//       tokens as IN.xyz), PREFIX_binary.ply (little endian doubles) and PREFIX.off
//   df_l1_read_benchmark read FILE [--stream]    reads FILE with read_point_cloud()
//       (or, with --stream, the std::istream reader of its format) and prints the
//       seconds, MB/s, the point count, a digest of the bits of every coordinate
//       (equal digests: bit-identical values) and the peak RSS of the process.
//
// Run `read` once per process: the peak RSS is the process's.

#include <CGAL/DF_L1_skeleton/IO/read_point_cloud.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

std::uint64_t digest(const CGAL::DF_L1::Point_cloud<K>& pc)
{
  std::uint64_t h = 1469598103934665603ull; // FNV-1a over the bit patterns
  auto add = [&h](double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    for(int i = 0; i < 8; ++i) {
      h ^= (bits >> (8 * i)) & 0xff;
      h *= 1099511628211ull;
    }
  };
  for(const auto& p : pc.points) {
    add(p.x());
    add(p.y());
    add(p.z());
  }
  for(const auto& n : pc.normals) {
    add(n.x());
    add(n.y());
    add(n.z());
  }
  return h;
}

int convert(const std::string& in_name, const std::string& prefix)
{
  std::vector<std::string> lines;
  {
    std::ifstream in(in_name);
    for(std::string line; std::getline(in, line);)
      if(!line.empty())
        lines.push_back(line);
  }
  const auto cloud = CGAL::DF_L1::read_point_cloud<K>(in_name);
  const std::string header_props = "property double x\nproperty double y\nproperty double z\n";
  {
    std::ofstream out(prefix + ".ply", std::ios::binary);
    out << "ply\nformat ascii 1.0\nelement vertex " << lines.size() << "\n" << header_props
        << "end_header\n";
    for(const std::string& l : lines)
      out << l << "\n";
  }
  {
    std::ofstream out(prefix + "_binary.ply", std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << cloud.points.size() << "\n"
        << header_props << "end_header\n";
    for(const auto& p : cloud.points) {
      const double v[3] = {p.x(), p.y(), p.z()};
      out.write(reinterpret_cast<const char*>(v), sizeof v); // the benchmark host is little endian
    }
  }
  {
    std::ofstream out(prefix + ".off", std::ios::binary);
    out << "OFF\n" << lines.size() << " 0 0\n";
    for(const std::string& l : lines)
      out << l << "\n";
  }
  return 0;
}

int read(const std::string& name, bool stream)
{
  const auto start = std::chrono::steady_clock::now();
  CGAL::DF_L1::Point_cloud<K> pc;
  if(stream) {
    std::ifstream in(name, std::ios::binary);
    const std::string ext = std::filesystem::path(name).extension().string();
    if(ext == ".ply")
      pc = CGAL::DF_L1::read_ply_point_cloud<K>(in, name);
    else if(ext == ".off")
      pc = CGAL::DF_L1::read_off_point_cloud<K>(in, name);
    else
      pc = CGAL::DF_L1::read_xyz_point_cloud<K>(in, name);
  } else {
    pc = CGAL::DF_L1::read_point_cloud<K>(name);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double mb = static_cast<double>(std::filesystem::file_size(name)) / 1e6;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("%s%s: %.0f MB, %zu points, %.3f s, %.0f MB/s, digest %016llx, peak RSS %.0f MB\n",
              name.c_str(), stream ? " (stream)" : "", mb, pc.points.size(), seconds, mb / seconds,
              static_cast<unsigned long long>(digest(pc)), usage.ru_maxrss / 1024.0);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if(args.size() == 3 && args[0] == "convert")
      return convert(args[1], args[2]);
    if((args.size() == 2 || (args.size() == 3 && args[2] == "--stream")) && args[0] == "read")
      return read(args[1], args.size() == 3);
  } catch(const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  std::cerr << "usage: df_l1_read_benchmark convert IN.xyz PREFIX\n"
               "       df_l1_read_benchmark read FILE [--stream]\n";
  return 2;
}
