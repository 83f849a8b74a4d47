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
#include "sky/sky.hpp"
#include "core/tensor.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

// A free-falling worldline: a timelike geodesic from `start` (scene
// coordinates) with 3-velocity `velocity` relative to the static observer
// there (components on e_r, e_theta, e_phi or e_x, e_y, e_z; units of c),
// integrated for `duration` of proper time.  Identical specs within a shot
// share one integration.
struct WorldlineSpec {
  Spacetime spacetime = Minkowski{};
  Vec4 start{};
  Vec3 velocity{};
  double duration = 0.0;
  std::string where;  // "shot.lua:12", where the script made it

  // Exact textual key of the parameters, for sharing integrations.
  std::string key() const;
};

enum class ObserverKind { static_observer, zamo, free_fall };

struct ObserverSpec {
  ObserverKind kind = ObserverKind::static_observer;
  Vec4 position{};  // static / zamo: the event (t is the scene time)
  std::optional<WorldlineSpec> worldline;  // free_fall
  double proper_time = 0.0;                // free_fall: where on the worldline
};

// Thin equatorial disk, checkered in Boyer–Lindquist r and phi.
struct DiskSpec {
  double inner = 6.0, outer = 20.0;
  int rings = 7, sectors = 24;
  Color color_a = {1.0f, 0.55f, 0.15f}, color_b = {0.35f, 0.12f, 0.03f};
};

// A checkered sphere of proper radius `radius` in the local frame of a
// tetrad: held at rest at `position`, or free-falling along `worldline`.
struct SphereSpec {
  double radius = 1.0;
  std::optional<Vec4> position;
  std::optional<WorldlineSpec> worldline;
  int rows = 8, columns = 16;
  Color color_a = {0.95f, 0.95f, 0.95f}, color_b = {0.8f, 0.1f, 0.1f};
};

struct FrameScene {
  Spacetime spacetime = Minkowski{};
  ObserverSpec observer;
  CameraSpec camera;
  std::optional<DiskSpec> disk;
  SkySpec sky;
  std::vector<SphereSpec> spheres;
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
