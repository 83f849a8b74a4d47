#include "job/stripes.hpp"

#include <algorithm>
#include <stdexcept>

namespace lc::farm {

StripeLayout::StripeLayout(int height, int stripes) : height_(height), stripes_(std::clamp(stripes, 1, std::max(1, height))) {
  if (height < 1) throw std::invalid_argument("StripeLayout: height must be at least 1");
}

std::vector<int> StripeLayout::rows(int stripe) const {
  std::vector<int> out;
  out.reserve(row_count(stripe));
  for (int j = stripe; j < height_; j += stripes_) out.push_back(j);
  return out;
}

// Rows s, s+S, s+2S, ... below the height: ceil((H - s) / S).
int StripeLayout::row_count(int stripe) const {
  if (stripe < 0 || stripe >= stripes_) return 0;
  return (height_ - stripe + stripes_ - 1) / stripes_;
}

}  // namespace lc::farm
