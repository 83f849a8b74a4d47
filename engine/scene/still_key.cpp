#include "scene/still_key.hpp"

#include <fmt/format.h>

namespace lc {

namespace {

// The camera, the sky and the objects are keyed by their registries from
// their declared fields (core/registry.hpp), so a new kind or field joins
// the key by itself.  A new member of these two structs must be added here,
// or frames that differ in it would share rays: each size must be the sum
// of the members' known here (x86-64, libstdc++, where only the last pads
// to the struct's alignment), so a new member trips it, while a registered
// kind growing (a larger spacetime, say) does not.
#if defined(__x86_64__) && defined(__GLIBCXX__)
constexpr std::size_t aligned(std::size_t n, std::size_t a) { return (n + a - 1) / a * a; }
static_assert(sizeof(SceneSpec) == aligned(sizeof(Spacetime) + sizeof(ObserverSpec) + sizeof(CameraSpec) +
                                               sizeof(SkySpec) + sizeof(std::vector<ObjectSpec>) + sizeof(LightParams),
                                           alignof(SceneSpec)),
              "SceneSpec has a member still_key does not know: add it to still_key");
static_assert(sizeof(ObserverSpec) ==
                  sizeof(double) /* kind, padded */ + sizeof(Vec4) + sizeof(std::optional<WorldlineSpec>) + sizeof(double) +
                      sizeof(std::string) /* where: not in the key, it does not change the picture */,
              "ObserverSpec has a member still_key does not know: add it to still_key");
#endif

std::string hex(double v) { return fmt::format("{:a}", v); }

}  // namespace

std::string still_key(const SceneSpec& fs) {
  std::string k = "spacetime " + describe(fs.spacetime, true);
  const ObserverSpec& ob = fs.observer;
  switch (ob.kind) {
    case ObserverKind::static_observer:
    case ObserverKind::zamo:
      // Fixed in space: its time is what the key leaves out.
      k += fmt::format("|observer {} {} {} {}", ob.kind == ObserverKind::zamo ? "zamo" : "static", hex(ob.position[1]),
                       hex(ob.position[2]), hex(ob.position[3]));
      break;
    case ObserverKind::free_fall:
      // Moving: no two of its frames are the same scene shifted in time.
      return {};
  }
  k += "|camera " + CameraRegistry::key(fs.camera);
  k += "|sky " + SkyRegistry::key(fs.sky);
  for (const ObjectSpec& o : fs.objects) k += "|object " + ObjectRegistry::key(o);
  k += "|light" + fields_key(fs.light);
  return k;
}

}  // namespace lc
