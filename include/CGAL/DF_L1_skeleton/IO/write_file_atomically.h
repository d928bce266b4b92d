// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_WRITE_FILE_ATOMICALLY_H
#define CGAL_DF_L1_SKELETON_IO_WRITE_FILE_ATOMICALLY_H

/// \file write_file_atomically.h
/// Writing a file "whole or not at all": the content goes to a temporary file
/// next to the destination, which is renamed over the destination only once it
/// has been written and closed without error. A reader of the destination thus
/// sees either the old file or the complete new one, never a truncated one.
///
/// Two additions serve programs that write several files and may be stopped:
/// `Atomic_file_group` renames the files of a group together at its commit, and
/// `remove_unfinished_files()`, async-signal-safe, removes the temporary files of
/// the writes in progress from a signal handler.

#include <CGAL/DF_L1_skeleton/errors.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <locale>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#if defined(_WIN32)
#include <process.h>
#else
#include <fcntl.h>
#include <sys/stat.h>
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

/// The temporary files being written, for remove_unfinished_files(): fixed
/// buffers, since a signal handler may neither allocate nor lock. Zero-initialised
/// static storage, so no constructor runs and every slot starts free.
struct Unfinished_file_slot
{
  std::atomic<int> state; // 0 free, 1 being filled, 2 holds a path to remove
  char path[4096];
};
constexpr int unfinished_file_slot_count = 32;
inline Unfinished_file_slot unfinished_file_slots[unfinished_file_slot_count];
/// The number of Atomic_file_group objects renaming their files.
inline std::atomic<int> committing_group{0};

/// Registers `path` for removal on a signal; returns its slot, or -1 when the
/// path is too long or the slots are full (the file is then written all the same).
inline int register_unfinished_file(const std::string& path) noexcept
{
  if(path.size() >= sizeof(Unfinished_file_slot::path))
    return -1;
  for(int i = 0; i < unfinished_file_slot_count; ++i) {
    int expected = 0;
    Unfinished_file_slot& slot = unfinished_file_slots[i];
    if(slot.state.compare_exchange_strong(expected, 1)) {
      std::memcpy(slot.path, path.c_str(), path.size() + 1);
      slot.state.store(2); // published only once complete
      return i;
    }
  }
  return -1;
}

inline void unregister_unfinished_file(int slot) noexcept
{
  if(slot >= 0)
    unfinished_file_slots[slot].state.store(0);
}

/// Registers the temporary file before it is created (a signal may come at any
/// point after), and removes it on scope exit unless it was handed over.
class Temporary_file_guard
{
public:
  explicit Temporary_file_guard(std::filesystem::path p)
      : path_(std::move(p)), slot_(register_unfinished_file(path_.string()))
  {}
  Temporary_file_guard(const Temporary_file_guard&) = delete;
  Temporary_file_guard& operator=(const Temporary_file_guard&) = delete;
  ~Temporary_file_guard()
  {
    if(armed_) {
      std::error_code ec; // best effort: never throw from a destructor
      std::filesystem::remove(path_, ec);
    }
    unregister_unfinished_file(slot_);
  }
  /// The file was renamed, or is owned by someone else from now on.
  void release() { armed_ = false; }
  /// Hands the registration over too (to an Atomic_file_group).
  int release_slot()
  {
    armed_ = false;
    const int slot = slot_;
    slot_ = -1;
    return slot;
  }
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
  int slot_;
  bool armed_ = true;
};

#if !defined(_WIN32)
/// An output buffer over a file descriptor that keeps the error of the first
/// failed write() or close(): a std::ofstream reports a full disk only as a
/// failed state, and errno is overwritten before it can be read.
class Fd_output_buffer : public std::streambuf
{
public:
  explicit Fd_output_buffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof(buffer_)); }
  Fd_output_buffer(const Fd_output_buffer&) = delete;
  Fd_output_buffer& operator=(const Fd_output_buffer&) = delete;
  ~Fd_output_buffer() override
  {
    if(fd_ >= 0)
      ::close(fd_);
  }
  /// errno of the first failure, 0 if none.
  int error() const { return error_; }
  /// Writes what is buffered and closes the descriptor; false on any failure.
  bool close()
  {
    const bool written = write_buffer();
    const int fd = fd_;
    fd_ = -1;
    // Some file systems (NFS, quotas) report a full disk only here.
    if(::close(fd) != 0 && error_ == 0)
      error_ = errno;
    return written && error_ == 0;
  }

