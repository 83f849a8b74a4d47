#include "script/script_paths.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace lc {

namespace fs = std::filesystem;

fs::path library_dir() {
  std::vector<fs::path> tried;
  if (const char* env = std::getenv("LIGHTCONE_SCRIPTS"); env && *env) {
    tried.emplace_back(env);
  } else {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) tried.push_back(exe.parent_path().parent_path() / "share" / "lightcone" / "scripts");
    tried.push_back(fs::path(LIGHTCONE_SOURCE_DIR) / "scripts");
  }
  for (const auto& dir : tried)
    if (fs::exists(dir / "lightcone.lua")) return dir;
  std::string list;
  for (const auto& dir : tried) list += "\n  " + (dir / "lightcone.lua").string();
  throw std::runtime_error(fmt::format(
      "cannot find the lightcone Lua library; looked for:{}\nset LIGHTCONE_SCRIPTS to the scripts/ folder", list));
}

fs::path shots_dir() { return library_dir().parent_path() / "shots"; }

std::vector<fs::path> require_dirs_for(const fs::path& script) {
  fs::path own = script.parent_path();
  if (own.empty()) own = ".";
  return {library_dir(), own};
}

}  // namespace lc
