#pragma once
// The scenes of the frames a process is working on.  Each rank (and the
// local farm) keeps one: a frame's scene is evaluated by the process's own
// Shot (Lua, one call at a time) and built once, however many stripes of it
// the threads render; worldlines and textures are shared through the one
// ShotResources, so they are integrated and loaded once per process per
// shot.  Thread-safe.

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>

#include "render/scene_builder.hpp"
#include "script/shot.hpp"

namespace lc::farm {

class SceneCache {
 public:
  // Keeps the `capacity` most recently built scenes (frames arrive in order,
  // so a handful covers the frames in flight).
  // `window`: scenes for that window of the frame (render --region).
  SceneCache(Shot& shot, int width, int height, std::size_t capacity = 8, const ImageWindow& window = {});

  // The scene of `frame`, building it on first use; threads asking for the
  // same frame meanwhile wait for that one build.  Throws the build's error
  // (naming the shot file and frame) to every asker.
  std::shared_ptr<const Scene> get(int frame);

 private:
  struct Entry {
    bool ready = false;
    std::shared_ptr<const Scene> scene;
    std::exception_ptr error;
  };
  std::shared_ptr<const Scene> build(int frame);

  Shot& shot_;
  int width_, height_;
  ImageWindow window_;
  std::size_t capacity_;
  ShotResources resources_;
  std::mutex lua_mutex_;  // Shot is not thread-safe
  std::mutex mutex_;
  std::condition_variable built_;
  std::map<int, std::shared_ptr<Entry>> entries_;
  std::deque<int> order_;  // frames by time of first request
};

}  // namespace lc::farm
