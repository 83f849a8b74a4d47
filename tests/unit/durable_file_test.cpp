// Tests of lc::DurableFile (pipeline/durable_file.cpp), which every output
// of lightcone goes through: the final name shows a file only when it is
// complete, a failed or abandoned write changes nothing and leaves no
// temporary, and errors name the file and the reason.

#include "durable_file.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

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

TEST(DurableFile, TemporaryNamesAreTheFinalNameAndAPid) {
  EXPECT_TRUE(lc::is_temporary_name("kerr.0003.png.tmp-77"));
  EXPECT_TRUE(lc::is_temporary_name("out.csv.tmp-123456"));
  EXPECT_FALSE(lc::is_temporary_name("kerr.0003.png"));
  EXPECT_FALSE(lc::is_temporary_name("kerr.0003.png.tmp-"));
  EXPECT_FALSE(lc::is_temporary_name("kerr.0003.png.tmp-12x"));
  EXPECT_FALSE(lc::is_temporary_name(".tmp-12"));  // a temporary of no name
}

}  // namespace
