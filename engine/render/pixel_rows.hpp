#pragma once
// The renderer's stages for rows of pixels, each with one job, over a batch
// of work items (SampleItem: a sample that carries its own place in the
// frame and the scene it sees), in the order a sample flows through them:
//   plan         which samples of the row's N x N pixel grids to take
//                (RowPlan: every one, or adaptive rounds) -> RowItems;
//   recall       the sample memo's kept samples stand in for traced ones
//                (MemoStage, in front of the ray stages);
//   generate     camera samples -> camera rays -> ray starts, in the scene
//                each item sees (FrameScenes::scene_at; an image point
//                without a ray is never traced);
//   trace        ray starts -> hit records (render/trace.hpp);
//   shade        hit records -> colours (render/shade.hpp);
//   keep         into the row's samples at each item's slot as the frame
//                uses them (FrameSample), and into the memo;
//   reconstruct  samples -> pixels: colour, alpha (the share of samples with
//                a ray), the layers from the pixel's centre ray, the sky
//                point of its first ray (reconstruct_row).
// Where the frame's shutter is open and its scene changes within it
// (SceneIn::instants), each grid sample sees one instant of it
// (render/sample_times.hpp): that is a field of the item, not a branch of
// the row loop.  A new per-sample feature is a field of SampleItem or a
// stage between these.
// Templated on the camera so that any class satisfying CameraModel (a
// registered one, through Camera, or a test's own) drives the same stages,
// inlined into one loop per row.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "camera/camera_sample.hpp"
#include "core/constants.hpp"
#include "image/srgb.hpp"
#include "render/layers.hpp"
#include "render/ray_start.hpp"
#include "render/renderer.hpp"
#include "render/sample_memo.hpp"
#include "render/sample_times.hpp"
#include "render/trace.hpp"

namespace lc {

namespace pixel_rows {

// Where the samples of a row sit (their slots): sample k = b N + a of pixel
// i's N x N grid is number i N N + k of the row; the layers' centre ray of
// pixel i (where no grid sample at the frame's moment sits at the centre)
// is W N N + i; in a blurred frame under point stars, instant k's extra ray
// through pixel i's first-sample point is W N N + W + k W + i.
struct RowGrid {
  int N;
  std::size_t W, NN;
  int centre;  // grid index b N + a of the centre sample, if N is odd; else -1
  RowGrid(int n, int width)
      : N(n), W(static_cast<std::size_t>(width)), NN(static_cast<std::size_t>(n) * n),
        centre(n % 2 == 1 ? (n / 2) * n + n / 2 : -1) {}
  // The sub-pixel (a, b) traced first in pixel column i when sampling
  // adaptively: one corner, alternating along the row between the top-left
  // and the bottom-right: neighbours' first samples then sit on different
  // sub-rows, so an edge that runs along the row inside a pixel row makes
  // them differ (a vertical one does anyway).
  std::pair<int, int> first_sample(std::size_t i) const {
    return i % 2 == 0 ? std::pair{0, 0} : std::pair{N - 1, N - 1};
  }
  std::size_t first_index(std::size_t i) const {
    const auto [a, b] = first_sample(i);
    return static_cast<std::size_t>(b) * N + a;
  }
  // The slots of pixel i's centre ray and of its star ray at instant k.
  std::size_t centre_slot(std::size_t i) const { return W * NN + i; }
  std::size_t star_slot(int k, std::size_t i) const { return W * NN + W + static_cast<std::size_t>(k) * W + i; }
  // Slots of a row whose frame has `instants` instants.
  std::size_t slots(int instants) const { return W * NN + W + static_cast<std::size_t>(instants) * W; }
  // The image point of sample g of row j.
  CameraSample point(std::size_t g, int j) const {
    const std::size_t i = g / NN, k = g % NN;
    const int a = static_cast<int>(k) % N, b = static_cast<int>(k) / N;
    return {static_cast<double>(i) + (a + 0.5) / N, j + (b + 0.5) / N, 0.0};
  }
};

// A sample as adaptive sampling compares it: its hit kind and its colour
// after the sRGB curve (what a viewer sees), worked out once per sample,
// not per comparison (the curve's pow shows in a Kerr frame's time:
// docs/performance.md, change 24).
struct Perceived {
  HitKind kind = HitKind::sky;
  std::array<double, 3> srgb{};
  explicit Perceived(const FrameSample& s) : kind(s.kind) {
    for (int c = 0; c < 3; ++c) srgb[c] = linear_to_srgb(s.color[c]);
  }
  Perceived() = default;
};

// Whether two samples agree closely enough to stand for the pixels and
// sub-pixels between them: the same hit kind, and every colour channel
// within adaptive_sample_threshold after the sRGB curve.
inline bool samples_agree(const Perceived& x, const Perceived& y) {
  if (x.kind != y.kind) return false;
  for (int c = 0; c < 3; ++c)
    if (std::abs(x.srgb[c] - y.srgb[c]) > adaptive_sample_threshold) return false;
  return true;
}

// The plan stage: which grid samples of a row to take, round by round.
// Not adaptive (or N = 1): every sample, in one round.  Adaptive (along the
// row: the rows above and below belong to other stripes): first one sample
// of every pixel (RowGrid::first_sample); then the whole grid of each pixel
// whose first sample disagrees with a row neighbour's; then, in rounds, of
// each neighbour of a pixel whose grid turned out not to be flat (a feature
// found inside one pixel may reach into the next without touching its
// first sample).  In a row that wraps around (a whole sphere's: `wraps`)
// the first and last pixels are neighbours.
class RowPlan {
 public:
  RowPlan(const RowGrid& grid, bool adaptive, bool wraps = false)
      : grid_(grid), adaptive_(adaptive && grid.N >= 2), wraps_(wraps && grid.W >= 3),
        seen_(adaptive_ ? grid.W * grid.NN : 0),
        full_(grid.W), next_(grid.W) {}

