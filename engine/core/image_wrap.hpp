#pragma once
// Where an image continues past its own edges: an equirectangular frame of
// the whole sphere is one picture around (its left and right edges are the
// same meridian) and over the poles (above its top row, the same row half
// a turn away).  The camera says so (camera/camera.hpp); what looks across
// an edge at neighbouring pixels uses it: adaptive supersampling's row
// neighbours (render/pixel_rows.hpp) and the point-star stage's grid of
// rays and its tent filter (stars/ray_grid.hpp, stars/pixel_deposits.hpp).

namespace lc {

struct ImageWrap {
  // Column -1 is column W-1 and column W is column 0 (a full turn across).
  bool columns = false;
  // Above row 0 lies row 0 half a turn away, below row H-1 row H-1 half a
  // turn away, and the pole itself on the edge between (only with columns,
  // and an even width, so that half a turn is a whole number of pixels).
  bool poles = false;
  bool operator==(const ImageWrap&) const = default;
};

}  // namespace lc
