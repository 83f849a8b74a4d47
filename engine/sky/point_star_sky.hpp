#pragma once
// lc.starfield{...}: stars as points (docs/stars.md), drawn by the star
// pass after the pixels (stars/star_pass.hpp) from the rays' directions at
// infinity, so they stay sharp at any field of view and are lensed as
// points are, over a diffuse background each ray looks up as a texture.
// The stars come from the generated field (image/generated_stars.hpp: the same
// catalogue as lc.sky_stars{}, its Milky-Way-like band included) or from
// KStars' catalogue of Hipparcos and Tycho stars as Debian's kstars-data
// installs it (read there, never shipped: it is GPL data).

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/color.hpp"
#include "core/fields.hpp"
#include "image/texture.hpp"
#include "stars/star_field.hpp"
#include "stars/star_pass.hpp"

namespace lc {

class ShotResources;

enum class StarCatalogue { generated, kstars };
constexpr std::array<std::string_view, 2> choice_names(StarCatalogue) { return {"generated", "kstars"}; }

// Where KStars' catalogue is read from: Debian's kstars-data installs it
// here; the environment variable LIGHTCONE_STAR_CATALOGUE names another
// file of its format (docs/stars.md).
inline constexpr std::string_view kstars_catalogue_file = "/usr/share/kstars/stars.dat";
std::string kstars_catalogue_path();

// The light of a star of magnitude V = 0, before `brightness`: a pixel of
// 1e-6 sr holding all of it shows 300 (linear).  The generated field's
// brightest stars are about this bright.
inline constexpr double star_flux_v0 = 3e-4;

// A sky's point stars as the star pass takes them.
struct PointStars {
  std::shared_ptr<const StarField> field;
  double glare = 0.0;       // share of each star's light in the halo
  double glare_size = 0.0;  // the halo's scale, as a fraction of the frame's height
};

class PointStarSky {
 public:
  static constexpr std::string_view name = "starfield";
  struct Params {
    StarCatalogue catalogue = StarCatalogue::generated;
    double faintest = 8.0;
    std::uint32_t seed = 1;
    std::string background = "auto";
    double rotate = 0.0, brightness = 0.0, glare = 0.1, glare_size = 0.002;
    static constexpr auto fields = std::tuple{
        field("catalogue", &Params::catalogue, std::optional<StarCatalogue>{StarCatalogue::generated}, std::nullopt,
              std::nullopt,
              "generated: the procedural field of `seed` (~7,000 stars and a Milky-Way-like band); kstars: the real "
              "sky's Hipparcos and Tycho stars to V = 9, J2000 (the equator's pole on +z, right ascension 0 on +x), "
              "from /usr/share/kstars/stars.dat (Debian's kstars-data) or the file LIGHTCONE_STAR_CATALOGUE names"),
        field("faintest", &Params::faintest, std::optional<double>{8.0}, at_least(-2.0), at_most(12.0),
              "the faintest stars drawn", "magnitudes (V)"),
        field("seed", &Params::seed, std::optional<std::uint32_t>{1}, at_least(0), at_most(2147483647),
              "the generated field's seed (its stars and its band's glow)"),
        field("background", &Params::background, std::optional<std::string_view>{"auto"}, std::nullopt,
              std::nullopt,
              "the diffuse light behind the stars: \"generated\" (the glow of the generated field's Milky-Way-like "
              "band, for `seed`), \"none\", or an equirectangular image (a file, as lc.sky_image's); \"auto\": "
              "\"generated\" for the generated catalogue, \"none\" for kstars (whose sky the band is not: "
              "docs/stars.md)"),
        field("rotate", &Params::rotate, std::optional<double>{0.0}, std::nullopt, std::nullopt,
              "added to the longitude of the stars and the background", "degrees"),
        field("brightness", &Params::brightness, std::optional<double>{0.0}, at_least(-64.0), at_most(64.0),
              "the stars' and the background's light times 2^brightness (for scenes in physical units: "
              "docs/light.md)",
              "stops"),
        field("glare", &Params::glare, std::optional<double>{0.1}, at_least(0.0), at_most(1.0),
              "the share of each star's light spread into a halo around it, so bright stars read as stars (0: none)"),
        field("glare_size", &Params::glare_size, std::optional<double>{0.002}, above(0.0), at_most(0.05),
              "the halo's scale (it reaches 8 times as far)", "of the frame's height"),
    };
    // The catalogue must be there to be read: checked where the shot names
    // it.  Throws std::invalid_argument.
    void validate() const;
  };
  // The image a frame with this sky reads, if its background is one (the
  // KStars catalogue is the system's, not the shot's).
  static std::vector<std::string> assets(const Params& p);
  // The KStars catalogue, when the stars are read from it.
  static std::vector<std::string> system_files(const Params& p);
  // What render --sky kstars delivers this sky as (every sky kind has one:
  // SkyModel): every field but the catalogue kept, a "generated" background
  // becoming "none", since the generated field's band is not the real
  // Milky Way.
  static Params real_stars(const Params& p);
  // What p.background stands for: "generated", "none" or an image's file
  // ("auto" resolved by the catalogue).
  static std::string background(const Params& p);

  PointStarSky(const Params& p, ShotResources& res);
  // The stars alone, as the stage after the pixels needs them (without the
  // background, which only the rays look up).
  static PointStars stars(const Params& p, ShotResources& res);

  // The background in the direction (theta from +z, phi = atan2(y, x)).
  Color color(double theta, double phi) const;
  const PointStars& point_stars() const { return stars_; }

 private:
  double rotate_;
  float scale_;
  std::shared_ptr<const Texture> background_;  // none: black
  PointStars stars_;
};

// The real stars (KStars' catalogue) at `rotate` degrees and `brightness`
// stops, the rest defaults: what render --sky kstars makes of the skies
// that only stand in for one (the generated stars, the checker).
inline PointStarSky::Params real_stars_at(double rotate, double brightness) {
  PointStarSky::Params real;
  real.catalogue = StarCatalogue::kstars;
  real.rotate = rotate;
  real.brightness = brightness;
  return real;
}

}  // namespace lc
