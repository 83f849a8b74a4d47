#pragma once
// lc.light{...}: how a frame shows the light its rays bring (docs/light.md).
// `geometric`, the default and the paper's look, shows every texture as it
// is; `shifted` shows it as the frequency ratio g of each hit makes it: the
// colour shifted (light/spectral_shift.hpp) and the intensity beamed
// (I_nu / nu^3 invariant: g^4 integrated over frequency), each switchable,
// and g taken whole or only its gravitational or kinematic part.  A glowing
// disk's blackbody is seen through the same switches.
//
// The parts: with u_ref the zero-angular-momentum observer (ZAMO; in a
// static spacetime the static observer) at each end of the ray, and
// D(u) = p.u (p.u_observer = 1),
//   g = 1 / D(u_emitter) = [1 / D(u_ref,obs)] [D(u_ref,obs) / D(u_ref,em)] [D(u_ref,em) / D(u_emitter)]
// the middle factor is the gravitational part g_grav (with frame dragging),
// the outer two the kinematic part g / g_grav: the Doppler shifts of the
// observer and the emitter against the ZAMOs where they are.

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <utility>

#include "core/color.hpp"
#include "core/fields.hpp"
#include "light/spectral_shift.hpp"

namespace lc {

enum class LightModel { geometric, shifted };
constexpr std::array<std::string_view, 2> choice_names(LightModel) { return {"geometric", "shifted"}; }

struct LightParams {
  LightModel model = LightModel::geometric;
  int color_shift = 1, beaming = 1, gravitational = 1, kinematic = 1;
  static constexpr auto fields = std::tuple{
      field("model", &LightParams::model, std::optional<LightModel>{LightModel::geometric}, std::nullopt,
            std::nullopt,
            "geometric: textures as they are (the paper's look); shifted: seen through each hit's frequency ratio g"),
      field("color_shift", &LightParams::color_shift, std::optional<int>{1}, at_least(0), at_most(1),
            "shifted: 1 shifts the spectrum by g (colour), 0 leaves it"),
      field("beaming", &LightParams::beaming, std::optional<int>{1}, at_least(0), at_most(1),
            "shifted: 1 scales the intensity by g^4 (beaming), 0 leaves it"),
      field("gravitational", &LightParams::gravitational, std::optional<int>{1}, at_least(0), at_most(1),
            "shifted: 1 includes g's gravitational part (ZAMO to ZAMO, frame dragging included)"),
      field("kinematic", &LightParams::kinematic, std::optional<int>{1}, at_least(0), at_most(1),
            "shifted: 1 includes g's kinematic part (the observer's and the emitter's motion against the ZAMOs)"),
  };
  // The switches belong to the shifted model: a geometric light that sets
  // one would be silently ignored.  Throws std::invalid_argument.
  void validate() const {
    if (model == LightModel::geometric && !(color_shift && beaming && gravitational && kinematic))
      throw std::invalid_argument(
          "color_shift, beaming, gravitational and kinematic choose what model = \"shifted\" shows; the geometric "
          "model shows textures as they are (set model = \"shifted\", or leave the switches out)");
  }
};

// How one hit's light is seen: the ratio its spectrum is shifted by and the
// ratio its intensity is beamed by (1 where the light model leaves them).
struct SeenShift {
  double color = 1.0, beaming = 1.0;
  const SpectralShift* spectra = nullptr;  // set whenever color != 1

  // Intensity factor beyond what shifting the spectrum by `color` gives:
  // (beaming / color)^4 (a spectrum shifted by g alone carries g^4 more light).
  float extra_beaming() const {
    const double b = beaming / color;
    return static_cast<float>((b * b) * (b * b));
  }
  // A texture's colour c (linear sRGB) seen so.
  Color texture(const Color& c) const {
    if (color == 1.0 && beaming == 1.0) return c;
    Color out = color == 1.0 ? c : (*spectra)(c, color);
    const float k = extra_beaming();
    for (float& v : out) v *= k;
    return out;
  }
};

// A frame's light model, built.
class Light {
 public:
  // The paper's look.
  Light() = default;
  // spectra: the table of texture spectra (shared by the shot's frames).
  Light(const LightParams& p, std::shared_ptr<const SpectralShift> spectra) : p_(p), spectra_(std::move(spectra)) {}

  // Whether seen() needs g's gravitational part (else any value will do).
  bool splits() const {
    return p_.model == LightModel::shifted && (p_.color_shift || p_.beaming) && !(p_.gravitational && p_.kinematic);
  }
  // How light of frequency ratio g, of which g_grav is gravitational, is
  // seen.
  SeenShift seen(double g, double g_grav) const {
    if (p_.model == LightModel::geometric) return {};
    const double used = p_.gravitational && p_.kinematic ? g
                        : p_.gravitational               ? g_grav
                        : p_.kinematic                   ? g / g_grav
                                                         : 1.0;
    return {p_.color_shift ? used : 1.0, p_.beaming ? used : 1.0, spectra_.get()};
  }

 private:
  LightParams p_;
  std::shared_ptr<const SpectralShift> spectra_;
};

}  // namespace lc
