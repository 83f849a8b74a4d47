#pragma once
// A file of a render folder, opened for the monitor to read (docs/monitor.md,
// "Safe by default").  The monitor reads a folder it does not own: a name in
// it may be a link to a file outside (/etc/passwd), to a device that never
// ends (/dev/zero) or a FIFO that blocks its reader until a writer comes.
// So a file is opened without following a link in its last component and
// without blocking (O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC), and kept only if
// the open file is a regular one; it is read by what was opened, never by
// its name again, and never more than a bound.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace lc::monitor {

class FolderFile {
 public:
  // Opens `path`; never throws.  `missing()`: there is no such file;
  // `refused()`: there is one but it is not read, `why()` says so (a link,
  // not a regular file, or not readable).
  explicit FolderFile(const std::filesystem::path& path);
  ~FolderFile();
  FolderFile(const FolderFile&) = delete;
  FolderFile& operator=(const FolderFile&) = delete;

  bool missing() const { return missing_; }
  bool refused() const { return fd_ < 0 && !missing_ && !released_; }
  const std::string& why() const { return why_; }
  std::uintmax_t size() const { return size_; }
  // What the open file is, and when it last changed (as fstat said when it
  // was opened): the journal cache's key (JournalCache, monitor/parsed_cache.hpp).
  std::uint64_t device() const { return device_; }
  std::uint64_t inode() const { return inode_; }
  std::int64_t modified_ns() const { return modified_ns_; }

  // The file's first `bytes` bytes (fewer if it is shorter; a file growing
  // meanwhile is read up to the size it had when opened).  Throws
  // std::runtime_error on a read error.
  std::string head(std::size_t bytes) const;

  // Up to `bytes` bytes from `offset` (fewer past the size it had when
  // opened).  Throws std::runtime_error on a read error.
  std::string read_at(std::uintmax_t offset, std::size_t bytes) const;

  // A path to the open file itself (/proc/self/fd/N), for a reader that
  // takes a path and opens it as it is (the EXR reader): it opens this very
  // file, checked regular, whatever is at its name by then.  Not for the
  // farm's readers, which refuse links (this path is one).  Only while this
  // object lives, and only if opened.
  std::filesystem::path open_file_path() const;

  // The whole file.  Throws std::runtime_error if it is longer than
  // `max_bytes` or on a read error.
  std::string read_all(std::size_t max_bytes) const;

  // Hands the open descriptor over to a caller that closes it (libmicrohttpd,
  // which sends a file from it as the client reads and closes it with its
  // response): returned in blocking mode, as libmicrohttpd wants it (a
  // regular file: a read never waits for a writer).  -1 when not opened or
  // already handed over; this object reads nothing after.
  int release();

 private:
  int fd_ = -1;
  bool missing_ = false;
  bool released_ = false;  // its descriptor handed over (release)
  std::string why_;
  std::uintmax_t size_ = 0;
  std::uint64_t device_ = 0, inode_ = 0;
  std::int64_t modified_ns_ = 0;
};

}  // namespace lc::monitor
