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
#include "objects/objects.hpp"
#include "render/hit_record.hpp"
#include "render/scene.hpp"

namespace lc {

// The colour of the record `hit` in the scene sc, and for a sky ray where it
// went with the light model's ratios there (untouched fields of a non-sky
// ray say "not the sky").  Only rays that reached the first end have a sky
// point: point stars (the star stage) are drawn on the scene's own sky,
// never across a throat into another end's directions.
template <class S>
Shading shade(const SceneIn<S>& sc, const HitRecord& hit) {
  Shading out;
  if (hit.kind == HitKind::sky) {
    const SeenShift shift = sc.light.seen(hit.g, hit.g_gravity);
    out.color = shift.texture(sc.sky_of(hit.spacetime_end).color(hit.sky_theta, hit.sky_phi));
    if (hit.spacetime_end != 0) return out;
    out.sky.theta = hit.sky_theta;
    out.sky.phi = hit.sky_phi;
    out.sky.color = static_cast<float>(shift.color);
    out.sky.beaming = static_cast<float>(shift.beaming);
  } else if (hit.object != HitRecord::no_object) {
    with_object(sc.objects->lists, hit.object,
                [&](const auto& o) { out.color = o.color_at(hit.surface, sc.light.seen(hit.g, hit.g_gravity)); });
  }
  return out;
}

// Fills s.color and s.sky from its record (shade above).
template <class S>
void shade(const SceneIn<S>& sc, RaySample& s) {
  const Shading sh = shade(sc, s.hit);
  s.color = sh.color;
  s.sky = sh.sky;
}

}  // namespace lc
