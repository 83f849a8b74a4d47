#include "store/frame_files.hpp"

#include <cstdio>
#include <map>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "store/frame_list.hpp"
#include "store/journal.hpp"

namespace lc::farm {

std::filesystem::path frame_path(const std::filesystem::path& dir, const std::string& shot, int frame,
                                 const char* extension) {
  return dir / fmt::format("{}.{:04d}.{}", shot, frame, extension);
}

std::vector<int> check_frames_current(const std::filesystem::path& dir, const std::string& shot,
                                      const std::vector<int>& frames, bool allow_stale, const char* command) {
  const JournalContents journal = read_journal(dir / (shot + ".journal"));
  if (journal.last_frame < 0) return {};
  std::map<int, std::uintmax_t> sizes;
  for (int f : frames) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(frame_path(dir, shot, f, "png"), ec);
    sizes[f] = ec ? 0 : bytes;
  }
  const StaleFrames stale = stale_frames(journal, sizes);
  if (!stale.any()) return stale.absent;
  const JournalFrame& latest = journal.frames.at(journal.last_frame);
  std::vector<std::string> reasons;
  if (!stale.other_settings.empty())
    reasons.push_back(fmt::format("{} rendered with other settings than the latest render ({})",
                                  frames_were(stale.other_settings), latest.settings.describe()));
  if (!stale.earlier_script.empty())
    reasons.push_back(fmt::format("{} rendered from an earlier version of the shot (its script or modules)",
                                  frames_were(stale.earlier_script)));
  if (!stale.earlier_sky.empty())
    reasons.push_back(fmt::format("{} rendered with an earlier version of the sky's image or star catalogue", frames_were(stale.earlier_sky)));
  if (!stale.unrecorded.empty())
    reasons.push_back(fmt::format("{} not recorded in {}.journal as finished (a render stopped while writing, or the "
                                  "files were put there by hand)",
                                  frames_were(stale.unrecorded), shot));
  const std::string what = fmt::format("{}: shot {}: {}", dir.string(), shot, fmt::join(reasons, "; "));
  if (allow_stale) {
    fmt::print(stderr, "{}: warning: --allow-stale: using them as they are: {}\n", command, what);
    return stale.absent;
  }
  throw std::runtime_error(fmt::format(
      "{}. Shown together they would mix versions: finish the render (lightcone render <shot.lua> --out {} --force "
      "renders them again) or pass --allow-stale to use the frames as they are",
      what, dir.string()));
}

}  // namespace lc::farm
