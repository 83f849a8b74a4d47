#pragma once
// The render folders the monitor shows (docs/monitor.md, "Folders"): those
// it was given, and the folders found under them as they appear.  A folder
// given that holds no render yet is searched for render folders (those
// holding a <shot>.journal or <shot>.events) down to a bounded depth, on
// every listing, within a bound of entries read and of folders listed;
// links are never followed, hidden folders never entered, and a render
// folder's own sub-folders (its previews) never searched.  A folder keeps
// its number for as long as the monitor runs, even if it goes away.

#include <cstddef>
#include <filesystem>
#include <mutex>
#include <set>
#include <vector>

namespace lc::monitor {

inline constexpr int max_folder_depth = 3;            // levels searched below a folder given
inline constexpr std::size_t max_listed_folders = 256;
inline constexpr std::size_t max_entries_per_search = 20000;

class FolderList {
 public:
  // `roots`: canonical folders, listed first, in this order.
  explicit FolderList(std::vector<std::filesystem::path> roots);
  // Searches the folders given for render folders not yet listed, adds
  // them, and gives the whole list (a folder's number is its index).
  std::vector<std::filesystem::path> search() const;
  // The list as it stands, without searching.
  std::vector<std::filesystem::path> current() const;

 private:
  std::vector<std::filesystem::path> roots_;
  mutable std::mutex mutex_;
  mutable std::vector<std::filesystem::path> listed_;
  mutable std::set<std::filesystem::path> known_;
  // Folders given found to hold renders: not searched again (a film's
  // folder holds a file per frame).
  mutable std::set<std::filesystem::path> render_roots_;
};

}  // namespace lc::monitor
