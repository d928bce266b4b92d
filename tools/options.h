// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Command-line options of df_l1_skeleton: a table, so that parsing, --help and the
// defaults shown by --help cannot drift apart.
#ifndef DF_L1_TOOLS_OPTIONS_H
#define DF_L1_TOOLS_OPTIONS_H

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace df_l1_tool {

struct Usage_error : std::runtime_error
{
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

struct Option
{
  std::string name;          // without the leading "--"
  std::string argument;      // name of the argument, empty for a flag
  std::string default_text;  // shown by --help
  std::string help;
  std::function<void(const std::string&)> apply;
};

inline double parse_number(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
    throw Usage_error("--" + option + " expects a number, got '" + text + "'");
  return x;
}

inline long parse_integer(const std::string& option, const std::string& text, long lo, long hi)
{
  char* end = nullptr;
  errno = 0;
  const long x = std::strtol(text.c_str(), &end, 10);
  if(text.empty() || *end != '\0' || errno == ERANGE)
    throw Usage_error("--" + option + " expects an integer, got '" + text + "'");
  if(x < lo || x > hi)
    throw Usage_error("--" + option + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                      "], got " + text);
  return x;
}

// A number of bytes: an integer or decimal number with an optional unit K, M, G or T
// (powers of 1024; "KiB", "MB" and "B" are read alike).
inline double parse_bytes(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  std::string unit(end);
  for(char& c : unit)
    c = char(std::toupper(static_cast<unsigned char>(c)));
  if(unit.size() > 1 && unit.back() == 'B')
    unit.pop_back();
  if(unit.size() > 1 && unit.back() == 'I')
    unit.pop_back();
  const std::string units = "BKMGT";
  const std::size_t power = unit.empty() ? 0 : units.find(unit);
  if(text.empty() || end == text.c_str() || errno == ERANGE || !std::isfinite(x) || !(x > 0) || unit.size() > 1 ||
     power == std::string::npos)
    throw Usage_error("--" + option + " expects a positive size such as 512M, 4G or 1073741824, got '" + text + "'");
  return x * std::pow(1024.0, double(power));
}

// Parses argv against the table; returns the positional arguments.
inline std::vector<std::string> parse_options(int argc, char** argv, const std::vector<Option>& table)
{
  std::vector<std::string> positional;
  for(int a = 1; a < argc; ++a)
  {
    std::string arg = argv[a];
    if(arg.size() < 3 || arg.compare(0, 2, "--") != 0)
    {
      if(arg.size() > 1 && arg[0] == '-' && arg != "-")
        throw Usage_error("unknown option '" + arg + "' (see --help)");
      positional.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2), value;
    const std::size_t eq = name.find('=');
    const bool has_value = eq != std::string::npos;
    if(has_value)
    {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    const Option* option = nullptr;
    for(const Option& o : table)
      if(o.name == name)
        option = &o;
    if(option == nullptr)
      throw Usage_error("unknown option '--" + name + "' (see --help)");
    if(option->argument.empty())
    {
      if(has_value)
        throw Usage_error("--" + name + " takes no argument");
    }
    else if(!has_value)
    {
      if(a + 1 >= argc)
        throw Usage_error("--" + name + " expects " + option->argument);
      value = argv[++a];
    }
    option->apply(value);
  }
  return positional;
}

} // namespace df_l1_tool

#endif // DF_L1_TOOLS_OPTIONS_H
