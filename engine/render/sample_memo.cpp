#include "render/sample_memo.hpp"

namespace lc {

SampleMemo::SampleMemo(const RenderSettings& rs)
    : row_size_(static_cast<std::size_t>(rs.width) * (static_cast<std::size_t>(rs.supersample) * rs.supersample + 1)) {
  rows_.reserve(static_cast<std::size_t>(rs.height));
  for (int j = 0; j < rs.height; ++j) rows_.push_back(std::make_unique<Slot>());
}

std::optional<SampleMemo::Row> SampleMemo::row(int j, const std::string& key, double time) {
  if (key.empty() || j < 0 || static_cast<std::size_t>(j) >= rows_.size()) return std::nullopt;
  Slot& slot = *rows_[static_cast<std::size_t>(j)];
  if (!slot.mutex.try_lock()) return std::nullopt;
  Row row(slot, time, slot.key == key);
  if (slot.key != key) {
    // Another scene: nothing of the last one's samples applies.  Memory
    // comes with a row's first use, so a process holds only its rows.
    slot.key = key;
    slot.samples.assign(row_size_, Kept{});
    slot.sky.clear();
  }
  return row;
}

}  // namespace lc
