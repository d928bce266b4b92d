// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// df_l1_generate: writes a synthetic point cloud with a known skeleton (see
// tools/evaluation/synthetic_shapes.h) to an .xyz file.
//
//   df_l1_generate SHAPE VARIANT N SEED OUTPUT.xyz
//   df_l1_generate --list
//
// SHAPE is a named shape or a shape of the procedural corpus (FAMILY_INDEX, e.g.
// trees_12; tools/evaluation/shape_corpus.h), VARIANT a variant or a corpus degradation
// (e.g. noise_0.6, outliers_3).

#include "evaluation/shape_corpus.h"
#include "evaluation/synthetic_shapes.h"

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
        "the same arguments always give the same file. --list prints the shape and variant names.\n"
        "SHAPE may also be a corpus shape FAMILY_INDEX (e.g. trees_12) and VARIANT a corpus\n"
        "degradation (e.g. noise_0.6); scripts/quality.sh judges the library on all of them.\n";
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
    std::cout << "\ncorpus shapes: FAMILY_INDEX, 0 <= INDEX < " << corpus_shapes_per_family << ", FAMILY in";
    for(const std::string& f : corpus_families())
      std::cout << ' ' << f;
    std::cout << "\ncorpus degradations:";
    for(const Degradation& d : corpus_degradations())
      std::cout << ' ' << d.name;
    std::cout << '\n';
    return 0;
  }
  if(argc != 6)
    return usage_error("expected 5 arguments");

  Shape shape;
  Variant variant = Variant::clean;
  Variant_options options;
  try {
    const std::string name = argv[1];
    bool corpus = false;
    for(const std::string& f : corpus_families()) {
      const std::string prefix = f + "_";
      if(name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
         name.find_first_not_of("0123456789", prefix.size()) == std::string::npos && name.size() - prefix.size() <= 6) {
        shape = corpus_shape(f, std::stoi(name.substr(prefix.size())));
        corpus = true;
      }
    }
    if(!corpus)
      shape = shape_by_name(name);
    bool degradation = false;
    for(const Degradation& d : corpus_degradations())
      if(d.name == argv[2] && std::string(argv[2]) != to_string(d.variant)) {
        variant = d.variant;
        options = d.options;
        degradation = true;
      }
    if(!degradation)
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
    const Sample sample = make_sample(shape, variant, std::size_t(n), seed, options);
    write_xyz(argv[5], sample.points);
    std::cout << "wrote " << sample.points.size() << " points (" << shape.name() << ", " << to_string(variant)
              << ", seed " << seed << ") to " << argv[5] << '\n';
  } catch(const std::exception& e) {
    std::cerr << "df_l1_generate: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
