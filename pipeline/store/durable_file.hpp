#pragma once
// Durable output files, for every file lightcone writes under a name a user
// or a later run reads (frames, videos, sheets, CSV, star fields).
//
// The guarantee: no half-written file is ever visible under its final name;
// after commit() returns, the file and its name survive a crash.
//
// How: the bytes go to a temporary beside the final name (same directory,
// so the rename is atomic), written either through write() or by a library
// that takes a path (FFmpeg, the image layer) at library_path().  commit()
// fsyncs the temporary, renames it over the final name and fsyncs the
// directory.  A DurableFile destroyed uncommitted (an error, an interrupt
// unwinding the stack) removes its temporary and leaves the final name as it
// was.  Only a process killed outright leaves a temporary; its name says so
// (is_temporary_name); the next DurableFile of the same final name removes
// it, once the process that made it is gone.  Errors are std::runtime_error
// naming the final path and the OS reason.
//
// What the final name may be (docs/cli.md, "Output files"), for a name the
// user gave (FinalName::users):
// - absent or a regular file: replaced as above;
// - a symbolic link: followed (any depth), the file it ends at is replaced
//   and the link kept, as a shell's `>` would write through it;
// - a character device (/dev/null, a terminal) or a FIFO, or an open
//   descriptor (/dev/stdout, /dev/fd/N, /proc/self/fd/N): written in place,
//   never replaced; the bytes go to a temporary in the system's temporary
//   directory first (libraries that write by path may seek) and are copied
//   in at commit(), with an error on any short write;
// - a directory, a block device or a socket: refused before any work.
// A name lightcone gives a file of its own in a folder it keeps (a render's
// frames, previews and meter: FinalName::own) is the name itself: whatever
// is there (a link, a FIFO, a device) is replaced by the rename and nothing
// it leads to is written; only a directory is refused.
//
// The temporary is never a link either: a file already under its name (a
// killed process of the same pid left it, or someone planted it) is removed
// first, and write() or library_path() creates it afresh (O_EXCL, without
// following a link).  A library is never handed the temporary's name: its
// name is predictable (the pid), so a link planted there after it was
// cleared would lead the library's own open(O_CREAT | O_TRUNC) to a file
// elsewhere.  It is handed /proc/self/fd/N of the descriptor created here,
// which opens this very file whatever is under the name by then.  commit()
// renames the temporary only if its name still holds that file.

#include <filesystem>
#include <initializer_list>
#include <string_view>

namespace lc {

// Whether a DurableFile looks for temporaries of its name that killed
// processes left: every output does, except where the caller cleans a whole
// folder of them once (the frame store, at the start of a render), which
// keeps a frame's write from listing a folder of thousands of frames.
enum class StaleTemporaries { remove, cleaned_by_caller };

// Whose name the final path is, which decides what a link or a special
// file under it means (above).
enum class FinalName {
  users,  // given by the user (-o FILE): written through as a shell's `>` would
  own,    // lightcone's own file in a folder it keeps: the name itself is replaced
};

class DurableFile {
 public:
  // Input: the final path.  Reserves "<final>.tmp-<pid>" (the pid keeps two
  // processes writing the same name apart; for a device, FIFO or descriptor
  // "lightcone-<name>.tmp-<pid>" in the temporary directory) and removes
  // temporaries of the same name left by processes that are gone, and
  // whatever is under its own temporary's name; nothing is created yet.
  // Throws when `final_path` cannot be a file (a directory; for a user's
  // name also a block device, a socket, a link loop), which would otherwise
  // be found only after all the work, or when a file under the temporary's
  // name cannot be removed.
  explicit DurableFile(std::filesystem::path final_path, StaleTemporaries stale = StaleTemporaries::remove,
                       FinalName name = FinalName::users);
  ~DurableFile();
  DurableFile(const DurableFile&) = delete;
  DurableFile& operator=(const DurableFile&) = delete;

  // The path as given (what messages name).
  const std::filesystem::path& final_path() const { return final_; }
  // The temporary's name, for messages and tests.  Never hand it to a
  // library that writes by path: library_path() is what it writes to.
  const std::filesystem::path& temp_path() const { return temp_; }

  // Where a library that writes by path (the image layer, FFmpeg) writes,
  // reads back what it wrote, or reopens it: /proc/self/fd/N of the
  // temporary, which the first call creates as write() does (so that it
  // holds only what the library writes; a library's truncating open is
  // harmless).  Valid while this object lives and is not committed.
  // Throws naming the final path when the temporary cannot be created
  // (something appeared under its name since the constructor cleared it,
  // a missing directory, a full disk) or /proc is not there to reach it.
  std::filesystem::path library_path();

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
  void create_temp();
  void check_temp_is_ours() const;
  void sync_temp() const;
  void rename_into_place();
  void copy_into_stream();
  void put_in_place();
  void clear_temporary_name() const;

  std::filesystem::path final_;  // as given
  std::filesystem::path target_;  // where the bytes end: final_ with its links followed
  std::filesystem::path temp_;
  bool stream_ = false;  // target_ is written in place (a device, FIFO or descriptor)
  int descriptor_ = -1;  // for /dev/fd/N and the like: N, written through a copy of it
  int fd_ = -1;          // the temporary, open from its creation (write(), library_path()) to commit()
  bool created_ = false;  // the temporary was made by this object (only then is it removed)
  bool committed_ = false;
};

void commit_together(std::initializer_list<DurableFile*> files);

// Input: an open descriptor of this process.  Output: /proc/self/fd/N, a
// path that opens the very file the descriptor is open on (never what is
// under that file's name by then), for a library that takes a path: the
// image and video writers (DurableFile::library_path), the monitor's EXR
// reader.  The path is a link, so a reader that refuses links cannot use it.
std::filesystem::path descriptor_path(int fd);

// Input: a directory ("" is the current one).  fsyncs it, so that renames
// and new names in it survive a crash; throws naming it.
void sync_directory(const std::filesystem::path& dir);

// A file lightcone keeps open in a folder of its own (the lock, a journal,
// an event log), opened in place: never through a link, never blocking (a
// FIFO would hang the open, or the first read, for good), and only if it is
// a regular file.  Inputs: the path; `flags`: O_RDONLY, O_WRONLY or O_RDWR,
// with O_CREAT and O_APPEND as wanted (O_NOFOLLOW, O_CLOEXEC and O_NOCTTY
// are added; O_NONBLOCK is used to open and cleared after); `what` says
// what the caller was doing, for messages ("lock", "write the journal").
// Output: the descriptor, and whether this call created the file (so that a
// caller that fails can remove what it made and only that); fd -1 when the
// file is absent and O_CREAT not given.  Throws std::runtime_error naming
// the path: "cannot lock out/lightcone.lock: it is a symbolic link, not a
// regular file; ..." or the OS's reason.
struct OwnFile {
  int fd = -1;
  bool created = false;
};
OwnFile open_own_file(const std::filesystem::path& path, int flags, std::string_view what);

// Whether `file_name` is a DurableFile temporary ("<name>.tmp-<digits>"):
// one found on disk was left by a killed process, since a live one removes
// its own.
bool is_temporary_name(std::string_view file_name);

}  // namespace lc
