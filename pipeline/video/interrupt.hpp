#pragma once
// Ctrl-C (SIGINT) and kill (SIGTERM) during an encode: instead of dying with
// a temporary file on disk, the command notices the signal between frames,
// throws Interrupted, and the writers' destructors remove their temporaries.

#include <signal.h>

#include <stdexcept>

namespace lc {

// Thrown by InterruptGuard::check after a signal; `signal` is its number.
struct Interrupted : std::runtime_error {
  explicit Interrupted(int sig);
  int signal;
};

// While alive, SIGINT and SIGTERM are recorded instead of ending the
// process; the previous handlers come back on destruction.  One guard at a
// time (the recorded signal lives in the one place a handler may write).
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Throws Interrupted if a signal arrived since construction.
  void check() const;

 private:
  struct sigaction previous_int_ {}, previous_term_ {};
};

}  // namespace lc
