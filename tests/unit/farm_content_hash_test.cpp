// Tests of lc::farm::hash_file (pipeline/farm/content_hash.cpp): it hashes
// the inputs of a render, which a shot names, so it must not block or run
// forever on what is no regular file.

#include "farm/content_hash.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "scratch_dir.hpp"

namespace {

using lc::farm::hash_file;
using lc::test::ScratchDir;

std::string error_of(const std::filesystem::path& file) {
  try {
    hash_file(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << file;
  return {};
}

TEST(FarmContentHash, HashesRegularFilesOnly) {
  ScratchDir dir;
  std::ofstream(dir / "a.png") << "abc";
  EXPECT_EQ(hash_file(dir / "a.png"), lc::farm::hash_bytes("abc"));
  // A FIFO blocked the open until something wrote to it (as /dev/zero never
  // ended; the e2e tests use it). After 5 s a helper keeps opening the FIFO
  // while the test still waits, so a regression fails rather than hangs.
  const auto fifo = dir / "fifo.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::atomic<bool> done{false};
  std::thread unblock([&] {
    for (int i = 0; !done; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      if (i >= 50 && !done) ::close(::open(fifo.c_str(), O_RDWR));
    }
  });
  const auto t0 = std::chrono::steady_clock::now();
  const std::string msg = error_of(fifo);
  done = true;
  unblock.join();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 4.0);
  EXPECT_EQ(msg, "cannot read " + fifo.string() + ": a FIFO, not a regular file");
  EXPECT_EQ(error_of(dir.path()), "cannot read " + dir.path().string() + ": a directory, not a regular file");
  EXPECT_EQ(error_of(dir / "nope"), "cannot read " + (dir / "nope").string() + ": No such file or directory");
}

}  // namespace
