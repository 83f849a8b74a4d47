#include "atomic_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>
#include <unistd.h>

namespace lc {

namespace {
[[noreturn]] void fail(const std::filesystem::path& p, const char* what, int err) {
  throw std::runtime_error(fmt::format("cannot {} {}: {}", what, p.string(), std::strerror(err)));
}
}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  temp_ = path_;
  temp_ += fmt::format(".tmp-{}", ::getpid());
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_) fail(path_, "write", errno);
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  std::error_code ec;  // a destructor must not throw
  if (!committed_) std::filesystem::remove(temp_, ec);
}

void AtomicFile::write(std::string_view data) {
  if (std::fwrite(data.data(), 1, data.size(), file_) != data.size()) fail(path_, "write", errno);
}

void AtomicFile::commit() {
  if (std::fflush(file_) != 0) fail(path_, "write", errno);
  if (::fsync(::fileno(file_)) != 0) fail(path_, "sync", errno);
  const int rc = std::fclose(file_);
  file_ = nullptr;
  if (rc != 0) fail(path_, "write", errno);
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) fail(path_, "rename onto", errno);
  committed_ = true;
}

void write_output(const std::optional<std::filesystem::path>& path, std::string_view data) {
  if (path) {
    AtomicFile out(*path);
    out.write(data);
    out.commit();
    return;
  }
  if (std::fwrite(data.data(), 1, data.size(), stdout) != data.size() || std::fflush(stdout) != 0)
    throw std::runtime_error(fmt::format("cannot write to standard output: {}", std::strerror(errno)));
}

void require_extension(const std::filesystem::path& path, std::string_view extension, std::string_view what) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != extension)
    throw std::invalid_argument(fmt::format("-o {}: {} (name it {})", path.string(), what, extension));
}

}  // namespace lc
