#pragma once
// The camera a shot asked for (lc.<name>{...}): one of the registered
// cameras' parameters, one line each below, in the order of the cameras'
// registry (camera/camera.hpp, which checks the two lists agree).  What
// holds, reads, keys or describes a camera spec includes this header, not
// the cameras' code (docs/architecture.md, "What a new kind rebuilds").

#include "camera/equirect_params.hpp"
#include "camera/fisheye_params.hpp"
#include "camera/pinhole_params.hpp"
#include "core/registry.hpp"

namespace lc {

// Every camera kind's parameters, one line each.
using CameraSpecs = SpecRegistry<PinholeParams, FisheyeParams, EquirectParams>;

using CameraSpec = CameraSpecs::Spec;

}  // namespace lc
