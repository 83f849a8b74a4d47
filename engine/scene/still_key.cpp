#include "scene/still_key.hpp"

#include <fmt/format.h>

namespace lc {

namespace {

// A new field in these structs must join the key, or frames that differ in
// it would share rays: their sizes (x86-64, libstdc++) trip when one is
// added.  Update them with the key.
#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(FrameScene) == 448, "FrameScene changed: add the field to still_key");
static_assert(sizeof(ObserverSpec) == 216, "ObserverSpec changed: add the field to still_key");
static_assert(sizeof(DiskSpec) == 48, "DiskSpec changed: add the field to still_key");
static_assert(sizeof(SphereSpec) == 248, "SphereSpec changed: add the field to still_key");
#endif

std::string hex(double v) { return fmt::format("{:a}", v); }

std::string color(const Color& c) { return fmt::format("{:a},{:a},{:a}", c[0], c[1], c[2]); }

}  // namespace

std::string still_key(const FrameScene& fs) {
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
  if (fs.disk) {
    const DiskSpec& d = *fs.disk;
    k += fmt::format("|disk {} {} {} {} {} {}", hex(d.inner), hex(d.outer), d.rings, d.sectors, color(d.color_a),
                     color(d.color_b));
  }
  k += "|sky " + SkyRegistry::key(fs.sky);
  for (const SphereSpec& sp : fs.spheres) {
    k += fmt::format("|sphere {} {} {} {} {}", hex(sp.radius), sp.rows, sp.columns, color(sp.color_a), color(sp.color_b));
    if (sp.position)
      k += fmt::format(" at {} {} {}", hex((*sp.position)[1]), hex((*sp.position)[2]), hex((*sp.position)[3]));
    if (sp.worldline) k += " along " + sp.worldline->key();
  }
  return k;
}

}  // namespace lc
