#include "assets/asset_path.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <stdexcept>
#include <system_error>
#include <string>

#include <fmt/format.h>

#include "core/file_checks.hpp"

namespace lc {

namespace fs = std::filesystem;

fs::path resolve_sky_image(const fs::path& file, const std::vector<fs::path>& dirs) {
  const std::string name = file.string();
  if (file.is_absolute()) {
    throw std::invalid_argument(fmt::format(
        "sky image '{}': the field 'file' must be a path relative to the shot's folder, not an absolute one", name));
  }
  std::string tried;
  std::string folders;
  for (const auto& dir : dirs) {
    tried += "\n  " + (dir / file).string();
    folders += (folders.empty() ? "" : ", ") + dir.string();
  }
  for (const auto& dir : dirs) {
    const fs::path candidate = dir / file;
    std::error_code ec;
    if (!fs::exists(candidate, ec)) continue;
    const fs::path real = fs::canonical(candidate, ec);
    if (ec) throw std::invalid_argument(fmt::format("sky image '{}' ({}): {}", name, candidate.string(), ec.message()));
    const bool inside = std::any_of(dirs.begin(), dirs.end(), [&](const fs::path& d) {
      std::error_code dec;
      const fs::path root = fs::canonical(d, dec);
      return !dec && is_within(real, root);
    });
    if (!inside) {
      throw std::invalid_argument(fmt::format(
          "sky image '{}' ({}) leads through a link to {}, outside the folders sky images are read from ({})", name,
          candidate.string(), real.string(), folders));
    }
    struct stat st {};
    if (::stat(real.c_str(), &st) != 0) {
      throw std::invalid_argument(
          fmt::format("sky image '{}' ({}): {}", name, candidate.string(), std::generic_category().message(errno)));
    }
    if (!S_ISREG(st.st_mode)) {
      throw std::invalid_argument(fmt::format("sky image '{}' ({}) is {}, not a regular file", name,
                                              candidate.string(), file_kind(st.st_mode)));
    }
    return real;
  }
  throw std::invalid_argument(fmt::format("sky image '{}' not found; looked in:{}", name, tried));
}

}  // namespace lc
