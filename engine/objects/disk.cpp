#include "objects/disk.hpp"

#include "assets/shot_resources.hpp"

namespace lc {

void Disk::glow(const std::optional<NovikovThorneFlux>& flux, ShotResources& res) {
  if (!flux)
    throw std::invalid_argument(fmt::format(
        "disk: temperature = {} makes a glowing Novikov–Thorne disk, which needs a Kerr hole with mass > 0 and "
        "|spin| < mass (set temperature = 0 for the checker)",
        p_.temperature));
  flux_ = flux;
  flux_max_ = (*flux_)(flux_->peak_radius());
  // The hottest ring, unshifted, has luminance 1: the table's reference is
  // its light, a blackbody at f T_max (the dilution f^-4 cancels).
  colors_ = res.blackbody_colors(p_.color_correction * p_.temperature);
}

}  // namespace lc
