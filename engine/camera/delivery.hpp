#pragma once
// A shot made for a flat screen, delivered to another (render --camera,
// showcase --camera; docs/cameras.md, "A shot through a dome or a 360
// camera"): its frames through a dome master, a 360-degree camera or
// omnidirectional stereo in place of its own, framed from its own camera's
// orientation (the sky it is delivered under: scene/delivered_sky.hpp).
//   dome: the 180-degree fisheye, its axis pitched 90 - E above the shot's
//         aim, so what the shot looked at sits E degrees (dome_elevation,
//         35 by default) above the dome's front horizon, the sweet spot a
//         seated audience looks at without craning (not the zenith); a
//         tilted dome's tilt is the fisheye's own `tilt`, which keeps that
//         height above the audience's horizon;
//   360:  the whole sphere, its front the shot's heading (yaw) but its
//         horizon level (no pitch, no roll: a viewer in a headset chooses
//         where to look, and a sphere that tilts under them is sickening);
//   ods:  the 360's sphere in omnidirectional stereo (top-bottom), the eyes
//         `separation` apart.
// Square frames for the dome and ODS, 2:1 for the sphere, of the shot's
// height (ODS: each eye's 2:1 picture of it) unless a size is given.

#include "camera/camera_spec.hpp"
#include "camera/delivery_camera.hpp"

namespace lc {

// The camera `shot_camera` (any kind) is delivered through.  Assumes the
// delivery's angles are in range (the command line checks them).
CameraSpec delivered(const CameraSpec& shot_camera, const Delivery& to);

}  // namespace lc
