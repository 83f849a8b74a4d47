#include "bench_command.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "geodesic/null_ray.hpp"
#include "observer/ray_direction.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace {

// The fixed Kerr ray set: the camera of shots/bench/kerr_disk.lua (a = 0.9,
// static observer at r = 30, theta = 80 deg, phi = 0, looking at the hole,
// 40 deg horizontal field of view), size x size pixel-centre rays, traced to
// capture or escape with no scene objects.
struct KerrRaySet {
  Kerr kerr{1.0, 0.9};
  Vec4 x{};
  Mat4 g{};
  Tetrad frame{};
  int size;

  explicit KerrRaySet(int n) : size(n) {
    const Vec4 s = {0.0, 30.0, 80.0 * degree, 0.0};
    x = kerr.trace_from_scene(s);
    g = kerr.metric(x);
    frame = static_polar_tetrad(kerr, s);
  }

  // Traces row j; returns accepted steps.
  long trace_row(int j) const {
    const double t = std::tan(20.0 * degree);
    long steps = 0;
    for (int i = 0; i < size; ++i) {
      const double u = (2.0 * (i + 0.5) / size - 1.0) * t, v = (1.0 - 2.0 * (j + 0.5) / size) * t;
      // forward = -e_r, up = -e_theta, right = e_phi
      const Vec4 p = backward_ray_momentum(g, frame, {-1.0, -v, u});
      steps += trace_null_ray(kerr, x, p, RayOptions{}).steps;
    }
    return steps;
  }
};

struct Timing {
  double seconds;
  long steps;
};

Timing run(const KerrRaySet& set, int threads) {
  std::atomic<int> next{0};
  std::atomic<long> steps{0};
  const auto t0 = std::chrono::steady_clock::now();
  auto worker = [&] {
    long local = 0;
    for (int j; (j = next.fetch_add(1)) < set.size;) local += set.trace_row(j);
    steps += local;
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {s, steps.load()};
}

}  // namespace

int run_bench(const BenchCommand& cmd) {
  const int all = cmd.threads > 0 ? cmd.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const KerrRaySet set(cmd.size);
  const long rays = static_cast<long>(cmd.size) * cmd.size;
  fmt::print("lightcone bench: Kerr a = 0.9 ray set, {}x{} rays from r = 30, theta = 80 deg (tolerance {:g})\n",
             cmd.size, cmd.size, default_ray_tolerance);
  Timing one{1e300, 0}, many{1e300, 0};
  for (int r = 0; r < cmd.repeats; ++r) {
    const Timing a = run(set, 1);
    if (a.seconds < one.seconds) one = a;
    if (all > 1) {
      const Timing b = run(set, all);
      if (b.seconds < many.seconds) many = b;
    }
  }
  fmt::print("  {:>9} {:>14} {:>14} {:>12} {:>22}\n", "threads", "rays/s", "steps/s", "steps/ray", "rays per core-second");
  fmt::print("  {:>9} {:>14.0f} {:>14.0f} {:>12.1f} {:>22.0f}\n", 1, rays / one.seconds, one.steps / one.seconds,
             double(one.steps) / rays, rays / one.seconds);
  if (all > 1)
    fmt::print("  {:>9} {:>14.0f} {:>14.0f} {:>12.1f} {:>22.0f}   (scaling {:.2f} of linear)\n", all,
               rays / many.seconds, many.steps / many.seconds, double(many.steps) / rays, rays / many.seconds / all,
               one.seconds / many.seconds / all);
  return 0;
}

}  // namespace lc
