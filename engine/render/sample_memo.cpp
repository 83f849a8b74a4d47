#include "render/sample_memo.hpp"

namespace lc {

SampleMemo::SampleMemo(const RenderSettings& rs)
    : row_size_(static_cast<std::size_t>(rs.width) * (static_cast<std::size_t>(rs.supersample) * rs.supersample + 1)) {
  rows_.reserve(static_cast<std::size_t>(rs.height));
  for (int j = 0; j < rs.height; ++j) rows_.push_back(std::make_unique<Slot>());
}

std::optional<SampleMemo::Row> SampleMemo::row(int j, const std::string& key) {
  if (key.empty() || j < 0 || static_cast<std::size_t>(j) >= rows_.size()) return std::nullopt;
  Slot& slot = *rows_[static_cast<std::size_t>(j)];
  if (!slot.mutex.try_lock()) return std::nullopt;
  Row row(slot);
  if (slot.key != key) {
    // Another scene: nothing of the last one's samples applies.  Memory
    // comes with a row's first use, so a process holds only its rows.
    slot.key = key;
    slot.samples.assign(row_size_, Kept{});
  }
  return row;
}

RaySample SampleMemo::Row::get(std::size_t g) const {
  const Kept& k = slot_->samples[g];
  RaySample s;
  s.color = k.color;
  s.kind = static_cast<HitKind>(k.kind);
  s.r = k.r;
  s.phi = k.phi;
  s.t = k.t;
  s.order = k.order;
  return s;
}

void SampleMemo::Row::put(std::size_t g, const RaySample& s) {
  Kept& k = slot_->samples[g];
  k.kept = !s.depends_on_time;
  if (!k.kept) return;
  k.color = s.color;
  k.kind = static_cast<std::uint8_t>(s.kind);
  k.r = static_cast<float>(s.r);
  k.phi = static_cast<float>(s.phi);
  k.t = static_cast<float>(s.t);
  k.order = s.order;
}

}  // namespace lc
