// Tests of lc::DurableFile (pipeline/store/durable_file.cpp), which every output
// of lightcone goes through: the final name shows a file only when it is
// complete, a failed or abandoned write changes nothing and leaves no
// temporary, and errors name the file and the reason.

#include "store/durable_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "image/image_io.hpp"
#include "cli/interrupt.hpp"
#include "scratch_dir.hpp"
#include "test_errors.hpp"
#include "tiny_frame.hpp"

namespace {

namespace fs = std::filesystem;
using lc::DurableFile;
using lc::test::error_of;
using lc::test::ScratchDir;
using Names = std::vector<std::string>;

// The bytes of file `p` ("" if it cannot be read).
std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(DurableFile, TheFinalNameAppearsOnlyAtCommit) {
  ScratchDir dir;
  DurableFile out(dir / "out.csv");
  out.write("a,b\n");
  out.write("1,2\n");
  EXPECT_EQ(dir.names(), Names{out.temp_path().filename().string()});
  EXPECT_EQ(out.temp_path().parent_path(), dir.path());  // beside it: the rename stays in one file system
  EXPECT_TRUE(lc::is_temporary_name(out.temp_path().filename().string()));
  out.commit();
  EXPECT_EQ(dir.names(), Names{"out.csv"});
  EXPECT_EQ(contents(dir / "out.csv"), "a,b\n1,2\n");
}

TEST(DurableFile, AnOldFileStaysWholeUntilTheNewOneIsCommitted) {
  ScratchDir dir;
  std::ofstream(dir / "out.csv") << "old";
  DurableFile out(dir / "out.csv");
  out.write("new");
  EXPECT_EQ(contents(dir / "out.csv"), "old");
  out.commit();
  EXPECT_EQ(contents(dir / "out.csv"), "new");
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(DurableFile, AnAbandonedWriteChangesNothingAndLeavesNoTemporary) {
  ScratchDir dir;
  std::ofstream(dir / "out.csv") << "old";
  { DurableFile out(dir / "out.csv"); out.write("half"); }
  EXPECT_EQ(dir.names(), Names{"out.csv"});
  EXPECT_EQ(contents(dir / "out.csv"), "old");
  // An interrupt unwinds the same way (encode stops between frames so).
  EXPECT_THROW(
      {
        DurableFile out(dir / "new.csv");
        out.write("half");
        throw lc::Interrupted(SIGINT);
      },
      lc::Interrupted);
  EXPECT_EQ(dir.names(), Names{"out.csv"});
}

TEST(DurableFile, ALibraryWritesByPath) {
  ScratchDir dir;
  DurableFile out(dir / "sheet.png");
  const fs::path lib = out.library_path();
  EXPECT_EQ(lib.parent_path(), "/proc/self/fd");  // the temporary's descriptor, not its name
  EXPECT_EQ(dir.names(), Names{out.temp_path().filename().string()});  // made by library_path itself
  std::ofstream(lib, std::ios::binary | std::ios::trunc) << "picture";  // as FFmpeg or the image layer would
  EXPECT_EQ(out.library_path(), lib);  // one temporary however often asked
  EXPECT_FALSE(fs::exists(dir / "sheet.png"));
  out.commit();
  EXPECT_EQ(dir.names(), Names{"sheet.png"});
  EXPECT_EQ(contents(dir / "sheet.png"), "picture");
}

TEST(DurableFile, ErrorsNameTheFileAndTheReason) {
  ScratchDir dir;
  const fs::path nowhere = dir / "no" / "out.csv";
  EXPECT_EQ(error_of([&] { DurableFile(nowhere).write("x"); }),
            "cannot write " + nowhere.string() + ": No such file or directory");
  EXPECT_EQ(error_of([&] { DurableFile out(dir.path()); }), "cannot write " + dir.path().string() + ": it is a directory");
  // A library that failed to write anything: nothing to commit.
  EXPECT_EQ(error_of([&] { DurableFile(dir / "video.mp4").commit(); }),
            "cannot sync " + (dir / "video.mp4").string() + ": No such file or directory");
  EXPECT_TRUE(dir.names().empty());
}

TEST(DurableFile, AFailedRenameLeavesTheFinalNameAsItWasAndNoTemporary) {
  ScratchDir dir;
  std::string message;
  {
    DurableFile out(dir / "out");
    out.write("data");
    fs::create_directories(dir / "out" / "inside");  // appeared meanwhile: a file cannot replace it
    message = error_of([&] { out.commit(); });
  }
  EXPECT_EQ(message.rfind("cannot rename onto " + (dir / "out").string() + ": ", 0), 0u) << message;
  EXPECT_TRUE(fs::is_directory(dir / "out" / "inside"));
  EXPECT_EQ(dir.names(), Names{"out"});
}

TEST(DurableFile, FilesCommittedTogetherAppearTogether) {
  ScratchDir dir;
  DurableFile exr(dir / "s.0001.exr"), png(dir / "s.0001.png");
  exr.write("exr");
  png.write("png");
  EXPECT_EQ(dir.names().size(), 2u);
  EXPECT_FALSE(fs::exists(exr.final_path()));
  lc::commit_together({&exr, &png});
  EXPECT_EQ(dir.names(), (Names{"s.0001.exr", "s.0001.png"}));
  EXPECT_EQ(contents(dir / "s.0001.png"), "png");
}

TEST(DurableFile, WhenOneOfFilesCommittedTogetherFailsNeitherAppears) {
  ScratchDir dir;
  {
    DurableFile exr(dir / "s.0001.exr"), png(dir / "s.0001.png");
    exr.write("exr");  // the PNG writer failed before writing anything
    EXPECT_EQ(error_of([&] { lc::commit_together({&exr, &png}); }),
              "cannot sync " + (dir / "s.0001.png").string() + ": No such file or directory");
  }
  EXPECT_TRUE(dir.names().empty());
}

TEST(DurableFile, CommittingTwiceIsAMistake) {
  ScratchDir dir;
  DurableFile out(dir / "out.csv");
  out.write("x");
  out.commit();
  EXPECT_THROW(out.commit(), std::logic_error);
  EXPECT_THROW(out.write("y"), std::logic_error);
  EXPECT_EQ(contents(dir / "out.csv"), "x");
}

TEST(DurableFile, SyncDirectoryNamesWhatItCannotSync) {
  ScratchDir dir;
  EXPECT_NO_THROW(lc::sync_directory(dir.path()));
  EXPECT_NO_THROW(lc::sync_directory(""));  // a relative output path's directory: the current one
  EXPECT_EQ(error_of([&] { lc::sync_directory(dir / "gone"); }),
            "cannot open " + (dir / "gone").string() + " to sync it: No such file or directory");
}

// A character device node at `p` with the numbers of /dev/null (1, 3) or
// /dev/full (1, 7), made in the scratch folder so that a regression replaces
// that node and not the system's; false where nodes cannot be made (not root).
bool make_char_device(const fs::path& p, unsigned minor) {
  return ::mknod(p.c_str(), S_IFCHR | 0666, makedev(1, minor)) == 0;
}

bool is_char_device(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

TEST(DurableFile, ADeviceIsWrittenInPlaceNeverReplaced) {
  ScratchDir dir;
  const fs::path null = dir / "null";
  if (!make_char_device(null, 3)) GTEST_SKIP() << "cannot make a device node here (not root)";
  {
    DurableFile out(null);
    EXPECT_NE(out.temp_path().parent_path(), dir.path());  // no temporary beside a device
    out.write("discarded");
    out.commit();
    EXPECT_FALSE(fs::exists(out.temp_path()));
  }
  EXPECT_TRUE(is_char_device(null));
  EXPECT_EQ(dir.names(), Names{"null"});
  // A library writing by path goes to the temporary, copied in at commit.
  {
    DurableFile out(null);
    std::ofstream(out.library_path(), std::ios::binary) << "picture";
    out.commit();
    EXPECT_FALSE(fs::exists(out.temp_path()));
  }
  EXPECT_TRUE(is_char_device(null));
}

TEST(DurableFile, AFullDeviceIsAnErrorNamingIt) {
  ScratchDir dir;
  const fs::path full = dir / "full";
  if (!make_char_device(full, 7)) GTEST_SKIP() << "cannot make a device node here (not root)";
  fs::path temp;
  {
    DurableFile out(full);
    temp = out.temp_path();
    out.write("no room");
    EXPECT_EQ(error_of([&] { out.commit(); }), "cannot write " + full.string() + ": No space left on device");
  }
  EXPECT_TRUE(is_char_device(full));
  EXPECT_FALSE(fs::exists(temp));
}

TEST(DurableFile, AFifoIsWrittenInPlace) {
  ScratchDir dir;
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  std::string got;
  std::thread reader([&] { got = contents(fifo); });
  {
    DurableFile out(fifo);
    out.write("through ");
    out.write("the pipe");
    out.commit();
  }
  reader.join();
  EXPECT_EQ(got, "through the pipe");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(DurableFile, AnOpenDescriptorIsWrittenThroughNotReopened) {
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  for (const std::string name : {"/dev/fd/", "/proc/self/fd/"}) {
    DurableFile out(name + std::to_string(ends[1]));
    out.write("via " + name);
    out.commit();
    char buf[64] = {};
    const ssize_t n = ::read(ends[0], buf, sizeof buf);
    EXPECT_EQ(std::string(buf, n > 0 ? n : 0), "via " + name);
  }
  ::close(ends[0]);
  ::close(ends[1]);
}

TEST(DurableFile, ALinkIsFollowedAndKept) {
  ScratchDir dir;
  fs::create_directories(dir / "real");
  std::ofstream(dir / "real" / "out.csv") << "old";
  fs::create_symlink("real/out.csv", dir / "link.csv");
  fs::create_symlink("link.csv", dir / "link2.csv");  // a link to a link
  {
    DurableFile out(dir / "link2.csv");
    EXPECT_EQ(out.temp_path().parent_path(), dir / "real");  // beside the file the links end at
    out.write("new");
    out.commit();
  }
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_TRUE(fs::is_symlink(dir / "link2.csv"));
  EXPECT_EQ(contents(dir / "real" / "out.csv"), "new");
  // A dangling link: the file it names is made.
  fs::create_symlink("real/made.csv", dir / "dangling.csv");
  {
    DurableFile out(dir / "dangling.csv");
    out.write("made");
    out.commit();
  }
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.csv"));
  EXPECT_EQ(contents(dir / "real" / "made.csv"), "made");
}

TEST(DurableFile, WhatCannotBeAFileIsRefusedBeforeAnyWork) {
  ScratchDir dir;
  fs::create_symlink("loop2", dir / "loop1");
  fs::create_symlink("loop1", dir / "loop2");
  EXPECT_EQ(error_of([&] { DurableFile out(dir / "loop1"); }),
            "cannot follow the links of " + (dir / "loop1").string() + ": Too many levels of symbolic links");
  const fs::path socket_path = dir / "sock";
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, socket_path.c_str(), sizeof addr.sun_path - 1);
  ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0) << std::strerror(errno);
  EXPECT_EQ(error_of([&] { DurableFile out(socket_path); }),
            "cannot write " + socket_path.string() + ": it is a socket, which lightcone does not write to");
  ::close(s);
  fs::create_symlink("sock", dir / "to_sock");
  EXPECT_EQ(error_of([&] { DurableFile out(dir / "to_sock"); }),
            "cannot write " + (dir / "to_sock").string() + ": it is a socket, which lightcone does not write to (" +
                (dir / "sock").string() + ")");
  if (::mknod((dir / "block").c_str(), S_IFBLK | 0600, makedev(7, 250)) == 0) {
    EXPECT_EQ(error_of([&] { DurableFile out(dir / "block"); }),
              "cannot write " + (dir / "block").string() + ": it is a block device, which lightcone does not write to");
  }
}

// A file outside the folder a test writes in, which nothing may write.
struct Outside {
  explicit Outside(const ScratchDir& dir) : path(dir / "outside.txt") { std::ofstream(path) << "not lightcone's"; }
  bool unchanged() const { return contents(path) == "not lightcone's"; }
  fs::path path;
};

TEST(DurableFile, AnOwnNameIsReplacedNeverFollowed) {
  // A frame's, a preview's or the meter's name in a render's folder: a
  // link planted there had the file it leads to replaced (issue 43).
  ScratchDir dir;
  const Outside outside(dir);
  fs::create_directories(dir / "out");
  fs::create_symlink(outside.path, dir / "out" / "s.0000.png");
  {
    DurableFile out(dir / "out" / "s.0000.png", lc::StaleTemporaries::remove, lc::FinalName::own);
    EXPECT_EQ(out.temp_path().parent_path(), dir / "out");
    out.write("frame");
    out.commit();
  }
  EXPECT_TRUE(outside.unchanged());
  EXPECT_FALSE(fs::is_symlink(dir / "out" / "s.0000.png"));
  EXPECT_EQ(contents(dir / "out" / "s.0000.png"), "frame");
  // A FIFO is replaced too, not written in (nobody reads it).
  ASSERT_EQ(::mkfifo((dir / "out" / "s.meter").c_str(), 0600), 0);
  {
    DurableFile out(dir / "out" / "s.meter", lc::StaleTemporaries::remove, lc::FinalName::own);
    out.write("readings");
    out.commit();
  }
  EXPECT_EQ(contents(dir / "out" / "s.meter"), "readings");
  EXPECT_EQ(error_of([&] { DurableFile out(dir / "out", lc::StaleTemporaries::remove, lc::FinalName::own); }),
            "cannot write " + (dir / "out").string() + ": it is a directory");
}

TEST(DurableFile, TheTemporaryIsNeverWrittenThrough) {
  // A link under the temporary's name (it carries the pid, so it can be
  // planted ahead) was truncated and written through, then renamed into
  // place as a link to what it led to.
  ScratchDir dir;
  const Outside outside(dir);
  const fs::path temp = dir / ("out.csv.tmp-" + std::to_string(::getpid()));
  for (const bool by_library : {false, true}) {
    fs::create_symlink(outside.path, temp);
    {
      DurableFile out(dir / "out.csv");
      EXPECT_EQ(out.temp_path(), temp);
      if (by_library)
        std::ofstream(out.library_path(), std::ios::binary) << "picture";
      else
        out.write("a,b\n");
      out.commit();
    }
    EXPECT_TRUE(outside.unchanged());
    EXPECT_FALSE(fs::is_symlink(dir / "out.csv"));
    EXPECT_EQ(contents(dir / "out.csv"), by_library ? "picture" : "a,b\n");
  }
  // One that cannot be removed stops the write before anything is written.
  fs::create_directories(temp / "inside");
  const std::string message = error_of([&] { DurableFile out(dir / "out.csv"); });
  EXPECT_EQ(message.rfind("cannot write " + (dir / "out.csv").string() + ": its temporary " + temp.string() +
                              " is already there and cannot be removed (",
                          0),
            0u)
      << message;
}

TEST(DurableFile, ALinkPlantedAtTheTemporaryAfterItWasClearedIsNeverWrittenThrough) {
  // The temporary's name is predictable ("<final>.tmp-<pid>"), and the
  // constructor's clearing of it comes before the write: a link planted in
  // between was followed by the image writers and FFmpeg, which were handed
  // that name and open it O_CREAT | O_TRUNC, so a frame overwrote the file
  // the link led to (review of issue 43).  The link is planted here at that
  // exact moment, then the image layer writes as the frame store does.
  ScratchDir dir;
  const Outside outside(dir);
  fs::create_directories(dir / "out");
  const fs::path exr = dir / "out" / "s.0001.exr";
  const lc::FrameImage frame = lc::test::tiny_frame();
  for (const bool by_library : {true, false}) {
    {
      DurableFile out(exr, lc::StaleTemporaries::cleaned_by_caller, lc::FinalName::own);
      fs::create_symlink(outside.path, out.temp_path());
      const std::string message = error_of([&] {
        if (by_library) lc::write_exr(out.library_path(), frame, {}, out.final_path());
        else out.write("bytes");
        out.commit();
      });
      EXPECT_EQ(message, "cannot write " + exr.string() + ": something appeared under its temporary's name " +
                             out.temp_path().string() +
                             " after lightcone had cleared it (a planted link?), and lightcone writes only into a "
                             "temporary it created itself: nothing was written, and what is there was left as it is "
                             "(move it away)");
    }
    EXPECT_TRUE(outside.unchanged());
    EXPECT_FALSE(fs::exists(exr));
    // What it made is its own to remove; the link is not.
    const fs::path temp = dir / "out" / ("s.0001.exr.tmp-" + std::to_string(::getpid()));
    EXPECT_TRUE(fs::is_symlink(temp));
    fs::remove(temp);
  }
  // The link swapped in for the temporary after it was made (its name
  // unlinked, a link put there), before the library opens it: the library
  // writes the file made, and the commit refuses to rename the link into
  // place.
  {
    DurableFile out(exr, lc::StaleTemporaries::cleaned_by_caller, lc::FinalName::own);
    const fs::path lib = out.library_path();
    fs::remove(out.temp_path());
    fs::create_symlink(outside.path, out.temp_path());
    lc::write_exr(lib, frame, {}, out.final_path());
    EXPECT_TRUE(outside.unchanged());
    EXPECT_EQ(error_of([&] { out.commit(); }),
              "cannot write " + exr.string() + ": its temporary " + out.temp_path().string() +
                  " was removed or replaced while it was being written, and lightcone puts in place only the file it "
                  "wrote (nothing was put in place)");
    fs::remove(out.temp_path());
  }
  EXPECT_TRUE(outside.unchanged());
  EXPECT_FALSE(fs::exists(exr));
  // Written as usual, the frame is the image layer's bytes for the image.
  {
    DurableFile out(exr, lc::StaleTemporaries::cleaned_by_caller, lc::FinalName::own);
    lc::write_exr(out.library_path(), frame, {}, out.final_path());
    out.commit();
  }
  lc::write_exr(dir / "plain.exr", frame);
  EXPECT_EQ(contents(exr), contents(dir / "plain.exr"));
  EXPECT_EQ(dir.names(), (Names{"out", "outside.txt", "plain.exr"}));
}

TEST(DurableFile, OwnFilesAreOpenedOnlyAsRegularFiles) {
  ScratchDir dir;
  const Outside outside(dir);
  // Absent: made (and said so) or, without O_CREAT, none.
  EXPECT_EQ(lc::open_own_file(dir / "log", O_RDONLY, "read").fd, -1);
  lc::OwnFile made = lc::open_own_file(dir / "log", O_WRONLY | O_APPEND | O_CREAT, "write");
  ASSERT_GE(made.fd, 0);
  EXPECT_TRUE(made.created);
  EXPECT_EQ(::write(made.fd, "x", 1), 1);  // blocking again, writable
  EXPECT_EQ(::fcntl(made.fd, F_GETFL) & O_NONBLOCK, 0);
  ::close(made.fd);
  lc::OwnFile again = lc::open_own_file(dir / "log", O_WRONLY | O_APPEND | O_CREAT, "write");
  EXPECT_FALSE(again.created);
  ::close(again.fd);
  // A link, dangling or not, is refused: never written through, never made.
  const std::string link = ": it is a symbolic link, and lightcone never follows a link among its own files in a "
                           "folder (move it away)";
  const std::string why = ", not a regular file, and lightcone keeps its own files in a folder as regular files only "
                          "(move it away)";
  fs::create_symlink(outside.path, dir / "lock");
  fs::create_symlink(dir / "nowhere", dir / "dangling");
  for (const char* name : {"lock", "dangling"}) {
    EXPECT_EQ(error_of([&] { lc::open_own_file(dir / name, O_RDWR | O_CREAT, "lock"); }),
              "cannot lock " + (dir / name).string() + link);
    EXPECT_EQ(error_of([&] { lc::open_own_file(dir / name, O_RDONLY, "read"); }),
              "cannot read " + (dir / name).string() + link);
  }
  EXPECT_TRUE(outside.unchanged());
  EXPECT_FALSE(fs::exists(dir / "nowhere"));
  // A FIFO is refused at once, however opened (for reading or writing,
  // open would wait for the other end; a read of one opened both ways
  // would wait for a writer).
  const lc::test::UnblockedFifo fifo(dir / "journal");
  const auto start = std::chrono::steady_clock::now();
  for (const int flags : {O_RDONLY, O_WRONLY | O_CREAT, O_RDWR | O_CREAT, O_WRONLY | O_APPEND})
    EXPECT_EQ(error_of([&] { lc::open_own_file(fifo.path(), flags, "read the journal"); }),
              "cannot read the journal " + fifo.path().string() + ": it is a FIFO" + why);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(3));
  fs::create_directories(dir / "folder");
  EXPECT_EQ(error_of([&] { lc::open_own_file(dir / "folder", O_RDONLY, "read"); }),
            "cannot read " + (dir / "folder").string() + ": it is a directory" + why);
  // Where it cannot be made: the OS's reason.
  EXPECT_EQ(error_of([&] { lc::open_own_file(dir / "no" / "lock", O_RDWR | O_CREAT, "lock"); }),
            "cannot lock " + (dir / "no" / "lock").string() + ": No such file or directory");
}

Names sorted(Names n) {
  std::sort(n.begin(), n.end());
  return n;
}

// The pid of a process that has ended (a child, waited for).
pid_t a_dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

TEST(DurableFile, TemporariesOfProcessesThatAreGoneAreRemoved) {
  ScratchDir dir;
  const std::string dead = "video.mp4.tmp-" + std::to_string(a_dead_pid());
  const std::string alive = "video.mp4.tmp-" + std::to_string(::getppid());
  const std::string other = "other.mp4.tmp-" + std::to_string(a_dead_pid());
  for (const auto& n : {dead, alive, other}) std::ofstream(dir / n) << "left";
  {
    DurableFile out(dir / "video.mp4");
    EXPECT_EQ(dir.names(), sorted({other, alive}));  // only its own name's, only the dead one's
  }
  // The frame store clears its folder itself: its writes do not look.
  std::ofstream(dir / dead) << "left";
  { DurableFile out(dir / "video.mp4", lc::StaleTemporaries::cleaned_by_caller); }
  EXPECT_EQ(dir.names(), sorted({other, dead, alive}));
}

TEST(DurableFile, TemporaryNamesAreTheFinalNameAndAPid) {
  EXPECT_TRUE(lc::is_temporary_name("kerr.0003.png.tmp-77"));
  EXPECT_TRUE(lc::is_temporary_name("out.csv.tmp-123456"));
  EXPECT_FALSE(lc::is_temporary_name("kerr.0003.png"));
  EXPECT_FALSE(lc::is_temporary_name("kerr.0003.png.tmp-"));
  EXPECT_FALSE(lc::is_temporary_name("kerr.0003.png.tmp-12x"));
  EXPECT_FALSE(lc::is_temporary_name(".tmp-12"));  // a temporary of no name
}

}  // namespace
