// Writes the manual's parameter page: the text of parameters.md.in with the line
// @PARAMETER_TABLE@ replaced by a table made from CGAL::DF_L1::parameter_table(), so
// that the manual, the named parameters and the tool's --help share one source.
//
//   df_l1_parameter_page TEMPLATE.md.in OUTPUT.md

#include <CGAL/DF_L1_skeleton/Parameters.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {

std::string type_text(const CGAL::DF_L1::Parameter_info& p)
{
  using K = CGAL::DF_L1::Parameter_kind;
  switch(p.kind)
  {
  case K::INTEGER: return "integer in " + p.range_text();
  case K::REAL: return "real in " + p.range_text();
  case K::BOOLEAN: return "Boolean";
  case K::CHOICE: break;
  }
  std::string s;
  for(const char* c : p.choices)
    if(c)
      s += (s.empty() ? "" : ", ") + std::string("`") + c + "`";
  return "one of " + s;
}

std::string table()
{
  std::ostringstream t;
  t << "| parameter | read by | value | default | tool option | meaning |\n"
    << "|---|---|---|---|---|---|\n";
  for(const CGAL::DF_L1::Parameter_info& p : CGAL::DF_L1::parameter_table())
  {
    std::string help = p.help;
    for(std::size_t i = help.find('|'); i != std::string::npos; i = help.find('|', i + 2))
      help.replace(i, 1, "\\|");
    t << "| `" << p.name << "` | `DF_L1_skeletonization::" << p.stage << "()` | " << type_text(p) << " | `" << p.default_text
      << "` | `--" << p.option() << "` | " << help << " |\n";
  }
  return t.str();
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 3)
  {
    std::cerr << "usage: df_l1_parameter_page TEMPLATE.md.in OUTPUT.md\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if(!in)
  {
    std::cerr << "df_l1_parameter_page: cannot read " << argv[1] << "\n";
    return 1;
  }
  std::ostringstream page;
  bool placed = false;
  for(std::string line; std::getline(in, line);)
  {
    if(line == "@PARAMETER_TABLE@")
    {
      page << table();
      placed = true;
    }
    else
      page << line << "\n";
  }
  if(!placed)
  {
    std::cerr << "df_l1_parameter_page: " << argv[1] << " has no @PARAMETER_TABLE@ line\n";
    return 1;
  }
  std::ofstream out(argv[2]);
  out << page.str();
  if(!out.flush())
  {
    std::cerr << "df_l1_parameter_page: cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