  // The first round's samples into `where`.
  void first_round(std::vector<std::size_t>& where) {
    where.clear();
    for (std::size_t i = 0; i < grid_.W; ++i) {
      full_[i] = !adaptive_;
      if (adaptive_)
        where.push_back(i * grid_.NN + grid_.first_index(i));
      else
        for (std::size_t k = 0; k < grid_.NN; ++k) where.push_back(i * grid_.NN + k);
    }
  }
  // Takes in the samples of the round just taken (`where`, their values in
  // `samples` at their grid indices) and puts the next round's into
  // `where`: false when there is none.
  bool next_round(std::vector<std::size_t>& where, const std::vector<FrameSample>& samples) {
    if (!adaptive_) return false;
    for (const std::size_t g : where) seen_[g] = Perceived(samples[g]);
    if (first_) {
      first_ = false;
      for (std::size_t i = 0; i < grid_.W; ++i)
        next_[i] = (i > 0 && !samples_agree(first_of(i), first_of(i - 1))) ||
                   (i + 1 < grid_.W && !samples_agree(first_of(i), first_of(i + 1)));
      if (wraps_) {
        const std::size_t last = grid_.W - 1;
        if (!samples_agree(first_of(0), first_of(last))) next_[0] = next_[last] = 1;
      }
    } else {
      std::fill(next_.begin(), next_.end(), 0);
      for (const std::size_t g : where) full_[g / grid_.NN] = 2;  // refined in this round
      for (std::size_t i = 0; i < grid_.W; ++i) {
        if (full_[i] != 2) continue;
        full_[i] = 1;
        bool flat = true;
        for (std::size_t k = 0; k < grid_.NN && flat; ++k) flat = samples_agree(seen_[i * grid_.NN + k], first_of(i));
        if (!flat) {
          if (i > 0) next_[i - 1] = 1;
          if (i + 1 < grid_.W) next_[i + 1] = 1;
          if (wraps_ && i == 0) next_[grid_.W - 1] = 1;
          if (wraps_ && i + 1 == grid_.W) next_[0] = 1;
        }
      }
    }
    where.clear();
    for (std::size_t i = 0; i < grid_.W; ++i)
      if (next_[i] && !full_[i])
        for (std::size_t k = 0; k < grid_.NN; ++k)
          if (k != grid_.first_index(i)) where.push_back(i * grid_.NN + k);
    return !where.empty();
  }
  // Whether pixel i's whole grid was taken (else only its first sample).
  bool full(std::size_t i) const { return full_[i] != 0; }
  // Whether a grid sample of pixel i sits at its centre and was taken.
  bool has_centre_sample(std::size_t i) const {
    return grid_.centre >= 0 && (full_[i] || grid_.first_index(i) == static_cast<std::size_t>(grid_.centre));
  }

