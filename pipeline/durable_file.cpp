#include "durable_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

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

}  // namespace

DurableFile::DurableFile(fs::path final_path) : final_(std::move(final_path)) {
  std::error_code ec;
  if (fs::is_directory(final_, ec))
    throw std::runtime_error(fmt::format("cannot write {}: it is a directory", final_.string()));
  temp_ = final_;
  temp_ += fmt::format("{}{}", kTempMark, ::getpid());
}

DurableFile::~DurableFile() {
  // A destructor must not throw: clean-up is best effort.
  if (fd_ >= 0) ::close(fd_);
  std::error_code ec;
  if (!committed_) fs::remove(temp_, ec);
}

void DurableFile::write(std::string_view bytes) {
  // Input: the next bytes of the file.  Loops because write() may take
  // fewer bytes than asked, and a signal may interrupt it.
  if (committed_) throw std::logic_error("DurableFile::write after commit");
  if (fd_ < 0) {
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) fail("write", final_, errno);
  }
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write", final_, errno);
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void DurableFile::sync_temp() const {
  // The data must be on disk before the name points at it, or a crash could
  // leave a complete-looking name over an empty file.  A library that wrote
  // by path has closed its file: reopen it to sync.
  if (fd_ >= 0) {
    if (::fsync(fd_) != 0) fail("sync", final_, errno);
    return;
  }
  const int fd = ::open(temp_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail("sync", final_, errno);
  sync_and_close(fd, final_);
}

void DurableFile::rename_into_place() {
  // Assumes sync_temp() succeeded.  Closes the write descriptor first so
  // that a late write error (reported by close) stops the rename.
  if (fd_ >= 0) {
    const int rc = ::close(fd_);
    fd_ = -1;
    if (rc != 0) fail("write", final_, errno);
  }
  if (std::rename(temp_.c_str(), final_.c_str()) != 0) fail("rename onto", final_, errno);
  committed_ = true;
}

void DurableFile::commit() { commit_together({this}); }

void commit_together(std::initializer_list<DurableFile*> files) {
  // Input: uncommitted files, each written.  Syncs every file before the
  // first rename, so a failed sync leaves every final name as it was.
  for (DurableFile* f : files) {
    if (f->committed_) throw std::logic_error("DurableFile committed twice: " + f->final_.string());
    f->sync_temp();
  }
  std::vector<fs::path> dirs;
  for (DurableFile* f : files) {
    f->rename_into_place();
    const fs::path dir = f->final_.parent_path();
    if (std::find(dirs.begin(), dirs.end(), dir) == dirs.end()) dirs.push_back(dir);
  }
  for (const fs::path& dir : dirs) sync_directory(dir);
}

void sync_directory(const fs::path& dir) {
  const fs::path d = dir.empty() ? fs::path(".") : dir;
  const int fd = ::open(d.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot open {} to sync it: {}", d.string(), std::strerror(errno)));
  sync_and_close(fd, d);
}

bool is_temporary_name(std::string_view file_name) {
  const auto at = file_name.rfind(kTempMark);
  if (at == std::string_view::npos || at == 0) return false;
  const std::string_view pid = file_name.substr(at + kTempMark.size());
  return !pid.empty() && std::all_of(pid.begin(), pid.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace lc
