#include "camera/camera_spec.hpp"

#include <variant>

#include "camera/camera_params.hpp"
#include "core/spec_box_impl.hpp"

namespace lc {

// The box's members, its name, key and JSON, and for each camera kind how a
// box is made from its parameters and read back: one line per kind, as
// camera/camera_params.hpp lists them.  A kind missing here is a link error
// naming SpecAccess<CameraSpecKinds, ItsParams>.
template class SpecBox<CameraSpecKinds>;
template std::string_view kind_name(const CameraSpec&);
template std::string kind_key(const CameraSpec&);
template std::string kind_json(const CameraSpec&, bool);
template struct SpecAccess<CameraSpecKinds, PinholeParams>;
template struct SpecAccess<CameraSpecKinds, FisheyeParams>;
template struct SpecAccess<CameraSpecKinds, EquirectParams>;

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
