// The scans of ../shared/data, which tests read when they are present. Every test that
// reads them carries the tag [shared_data]; CTest runs those tests as entries of their
// own (df_l1_test_<area>_shared_data) and reports such an entry as skipped when it
// prints the message of a missing folder below. The environment variable
// DF_L1_SHARED_DATA_DIR overrides the folder the build was configured with.
#ifndef DF_L1_TEST_SUPPORT_SHARED_DATA_H
#define DF_L1_TEST_SUPPORT_SHARED_DATA_H

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace DF_L1_test {

// The shared data folder, or "" (with the skip message) when it is absent.
inline std::string shared_data_folder()
{
  std::string folder;
  if(const char* from_environment = std::getenv("DF_L1_SHARED_DATA_DIR"))
    folder = from_environment;
#ifdef DF_L1_SHARED_DATA_DIR
  else
    folder = DF_L1_SHARED_DATA_DIR;
#endif
  std::error_code ec;
  if(folder.empty() || !std::filesystem::is_directory(folder, ec))
  {
    WARN("skipped: the shared data folder " << (folder.empty() ? "(not configured)" : folder) << " is absent");
    return std::string();
  }
  return folder;
}

// The path of a shared scan, or "" (with a message naming it) when it is absent.
inline std::string shared_data_file(const std::string& name)
{
  const std::string folder = shared_data_folder();
  if(folder.empty())
    return std::string();
  const std::string path = folder + "/" + name;
  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec))
  {
    WARN("skipped: " << name << " is not in the shared data folder " << folder);
    return std::string();
  }
  return path;
}

} // namespace DF_L1_test

#endif // DF_L1_TEST_SUPPORT_SHARED_DATA_H
