#pragma once
// The one test hook in production code: LIGHTCONE_TEST_PAUSE_AFTER
// (docs/cli.md, "Environment"; docs/architecture.md, "Test hooks").  A
// render reads it once, when its job is loaded (job/render_job.cpp), and,
// when it is set, renders through a PausingStripeRenderer
// (stages/pausing_stripe_renderer.hpp): the e2e tests stop a
// render at a known working set however fast the machine is, instead of at
// a moment a sleep guessed.  Nothing else in lightcone reads a test
// variable.

#include <optional>

namespace lc::farm {

// The variable's name, for messages and the docs' test.
inline constexpr const char* test_pause_variable = "LIGHTCONE_TEST_PAUSE_AFTER";

// The number of working sets LIGHTCONE_TEST_PAUSE_AFTER asks a render to
// pause after, if it is set (a whole number >= 0; anything else throws
// std::invalid_argument naming the variable).
std::optional<long> test_pause_after();

}  // namespace lc::farm
