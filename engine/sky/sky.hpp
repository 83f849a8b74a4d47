#pragma once
// The registry of skies: every kind lightcone knows, one line each in the
// variant below, each a class satisfying SkyModel in its own file.  A sky
// is what an escaping ray sees: a colour for the direction it leaves in.
// The scene holds the parameters a shot gave (SkySpec: lc.<name>{...}), the
// built scene the sky with what it loaded (Sky).

#include <array>
#include <optional>
#include <concepts>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/color.hpp"
#include "core/fields.hpp"
#include "core/registry.hpp"
#include "sky/checker_sky.hpp"
#include "sky/image_sky.hpp"
#include "sky/point_star_sky.hpp"
#include "sky/star_image_sky.hpp"

namespace lc {

class ShotResources;

// What a sky is: name (its Lua constructor lc.<name>{...}), Params with
// declared fields, assets(params) (the files it reads, for a shot's input
// hash), a constructor from the parameters and the shot's resources, and
// the colour for a direction (theta from +z, phi = atan2(y, x)); a sky with
// stars as points also has point_stars() (sky/point_star_sky.hpp), and one
// that reads a file of the system's (not the shot's: a star catalogue) has
// a static system_files(params) naming it by absolute path.  Each says what
// render --sky kstars delivers it as: a static real_stars(params), the
// real stars' parameters (scene/delivered_sky.hpp), or throwing
// std::invalid_argument saying why it cannot be.
template <class K>
concept SkyModel = requires(const K& k, const typename K::Params& p, ShotResources& res, double a) {
  requires std::same_as<std::remove_cv_t<decltype(K::name)>, std::string_view>;
  requires HasFields<typename K::Params>;
  { K::assets(p) } -> std::same_as<std::vector<std::string>>;
  { K::real_stars(p) } -> std::same_as<PointStarSky::Params>;
  K(p, res);
  { k.color(a, a) } -> std::same_as<Color>;
};

// Every sky kind, one line each.
using SkyRegistry = Registry<CheckerSky, ImageSky, StarImageSky, PointStarSky>;

// One assertion per sky: the compiler's notes name the one that fails and
// the requirement it misses.
static_assert(every_kind<SkyRegistry>([]<class K>() {
  static_assert(SkyModel<K>, "a registered sky must satisfy SkyModel");
}));

// The sky a shot asked for: one of the registered kinds' parameters.
using SkySpec = SkyRegistry::Spec;

// The files a sky reads (for a shot's input hash).
inline std::vector<std::string> sky_assets(const SkySpec& spec) {
  return std::visit(
      [](const auto& p) {
        std::vector<std::string> out;
        SkyRegistry::for_each([&](auto* kind) {
          using K = std::remove_pointer_t<decltype(kind)>;
          if constexpr (std::is_same_v<typename K::Params, std::decay_t<decltype(p)>>) out = K::assets(p);
        });
        return out;
      },
      spec);
}

// The files of the system's that a sky reads (absolute paths), for a shot's
// input hash beside its own assets: the frames change when these change.
inline std::vector<std::string> sky_system_files(const SkySpec& spec) {
  std::vector<std::string> out;
  SkyRegistry::for_each([&](auto* kind) {
    using K = std::remove_pointer_t<decltype(kind)>;
    if constexpr (requires(const typename K::Params& p) { K::system_files(p); })
      if (const auto* p = std::get_if<typename K::Params>(&spec)) out = K::system_files(*p);
  });
  return out;
}

// Whether the sky `spec` has point stars (drawn by the stage after the
// pixels, on pictures of at least 2x2: stars/star_pass.hpp), without
// reading them.
inline bool has_point_stars(const SkySpec& spec) {
  bool out = false;
  SkyRegistry::for_each([&](auto* kind) {
    using K = std::remove_pointer_t<decltype(kind)>;
    if constexpr (requires(const typename K::Params& p, ShotResources& res) { K::stars(p, res); })
      out = out || std::holds_alternative<typename K::Params>(spec);
  });
  return out;
}

// The point stars of the sky `spec` (without building the rest of it: the
// stage after the pixels needs only them), if it has any.
inline std::optional<PointStars> sky_point_stars(const SkySpec& spec, ShotResources& res) {
  std::optional<PointStars> out;
  SkyRegistry::for_each([&](auto* kind) {
    using K = std::remove_pointer_t<decltype(kind)>;
    if constexpr (requires(const typename K::Params& p) { K::stars(p, res); })
      if (const auto* p = std::get_if<typename K::Params>(&spec)) out = K::stars(*p, res);
  });
  return out;
}

// The sky of a frame, built.
class Sky {
 public:
  Sky(const SkySpec& spec, ShotResources& res) : kind_(SkyRegistry::build(spec, res)) {}

  // Colour in the direction (theta from +z, phi = atan2(y, x)).
  Color color(double theta, double phi) const {
    return std::visit([&](const auto& k) { return k.color(theta, phi); }, kind_);
  }
  // Its stars drawn as points after the pixels, if it has any.
  const PointStars* point_stars() const {
    return std::visit(
        [](const auto& k) -> const PointStars* {
          if constexpr (requires { k.point_stars(); })
            return &k.point_stars();
          else
            return nullptr;
        },
        kind_);
  }

 private:
  SkyRegistry::Kinds kind_;
};

}  // namespace lc
