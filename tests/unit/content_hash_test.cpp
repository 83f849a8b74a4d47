// Tests of lc::farm::hash_file (pipeline/store/content_hash.cpp): it hashes
// the inputs of a render, which a shot names, so it must not block or run
// forever on what is no regular file.

#include "store/content_hash.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>

#include "scratch_dir.hpp"
#include "test_errors.hpp"

namespace {

using lc::farm::hash_file;
using lc::test::ScratchDir;
using lc::test::UnblockedFifo;

// The message of hash_file's refusal of `file`.
std::string hash_error(const std::filesystem::path& file) {
  return lc::test::error_of([&] { hash_file(file); });
}

TEST(ContentHash, HashesRegularFilesOnly) {
  ScratchDir dir;
  std::ofstream(dir / "a.png") << "abc";
  EXPECT_EQ(hash_file(dir / "a.png"), lc::farm::hash_bytes("abc"));
  // A FIFO blocked the open until something wrote to it (as /dev/zero never
  // ended; the e2e tests use it).
  const UnblockedFifo fifo(dir / "fifo.png");
  const auto t0 = std::chrono::steady_clock::now();
  const std::string msg = hash_error(fifo.path());
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 4.0);
  EXPECT_EQ(msg, "cannot read " + fifo.path().string() + ": a FIFO, not a regular file");
  EXPECT_EQ(hash_error(dir.path()), "cannot read " + dir.path().string() + ": a directory, not a regular file");
  EXPECT_EQ(hash_error(dir / "nope"), "cannot read " + (dir / "nope").string() + ": No such file or directory");
}

}  // namespace
