#include "durable_file.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/file_checks.hpp"

namespace lc {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kTempMark = ".tmp-";

// "cannot <what> <path>: <OS reason for err>".
[[noreturn]] void fail(std::string_view what, const fs::path& p, int err) {
  throw std::runtime_error(fmt::format("cannot {} {}: {}", what, p.string(), std::strerror(err)));
}

// Inputs: an open descriptor and the name to blame.  fsyncs and closes it;
// the descriptor is closed even when the sync fails.
void sync_and_close(int fd, const fs::path& blame) {
  const int rc = ::fsync(fd);
  const int err = errno;
  if (::close(fd) != 0 && rc == 0) fail("write", blame, errno);  // NFS reports write errors on close
  if (rc != 0) fail("sync", blame, err);
}

// Where a path names an open descriptor of this process ("/dev/fd/3",
// "/proc/self/fd/1"): its number, else -1.  (/dev/stdout and /dev/stderr
// are links to these, followed before this is asked.)
int descriptor_named(const fs::path& p) {
  for (std::string_view dir : {"/dev/fd/", "/proc/self/fd/"}) {
    const std::string s = p.string();
    if (s.rfind(dir, 0) != 0) continue;
    const std::string_view n = std::string_view(s).substr(dir.size());
    int v = 0;
    const auto [end, ec] = std::from_chars(n.data(), n.data() + n.size(), v);
    if (ec == std::errc() && end == n.data() + n.size() && !n.empty()) return v;
  }
  return -1;
}

// Input: the path a user named.  Output: the path its links end at (each
// link read relative to its own directory), and, if the way there names an
// open descriptor, that descriptor.  Throws on a loop of links.
std::pair<fs::path, int> follow_links(const fs::path& named) {
  fs::path p = named;
  for (int hop = 0; hop < 40; ++hop) {
    if (const int fd = descriptor_named(p); fd >= 0) return {p, fd};
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return {p, -1};
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) fail("follow the link", named, ec.value());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  fail("follow the links of", named, ELOOP);
}

// "<dir>/<name>.tmp-<pid>" for every pid.  Input: a temporary's directory and
// the name before ".tmp-".  Removes those whose process is gone (a live one
// removes its own; one on another machine sharing the disk is alive there,
// so only names of this machine's dead pids are removed).
void remove_stale_temporaries(const fs::path& dir, const std::string& name) {
  std::error_code ec;
  const std::string prefix = name + std::string(kTempMark);
  for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    if (file.rfind(prefix, 0) != 0 || !is_temporary_name(file)) continue;
    const long pid = std::strtol(file.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && pid <= std::numeric_limits<pid_t>::max() && ::kill(static_cast<pid_t>(pid), 0) != 0 &&
        errno == ESRCH) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

}  // namespace

DurableFile::DurableFile(fs::path final_path, StaleTemporaries stale, FinalName name) : final_(std::move(final_path)) {
  std::error_code ec;
  if (name == FinalName::own) {
    // The name itself, never what it leads to (a rename replaces a link).
    target_ = final_;
    if (fs::is_directory(fs::symlink_status(final_, ec)))
      throw std::runtime_error(fmt::format("cannot write {}: it is a directory", final_.string()));
    if (stale == StaleTemporaries::remove) remove_stale_temporaries(target_.parent_path(), target_.filename().string());
    temp_ = target_;
    temp_ += fmt::format("{}{}", kTempMark, ::getpid());
    clear_temporary_name();
    return;
  }
  std::tie(target_, descriptor_) = follow_links(final_);
  const fs::file_status st = descriptor_ >= 0 ? fs::file_status(fs::file_type::character) : fs::status(target_, ec);
  const fs::file_type type = st.type();
  if (type == fs::file_type::directory || type == fs::file_type::block || type == fs::file_type::socket) {
    const char* what = type == fs::file_type::directory ? "a directory"
                       : type == fs::file_type::block   ? "a block device, which lightcone does not write to"
                                                        : "a socket, which lightcone does not write to";
    throw std::runtime_error(fmt::format("cannot write {}: it is {}{}", final_.string(), what,
                                         target_ == final_ ? "" : fmt::format(" ({})", target_.string())));
  }
  stream_ = type == fs::file_type::character || type == fs::file_type::fifo;
  if (stream_) {
    // Not beside a device: /dev is no place for temporaries, and a FIFO's
    // directory may not be writable.
    const fs::path dir = fs::temp_directory_path(ec);
    const std::string name = "lightcone-" + final_.filename().string();
    if (stale == StaleTemporaries::remove) remove_stale_temporaries(dir, name);
    temp_ = dir / fmt::format("{}{}{}", name, kTempMark, ::getpid());
  } else {
    if (stale == StaleTemporaries::remove) remove_stale_temporaries(target_.parent_path(), target_.filename().string());
    temp_ = target_;
    temp_ += fmt::format("{}{}", kTempMark, ::getpid());
  }
  clear_temporary_name();
}

void DurableFile::clear_temporary_name() const {
  // The temporary's name carries this process's pid, so whatever is there
  // is not a live writer's: a killed process of the same pid left it, or it
  // was planted (a link in a shared folder or in /tmp, which a library
  // writing by path would follow).  Unlinking removes a link, not what it
  // leads to; a name that cannot be removed (another user's in /tmp, a
  // directory) stops the write before anything is written through it.
  if (::unlink(temp_.c_str()) == 0 || errno == ENOENT || errno == ENOTDIR) return;
  const int err = errno;
  struct stat st {};
  if (::lstat(temp_.c_str(), &st) != 0) return;
  throw std::runtime_error(fmt::format("cannot write {}: its temporary {} is already there and cannot be removed ({})",
                                       final_.string(), temp_.string(), std::strerror(err)));
}

DurableFile::~DurableFile() {
  // A destructor must not throw: clean-up is best effort.  Only a temporary
  // this object made is removed: whatever else is under its name was put
  // there by someone else, and is left for them.
  if (fd_ >= 0) ::close(fd_);
  std::error_code ec;
  if (created_ && (!committed_ || stream_)) fs::remove(temp_, ec);
}

void DurableFile::create_temp() {
  // O_EXCL (which never follows a link): the constructor cleared the name,
  // so anything there now was put there since, and is neither written
  // through nor taken as the temporary.
  fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ >= 0) {
    created_ = true;
    return;
  }
  if (errno != EEXIST) fail("write", final_, errno);
  throw std::runtime_error(
      fmt::format("cannot write {}: something appeared under its temporary's name {} after lightcone had cleared "
                  "it (a planted link?), and lightcone writes only into a temporary it created itself: nothing was "
                  "written, and what is there was left as it is (move it away)",
                  final_.string(), temp_.string()));
}

