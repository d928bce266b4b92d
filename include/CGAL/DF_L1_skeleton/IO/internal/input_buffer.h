// Copyright (c) 2026 DF_L1_skeleton contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
#ifndef CGAL_DF_L1_SKELETON_IO_INTERNAL_INPUT_BUFFER_H
#define CGAL_DF_L1_SKELETON_IO_INTERNAL_INPUT_BUFFER_H

/// \file input_buffer.h
/// The bytes the point cloud readers parse: a regular file mapped read-only
/// (POSIX), or a stream read into memory. Not part of the public API.
///
/// Why a mapping: copying a 600 MB file into a `std::string` costs a zeroing
/// pass, a copy and a page fault per 4 KiB, which took more time than the
/// parsing, and kept a second copy of the file resident while the points were
/// built. A mapping is filled from the page cache with no copy, and the parsers
/// drop the pages they are done with (`drop_pages_before()`), so reading holds
/// about the points plus a few MB, whatever the file size.
/// One caveat of mappings: a file truncated by another process *while* it is
/// read ends the process with SIGBUS, which a library cannot catch; a program
/// that must report it handles SIGBUS while it reads (df_l1_skeleton does). Other
/// changes are caught after the parsing: the mapping keeps its descriptor, and
/// `check_unchanged()` compares the file's size and modification time with those
/// it had when it was mapped. A file removed or replaced by a rename meanwhile is
/// no change: the mapping still reads the file that was opened.

#include <CGAL/DF_L1_skeleton/IO/internal/reader_messages.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <memory>
#include <new>
#include <string>
#include <string_view>

#if defined(__unix__) || defined(__APPLE__)
#  include <fcntl.h>
#  include <sys/mman.h>
#  include <sys/stat.h>
#  include <unistd.h>
#  define CGAL_DF_L1_HAS_MMAP 1
#endif

