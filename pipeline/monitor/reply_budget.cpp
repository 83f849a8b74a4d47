#include "monitor/reply_budget.hpp"

namespace lc::monitor {

bool ReplyBudget::take(std::size_t bytes) {
  // Input: a body's size.  A compare-and-swap loop: two threads taking the
  // last bytes at once must not both get them.
  std::size_t held = held_.load();
  do {
    if (bytes > capacity_ || held > capacity_ - bytes) return false;
  } while (!held_.compare_exchange_weak(held, held + bytes));
  return true;
}

void ReplyBudget::give(std::size_t bytes) {
  // Input: bytes taken before by take (never more than are held).
  held_.fetch_sub(bytes);
}

}  // namespace lc::monitor
