#pragma once
// Which camera a shot is delivered through (camera/delivery.hpp): its own,
// a dome master's or a 360-degree one.  Apart from delivery.hpp so that the
// farm's journal names it without the camera registry.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace lc {

enum class DeliveryCamera { shot, dome, sphere };
constexpr std::array<std::string_view, 3> choice_names(DeliveryCamera) { return {"shot", "dome", "360"}; }
inline std::string_view name_of(DeliveryCamera d) { return choice_names(d)[static_cast<std::size_t>(d)]; }
// "shot", "dome" or "360" -> the camera; nullopt for another name.
inline std::optional<DeliveryCamera> delivery_named(std::string_view name) {
  for (const DeliveryCamera d : {DeliveryCamera::shot, DeliveryCamera::dome, DeliveryCamera::sphere})
    if (name == name_of(d)) return d;
  return std::nullopt;
}

}  // namespace lc
