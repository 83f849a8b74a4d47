#include "render/scene_builder.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "assets/asset_path.hpp"
#include "core/constants.hpp"
#include "objects/objects.hpp"
#include "observers/observers.hpp"
#include "render/ray_start.hpp"
#include "render/scene_visit.hpp"
#include "scene/still_key.hpp"
#include "spacetime/chart.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

// The kinds of each registry that are built in a spacetime, checked against
// every registered spacetime here, where they are built (and not in their
// registries' headers, so that those need not include the list of
// spacetimes: docs/architecture.md, "What a new kind rebuilds").
static_assert(every_kind<SpacetimeList>([]<class S>() {
  every_kind<ObjectRegistry>([]<class O>() {
    static_assert(ObjectKind<O, S>, "a registered object kind must satisfy ObjectKind in every registered spacetime");
  });
}));

static_assert(every_kind<SpacetimeList>([]<class S>() {
  every_kind<ObserverRegistry>([]<class O>() {
    static_assert(ObserverModel<O, S>,
                  "a registered observer kind must satisfy ObserverModel in every registered spacetime");
  });
}));

namespace {

// A radius, in the spacetime's flight measure (spacetime/ends.hpp), beyond
// which a ray moving outwards meets nothing more: twice the largest of the
// objects' reach and the spacetime's photon region.  The factor 2 keeps
// the relaxed integration well clear.
template <class S>
double free_radius(const SceneIn<S>& sc) {
  double reach = sc.spacetime.photon_reach();
  for_each_object(sc.objects->lists, [&](const auto& o, std::size_t) { reach = std::max(reach, o.reach(sc.spacetime)); });
  return 2.0 * std::max(reach, 1.0);
}

// A stereo camera's eyes stand off the observer (render/ray_start.hpp,
// displaced_eye): each is made here once, so an eye pushed where the
// observer cannot stand (a horizon's capture region; where its frame
// cannot be carried, as a static observer's into the ergoregion) is
// refused where the scene is built, by render before its first ray (the
// callers name the file and frame) and by inspect, not mid-render.  The
// eyes are those of a row through the middle of each eye's picture, at
// most 64 columns of it: a pinhole's two, the widest circle of an
// equirect's omnidirectional stereo.  Throws std::invalid_argument.
template <class S>
void check_eyes(const SceneIn<S>& sc, const CameraSpec& spec) {
  for (const EyePicture& p : sc.camera.pictures()) {
    if (p.eye == 0) continue;
    const int step = std::max(1, p.width / 64);
    std::optional<Vec3> last;
    for (int i = 0; i < p.width; i += step) {
      const auto r = sc.camera.ray({p.x0 + i + 0.5, p.y0 + 0.5 * p.height, 0.0});
      if (!r || r->at_observer() || (last && *last == r->eye)) continue;
      last = r->eye;
      try {
        (void)displaced_eye(sc, r->eye);
      } catch (const std::invalid_argument& e) {
        const double separation = stereo_separation(spec);
        throw std::invalid_argument(fmt::format(
            "the camera's {} eye (stereo, `separation` {:g} M) cannot stand there: {}; give the camera a smaller "
            "`separation`, or place the observer further out",
            p.eye < 0 ? "left" : "right", separation, e.what()));
      }
    }
  }
}

template <class S>
Scene build(const S& st, const SceneSpec& fs, int width, int height, ShotResources& res, const RayOptions& rays,
            const ImageWindow& window) {
  SceneIn<S> sc{st, {}, Camera(fs.camera, width, height, window), Sky(fs.sky, res), {}, {}, rays};
  for (const EndSky& e : fs.end_skies) sc.end_skies.emplace_back(e.end, Sky(e.sky, res));
  if (fs.light.model != LightModel::geometric) sc.light = Light(fs.light, res.spectral_shift());
  // The observer's kind places it and checks where it stands; the frame's
  // own eye is its path at offset 0.
  sc.observer_path = ObserverPath<S>(fs.observer, st, res, sc.light.splits());
  sc.eye = sc.observer_path.at(0.0);
  check_eyes(sc, fs.camera);

  auto objects = std::make_shared<ObjectSet>();
  for (const ObjectSpec& o : fs.objects) add_object(objects->lists, o, st, res, sc.eye.event);
  sc.objects = std::move(objects);
  sc.rays.free_radius = free_radius(sc);
  // Where the spacetime's far field is known (far_field_radius), rays
  // escape there, or beyond the objects; the sky lookup adds the rest of
  // the bending (escape_direction).
  if (rays.escape == EscapeRule::far_field)
    sc.rays.escape_radius =
        std::min(sc.rays.escape_radius, std::max(sc.rays.free_radius, st.far_field_radius()));
  if constexpr (S::stationary) {
    // With what the rays are traced by: frames share rays only if these
    // agree too.
    sc.still_key = still_key(fs);
    if (!sc.still_key.empty())
      sc.still_key += fmt::format("|image {}x{}{}|rays {:a} {:a} {:a} {:a} {} {:a} {} {:a} {}", width, height,
                                  window.windowed() ? fmt::format(" at {},{} of {}x{}", window.x0, window.y0,
                                                                  window.frame_width, window.frame_height)
                                                    : "",
                                  rays.control.rtol, rays.control.atol, rays.control.h_min, rays.control.h_max,
                                  static_cast<int>(rays.kerr_chart), rays.escape_radius, static_cast<int>(rays.escape),
                                  rays.free_radius, rays.max_steps);
  }
  return sc;
}

}  // namespace