fs::path DurableFile::library_path() {
  if (committed_) throw std::logic_error("DurableFile::library_path after commit");
  if (fd_ < 0) create_temp();
  // Without /proc (a chroot, a container without it) the path would lead
  // nowhere, or elsewhere: say so rather than let the library fail vaguely.
  const fs::path path = descriptor_path(fd_);
  struct stat via {}, own {};
  if (::stat(path.c_str(), &via) != 0 || ::fstat(fd_, &own) != 0 || via.st_dev != own.st_dev ||
      via.st_ino != own.st_ino)
    throw std::runtime_error(fmt::format(
        "cannot write {}: {} does not lead to its temporary (is /proc mounted?); lightcone hands the image and video "
        "libraries that path, never the temporary's name, which a link planted there could lead elsewhere",
        final_.string(), path.string()));
  return path;
}

void DurableFile::write(std::string_view bytes) {
  // Input: the next bytes of the file.  Loops because write() may take
  // fewer bytes than asked, and a signal may interrupt it.
  if (committed_) throw std::logic_error("DurableFile::write after commit");
  if (fd_ < 0) create_temp();
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write", final_, errno);
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void DurableFile::check_temp_is_ours() const {
  // A library wrote through the descriptor, so the file is right whatever
  // is under its name by now; but the rename takes the name, which must
  // still hold that file, or a file or link put there meanwhile would
  // become the output.  Assumes sync_temp() found the temporary created.
  struct stat own {}, named {};
  if (::fstat(fd_, &own) != 0) fail("write", final_, errno);
  if (::lstat(temp_.c_str(), &named) == 0 && named.st_dev == own.st_dev && named.st_ino == own.st_ino) return;
  throw std::runtime_error(fmt::format(
      "cannot write {}: its temporary {} was removed or replaced while it was being written, and lightcone puts in "
      "place only the file it wrote (nothing was put in place)",
      final_.string(), temp_.string()));
}

void DurableFile::sync_temp() const {
  // The data must be on disk before the name points at it, or a crash could
  // leave a complete-looking name over an empty file.  A temporary never
  // created (a library that failed before writing anything) is not looked
  // for by name: a file there is not this one's.
  if (fd_ < 0) fail("sync", final_, ENOENT);
  if (::fsync(fd_) != 0) fail("sync", final_, errno);
}

void DurableFile::rename_into_place() {
  // Assumes sync_temp() succeeded.  Closes the write descriptor first so
  // that a late write error (reported by close) stops the rename.
  if (fd_ >= 0) {
    const int rc = ::close(fd_);
    fd_ = -1;
    if (rc != 0) fail("write", final_, errno);
  }
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) fail("rename onto", final_, errno);
  committed_ = true;
}

