// A render job (pipeline/job/render_job.hpp): what every rank derives from the
// flags and the shot, the test hook's value among it.

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "job/render_job.hpp"

namespace lc {
namespace {

// Sets an environment variable for one test and restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_.empty())
      ::unsetenv(name_);
    else
      ::setenv(name_, old_.c_str(), 1);
  }

 private:
  const char* name_;
  std::string old_;
};

RenderRequest orbit_command() {
  RenderRequest cmd;
  cmd.shot = std::string(LIGHTCONE_TEST_DATA) + "/farm/farm_orbit.lua";
  cmd.out = "unused";
  cmd.frames = "0:1";
  return cmd;
}

TEST(RenderJob, HoldsTheFramesTheLayoutAndTheTestPause) {
  ScopedEnv pause("LIGHTCONE_TEST_PAUSE_AFTER", "7");
  RenderRequest cmd = orbit_command();
  cmd.stripes = 4;
  const RenderJob job = load_render_job(cmd);
  ASSERT_TRUE(job.shot);
  EXPECT_EQ(job.frames, (std::vector<int>{0, 1}));
  EXPECT_EQ(job.layout.stripes(), 4);
  ASSERT_TRUE(job.test_pause);
  EXPECT_EQ(*job.test_pause, 7);
}

TEST(RenderJob, WithoutTheHookThereIsNoPause) {
  ScopedEnv pause("LIGHTCONE_TEST_PAUSE_AFTER", "");
  EXPECT_FALSE(load_render_job(orbit_command()).test_pause);
}

TEST(RenderJob, ABadTestPauseIsRefusedNamingTheVariable) {
  ScopedEnv pause("LIGHTCONE_TEST_PAUSE_AFTER", "soon");
  try {
    load_render_job(orbit_command());
    FAIL() << "a bad LIGHTCONE_TEST_PAUSE_AFTER was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("LIGHTCONE_TEST_PAUSE_AFTER=soon"), std::string::npos) << e.what();
  }
}

TEST(RenderJob, ABadFlagIsRefusedNamingIt) {
  RenderRequest cmd = orbit_command();
  cmd.stripes = 0;
  try {
    load_render_job(cmd);
    FAIL() << "--stripes 0 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--stripes 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lc
