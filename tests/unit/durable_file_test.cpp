// Tests of lc::DurableFile (pipeline/durable_file.cpp), which every output
// of lightcone goes through: the final name shows a file only when it is
// complete, a failed or abandoned write changes nothing and leaves no
// temporary, and errors name the file and the reason.

#include "durable_file.hpp"

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

#include <cstring>
#include <thread>

#include "interrupt.hpp"
#include "scratch_dir.hpp"
#include "test_errors.hpp"

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
  std::ofstream(out.temp_path(), std::ios::binary) << "picture";  // as FFmpeg or the image layer would
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
    std::ofstream(out.temp_path(), std::ios::binary) << "picture";
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
