#pragma once
// Camera-ray samples kept from earlier frames for later ones.  In a
// stationary spacetime, frames whose scenes differ only by the observer's
// time (equal SceneIn::still_key) see the same thing along every ray that
// stays clear of moving objects' paths: the same ray, traced the same way,
// with its time shifted.  Such samples are kept per row, and a later frame
// of the same key takes them instead of tracing them again while its time
// is within the sample's reuse window (HitRecord::reuse_window: for as long as
// every moving object it came near stays clear of it; a ray that entered
// an object's tube is always traced).  Holds and a static observer
// watching a moving sphere (docs/performance.md, changes 25 and 34) cost
// only the rays that can change.
//
// Kept per (row, slot) for one RenderSettings, the slots of a row's samples
// (render/pixel_rows.hpp, RowGrid): slot g is pixel g / (N N)'s grid sample
// g % (N N), and W N N + i the centre ray of pixel i that the layers take.
// The renderer reads and fills it in one stage in front of its ray stages
// (pixel_rows::MemoStage).  Thread-safe: one thread holds a row at a time.

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "render/hit_record.hpp"
#include "render/layers.hpp"
#include "render/renderer.hpp"

namespace lc {

class SampleMemo {
  // What a frame uses of a sample (render/layers.hpp's FrameSample: its
  // colour and layer values, the first of which is its hit kind), and the
  // frame times it holds for (none when from > to).
  static_assert(layers[0].name == "hit.kind");
  struct Kept {
    Color color{};
    LayerValues layers{};
    float from = 1.0f, to = 0.0f;
  };
  struct Slot {
    std::mutex mutex;
    std::string key;  // still_key of the frame the samples came from
    std::vector<Kept> samples;
    std::vector<SkyPoint> sky;  // where the sky is kept (point stars): per pixel, its grid's ray
  };

 public:
  // For frames rendered with `rs`.
  explicit SampleMemo(const RenderSettings& rs);

  // One row's samples while a thread renders it.
  class Row {
   public:
    // Whether the row held samples of this frame's key before it: the frame
    // continues a still stretch, so the next may well share its key (a
    // frame that starts one, or a pan's, whose key no other frame has,
    // need not work out its rays' reuse windows).
    bool continues() const { return continues_; }
    // Whether sample g was kept from an earlier frame, for this one's time.
    bool has(std::size_t g) const {
      const Kept& k = slot_->samples[g];
      return k.from <= time_ && time_ <= k.to;
    }
    // Kept sample g (has(g)); its sky point is kept only where put_sky
    // put it.
    FrameSample get(std::size_t g) const {
      const Kept& k = slot_->samples[g];
      return {k.color, k.layers, static_cast<HitKind>(static_cast<int>(k.layers[0])), {}};
    }
    // The sky point of pixel i's ray for point stars, kept with its sample.
    SkyPoint sky(std::size_t i) const { return i < slot_->sky.size() ? slot_->sky[i] : SkyPoint{}; }
    void put_sky(std::size_t i, const SkyPoint& p, std::size_t width) {
      slot_->sky.resize(width);
      slot_->sky[i] = p;
    }
    // Sample g of this frame, kept for frames within `window` of its time
    // (HitRecord::reuse_window; <= 0: not kept).  The window is stored in
    // floats, rounded inwards.
    void put(std::size_t g, const FrameSample& s, float window) {
      Kept k{s.color, s.layers, 1.0f, 0.0f};
      if (window > 0.0f) {
        k.from = inwards(time_ - static_cast<double>(window), +1);
        k.to = inwards(time_ + static_cast<double>(window), -1);
      }
      slot_->samples[g] = k;
    }

   private:
    friend class SampleMemo;
    Row(Slot& slot, double time, bool continues)
        : lock_(slot.mutex, std::adopt_lock), slot_(&slot), time_(time), continues_(continues) {}
    // x as a float, rounded towards +inf (dir > 0) or -inf.
    static float inwards(double x, int dir) {
      float f = static_cast<float>(x);
      if (dir > 0 && f < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
      if (dir < 0 && f > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
      return f;
    }
    std::unique_lock<std::mutex> lock_;
    Slot* slot_;
    double time_;  // the frame's observer time
    bool continues_;
  };

  // Row j for a frame whose scene has still_key `key` and observer time
  // `time`: the samples kept from frames of the same key (none, if the row
  // last held another key).  nullopt when nothing can be kept (an empty
  // key: a spacetime that is not stationary) or another thread holds the
  // row (the caller traces all).
  std::optional<Row> row(int j, const std::string& key, double time);

  // Samples per row: W N N grid samples and W centre rays.
  std::size_t row_size() const { return row_size_; }
  // Bytes a memo for `rs` holds once every row has been used (with point
  // stars: a sky point per pixel too).
  static std::size_t bytes_for(const RenderSettings& rs) {
    return static_cast<std::size_t>(rs.height) * static_cast<std::size_t>(rs.width) *
           ((static_cast<std::size_t>(rs.supersample) * rs.supersample + 1) * sizeof(Kept) + sizeof(SkyPoint));
  }

 private:
  std::size_t row_size_;
  std::vector<std::unique_ptr<Slot>> rows_;
};

}  // namespace lc
