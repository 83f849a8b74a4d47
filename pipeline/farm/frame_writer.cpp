#include "farm/frame_writer.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

namespace lc::farm {

namespace fs = std::filesystem;

namespace {

void sync_file(const fs::path& p) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot open {} to sync it: {}", p.string(), std::strerror(errno)));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw std::runtime_error(fmt::format("cannot sync {}: {}", p.string(), std::strerror(err)));
}

// Reads the file back and checks its size matches; throws naming `final`.
void verify(const fs::path& temp, const fs::path& final, FrameFormat format, const FrameImage& image) {
  try {
    const FrameImage back = format == FrameFormat::exr ? read_exr(temp) : read_image_linear(temp);
    if (back.width != image.width || back.height != image.height)
      throw std::runtime_error(fmt::format("it reads back as {}x{}", back.width, back.height));
  } catch (const std::exception& e) {
    throw std::runtime_error(
        fmt::format("cannot write {}: the file written does not read back ({})", final.string(), e.what()));
  }
}

}  // namespace

void write_verified(const fs::path& final, FrameFormat format, const FrameImage& image, const ImageMetadata& metadata) {
  fs::path temp = final;
  temp += fmt::format(".tmp-{}", ::getpid());
  try {
    if (format == FrameFormat::exr)
      write_exr(temp, image, metadata);
    else
      write_png(temp, image);
    verify(temp, final, format, image);
    sync_file(temp);
    fs::rename(temp, final);
  } catch (...) {
    std::error_code ec;
    fs::remove(temp, ec);
    throw;
  }
}

}  // namespace lc::farm
