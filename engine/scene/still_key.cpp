#include "scene/still_key.hpp"

#include <fmt/format.h>

#include "scene/scene_skies.hpp"

namespace lc {

namespace {

// The observer, the camera, the sky and the objects are keyed by their
// registries from their declared fields (core/registry.hpp), so a new kind
// or field joins the key by itself.  A new member of these structs must be
// added here, or frames that differ in it would share rays: each size must
// be the sum of the members' known here (x86-64, libstdc++, where only the
// last pads to the struct's alignment), so a new member trips it, while a
// registered kind growing (a larger spacetime, say) does not.
#if defined(__x86_64__) && defined(__GLIBCXX__)
constexpr std::size_t aligned(std::size_t n, std::size_t a) { return (n + a - 1) / a * a; }
static_assert(sizeof(SceneSpec) == aligned(sizeof(Spacetime) + sizeof(ObserverSpec) + sizeof(CameraSpec) +
                                               sizeof(SkySpec) + sizeof(std::vector<ObjectSpec>) + sizeof(LightParams) +
                                               sizeof(std::optional<double>) /* shutter: see still_key */ +
                                               sizeof(std::optional<double>) /* exposure: not in the key */ +
                                               sizeof(std::vector<EndSky>) /* end_skies: with the sky */,
                                           alignof(SceneSpec)),
              "SceneSpec has a member still_key does not know: add it to still_key");
// An observer at rest is keyed by its position alone (AtRestParams'
// extra_key): a new member there must join that key.
static_assert(sizeof(AtRestParams<StaticObserver>) ==
                  sizeof(Vec4) + sizeof(std::string) /* where: not in the key, it does not change the picture */,
              "AtRestParams has a member its extra_key does not know: add it there");
#endif

// The key of everything but the observer's clock (for one fixed in space,
// whose extra_key leaves it out).
std::string key_without_clock(const SceneSpec& fs) {
  std::string k = "spacetime " + describe(fs.spacetime, true);
  k += "|observer " + ObserverRegistry::key(fs.observer);
  k += "|camera " + kind_key(fs.camera);
  for_each_sky(fs, [&](std::string_view end, const SkySpec& sky) {
    k += "|sky " + (end.empty() ? std::string() : std::string(end) + " ") + SkyRegistry::key(sky);
  });
  for (const ObjectSpec& o : fs.objects) k += "|object " + kind_key(o);
  k += "|light" + fields_key(fs.light);
  // Not the shutter: a frame whose scene changes within an open shutter
  // neither takes nor keeps samples (render/pixel_rows.hpp), and any other
  // renders as with the shutter closed.  Not the exposure: it changes what
  // the PNG shows, not one ray.
  return k;
}

}  // namespace

std::string still_key(const SceneSpec& fs) {
  // A moving observer: no two of its frames are the same scene shifted in
  // time.  One fixed in space is keyed without its time (its extra_key).
  if (!observer_fixed_in_space(fs.observer)) return {};
  return key_without_clock(fs);
}

std::string scene_key(const SceneSpec& fs) {
  return key_without_clock(fs) + fmt::format("|clock {:a}", observer_clock(fs.observer));
}

}  // namespace lc