void DurableFile::copy_into_stream() {
  // Assumes the temporary is written.  Opens the target without truncating
  // or creating (a device or FIFO exists; truncating a descriptor a shell
  // opened for `>>` would lose what it holds) and copies the bytes in.  The
  // temporary is read through its descriptor, never its name: its name in
  // the system's temporary directory is anyone's to plant a file at.
  if (fd_ < 0) fail("read back the temporary of", final_, ENOENT);  // never created
  const int in = ::open(descriptor_path(fd_).c_str(), O_RDONLY | O_CLOEXEC);
  const int open_err = errno;
  const int rc = ::close(fd_);
  const int close_err = errno;
  fd_ = -1;
  if (in < 0) fail("read back the temporary of", final_, open_err);
  if (rc != 0) {
    ::close(in);
    fail("write", final_, close_err);
  }
  const int out = descriptor_ >= 0 ? ::fcntl(descriptor_, F_DUPFD_CLOEXEC, 0)
                                   : ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (out < 0) {
    const int err = errno;
    ::close(in);
    fail("write", final_, err);
  }
  std::vector<char> buffer(1 << 20);
  int err = 0;
  for (;;) {
    const ssize_t n = ::read(in, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n < 0) err = errno;
      break;
    }
    for (ssize_t done = 0; done < n && err == 0;) {
      const ssize_t w = ::write(out, buffer.data() + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) err = w < 0 ? errno : EIO;
      else done += w;
    }
    if (err != 0) break;
  }
  ::close(in);
  if (::close(out) != 0 && err == 0) err = errno;
  if (err != 0) fail("write", final_, err);
  committed_ = true;
  std::error_code ignored;
  fs::remove(temp_, ignored);
}

void DurableFile::put_in_place() {
  if (stream_) copy_into_stream();
  else rename_into_place();
}

void DurableFile::commit() { commit_together({this}); }

void commit_together(std::initializer_list<DurableFile*> files) {
  // Input: uncommitted files, each written.  Syncs every file before the
  // first rename, so a failed sync leaves every final name as it was.
  for (DurableFile* f : files) {
    if (f->committed_) throw std::logic_error("DurableFile committed twice: " + f->final_.string());
    if (f->stream_) continue;  // not synced (a device or FIFO keeps nothing), nor renamed: read by its descriptor
    f->sync_temp();
    f->check_temp_is_ours();
  }
  std::vector<fs::path> dirs;
  for (DurableFile* f : files) {
    f->put_in_place();
    if (f->stream_) continue;
    const fs::path dir = f->target_.parent_path();
    if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
  }
  for (const fs::path& dir : dirs) sync_directory(dir);
}

fs::path descriptor_path(int fd) { return fmt::format("/proc/self/fd/{}", fd); }

void sync_directory(const fs::path& dir) {
  const fs::path d = dir.empty() ? fs::path(".") : dir;
  const int fd = ::open(d.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot open {} to sync it: {}", d.string(), std::strerror(errno)));
  sync_and_close(fd, d);
}

namespace {

// Throws why `path` could not be opened as a regular file of lightcone's
// own: what it is, when it is no regular file (open says only ELOOP for a
// link, ENXIO for a FIFO without a reader), else the OS's reason `err`.
[[noreturn]] void refuse_own_file(std::string_view what, const fs::path& path, int err, const struct stat* opened) {
  struct stat st {};
  const bool known = opened ? (st = *opened, true) : ::lstat(path.c_str(), &st) == 0;
  if (!known || S_ISREG(st.st_mode)) fail(what, path, err);
  if (S_ISLNK(st.st_mode))
    throw std::runtime_error(fmt::format(
        "cannot {} {}: it is a symbolic link, and lightcone never follows a link among its own files in a folder "
        "(move it away)",
        what, path.string()));
  throw std::runtime_error(fmt::format(
      "cannot {} {}: it is {}, not a regular file, and lightcone keeps its own files in a folder as regular files "
      "only (move it away)",
      what, path.string(), file_kind(st.st_mode)));
}

}  // namespace

OwnFile open_own_file(const fs::path& path, int flags, std::string_view what) {
  constexpr int guard = O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY;
  const bool create = (flags & O_CREAT) != 0;
  const int access = flags & ~(O_CREAT | O_EXCL);
  OwnFile out;
  // Created only when absent (O_EXCL), so `created` is exact; an existing
  // one is opened as it is.  A file removed between the two opens (a
  // releasing lock holder) is looked for again.
  for (int attempt = 0; attempt < 100 && out.fd < 0; ++attempt) {
    if (create) {
      out.fd = ::open(path.c_str(), access | O_CREAT | O_EXCL | guard, 0644);
      if (out.fd >= 0) {
        out.created = true;
        break;
      }
      if (errno != EEXIST) fail(what, path, errno);
    }
    out.fd = ::open(path.c_str(), access | guard);
    if (out.fd >= 0) break;
    if (errno != ENOENT) refuse_own_file(what, path, errno, nullptr);
    if (!create) return out;
  }
  if (out.fd < 0) fail(what, path, EAGAIN);
  struct stat st {};
  if (::fstat(out.fd, &st) != 0) {
    const int err = errno;
    ::close(out.fd);
    fail(what, path, err);
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(out.fd);
    refuse_own_file(what, path, 0, &st);
  }
  const int status = ::fcntl(out.fd, F_GETFL);
  if (status < 0 || ::fcntl(out.fd, F_SETFL, status & ~O_NONBLOCK) != 0) {
    const int err = errno;
    ::close(out.fd);
    fail(what, path, err);
  }
  return out;
}

bool is_temporary_name(std::string_view file_name) {
  const auto at = file_name.rfind(kTempMark);
  if (at == std::string_view::npos || at == 0) return false;
  const std::string_view pid = file_name.substr(at + kTempMark.size());
  return !pid.empty() && std::all_of(pid.begin(), pid.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace lc
