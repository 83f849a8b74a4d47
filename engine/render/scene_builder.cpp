#include "render/scene_builder.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "scene/asset_path.hpp"
#include "scene/still_key.hpp"

namespace lc {

ShotResources::ShotResources(std::vector<std::filesystem::path> asset_dirs) : asset_dirs_(std::move(asset_dirs)) {}

std::shared_ptr<const Worldline> ShotResources::worldline(const WorldlineSpec& spec) {
  const std::string key = spec.key();
  {
    std::lock_guard lock(mutex_);
    if (auto it = worldlines_.find(key); it != worldlines_.end()) return it->second;
  }
  // Integrate outside the lock; a racing duplicate is harmless (same result).
  auto w = std::make_shared<const Worldline>(Worldline::integrate(spec));
  std::lock_guard lock(mutex_);
  return worldlines_.emplace(key, std::move(w)).first->second;
}

std::shared_ptr<const Texture> ShotResources::texture(const std::filesystem::path& file) {
  const std::filesystem::path found = resolve_sky_image(file, asset_dirs_);
  {
    std::lock_guard lock(mutex_);
    if (auto it = textures_.find(found); it != textures_.end()) return it->second;
  }
  auto t = std::make_shared<const Texture>(Texture::load(found));
  std::lock_guard lock(mutex_);
  return textures_.emplace(found, std::move(t)).first->second;
}

std::shared_ptr<const Texture> ShotResources::starfield(std::uint32_t seed, int width) {
  const auto key = std::pair{seed, width};
  {
    std::lock_guard lock(mutex_);
    if (auto it = starfields_.find(key); it != starfields_.end()) return it->second;
  }
  FrameImage img = render_starfield(width, width / 2, seed);
  auto t = std::make_shared<const Texture>(Texture::from_pixels(img.width, img.height, std::move(img.rgb)));
  std::lock_guard lock(mutex_);
  return starfields_.emplace(key, std::move(t)).first->second;
}

std::vector<std::filesystem::path> ShotResources::files() const {
  std::lock_guard lock(mutex_);
  std::vector<std::filesystem::path> out;
  for (const auto& [path, tex] : textures_) out.push_back(path);
  return out;
}

namespace {

template <class S>
Tetrad rest_frame_for_object(const S& st, const Vec4& scene) {
  if constexpr (std::is_same_v<S, Kerr>)
    return static_polar_tetrad(st, scene);
  else
    return static_cartesian_tetrad(st, st.trace_from_scene(scene));
}

// A coordinate radius beyond which a ray moving outwards meets nothing more:
// twice the largest of the objects' reach and the holes' photon region
// (Kerr: photon orbits lie within 4M; a dihole's within 4(m1 + m2) of its
// holes at +-d).  The factor 2 keeps the relaxed integration well clear.
template <class S>
double free_radius(const SceneOf<S>& sc) {
  double reach = 0.0;
  if constexpr (std::is_same_v<S, Kerr>) reach = 4.0 * sc.spacetime.mass() + std::abs(sc.spacetime.spin());
  if constexpr (std::is_same_v<S, Dihole>)
    reach = 4.0 * sc.spacetime.asymptotic_mass() + sc.spacetime.separation();
  if (sc.disk) reach = std::max(reach, sc.disk->spec.outer + std::abs(sc.spacetime.asymptotic_mass()));
  for (const Sphere& sp : sc.spheres)
    for (int k = 0; k < 3; ++k)
      reach = std::max({reach, std::abs(sp.life_lo[k]) + 2.0 * sp.spec.radius, std::abs(sp.life_hi[k]) + 2.0 * sp.spec.radius});
  return 2.0 * std::max(reach, 1.0);
}

// Where a dihole's (or flat space's) rays may stop: beyond the free-flight
// radius, where the multipoles beyond the monopole bend light by less than
// far_field_bending; the monopole's share comes from weak_field_tail.hpp.
// Unequal holes have a dipole, (m1 - m2) d / r^2, bending ~|m1 - m2| d / r^2;
// equal ones a quadrupole, ~M d^2 / r^3.  The paper's dihole: ~93 M instead
// of 1000 M; masses 0.6 and 0.2: ~630 M.
template <class S>
double far_field_escape_radius(const SceneOf<S>& sc) {
  double radius = sc.rays.free_radius;
  if constexpr (std::is_same_v<S, Dihole>) {
    const Dihole& h = sc.spacetime;
    const double M = h.asymptotic_mass(), d = h.separation(), dm = std::abs(h.mass1() - h.mass2());
    radius = std::max({radius, std::cbrt(M * d * d / far_field_bending), std::sqrt(dm * d / far_field_bending)});
  }
  return radius;
}

template <class S>
Scene build(const S& st, const FrameScene& fs, int width, int height, ShotResources& res, const RayOptions& rays) {
  const std::string here = describe(fs.spacetime);
  auto check_same = [&](const WorldlineSpec& w, const char* what) {
    if (describe(w.spacetime, true) != describe(fs.spacetime, true))
      throw std::invalid_argument(fmt::format(
          "{}: {}'s worldline ({}) was made in {}, but this frame's spacetime is {}; a worldline only "
          "makes sense in the spacetime it was integrated in",
          w.where, what, w.where, describe(w.spacetime), here));
  };

  SceneOf<S> sc{st, {}, 0.0, {}, {}, PinholeCamera(fs.camera, width, height), std::nullopt, Sky{fs.sky, nullptr}, {},
                rays};
  const ObserverSpec& ob = fs.observer;
  try {
    if (ob.kind == ObserverKind::free_fall) {
      check_same(*ob.worldline, "the observer");
      const auto w = res.worldline(*ob.worldline);
      const WorldlineEvent ev = w->at_proper_time(ob.proper_time);
      sc.observer = ev.x;
      sc.frame = ev.frame;
      sc.observer_scene = st.scene_from_trace(ev.x);
    } else {
      sc.observer = st.trace_from_scene(ob.position);
      sc.observer_scene = ob.position;
      sc.frame = ob.kind == ObserverKind::zamo ? zamo_polar_tetrad(st, ob.position)
                                               : static_polar_tetrad(st, ob.position);
    }
  } catch (const ObserverError& e) {
    throw std::invalid_argument(fmt::format("observer: {}", e.what()));
  }
  if (st.captured(sc.observer))
    throw std::invalid_argument("observer: too close to a horizon (inside the capture region where rays are stopped)");
  sc.metric = st.metric(sc.observer);
  double r_unused, phi_unused;
  scene_polar(st, sc.observer, sc.observer_time, r_unused, phi_unused);

  if (fs.disk) sc.disk = Disk{*fs.disk};
  if (fs.sky.kind == SkyKind::image) sc.sky.texture = res.texture(fs.sky.image);
  if (fs.sky.kind == SkyKind::stars) sc.sky.texture = res.starfield(fs.sky.seed, fs.sky.resolution);
  for (const SphereSpec& spec : fs.spheres) {
    Sphere sp{spec, nullptr, {}, {}};
    if (spec.worldline) {
      check_same(*spec.worldline, "a sphere");
      sp.worldline = res.worldline(*spec.worldline);
    } else {
      sp.rest_position = st.trace_from_scene(*spec.position);
      try {
        sp.rest_frame = rest_frame_for_object(st, *spec.position);
      } catch (const ObserverError& e) {
        throw std::invalid_argument(fmt::format("sphere at rest: {}", e.what()));
      }
    }
    sp.bounds(-1e300, 1e300, sp.life_lo, sp.life_hi);
    sc.spheres.push_back(std::move(sp));
  }
  sc.rays.free_radius = free_radius(sc);
  if constexpr (!std::is_same_v<S, Kerr>)
    if (rays.escape == EscapeRule::far_field)
      sc.rays.escape_radius = std::min(sc.rays.escape_radius, far_field_escape_radius(sc));
  if constexpr (std::is_same_v<S, Kerr>) sc.observer_jacobian = st.trace_jacobian(sc.observer_scene);
  if constexpr (S::stationary) {
    // With what the rays are traced by: frames share rays only if these
    // agree too.
    sc.still_key = still_key(fs);
    if (!sc.still_key.empty())
      sc.still_key += fmt::format("|image {}x{}|rays {:a} {:a} {:a} {:a} {} {:a} {} {:a} {}", width, height,
                                  rays.control.rtol, rays.control.atol, rays.control.h_min, rays.control.h_max,
                                  static_cast<int>(rays.kerr_chart), rays.escape_radius, static_cast<int>(rays.escape),
                                  rays.free_radius, rays.max_steps);
  }
  return sc;
}

}  // namespace

Scene build_scene(const FrameScene& fs, int width, int height, ShotResources& resources, const RayOptions& rays) {
  Spacetime st = fs.spacetime;
  if (auto* k = std::get_if<Kerr>(&st)) *k = k->with_sense(KerrSchildSense::outgoing);
  return std::visit([&](const auto& s) { return build(s, fs, width, height, resources, rays); }, st);
}

}  // namespace lc
