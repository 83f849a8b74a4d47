#pragma once
// The message of the exception the code under test throws, for the many
// tests that check what an error says (the path, the reason, the fix).

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace lc::test {

// Input: `f`, expected to throw an E (or something derived from it).
// Returns its what(); "" and a test failure when `f` returns normally.
// Exceptions of other types pass through, and gtest reports them.
template <class E = std::runtime_error, class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception thrown";
  return {};
}

}  // namespace lc::test