 private:
  const Perceived& first_of(std::size_t i) const { return seen_[i * grid_.NN + grid_.first_index(i)]; }
  const RowGrid& grid_;
  bool adaptive_, wraps_;
  bool first_ = true;
  std::vector<Perceived> seen_;  // the samples taken, as samples_agree compares them
  std::vector<char> full_, next_;
};

// The scenes a frame's samples see, by index: the instants of its open
// shutter 0 .. K-1 (SceneIn::instants), each seen by its own camera, then
// the frame's own scene at K, seen by `camera`; with the shutter closed the
// frame's own is the only one, at 0.  An index rather than the sample's
// time because an instant may sit at the frame's own moment, where the
// layers' centre ray must still see the frame's own scene through the
// caller's camera.
template <class S, class C>
struct FrameScenes {
  const SceneIn<S>& frame;
  const C& camera;

  // The index of the frame's own scene (= the number of instants).
  int own() const { return static_cast<int>(frame.instants.size()); }
  // The scene an item of scene index k sees (SampleItem::scene).
  const SceneIn<S>& scene_at(int k) const { return k < own() ? frame.instants[static_cast<std::size_t>(k)] : frame; }
  // f(k, scene k, its camera) for every scene, the frame's own last.
  template <class F>
  void each(F&& f) const {
    for (int k = 0; k < own(); ++k) f(k, scene_at(k), scene_at(k).camera);
    f(own(), frame, camera);
  }
};

// Which scene (FrameScenes) each grid sample of a row sees: the instants of
// sample_instants in a blurred frame (the same for any split of the frame
// into rows and windows), else the frame's own.  Kept between rows.
struct RowTimes {
  std::vector<int> scene;  // of row sample g < W N N
  int own = 0;             // the frame's own scene

  // Fills in row j of a frame of `instants` instants (`window`: where the
  // rows sit in the whole frame).
  void fill(const RowGrid& grid, int instants, int j, const ImageWindow& window) {
    own = instants;
    scene.assign(grid.W * grid.NN, own);
    if (instants == 0) return;
    for (std::size_t i = 0; i < grid.W; ++i)
      sample_instants(window.x0 + static_cast<std::int64_t>(i), window.y0 + static_cast<std::int64_t>(j), instants,
                      static_cast<int>(grid.first_index(i)), grid.first_sample(i).first != 0,
                      std::span<int>(scene.data() + i * grid.NN, grid.NN));
  }
  // The scene of pixel i's first sample (its ray for point stars).
  int of_first(const RowGrid& grid, std::size_t i) const { return scene[i * grid.NN + grid.first_index(i)]; }
};

// Whether pixel i's layers come from a grid sample (else its own centre
// ray): one sits at its centre, was taken, and sees the frame's own scene.
inline bool centre_in_grid(const RowGrid& grid, const RowPlan& plan, const RowTimes& times, std::size_t i) {
  return plan.has_centre_sample(i) && times.scene[i * grid.NN + static_cast<std::size_t>(grid.centre)] == times.own;
}

// One sample as the stages pass it along (after pbrt-v4's wavefront work
// items): it carries its place in the frame and the scene it sees, so one
// batch holds grid samples, centre rays and star rays alike, and no stage
// asks which kind of sample or frame it has.
struct SampleItem {
  CameraSample point;        // image point, and time: the moment of its scene
  int row = 0;               // j
  std::size_t pixel = 0;     // column i
  std::size_t slot = 0;      // where its FrameSample goes in the row (RowGrid)
  int scene = 0;             // which scene it sees (FrameScenes)
  bool carries_sky = false;  // pixel's ray for point stars: its sky point goes into and out of the memo with it
  // In: 0 asks its ray not to work out how long it stays valid (a frame no
  // later one is likely to reuse); out: its record's reuse_window.
  float reuse_window = 0.0f;
};

// The items of a row, made from the plan (the first half of the generate
// stage): each item's point, scene and slot.  Returns views of one buffer,
// valid until the next call.
template <class S, class C>
class RowItems {
 public:
  RowItems(const FrameScenes<S, C>& scenes, const RowGrid& grid, const RowTimes& times, bool sky_points)
      : scenes_(scenes), grid_(grid), times_(times), sky_points_(sky_points) {}

