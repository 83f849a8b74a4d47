#pragma once
// The sky a shot is delivered under (render --sky; docs/cameras.md, "A shot
// through a dome or a 360 camera"): its own, or KStars' real stars in its
// place.  Here, above both the cameras and the skies, beside the delivery's
// camera (camera/delivery.hpp).

#include <optional>
#include <type_traits>
#include <variant>

#include "camera/delivery_camera.hpp"
#include "sky/sky.hpp"

namespace lc {

// The sky `shot_sky` is delivered under: with kstars, what its kind's
// real_stars(params) makes of it (sky/sky.hpp, SkyModel: a kind without
// one does not compile).  Throws std::invalid_argument where the kind says
// it cannot be (an image: sky/image_sky.hpp).
inline SkySpec delivered_sky(const SkySpec& shot_sky, DeliverySky to) {
  if (to == DeliverySky::shot) return shot_sky;
  return std::visit(
      [](const auto& p) -> SkySpec {
        std::optional<PointStarSky::Params> real;
        SkyRegistry::for_each([&](auto* kind) {
          using K = std::remove_pointer_t<decltype(kind)>;
          if constexpr (std::is_same_v<typename K::Params, std::decay_t<decltype(p)>>) real = K::real_stars(p);
        });
        return *real;  // every Params is one kind's
      },
      shot_sky);
}

}  // namespace lc