protected:
  int_type overflow(int_type c) override
  {
    if(!write_buffer())
      return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return write_buffer() ? 0 : -1; }
  std::streamsize xsputn(const char* s, std::streamsize n) override
  {
    if(n < epptr() - pptr()) {
      std::memcpy(pptr(), s, static_cast<std::size_t>(n));
      pbump(static_cast<int>(n));
      return n;
    }
    return write_buffer() && write_all(s, static_cast<std::size_t>(n)) ? n : 0;
  }

private:
  bool write_all(const char* p, std::size_t n)
  {
    while(n > 0 && error_ == 0) {
      const ::ssize_t w = ::write(fd_, p, n);
      if(w < 0 && errno == EINTR)
        continue;
      if(w <= 0) // 0: no progress on a regular file, which should not happen
        error_ = w < 0 ? errno : EIO;
      else {
        p += w;
        n -= static_cast<std::size_t>(w);
      }
    }
    return error_ == 0;
  }
  bool write_buffer()
  {
    const bool ok = fd_ >= 0 && write_all(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    setp(buffer_, buffer_ + sizeof(buffer_));
    return ok;
  }

  int fd_;
  int error_ = 0;
  char buffer_[1 << 15];
};

/// Opens `path` for writing (creating it if `exclusive`, failing if it exists);
/// -1 with errno on failure.
inline int open_for_writing(const std::filesystem::path& path, bool exclusive)
{
  int flags = O_WRONLY;
#ifdef O_CLOEXEC
  flags |= O_CLOEXEC;
#endif
  if(exclusive)
    flags |= O_CREAT | O_EXCL;
  int fd;
  do
    fd = ::open(path.c_str(), flags, 0666);
  while(fd < 0 && errno == EINTR);
  return fd;
}
#endif

class Atomic_file_group_access;

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

/// Writes the content to `file`, open as `fd` (POSIX) and closes it, checking
/// every write and the close; `path` is the name for messages.
template <class F>
void write_and_close(int fd, const std::filesystem::path& file, const std::string& path, F& write_content, bool binary)
{
#if !defined(_WIN32)
  (void)file;
  (void)binary; // no text mode on POSIX
  Fd_output_buffer buffer(fd);
  std::ostream os(&buffer);
  os.imbue(std::locale::classic());
  write_content(os);
  if(os)
    os.flush();
  const bool written = bool(os);
  if(!buffer.close() || !written)
    throw Write_error("cannot write '" + path + "': " + (written ? "closing the file failed: " : "writing failed: ") +
                      errno_reason(buffer.error(), "output error (disk full?)"));
#else
  (void)fd;
  std::ios_base::openmode mode = std::ios_base::out | std::ios_base::trunc;
  if(binary)
    mode |= std::ios_base::binary;
  errno = 0;
  std::ofstream os(file, mode);
  if(!os) {
    const int err = errno;
    throw Write_error("cannot write '" + path + "': cannot create a file in '" + file.parent_path().string() +
                      "': " + errno_reason(err, "cannot open file for writing"));
  }
  os.imbue(std::locale::classic());
  write_content(static_cast<std::ostream&>(os));
  errno = 0;
  if(os)
    os.flush();
  if(!os) {
    const int err = errno;
    throw Write_error("cannot write '" + path + "': writing failed: " + errno_reason(err, "output error (disk full?)"));
  }
  errno = 0;
  os.close();
  if(os.fail()) {
    const int err = errno;
    throw Write_error("cannot write '" + path + "': closing the file failed: " +
                      errno_reason(err, "output error (disk full?)"));
  }
#endif
}