  // Grid samples `where` of row j, each in its scene; a pixel's first
  // carries its sky point for point stars.
  std::span<const SampleItem> grid_samples(int j, std::span<const std::size_t> where) {
    items_.clear();
    for (const std::size_t g : where) {
      const std::size_t i = g / grid_.NN;
      add(j, i, g, grid_.point(g, j), times_.scene[g], sky_points_ && g % grid_.NN == grid_.first_index(i));
    }
    return items_;
  }
  // The layers' centre rays of row j where no grid sample stands for them
  // (centre_in_grid: even N, an unrefined pixel, a blurred frame), in the
  // frame's own scene.
  std::span<const SampleItem> centres(int j, const RowPlan& plan, bool layers) {
    items_.clear();
    for (std::size_t i = 0; layers && i < grid_.W; ++i)
      if (!centre_in_grid(grid_, plan, times_, i))
        add(j, i, grid_.centre_slot(i), {static_cast<double>(i) + 0.5, j + 0.5, 0.0}, times_.own, false);
    return items_;
  }
  // Under point stars, every instant's ray through each pixel's
  // first-sample point where the pixel's first sample did not see that
  // instant (the point-star stage draws each instant's stars from its own
  // plane of sky points).  None with the shutter closed.
  std::span<const SampleItem> star_rays(int j) {
    items_.clear();
    for (int k = 0; sky_points_ && k < times_.own; ++k)
      for (std::size_t i = 0; i < grid_.W; ++i)
        if (times_.of_first(grid_, i) != k)
          add(j, i, grid_.star_slot(k, i), grid_.point(i * grid_.NN + grid_.first_index(i), j), k, false);
    return items_;
  }

 private:
  // An item of row j, pixel i at `slot`, through image point p at the
  // moment of the scene it sees.
  void add(int j, std::size_t i, std::size_t slot, CameraSample p, int scene, bool sky) {
    p.time = scenes_.scene_at(scene).moment;
    items_.push_back({p, j, i, slot, scene, sky});
  }
  const FrameScenes<S, C>& scenes_;
  const RowGrid& grid_;
  const RowTimes& times_;
  bool sky_points_;
  std::vector<SampleItem> items_;
};

// The trace stage as the pixel stages call it: the records of the rays
// `starts` (of the items `items`, in order) into `out`.  TraceRays traces
// them; a test may stand in records kept from another render
// (PixelRows.RecordsShadeToTheSamePixels), which is what makes the
// records the one source of everything after the trace.
struct TraceRays {
  template <class S>
  void operator()(const SceneIn<S>& sc, std::span<const SampleItem>, std::span<const RayStart> starts,
                  std::span<HitRecord> out) const {
    trace_records(sc, starts, out);
  }
};

// The generate, trace, shade and keep stages for a batch of items, scene by
// scene: each item's camera ray and ray start in its scene, traced by
// `tracer`, shaded, and its FrameSample into out[item.slot]; item.
// reuse_window becomes its record's.  Scratch space is kept between
// batches.
template <class S, class C, class Tracer>
class RayStages {
 public:
  // Rays counted into `stats`; scenes and tracer outlive the stages.
  RayStages(const FrameScenes<S, C>& scenes, const Tracer& tracer, RenderStats& stats)
      : scenes_(scenes), tracer_(tracer), stats_(stats) {}

  // The samples of `items` into out[item.slot]; scene by scene, since a
  // batch of rays is traced in one scene.
  void operator()(std::span<SampleItem> items, std::vector<FrameSample>& out) {
    scenes_.each([&](int k, const SceneIn<S>& at, const auto& camera) {
      generate(k, at, camera, items, out);
      if (traced_.empty()) return;
      trace(at);
      shade_and_keep(at, items, out);
    });
  }