namespace CGAL {
namespace DF_L1 {
namespace internal {
namespace point_cloud_reader {

/// Asks Linux for transparent huge pages over `[p, p + bytes)`: filling hundreds
/// of MB of fresh memory otherwise costs a page fault per 4 KiB, which took more
/// time than the parsing on the machines measured. Only advice; harmless if refused.
inline void advise_huge_pages(const void* p, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::size_t huge = std::size_t(2) << 20;
  if(bytes < 2 * huge)
    return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (begin + huge - 1) / huge * huge;
  const std::uintptr_t last = (begin + bytes) / huge * huge;
  if(last > first)
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

/// Owns the bytes of one input; movable, not copyable.
class Input_buffer
{
public:
  Input_buffer() = default;
  Input_buffer(const Input_buffer&) = delete;
  Input_buffer& operator=(const Input_buffer&) = delete;
  Input_buffer(Input_buffer&& o) noexcept { swap(o); }
  Input_buffer& operator=(Input_buffer&& o) noexcept
  {
    Input_buffer tmp(std::move(o));
    swap(tmp);
    return *this;
  }
  ~Input_buffer() { unmap(); }

  /// Throws Read_error naming `name` if the mapped file's size or modification
  /// time differ from when it was mapped: the bytes parsed may then mix the old
  /// and the new content. A no-op for buffers that are not mappings.
  void check_unchanged(const std::string& name) const
  {
#ifdef CGAL_DF_L1_HAS_MMAP
    if(map_ == nullptr || fd_ < 0)
      return;
    struct stat now;
    if(::fstat(fd_, &now) != 0)
      return; // nothing to compare with; the parsing succeeded
    if(static_cast<std::uint64_t>(now.st_size) != static_cast<std::uint64_t>(map_size_))
      fail(name, "", "the file changed while it was being read (it had " + std::to_string(map_size_) +
                         " bytes when it was opened, " + std::to_string(static_cast<long long>(now.st_size)) +
                         " now)");
    const struct timespec modified = modification_time(now);
    if(modified.tv_sec != mtime_.tv_sec || modified.tv_nsec != mtime_.tv_nsec)
      fail(name, "", "the file changed while it was being read (it was modified after it was opened)");
#else
    (void)name;
#endif
  }

  std::string_view view() const { return std::string_view(data_, size_); }

  /// Lets the system reclaim the mapped pages before `offset`: the parsers call
  /// it as they advance. The bytes stay readable (a page comes back from the
  /// file if touched again), so views into them remain valid. A no-op for
  /// buffers that are not mappings.
  void drop_pages_before(std::size_t offset) const
  {
#ifdef CGAL_DF_L1_HAS_MMAP
    if(map_ == nullptr)
      return;
    const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const std::size_t end = std::min(offset, size_) / page * page;
    if(end > 0)
      ::madvise(map_, end, MADV_DONTNEED);
#else
    (void)offset;
#endif
  }

#ifdef CGAL_DF_L1_HAS_MMAP
  /// Maps the regular file open as `fd`, whose status is `st`, and takes the
  /// descriptor (for check_unchanged()); false, leaving `fd` to the caller, if
  /// the system refuses (the caller then reads it as a stream).
  bool map_file(int fd, const struct stat& st)
  {
    const std::size_t size = static_cast<std::size_t>(st.st_size);
    if(size == 0)
      return false; // mmap refuses empty mappings
    void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if(p == MAP_FAILED)
      return false;
    ::madvise(p, size, MADV_SEQUENTIAL); // read-ahead, and early reuse of read pages
    unmap();
    map_ = p;
    map_size_ = size;
    fd_ = fd;
    mtime_ = modification_time(st);
    data_ = static_cast<const char*>(p);
    size_ = size;
    return true;
  }
#endif

  /// Takes `n` bytes of `bytes`.
  void own(std::unique_ptr<char[]> bytes, std::size_t n)
  {
    unmap();
    owned_ = std::move(bytes);
    data_ = owned_ ? owned_.get() : "";
    size_ = n;
  }

private:
#ifdef CGAL_DF_L1_HAS_MMAP
  static struct timespec modification_time(const struct stat& st)
  {
#  if defined(__APPLE__)
    return st.st_mtimespec;
#  else
    return st.st_mtim;
#  endif
  }
#endif
  void swap(Input_buffer& o) noexcept
  {
    std::swap(owned_, o.owned_);
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    std::swap(map_, o.map_);
    std::swap(map_size_, o.map_size_);
#ifdef CGAL_DF_L1_HAS_MMAP
    std::swap(fd_, o.fd_);
    std::swap(mtime_, o.mtime_);
#endif
  }
  void unmap()
  {
#ifdef CGAL_DF_L1_HAS_MMAP
    if(map_ != nullptr)
      ::munmap(map_, map_size_);
    if(fd_ >= 0)
      ::close(fd_);
    fd_ = -1;
#endif
    map_ = nullptr;
  }

  std::unique_ptr<char[]> owned_;
  const char* data_ = "";
  std::size_t size_ = 0;
  void* map_ = nullptr;
  std::size_t map_size_ = 0;
#ifdef CGAL_DF_L1_HAS_MMAP
  int fd_ = -1;         // of the mapped file, for check_unchanged()
  struct timespec mtime_ = {}; // its modification time when mapped
#endif
};

/// Reads until `read_some(buffer, n)` returns 0 (it returns how many bytes it
/// put in `buffer`, at most `n`) into a buffer of `capacity` bytes, left
/// uninitialised, that grows geometrically when full.
template <class ReadSome>
Input_buffer read_to_end(std::size_t capacity, const std::string& name, ReadSome read_some)
{
  auto allocate = [&name](std::size_t n) {
    try {
      std::unique_ptr<char[]> bytes(new char[n]);
      advise_huge_pages(bytes.get(), n);
      return bytes;
    } catch(const std::bad_alloc&) {
      fail(name, "", "not enough memory to hold the input (" + std::to_string(n) + " bytes)");
    }
  };
  std::unique_ptr<char[]> bytes = allocate(capacity);
  std::size_t size = 0;
  for(;;) {
    if(size == capacity) {
      const std::size_t grown = capacity + capacity / 2;
      std::unique_ptr<char[]> bigger = allocate(grown);
      std::memcpy(bigger.get(), bytes.get(), size);
      bytes = std::move(bigger);
      capacity = grown;
    }
    const std::size_t got = read_some(bytes.get() + size, capacity - size);
    if(got == 0)
      break;
    size += got;
  }
  Input_buffer result;
  result.own(std::move(bytes), size);
  return result;
}

/// Reads everything left in `in`. A seekable stream (a file) is read in one
/// allocation of its remaining size, left uninitialised: no zeroing pass and no
/// reallocation copies. Other streams grow the buffer geometrically.
inline Input_buffer read_stream(std::istream& in, const std::string& name)
{
  if(!in)
    fail(name, "", "cannot read (the stream is not in a good state)");
  std::streamoff remaining = -1;
  {
    const std::istream::pos_type here = in.tellg();
    if(here != std::istream::pos_type(-1) && in.seekg(0, std::ios::end)) {
      const std::istream::pos_type end = in.tellg();
      if(end != std::istream::pos_type(-1) && end >= here)
        remaining = static_cast<std::streamoff>(end - here);
      in.seekg(here);
    }
    in.clear(in.rdstate() & ~std::ios::failbit); // a refused seek is no error
  }
  if(!in)
    fail(name, "", "read error");

  // The size is a hint only (a text-mode stream may deliver fewer bytes): the
  // loop reads to the end whatever it says.
  const std::size_t capacity =
      remaining > 0 ? static_cast<std::size_t>(remaining) + 1 : (std::size_t(1) << 16);
  Input_buffer result = read_to_end(capacity, name, [&in](char* to, std::size_t n) -> std::size_t {
    if(!in)
      return 0;
    in.read(to, static_cast<std::streamsize>(n));
    return static_cast<std::size_t>(in.gcount());
  });
  if(in.bad())
    fail(name, "", "read error");
  return result;
}

#ifdef CGAL_DF_L1_HAS_MMAP
/// Reads the open descriptor `fd` (a FIFO, a device, a file of /proc) to its
/// end, starting with a buffer of `capacity` bytes.
inline Input_buffer read_descriptor(int fd, std::size_t capacity, const std::string& name)
{
  return read_to_end(std::max<std::size_t>(capacity, 1), name, [fd, &name](char* to, std::size_t n) -> std::size_t {
    for(;;) {
      const ::ssize_t got = ::read(fd, to, n);
      if(got >= 0)
        return static_cast<std::size_t>(got);
      if(errno != EINTR)
        fail(name, "", std::string("read error: ") + std::strerror(errno));
    }
  });
}
#endif

/// Opens `filename` read-only and stores its content in `out`: mapped when it is
/// a regular file, else read from the same descriptor (a FIFO must be opened
/// once: closing it and opening it again would lose what its writer had sent
/// and could kill the writer with SIGPIPE). Returns false (and leaves `out`
/// alone) when there is no POSIX `open` or it fails; `open_errno` is then the
/// error of `open`, or 0.
inline bool read_with_descriptor(const std::string& filename, Input_buffer& out, int& open_errno)
{
  open_errno = 0;
#ifdef CGAL_DF_L1_HAS_MMAP
  int flags = O_RDONLY;
#  ifdef O_CLOEXEC
  flags |= O_CLOEXEC;
#  endif
  const int fd = ::open(filename.c_str(), flags);
  if(fd < 0) {
    open_errno = errno;
    return false;
  }
  struct stat st;
  // Size 0 is read, not mapped: files of /proc say 0 yet have content.
  const bool sized = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 &&
                     static_cast<std::uint64_t>(st.st_size) < static_cast<std::uint64_t>(SIZE_MAX);
  if(sized && out.map_file(fd, st)) // which then owns the descriptor
    return true;
  try {
    out = read_descriptor(fd, sized ? static_cast<std::size_t>(st.st_size) + 1 : std::size_t(1) << 16,
                          filename);
  } catch(...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return true;
#else
  (void)filename;
  (void)out;
  return false;
#endif
}

} // namespace point_cloud_reader
} // namespace internal
} // namespace DF_L1
} // namespace CGAL

#endif // CGAL_DF_L1_SKELETON_IO_INTERNAL_INPUT_BUFFER_H
