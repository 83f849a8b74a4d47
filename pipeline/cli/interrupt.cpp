#include "interrupt.hpp"

#include <csignal>
#include <string>

namespace lc {

namespace {
// A signal handler can only reach static storage, and may only store a
// sig_atomic_t: this is the one piece of global mutable state signal
// handling needs.  0: no signal yet.
volatile std::sig_atomic_t received = 0;
// Guards alive (main thread only; the handler does not read it).
int depth = 0;

extern "C" void record_signal(int sig) {
  if (received != 0) {
    // The second one: the default action (death by the signal) once this
    // handler returns.  signal() and raise() are async-signal-safe.
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  received = sig;
}
}  // namespace

std::string signal_name(int sig) { return sig == SIGINT ? "Ctrl-C (SIGINT)" : sig == SIGTERM ? "SIGTERM" : "a signal"; }

Interrupted::Interrupted(int sig) : std::runtime_error("interrupted by " + signal_name(sig)), signal(sig) {}

InterruptGuard::InterruptGuard() {
  // The outermost guard installs the recorder for SIGINT and SIGTERM,
  // keeping the old handlers.
  outermost_ = depth++ == 0;
  if (!outermost_) return;
  received = 0;
  struct sigaction sa = {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &previous_int_);
  sigaction(SIGTERM, &sa, &previous_term_);
}

InterruptGuard::~InterruptGuard() {
  --depth;
  if (!outermost_) return;
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

int InterruptGuard::signal() const { return received; }

void InterruptGuard::check() const {
  if (received != 0) throw Interrupted(received);
}

}  // namespace lc
