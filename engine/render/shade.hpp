#pragma once
// The shade stage: a hit record (render/hit_record.hpp) -> the sample's
// colour, for every path that traced it.  The sky of the end the ray
// escaped to (SceneIn::sky_of) is looked up in the direction it went and
// shown as the light model sees light from a source at rest far away; an
// object gives its colour at the surface point it was met
// (ObjectKind::color_at, the object seam); the horizon, a ray that gave up
// and an image point without a ray are black.  Reads nothing but the
// record and the scene, so records kept from a render shade to the same
// pixels again.

#include "core/color.hpp"
#include "render/hit_record.hpp"
#include "render/scene.hpp"

namespace lc {

// Fills s.color and s.sky (where a sky ray went and the light model's
// ratios there; untouched fields of a non-sky ray say "not the sky") from
// the record part of s.  Only rays that reached the first end have a sky
// point: point stars (the star stage) are drawn on the scene's own sky,
// never across a throat into another end's directions.
template <class S>
void shade(const SceneIn<S>& sc, RaySample& s) {
  s.color = {0.0f, 0.0f, 0.0f};
  s.sky = SkyPoint{};
  if (s.kind == HitKind::sky) {
    const SeenShift shift = sc.light.seen(s.g, s.g_gravity);
    s.color = shift.texture(sc.sky_of(s.spacetime_end).color(s.sky_theta, s.sky_phi));
    if (s.spacetime_end != 0) return;
    s.sky.theta = s.sky_theta;
    s.sky.phi = s.sky_phi;
    s.sky.color = static_cast<float>(shift.color);
    s.sky.beaming = static_cast<float>(shift.beaming);
  } else if (s.object != HitRecord::no_object) {
    with_object(sc.objects, s.object,
                [&](const auto& o) { s.color = o.color_at(s.surface, sc.light.seen(s.g, s.g_gravity)); });
  }
}

}  // namespace lc
