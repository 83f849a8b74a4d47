#include "stars/star_field.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "light/light.hpp"

namespace lc {

namespace {

float luminance_of(const Color& c) { return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]; }

// The stars' directions, each checked with its light first: the bins index
// cells by the direction's angles, so a NaN one must never reach them (a
// NaN from a catalogue line crashed the render there, issue #25).
std::vector<Vec3> checked_directions(const std::vector<PointStar>& stars) {
  std::vector<Vec3> out;
  out.reserve(stars.size());
  for (std::size_t k = 0; k < stars.size(); ++k) {
    const PointStar& s = stars[k];
    const double n = std::sqrt(dot3(s.direction, s.direction));
    if (!(std::abs(n - 1.0) < 1e-9))
      throw std::invalid_argument(fmt::format("star field: star {} of {} has the direction ({:g}, {:g}, {:g}), not a "
                                              "unit vector",
                                              k + 1, stars.size(), s.direction[0], s.direction[1], s.direction[2]));
    for (const float f : s.flux)
      if (!(f >= 0.0f) || !std::isfinite(f))
        throw std::invalid_argument(fmt::format("star field: star {} of {} has the light ({:g}, {:g}, {:g}): negative or "
                                                "not finite (a catalogue's readers refuse such a star with its line)",
                                                k + 1, stars.size(), s.flux[0], s.flux[1], s.flux[2]));
    out.push_back(s.direction);
  }
  return out;
}

// Cells about 1 degree wide: a frame's quads cover far less, so a lookup
// visits a cell or four; the sky holds ~41,000 of them.
constexpr double bin_size = 1.0 * degree;

}  // namespace

StarField::StarField(std::vector<PointStar> stars, std::shared_ptr<const BlackbodyColors> colors,
                     std::shared_ptr<const SpectralShift> spectra)
    : stars_(std::move(stars)), bins_(checked_directions(stars_), bin_size), colors_(std::move(colors)),
      spectra_(std::move(spectra)) {
  blackbody_scale_.assign(stars_.size(), 0.0f);
  luminance_.assign(stars_.size(), 0.0f);
  for (std::size_t k = 0; k < stars_.size(); ++k) {
    const PointStar& s = stars_[k];
    luminance_[k] = luminance_of(s.flux);
    faintest_ = k == 0 ? luminance_[k] : std::min(faintest_, static_cast<double>(luminance_[k]));
    if (s.temperature > 0.0) {
      if (!colors_) throw std::invalid_argument("star field: stars with temperatures need blackbody colours");
      const float y = luminance_of((*colors_)(s.temperature));
      blackbody_scale_[k] = y > 0.0f ? luminance_of(s.flux) / y : 0.0f;
    }
  }
}

Color StarField::seen(std::size_t k, float color, float beaming) const {
  const PointStar& s = stars_[k];
  if (color == 1.0f && beaming == 1.0f) return s.flux;
  const SeenShift shift{color, beaming, spectra_.get()};
  if (s.temperature <= 0.0) return shift.texture(s.flux);
  Color c = (*colors_)(color * s.temperature);
  const float k_scale = blackbody_scale_[k] * shift.extra_beaming();
  for (float& v : c) v *= k_scale;
  return c;
}

std::size_t StarField::bytes() const {
  return stars_.size() * (sizeof(PointStar) + 2 * sizeof(float)) + bins_.bytes();
}

}  // namespace lc