Scene build_scene(const SceneSpec& fs, int width, int height, ShotResources& resources, const RayOptions& rays,
                  const ImageWindow& window) {
  const Spacetime st = trace_chart(fs.spacetime);
  return std::visit([&](const auto& s) { return build(s, fs, width, height, resources, rays, window); }, st.kinds());
}

Scene build_scene(const FrameSpecs& specs, int width, int height, ShotResources& resources, const RayOptions& rays,
                  const ImageWindow& window) {
  Scene scene = build_scene(specs.frame, width, height, resources, rays, window);
  for (std::size_t k = 0; k < specs.instants.size(); ++k) {
    std::optional<Scene> at;
    try {
      at.emplace(build_scene(specs.instants[k], width, height, resources, rays, window));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(
          fmt::format("at {:+g} of the frame (an instant of its shutter): {}", specs.times[k], e.what()));
    }
    if (!at->same_spacetime_kind(scene))  // (Shot::frame_specs refuses a change of spacetime first)
      throw std::invalid_argument(fmt::format("at {:+g} of the frame: the spacetime changes kind within the shutter",
                                              specs.times[k]));
    visit_scene(
        [&](auto& sc) {
          auto& instant = at->get<std::decay_t<decltype(sc.spacetime)>>();
          instant.moment = specs.times[k];
          sc.instants.push_back(std::move(instant));
        },
        scene);
  }
  return scene;
}

namespace {

// f() with its std::invalid_argument prefixed by the shot file and frame.
template <class F>
Scene naming_frame(const std::filesystem::path& shot_file, int frame, F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: frame {}: {}", shot_file.string(), frame, e.what()));
  }
}

}  // namespace

Scene build_scene(const SceneSpec& fs, const std::filesystem::path& shot_file, int frame, int width, int height,
                        ShotResources& resources, const RayOptions& rays, const ImageWindow& window) {
  return naming_frame(shot_file, frame, [&] { return build_scene(fs, width, height, resources, rays, window); });
}

Scene build_scene(const FrameSpecs& specs, const std::filesystem::path& shot_file, int frame, int width, int height,
                  ShotResources& resources, const RayOptions& rays, const ImageWindow& window) {
  return naming_frame(shot_file, frame, [&] { return build_scene(specs, width, height, resources, rays, window); });
}

}  // namespace lc
