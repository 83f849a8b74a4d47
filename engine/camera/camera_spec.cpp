#include "camera/camera_spec.hpp"

#include <variant>

#include "camera/camera_params.hpp"
#include "core/spec_box_impl.hpp"

namespace lc {

// The box's members, and for each camera kind how a box is made from its
// parameters and read back: one line per kind, as camera/camera_params.hpp
// lists them.  A kind missing here is a link error naming
// SpecAccess<CameraSpecKinds, ItsParams>.
template class SpecBox<CameraSpecKinds>;
template struct SpecAccess<CameraSpecKinds, PinholeParams>;
template struct SpecAccess<CameraSpecKinds, FisheyeParams>;
template struct SpecAccess<CameraSpecKinds, EquirectParams>;

std::string_view camera_name(const CameraSpec& spec) { return CameraSpecs::name(spec.kinds()); }

std::string camera_key(const CameraSpec& spec) { return CameraSpecs::key(spec.kinds()); }

std::string camera_json(const CameraSpec& spec) { return CameraSpecs::json(spec.kinds()); }

double stereo_separation(const CameraSpec& spec) {
  return std::visit(
      [](const auto& c) {
        if constexpr (requires { c.separation; })
          return c.separation;
        else
          return 0.0;
      },
      spec.kinds());
}

}  // namespace lc
