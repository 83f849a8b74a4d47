#pragma once
// An output file that a library (FFmpeg, the image layer) writes by name:
// it is written under a temporary name beside the final one, synced and
// renamed by commit(); destroyed uncommitted, it removes the temporary.  So
// the final name only ever shows a complete file (the same rule as
// AtomicFile, for writers that need a path instead of bytes).

#include <filesystem>

namespace lc {

class TempOutput {
 public:
  // Checks that `final_path` is not a directory (renaming onto one would fail
  // only at the very end); throws std::runtime_error naming it.
  explicit TempOutput(std::filesystem::path final_path);
  ~TempOutput();
  TempOutput(const TempOutput&) = delete;
  TempOutput& operator=(const TempOutput&) = delete;

  // Where the writer should write: "<final>.tmp-<pid>".
  const std::filesystem::path& temp() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }

  // fsyncs the temporary and renames it onto the final name; throws
  // std::runtime_error naming the final path on failure.
  void commit();

 private:
  std::filesystem::path final_, temp_;
  bool committed_ = false;
};

}  // namespace lc
