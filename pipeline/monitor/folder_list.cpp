#include "monitor/folder_list.hpp"

#include <deque>
#include <string>
#include <utility>

namespace lc::monitor {

namespace fs = std::filesystem;

FolderList::FolderList(std::vector<fs::path> roots) : roots_(std::move(roots)), listed_(roots_) {
  known_.insert(roots_.begin(), roots_.end());
}

std::vector<fs::path> FolderList::current() const {
  const std::lock_guard lock(mutex_);
  return listed_;
}

std::vector<fs::path> FolderList::search() const {
  // Breadth first, so that a bound cut short leaves the deepest folders
  // for a later search; entries are read without following links
  // (symlink_status), so a link to / is neither searched nor listed.
  const std::lock_guard lock(mutex_);
  std::size_t budget = max_entries_per_search;
  std::deque<std::pair<fs::path, int>> queue;
  for (const fs::path& r : roots_)
    if (!render_roots_.count(r)) queue.emplace_back(r, 0);
  while (!queue.empty() && budget > 0 && listed_.size() < max_listed_folders) {
    const auto [dir, depth] = queue.front();
    queue.pop_front();
    bool renders = false;
    std::vector<fs::path> below;
    std::error_code ec;
    for (fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
         it.increment(ec)) {
      if (budget == 0) break;
      --budget;
      const fs::path& p = it->path();
      const fs::file_type type = it->symlink_status(ec).type();
      if (ec) break;
      const std::string ext = p.extension().string();
      if (type == fs::file_type::regular && (ext == ".journal" || ext == ".events")) renders = true;
      if (type == fs::file_type::directory && depth < max_folder_depth && p.filename().string().front() != '.' &&
          !known_.count(p))
        below.push_back(p);
    }
    if (renders && depth > 0) {
      listed_.push_back(dir);
      known_.insert(dir);
      continue;
    }
    if (renders) {  // a render folder given: its sub-folders are its own, and it is not read again
      render_roots_.insert(dir);
      continue;
    }
    for (fs::path& b : below) queue.emplace_back(std::move(b), depth + 1);
  }
  return listed_;
}

}  // namespace lc::monitor
