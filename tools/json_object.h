// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A minimal JSON object writer for the --report of df_l1_skeleton: programs read the report,
// so its keys keep their insertion order and its formatting stays fixed.
#ifndef DF_L1_TOOLS_JSON_OBJECT_H
#define DF_L1_TOOLS_JSON_OBJECT_H

#include <cmath>
#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace df_l1_tool {

// A JSON object written in insertion order, numbers with round-trip precision.
class Json_object
{
public:
  Json_object& number(const std::string& key, double x)
  {
    std::ostringstream s;
    if(std::isfinite(x))
      s << std::setprecision(15) << x;
    else
      s << "null";
    return raw(key, s.str());
  }
  Json_object& text(const std::string& key, const std::string& value)
  {
    std::string quoted = "\"";
    for(char c : value)
    {
      if(c == '"' || c == '\\')
        quoted += '\\';
      if(static_cast<unsigned char>(c) < 0x20)
        c = ' ';
      quoted += c;
    }
    return raw(key, quoted + "\"");
  }
  Json_object& boolean(const std::string& key, bool b) { return raw(key, b ? "true" : "false"); }
  Json_object& object(const std::string& key, const Json_object& o) { return raw(key, o.str("  ")); }
  Json_object& raw(const std::string& key, const std::string& value)
  {
    entries_.emplace_back(key, value);
    return *this;
  }
  // On one line: {"a": 1, "b": 2}.
  std::string inline_str() const
  {
    std::string s = "{";
    for(std::size_t i = 0; i < entries_.size(); ++i)
      s += (i ? ", \"" : "\"") + entries_[i].first + "\": " + entries_[i].second;
    return s + "}";
  }
  std::string str(const std::string& indent = "") const
  {
    std::string s = "{";
    for(std::size_t i = 0; i < entries_.size(); ++i)
      s += (i ? ",\n" : "\n") + indent + "  \"" + entries_[i].first + "\": " + entries_[i].second;
    return s + "\n" + indent + "}";
  }

private:
  std::vector<std::pair<std::string, std::string>> entries_;
};

} // namespace df_l1_tool

#endif // DF_L1_TOOLS_JSON_OBJECT_H
