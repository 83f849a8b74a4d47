#pragma once
// A sky's stars as points, ready for the star pass (stars/star_pass.hpp):
// each star's direction and light, binned for lookups, and how its light
// is seen through a frame's light model (light/light.hpp): a star with a
// temperature is a blackbody, and a blackbody at T seen shifted by g is
// exactly one at g T (g^3 B_nu(nu / g; T) = B_nu(nu; g T)); a star without
// one is shifted as textures are (light/spectral_shift.hpp).

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "core/color.hpp"
#include "core/tensor.hpp"
#include "light/blackbody.hpp"
#include "light/spectral_shift.hpp"
#include "stars/star_bins.hpp"

namespace lc {

struct PointStar {
  Vec3 direction;            // unit vector on the sky (the trace chart's directions at infinity)
  Color flux;                // linear RGB, unshifted: a pixel of solid angle Omega holding it all shows flux / Omega
  double temperature = 0.0;  // K: seen as a blackbody when shifted; 0: shifted as a texture's colour
};

class StarField {
 public:
  // colors: blackbody colours (any reference), needed when a star has a
  // temperature; spectra: the texture spectra.  Either may be null when no
  // star needs it.  Throws std::invalid_argument naming the star for one
  // whose direction is not a unit vector (NaN included) or whose flux is
  // negative or not finite, before anything is binned.
  StarField(std::vector<PointStar> stars, std::shared_ptr<const BlackbodyColors> colors,
            std::shared_ptr<const SpectralShift> spectra);

  std::span<const PointStar> stars() const { return stars_; }
  const StarBins& bins() const { return bins_; }

  // Star k's light's luminance, unshifted, and the least of them all.
  double luminance(std::size_t k) const { return luminance_[k]; }
  double faintest_luminance() const { return faintest_; }

  // Star k's light seen with the ratios SeenShift applies there (color,
  // beaming; 1 and 1 for the geometric light).
  Color seen(std::size_t k, float color, float beaming) const;

  std::size_t bytes() const;

 private:
  std::vector<PointStar> stars_;
  StarBins bins_;
  std::vector<float> blackbody_scale_;
  std::vector<float> luminance_;
  double faintest_ = 0.0;  // flux's luminance / the table's at the star's temperature
  std::shared_ptr<const BlackbodyColors> colors_;
  std::shared_ptr<const SpectralShift> spectra_;
};

}  // namespace lc
