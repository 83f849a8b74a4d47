#pragma once
// Where a camera ray that reached the sky went, for stars drawn as points
// after the pixels (stars/star_pass.hpp): its direction at infinity, how
// the frame's light model sees light from there, and where in its pixel
// the ray passed.

namespace lc {

struct SkyPoint {
  // Direction at infinity: theta from +z, phi in [0, 2 pi).  theta < 0:
  // the ray did not reach the sky (it met the disk, an object, the horizon
  // or gave up).  Doubles: neighbouring rays' directions differ by a pixel,
  // and lensed stars' magnifications come from those differences.
  double theta = -1.0, phi = 0.0;
  // The ratios light/light.hpp's SeenShift applies to the sky's light there
  // (1 for the geometric model).
  float color = 1.0f, beaming = 1.0f;
  // The ray's point in its pixel, in pixel units from the pixel's top-left
  // corner (the renderer fills it).
  float dx = 0.5f, dy = 0.5f;

  bool reached() const { return theta >= 0.0; }
};

}  // namespace lc
