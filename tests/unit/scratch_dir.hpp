#pragma once
// A scratch directory under the system temp directory, named after the
// running test (and the process, so parallel ctest runs never collide),
// created empty and removed at the end of the test; and a FIFO to put in it
// for tests of readers that must refuse one.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace lc::test {

class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("lightcone_" + std::string(info->test_suite_name()) + "_" +
                                                      info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  // The names of the entries in the directory, sorted: what a test expects
  // to find there and nothing else (a temporary left behind shows).
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(path_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::filesystem::path path_;
};

// A FIFO at `path` (made here) for tests of readers that must refuse one
// rather than open it: opening a FIFO for reading blocks until a writer
// comes.  So that a regression fails instead of hanging, after 5 s a helper
// thread keeps opening it for writing until this object goes (the test
// then sees the time it took).  Throws if the FIFO cannot be made.
class UnblockedFifo {
 public:
  explicit UnblockedFifo(std::filesystem::path path) : path_(std::move(path)) {
    if (::mkfifo(path_.c_str(), 0600) != 0)
      throw std::runtime_error("mkfifo " + path_.string() + ": " + std::strerror(errno));
    unblock_ = std::thread([this] {
      for (int i = 0; !done_; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (i >= 50 && !done_) ::close(::open(path_.c_str(), O_RDWR));
      }
    });
  }
  ~UnblockedFifo() {
    done_ = true;
    unblock_.join();
  }
  UnblockedFifo(const UnblockedFifo&) = delete;
  UnblockedFifo& operator=(const UnblockedFifo&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::atomic<bool> done_{false};
  std::thread unblock_;
};

}  // namespace lc::test
