#include "sky/point_star_sky.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "assets/shot_resources.hpp"
#include "core/constants.hpp"
#include "image/generated_stars.hpp"
#include "sky/texture_sky.hpp"
#include "stars/star_catalogue.hpp"

namespace lc {

namespace {

// Whether a resolved background (PointStarSky::background) is an image the
// shot names.
bool is_image(const std::string& background) { return background != "generated" && background != "none"; }

// The generated field's glow is smooth: this width shows it whole.
constexpr int glow_width = 2048;

// At most this many stars are read from a catalogue (KStars' holds 125,982).
constexpr std::size_t max_catalogue_stars = 1'000'000;

// The light of a star of magnitude v, before `brightness`.
double flux_of_magnitude(double v) { return star_flux_v0 * std::pow(10.0, -0.4 * v); }

Vec3 turned(const Vec3& d, double rotate) {
  const double c = std::cos(rotate * degree), s = std::sin(rotate * degree);
  return {c * d[0] - s * d[1], s * d[0] + c * d[1], d[2]};
}

// The generated field's stars: each one's light is its texture rendering's
// (image/generated_stars.hpp), shifted as a texture's colour.
StarField generated_stars(const PointStarSky::Params& p, ShotResources& res) {
  std::vector<PointStar> out;
  const double scale = std::exp2(p.brightness);
  for (const Star& s : starfield_catalogue(p.seed)) {
    const double flux = two_pi * s.sigma * s.sigma * s.peak;
    if (-2.5 * std::log10(flux / star_flux_v0) > p.faintest) continue;
    PointStar star{turned(unit3({s.direction[0], s.direction[1], s.direction[2]}), -p.rotate), {}, 0.0};
    for (int c = 0; c < 3; ++c) star.flux[c] = static_cast<float>(scale * flux * s.tint[static_cast<std::size_t>(c)]);
    out.push_back(star);
  }
  return StarField(std::move(out), nullptr, res.spectral_shift());
}

// KStars' stars: blackbodies at their B - V's temperature, of luminance
// their V's light.
StarField kstars_stars(const PointStarSky::Params& p, ShotResources& res) {
  const auto read = read_star_catalogue(kstars_catalogue_path(), p.faintest, max_catalogue_stars);
  auto colors = res.blackbody_colors(5800.0);
  std::vector<PointStar> out;
  out.reserve(read.size());
  const double scale = std::exp2(p.brightness);
  for (const CatalogueStar& s : read) {
    const double t = star_temperature(s.b_v);
    const Color c = (*colors)(t);
    const double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    const double k = scale * flux_of_magnitude(s.v_mag) / y;
    const double cd = std::cos(s.dec);
    PointStar star{turned({cd * std::cos(s.ra), cd * std::sin(s.ra), std::sin(s.dec)}, -p.rotate), {}, t};
    for (int m = 0; m < 3; ++m) star.flux[m] = static_cast<float>(k * c[m]);
    out.push_back(star);
  }
  return StarField(std::move(out), colors, res.spectral_shift());
}

}  // namespace

std::string kstars_catalogue_path() {
  const char* set = std::getenv("LIGHTCONE_STAR_CATALOGUE");
  return set && *set ? std::string(set) : std::string(kstars_catalogue_file);
}

// The generated glow belongs to the generated field's stars: behind the
// real sky's it would be a Milky Way in the wrong place, so the real sky's
// default is black (docs/stars.md says why no real Milky Way is the default).
std::string PointStarSky::background(const Params& p) {
  if (p.background != "auto") return p.background;
  return p.catalogue == StarCatalogue::generated ? "generated" : "none";
}

std::vector<std::string> PointStarSky::assets(const Params& p) {
  if (const std::string b = background(p); is_image(b)) return {b};
  return {};
}

std::vector<std::string> PointStarSky::system_files(const Params& p) {
  if (p.catalogue == StarCatalogue::kstars) return {kstars_catalogue_path()};
  return {};
}

PointStarSky::Params PointStarSky::real_stars(const Params& p) {
  Params real = p;
  real.catalogue = StarCatalogue::kstars;
  if (real.background == "generated") real.background = "none";
  return real;
}

void PointStarSky::Params::validate() const {
  if (catalogue == StarCatalogue::kstars) {
    const std::string file = kstars_catalogue_path();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      throw std::invalid_argument(fmt::format(
          "catalogue = \"kstars\" reads {}, which is not {}: install Debian's kstars-data (sudo apt-get "
          "install kstars-data), or use catalogue = \"generated\" (docs/stars.md)",
          file, std::filesystem::exists(file, ec) ? "a regular file" : "there"));
  }
}

// The stars are made once per shot for each catalogue, limit, seed, turn
// and brightness (ShotResources); a catalogue that does not parse is an
// error naming its file and line.
PointStars PointStarSky::stars(const Params& p, ShotResources& res) {
  const std::string key = fmt::format("{} {:a} {} {:a} {:a}", choice_name(p.catalogue), p.faintest, p.seed, p.rotate,
                                      p.brightness);
  PointStars out;
  out.field = res.star_field(key, [&] {
    if (p.catalogue == StarCatalogue::kstars) {
      try {
        return kstars_stars(p, res);
      } catch (const CatalogueError& e) {
        throw std::invalid_argument(fmt::format("starfield: the catalogue does not read: {}", e.what()));
      }
    }
    return generated_stars(p, res);
  });
  out.glare = p.glare;
  out.glare_size = p.glare_size;
  return out;
}

PointStarSky::PointStarSky(const Params& p, ShotResources& res)
    : rotate_(p.rotate), scale_(brightness_scale(p.brightness)), stars_(stars(p, res)) {
  const std::string b = background(p);
  if (b == "generated")
    background_ = res.sky_glow(p.seed, glow_width);
  else if (is_image(b))
    background_ = res.texture(b);
}

Color PointStarSky::color(double theta, double phi) const {
  if (!background_) return {0.0f, 0.0f, 0.0f};
  Color c;
  background_->sample(rotated_longitude(phi, rotate_) / two_pi, theta / pi, c.data());
  return scaled(c, scale_);
}

}  // namespace lc
