// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_generate: writes a synthetic point cloud with a known skeleton (see
// test/support/synthetic_shapes.h) to an .xyz file.
//
//   df_l1_generate SHAPE VARIANT N SEED OUTPUT.xyz
//   df_l1_generate --list

#include "support/synthetic_shapes.h"

#include <cstdint>
#include <exception>
#include <iostream>
#include <string>

namespace {

void print_usage(std::ostream& os)
{
  os << "usage: df_l1_generate SHAPE VARIANT N SEED OUTPUT.xyz\n"
        "       df_l1_generate --list\n"
        "Writes N points (one \"x y z\" line each) sampled on SHAPE and degraded by VARIANT;\n"
        "the same arguments always give the same file. --list prints the shape and variant names.\n";
}

/// Parses a whole string as an unsigned decimal integer; false on anything else.
bool parse_unsigned(const std::string& text, std::uint64_t& value)
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    return false;
  try {
    value = std::stoull(text);
  } catch(const std::exception&) { // out of range
    return false;
  }
  return true;
}

int usage_error(const std::string& message)
{
  std::cerr << "df_l1_generate: " << message << "\n";
  print_usage(std::cerr);
  return 2;
}

} // namespace

int main(int argc, char* argv[])
{
  using namespace DF_L1_test;
  if(argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    print_usage(std::cout);
    return 0;
  }
  if(argc == 2 && std::string(argv[1]) == "--list") {
    std::cout << "shapes:";
    for(const auto& entry : all_shapes())
      std::cout << ' ' << entry.first;
    std::cout << " (also star_K, many_armed_K for K arms, 3 <= K <= 16)\nvariants:";
    for(Variant v : all_variants())
      std::cout << ' ' << to_string(v);
    std::cout << '\n';
    return 0;
  }
  if(argc != 6)
    return usage_error("expected 5 arguments");

  Shape shape;
  Variant variant = Variant::clean;
  try {
    shape = shape_by_name(argv[1]);
    variant = variant_by_name(argv[2]);
  } catch(const std::invalid_argument& e) {
    return usage_error(e.what());
  }
  std::uint64_t n = 0, seed = 0;
  if(!parse_unsigned(argv[3], n) || n == 0)
    return usage_error(std::string("N must be a positive integer, got '") + argv[3] + "'");
  if(!parse_unsigned(argv[4], seed))
    return usage_error(std::string("SEED must be a non-negative integer, got '") + argv[4] + "'");

  try {
    const Sample sample = make_sample(shape, variant, std::size_t(n), seed);
    write_xyz(argv[5], sample.points);
    std::cout << "wrote " << sample.points.size() << " points (" << shape.name() << ", " << to_string(variant)
              << ", seed " << seed << ") to " << argv[5] << '\n';
  } catch(const std::exception& e) {
    std::cerr << "df_l1_generate: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
