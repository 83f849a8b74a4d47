#pragma once
// The registry of skies: every kind lightcone knows, one line each in the
// variant below, each a class satisfying SkyModel in its own file.  A sky
// is what an escaping ray sees: a colour for the direction it leaves in.
// The scene holds the parameters a shot gave (SkySpec: lc.<name>{...}), the
// built scene the sky with what it loaded (Sky).

#include <array>
#include <concepts>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/color.hpp"
#include "core/fields.hpp"
#include "sky/checker_sky.hpp"
#include "sky/image_sky.hpp"
#include "sky/star_sky.hpp"

namespace lc {

class ShotResources;

// What a sky is: name (its Lua constructor lc.<name>{...}), Params with
// declared fields, assets(params) (the files it reads, for a shot's input
// hash), a constructor from the parameters and the shot's resources, and
// the colour for a direction (theta from +z, phi = atan2(y, x)).
template <class K>
concept SkyModel = requires(const K& k, const typename K::Params& p, ShotResources& res, double a) {
  requires std::same_as<std::remove_cv_t<decltype(K::name)>, std::string_view>;
  requires HasFields<typename K::Params>;
  { K::assets(p) } -> std::same_as<std::vector<std::string>>;
  K(p, res);
  { k.color(a, a) } -> std::same_as<Color>;
};

using SkyKinds = std::variant<CheckerSky, ImageSky, StarSky>;

namespace detail {
template <class V>
struct SkyRegistry;
template <class... K>
struct SkyRegistry<std::variant<K...>> {
  static_assert((SkyModel<K> && ...), "every registered sky must satisfy SkyModel");
  using Spec = std::variant<typename K::Params...>;
  static constexpr std::array<std::string_view, sizeof...(K)> names = {K::name...};
};
}  // namespace detail

// The sky a shot asked for: one of the registered kinds' parameters.
using SkySpec = detail::SkyRegistry<SkyKinds>::Spec;

// f(static_cast<K*>(nullptr)) for each registered sky kind K.
template <class F>
void for_each_sky_type(F&& f) {
  [&]<class... K>(std::variant<K...>*) { (f(static_cast<K*>(nullptr)), ...); }(static_cast<SkyKinds*>(nullptr));
}

// The name of the kind a spec is for ("sky_checker": lc.sky_checker{...}).
inline std::string_view sky_name(const SkySpec& spec) { return detail::SkyRegistry<SkyKinds>::names[spec.index()]; }

// The files a sky reads.
inline std::vector<std::string> sky_assets(const SkySpec& spec) {
  return [&]<class... K>(std::variant<K...>*) {
    std::vector<std::string> out;
    std::size_t i = 0;
    ((spec.index() == i++ ? (void)(out = K::assets(std::get<typename K::Params>(spec))) : void()), ...);
    return out;
  }(static_cast<SkyKinds*>(nullptr));
}

// The sky of a frame, built.
class Sky {
 public:
  Sky(const SkySpec& spec, ShotResources& res) : kind_(build(spec, res)) {}

  // Colour in the direction (theta from +z, phi = atan2(y, x)).
  Color color(double theta, double phi) const {
    return std::visit([&](const auto& k) { return k.color(theta, phi); }, kind_);
  }

 private:
  template <std::size_t I = 0>
  static SkyKinds build(const SkySpec& spec, ShotResources& res) {
    using K = std::variant_alternative_t<I, SkyKinds>;
    if constexpr (I + 1 < std::variant_size_v<SkyKinds>)
      if (spec.index() != I) return build<I + 1>(spec, res);
    return K(std::get<I>(spec), res);
  }
  SkyKinds kind_;
};

}  // namespace lc
