#include "store/frame_record.hpp"

#include <fmt/format.h>

namespace lc::farm {

FrameSettings frame_settings(const RenderSettings& rs) {
  // Adaptive sampling only means something with more than one sample.
  FrameSettings s{rs.width, rs.height, rs.supersample, rs.layers, rs.adaptive && rs.supersample > 1};
  s.window = rs.window;
  return s;
}

std::string FrameSettings::describe() const { return describe(*this); }

std::string FrameSettings::describe(const FrameSettings& against) const {
  std::string of;
  if (window.windowed())
    of = fmt::format(" (the window at {},{} of a {}x{} frame)", window.x0, window.y0, window.frame_width,
                     window.frame_height);
  else if (against.window.windowed())
    of = " (the whole frame)";
  // The delivery, said where it or `against`'s is not the shot's own; a
  // dome's angles and ODS's separation where either's are not the defaults.
  std::string through;
  const Delivery &d = delivery, &o = against.delivery;
  if (d.camera != DeliveryCamera::shot) {
    through = fmt::format(", through the {} camera", name_of(d.camera));
    if (d.camera == DeliveryCamera::dome &&
        (d.dome_tilt != default_dome_tilt || d.dome_elevation != default_dome_elevation ||
         o.dome_tilt != default_dome_tilt || o.dome_elevation != default_dome_elevation))
      through += fmt::format(" (tilted {:g} degrees, the subject {:g} degrees up)", d.dome_tilt, d.dome_elevation);
    if (d.camera == DeliveryCamera::ods &&
        (d.separation != default_ods_separation || o.separation != default_ods_separation))
      through += fmt::format(" (eyes {:g} M apart)", d.separation);
  } else if (o.camera != DeliveryCamera::shot) {
    through = ", through the shot's own camera";
  }
  if (d.sky == DeliverySky::kstars)
    through += ", under the KStars sky";
  else if (o.sky != DeliverySky::shot)
    through += ", under the shot's own sky";
  const char* depth = png_depth == PngDepth::sixteen ? ", 16-bit PNG"
                      : against.png_depth == PngDepth::sixteen ? ", 8-bit PNG"
                                                               : "";
  // The shutter as the command line set it, where it or `against` did.
  std::string shutter_text;
  if (shutter.open) shutter_text += fmt::format(", shutter {}", *shutter.open);
  if (shutter.position) shutter_text += fmt::format(", shutter at {}", choice_name(*shutter.position));
  if (shutter.time_samples) shutter_text += fmt::format(", {} time samples", *shutter.time_samples);
  if (!shutter.any() && against.shutter.any()) shutter_text = ", the shot's shutter";
  return fmt::format("{}x{}{}{}, {}x{} samples per pixel{}, {}{}{}", width, height, of, through, supersample,
                     supersample, adaptive && supersample > 1 ? " (adaptive)" : "",
                     layers ? "with data layers" : "no data layers", depth, shutter_text);
}

}  // namespace lc::farm