 private:
  // Ray starts for the items of scene k (into starts_, traced_ and
  // index_, their place in `items`); an item without a ray is kept as such
  // at once.
  template <class Camera>
  void generate(int k, const SceneIn<S>& at, const Camera& camera, std::span<SampleItem> items,
                std::vector<FrameSample>& out) {
    eyes_.clear();
    starts_.clear();
    traced_.clear();
    index_.clear();
    for (std::size_t n = 0; n < items.size(); ++n) {
      SampleItem& item = items[n];
      if (item.scene != k) continue;
      if (const std::optional<CameraRay> r = camera.ray(item.point)) {
        starts_.push_back(eyes_.start(at, *r));
        traced_.push_back(item);
        index_.push_back(n);
      } else {
        const HitRecord none = no_ray_record();
        out[item.slot] = frame_sample(none, Shading{});
        item.reuse_window = none.reuse_window;
      }
    }
  }
  // The records of starts_ into records_, each asked whether to work out
  // its reuse window as its item says.
  void trace(const SceneIn<S>& at) {
    records_.assign(starts_.size(), HitRecord{});
    for (std::size_t m = 0; m < records_.size(); ++m) records_[m].reuse_window = traced_[m].reuse_window;
    tracer_(at, std::span<const SampleItem>(traced_), std::span<const RayStart>(starts_),
            std::span<HitRecord>(records_));
  }
  // Each record shaded and kept at its item's slot.
  void shade_and_keep(const SceneIn<S>& at, std::span<SampleItem> items, std::vector<FrameSample>& out) {
    for (std::size_t m = 0; m < records_.size(); ++m) {
      const HitRecord& hit = records_[m];
      SampleItem& item = items[index_[m]];
      out[item.slot] = frame_sample(hit, shading(at, hit));
      item.reuse_window = hit.reuse_window;
      ++stats_.rays;
      stats_.steps += hit.steps;
      if (hit.kind == HitKind::gave_up) ++stats_.gave_up;
    }
  }
  const FrameScenes<S, C>& scenes_;
  const Tracer& tracer_;
  RenderStats& stats_;
  EyePool eyes_;
  std::vector<RayStart> starts_;
  std::vector<SampleItem> traced_;
  std::vector<std::size_t> index_;
  std::vector<HitRecord> records_;
};

// The sample memo as a stage in front of the ray stages (`next`), for one
// row: items kept from an earlier frame of the same still_key are taken
// from it, the rest go on to `next` and are kept for later frames.  A
// blurred frame takes and keeps nothing: its samples are not the frame's
// scene shifted in time.  Holds the memo's row (its lock) while it lives.
template <class Next>
class MemoStage {
 public:
  // Row j of `memo` (none: every item goes on) for the frame sc, whose
  // rows are `width` pixels; `next` and `stats` outlive the stage.
  template <class S>
  MemoStage(SampleMemo* memo, const SceneIn<S>& sc, int j, std::size_t width, Next& next, RenderStats& stats)
      : next_(next), stats_(stats), width_(width) {
    if (memo && sc.instants.empty()) row_ = memo->row(j, sc.still_key, sc.eye.time);
    // Rays work out how long they stay valid near a moving object only
    // where a later frame is likely to use it (0: not worked out).
    window_ = row_ && row_->continues() ? std::numeric_limits<float>::infinity() : 0.0f;
  }

  // The samples of `items` into out[item.slot].
  void operator()(std::span<const SampleItem> items, std::vector<FrameSample>& out) {
    rest_.clear();
    for (const SampleItem& item : items) {
      if (row_ && row_->has(item.slot)) {
        out[item.slot] = row_->get(item.slot);
        if (item.carries_sky) out[item.slot].sky = row_->sky(item.pixel);
        ++stats_.reused;
      } else {
        rest_.push_back(item);
        rest_.back().reuse_window = window_;
      }
    }
    next_(std::span<SampleItem>(rest_), out);
    if (!row_) return;
    for (const SampleItem& item : rest_) {
      row_->put(item.slot, out[item.slot], item.reuse_window);
      if (item.carries_sky) row_->put_sky(item.pixel, out[item.slot].sky, width_);
    }
  }

