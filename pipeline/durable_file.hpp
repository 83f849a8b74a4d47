#pragma once
// Durable output files, for every file lightcone writes under a name a user
// or a later run reads (frames, videos, sheets, CSV, star fields).
//
// The guarantee: no half-written file is ever visible under its final name;
// after commit() returns, the file and its name survive a crash.
//
// How: the bytes go to a temporary beside the final name (same directory,
// so the rename is atomic), written either through write() or by a library
// that takes a path (FFmpeg, the image layer) at temp_path().  commit()
// fsyncs the temporary, renames it over the final name and fsyncs the
// directory.  A DurableFile destroyed uncommitted (an error, an interrupt
// unwinding the stack) removes its temporary and leaves the final name as it
// was.  Only a process killed outright leaves a temporary; its name says so
// (is_temporary_name); the next DurableFile of the same final name removes
// it, once the process that made it is gone.  Errors are std::runtime_error
// naming the final path and the OS reason.
//
// What the final name may be (docs/cli.md, "Output files"):
// - absent or a regular file: replaced as above;
// - a symbolic link: followed (any depth), the file it ends at is replaced
//   and the link kept, as a shell's `>` would write through it;
// - a character device (/dev/null, a terminal) or a FIFO, or an open
//   descriptor (/dev/stdout, /dev/fd/N, /proc/self/fd/N): written in place,
//   never replaced; the bytes go to a temporary in the system's temporary
//   directory first (libraries that write by path may seek) and are copied
//   in at commit(), with an error on any short write;
// - a directory, a block device or a socket: refused before any work.

#include <filesystem>
#include <initializer_list>
#include <string_view>

namespace lc {

// Whether a DurableFile looks for temporaries of its name that killed
// processes left: every output does, except where the caller cleans a whole
// folder of them once (the frame store, at the start of a render), which
// keeps a frame's write from listing a folder of thousands of frames.
enum class StaleTemporaries { remove, cleaned_by_caller };

class DurableFile {
 public:
  // Input: the final path.  Reserves "<final>.tmp-<pid>" (the pid keeps two
  // processes writing the same name apart; for a device, FIFO or descriptor
  // "lightcone-<name>.tmp-<pid>" in the temporary directory) and removes
  // temporaries of the same name left by processes that are gone; nothing is
  // created yet.  Throws when `final_path` cannot be a file (a directory, a
  // block device, a socket, a link loop), which would otherwise be found
  // only after all the work.
  explicit DurableFile(std::filesystem::path final_path, StaleTemporaries stale = StaleTemporaries::remove);
  ~DurableFile();
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  // The path as given (what messages name).
  const std::filesystem::path& final_path() const { return final_; }
  // Where a library that writes by path should write (it creates the file).
  const std::filesystem::path& temp_path() const { return temp_; }

  // Appends `bytes` to the temporary, creating it on the first call; throws
  // on a write error (a missing directory, a full disk).
  void write(std::string_view bytes);

  // Makes the file durable under its final name (see above).  Throws if the
  // temporary was never written or cannot be synced or renamed; the
  // temporary is then removed by the destructor.
  void commit();

  // commit() for several files at once (a frame's EXR and PNG): each synced
  // and renamed in order, then each directory synced once, so the guarantee
  // holds for all of them at one directory sync instead of one per file.
  friend void commit_together(std::initializer_list<DurableFile*> files);

 private:
  void sync_temp() const;
  void rename_into_place();
  void copy_into_stream();
  void put_in_place();

  std::filesystem::path final_;  // as given
  std::filesystem::path target_;  // where the bytes end: final_ with its links followed
  std::filesystem::path temp_;
  bool stream_ = false;  // target_ is written in place (a device, FIFO or descriptor)
  int descriptor_ = -1;  // for /dev/fd/N and the like: N, written through a copy of it
  int fd_ = -1;          // open while write() is in use
  bool committed_ = false;
};

void commit_together(std::initializer_list<DurableFile*> files);

// Input: a directory ("" is the current one).  fsyncs it, so that renames
// and new names in it survive a crash; throws naming it.
void sync_directory(const std::filesystem::path& dir);

// Whether `file_name` is a DurableFile temporary ("<name>.tmp-<digits>"):
// one found on disk was left by a killed process, since a live one removes
// its own.
bool is_temporary_name(std::string_view file_name);

}  // namespace lc
