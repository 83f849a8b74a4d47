// Ctrl-C and kill while a command works: the first SIGINT or SIGTERM is
// recorded (the command stops where it can), a second one ends the process,
// guards nest, and the old handlers come back.

#include "cli/interrupt.hpp"

#include <gtest/gtest.h>

#include <csignal>

namespace lc {
namespace {

// The handler now installed for `sig`.
void (*handler_of(int sig))(int) {
  struct sigaction now = {};
  sigaction(sig, nullptr, &now);
  return now.sa_handler;
}

TEST(Interrupt, TheFirstSignalIsRecordedNotFatal) {
  const auto before = handler_of(SIGINT);
  {
    InterruptGuard guard;
    EXPECT_EQ(guard.signal(), 0);
    EXPECT_NO_THROW(guard.check());
    std::raise(SIGINT);
    EXPECT_EQ(guard.signal(), SIGINT);
    try {
      guard.check();
      FAIL() << "no Interrupted thrown";
    } catch (const Interrupted& e) {
      EXPECT_EQ(e.signal, SIGINT);
      EXPECT_STREQ(e.what(), "interrupted by Ctrl-C (SIGINT)");
    }
  }
  EXPECT_EQ(handler_of(SIGINT), before);  // restored
}

TEST(Interrupt, NestedGuardsShareOneRecord) {
  InterruptGuard outer;
  {
    InterruptGuard inner;  // a render inside the showcase
    std::raise(SIGTERM);
    EXPECT_EQ(inner.signal(), SIGTERM);
  }
  EXPECT_EQ(outer.signal(), SIGTERM);  // the inner guard neither reset it nor removed the handler
  EXPECT_NE(handler_of(SIGTERM), SIG_DFL);
  EXPECT_EQ(signal_name(SIGTERM), "SIGTERM");
}

TEST(Interrupt, ASecondSignalEndsTheProcessAtOnce) {
  EXPECT_EXIT(
      {
        InterruptGuard guard;
        std::raise(SIGINT);
        std::raise(SIGINT);
        std::_Exit(0);  // not reached
      },
      ::testing::KilledBySignal(SIGINT), "");
}

}  // namespace
}  // namespace lc
