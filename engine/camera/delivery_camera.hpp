#pragma once
// How a shot is delivered (camera/delivery.hpp): through its own camera, a
// dome master's, a 360-degree one's or omnidirectional stereo's, with the
// dome's geometry and the eyes' separation, and under its own sky or the
// real one.  Apart from delivery.hpp so that the farm's journal names it
// without the camera and sky registries.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace lc {

enum class DeliveryCamera { shot, dome, sphere, ods };
constexpr std::array<std::string_view, 4> choice_names(DeliveryCamera) { return {"shot", "dome", "360", "ods"}; }
inline std::string_view name_of(DeliveryCamera d) { return choice_names(d)[static_cast<std::size_t>(d)]; }
// "shot", "dome", "360" or "ods" -> the camera; nullopt for another name.
inline std::optional<DeliveryCamera> delivery_named(std::string_view name) {
  for (const DeliveryCamera d : {DeliveryCamera::shot, DeliveryCamera::dome, DeliveryCamera::sphere, DeliveryCamera::ods})
    if (name == name_of(d)) return d;
  return std::nullopt;
}

// The sky a shot is delivered under: its own, or KStars' real stars in its
// place (render --sky kstars; docs/cameras.md says which skies give way).
enum class DeliverySky { shot, kstars };
constexpr std::array<std::string_view, 2> choice_names(DeliverySky) { return {"shot", "kstars"}; }
inline std::string_view name_of(DeliverySky s) { return choice_names(s)[static_cast<std::size_t>(s)]; }

// The defaults of the delivery's numbers (render --dome-tilt,
// --dome-elevation, --separation), in one place.
inline constexpr double default_dome_tilt = 0.0;        // degrees: a level dome
inline constexpr double default_dome_elevation = 35.0;  // degrees above the front horizon: the seated sweet spot
inline constexpr double default_ods_separation = 1.0;   // M: the equirect's own default (checked in delivery.hpp)
inline constexpr double max_dome_angle = 90.0;          // degrees: both angles from 0 (level, horizon) to this

// Everything the command line says of a delivery.  The numbers are held
// at their defaults where they do not apply (a tilt without a dome), so
// two deliveries that give the same frames compare equal.
struct Delivery {
  DeliveryCamera camera = DeliveryCamera::shot;
  double dome_tilt = default_dome_tilt;            // the dome's forward tilt, degrees (dome)
  double dome_elevation = default_dome_elevation;  // the shot's subject above the front horizon, degrees (dome)
  double separation = default_ods_separation;      // between the eyes, M (ods)
  DeliverySky sky = DeliverySky::shot;
  bool operator==(const Delivery&) const = default;
  // Whether anything beyond the camera's kind differs from the defaults
  // (what older journals and digests did not record).
  bool beyond_camera() const {
    return dome_tilt != default_dome_tilt || dome_elevation != default_dome_elevation ||
           separation != default_ods_separation || sky != DeliverySky::shot;
  }
};

// The frame size for `to` when none is given: the shot's own for the
// shot's camera, else square (dome), 2:1 (360) or two 2:1 pictures one
// above the other (ods) of the shot's height.
inline std::pair<int, int> delivery_size(DeliveryCamera to, int width, int height) {
  switch (to) {
    case DeliveryCamera::shot: return {width, height};
    case DeliveryCamera::dome: return {height, height};
    case DeliveryCamera::sphere: return {2 * height, height};
    case DeliveryCamera::ods: return {2 * height, 2 * height};
  }
  return {width, height};
}

}  // namespace lc
