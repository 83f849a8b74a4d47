#include "core/file_checks.hpp"

#include <sys/stat.h>

#include <algorithm>

namespace lc {

bool is_within(const std::filesystem::path& path, const std::filesystem::path& dir) {
  const auto [d, p] = std::mismatch(dir.begin(), dir.end(), path.begin(), path.end());
  // A trailing '/' of dir is an empty last element.
  return d == dir.end() || (d->empty() && std::next(d) == dir.end());
}

const char* file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace lc
