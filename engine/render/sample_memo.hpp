#pragma once
// Camera-ray samples kept from earlier frames for later ones.  In a
// stationary spacetime, frames whose scenes differ only by the observer's
// time (equal SceneIn::still_key) see the same thing along every ray that
// stays clear of moving objects' paths: the same ray, traced the same way,
// with its time shifted.  Such samples are kept per row, and a later frame
// of the same key takes them instead of tracing them again; a sample whose
// ray came near a moving object (RaySample::depends_on_time) is always
// traced.  Holds and a static observer watching a moving sphere
// (docs/performance.md, change 25) cost only the rays that can change.
//
// Kept per (row, sample index) for one RenderSettings: sample g of a row is
// pixel g / (N N)'s grid sample g % (N N), and W N N + i the centre ray of
// pixel i that the layers take.  Thread-safe: one thread holds a row at a
// time.

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "render/hit.hpp"
#include "render/layers.hpp"
#include "render/renderer.hpp"

namespace lc {

class SampleMemo {
  // What a frame uses of a sample (render/layers.hpp's FrameSample: its
  // colour, layer values and hit kind), and whether one is kept.
  struct Kept {
    Color color{};
    LayerValues layers{};
    std::uint8_t kind = 0;  // HitKind
    bool kept = false;
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
    // Whether sample g was kept from an earlier frame.
    bool has(std::size_t g) const { return slot_->samples[g].kept; }
    // Kept sample g (has(g)); its sky point is kept only where put_sky
    // put it.
    FrameSample get(std::size_t g) const {
      const Kept& k = slot_->samples[g];
      return {k.color, k.layers, static_cast<HitKind>(k.kind), {}};
    }
    // The sky point of pixel i's ray for point stars, kept with its sample.
    SkyPoint sky(std::size_t i) const { return i < slot_->sky.size() ? slot_->sky[i] : SkyPoint{}; }
    void put_sky(std::size_t i, const SkyPoint& p, std::size_t width) {
      slot_->sky.resize(width);
      slot_->sky[i] = p;
    }
    // Sample g of this frame, kept for later frames unless its ray came near
    // a moving object (`keep` false: RaySample::depends_on_time).
    void put(std::size_t g, const FrameSample& s, bool keep) {
      slot_->samples[g] = {s.color, s.layers, static_cast<std::uint8_t>(s.kind), keep};
    }

   private:
    friend class SampleMemo;
    Row(Slot& slot) : lock_(slot.mutex, std::adopt_lock), slot_(&slot) {}
    std::unique_lock<std::mutex> lock_;
    Slot* slot_;
  };

  // Row j for a frame whose scene has still_key `key`: the samples kept
  // from frames of the same key (none, if the row last held another key).
  // nullopt when nothing can be kept (an empty key: a spacetime that is not
  // stationary) or another thread holds the row (the caller traces all).
  std::optional<Row> row(int j, const std::string& key);

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
