#include "store/dir_lock.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "durable_file.hpp"

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
// and start over if not.  The file is opened as lightcone's own
// (open_own_file): a link planted under its name is refused, never
// truncated through, and a FIFO never blocks.  A lock file this call made
// and could not use (a full disk) is removed again; one that was there
// before is left.
DirLock::DirLock(const std::filesystem::path& dir, const char* flag) : file_(dir / file_name) {
  // "--out DIR: <why>", the one form of every refusal.
  auto refuse = [&](const std::string& why) {
    return std::runtime_error(fmt::format("{} {}: {}", flag, dir.string(), why));
  };
  for (int attempt = 0; attempt < 100; ++attempt) {
    OwnFile own;
    try {
      own = open_own_file(file_, O_RDWR | O_CREAT, "write to the output directory's lock");
    } catch (const std::runtime_error& e) {
      throw refuse(e.what());
    }
    const int fd = own.fd;
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string who = holder(fd);
      ::close(fd);
      // A lock file this call made and cannot use goes (NFS without lockd:
      // ENOLCK); one that is held is another render's.
      if (err != EWOULDBLOCK && own.created) ::unlink(file_.c_str());
      if (err == EWOULDBLOCK)
        throw refuse(fmt::format("another lightcone render is writing there ({}); wait for it to finish or stop it — "
                                 "a stopped render resumes where it left off",
                                 who));
      throw refuse(fmt::format("cannot lock {}: {}", file_.string(), std::strerror(err)));
    }
    struct stat held {}, named {};
    if (::fstat(fd, &held) == 0 && ::lstat(file_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      char host[256] = {};
      ::gethostname(host, sizeof host - 1);
      const std::string who = fmt::format("pid {} on {}\n", ::getpid(), host);
      // Written before the old text is cut, so a write that fails leaves
      // a file that was there as it was (less a torn tail at worst).
      if (::pwrite(fd, who.data(), who.size(), 0) != static_cast<ssize_t>(who.size()) ||
          ::ftruncate(fd, static_cast<off_t>(who.size())) != 0) {
        const int err = errno;
        if (own.created) ::unlink(file_.c_str());  // still held: nobody else has it
        ::close(fd);
        throw refuse(fmt::format("cannot write to the output directory ({}: {})", file_.string(), std::strerror(err)));
      }
      fd_ = fd;
      return;
    }
    ::close(fd);  // lost a race with a releasing holder: try again
  }
  throw refuse(fmt::format("cannot lock {} (it keeps changing)", file_.string()));
}

DirLock::~DirLock() {
  if (fd_ < 0) return;
  // Unlink while still holding the lock, so nobody locks a file about to vanish.
  std::error_code ec;
  std::filesystem::remove(file_, ec);
  ::close(fd_);
}

}  // namespace lc::farm
