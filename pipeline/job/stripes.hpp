#pragma once
// How a frame is cut into working sets.  Stripes are interleaved rows: row
// j belongs to stripe j mod S.  Every stripe then samples the whole image
// from top to bottom, so stripes cost nearly the same even when the hole's
// shadow (cheap) or the disk's edge (expensive) covers only some rows, and
// a preview of every k-th stripe is an evenly thinned image.

#include <vector>

namespace lc::farm {

// Stripes per frame when the user does not choose (docs/performance.md,
// "Farm", has the measurement behind it).
inline constexpr int default_stripes = 512;

class StripeLayout {
 public:
  // `stripes` is clamped to 1 .. height (a stripe never comes out empty).
  StripeLayout(int height, int stripes);

  int stripes() const { return stripes_; }
  int height() const { return height_; }
  // The rows of stripe s, top to bottom.
  std::vector<int> rows(int stripe) const;
  // Number of rows of stripe s, without building the list.
  int row_count(int stripe) const;
  // The stripe row j belongs to.
  int stripe_of(int row) const { return row % stripes_; }
  // Whether stripe s is part of a preview that renders every k-th stripe
  // (k >= 1; k = 1 is every stripe).
  static bool in_preview(int stripe, int every) { return stripe % every == 0; }

 private:
  int height_, stripes_;
};

}  // namespace lc::farm
