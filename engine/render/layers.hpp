#pragma once
// The data layers a frame can carry besides colour (docs/layers.md), one
// line each in the table below: a name (the EXR channel), what it holds,
// and how to read it from a ray's hit record.  The frame image, the
// pixel loop, the sample memo, `lightcone trace`'s report, the help text and
// docs/layers.md (checked by a test) all read this table and nothing else.

#include <array>
#include <cstddef>
#include <string_view>

#include "render/hit_record.hpp"

namespace lc {

struct LayerSpec {
  std::string_view name;
  std::string_view what;
  float (*value)(const HitRecord&);
};

inline constexpr std::array layers = {
    LayerSpec{"hit.kind",
              "what the ray found: 0 sky, 2 horizon, 4 gave up (integration failed; the pixel is black), 5 no ray (the "
              "camera has none through the pixel centre: black, alpha 0), or the object kind's own number: 1 disk, "
              "3 sphere (`lightcone trace` names it)",
              [](const HitRecord& s) { return static_cast<float>(static_cast<int>(s.kind)); }},
    LayerSpec{"hit.r",
              "radius of the event where the ray ended: the scene chart's r where it is polar (Boyer–Lindquist for "
              "Kerr, static for Kottler, the signed distance l from the throat for a wormhole: negative in the other "
              "universe), distance from the origin otherwise (where exactly, for the sky and the horizon: below)",
              [](const HitRecord& s) { return static_cast<float>(s.r); }},
    LayerSpec{"hit.phi", "longitude of that event in [0, 2π): Boyer–Lindquist φ for Kerr, atan2(y, x) otherwise",
              [](const HitRecord& s) { return static_cast<float>(s.phi); }},
    LayerSpec{"hit.t",
              "coordinate time of that event minus the observer's: negative, light left it earlier (Boyer–Lindquist "
              "t for Kerr)",
              [](const HitRecord& s) { return static_cast<float>(s.t); }},
    LayerSpec{"hit.g",
              "frequency ratio ν_observed / ν_emitted of the light: above 1 blueshifted, below 1 redshifted; the "
              "disk's matter orbits, a sphere moves with its worldline, the sky's light left a source at rest far "
              "away; 0 for the horizon and gave-up pixels (docs/light.md)",
              [](const HitRecord& s) { return static_cast<float>(s.g); }},
    LayerSpec{"hit.order",
              "number of crossings of the equatorial plane (z = 0) before the end: 0 for the direct image of the "
              "disk, 1 for the first image seen under/over the hole, …",
              [](const HitRecord& s) { return static_cast<float>(s.order); }},
};
inline constexpr std::size_t layer_count = layers.size();

// A sample's values of every layer, in table order.
using LayerValues = std::array<float, layer_count>;
inline LayerValues layer_values(const HitRecord& s) {
  LayerValues v;
  for (std::size_t k = 0; k < layer_count; ++k) v[k] = layers[k].value(s);
  return v;
}

// What a frame uses of a shaded sample: its colour, its hit kind (adaptive
// sampling compares those), its layer values (for the pixel's centre) and
// where it went on the sky (for point stars).
struct FrameSample {
  Color color{};
  LayerValues layers{};
  HitKind kind = HitKind::gave_up;
  SkyPoint sky{};
};
inline FrameSample frame_sample(const HitRecord& hit, const Shading& s) {
  return {s.color, layer_values(hit), hit.kind, s.sky};
}

// The record of an image point the camera has no ray through: kind no_ray,
// never traced (and so black: Shading's defaults).
inline HitRecord no_ray_record() {
  HitRecord r;
  r.kind = HitKind::no_ray;
  r.reason = StopReason::no_ray;
  return r;
}

// The same as a sample, for the tools that trace one pixel.
inline RaySample no_ray_sample() {
  RaySample s;
  s.hit = no_ray_record();
  return s;
}

}  // namespace lc
