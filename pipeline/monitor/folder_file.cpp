#include "monitor/folder_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "store/durable_file.hpp"

namespace lc::monitor {

FolderFile::FolderFile(const std::filesystem::path& path) {
  // Inputs: a path inside a folder the monitor serves.  O_NONBLOCK: opening
  // a FIFO for reading would otherwise wait for a writer (for ever).
  fd_ = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    const int err = errno;
    missing_ = err == ENOENT || err == ENOTDIR;
    why_ = err == ELOOP ? "is a link: the monitor reads only regular files inside the folder, not followed through links"
                        : fmt::format("cannot be read: {}", std::strerror(err));
    return;
  }
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    why_ = "is not a regular file: the monitor reads only regular files inside the folder";
    return;
  }
  size_ = static_cast<std::uintmax_t>(st.st_size);
  device_ = static_cast<std::uint64_t>(st.st_dev);
  inode_ = static_cast<std::uint64_t>(st.st_ino);
  modified_ns_ = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
}

FolderFile::~FolderFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::filesystem::path FolderFile::open_file_path() const { return descriptor_path(fd_); }

std::string FolderFile::head(std::size_t bytes) const { return read_at(0, bytes); }

std::string FolderFile::read_at(std::uintmax_t offset, std::size_t bytes) const {
  // Input: an opened file; pread, so that the offset of the descriptor
  // stays at 0.  No more
  // than the size fstat gave is read: a file growing meanwhile is read as
  // it was then.
  if (offset >= size_) return {};
  if (bytes > size_ - offset) bytes = static_cast<std::size_t>(size_ - offset);
  std::string out(bytes, '\0');
  std::size_t got = 0;
  while (got < bytes) {
    const ssize_t n = ::pread(fd_, out.data() + got, bytes - got, static_cast<off_t>(offset + got));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(fmt::format("read error: {}", std::strerror(errno)));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  out.resize(got);
  return out;
}

std::string FolderFile::read_all(std::size_t max_bytes) const {
  // Input: an opened file; the bound keeps one request from holding a
  // huge file in memory.
  if (size_ > max_bytes) throw std::runtime_error(fmt::format("is larger than {} bytes: not served", max_bytes));
  return head(static_cast<std::size_t>(size_));
}

int FolderFile::release() {
  // Input: an opened file (or not: -1).  O_NONBLOCK was for the open alone
  // (a FIFO would have blocked it); the file is checked regular by now.
  const int fd = fd_;
  fd_ = -1;
  if (fd >= 0) {
    released_ = true;
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  }
  return fd;
}

}  // namespace lc::monitor
