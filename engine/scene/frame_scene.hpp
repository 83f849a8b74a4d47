#pragma once
// The evaluated scene of one frame: plain data, read from the shot script and
// nothing else.  Positions are scene coordinates (Boyer–Lindquist for Kerr,
// Cartesian otherwise) with angles in radians; colours are linear RGB.
// Building a renderable Scene from it is render/scene.hpp's job.

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "core/color.hpp"
#include "objects/objects.hpp"
#include "sky/sky.hpp"
#include "core/tensor.hpp"
#include "scene/worldline_spec.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

enum class ObserverKind { static_observer, zamo, free_fall };

struct ObserverSpec {
  ObserverKind kind = ObserverKind::static_observer;
  Vec4 position{};  // static / zamo: the event (t is the scene time)
  std::optional<WorldlineSpec> worldline;  // free_fall
  double proper_time = 0.0;                // free_fall: where on the worldline
};

struct FrameScene {
  Spacetime spacetime = Minkowski{};
  ObserverSpec observer;
  CameraSpec camera;
  SkySpec sky;
  std::vector<ObjectSpec> objects;  // the scene's `disk`, then its `objects`
};

// Frame-independent settings of a shot.
struct ShotInfo {
  std::string name;
  int frames = 1;
  double fps = 30.0;
  int width = 640, height = 360;
  int supersample = 1;  // N x N samples per pixel
};

}  // namespace lc
