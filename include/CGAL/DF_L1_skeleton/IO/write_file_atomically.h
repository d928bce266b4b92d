// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_WRITE_FILE_ATOMICALLY_H
#define CGAL_DF_L1_SKELETON_IO_WRITE_FILE_ATOMICALLY_H

/// \file write_file_atomically.h
/// Writing a file "whole or not at all": the content goes to a temporary file
/// next to the destination, which is renamed over the destination only once it
/// has been written and closed without error. A reader of the destination thus
/// sees either the old file or the complete new one, never a truncated one.

#include <CGAL/DF_L1_skeleton/errors.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <locale>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>

#if defined(_WIN32)
#include <process.h>
#else
#include <unistd.h>
#endif

namespace CGAL {
namespace DF_L1 {
namespace internal {

inline long current_process_id()
{
#if defined(_WIN32)
  return static_cast<long>(::_getpid());
#else
  return static_cast<long>(::getpid());
#endif
}

/// Removes the temporary file on scope exit unless it was handed over.
class Temporary_file_guard
{
public:
  explicit Temporary_file_guard(std::filesystem::path p) : path_(std::move(p)) {}
  Temporary_file_guard(const Temporary_file_guard&) = delete;
  Temporary_file_guard& operator=(const Temporary_file_guard&) = delete;
  ~Temporary_file_guard()
  {
    if(armed_) {
      std::error_code ec; // best effort: never throw from a destructor
      std::filesystem::remove(path_, ec);
    }
  }
  void release() { armed_ = false; }

private:
  std::filesystem::path path_;
  bool armed_ = true;
};

/// The reason for the last failed system call, as text (errno is set by the
/// C library under std::ofstream on the platforms we target; it is only used
/// to make the message more helpful).
inline std::string errno_reason(int err, const char* fallback)
{
  if(err == 0)
    return fallback;
  return std::generic_category().message(err);
}

/// Checks the destination before anything is created, so that the common
/// mistakes get a clear message rather than a generic "cannot open".
inline std::filesystem::path checked_destination(const std::string& path)
{
  namespace fs = std::filesystem;
  if(path.empty())
    throw Write_error("cannot write file: empty output path");

  fs::path dest(path);
  std::error_code ec;

  // Write through symbolic links rather than replacing the link itself (the
  // bound stops on link cycles, which then fail below or at opening).
  for(int depth = 0; depth < 40 && fs::is_symlink(dest, ec); ++depth) {
    const fs::path target = fs::read_symlink(dest, ec);
    if(ec)
      break;
    dest = target.is_absolute() ? target : dest.parent_path() / target;
  }

  if(!dest.has_filename())
    throw Write_error("cannot write '" + path + "': the path names a directory, not a file");

  if(fs::is_directory(dest, ec))
    throw Write_error("cannot write '" + path + "': a directory with this name exists");

  const fs::path dir = dest.has_parent_path() ? dest.parent_path() : fs::path(".");
  if(!fs::exists(dir, ec))
    throw Write_error("cannot write '" + path + "': directory '" + dir.string() +
                      "' does not exist");
  if(!fs::is_directory(dir, ec))
    throw Write_error("cannot write '" + path + "': '" + dir.string() + "' is not a directory");
  return dest;
}

/// A fresh name `.<name>.tmp.<pid>.<counter>` in the directory of `dest`.
/// The pid separates processes, the counter separates threads and calls.
inline std::filesystem::path temporary_path_for(const std::filesystem::path& dest)
{
  static std::atomic<unsigned long> counter{0};
  const std::filesystem::path dir = dest.parent_path();
  const std::string base = "." + dest.filename().string() + ".tmp." +
                           std::to_string(current_process_id()) + ".";
  for(;;) {
    std::filesystem::path candidate = dir / (base + std::to_string(counter++));
    std::error_code ec;
    // A leftover from a crashed process with a recycled pid must not be reused.
    if(!std::filesystem::exists(candidate, ec))
      return candidate;
  }
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Writes a file whole or not at all.
///
/// `write_content(os)` writes the content to `os`, a stream opened on a
/// temporary file in the directory of `path` and imbued with the classic "C"
/// locale (so that numbers never get locale-specific separators). When it
/// returns and the stream has been flushed and closed without error, the
/// temporary file is renamed over `path`. On any failure the temporary file is
/// removed and `path` is left as it was.
///
/// If `path` is a symbolic link, the file it points to is replaced. If `path`
/// exists, its permissions are carried over to the new file.
///
/// \tparam F a callable `void(std::ostream&)`
/// \param path the destination
/// \param write_content writes the content
/// \param binary open the stream in binary mode
/// \throws Write_error naming `path` and the reason when the file cannot be
///         created, written, closed or renamed (missing directory, permission
///         denied, disk full...).
/// \throws any exception thrown by `write_content`, unchanged (the temporary
///         file is removed and `path` untouched).
template <class F>
void write_file_atomically(const std::string& path, F&& write_content, bool binary = false)
{
  namespace fs = std::filesystem;
  const fs::path dest = internal::checked_destination(path);
  const fs::path tmp = internal::temporary_path_for(dest);

  std::ios_base::openmode mode = std::ios_base::out | std::ios_base::trunc;
  if(binary)
    mode |= std::ios_base::binary;

  // Declared before the stream so that the stream is closed before the file is
  // removed (an open file cannot be removed on Windows).
  internal::Temporary_file_guard guard(tmp);
  errno = 0;
  std::ofstream os(tmp, mode);
  if(!os) {
    const int err = errno; // before anything else can change it
    throw Write_error("cannot write '" + path + "': cannot create a file in '" +
                      tmp.parent_path().string() + "': " +
                      internal::errno_reason(err, "cannot open file for writing"));
  }
  os.imbue(std::locale::classic());

  write_content(static_cast<std::ostream&>(os));

  errno = 0;
  if(os)
    os.flush();
  if(!os) {
    const int err = errno;
    throw Write_error("cannot write '" + path + "': writing failed: " +
                      internal::errno_reason(err, "output error (disk full?)"));
  }
  errno = 0;
  os.close();
  if(os.fail()) {
    const int err = errno;
    throw Write_error("cannot write '" + path + "': closing the file failed: " +
                      internal::errno_reason(err, "output error (disk full?)"));
  }

  std::error_code ec;
  const fs::file_status old_status = fs::status(dest, ec);
  if(!ec && fs::exists(old_status)) {
    std::error_code ignored; // keeping the permissions is a courtesy, not a requirement
    fs::permissions(tmp, old_status.permissions(), fs::perm_options::replace, ignored);
  }

  ec.clear();
  fs::rename(tmp, dest, ec);
  if(ec)
    throw Write_error("cannot write '" + path + "': cannot replace the file: " + ec.message());
  guard.release();
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_WRITE_FILE_ATOMICALLY_H
