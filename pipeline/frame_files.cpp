#include "frame_files.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

namespace lc {

namespace fs = std::filesystem;

fs::path frame_path(const fs::path& dir, const std::string& shot, int frame, const char* extension) {
  return dir / fmt::format("{}.{:04d}.{}", shot, frame, extension);
}

namespace {

// fsync a file by name (the image writers close their files themselves).
void sync_file(const fs::path& p) {
  const int fd = ::open(p.c_str(), O_RDONLY);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot open {} to sync it: {}", p.string(), std::strerror(errno)));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw std::runtime_error(fmt::format("cannot sync {}: {}", p.string(), std::strerror(err)));
}

// Writes with `write` to a temporary beside `final`, syncs, renames.
template <class Write>
void write_atomically(const fs::path& final, Write&& write) {
  fs::path temp = final;
  temp += fmt::format(".tmp-{}", ::getpid());
  try {
    write(temp);
    sync_file(temp);
    fs::rename(temp, final);
  } catch (...) {
    std::error_code ec;
    fs::remove(temp, ec);
    throw;
  }
}

}  // namespace

void write_frame_files(const fs::path& dir, const std::string& shot, int frame, const FrameImage& image,
                       const std::vector<std::pair<std::string, std::string>>& metadata) {
  write_atomically(frame_path(dir, shot, frame, "exr"), [&](const fs::path& p) { write_exr(p, image, metadata); });
  write_atomically(frame_path(dir, shot, frame, "png"), [&](const fs::path& p) { write_png(p, image); });
}

}  // namespace lc
