#pragma once
// Ctrl-C (SIGINT) and kill (SIGTERM) while a command works: instead of
// dying with a temporary file on disk or a frame half stored, the command
// notices the signal where it can stop cleanly — encode between frames
// (check() throws Interrupted and the writers' destructors remove their
// temporaries), render once the frames it holds complete are stored — says
// what it kept, and exits with 128 + the signal, as a shell reports a death
// by it (130, 143).  A second signal ends the process at once, for a user
// who will not wait.

#include <signal.h>

#include <stdexcept>
#include <string>

namespace lc {

// "Ctrl-C (SIGINT)" or "SIGTERM": for messages.
std::string signal_name(int sig);

// Thrown by InterruptGuard::check after a signal; `signal` is its number.
struct Interrupted : std::runtime_error {
  explicit Interrupted(int sig);
  int signal;
};

// While alive, SIGINT and SIGTERM are recorded instead of ending the
// process (the first; a second one of either ends it); the previous
// handlers come back on destruction.  Guards nest: an inner one (a render
// inside the showcase) shares the outer one's record and leaves the
// handlers alone.  Made and destroyed on the main thread.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The signal received since the outermost guard was made, 0 if none.
  int signal() const;
  // Throws Interrupted if a signal arrived since the outermost guard was made.
  void check() const;

 private:
  bool outermost_ = false;
  struct sigaction previous_int_ {}, previous_term_ {};
};

}  // namespace lc
