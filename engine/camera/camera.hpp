#pragma once
// The registry of cameras: every kind lightcone knows, one line each in
// the variant below, each a class satisfying CameraModel in its own file.
// A camera maps an image point to a direction in the observer's frame; the
// scene holds the parameters a shot gave (CameraSpec: lc.<name>{...}), the
// built scene the camera for its image size (Camera).

#include <array>
#include <concepts>
#include <string_view>
#include <type_traits>
#include <variant>

#include "camera/camera_axes.hpp"
#include "camera/pinhole.hpp"
#include "core/fields.hpp"

namespace lc {

// What a camera is: name (its Lua constructor lc.<name>{...}), Params with
// declared fields, a constructor from them and the image size, the
// direction (unit, on the tetrad's legs) through image point (px, py) in
// pixel units, and its axes (for reports).
template <class C>
concept CameraModel = requires(const C& c, const typename C::Params& p, double px) {
  requires std::same_as<std::remove_cv_t<decltype(C::name)>, std::string_view>;
  requires HasFields<typename C::Params>;
  C(p, 1, 1);
  { c.direction(px, px) } -> std::same_as<Vec3>;
  { c.axes() } -> std::same_as<const CameraAxes&>;
};

using CameraKinds = std::variant<PinholeCamera>;

namespace detail {
template <class V>
struct CameraRegistry;
template <class... C>
struct CameraRegistry<std::variant<C...>> {
  static_assert((CameraModel<C> && ...), "every registered camera must satisfy CameraModel");
  using Spec = std::variant<typename C::Params...>;
};
}  // namespace detail

// The camera a shot asked for: one of the registered kinds' parameters.
using CameraSpec = detail::CameraRegistry<CameraKinds>::Spec;

// The name of the kind a spec is for ("camera": lc.camera{...}).
inline std::string_view camera_name(const CameraSpec& spec) {
  static constexpr auto names = []<class... C>(std::variant<C...>*) {
    return std::array<std::string_view, sizeof...(C)>{C::name...};
  }(static_cast<CameraKinds*>(nullptr));
  return names[spec.index()];
}

// f(TypeTag-like) for each registered camera kind C: f(static_cast<C*>(nullptr)).
template <class F>
void for_each_camera_type(F&& f) {
  [&]<class... C>(std::variant<C...>*) { (f(static_cast<C*>(nullptr)), ...); }(static_cast<CameraKinds*>(nullptr));
}

// The camera of a frame, for its image size.
class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height) : kind_(build(spec, width, height)) {}

  Vec3 direction(double px, double py) const {
    return std::visit([&](const auto& c) { return c.direction(px, py); }, kind_);
  }
  const CameraAxes& axes() const {
    return std::visit([](const auto& c) -> const CameraAxes& { return c.axes(); }, kind_);
  }

 private:
  // The kind whose parameters the spec holds (same position in both variants).
  template <std::size_t I = 0>
  static CameraKinds build(const CameraSpec& spec, int width, int height) {
    using C = std::variant_alternative_t<I, CameraKinds>;
    if constexpr (I + 1 < std::variant_size_v<CameraKinds>)
      if (spec.index() != I) return build<I + 1>(spec, width, height);
    return C(std::get<I>(spec), width, height);
  }
  CameraKinds kind_;
};

}  // namespace lc