/// Gives a new file the permissions of the file it replaces (a courtesy, not a requirement).
inline void copy_permissions(const std::filesystem::path& from, const std::filesystem::path& to)
{
  std::error_code ec;
  const std::filesystem::file_status old_status = std::filesystem::status(from, ec);
  if(!ec && std::filesystem::exists(old_status))
    std::filesystem::permissions(to, old_status.permissions(), std::filesystem::perm_options::replace, ec);
}

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Makes the files that `write_file_atomically()` writes in its lifetime appear
/// together: each is written and closed in its temporary file as usual, but only
/// `commit()` renames them over their destinations, one after the other, with no
/// computation in between. A group destroyed without `commit()` (an exception,
/// say) removes the temporary files and leaves every destination as it was.
///
/// The group applies to the calls made by the thread that created it. Groups do
/// not nest. Destinations that are not regular files (devices, FIFOs) are
/// written in place at once, as without a group.
class Atomic_file_group
{
public:
  /// Starts collecting the files of this thread's `write_file_atomically()` calls.
  /// \throws std::logic_error if this thread already has a group
  Atomic_file_group()
  {
    if(current() != nullptr)
      throw std::logic_error("Atomic_file_group: a group is already active in this thread");
    current() = this;
  }
  Atomic_file_group(const Atomic_file_group&) = delete;
  Atomic_file_group& operator=(const Atomic_file_group&) = delete;
  /// Removes the temporary files not committed.
  ~Atomic_file_group()
  {
    for(const Pending& p : pending_) {
      std::error_code ec;
      std::filesystem::remove(p.temporary, ec);
      internal::unregister_unfinished_file(p.slot);
    }
    current() = nullptr;
  }

  /// Renames every file written since the group was created over its
  /// destination, in the order they were written. While it runs,
  /// `remove_unfinished_files()` removes nothing (and returns false), so that a
  /// signal cannot leave some destinations new and others old.
  /// \throws Write_error naming the destination when a rename fails (rare: the
  ///         temporary file is in the destination's directory); the files
  ///         renamed before it stay, the others are removed with the group.
  void commit()
  {
    internal::committing_group.fetch_add(1); // a count: groups of other threads may commit too
    struct Done
    {
      ~Done() { internal::committing_group.fetch_sub(1); }
    } done;
    std::size_t renamed = 0;
    for(; renamed < pending_.size(); ++renamed) {
      Pending& p = pending_[renamed];
      std::error_code ec;
      std::filesystem::rename(p.temporary, p.destination, ec);
      if(ec) {
        const std::string message = "cannot write '" + p.path + "': cannot replace the file: " + ec.message();
        forget(renamed);
        throw Write_error(message);
      }
      internal::unregister_unfinished_file(p.slot);
      p.slot = -1;
    }
    forget(renamed);
  }

  /// The number of files waiting for `commit()`.
  std::size_t size() const { return pending_.size(); }

private:
  friend class internal::Atomic_file_group_access;
  struct Pending
  {
    std::filesystem::path temporary, destination;
    std::string path; // as the caller named it
    int slot;
  };
  // Drops the first `renamed` files, already renamed and unregistered.
  void forget(std::size_t renamed)
  {
    pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(renamed));
  }
  static Atomic_file_group*& current()
  {
    static thread_local Atomic_file_group* group = nullptr;
    return group;
  }
  std::vector<Pending> pending_;
};

namespace internal {

class Atomic_file_group_access
{
public:
  static Atomic_file_group* current() { return Atomic_file_group::current(); }
  static void add(Atomic_file_group& group, Temporary_file_guard& guard, const std::filesystem::path& dest,
                  const std::string& path)
  {
    const std::filesystem::path temporary = guard.path();
    group.pending_.push_back({temporary, dest, path, -1});
    group.pending_.back().slot = guard.release_slot(); // after the push, which may throw
  }
};

} // namespace internal

