#pragma once
// A file that appears under its final name only when complete: written to a
// temporary name in the same directory, flushed to disk, then renamed.  If
// the writer fails or is destroyed before commit(), the temporary file is
// removed and nothing is left under the final name.

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace lc {

class AtomicFile {
 public:
  // Opens a temporary next to `path`.  Throws std::runtime_error naming the
  // path and the OS reason when the directory is missing or not writable.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends bytes; throws on a write error (e.g. a full disk).
  void write(std::string_view data);
  // Flushes, fsyncs and renames onto the final name; throws on failure (and
  // then leaves no file behind).
  void commit();

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_, temp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

// Throws std::invalid_argument "-o PATH: <what> (name it <extension>)"
// unless `path` ends in `extension` (".png"; any case): a writer of one
// format must not put its bytes under another format's name.
void require_extension(const std::filesystem::path& path, std::string_view extension, std::string_view what);

// Writes `data` atomically to `path`, or to standard output when no path is
// given (for commands whose output defaults to stdout).
void write_output(const std::optional<std::filesystem::path>& path, std::string_view data);

}  // namespace lc
