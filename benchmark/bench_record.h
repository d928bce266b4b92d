// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// One benchmark result: a line of tab-separated key=value fields, in the order they
// were set. Flat text keeps the results readable, greppable and appendable by a shell
// script, and needs no JSON parser to read back.
#ifndef DF_L1_BENCHMARK_BENCH_RECORD_H
#define DF_L1_BENCHMARK_BENCH_RECORD_H

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace DF_L1_bench {

class Record
{
public:
  Record& set(const std::string& key, const std::string& value)
  {
    if(key.find_first_of("=\t\n") != std::string::npos || value.find_first_of("\t\n") != std::string::npos)
      throw std::invalid_argument("benchmark record: bad key or value '" + key + "'");
    for(auto& f : fields_)
      if(f.first == key)
      {
        f.second = value;
        return *this;
      }
    fields_.emplace_back(key, value);
    return *this;
  }
  Record& set(const std::string& key, double value)
  {
    std::ostringstream os;
    os.precision(6);
    os << value;
    return set(key, os.str());
  }

  bool has(const std::string& key) const
  {
    return std::any_of(fields_.begin(), fields_.end(), [&](const auto& f) { return f.first == key; });
  }
  std::string text(const std::string& key, const std::string& fallback = "") const
  {
    for(const auto& f : fields_)
      if(f.first == key)
        return f.second;
    return fallback;
  }
  double number(const std::string& key) const
  {
    const std::string t = text(key);
    if(t.empty())
      return std::nan("");
    try
    {
      return std::stod(t);
    }
    catch(const std::exception&)
    {
      return std::nan("");
    }
  }
  const std::vector<std::pair<std::string, std::string>>& fields() const { return fields_; }

  std::string line() const
  {
    std::string s;
    for(const auto& f : fields_)
      s += (s.empty() ? "" : "\t") + f.first + "=" + f.second;
    return s;
  }
  static Record parse(const std::string& line)
  {
    Record r;
    std::istringstream is(line);
    std::string field;
    while(std::getline(is, field, '\t'))
    {
      const std::size_t eq = field.find('=');
      if(eq != std::string::npos)
        r.fields_.emplace_back(field.substr(0, eq), field.substr(eq + 1));
    }
    return r;
  }

private:
  std::vector<std::pair<std::string, std::string>> fields_;
};

inline std::vector<Record> read_records(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot read " + path);
  std::vector<Record> records;
  std::string line;
  while(std::getline(in, line))
    if(!line.empty() && line[0] != '#')
      records.push_back(Record::parse(line));
  return records;
}

/// Median, min and max of repeated measurements.
struct Spread
{
  double median = 0, min = 0, max = 0;
};

inline Spread spread(std::vector<double> x)
{
  Spread s;
  if(x.empty())
    return s;
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  s.median = n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
  s.min = x.front();
  s.max = x.back();
  return s;
}

/// Numbers as one comma-separated field, and back.
inline std::string join_numbers(const std::vector<double>& x)
{
  std::ostringstream os;
  os.precision(6);
  for(std::size_t i = 0; i < x.size(); ++i)
    os << (i ? "," : "") << x[i];
  return os.str();
}

inline std::vector<double> split_numbers(const std::string& text)
{
  std::vector<double> x;
  std::istringstream is(text);
  std::string item;
  while(std::getline(is, item, ','))
    try
    {
      x.push_back(std::stod(item));
    }
    catch(const std::exception&)
    {
      return {}; // not a list of numbers
    }
  return x;
}

} // namespace DF_L1_bench

#endif // DF_L1_BENCHMARK_BENCH_RECORD_H