/// \ingroup PkgDFL1SkeletonRef
/// Removes the temporary files of the writes in progress in this process (of
/// `write_file_atomically()`, and those an `Atomic_file_group` holds), and
/// returns true; returns false and removes nothing while a group commits.
///
/// It is async-signal-safe (it only reads fixed buffers and calls `unlink()`), for a
/// handler of SIGINT or SIGTERM that then ends the process with `_exit()`, so that
/// a stopped program leaves no temporary file behind. The handler must run on the
/// thread that writes (a handler on another thread can forward the signal to it
/// with `pthread_kill()`): a write on another thread may create its file just
/// after the removal. On false, the handler should let the commit finish and end
/// the process then: the destinations are then all new.
inline bool remove_unfinished_files() noexcept
{
  if(internal::committing_group.load() != 0)
    return false;
  for(int i = 0; i < internal::unfinished_file_slot_count; ++i)
    if(internal::unfinished_file_slots[i].state.load() == 2) {
#if !defined(_WIN32)
      ::unlink(internal::unfinished_file_slots[i].path);
#else
      std::remove(internal::unfinished_file_slots[i].path);
#endif
    }
  return true;
}

/// \ingroup PkgDFL1SkeletonRef
/// Writes a file whole or not at all.
///
/// `write_content(os)` writes the content to `os`, a stream on a temporary file
/// in the directory of `path` and imbued with the classic "C" locale (so that
/// numbers never get locale-specific separators). When it returns and every
/// write and the closing of the file succeeded, the temporary file is renamed over
/// `path` (by the `Atomic_file_group` of this thread, if there is one, at its
/// commit). On any failure the temporary file is removed and `path` is left as it
/// was. A full disk gives the system's reason: `"cannot write 'out.ply': writing
/// failed: No space left on device"`.
///
/// If `path` is a symbolic link, the file it points to is replaced. If `path`
/// exists, its permissions are carried over to the new file. If `path` exists and
/// is not a regular file (a device such as `/dev/null`, a FIFO), it cannot be
/// replaced by a rename: it is written in place, and is not atomic.
///
/// \tparam F a callable `void(std::ostream&)`
/// \param path the destination
/// \param write_content writes the content
/// \param binary open the stream in binary mode (no effect on POSIX systems)
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
  int fd = -1;
#if !defined(_WIN32)
  {
    std::error_code ec;
    const fs::file_status status = fs::status(dest, ec);
    if(!ec && fs::exists(status) && !fs::is_regular_file(status)) {
      fd = internal::open_for_writing(dest, false);
      if(fd < 0)
        throw Write_error("cannot write '" + path + "': " + internal::errno_reason(errno, "cannot open file for writing"));
      internal::write_and_close(fd, dest, path, write_content, binary);
      return;
    }
  }
#endif
  // The guard is registered before the file exists, and outlives the stream.
  std::optional<internal::Temporary_file_guard> guard;
  for(;;) {
    guard.emplace(internal::temporary_path_for(dest));
#if !defined(_WIN32)
    fd = internal::open_for_writing(guard->path(), true);
    if(fd < 0 && errno == EEXIST) { // another process took the name meanwhile
      guard->release();
      continue;
    }
    if(fd < 0) {
      const int err = errno;
      throw Write_error("cannot write '" + path + "': cannot create a file in '" +
                        guard->path().parent_path().string() + "': " +
                        internal::errno_reason(err, "cannot open file for writing"));
    }
#endif
    break;
  }
  internal::write_and_close(fd, guard->path(), path, write_content, binary);
  internal::copy_permissions(dest, guard->path());

  if(Atomic_file_group* group = internal::Atomic_file_group_access::current()) {
    internal::Atomic_file_group_access::add(*group, *guard, dest, path);
    return;
  }
  std::error_code ec;
  fs::rename(guard->path(), dest, ec);
  if(ec)
    throw Write_error("cannot write '" + path + "': cannot replace the file: " + ec.message());
  guard->release();
}

} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_WRITE_FILE_ATOMICALLY_H