 private:
  Next& next_;
  RenderStats& stats_;
  std::size_t width_;
  std::optional<SampleMemo::Row> row_;
  float window_ = 0.0f;
  std::vector<SampleItem> rest_;
};

// Sample s as the sky point of pixel column i: where the pixel's first
// sample sits in it (RowGrid::first_sample), which is where its ray went.
inline SkyPoint sky_point_of(const RowGrid& grid, std::size_t i, const FrameSample& s) {
  const auto [a, b] = grid.first_sample(i);
  SkyPoint sp = s.sky;
  sp.dx = static_cast<float>((a + 0.5) / grid.N);
  sp.dy = static_cast<float>((b + 0.5) / grid.N);
  return sp;
}

// The reconstruct stage: row j's pixels from its samples.  Colour: the mean
// of the samples taken (the whole grid, or the first sample of an
// unrefined pixel); alpha (where the image has it): the share of them with
// a ray; the layers: the centre sample's (centre_in_grid), else the centre
// ray's; the sky point: the first sample's, with where in the pixel it
// passed, in the plane of the scene it saw (a plane per instant of a
// blurred frame).
inline void reconstruct_row(const RowGrid& grid, const RowPlan& plan, const RowTimes& times,
                            const std::vector<FrameSample>& samples, int j, bool layers, FrameImage& img) {
  const std::size_t W = grid.W, NN = grid.NN;
  const std::size_t plane = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  for (std::size_t i = 0; i < W; ++i) {
    double acc[3] = {0, 0, 0};
    int n = 0, with_ray = 0;
    for (std::size_t k = 0; k < NN; ++k) {
      if (!plan.full(i) && k != grid.first_index(i)) continue;
      const FrameSample& s = samples[i * NN + k];
      for (int c = 0; c < 3; ++c) acc[c] += s.color[c];
      ++n;
      with_ray += s.kind != HitKind::no_ray;
    }
    const std::size_t p = static_cast<std::size_t>(j) * W + i;
    for (int c = 0; c < 3; ++c) img.rgb[3 * p + c] = static_cast<float>(acc[c] / n);
    if (!img.alpha.empty()) img.alpha[p] = static_cast<float>(with_ray) / static_cast<float>(n);
    if (!img.sky.empty())
      img.sky[static_cast<std::size_t>(times.of_first(grid, i)) * plane + p] =
          sky_point_of(grid, i, samples[i * NN + grid.first_index(i)]);
    if (layers) {
      const FrameSample& centre_sample = centre_in_grid(grid, plan, times, i)
                                             ? samples[i * NN + static_cast<std::size_t>(grid.centre)]
                                             : samples[grid.centre_slot(i)];
      for (std::size_t l = 0; l < layer_count; ++l) img.layers[l].values[p] = centre_sample.layers[l];
    }
  }
}

// The star rays `stars` of row j (RowItems::star_rays) into their instants'
// planes of sky points.
inline void place_star_rays(const RowGrid& grid, std::span<const SampleItem> stars,
                            const std::vector<FrameSample>& samples, int j, FrameImage& img) {
  const std::size_t plane = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  for (const SampleItem& item : stars)
    img.sky[static_cast<std::size_t>(item.scene) * plane + static_cast<std::size_t>(j) * grid.W + item.pixel] =
        sky_point_of(grid, item.pixel, samples[item.slot]);
}

}  // namespace pixel_rows

// Renders the listed rows of the scene sc as seen by `camera` into img (and
// its layers), and returns the rays and steps spent.  With a memo, samples
// kept from an earlier frame of the same still_key stand in for traced
// ones (MemoStage).  Each pixel's first sample is its ray for point stars
// (their grid: a fixed point of every pixel, traced whatever adaptive
// sampling does).  `tracer` is the trace stage (pixel_rows::TraceRays).
//
// A blurred frame (sc.instants not empty: docs/motion_blur.md) differs
// only in its items: a grid of at least as many samples as instants
// (samples_per_side), each in its instant's scene (RowTimes), the layers'
// centre rays at the frame's own moment, and under point stars a plane of
// sky points per instant (RowItems::star_rays).
template <class S, class C, class Tracer = pixel_rows::TraceRays>
RenderStats render_rows_with(const SceneIn<S>& sc, const C& camera, const RenderSettings& rs, std::span<const int> rows,
                             FrameImage& img, SampleMemo* memo, const Tracer& tracer = {}) {
  using namespace pixel_rows;
  RenderStats stats;
  const FrameScenes<S, C> scenes{sc, camera};
  const RowGrid grid(samples_per_side(rs.supersample, scenes.own()), rs.width);
  RowTimes times;
  RowItems<S, C> items(scenes, grid, times, !img.sky.empty());
  RayStages<S, C, Tracer> rays(scenes, tracer, stats);
  std::vector<FrameSample> samples(grid.slots(scenes.own()));  // the row's, by slot
  std::vector<std::size_t> where;
  for (int j : rows) {
    MemoStage take(memo, sc, j, grid.W, rays, stats);
    times.fill(grid, scenes.own(), j, rs.window);
    RowPlan plan(grid, rs.adaptive, camera.wrap().columns);
    plan.first_round(where);
    do {
      take(items.grid_samples(j, where), samples);
    } while (plan.next_round(where, samples));
    take(items.centres(j, plan, rs.layers), samples);
    reconstruct_row(grid, plan, times, samples, j, rs.layers, img);
    const std::span<const SampleItem> stars = items.star_rays(j);
    take(stars, samples);
    place_star_rays(grid, stars, samples, j, img);
  }
  return stats;
}

}  // namespace lc
