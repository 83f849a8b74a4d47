#include "script/shot.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "lua/table_reader.hpp"
#include "script/engine_api.hpp"
#include "script/scene_reader.hpp"
#include "scene/still_key.hpp"
#include "script/script_paths.hpp"

namespace lc {

Shot::Shot(const std::filesystem::path& file, lua::SandboxLimits limits) : file_(file), limits_(std::move(limits)) {
  unused_.emplace(load(info_));
}

Shot::Loaded Shot::load(ShotInfo& info) {
  Loaded out{lua::Sandbox(require_dirs_for(file_), limits_)};
  install_engine_api(out.sandbox, &memo_);
  out.sandbox.run_file(file_, 1);
  lua_State* L = out.sandbox.state();
  if (!lua_istable(L, -1))
    throw lua::FieldError(fmt::format("{}: the script must return a shot table, got {}", file_.string(),
                                      luaL_typename(L, -1)));
  {
    lua::TableReader t(L, -1, file_.string());
    // Known before the other fields are read: a misspelt 'frames' must not
    // be taken for a misspelling of 'frame'.
    t.mark_known({"frame", "description"});
    info = read_shot_info(t);
    t.push_field("frame");
    if (!lua_isfunction(L, -1))
      throw lua::FieldError(fmt::format("{}: field 'frame' must be a function(i) returning the scene of frame i, got {}",
                                        file_.string(), luaL_typename(L, -1)));
    out.frame_ref = luaL_ref(L, LUA_REGISTRYINDEX);
    t.finish();
  }
  lua_pop(L, 1);
  note_loaded_files(out.sandbox);
  return out;
}

void Shot::note_loaded_files(const lua::Sandbox& sandbox) {
  for (const auto& p : sandbox.loaded_files())
    if (std::find(loaded_files_.begin(), loaded_files_.end(), p) == loaded_files_.end()) loaded_files_.push_back(p);
}

SceneSpec Shot::frame(int i) {
  const std::string ctx = fmt::format("{}: frame {}", file_.string(), i);
  if (i < 0 || i >= info_.frames)
    throw lua::FieldError(fmt::format("{}: no such frame (the shot has frames 0 to {})", ctx, info_.frames - 1));
  return evaluate(i, ctx);
}

FrameSpecs Shot::frame_specs(int i) {
  FrameSpecs out;
  out.frame = frame(i);
  out.shutter = frame_shutter(info_.shot_shutter(), out.frame.shutter, shutter_override_);
  if (out.shutter.closed()) return out;
  const std::string frame_key = scene_key(out.frame);
  bool changes = false;
  for (const double t : out.shutter.instants()) {
    const double at = std::clamp(i + t, 0.0, static_cast<double>(info_.frames - 1));
    SceneSpec s = at == i ? out.frame : evaluate_instant(i, at);
    if (s.spacetime.index() != out.frame.spacetime.index())
      throw std::invalid_argument(fmt::format(
          "{}: frame {}: the spacetime is {} at the frame but {} at {:g}, within its shutter; a shutter cannot be "
          "open across a change of spacetime: close it for this frame (its `shutter = 0`)",
          file_.string(), i, spacetime_name(out.frame.spacetime), spacetime_name(s.spacetime), at));
    // The star stage draws each instant's point stars: a sky of another
    // kind within the shutter is a cut, too.
    if (s.sky.index() != out.frame.sky.index())
      throw std::invalid_argument(fmt::format(
          "{}: frame {}: the sky is lc.{} at the frame but lc.{} at {:g}, within its shutter; a shutter cannot be "
          "open across a change of sky: close it for this frame (its `shutter = 0`)",
          file_.string(), i, SkyRegistry::name(out.frame.sky), SkyRegistry::name(s.sky), at));
    // Each sample takes one instant's camera: a cut between cameras mixes
    // their pictures pixel by pixel.
    if (const auto cut = camera_cut(out.frame.camera, s.camera))
      throw std::invalid_argument(fmt::format(
          "{}: frame {}: the camera is {} at the frame but {} at {:g}, within its shutter; a shutter cannot be open "
          "across a change of camera kind, stereo layout or projection: close it for this frame (its `shutter = 0`)",
          file_.string(), i, cut->at_frame, cut->at_instant, at));
    changes = changes || scene_key(s) != frame_key;
    out.times.push_back(t);
    out.instants.push_back(std::move(s));
  }
  if (!changes) {
    out.times.clear();
    out.instants.clear();
  }
  return out;
}

SceneSpec Shot::evaluate_instant(int i, double at) {
  const std::string ctx = fmt::format("{}: frame {} at {:g}", file_.string(), i, at);
  const std::string hint = fmt::format(
      " (frame {}'s shutter is open: frame(i) is also called at fractional i, the instants of its shutter; a script "
      "that only knows whole frames can close it with `shutter = 0`: docs/motion_blur.md)",
      i);
  try {
    return evaluate(at, ctx);
  } catch (const lua::FieldError& e) {
    throw lua::FieldError(std::string(e.what()) + hint);
  } catch (const lua::ScriptError& e) {
    throw lua::ScriptError(std::string(e.what()) + hint);
  }
}

SceneSpec Shot::evaluate(double at, const std::string& ctx) {
  ShotInfo unused_info;
  Loaded fresh = unused_ ? std::move(*unused_) : load(unused_info);
  unused_.reset();
  lua_State* L = fresh.sandbox.state();
  lua_rawgeti(L, LUA_REGISTRYINDEX, fresh.frame_ref);
  lua_pushnumber(L, at);
  try {
    fresh.sandbox.call(1, 1);
    note_loaded_files(fresh.sandbox);  // modules required inside frame()
  } catch (const lua::ScriptError& e) {
    // The script's line alone does not say which of its frames failed.
    throw lua::ScriptError(fmt::format("{}: {}", ctx, e.what()));
  }
  if (!lua_istable(L, -1)) {
    const std::string got = luaL_typename(L, -1);
    lua_pop(L, 1);
    throw lua::FieldError(fmt::format("{}: frame(i) must return a scene table, got {}", ctx, got));
  }
  try {
    lua::TableReader t(L, -1, ctx);
    SceneSpec fs = read_scene_spec(t);
    lua_pop(L, 1);
    fs.camera = delivered(fs.camera, delivery_);
    return fs;
  } catch (...) {
    lua_pop(L, 1);
    throw;
  }
}

std::vector<std::filesystem::path> Shot::loaded_files() const { return loaded_files_; }

std::vector<std::filesystem::path> Shot::asset_dirs() const {
  std::filesystem::path own = file_.parent_path();
  if (own.empty()) own = ".";
  return {own, library_dir().parent_path() / "shots"};
}

}  // namespace lc
