#pragma once
// One render per output directory: an exclusive flock on DIR/lightcone.lock,
// which holds the holder's pid and host for the message the next one gets.
// The kernel drops the lock when the holder dies (even by SIGKILL), so a
// stale file never blocks anyone.

#include <filesystem>

namespace lc::farm {

class DirLock {
 public:
  // Takes the lock or throws std::runtime_error: naming the pid and host of
  // the render holding it, or why the file cannot be created (an output
  // directory that cannot be written).  `flag` names the option for messages.
  DirLock(const std::filesystem::path& dir, const char* flag);
  // Releases the lock and removes the file.
  ~DirLock();
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;

  static constexpr const char* file_name = "lightcone.lock";

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

}  // namespace lc::farm
