#pragma once
// The list of camera kinds' parameters, one line each, in the order of the
// cameras' registry (camera/camera_registry.hpp, which checks the two lists
// agree): the variant a CameraSpec holds (camera/camera_spec.hpp).  Only
// what visits every camera kind — reads, keys, describes or builds one —
// includes this list (docs/architecture.md, "What a new kind rebuilds").

#include "camera/camera_spec.hpp"
#include "camera/equirect_params.hpp"
#include "camera/fisheye_params.hpp"
#include "camera/pinhole_params.hpp"
#include "core/registry.hpp"

namespace lc {

// Every camera kind's parameters, one line each.
using CameraSpecs = SpecRegistry<PinholeParams, FisheyeParams, EquirectParams>;

// The variant itself, as a class so that camera/camera_spec.hpp can name
// it before the list.
struct CameraSpecKinds : CameraSpecs::Spec {
  using Specs = CameraSpecs;
  using CameraSpecs::Spec::Spec;
  CameraSpecKinds() = default;
  CameraSpecKinds(const CameraSpecs::Spec& spec) : CameraSpecs::Spec(spec) {}
};

}  // namespace lc
