#include "farm/dir_lock.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lc::farm {

namespace {

// What the holder wrote into the lock file ("pid 123 on host"), or a
// placeholder if it had not written it yet.
std::string holder(int fd) {
  char buf[256] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string s = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s.empty() ? "a process that has not written its pid yet" : s;
}

}  // namespace

// Opens (creating) the lock file and locks it without waiting.  Because the
// file is removed on release, a racer may lock a file that was just
// unlinked: after locking, check that the path still names the locked file,
// and start over if not.
DirLock::DirLock(const std::filesystem::path& dir, const char* flag) : file_(dir / file_name) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw std::runtime_error(fmt::format("{} {}: cannot write to the output directory ({}: {})", flag,
                                           dir.string(), file_.string(), std::strerror(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string who = holder(fd);
      ::close(fd);
      if (err == EWOULDBLOCK)
        throw std::runtime_error(fmt::format(
            "{} {}: another lightcone render is writing there ({}); wait for it to finish or stop it — a stopped "
            "render resumes where it left off",
            flag, dir.string(), who));
      throw std::runtime_error(fmt::format("{} {}: cannot lock {}: {}", flag, dir.string(), file_.string(),
                                           std::strerror(err)));
    }
    struct stat held {}, named {};
    if (::fstat(fd, &held) == 0 && ::stat(file_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      char host[256] = {};
      ::gethostname(host, sizeof host - 1);
      const std::string who = fmt::format("pid {} on {}\n", ::getpid(), host);
      if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, who.data(), who.size(), 0) != static_cast<ssize_t>(who.size())) {
        const int err = errno;
        ::close(fd);
        throw std::runtime_error(fmt::format("{} {}: cannot write to the output directory ({}: {})", flag,
                                             dir.string(), file_.string(), std::strerror(err)));
      }
      fd_ = fd;
      return;
    }
    ::close(fd);  // lost a race with a releasing holder: try again
  }
  throw std::runtime_error(fmt::format("{} {}: cannot lock {} (it keeps changing)", flag, dir.string(), file_.string()));
}

DirLock::~DirLock() {
  if (fd_ < 0) return;
  // Unlink while still holding the lock, so nobody locks a file about to vanish.
  std::error_code ec;
  std::filesystem::remove(file_, ec);
  ::close(fd_);
}

}  // namespace lc::farm
