#include "objects/disk.hpp"

#include "assets/shot_resources.hpp"
#include "core/constants.hpp"

namespace lc {

void Disk::glow(const std::optional<NovikovThorneFlux>& flux, ShotResources& res) {
  const std::string how = p_.temperature > 0.0 ? fmt::format("temperature = {:g}", p_.temperature)
                                                : fmt::format("solar_masses = {:g}, accretion_rate = {:g}", p_.solar_masses,
                                                              p_.accretion_rate);
  if (!flux)
    throw std::invalid_argument(fmt::format(
        "disk: {} makes a glowing Novikov–Thorne disk, which needs a Kerr or Kerr–Newman hole with mass > 0 and "
        "spin^2 + charge^2 < mass^2 (lightcone has the flux of no other spacetime's disk; leave temperature, "
        "solar_masses and accretion_rate at 0 for the checker)",
        how));
  flux_ = flux;
  const double peak = flux_->peak_radius();
  flux_max_ = (*flux_)(peak);
  t_max_ = p_.temperature > 0.0 ? p_.temperature : flux_->temperature(peak, p_.solar_masses, p_.accretion_rate);
  if (!(t_max_ >= 1.0) || !(t_max_ <= 1e9))
    throw std::invalid_argument(fmt::format(
        "disk: {} makes the hottest ring {:.4g} K, outside the 1 K to 1e9 K lightcone shows", how, t_max_));
  // The table's reference is the hottest ring's light, a blackbody at f T_max
  // diluted by f^-4.  Given a temperature, that light, unshifted, has
  // luminance 1 (the dilution cancels); given physical units, the light is
  // in cd/m^2.
  const double f = p_.color_correction;
  colors_ = res.blackbody_colors(f * t_max_);
  if (p_.solar_masses > 0.0)
    scale_ = static_cast<float>(luminous_efficacy * blackbody_xyz(f * t_max_).Y / (f * f * f * f));
}

}  // namespace lc
