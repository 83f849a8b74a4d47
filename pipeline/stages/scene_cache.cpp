#include "stages/scene_cache.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace lc::farm {

SceneCache::SceneCache(Shot& shot, int width, int height, std::size_t capacity, const ImageWindow& window)
    : shot_(shot), width_(width), height_(height), window_(window), capacity_(std::max<std::size_t>(1, capacity)),
      resources_(shot.asset_dirs()) {}

// Evaluates the frame (serialised: one Lua state) and builds its scene
// (in parallel with other builds: ShotResources is thread-safe).
std::shared_ptr<const Scene> SceneCache::build(int frame) {
  FrameSpecs specs;
  {
    std::lock_guard lock(lua_mutex_);
    specs = shot_.frame_specs(frame);
  }
  return std::make_shared<const Scene>(
      build_scene(specs, shot_.file(), frame, width_, height_, resources_, RayOptions{}, window_));
}

std::shared_ptr<const Scene> SceneCache::get(int frame) {
  std::unique_lock lock(mutex_);
  if (auto it = entries_.find(frame); it != entries_.end()) {
    auto entry = it->second;  // keep it alive even if evicted meanwhile
    built_.wait(lock, [&] { return entry->ready; });
    if (entry->error) std::rethrow_exception(entry->error);
    return entry->scene;
  }
  auto entry = std::make_shared<Entry>();
  entries_[frame] = entry;
  order_.push_back(frame);
  while (order_.size() > capacity_) {
    entries_.erase(order_.front());
    order_.pop_front();
  }
  lock.unlock();
  try {
    auto scene = build(frame);
    lock.lock();
    entry->scene = std::move(scene);
  } catch (...) {
    lock.lock();
    entry->error = std::current_exception();
  }
  entry->ready = true;
  built_.notify_all();
  if (entry->error) std::rethrow_exception(entry->error);
  return entry->scene;
}

}  // namespace lc::farm
