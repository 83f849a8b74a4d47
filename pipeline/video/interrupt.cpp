#include "video/interrupt.hpp"

#include <csignal>
#include <string>

namespace lc {

namespace {
// A signal handler can only reach static storage, and may only store a
// sig_atomic_t: this is the one piece of global mutable state the encode
// stage needs.  0: no signal yet.
volatile std::sig_atomic_t received = 0;

extern "C" void record_signal(int sig) { received = sig; }
}  // namespace

Interrupted::Interrupted(int sig)
    : std::runtime_error(std::string("interrupted by ") + (sig == SIGINT ? "Ctrl-C (SIGINT)" : "SIGTERM")),
      signal(sig) {}

InterruptGuard::InterruptGuard() {
  // Installs the recorder for SIGINT and SIGTERM, keeping the old handlers.
  received = 0;
  struct sigaction sa = {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &previous_int_);
  sigaction(SIGTERM, &sa, &previous_term_);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

void InterruptGuard::check() const {
  if (received != 0) throw Interrupted(received);
}

}  // namespace lc
