#include "video/temp_output.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

namespace lc {

namespace fs = std::filesystem;

TempOutput::TempOutput(fs::path final_path) : final_(std::move(final_path)) {
  std::error_code ec;
  if (fs::is_directory(final_, ec))
    throw std::runtime_error(fmt::format("cannot write {}: it is a directory", final_.string()));
  temp_ = final_;
  temp_ += fmt::format(".tmp-{}", ::getpid());
}

TempOutput::~TempOutput() {
  std::error_code ec;  // a destructor must not throw
  if (!committed_) fs::remove(temp_, ec);
}

void TempOutput::commit() {
  // The data must be on disk before the name points at it, or a crash
  // could leave a complete-looking name over an empty file.
  const int fd = ::open(temp_.c_str(), O_RDONLY);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot sync {}: {}", final_.string(), std::strerror(errno)));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw std::runtime_error(fmt::format("cannot sync {}: {}", final_.string(), std::strerror(err)));
  std::error_code ec;
  fs::rename(temp_, final_, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot rename onto {}: {}", final_.string(), ec.message()));
  committed_ = true;
}

}  // namespace lc
